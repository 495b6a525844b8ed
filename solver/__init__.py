"""accelab's solver: acceleration analysis of planar linkages, position to jerk.

Two layers (see the README):

* :mod:`solver.kernels` -- unit-free closed forms on numpy arrays of SI floats;
* the unit-aware classes below, which take and return pint Quantities built on
  the package's single registry ``ureg``.

>>> from solver import FourBar
>>> r = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
...     theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")
>>> r.alpha3.to("rad/s^2")
"""

from .errors import AccelabError, InvalidInput, NotAssemblable, NoConvergence, Singular
from .units import Q_, ureg
from .mechanisms import (FourBar, GearedFiveBar, InvertedSliderCrank, MECHANISMS,
                         RotatingPoint, SliderCrank, SlottedLink)
from .vectorloops import VectorLoopLinkage

__all__ = ["ureg", "Q_", "FourBar", "SliderCrank", "InvertedSliderCrank", "GearedFiveBar",
           "RotatingPoint", "SlottedLink", "VectorLoopLinkage", "AccelabError", "InvalidInput",
           "NotAssemblable", "Singular", "NoConvergence", "MECHANISMS"]
