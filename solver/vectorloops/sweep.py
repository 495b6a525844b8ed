"""Solving a vector-loop linkage at one position or along a sweep of theta2.

A sweep continues one assembly: each position starts from the previous
solution advanced by the velocity solution (dq/dtheta2 times the step). A
converged solution far from that prediction means Newton-Raphson crossed to
another assembly; the step is then subdivided, and a position still reached
only by a jump is reported ``singular`` rather than returned.

To be fast the sweep does this sequential continuation only on a coarse
subset of the positions (steps in theta2 that adapt to how fast the solution
bends, where the input array is monotonic), then solves every position in
between in one batched Newton-Raphson (numpy over positions) from cubic
Hermite interpolation of the coarse solutions and their slopes dq/dtheta2. Each
batched position must converge close to its interpolated guess; an interval
where one does not (a toggle nearby, a non-assemblable stretch, another
assembly within reach) is walked again position by position, and if that walk
disagrees with the coarse chain the sweep restarts from there. Results are
the same as the position-by-position walk to round-off (``batch=False``
gives that walk).

After a stretch that cannot be assembled, the first position that closes
again is accepted only if a continuation walk from a solved position (the
nearest below it and the nearest above it in theta2, modulo a turn of the
crank when the input drives only whole gear ratios) reaches it on the
followed assembly; otherwise it is reported ``not_assemblable`` on this
assembly, with a message.

The followed assembly has an *orientation* (the sign of det J, see
:mod:`.newton`), which can change along a continuous path only through a
singular position. Every solved position is checked against it. A position
reached with the other orientation means either that Newton-Raphson jumped
(a walk in small steps then stays on the assembly) or that the sweep passed a
singular position where two assemblies meet, a change point: there the
sweep stays on the assembly with its orientation (:mod:`.crossing`) and says
so in a note, or, if it cannot find it, marks the positions past the change
point ``singular``; it never reports the other assembly as if it were the
same. A sweep that starts on a singular position reports that position
(``singular``, from its condition) and continues from the next one that
converges, with a note that the guesses did not choose the assembly.
"""

import math

import numpy as np

from ..errors import Singular
from ..status import NOT_ASSEMBLABLE, OK, SINGULAR
from .crossing import ambiguity_message, singular_passage_note, singular_start_note
from .newton import (CONVERGED, DEFAULT_TOL, ORIENTATION_FLOOR, SINGULAR_CONDITION,
                     SINGULAR_STEP, condition,
                     no_convergence, step_tolerance)
from .walks import JUMP_TOLERANCE, MATCH_TOLERANCE, Walks, sign_of

COARSE_STEP = 0.25      # [rad] first theta2 step between sequentially solved positions
COARSE_RANGE = (0.02, 0.6)  # [rad] the step adapts within this range
COARSE_TARGET = 0.005   # [rad or length scale] aimed-at chord/slope mismatch per step
MAX_STRIDE = 256        # most positions between two sequentially solved ones
MIN_STRIDE = 2          # below this, walk position by position
GAP_CHUNK = 16          # positions tried together while the loops do not close
HIGHER_ORDER_CAP = 0.1  # [rad or length scale] largest 2nd+3rd order predictor term
SAMPLE_SINGULAR = 100.0  # a solved position whose |orientation| is below this many times
                         # Newton's step tolerance (at most 1e-3) is treated as singular:
                         # its orientation's sign and its slope are not trusted


