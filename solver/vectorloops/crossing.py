"""Staying on one assembly through a singular position where two meet.

At a change point (a Grashof fourbar with s + l = p + q, a parallelogram at
its flat positions, ...) two assemblies pass through the same singular
configuration q_c at theta2 = t_c: the solutions near it lie on two curves
that cross there. Continuation follows the smooth curve through the
crossing, and that curve changes orientation (the sign of det J, which tells
open from crossed) at q_c: on the far side it is the *other* assembly. The
assembly with the orientation the sweep followed lies on the second curve.

Near q_c the two curves at theta2 = t are q_c + (t - t_c) v1 and
q_c + (t - t_c) v2, and v2 - v1 is along the null vector phi of J(q_c). From
the smooth-curve solution q_s at t, the other is therefore on the line
q_s + k phi. Along that line the left null vector psi of J(q_c) sees

    g(k) = psi . F(q_s + k phi, t) ~ a k + b k^2,

one root at k = 0 (q_s itself) and the other at k = -a/b: three residual
evaluations locate it, and Newton-Raphson from there converges to it.
:func:`other_branch` does this and accepts the result only with the
wanted orientation and near q_c.
"""

import math

import numpy as np

from .newton import CONVERGED, ORIENTATION_FLOOR

SWITCH_DISTANCE = 0.01  # [rad] of theta2 from the crossing where the curves are told apart
REACH = 8.0  # the other curve's point is at most this many times farther from
# q_c than q_s is (plus JUMP_TOLERANCE), in scaled units


def other_branch(system, t_c, q_c, t, q_s, sign, tol, slack):
    """The solution at theta2 = ``t`` on the other curve through the singular
    configuration ``q_c`` (at ``t_c``) than ``q_s``, with orientation ``sign``.

    Parameters
    ----------
    system : LoopSystem
    t_c, t : float
        Input angles of the crossing and of the wanted solution [rad].
    q_c, q_s : array (nu,)
        The singular configuration, and the solution at ``t`` on the curve
        the continuation followed [rad, m].
    sign : +1 or -1
        Orientation wanted (that of the assembly before the crossing).
    tol : float
        Newton-Raphson tolerance [-] (loop residual relative to the length scale).
    slack : float
        Extra distance [scaled] allowed from q_c.

    Returns
    -------
    (q, iterations, slope, orient) or None when not found.
    """
    scale = system.scale
    q_c = np.asarray(q_c, dtype=float)
    q_s = np.asarray(q_s, dtype=float)
    r = float(np.max(np.abs(q_s - q_c) / scale))
    if not r > 0.0:
        return None
    J = system.evaluate(q_c[None], np.array([t_c]))[1][0]
    U, _, Vt = np.linalg.svd(J * scale)
    phi, psi = Vt[-1] * scale, U[:, -1]
    k0 = r

    def g(k):
        return float(psi @ system.evaluate((q_s + k * phi)[None], np.array([t]))[0][0])

    gp, gm = g(k0), g(-k0)
    a, b = (gp - gm) / (2 * k0), (gp + gm) / (2 * k0 * k0)
    tries = [-a / b] if b != 0.0 and math.isfinite(a / b) else []
    tries += [k0, -k0, 2 * k0, -2 * k0, 0.5 * k0, -0.5 * k0]
    reach = REACH * r + slack
    for k in tries:
        q, it, _, reason, slope, orient = system.newton1(q_s + k * phi, t, tol)
        if (
            reason == CONVERGED
            and slope is not None
            and abs(orient) >= ORIENTATION_FLOOR
            and math.copysign(1.0, orient) == sign
            and np.max(np.abs(np.asarray(q) - q_c) / scale) <= reach
        ):
            return np.asarray(q), it, np.asarray(slope), orient
    return None


def crossing_note(t_c, t):
    """What a sweep says when it kept its assembly through a crossing."""
    return (
        f"near theta2 = {math.degrees(t_c):.6g} deg the linkage passes a singular position "
        f"where two of its assemblies meet (a change point: the Jacobian's orientation "
        f"changes sign through it), and its geometry does not decide which one it takes "
        f"after it. From theta2 = {math.degrees(t):.6g} deg on, this sweep stays on the "
        f"assembly it followed before (the same orientation, continuous through the meeting "
        f"point); the other is equally possible: sweep from there with guesses on it to see "
        f"it."
    )


def ambiguity_message(t_c, t):
    """What a sweep says when it cannot find its assembly past a crossing."""
    return (
        f"near theta2 = {math.degrees(t_c):.6g} deg the linkage passes a singular position "
        f"where two of its assemblies meet, and at theta2 = {math.degrees(t):.6g} deg this "
        f"sweep cannot find the assembly it followed before (only the other, which it does "
        f"not report as if it were the same): positions past that point are marked singular. "
        f"Sweep from there with guesses on the assembly you want."
    )


def singular_start_note(t0, t1):
    """What a sweep says when it starts on a singular position."""
    return (
        f"the sweep starts on a singular position (theta2 = {math.degrees(t0):.6g} deg), "
        f"where assemblies can meet, so the guesses there do not choose one: it continues "
        f"from theta2 = {math.degrees(t1):.6g} deg on the assembly Newton-Raphson reached "
        f"there, and another may be equally possible. Start the sweep off the singular "
        f"position, with guesses on the assembly you want, to choose."
    )


def singular_passage_note(t_s, t):
    """What a sweep says when it went through a singular sampled position and
    found its own orientation again past it."""
    return (
        f"at theta2 = {math.degrees(t_s):.6g} deg the sweep passes a singular position; "
        f"from theta2 = {math.degrees(t):.6g} deg on it continues on the assembly with the "
        f"orientation it followed before. If two assemblies meet there (a change point), "
        f"the other is equally possible."
    )
