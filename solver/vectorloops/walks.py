"""Continuation in small steps along one curve of solutions q(theta2).

:class:`Continuation` knows only the loop equations (a :class:`.newton.LoopSystem`),
Newton-Raphson's tolerance, the length scale and the threshold below which a
solved position counts as singular. :meth:`Continuation.follow` walks from one
solution to another input angle, halving its step where Newton-Raphson jumps
or lands on the other orientation (the sign of det J, :mod:`.newton`), and
stops at a change in orientation (a singular position, :mod:`.crossing`).
It knows nothing of a sweep's results: :mod:`.assembly` decides with it which
solution a sweep keeps, and :mod:`.sweep` drives the sweep.
"""

import math

import numpy as np

from .newton import CONVERGED, ORIENTATION_FLOOR, step_tolerance

JUMP_TOLERANCE = 0.05  # [rad or length scale] beyond the predicted change
WALK_STEP = 0.05  # [rad] largest continuation step of a walk
MIN_WALK_STEP = 1e-6  # [rad] smallest step of a walk before it gives up
WALK_ITERATIONS = 8  # Newton steps a walk step may take before it is halved
MATCH_TOLERANCE = 1e-8  # [rad or length scale] two solutions are the same assembly
SAMPLE_SINGULAR = 100.0  # a solved position whose |orientation| is below this many times
# Newton's step tolerance (at most 1e-3) is treated as singular:
# its orientation's sign and its slope are not trusted


def sign_of(x):
    """The sign of ``x`` as +1.0 or -1.0 (of -0.0: -1.0)."""
    return math.copysign(1.0, x)


class Continuation:
    """Path following on the loop equations of ``system`` (a LoopSystem) with
    Newton-Raphson's convergence tolerance ``tol`` [-].

    ``scale`` (array) and ``scale_list`` (floats) are the unknowns' scales
    [rad or length scale]; ``sample_singular`` is the |orientation| below
    which a solution is singular (its orientation's sign and slope not
    trusted).
    """

    def __init__(self, system, tol):
        self.system, self.tol = system, tol
        self.scale = system.scale
        self.scale_list = [float(x) for x in system.scale]
        self.sample_singular = min(1e-3, SAMPLE_SINGULAR * step_tolerance(tol))

    def jumped(self, q, pred, change):
        """Did Newton-Raphson land at ``q`` further from the prediction ``pred``
        than the step explains? ``change`` is the step's largest scaled
        first-order change [rad or length scale]. Returns a bool."""
        limit = JUMP_TOLERANCE + 0.5 * change
        return any(abs(a - b) > limit * sc for a, b, sc in zip(q, pred, self.scale_list))

    def follow(self, q, slope, t0, target, sign, orient=math.nan):
        """Continuation from (t0, q, slope, orient) to theta2 = target [rad] in
        steps of at most WALK_STEP, halved where a step jumps, does not close
        within WALK_ITERATIONS, or (``sign`` not None) lands on the other
        orientation.

        Returns ``(kind, data)``: ``("arrived", (q, slope, orient))``;
        ``("stuck", distance reached [rad])``; or, when the orientation changes
        within a step no longer than MIN_WALK_STEP, or a step lands on a
        singular position (``|orient|`` below ``sample_singular``: the walk
        is at the crossing itself), ``("flip", (t_p, q_p, orient_p, slope_p,
        t_n, q_n, orient_n))`` on either side of it.
        """
        q = np.asarray(q, dtype=float)
        slope = np.asarray(slope, dtype=float)
        t = t0
        dist = target - t0
        h = math.copysign(min(WALK_STEP, abs(dist)), dist)
        while (target - t) * dist > 0.0:
            if not np.isfinite(slope).all():
                return "stuck", abs(t - t0)
            if abs(h) >= abs(target - t):  # the last step lands on target exactly
                t_next, h = target, target - t
            else:
                t_next = t + h
            pred = q + slope * h
            change = float(np.max(np.abs(slope * h) / self.scale))
            qk, _, _, reason, sk, ok = self.system.newton1(pred, t_next, self.tol, WALK_ITERATIONS)
            closed = (
                reason == CONVERGED
                and sk is not None
                and not self.jumped(np.asarray(qk), pred, change)
            )
            other = (
                closed and sign is not None and abs(ok) >= ORIENTATION_FLOOR and sign_of(ok) != sign
            )
            if (
                closed
                and not other
                and sign is not None
                and math.isfinite(orient)
                and not abs(ok) >= self.sample_singular
            ):
                return "flip", (t, q, orient, slope, t_next, np.asarray(qk), ok)
            if closed and not other:
                q, slope, t, orient = np.asarray(qk), np.asarray(sk), t_next, ok
                h = math.copysign(min(2.0 * abs(h), WALK_STEP), dist)
                continue
            if other and abs(h) <= MIN_WALK_STEP and math.isfinite(orient):
                return "flip", (t, q, orient, slope, t_next, np.asarray(qk), ok)
            h /= 2.0
            if abs(h) < MIN_WALK_STEP and not other:
                return "stuck", abs(t - t0)
        return "arrived", (q, slope, orient)
