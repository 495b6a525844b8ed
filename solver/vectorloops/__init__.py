"""Any planar linkage as vector loops, solved by Newton-Raphson (section 7.8).

A linkage is a set of named vectors and the loops they close (CONVENTIONS,
"Any linkage as vector loops"). Position comes from Newton-Raphson with the
analytic Jacobian; velocity, acceleration and jerk from linear solves with
the same Jacobian. :class:`VectorLoopLinkage` is the unit-aware class;
:func:`solve_case` is the batch contract's ``loops`` mechanism.
"""

from .batch import solve_case
from .linkage import VectorLoopLinkage

__all__ = ["VectorLoopLinkage", "solve_case"]