class Sweep(Walks):
    """The state of one sweep: results so far and the continuation state."""

    def __init__(self, system, theta2, q0, tol):
        self.system, self.theta2, self.tol = system, theta2, tol
        N, nu = len(theta2), system.n_unknowns
        self.q = np.full((N, nu), np.nan)
        self.slope = np.full((N, nu), np.nan)     # at sequentially solved positions
        self.orient = np.full(N, np.nan)          # orientation of solved positions
        self.status = np.full(N, OK, dtype=np.int8)
        self.iterations = np.zeros(N, dtype=int)
        self.sequential = np.zeros(N, dtype=bool)  # solved by continuation (anchors)
        self.errors = {}
        self.notes = {}         # position -> what the sweep decided there (crossings)
        self.guess = np.asarray(q0, dtype=float)
        self.last = None        # index of the last position solved by continuation
        self.taylor = None      # 2nd and 3rd Taylor coefficients of q(theta2) at last
        self.gap = False        # a position failed since self.last
        self.walk_failed = {}   # (anchor, direction) -> distance a rejoining walk failed at
        self.failures = 0       # consecutive failed positions
        self.coarse = COARSE_STEP   # current coarse step [rad]
        self.scale = system.scale
        self.scale_list = [float(x) for x in system.scale]
        # the continuation state in plain floats: (theta2, q, slope or None) of
        # self.last; the per-position bookkeeping of a 4-unknown linkage is
        # cheaper in Python than in numpy calls
        self.state = None
        self.sign = None        # orientation (+1 / -1) of the followed assembly
        self.singular_last = False  # self.last is a singular position
        self.singular_start = None  # index of a singular first position, until the sign is set
        self.blocked = None     # (theta2, direction): past it the assembly was lost
        self.sample_singular = min(1e-3, SAMPLE_SINGULAR * step_tolerance(tol))
        self.theta2_list = [float(x) for x in theta2]

    # --- bookkeeping --------------------------------------------------------
    def accept(self, i, q, it, slope, orient):
        q = [float(x) for x in q]
        singular = not abs(orient) >= self.sample_singular
        if singular:
            slope = None            # dq/dtheta2 means nothing at a singular position
        slope = None if slope is None else [float(x) for x in slope]
        if slope is not None and not all(math.isfinite(x) for x in slope):
            slope = None
        self.q[i], self.iterations[i], self.status[i] = q, it, OK
        self.slope[i] = np.nan if slope is None else slope
        self.orient[i] = orient
        self.sequential[i] = True
        t = float(self.theta2[i])
        if not singular and self.sign is None:
            self.sign = sign_of(orient)
            if self.singular_start is not None:
                self.notes[i] = singular_start_note(float(self.theta2[self.singular_start]), t)
                self.singular_start = None
        elif singular and self.sign is None and self.state is None:
            self.singular_start = i
        # second and third derivatives of q(theta2) at i from the cubic through the
        # previous solved position: the predictor becomes a cubic Taylor polynomial
        self.taylor = None
        if self.state is not None and not self.gap and slope is not None:
            t0, q0, s0 = self.state
            h = t - t0
            if s0 is not None and abs(h) > 1e-9:
                dq = [a - b for a, b in zip(q0, q)]
                h2, h3 = h * h, h * h * h
                self.taylor = ([(3 * d + h * (a + 2 * b)) / h2 for d, a, b in zip(dq, s0, slope)],
                               [(2 * d + h * (a + b)) / h3 for d, a, b in zip(dq, s0, slope)])
        self.state = (t, q, slope)
        self.last, self.gap = i, False
        self.singular_last = singular
        self.failures = 0

    def restore(self, a):
        """Continue from solved position a (to walk an interval again)."""
        slope = self.slope[a]
        self.state = (float(self.theta2[a]), [float(x) for x in self.q[a]],
                      [float(x) for x in slope] if np.isfinite(slope).all() else None)
        self.last, self.gap, self.failures, self.taylor = a, False, 0, None
        self.singular_last = not abs(self.orient[a]) >= self.sample_singular

    def fail(self, i, status, exc):
        self.status[i] = status
        self.q[i] = np.nan
        self.errors[i] = exc
        self.failures += 1
        if self.last is not None:
            self.gap = True

    def message(self):
        bad = [i for i in self.errors if self.status[i] != OK]
        return self.errors[min(bad)] if bad else None

    def jumped(self, q, pred, change):
        """Did Newton-Raphson land further from the prediction than the step explains?"""
        limit = JUMP_TOLERANCE + 0.5 * change
        return any(abs(a - b) > limit * sc for a, b, sc in zip(q, pred, self.scale_list))

    def flipped(self, orient):
        """Is ``orient`` (trusted in sign) the other orientation than the followed one?"""
        return (self.sign is not None and abs(orient) >= ORIENTATION_FLOOR
                and sign_of(orient) != self.sign)

    def predict(self, t):
        """Continuation predictor from the last solved position to theta2 = t:
        ``(guess, change)``, ``change`` the largest scaled first-order change
        (None without a slope). The cubic Taylor terms are used only where they
        stay small (< HIGHER_ORDER_CAP), so they never carry a guess far from
        the tangent. ``t`` a float gives lists, an array gives arrays."""
        if not isinstance(t, float):
            return self._predict_many(np.asarray(t, dtype=float))
        if self.state is None:
            return [float(x) for x in self.guess], None
        t0, q, slope = self.state
        if slope is None:
            return list(q), None
        d = t - t0
        sc = self.scale_list
        lin = [x * d for x in slope]
        change = max(abs(x) / c for x, c in zip(lin, sc))
        guess = [a + b for a, b in zip(q, lin)]
        if self.taylor is not None:
            c2, c3 = self.taylor
            hot = [d * d * (a + b * d) for a, b in zip(c2, c3)]
            if max(abs(x) / c for x, c in zip(hot, sc)) <= HIGHER_ORDER_CAP:
                guess = [a + b for a, b in zip(guess, hot)]
        return guess, change

    def _predict_many(self, t):
        shape = t.shape + (self.system.n_unknowns,)
        if self.state is None:
            return np.broadcast_to(self.guess, shape), None
        t0, q, slope = self.state
        if slope is None:
            return np.broadcast_to(np.array(q), shape), None
        d = (t - t0)[..., None]
        lin = np.array(slope) * d
        guess = np.array(q) + lin
        if self.taylor is not None:
            c2, c3 = np.array(self.taylor[0]), np.array(self.taylor[1])
            hot = d * d * (c2 + c3 * d)
            small = np.max(np.abs(hot) / self.scale, axis=-1, keepdims=True) <= HIGHER_ORDER_CAP
            guess = guess + np.where(small, hot, 0.0)
        return guess, np.max(np.abs(lin) / self.scale, axis=-1)

    # --- one position by continuation ----------------------------------------
    def step(self, i, result=None):
        """Solve position i from the continuation state (or post-process the
        Newton ``result`` already computed from that same prediction)."""
        t = float(self.theta2[i])
        if self.blocked is not None and (t - self.blocked[0]) * self.blocked[1] > 0:
            self.fail(i, SINGULAR, Singular(ambiguity_message(self.blocked[0], t)))
            return False
        pred, change = self.predict(t)
        leaving = self.singular_last and self.state is not None
        if result is None or (leaving and result.reason == SINGULAR_STEP):
            result = self.system.newton1(pred, t, self.tol, least_squares=leaving)
        q, it, res, reason, slope, orient = result
        if reason == SINGULAR_STEP:
            result = self.singular_step(pred, t)
            if result is not None:
                q, it, res, reason, slope, orient = result
        if reason != CONVERGED:
            self.fail(i, NOT_ASSEMBLABLE, no_convergence(t, res * self.system.unit, it, reason))
            return False
        trusted = abs(orient) >= self.sample_singular
        if self.gap:  # across a gap the prediction means little: walk to check instead
            ok, q, slope, orient = self.rejoin(i, np.asarray(q), slope, orient)
            if not ok:
                return False
        elif ((change is not None and self.jumped(q, pred, change))
              or (self.flipped(orient) and trusted and not leaving)):
            found = self.subdivide(i, t, it)
            if found is None:
                return False
            q, it, slope, orient = found
        elif leaving and self.sign is not None and trusted:
            t_s, q_c = float(self.state[0]), np.array(self.state[1])
            if self.flipped(orient) and t != t_s:
                found = self.switch(i, t_s, q_c, (np.asarray(q) - q_c) / (t - t_s), t)
                if found is None:
                    return False
                q, it, slope, orient = found
            else:
                self.notes[i] = singular_passage_note(t_s, t)
        self.accept(i, q, it, slope, orient)
        return True

    def singular_step(self, q0, t):
        """Newton-Raphson met an exactly singular Jacobian on its way from q0:
        try again with least-squares steps there. The result is returned if it
        converges, except for the first position of a sweep, where it must
        also be singular itself (a condition below SINGULAR_CONDITION: it is
        then accepted and reported ``singular``); otherwise None: the guesses,
        not the position, are singular, and they choose no assembly."""
        result = self.system.newton1(q0, t, self.tol, least_squares=True)
        if result.reason != CONVERGED:
            return None
        if self.state is not None:
            return result
        J = self.system.evaluate(np.array([result.q]), np.array([t]))[1]
        if not condition(J, self.system.model)[0] < SINGULAR_CONDITION:
            return None
        return result

    def scan_gap(self, i, stop):
        """Positions i..stop-1 while the loops do not close: every one starts from
        the same prediction, so Newton-Raphson runs on them together. Processes
        positions until one is accepted; returns the next index."""
        idx = np.arange(i, stop)
        t = self.theta2[idx]
        q0, _ = self.predict(t)
        q, it, res, reason, slope, orient = self.system.newton(q0, t, self.tol)
        for k, n in enumerate(idx):
            result = (q[k], int(it[k]), float(res[k]), reason[k],
                      slope[k] if reason[k] == CONVERGED else None, float(orient[k]))
            if self.step(n, result):
                return n + 1
        return stop

    # --- the coarse chain and the batched positions between ----------------------
    def coarse_end(self, a):
        """Index b of the next sequentially solved position after a: theta2 monotonic
        on [a, b], |theta2[b] - theta2[a]| <= the coarse step, b - a <= MAX_STRIDE
        (at least a + 1)."""
        t = self.theta2_list
        stop = min(a + MAX_STRIDE, len(t) - 1)
        if stop <= a + 1:
            return a + 1
        t0, prev = t[a], t[a + 1]
        sign = math.copysign(1.0, prev - t0)
        if prev == t0:
            return a + 1
        limit = self.coarse
        b = a + 1
        while b < stop:
            nxt = t[b + 1]
            if (nxt - prev) * sign <= 0.0 or (nxt - t0) * sign > limit:
                break
            b, prev = b + 1, nxt
        return b

    def coarse_step(self, a, b):
        """Continuation from a straight to b; accepted only without a jump, on the
        followed orientation away from singular positions, and with slopes at
        both ends consistent with the chord (a smooth branch)."""
        t = float(self.theta2[b])
        pred, change = self.predict(t)
        q, it, res, reason, slope, orient = self.system.newton1(pred, t, self.tol)
        lo, hi = COARSE_RANGE
        if (reason != CONVERGED or slope is None or not abs(orient) >= self.sample_singular
                or self.flipped(orient)):
            self.coarse = max(lo, 0.5 * self.coarse)
            return False
        ta, qa, sa = self.state
        h = t - ta
        error = max(abs(q1 - q0 - 0.5 * h * (s0 + s1)) / sc
                    for q0, q1, s0, s1, sc in zip(qa, q, sa, slope, self.scale_list))
        # the mismatch grows like h**3: aim the next step at COARSE_TARGET
        grow = 0.9 * (COARSE_TARGET / max(error, 1e-12)) ** (1 / 3)
        self.coarse = min(hi, max(lo, abs(h) * min(2.0, max(0.5, grow))))
        if error > JUMP_TOLERANCE or self.jumped(q, pred, change):
            return False
        self.accept(b, q, it, slope, orient)
        return True

    def batch(self, intervals):
        """Solve the interior positions of the coarse ``intervals`` [(a, b), ...]
        together. Returns the intervals where some position failed its check."""
        if not intervals:
            return []
        A = np.array([a for a, b in intervals])
        Bn = np.array([b for a, b in intervals])
        counts = Bn - A - 1
        owner = np.repeat(np.arange(len(intervals)), counts)
        idx = np.concatenate([np.arange(a + 1, b) for a, b in intervals])
        th = self.theta2
        guess, rate = self.hermite(idx, A[owner], Bn[owner])
        q, it, res, reason, _, orient = self.system.newton(guess, th[idx], self.tol,
                                                           slopes=False)
        dt = np.abs(th[idx] - th[idx - 1])[:, None]
        change = np.max(np.abs(rate * dt) / self.scale, axis=1)
        off = np.max(np.abs(q - guess) / self.scale, axis=1)
        good = (reason == CONVERGED) & (off <= JUMP_TOLERANCE + 0.5 * change)
        if self.sign is not None:   # never the other orientation
            good &= ~((np.abs(orient) >= ORIENTATION_FLOOR) & (np.sign(orient) != self.sign))
        self.q[idx], self.iterations[idx], self.orient[idx] = q, it, orient
        bad = np.unique(owner[~good])
        return [intervals[k] for k in bad]

    def hermite(self, idx, a, b):
        """Cubic Hermite interpolation of q and dq/dtheta2 at positions idx between
        solved positions a and b (arrays alike): (guess, rate)."""
        th = self.theta2
        h = (th[b] - th[a])[:, None]
        s = ((th[idx] - th[a]) / (th[b] - th[a]))[:, None]
        s2, s3 = s * s, s * s * s
        qa, qb, sa, sb = self.q[a], self.q[b], self.slope[a] * h, self.slope[b] * h
        guess = ((2 * s3 - 3 * s2 + 1) * qa + (s3 - 2 * s2 + s) * sa
                 + (3 * s2 - 2 * s3) * qb + (s3 - s2) * sb)
        rate = ((6 * s2 - 6 * s) * qa + (3 * s2 - 4 * s + 1) * sa
                + (6 * s - 6 * s2) * qb + (3 * s2 - 2 * s) * sb) / h
        return guess, rate

    def reset_after(self, b):
        """Forget everything solved after position b (the chain is restarted there)."""
        self.q[b + 1:] = np.nan
        self.slope[b + 1:] = np.nan
        self.orient[b + 1:] = np.nan
        self.status[b + 1:] = OK
        self.iterations[b + 1:] = 0
        self.sequential[b + 1:] = False
        self.errors = {i: e for i, e in self.errors.items() if i <= b}
        self.notes = {i: e for i, e in self.notes.items() if i <= b}
        self.walk_failed = {k: v for k, v in self.walk_failed.items() if k[0] <= b}
        if self.blocked is not None and self.blocked[2] > b:
            self.blocked = None

    def advance(self, i, stop):
        """Solve position i by continuation; while the loops do not close (the
        position before failed) try a chunk of positions at once. Returns the
        next index."""
        if self.failures and (self.last is None or self.gap):
            chunk = max(GAP_CHUNK, min(self.failures, 256))
            return self.scan_gap(i, min(stop, i + chunk))
        self.step(i)
        return i + 1

    def walk_dense(self, start, stop):
        """Position by position from start to stop - 1 (no coarse steps)."""
        i = start
        while i < stop:
            i = self.advance(i, stop)

    def run(self, batch=True):
        N = len(self.theta2)
        start = 0
        while start < N:
            intervals = []
            i = start
            dense_until = -1
            while i < N:
                if (batch and i > dense_until and self.last == i - 1 and not self.gap
                        and self.state[2] is not None):
                    b = self.coarse_end(i - 1)
                    if b - (i - 1) >= MIN_STRIDE:
                        if self.coarse_step(i - 1, b):
                            intervals.append((i - 1, b))
                            i = b + 1
                            continue
                        dense_until = b
                i = self.advance(i, N)
            start = N
            for a, b in self.batch(intervals):
                # walk this interval again position by position from a
                q_b, slope_b, it_b = self.q[b].copy(), self.slope[b].copy(), self.iterations[b]
                orient_b = self.orient[b]
                self.restore(a)
                self.walk_dense(a + 1, b + 1)
                if (self.status[b] == OK and self.last == b
                        and np.max(np.abs(self.q[b] - q_b) / self.scale) <= MATCH_TOLERANCE):
                    self.q[b], self.slope[b], self.iterations[b] = q_b, slope_b, it_b
                    self.orient[b] = orient_b
                    continue
                # the walk reached b differently: the chain after b is void
                self.reset_after(b)
                start = b + 1
                break
        return self.q, self.status, self.iterations, self.message()


