"""The unit-free entry point: a description in SI solved from position to jerk."""

from dataclasses import dataclass, field

import numpy as np

from ..errors import Singular
from ..status import OK, SINGULAR
from . import joints
from .derivatives import point_motion, solve_derivatives
from .description import read_description
from .newton import DEFAULT_TOL, SINGULAR_CONDITION, LoopSystem, check_tol, condition
from .sweep import singular_message, solve_sweep


@dataclass(eq=False)
class LoopMotion:
    """A vector-loop linkage solved at N positions (SI floats).

    ``q`` (N, n_unknowns) the unknowns; per vector ``L`` and ``theta`` (N,
    n_vectors) and their time derivatives ``dL``, ``dth`` (lists by order);
    ``points``: [R, V, A, J] of every named point, complex (N, n_points);
    per position ``status`` (int8, :mod:`accelab.solver.status`), ``condition``,
    Newton ``iterations``; ``message`` (the first failed position's error,
    else what the sweep noted, else the first singular position's) and
    ``notes`` (position -> what the sweep decided there).
    """

    q: np.ndarray
    status: np.ndarray
    iterations: np.ndarray
    condition: np.ndarray
    message: object = None
    notes: dict = field(default_factory=dict)
    L: np.ndarray | None = None
    theta: np.ndarray | None = None
    dL: list | None = None
    dth: list | None = None
    points: list | None = None


def solve(system, theta2, omega2, alpha2=0.0, jerk2=0.0, order=3, tol=DEFAULT_TOL, batch=True):
    """Solve a :class:`LoopSystem` at an array of input angles (a sweep).

    ``tol`` is Newton-Raphson's convergence tolerance: the loop residual
    relative to the longest link (default 1e-13; see :meth:`LoopSystem.newton`).
    ``batch=False`` walks the sweep position by position instead of solving
    the positions between a coarse chain together (same results; slower).

    Returns a :class:`LoopMotion` (notes: where the sweep passed a change
    point on its own assembly, or left a singular first position; see
    :mod:`.sweep`).
    """
    theta2 = np.atleast_1d(np.asarray(theta2, dtype=float))
    N = len(theta2)
    inputs = [np.broadcast_to(np.asarray(x, dtype=float), (N,)) for x in (omega2, alpha2, jerk2)]
    tol = check_tol(tol)
    q, status, iterations, message, notes = solve_sweep(
        system, theta2, system.model.guess, tol, batch
    )
    if message is None and notes:
        message = Singular(" ".join(notes.values()))
    ok = status == OK
    nv = len(system.fixed_length)
    out = LoopMotion(
        q=q,
        status=status,
        iterations=iterations,
        message=message,
        notes=notes,
        condition=np.full(N, np.nan),
    )
    L = np.full((N, nv), np.nan)
    theta = np.full((N, nv), np.nan)
    dL = [np.full((N, nv), np.nan) for _ in range(order)]
    dth = [np.full((N, nv), np.nan) for _ in range(order)]
    npts = system.model.point_signs.shape[0]
    pts = [np.full((N, npts), np.nan + 0j) for _ in range(order + 1)]
    if ok.any():
        d = solve_derivatives(system, q[ok], theta2[ok], [x[ok] for x in inputs], order)
        L[ok], theta[ok] = d["L"], d["theta"]
        for n in range(order):
            dL[n][ok], dth[n][ok] = d["dL"][n], d["dth"][n]
        for n, p in enumerate(point_motion(system, d, order)):
            pts[n][ok] = p
        cond = condition(d["J"], system.model)
        out.condition[ok] = cond
        singular = np.zeros(N, dtype=bool)
        singular[ok] = ~(cond >= SINGULAR_CONDITION)
        # two joints meeting: round-off grows with the derivative's order (joints.py)
        meet, why = joints.meeting(system.model, d["L"], d["theta"], cond, order)
        singular[np.flatnonzero(ok)[meet]] = True
        if singular.any():  # positions stand; their derivatives cannot be vouched for
            status[singular] = SINGULAR
            for arr in dL + dth + pts[1:]:
                arr[singular] = np.nan
            i = int(np.flatnonzero(singular)[0])
            if why is not None and int(np.flatnonzero(ok)[why[0]]) == i:
                text = joints.message(
                    theta2[i], *why[1:], model=system.model, unit=system.unit, order=order
                )
            else:
                text = singular_message(theta2[i], out.condition[i])
            out.message = out.message or Singular(text, condition=float(out.condition[i]))
    unit = system.unit  # back from the system's normalized lengths
    if unit != 1.0:
        q[:, system.model.unknown_is_length] *= unit
        L *= unit
        for x in dL + pts:
            x *= unit
    out.L, out.theta, out.dL, out.dth, out.points = L, theta, dL, dth, pts
    return out


def system_from_case(case):
    """Read a description dict (quantity strings) into a ready LoopSystem."""
    return LoopSystem(read_description(case))
