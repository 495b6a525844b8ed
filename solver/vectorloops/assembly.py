"""Keeping a sweep on its assembly, one position at a time.

:func:`step` solves one position by continuation from the sweep's record
(:class:`.record.SweepRecord`) with a :class:`.walks.Continuation`, both
given explicitly, and decides what the sweep keeps there:

- a solution far from the prediction, or with the other orientation (the
  sign of det J, :mod:`.newton`), is walked to in small steps
  (:func:`subdivide`): either Newton-Raphson had jumped, or a singular
  position where two assemblies meet lies on the way (a change point), past
  which the solution with the followed orientation is found (:func:`switch`,
  :mod:`.crossing`);
- after a stretch that cannot be assembled, a solution is kept only if a
  walk from a solved position reaches it on the followed assembly
  (:func:`rejoin`);
- a position on none of these terms fails in the record, with a message.
"""

import math

import numpy as np

from ..errors import NotAssemblable, Singular
from ..status import NOT_ASSEMBLABLE, OK, SINGULAR
from .crossing import (
    SWITCH_DISTANCE,
    ambiguity_message,
    crossing_note,
    other_branch,
    singular_passage_note,
)
from .newton import (
    CONVERGED,
    ORIENTATION_FLOOR,
    SINGULAR_CONDITION,
    SINGULAR_STEP,
    condition,
    no_convergence,
)
from .walks import JUMP_TOLERANCE, MATCH_TOLERANCE, sign_of


class _BranchJump(Singular):
    """Newton-Raphson reached closure only on another assembly."""


def step(rec, cont, i, result=None):
    """Solve position i of the record ``rec`` by continuation ``cont`` from its
    state (or post-process the Newton ``result`` already computed from that
    same prediction). Returns True if position i was accepted, False if it
    failed (recorded in ``rec``)."""
    t = float(rec.theta2[i])
    if rec.blocked is not None and (t - rec.blocked[0]) * rec.blocked[1] > 0:
        rec.fail(i, SINGULAR, Singular(ambiguity_message(rec.blocked[0], t)))
        return False
    pred, change = rec.predict(t)
    system = cont.system
    leaving = rec.singular_last and rec.state is not None
    if result is None or (leaving and result.reason == SINGULAR_STEP):
        result = system.newton1(pred, t, cont.tol, least_squares=leaving)
    q, it, res, reason, slope, orient = result
    if reason == SINGULAR_STEP:
        result = singular_step(rec, cont, pred, t)
        if result is not None:
            q, it, res, reason, slope, orient = result
    if reason != CONVERGED:
        rec.fail(i, NOT_ASSEMBLABLE, no_convergence(t, res * system.unit, it, reason))
        return False
    trusted = abs(orient) >= cont.sample_singular
    if rec.gap:  # across a gap the prediction means little: walk to check instead
        ok, q, slope, orient = rejoin(rec, cont, i, np.asarray(q), slope, orient)
        if not ok:
            return False
    elif (change is not None and cont.jumped(q, pred, change)) or (
        rec.flipped(orient) and trusted and not leaving
    ):
        found = subdivide(rec, cont, i, t, it)
        if found is None:
            return False
        q, it, slope, orient = found
    elif leaving and rec.sign is not None and trusted:
        t_s, q_c = float(rec.state[0]), np.array(rec.state[1])
        if rec.flipped(orient) and t != t_s:
            found = switch(rec, cont, i, t_s, q_c, (np.asarray(q) - q_c) / (t - t_s), t)
            if found is None:
                return False
            q, it, slope, orient = found
        else:
            rec.notes[i] = singular_passage_note(t_s, t)
    rec.accept(i, q, it, slope, orient)
    return True


