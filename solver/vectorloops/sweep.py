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
"""

import math

import numpy as np

from ..errors import NotAssemblable, Singular
from ..kernels import NOT_ASSEMBLABLE, OK, SINGULAR, SINGULAR_CONDITION
from .newton import CONVERGED, DEFAULT_TOL, no_convergence

JUMP_TOLERANCE = 0.05   # [rad or length scale] beyond the predicted change
SUBSTEPS = 8
COARSE_STEP = 0.25      # [rad] first theta2 step between sequentially solved positions
COARSE_RANGE = (0.02, 0.6)  # [rad] the step adapts within this range
COARSE_TARGET = 0.005   # [rad or length scale] aimed-at chord/slope mismatch per step
MAX_STRIDE = 64         # most positions between two sequentially solved ones
MIN_STRIDE = 4          # below this, walk position by position
GAP_CHUNK = 16          # positions tried together while the loops do not close
WALK_STEP = 0.05        # [rad] continuation step when rejoining the assembly after a gap
MIN_WALK_STEP = 1e-6    # [rad] smallest step of that walk before it gives up
WALK_ITERATIONS = 8     # Newton steps a walk step may take before it is halved
MATCH_TOLERANCE = 1e-8  # [rad or length scale] two solutions are the same assembly
HIGHER_ORDER_CAP = 0.1  # [rad or length scale] largest 2nd+3rd order predictor term


class _BranchJump(Singular):
    """Newton-Raphson reached closure only on another assembly."""


class _Sweep:
    """The state of one sweep: results so far and the continuation state."""

    def __init__(self, system, theta2, q0, tol):
        self.system, self.theta2, self.tol = system, theta2, tol
        N, nu = len(theta2), system.n_unknowns
        self.q = np.full((N, nu), np.nan)
        self.slope = np.full((N, nu), np.nan)     # at sequentially solved positions
        self.status = np.full(N, OK, dtype=np.int8)
        self.iterations = np.zeros(N, dtype=int)
        self.sequential = np.zeros(N, dtype=bool)  # solved by continuation (anchors)
        self.errors = {}
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

    # --- bookkeeping --------------------------------------------------------
    def accept(self, i, q, it, slope):
        q = [float(x) for x in q]
        slope = None if slope is None else [float(x) for x in slope]
        if slope is not None and not all(math.isfinite(x) for x in slope):
            slope = None
        self.q[i], self.iterations[i], self.status[i] = q, it, OK
        self.slope[i] = np.nan if slope is None else slope
        self.sequential[i] = True
        # second and third derivatives of q(theta2) at i from the cubic through the
        # previous solved position: the predictor becomes a cubic Taylor polynomial
        t = float(self.theta2[i])
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
        self.failures = 0

    def restore(self, a):
        """Continue from solved position a (to walk an interval again)."""
        slope = self.slope[a]
        self.state = (float(self.theta2[a]), [float(x) for x in self.q[a]],
                      [float(x) for x in slope] if np.isfinite(slope).all() else None)
        self.last, self.gap, self.failures, self.taylor = a, False, 0, None

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

    def predict(self, t):
        """Continuation predictor from the last solved position to theta2 = t:
        ``(guess, change)``, ``change`` the largest scaled first-order change
        (None without a slope). The cubic Taylor terms are used only where they
        stay small (< HIGHER_ORDER_CAP), so they never carry a guess far from
        the tangent. ``t`` a float gives lists, an array gives arrays."""
        if np.ndim(t):
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
        pred, change = self.predict(t)
        if result is None:
            result = self.system.newton1(pred, t, self.tol)
        q, it, res, reason, slope = result
        if reason != CONVERGED:
            self.fail(i, NOT_ASSEMBLABLE, no_convergence(t, res, it, reason))
            return False
        if self.gap:  # across a gap the prediction means little: walk to check instead
            ok, q, slope = self.rejoin(i, np.asarray(q), slope)
            if not ok:
                return False
        elif change is not None and self.jumped(q, pred, change):
            try:
                q, it, slope = self.subdivide(t)
            except _BranchJump as exc:
                self.fail(i, SINGULAR, exc)
                return False
        self.accept(i, q, it, slope)
        return True

    def subdivide(self, t):
        """Walk from the last solved position to t in small steps; raise
        _BranchJump if it still jumps."""
        q_prev = self.q[self.last]
        t_prev = float(self.theta2[self.last])
        slope = self.slope[self.last]
        total = 0
        for k in range(1, SUBSTEPS + 1):
            tk = t_prev + (t - t_prev) * k / SUBSTEPS
            h = tk - (t_prev + (t - t_prev) * (k - 1) / SUBSTEPS)
            pred = q_prev + slope * h
            change = float(np.max(np.abs(slope * h) / self.scale))
            qk, it, res, reason, new_slope = self.system.newton1(pred, tk, self.tol)
            total += it
            if reason != CONVERGED or new_slope is None or self.jumped(np.asarray(qk), pred,
                                                                         change):
                raise _BranchJump(
                    f"near theta2 = {np.degrees(tk):.6g} deg Newton-Raphson reaches the loops' "
                    f"closure only on another assembly: the linkage passes a limit (toggle) "
                    f"position there. Sweep a range that avoids it.")
            q_prev, slope = np.asarray(qk), np.asarray(new_slope)
        return q_prev, total, slope

    # --- after a stretch that cannot be assembled ------------------------------
    def rejoin(self, i, q_try, slope_try):
        """Is the solution found at i, after a gap, on the followed assembly?

        Walk by continuation to theta2[i] from the nearest solved position
        below it and from the nearest above it (modulo the input's period, if
        it has one), nearer first; a walk that arrives defines the assembly.
        Returns ``(ok, q, slope)``.
        """
        t = float(self.theta2[i])
        anchors = np.flatnonzero(self.sequential[:i] & (self.status[:i] == OK))
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
            q_w, slope_w = reached
            if dist != t - self.theta2[a]:   # the same configuration, whole turns away
                q_w, _, _, reason, slope_w = self.system.newton1(q_w, t, self.tol)
                if reason != CONVERGED or slope_w is None:
                    continue
                q_w = np.asarray(q_w)
            if np.max(np.abs(q_w - q_try) / self.scale) <= MATCH_TOLERANCE:
                return True, q_try, slope_try
            return True, q_w, slope_w
        self.fail(i, NOT_ASSEMBLABLE, NotAssemblable(
            f"at theta2 = {np.degrees(t):.6g} deg the loops close again after a range where "
            f"they cannot, but not on the assembly this sweep follows: no continuous path "
            f"from the positions solved before reaches it. Solve this range on its own, with "
            f"guesses for the assembly you want."))
        return False, None, None

    def walk(self, a, dist):
        """Continuation from solved position a over ``dist`` [rad] of theta2, in
        steps of at most WALK_STEP, halved where a step jumps or does not close
        within WALK_ITERATIONS. Returns (q, slope) at theta2[a] + dist, or the
        distance [rad] it reached before it had to give up."""
        q = self.q[a]
        slope = self.slope[a]
        t0 = t = float(self.theta2[a])
        target = t + dist
        h = math.copysign(min(WALK_STEP, abs(dist)), dist)
        while abs(target - t) > 0.0:
            if not np.isfinite(slope).all():
                return abs(t - t0)
            h = math.copysign(min(abs(h), abs(target - t)), dist)
            pred = q + slope * h
            change = float(np.max(np.abs(slope * h) / self.scale))
            qk, _, _, reason, sk = self.system.newton1(pred, t + h, self.tol, WALK_ITERATIONS)
            if reason == CONVERGED and sk is not None and not self.jumped(np.asarray(qk), pred,
                                                                          change):
                q, slope, t = np.asarray(qk), np.asarray(sk), t + h
                h = math.copysign(min(2.0 * abs(h), WALK_STEP), dist)
                continue
            h /= 2.0
            if abs(h) < MIN_WALK_STEP:
                return abs(t - t0)
        return q, slope

    def scan_gap(self, i, stop):
        """Positions i..stop-1 while the loops do not close: every one starts from
        the same prediction, so Newton-Raphson runs on them together. Processes
        positions until one is accepted; returns the next index."""
        idx = np.arange(i, stop)
        t = self.theta2[idx]
        q0, _ = self.predict(t)
        q, it, res, reason, slope = self.system.newton(q0, t, self.tol)
        for k, n in enumerate(idx):
            result = (q[k], int(it[k]), float(res[k]), reason[k],
                      slope[k] if reason[k] == CONVERGED else None)
            if self.step(n, result):
                return n + 1
        return stop

    # --- the coarse chain and the batched positions between ----------------------
    def coarse_end(self, a):
        """Index b of the next sequentially solved position after a: theta2 monotonic
        on [a, b], |theta2[b] - theta2[a]| <= COARSE_STEP, b - a <= MAX_STRIDE."""
        t = self.theta2
        w = t[a:a + MAX_STRIDE + 1]
        if len(w) < 2:
            return a + 1
        d = np.diff(w)
        sign = np.sign(d[0])
        if sign == 0:
            return a + 1
        steps = d * sign
        run = len(steps) if (steps > 0).all() else int(np.argmin(steps > 0))
        dist = (w[1:run + 1] - w[0]) * sign
        n = int(np.searchsorted(dist, self.coarse, side="right"))
        return a + max(n, 1)

    def coarse_step(self, a, b):
        """Continuation from a straight to b; accepted only without a jump and with
        slopes at both ends consistent with the chord (a smooth branch)."""
        t = float(self.theta2[b])
        pred, change = self.predict(t)
        q, it, res, reason, slope = self.system.newton1(pred, t, self.tol)
        lo, hi = COARSE_RANGE
        if reason != CONVERGED or slope is None:
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
        self.accept(b, q, it, slope)
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
        q, it, res, reason, _ = self.system.newton(guess, th[idx], self.tol, slopes=False)
        dt = np.abs(th[idx] - th[idx - 1])[:, None]
        change = np.max(np.abs(rate * dt) / self.scale, axis=1)
        off = np.max(np.abs(q - guess) / self.scale, axis=1)
        good = (reason == CONVERGED) & (off <= JUMP_TOLERANCE + 0.5 * change)
        self.q[idx], self.iterations[idx] = q, it
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
        self.status[b + 1:] = OK
        self.iterations[b + 1:] = 0
        self.sequential[b + 1:] = False
        self.errors = {i: e for i, e in self.errors.items() if i <= b}
        self.walk_failed = {k: v for k, v in self.walk_failed.items() if k[0] <= b}

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
                self.restore(a)
                self.walk_dense(a + 1, b + 1)
                if (self.status[b] == OK and self.last == b
                        and np.max(np.abs(self.q[b] - q_b) / self.scale) <= MATCH_TOLERANCE):
                    self.q[b], self.slope[b], self.iterations[b] = q_b, slope_b, it_b
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
        Newton-Raphson's convergence tolerance (loop residual relative to the
        length scale; see :meth:`LoopSystem.newton`).
    batch : bool
        Solve the positions between a coarse sequential chain together
        (default); False walks position by position (the reference path).

    Returns ``(q, status, iterations, message)``: q (N, n_unknowns) with NaN
    where not valid, int8 status per position (0 ok, 1 not assemblable,
    2 only reachable by a branch jump), Newton iterations per position, and
    the error of the first failed position (or None). Singular Jacobians at
    converged positions are flagged afterwards, on the whole stack at once.
    """
    theta2 = np.asarray(theta2, dtype=float)
    return _Sweep(system, theta2, q0, tol).run(batch)


def singular_message(theta2, cond):
    return (f"the loop equations are singular at theta2 = {np.degrees(theta2):.6g} deg "
            f"(Jacobian condition measure {cond:.2e} < {SINGULAR_CONDITION:g}; its condition "
            f"number is about {2 / max(cond, 1e-300):.2e}): two links are aligned (a toggle or "
            f"limit position), so velocities and accelerations are not defined there. Move "
            f"theta2 away from it.")
