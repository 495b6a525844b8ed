"""Continuation walks of a sweep (:mod:`.sweep`) in small steps: to check a
position that Newton-Raphson reached off the prediction, through a singular
position where two assemblies meet (:mod:`.crossing`), and back onto the
followed assembly after a stretch that cannot be assembled.

:class:`Walks` holds these methods of the sweep's state (``Sweep``); every
walk keeps the followed orientation (the sign of det J, :mod:`.newton`).
"""

import math

import numpy as np

from ..errors import NotAssemblable, Singular
from ..status import NOT_ASSEMBLABLE, OK, SINGULAR
from .crossing import SWITCH_DISTANCE, ambiguity_message, crossing_note, other_branch
from .newton import CONVERGED, ORIENTATION_FLOOR

JUMP_TOLERANCE = 0.05   # [rad or length scale] beyond the predicted change
WALK_STEP = 0.05        # [rad] largest continuation step of a walk
MIN_WALK_STEP = 1e-6    # [rad] smallest step of a walk before it gives up
WALK_ITERATIONS = 8     # Newton steps a walk step may take before it is halved
MATCH_TOLERANCE = 1e-8  # [rad or length scale] two solutions are the same assembly


class _BranchJump(Singular):
    """Newton-Raphson reached closure only on another assembly."""


def sign_of(x):
    return math.copysign(1.0, x)


