"""``python -m solver``: the whole ``accelab`` command, as ``python -m accelab``.

A program, not part of the library: kept so that scripts written for
``python -m solver`` keep working (allowed in tests/test_layers.py).
"""

import sys

from accelab.cli import main

sys.exit(main())
