"""What a sweep (:mod:`.sweep`) knows so far: its results per position and the
state it continues from.

:class:`SweepRecord` holds the per-position arrays (unknowns, slopes,
orientations, status, Newton iterations, which positions the continuation
solved), the errors and notes, and the continuation state: the last
position solved by continuation, the predictor from it, the followed
orientation and where the assembly was lost. It decides nothing about
assemblies (that is :mod:`.assembly`); it records and predicts.
"""

import math

import numpy as np

from ..status import OK
from .crossing import singular_start_note
from .newton import ORIENTATION_FLOOR
from .walks import sign_of

HIGHER_ORDER_CAP = 0.1  # [rad or length scale] largest 2nd+3rd order predictor term


class SweepRecord:
    """The results of one sweep along ``theta2`` (1-D array [rad]) so far and
    its continuation state, from the guesses ``q0``; ``scale`` (array) the
    unknowns' scales [rad or length scale] and ``sample_singular`` the
    |orientation| below which a solved position is singular."""

    def __init__(self, theta2, q0, scale, sample_singular):
        self.theta2, self.sample_singular = theta2, sample_singular
        N, nu = len(theta2), len(scale)
        self.q = np.full((N, nu), np.nan)
        self.slope = np.full((N, nu), np.nan)  # at sequentially solved positions
        self.orient = np.full(N, np.nan)  # orientation of solved positions
        self.status = np.full(N, OK, dtype=np.int8)
        self.iterations = np.zeros(N, dtype=int)
        self.sequential = np.zeros(N, dtype=bool)  # solved by continuation (anchors)
        self.errors = {}
        self.notes = {}  # position -> what the sweep decided there (crossings)
        self.guess = np.asarray(q0, dtype=float)
        self.last = None  # index of the last position solved by continuation
        self.taylor = None  # 2nd and 3rd Taylor coefficients of q(theta2) at last
        self.gap = False  # a position failed since self.last
        self.walk_failed = {}  # (anchor, direction) -> distance a rejoining walk failed at
        self.failures = 0  # consecutive failed positions
        self.scale = scale
        self.scale_list = [float(x) for x in scale]
        # the continuation state in plain floats: (theta2, q, slope or None) of
        # self.last; the per-position bookkeeping of a 4-unknown linkage is
        # cheaper in Python than in numpy calls
        self.state = None
        self.sign = None  # orientation (+1 / -1) of the followed assembly
        self.singular_last = False  # self.last is a singular position
        self.singular_start = None  # index of a singular first position, until the sign is set
        self.blocked = None  # (theta2, direction, i): past it the assembly was lost

    def accept(self, i, q, it, slope, orient):
        """Position i solved by continuation: ``q``, Newton ``it``erations, its
        ``slope`` dq/dtheta2 (or None) and orientation ``orient``; it becomes the
        state the sweep continues from (the first trusted orientation sets the
        followed one)."""
        q = [float(x) for x in q]
        singular = not abs(orient) >= self.sample_singular
        if singular:
            slope = None  # dq/dtheta2 means nothing at a singular position
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
                self.taylor = (
                    [(3 * d + h * (a + 2 * b)) / h2 for d, a, b in zip(dq, s0, slope)],
                    [(2 * d + h * (a + b)) / h3 for d, a, b in zip(dq, s0, slope)],
                )
        self.state = (t, q, slope)
        self.last, self.gap = i, False
        self.singular_last = singular
        self.failures = 0

    def restore(self, a):
        """Continue from solved position a (to walk an interval again)."""
        slope = self.slope[a]
        self.state = (
            float(self.theta2[a]),
            [float(x) for x in self.q[a]],
            [float(x) for x in slope] if np.isfinite(slope).all() else None,
        )
        self.last, self.gap, self.failures, self.taylor = a, False, 0, None
        self.singular_last = not abs(self.orient[a]) >= self.sample_singular

    def fail(self, i, status, exc):
        """Position i failed with ``status`` (:mod:`accelab.solver.status`) and error ``exc``."""
        self.status[i] = status
        self.q[i] = np.nan
        self.errors[i] = exc
        self.failures += 1
        if self.last is not None:
            self.gap = True

    def reset_after(self, b):
        """Forget everything solved after position b (the chain is restarted there)."""
        self.q[b + 1 :] = np.nan
        self.slope[b + 1 :] = np.nan
        self.orient[b + 1 :] = np.nan
        self.status[b + 1 :] = OK
        self.iterations[b + 1 :] = 0
        self.sequential[b + 1 :] = False
        self.errors = {i: e for i, e in self.errors.items() if i <= b}
        self.notes = {i: e for i, e in self.notes.items() if i <= b}
        self.walk_failed = {k: v for k, v in self.walk_failed.items() if k[0] <= b}
        if self.blocked is not None and self.blocked[2] > b:
            self.blocked = None

    def message(self):
        """The error of the first failed position, or None."""
        bad = [i for i in self.errors if self.status[i] != OK]
        return self.errors[min(bad)] if bad else None

    def flipped(self, orient):
        """Is ``orient`` (trusted in sign) the other orientation than the followed one?"""
        return (
            self.sign is not None
            and abs(orient) >= ORIENTATION_FLOOR
            and sign_of(orient) != self.sign
        )

    def predict(self, t):
        """Continuation predictor from the last solved position to theta2 = t
        [rad]: ``(guess, change)``, ``change`` the largest scaled first-order
        change [rad or length scale] (None without a slope). The cubic Taylor
        terms are used only where they stay small (< HIGHER_ORDER_CAP), so they
        never carry a guess far from the tangent. ``t`` a float gives lists, an
        array gives arrays."""
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
        shape = t.shape + (len(self.scale_list),)
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
