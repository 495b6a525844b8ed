"""Solving a vector-loop linkage at one position or along a sweep of theta2.

A sweep continues one assembly: each position starts from the previous
solution advanced by the velocity solution (dq/dtheta2 times the step). A
converged solution far from that prediction means Newton-Raphson crossed to
another assembly; the step is then subdivided, and a position still reached
only by a jump is reported ``singular`` rather than returned.
"""

import numpy as np

from ..errors import NoConvergence, Singular
from ..kernels import NOT_ASSEMBLABLE, OK, SINGULAR, SINGULAR_CONDITION

JUMP_TOLERANCE = 0.05   # [rad or length scale] beyond the predicted change
SUBSTEPS = 8


def _jumped(system, q, pred, change):
    return np.max(np.abs(q - pred) / system.scale) > JUMP_TOLERANCE + 0.5 * change


def solve_sweep(system, theta2, q0):
    """Positions along ``theta2`` (1-D array [rad]) from the guesses ``q0``.

    Returns ``(q, status, iterations, message)``: q (N, n_unknowns) with NaN
    where not valid, int8 status per position (0 ok, 1 not assemblable,
    2 only reachable by a branch jump), Newton iterations per position, and
    the first error message met (or None). Singular Jacobians at converged
    positions are flagged afterwards, on the whole stack at once.
    """
    N = len(theta2)
    nu = system.n_unknowns
    q = np.full((N, nu), np.nan)
    status = np.full(N, OK, dtype=np.int8)
    iterations = np.zeros(N, dtype=int)
    message = None
    q_prev, t_prev, slope = np.asarray(q0, dtype=float), None, None
    for i in range(N):
        t = float(theta2[i])
        try:
            if slope is None:
                qi, it, _, J, new_slope = system.solve_position(q_prev, t)
            else:
                pred = q_prev + slope * (t - t_prev)
                change = float(np.max(np.abs(slope * (t - t_prev)) / system.scale))
                qi, it, _, J, new_slope = system.solve_position(pred, t)
                if _jumped(system, qi, pred, change):
                    qi, it, J, new_slope = _subdivide(system, q_prev, t_prev, slope, t)
        except NoConvergence as exc:
            status[i] = NOT_ASSEMBLABLE
            message = message or exc
            continue
        except _BranchJump as exc:
            status[i] = SINGULAR
            message = message or exc
            continue
        iterations[i] = it
        q[i] = qi
        q_prev, t_prev, slope = qi, t, new_slope
    return q, status, iterations, message


class _BranchJump(Singular):
    """Newton-Raphson reached closure only on another assembly."""


def _subdivide(system, q_prev, t_prev, slope, t):
    """Walk from t_prev to t in small steps; raise _BranchJump if it still jumps."""
    total = 0
    for k in range(1, SUBSTEPS + 1):
        tk = t_prev + (t - t_prev) * k / SUBSTEPS
        pred = q_prev + slope * (tk - t_prev)
        change = float(np.max(np.abs(slope * (tk - t_prev)) / system.scale))
        qk, it, _, J, new_slope = system.solve_position(pred, tk)
        total += it
        if _jumped(system, qk, pred, change):
            raise _BranchJump(
                f"near theta2 = {np.degrees(tk):.6g} deg Newton-Raphson reaches the loops' "
                f"closure only on another assembly: the linkage passes a limit (toggle) "
                f"position there. Sweep a range that avoids it.")
        q_prev, t_prev, slope = qk, tk, new_slope
    return q_prev, total, J, slope


def singular_message(theta2, cond):
    return (f"the loop equations are singular at theta2 = {np.degrees(theta2):.6g} deg "
            f"(Jacobian condition measure {cond:.2e} < {SINGULAR_CONDITION:g}; its condition "
            f"number is about {2 / max(cond, 1e-300):.2e}): two links are aligned (a toggle or "
            f"limit position), so velocities and accelerations are not defined there. Move "
            f"theta2 away from it.")
