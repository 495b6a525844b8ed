"""Joints that meet: where a pin passes over a pivot or over another pin (unit-free).

Between any two joints of a loop runs a *diagonal*: the signed sum of the loop's
vectors from one joint to the other (in ``R2 + R3 - R4 - R1``, ``R2 + R3`` runs from
O2 to B, and ``R2 - R1`` from O4 to A, once round the loop). Where a diagonal's length
s nears zero, its direction is 0/0: the Jacobian becomes singular although the motion
may stay smooth (a kite fourbar, a = d and b = c, whose crank pin A passes over the
pivot O4). Each derivative then divides by about s once more, and its round-off grows
like eps (span / s)^n of its scale while the output stays finite, so no condition
threshold fixed for every order can catch it: at a Jacobian condition measure of 5e-4
a jerk came out 1.7e-4 of its scale off, and at 1.5e-4 2e-2 off, answered as right.

The closed-form kernels refuse the same positions by the same estimate
(:func:`accelab.solver.kernels.common.over_the_pivot`, measured there and here: 1 to
10 times eps (span / s)^n); here it applies where a diagonal is that short and the
diagonal runs along links that turn with the unknowns (:func:`diagonals`: a joint over
another elsewhere, a slider's block over a pivot, costs nothing).
"""

import numpy as np

from ..kernels.common import EPS, MAX_ROUNDOFF, ROUNDOFF_GAIN, pivot_fraction
from .description import loop_terms

#: the Jacobian condition measure (1 best, 0 singular) below which short diagonals are
#: looked at: this only skips well-conditioned positions. The estimate decides, not the
#: measure: a kite with links 3 and 4 short beside the crank (a = d = 5, b = c = 0.3) is
#: still at 1e-2 where its jerk is 3.6e-6 off
CONDITION_GATE = 0.5


def diagonals(model):
    """Every diagonal of every loop along which the links turn with the unknowns: a list
    of (label, signs over the vectors, loop index), each diagonal once (its reverse is the
    rest of the loop).

    Only runs of vectors whose angles all follow unknown angles count: where such a run
    closes on itself (links 3 and 4 of a kite folded, A on O4), their columns of the
    Jacobian fall in line and it turns singular. A joint passing over another along a run
    that holds the ground, the input or a slider's fixed direction (in the other kite,
    a = b and c = d, B stays on O2 while the crank turns) divides by nothing."""
    out, seen = [], set()
    for k, text in enumerate(model.loop_names):
        terms = loop_terms(text, model.names)
        n = len(terms)
        for start in range(n):
            for length in range(2, n - 1):
                run = [terms[(start + i) % n] for i in range(length)]
                if any(model.angle_unknown[index] < 0 for index, _ in run):
                    continue
                signs = np.zeros(len(model.names))
                for index, sign in run:
                    signs[index] += sign
                if not signs.any():
                    continue
                mask = signs != 0  # the diagonal and the rest of the loop read back: one key
                rest = (model.signs[k] != 0) & ~mask
                key = (k, min(tuple(mask), tuple(rest)))
                if key in seen:
                    continue
                seen.add(key)
                flip = -1.0 if run[0][1] < 0 else 1.0  # read from its first vector's tail
                label = " ".join(
                    f"{'-' if flip * sign < 0 else '+'} {model.names[index]}" for index, sign in run
                ).lstrip("+ ")
                out.append((label, signs, k))
    return out


def meeting(model, L, theta, cond, order=3):
    """Positions where two joints meet too nearly to vouch for outputs of ``order``.

    Parameters
    ----------
    model : LoopModel
    L, theta : arrays (N, n_vectors)
        Every vector's length [m] (any unit: only ratios count) and angle [rad].
    cond : array (N,)
        The Jacobian condition measure of each position [-].
    order : int
        The highest derivative reported (1 velocity, 2 acceleration, 3 jerk).

    Returns
    -------
    refuse : bool array (N,)
        Where ROUNDOFF_GAIN * eps * (span / s)^order passes MAX_ROUNDOFF for some
        diagonal of length s (span: the sum of its loop's lengths), at a condition
        measure below :data:`CONDITION_GATE`.
    first : tuple or None
        (position index, loop index, diagonal label, s, span, estimate) of the first
        refused position, for :func:`message`.
    """
    N = L.shape[0]
    refuse = np.zeros(N, dtype=bool)
    gated = np.asarray(cond) < CONDITION_GATE
    if order < 1 or not gated.any():
        return refuse, None
    z = L * np.exp(1j * theta)
    worst = np.zeros(N)
    which: list[tuple[int, int, str, float, float, float] | None] = [None] * N
    for label, signs, k in diagonals(model):
        span = np.abs(L) @ (model.signs[k] != 0)
        s = np.abs(z @ signs)
        with np.errstate(divide="ignore"):
            estimate = ROUNDOFF_GAIN * EPS * (span / s) ** order
        near = gated & (s < span * pivot_fraction(order)) & (estimate > worst)
        for i in np.flatnonzero(near):
            worst[i] = estimate[i]
            which[int(i)] = (int(i), k, label, float(s[i]), float(span[i]), float(estimate[i]))
    refuse = worst > MAX_ROUNDOFF
    hits = np.flatnonzero(refuse)
    return refuse, (which[hits[0]] if len(hits) else None)


#: what the derivative of each order is called in a message
ORDER_NAMES = {1: "velocity", 2: "acceleration", 3: "jerk"}


def message(theta2, loop, label, s, span, estimate, *, model=None, unit=1.0, order=3):
    """Why a position is refused, and how far to move: ``loop`` the loop's index and
    ``label`` the diagonal (from :func:`meeting`), ``s`` and ``span`` times ``unit`` [m]."""
    where = f" {model.loop_names[loop]!r}" if model is not None else ""
    return (
        f"two joints of the loop{where} meet at theta2 = {np.degrees(theta2):.6g} deg: the "
        f"diagonal {label} between them is {s * unit:.3g} m long, so its direction is "
        f"undefined and each derivative divides by that length again (round-off in the "
        f"{ORDER_NAMES[order]} about {estimate:.0e} of its scale). Move theta2 until the two "
        f"joints are at least {span * unit * pivot_fraction(order):.3g} m apart "
        f"({pivot_fraction(order):.0e} of the loop's lengths' sum), or "
        f"change the lengths so that they never meet"
    )
