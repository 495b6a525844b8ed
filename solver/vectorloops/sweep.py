"""Solving a vector-loop linkage along a sweep of theta2 (one assembly).

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

The work is split by job: :class:`Sweep` (here) drives the coarse chain,
the batched positions and the run loop; :mod:`.assembly` solves one
position by continuation and decides which solution keeps the followed
assembly (subdivide, switch, rejoin); :class:`.walks.Continuation` follows
a path in small steps and knows nothing of the sweep's results; and
:class:`.record.SweepRecord` holds the results per position and the state
the continuation goes on from.
"""

import math

import numpy as np

from ..status import OK
from .assembly import scan_gap, step
from .newton import CONVERGED, DEFAULT_TOL, ORIENTATION_FLOOR, SINGULAR_CONDITION
from .record import HIGHER_ORDER_CAP, SweepRecord
from .walks import (
    JUMP_TOLERANCE,
    MATCH_TOLERANCE,
    MIN_WALK_STEP,
    SAMPLE_SINGULAR,
    WALK_STEP,
    Continuation,
    sign_of,
)

__all__ = [
    "Sweep",
    "solve_sweep",
    "singular_message",
    "COARSE_STEP",
    "COARSE_RANGE",
    "COARSE_TARGET",
    "MAX_STRIDE",
    "MIN_STRIDE",
    "GAP_CHUNK",
    # defined where they are used, named here too
    "HIGHER_ORDER_CAP",
    "SAMPLE_SINGULAR",
    "JUMP_TOLERANCE",
    "MATCH_TOLERANCE",
    "WALK_STEP",
    "MIN_WALK_STEP",
    "sign_of",
]

COARSE_STEP = 0.25  # [rad] first theta2 step between sequentially solved positions
COARSE_RANGE = (0.02, 0.6)  # [rad] the step adapts within this range
COARSE_TARGET = 0.005  # [rad or length scale] aimed-at chord/slope mismatch per step
MAX_STRIDE = 256  # most positions between two sequentially solved ones
MIN_STRIDE = 2  # below this, walk position by position
GAP_CHUNK = 16  # positions tried together while the loops do not close


