"""Unit-free closed forms: SI floats in, SI floats out, vectorized over arrays.

Nothing in this package imports pint. Each mechanism module has a ``solve``
that returns a :class:`~accelab.solver.kernels.common.Motion` holding the angular
(and slider) kinematics from position to jerk, a ``status`` code per position
a ``condition`` measure and a round-off estimate (``roundoff``) that
decides which positions are too near a limit to vouch for;
:mod:`accelab.solver.kernels.points` turns those into point positions,
velocities, accelerations and jerks only when asked.
"""

from ..status import NOT_ASSEMBLABLE, OK, SINGULAR, STATUS_NAMES
from .common import MAX_ROUNDOFF, Motion

__all__ = ["OK", "NOT_ASSEMBLABLE", "SINGULAR", "STATUS_NAMES", "MAX_ROUNDOFF", "Motion"]
