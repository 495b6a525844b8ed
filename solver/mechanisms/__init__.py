"""The unit-aware layer: mechanisms that take and return pint Quantities.

Each class converts its geometry to SI once, calls the unit-free kernel in
:mod:`accelab.solver.kernels` and wraps what the caller reads as Quantities.
"""

from ..registry import BATCH_MECHANISMS, mechanism_class
from .base import Mechanism, Result
from .fivebar import GearedFiveBar
from .fourbar import FourBar
from .invertedslidercrank import InvertedSliderCrank
from .rotation import RotatingPoint, SlottedLink
from .slidercrank import SliderCrank

# the batch format's mechanisms: name -> class (from the registry, accelab.solver.registry);
# a comment, not a doc comment: the API pages would print the whole dict
MECHANISMS: dict[str, type[Mechanism]] = {name: mechanism_class(name) for name in BATCH_MECHANISMS}

__all__ = [
    "Mechanism",
    "Result",
    "FourBar",
    "SliderCrank",
    "InvertedSliderCrank",
    "GearedFiveBar",
    "RotatingPoint",
    "SlottedLink",
    "MECHANISMS",
]
