"""accelab's solver: acceleration analysis of planar linkages, position to jerk.

Two layers (see the README, "How the code is laid out"):

* :mod:`accelab.solver.kernels` -- unit-free closed forms on numpy arrays of SI floats;
* the unit-aware classes below, which take and return pint Quantities built on
  the package's single registry ``ureg``.

>>> from accelab.solver import FourBar
>>> r = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
...     theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")
>>> r.alpha3.to("rad/s^2")

The general vector-loop solver (:mod:`accelab.solver.vectorloops`, section 7.8) and
the graphical constructions (:mod:`accelab.solver.graphical`, section 7.2) sit beside
them; :mod:`accelab.solver.registry` registers every mechanism once (its parameters,
class, construction) and :mod:`accelab.solver.cases` reads a case of the batch format
into SI floats once.

References
----------
R. L. Norton, *Design of Machinery*, McGraw-Hill, chapter 7, "Acceleration
Analysis". Equation, figure and example numbers in the docstrings (eq. 7.7,
Figure 7-4, Example 7-1 ...) are that chapter's; the position and velocity
equations of chapters 4 and 6 are cited where the chapter repeats them.
"""

from .errors import AccelabError, InvalidInput, NoConvergence, NotAssemblable, Singular
from .mechanisms import (
    MECHANISMS,
    FourBar,
    GearedFiveBar,
    InvertedSliderCrank,
    RotatingPoint,
    SliderCrank,
    SlottedLink,
)
from .units import Q_, ureg
from .vectorloops import VectorLoopLinkage

__all__ = [
    "ureg",
    "Q_",
    "FourBar",
    "SliderCrank",
    "InvertedSliderCrank",
    "GearedFiveBar",
    "RotatingPoint",
    "SlottedLink",
    "VectorLoopLinkage",
    "AccelabError",
    "InvalidInput",
    "NotAssemblable",
    "Singular",
    "NoConvergence",
    "MECHANISMS",
]