class Walks:
    """The walking methods of a sweep's state (mixed into ``Sweep``)."""

    # --- off the prediction: a jump, or through a singular position -----------
    def subdivide(self, i, t, it):
        """Position i converged far from the prediction (a jump) or with the
        other orientation than the followed assembly. Walk to it from the last
        solved position in small steps on the followed orientation
        (:meth:`follow`): if the walk arrives, Newton-Raphson had jumped and
        the walk's solution stands; if the orientation changes even within a
        step of MIN_WALK_STEP, a singular position where two assemblies meet
        lies there (a change point), and the sweep finds its own assembly past
        it (:meth:`switch`). Returns ``(q, iterations, slope, orient)`` or None
        (position i failed)."""
        t_a, q_a, s_a = self.state
        if s_a is None:
            self.fail(i, SINGULAR, _BranchJump(
                f"at theta2 = {np.degrees(t):.6g} deg Newton-Raphson reaches the loops' closure "
                f"only on another assembly, and the sweep cannot walk there from theta2 = "
                f"{np.degrees(t_a):.6g} deg. Sweep in smaller steps."))
            return None
        kind, data = self.follow(np.array(q_a), np.array(s_a), t_a, t, self.sign,
                                 float(self.orient[self.last]))
        if kind == "arrived":
            q_w, s_w, o_w = data
            return q_w, it, s_w, o_w
        if kind == "stuck":
            self.fail(i, SINGULAR, _BranchJump(
                f"near theta2 = {np.degrees(t_a + math.copysign(data, t - t_a)):.6g} deg "
                f"Newton-Raphson reaches the loops' closure only on another assembly: the "
                f"linkage passes a limit (toggle) position there. Sweep a range that avoids it."))
            return None
        t_p, q_p, o_p, s_p, t_n, q_n, o_n = data
        # the orientation is about linear in theta2 there
        w = o_p / (o_p - o_n) if o_p != o_n else 1.0
        return self.switch(i, t_p + w * (t_n - t_p), q_p + w * (q_n - q_p), s_p, t)

    def switch(self, i, t_c, q_c, v, t):
        """At position i (theta2 = t), past the singular position q_c at t_c
        that the continuation crossed along direction v (dq/dtheta2), find the
        solution with the followed orientation. Within SWITCH_DISTANCE of the
        crossing the two curves through q_c are told apart directly
        (:func:`.crossing.other_branch`); farther, at SWITCH_DISTANCE, and the
        sweep's own curve is followed from there to t. Returns ``(q,
        iterations, slope, orient)``, with a note, or None with position i
        failed and the positions past t_c blocked."""
        d = t - t_c
        t_w = t if abs(d) <= SWITCH_DISTANCE else t_c + math.copysign(SWITCH_DISTANCE, d)
        q_k, it, _, reason, s_k, o_k = self.system.newton1(q_c + v * (t_w - t_c), t_w, self.tol)
        near = found = None
        if reason == CONVERGED and s_k is not None:
            if abs(o_k) >= ORIENTATION_FLOOR and sign_of(o_k) == self.sign:
                near = np.asarray(q_k), it, np.asarray(s_k), o_k
            else:
                near = other_branch(self.system, t_c, q_c, t_w, np.asarray(q_k), self.sign,
                                    self.tol, JUMP_TOLERANCE)
        if near is not None and t_w == t:
            found = near
        elif near is not None:
            kind, data = self.follow(near[0], near[2], t_w, t, self.sign, near[3])
            if kind == "arrived":
                found = (data[0], near[1], data[1], data[2])
        if found is None:
            self.blocked = (t_c, math.copysign(1.0, d), i)
            self.fail(i, SINGULAR, Singular(ambiguity_message(t_c, t)))
            return None
        self.notes[i] = crossing_note(t_c, t)
        return found

    def follow(self, q, slope, t0, target, sign, orient=math.nan):
        """Continuation from (t0, q, slope, orient) to theta2 = target in steps of
        at most WALK_STEP, halved where a step jumps, does not close within
        WALK_ITERATIONS, or (``sign`` not None) lands on the other orientation.

        Returns ``(kind, data)``: ``("arrived", (q, slope, orient))``;
        ``("stuck", distance reached [rad])``; or, when the orientation changes
        within a step no longer than MIN_WALK_STEP, or a step lands on a
        singular position (``|orient|`` below the sweep's threshold: the walk
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
            if abs(h) >= abs(target - t):     # the last step lands on target exactly
                t_next, h = target, target - t
            else:
                t_next = t + h
            pred = q + slope * h
            change = float(np.max(np.abs(slope * h) / self.scale))
            qk, _, _, reason, sk, ok = self.system.newton1(pred, t_next, self.tol,
                                                           WALK_ITERATIONS)
            closed = (reason == CONVERGED and sk is not None
                      and not self.jumped(np.asarray(qk), pred, change))
            other = (closed and sign is not None and abs(ok) >= ORIENTATION_FLOOR
                     and sign_of(ok) != sign)
            if (closed and not other and sign is not None and math.isfinite(orient)
                    and not abs(ok) >= self.sample_singular):
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

    # --- after a stretch that cannot be assembled ------------------------------
    def rejoin(self, i, q_try, slope_try, orient_try):
        """Is the solution found at i, after a gap, on the followed assembly?

        Walk by continuation to theta2[i] from the nearest solved position
        below it and from the nearest above it (modulo the input's period, if
        it has one), nearer first; a walk that arrives defines the assembly.
        Returns ``(ok, q, slope, orient)``.
        """
        t = float(self.theta2[i])
        anchors = np.flatnonzero(self.sequential[:i] & (self.status[:i] == OK)
                                 & np.isfinite(self.slope[:i]).all(axis=1))
        d = t - self.theta2[anchors]
        period = self.system.period
        walks = []
        for forward in (True, False):
            if period:
                dist = np.remainder(d, period) if forward else np.remainder(d, period) - period
            else:
                dist = np.where(d >= 0 if forward else d <= 0, d, np.nan)
            if np.isfinite(dist).any():
                j = int(np.nanargmin(np.abs(dist)))
                walks.append((abs(float(dist[j])), int(anchors[j]), float(dist[j])))
        for _, a, dist in sorted(walks):
            key = (a, dist > 0)
            if key in self.walk_failed and abs(dist) > self.walk_failed[key]:
                continue            # an earlier walk from a stopped short of this
            reached = self.walk(a, dist)
            if isinstance(reached, float):
                self.walk_failed[key] = reached
                continue
            q_w, slope_w, orient_w = reached
            if dist != t - self.theta2[a]:   # the same configuration, whole turns away
                q_w, _, _, reason, slope_w, orient_w = self.system.newton1(q_w, t, self.tol)
                if reason != CONVERGED or slope_w is None or self.flipped(orient_w):
                    continue
                q_w = np.asarray(q_w)
            if np.max(np.abs(q_w - q_try) / self.scale) <= MATCH_TOLERANCE:
                return True, q_try, slope_try, orient_try
            return True, q_w, slope_w, orient_w
        self.fail(i, NOT_ASSEMBLABLE, NotAssemblable(
            f"at theta2 = {np.degrees(t):.6g} deg the loops close again after a range where "
            f"they cannot, but not on the assembly this sweep follows: no continuous path "
            f"from the positions solved before reaches it. Solve this range on its own, with "
            f"guesses for the assembly you want."))
        return False, None, None, None

    def walk(self, a, dist):
        """Continuation from solved position a over ``dist`` [rad] of theta2 on
        the followed orientation (:meth:`follow`). Returns (q, slope, orient) at
        theta2[a] + dist, or the distance [rad] it reached before it had to
        give up."""
        kind, data = self.follow(self.q[a], self.slope[a], float(self.theta2[a]),
                                 float(self.theta2[a]) + dist, self.sign, float(self.orient[a]))
        if kind == "arrived":
            return data
        return data if kind == "stuck" else abs(data[0] - float(self.theta2[a]))