def singular_step(rec, cont, q0, t):
    """Newton-Raphson met an exactly singular Jacobian on its way from q0 to
    theta2 = t [rad]: try again with least-squares steps there. The result is
    returned if it converges, except for the first position of a sweep,
    where it must also be singular itself (a condition below
    SINGULAR_CONDITION: it is then accepted and reported ``singular``);
    otherwise None: the guesses, not the position, are singular, and they
    choose no assembly."""
    system = cont.system
    result = system.newton1(q0, t, cont.tol, least_squares=True)
    if result.reason != CONVERGED:
        return None
    if rec.state is not None:
        return result
    J = system.evaluate(np.array([result.q]), np.array([t]))[1]
    if not condition(J, system.model)[0] < SINGULAR_CONDITION:
        return None
    return result


def scan_gap(rec, cont, i, stop):
    """Positions i..stop-1 while the loops do not close: every one starts from
    the same prediction, so Newton-Raphson runs on them together. Processes
    positions until one is accepted; returns the next index."""
    idx = np.arange(i, stop)
    t = rec.theta2[idx]
    q0, _ = rec.predict(t)
    q, it, res, reason, slope, orient = cont.system.newton(q0, t, cont.tol)
    for k, n in enumerate(idx):
        result = (
            q[k],
            int(it[k]),
            float(res[k]),
            reason[k],
            slope[k] if reason[k] == CONVERGED else None,
            float(orient[k]),
        )
        if step(rec, cont, n, result):
            return n + 1
    return stop


# --- off the prediction: a jump, or through a singular position -----------
def subdivide(rec, cont, i, t, it):
    """Position i (theta2 = t [rad], reached in ``it`` Newton iterations)
    converged far from the prediction (a jump) or with the other orientation
    than the followed assembly. Walk to it from the last solved position in
    small steps on the followed orientation (:meth:`.walks.Continuation.follow`):
    if the walk arrives, Newton-Raphson had jumped and the walk's solution
    stands; if the orientation changes even within a step of MIN_WALK_STEP,
    a singular position where two assemblies meet lies there (a change
    point), and the sweep finds its own assembly past it (:func:`switch`).
    Returns ``(q, iterations, slope, orient)`` or None (position i failed)."""
    t_a, q_a, s_a = rec.state
    if s_a is None:
        rec.fail(
            i,
            SINGULAR,
            _BranchJump(
                f"at theta2 = {np.degrees(t):.6g} deg Newton-Raphson reaches the loops' closure "
                f"only on another assembly, and the sweep cannot walk there from theta2 = "
                f"{np.degrees(t_a):.6g} deg. Sweep in smaller steps."
            ),
        )
        return None
    kind, data = cont.follow(
        np.array(q_a), np.array(s_a), t_a, t, rec.sign, float(rec.orient[rec.last])
    )
    if kind == "arrived":
        q_w, s_w, o_w = data
        return q_w, it, s_w, o_w
    if kind == "stuck":
        rec.fail(
            i,
            SINGULAR,
            _BranchJump(
                f"near theta2 = {np.degrees(t_a + math.copysign(data, t - t_a)):.6g} deg "
                f"Newton-Raphson reaches the loops' closure only on another assembly: the "
                f"linkage passes a limit (toggle) position there. Sweep a range that avoids it."
            ),
        )
        return None
    t_p, q_p, o_p, s_p, t_n, q_n, o_n = data
    # the orientation is about linear in theta2 there
    w = o_p / (o_p - o_n) if o_p != o_n else 1.0
    return switch(rec, cont, i, t_p + w * (t_n - t_p), q_p + w * (q_n - q_p), s_p, t)


