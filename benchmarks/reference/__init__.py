"""The project's one high-precision reference, for the benchmark and the tests.

Every linkage, closed-form or not, is solved the same way: its vector loops
closed by Newton-Raphson in mpmath at 40 to 60 significant digits, and its
velocity, acceleration and jerk from the differentiated loops (eqs. 7.2,
7.19 and 7.40), with no iteration (:mod:`.loops`). This shares neither formulas nor
round-off with the closed-form kernels, nor code with
:mod:`accelab.solver.vectorloops`. The closed-form mechanisms are written as their
loops, started from their position found by plain geometry, which also fixes
the assembly (:mod:`.mechanisms`); their limit positions come from the law
of cosines (:mod:`.limits`); :mod:`.cache` follows the benchmark's cycles and
keeps them. The tests check the reference itself against mpmath's numerical
differentiation of the geometric positions (tests/test_benchmarks_reference.py).

Results are rounded to float64 at the end, so the reference's error is far
below what any method compared with it can reach.
"""

from .cache import at_points, cached, cycle_key
from .limits import (
    fivebar_limits,
    fourbar_limits,
    fourbar_rocker_limits,
    invertedslidercrank_limit,
    slidercrank_limits,
    toggle_angle,
)
from .loops import DPS, LoopReference
from .mechanisms import (
    CIRCUIT_SIGN,
    POSITIONS,
    assembles,
    batch_branch,
    fourbar_position,
    rotating_point,
    slotted_link,
    solve,
)

__all__ = [
    "LoopReference",
    "DPS",
    "cached",
    "cycle_key",
    "at_points",
    "solve",
    "batch_branch",
    "rotating_point",
    "slotted_link",
    "assembles",
    "POSITIONS",
    "CIRCUIT_SIGN",
    "fourbar_position",
    "fourbar_limits",
    "fourbar_rocker_limits",
    "slidercrank_limits",
    "invertedslidercrank_limit",
    "fivebar_limits",
    "toggle_angle",
]
