"""The unit-aware layer: mechanisms that take and return pint Quantities.

Each class converts its geometry to SI once, calls the unit-free kernel in
:mod:`accelab.solver.kernels` and wraps what the caller reads as Quantities.
"""

from .base import Mechanism, Result
from .fourbar import FourBar
from .slidercrank import SliderCrank
from .invertedslidercrank import InvertedSliderCrank
from .fivebar import GearedFiveBar
from .rotation import RotatingPoint, SlottedLink

MECHANISMS = {
    "fourbar": FourBar,
    "slidercrank": SliderCrank,
    "invertedslidercrank": InvertedSliderCrank,
    "fivebar": GearedFiveBar,
    "rotation": RotatingPoint,
}

__all__ = ["Mechanism", "Result", "FourBar", "SliderCrank", "InvertedSliderCrank",
           "GearedFiveBar", "RotatingPoint", "SlottedLink", "MECHANISMS"]