def switch(rec, cont, i, t_c, q_c, v, t):
    """At position i (theta2 = t [rad]), past the singular position q_c at t_c
    [rad] that the continuation crossed along direction v (dq/dtheta2), find
    the solution with the followed orientation. Within SWITCH_DISTANCE of the
    crossing the two curves through q_c are told apart directly
    (:func:`.crossing.other_branch`); farther, at SWITCH_DISTANCE, and the
    sweep's own curve is followed from there to t. Returns ``(q, iterations,
    slope, orient)``, with a note, or None with position i failed and the
    positions past t_c blocked."""
    d = t - t_c
    t_w = t if abs(d) <= SWITCH_DISTANCE else t_c + math.copysign(SWITCH_DISTANCE, d)
    q_k, it, _, reason, s_k, o_k = cont.system.newton1(q_c + v * (t_w - t_c), t_w, cont.tol)
    near = found = None
    if reason == CONVERGED and s_k is not None:
        if abs(o_k) >= ORIENTATION_FLOOR and sign_of(o_k) == rec.sign:
            near = np.asarray(q_k), it, np.asarray(s_k), o_k
        else:
            near = other_branch(
                cont.system, t_c, q_c, t_w, np.asarray(q_k), rec.sign, cont.tol, JUMP_TOLERANCE
            )
    if near is not None and t_w == t:
        found = near
    elif near is not None:
        kind, data = cont.follow(near[0], near[2], t_w, t, rec.sign, near[3])
        if kind == "arrived":
            found = (data[0], near[1], data[1], data[2])
    if found is None:
        rec.blocked = (t_c, math.copysign(1.0, d), i)
        rec.fail(i, SINGULAR, Singular(ambiguity_message(t_c, t)))
        return None
    rec.notes[i] = crossing_note(t_c, t)
    return found


# --- after a stretch that cannot be assembled ------------------------------
def rejoin(rec, cont, i, q_try, slope_try, orient_try):
    """Is the solution ``q_try`` found at i, after a gap, on the followed assembly?

    Walk by continuation to theta2[i] from the nearest solved position
    below it and from the nearest above it (modulo the input's period, if
    it has one), nearer first; a walk that arrives defines the assembly.
    Returns ``(ok, q, slope, orient)``; not ok with position i failed.
    """
    t = float(rec.theta2[i])
    anchors = np.flatnonzero(
        rec.sequential[:i] & (rec.status[:i] == OK) & np.isfinite(rec.slope[:i]).all(axis=1)
    )
    d = t - rec.theta2[anchors]
    period = cont.system.period
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
        if key in rec.walk_failed and abs(dist) > rec.walk_failed[key]:
            continue  # an earlier walk from a stopped short of this
        reached = walk(rec, cont, a, dist)
        if isinstance(reached, float):
            rec.walk_failed[key] = reached
            continue
        q_w, slope_w, orient_w = reached
        if dist != t - rec.theta2[a]:  # the same configuration, whole turns away
            q_w, _, _, reason, slope_w, orient_w = cont.system.newton1(q_w, t, cont.tol)
            if reason != CONVERGED or slope_w is None or rec.flipped(orient_w):
                continue
            q_w = np.asarray(q_w)
        if np.max(np.abs(q_w - q_try) / cont.scale) <= MATCH_TOLERANCE:
            return True, q_try, slope_try, orient_try
        return True, q_w, slope_w, orient_w
    rec.fail(
        i,
        NOT_ASSEMBLABLE,
        NotAssemblable(
            f"at theta2 = {np.degrees(t):.6g} deg the loops close again after a range where "
            f"they cannot, but not on the assembly this sweep follows: no continuous path "
            f"from the positions solved before reaches it. Solve this range on its own, with "
            f"guesses for the assembly you want."
        ),
    )
    return False, None, None, None


def walk(rec, cont, a, dist):
    """Continuation from solved position a over ``dist`` [rad] of theta2 on
    the followed orientation (:meth:`.walks.Continuation.follow`). Returns
    (q, slope, orient) at theta2[a] + dist, or the distance [rad] it reached
    before it had to give up."""
    kind, data = cont.follow(
        rec.q[a],
        rec.slope[a],
        float(rec.theta2[a]),
        float(rec.theta2[a]) + dist,
        rec.sign,
        float(rec.orient[a]),
    )
    if kind == "arrived":
        return data
    return data if kind == "stuck" else abs(data[0] - float(rec.theta2[a]))