def solve_sweep(system, theta2, q0, tol=DEFAULT_TOL, batch=True):
    """Positions along ``theta2`` (1-D array [rad]) from the guesses ``q0``.

    Parameters
    ----------
    tol : float
        Newton-Raphson's convergence tolerance [-]: the loop residual relative
        to the length scale (see :meth:`LoopSystem.newton`).
    batch : bool
        Solve the positions between a coarse sequential chain together
        (default); False walks position by position (the reference path).

    Returns ``(q, status, iterations, message, notes)``: q (N, n_unknowns)
    with NaN where not valid, int8 status per position (0 ok, 1 not
    assemblable, 2 only reachable by a branch jump, or past a change point
    where the followed assembly was lost), Newton iterations per position,
    the error of the first failed position (or None), and ``notes``: a dict
    from position to what the sweep decided there without failing it
    (passing a change point on its own assembly, leaving a singular first
    position). Singular Jacobians at converged positions are flagged
    afterwards, on the whole stack at once.
    """
    theta2 = np.asarray(theta2, dtype=float)
    sweep = Sweep(system, theta2, q0, tol)
    q, status, iterations, message = sweep.run(batch)
    return q, status, iterations, message, {int(i): sweep.notes[i] for i in sorted(sweep.notes)}


def singular_message(theta2, cond):
    """The message of a singular position: ``theta2`` [rad] and the Jacobian's
    condition measure ``cond`` (1 best, 0 singular) [-]."""
    return (f"the loop equations are singular at theta2 = {np.degrees(theta2):.6g} deg "
            f"(Jacobian condition measure {cond:.2e} < {SINGULAR_CONDITION:g}; its condition "
            f"number is about {2 / max(cond, 1e-300):.2e}): two links are aligned (a toggle or "
            f"limit position), so velocities and accelerations are not defined there. Move "
            f"theta2 away from it.")