class Sweep:
    """One sweep of ``system`` (a LoopSystem) along ``theta2`` (1-D array [rad])
    from the guesses ``q0``, Newton-Raphson's tolerance ``tol`` [-]: the coarse
    chain, the batched positions between and the run loop. ``record`` (a
    :class:`.record.SweepRecord`) holds the results, ``continuation`` (a
    :class:`.walks.Continuation`) follows paths; :mod:`.assembly` solves the
    positions one at a time."""

    def __init__(self, system, theta2, q0, tol):
        self.system, self.theta2, self.tol = system, theta2, tol
        self.continuation = Continuation(system, tol)
        self.record = SweepRecord(theta2, q0, system.scale, self.continuation.sample_singular)
        self.coarse = COARSE_STEP  # current coarse step [rad]
        self.scale = system.scale
        self.theta2_list = [float(x) for x in theta2]

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
        both ends consistent with the chord (a smooth branch). Adapts the
        coarse step; returns whether b was accepted."""
        rec, cont = self.record, self.continuation
        t = float(self.theta2[b])
        pred, change = rec.predict(t)
        q, it, res, reason, slope, orient = self.system.newton1(pred, t, self.tol)
        lo, hi = COARSE_RANGE
        if (
            reason != CONVERGED
            or slope is None
            or not abs(orient) >= cont.sample_singular
            or rec.flipped(orient)
        ):
            self.coarse = max(lo, 0.5 * self.coarse)
            return False
        assert rec.state is not None  # called only from a solved position with a slope
        ta, qa, sa = rec.state
        h = t - ta
        error = max(
            abs(q1 - q0 - 0.5 * h * (s0 + s1)) / sc
            for q0, q1, s0, s1, sc in zip(qa, q, sa, slope, cont.scale_list)
        )
        # the mismatch grows like h**3: aim the next step at COARSE_TARGET
        grow = 0.9 * (COARSE_TARGET / max(error, 1e-12)) ** (1 / 3)
        self.coarse = min(hi, max(lo, abs(h) * min(2.0, max(0.5, grow))))
        if error > JUMP_TOLERANCE or cont.jumped(q, pred, change):
            return False
        rec.accept(b, q, it, slope, orient)
        return True

    def batch(self, intervals):
        """Solve the interior positions of the coarse ``intervals`` [(a, b), ...]
        together. Returns the intervals where some position failed its check."""
        if not intervals:
            return []
        rec = self.record
        A = np.array([a for a, b in intervals])
        Bn = np.array([b for a, b in intervals])
        counts = Bn - A - 1
        owner = np.repeat(np.arange(len(intervals)), counts)
        idx = np.concatenate([np.arange(a + 1, b) for a, b in intervals])
        th = self.theta2
        guess, rate = self.hermite(idx, A[owner], Bn[owner])
        q, it, res, reason, _, orient = self.system.newton(guess, th[idx], self.tol, slopes=False)
        dt = np.abs(th[idx] - th[idx - 1])[:, None]
        change = np.max(np.abs(rate * dt) / self.scale, axis=1)
        off = np.max(np.abs(q - guess) / self.scale, axis=1)
        good = (reason == CONVERGED) & (off <= JUMP_TOLERANCE + 0.5 * change)
        if rec.sign is not None:  # never the other orientation
            good &= ~((np.abs(orient) >= ORIENTATION_FLOOR) & (np.sign(orient) != rec.sign))
        rec.q[idx], rec.iterations[idx], rec.orient[idx] = q, it, orient
        bad = np.unique(owner[~good])
        return [intervals[k] for k in bad]

    def hermite(self, idx, a, b):
        """Cubic Hermite interpolation of q and dq/dtheta2 at positions idx between
        solved positions a and b (arrays alike): (guess, rate)."""
        th, rec = self.theta2, self.record
        h = (th[b] - th[a])[:, None]
        s = ((th[idx] - th[a]) / (th[b] - th[a]))[:, None]
        s2, s3 = s * s, s * s * s
        qa, qb, sa, sb = rec.q[a], rec.q[b], rec.slope[a] * h, rec.slope[b] * h
        guess = (
            (2 * s3 - 3 * s2 + 1) * qa
            + (s3 - 2 * s2 + s) * sa
            + (3 * s2 - 2 * s3) * qb
            + (s3 - s2) * sb
        )
        rate = (
            (6 * s2 - 6 * s) * qa
            + (3 * s2 - 4 * s + 1) * sa
            + (6 * s - 6 * s2) * qb
            + (3 * s2 - 2 * s) * sb
        ) / h
        return guess, rate

    # --- position by position -----------------------------------------------------
    def advance(self, i, stop):
        """Solve position i by continuation; while the loops do not close (the
        position before failed) try a chunk of positions at once. Returns the
        next index."""
        rec = self.record
        if rec.failures and (rec.last is None or rec.gap):
            chunk = max(GAP_CHUNK, min(rec.failures, 256))
            return scan_gap(rec, self.continuation, i, min(stop, i + chunk))
        step(rec, self.continuation, i)
        return i + 1

    def walk_dense(self, start, stop):
        """Position by position from start to stop - 1 (no coarse steps)."""
        i = start
        while i < stop:
            i = self.advance(i, stop)

    def run(self, batch=True):
        """Solve every position: the coarse chain with the batched positions
        between (``batch``), or position by position. Returns ``(q, status,
        iterations, message)`` (see :func:`solve_sweep`)."""
        rec = self.record
        N = len(self.theta2)
        start = 0
        while start < N:
            intervals = []
            i = start
            dense_until = -1
            while i < N:
                if (
                    batch
                    and i > dense_until
                    and rec.last == i - 1
                    and not rec.gap
                    and rec.state is not None
                    and rec.state[2] is not None
                ):
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
                q_b, slope_b, it_b = rec.q[b].copy(), rec.slope[b].copy(), rec.iterations[b]
                orient_b = rec.orient[b]
                rec.restore(a)
                self.walk_dense(a + 1, b + 1)
                if (
                    rec.status[b] == OK
                    and rec.last == b
                    and np.max(np.abs(rec.q[b] - q_b) / self.scale) <= MATCH_TOLERANCE
                ):
                    rec.q[b], rec.slope[b], rec.iterations[b] = q_b, slope_b, it_b
                    rec.orient[b] = orient_b
                    continue
                # the walk reached b differently: the chain after b is void
                rec.reset_after(b)
                start = b + 1
                break
        return rec.q, rec.status, rec.iterations, rec.message()


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
    notes = sweep.record.notes
    return q, status, iterations, message, {int(i): notes[i] for i in sorted(notes)}


def singular_message(theta2, cond):
    """The message of a singular position: ``theta2`` [rad] and the Jacobian's
    condition measure ``cond`` (1 best, 0 singular) [-]."""
    return (
        f"the loop equations are singular at theta2 = {np.degrees(theta2):.6g} deg "
        f"(Jacobian condition measure {cond:.2e} < {SINGULAR_CONDITION:g}; its condition "
        f"number is about {2 / max(cond, 1e-300):.2e}): two links are aligned (a toggle or "
        f"limit position), so velocities and accelerations are not defined there. Move "
        f"theta2 away from it."
    )
