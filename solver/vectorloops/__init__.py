"""Any planar linkage as vector loops, solved by Newton-Raphson (section 7.8).

A linkage is a set of named vectors and the loops they close
(docs/conventions.md#vector-loop-format, "Any linkage as vector loops").
Position comes from Newton-Raphson with the analytic Jacobian; velocity,
acceleration and jerk from linear solves with the same Jacobian.
:class:`VectorLoopLinkage` is the unit-aware class; :func:`solve_loops_case`
is the batch contract's ``loops`` mechanism.

A sweep over an array of theta2 follows one assembly by continuation on a
coarse subset of the positions and solves the positions in between in one
batched Newton-Raphson (:mod:`.sweep`); ``tol=`` on
:meth:`VectorLoopLinkage.solve` sets Newton-Raphson's convergence tolerance
(default 1e-13, round-off). The assembly is told by its orientation (the
sign of det J); through a change point, where two assemblies meet, a sweep
keeps that orientation and says so in ``notes`` (:mod:`.crossing`).

Modules: :mod:`.description` (reading a description), :mod:`.newton` (the
loop equations and Newton-Raphson), :mod:`.straightline` (one position's
Newton step as generated Python), :mod:`.products` (BLAS products that stay
single-threaded), :mod:`.sweep` (the sweep's run), :mod:`.assembly` (one
position on the followed assembly), :mod:`.walks` (continuation in small
steps), :mod:`.record` (a sweep's results), :mod:`.crossing` (change points),
:mod:`.derivatives` (velocity to jerk), :mod:`.solve`, :mod:`.linkage` and
:mod:`.batch` (the entry points).
"""

from .batch import solve_loops_case
from .linkage import LoopResult, VectorLoopLinkage
from .newton import SINGULAR_CONDITION

__all__ = ["VectorLoopLinkage", "LoopResult", "solve_loops_case", "SINGULAR_CONDITION"]
