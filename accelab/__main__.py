"""``python -m accelab``: the same as the ``accelab`` command."""

import sys

from accelab.cli import main

sys.exit(main())
