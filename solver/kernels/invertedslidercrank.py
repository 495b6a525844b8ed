"""The inverted slider-crank, position to jerk, with its Coriolis term (unit-free).

Vector loop (docs/conventions.md#mechanisms; its second derivative is eq. 7.20):
    a e^{j theta2} - b e^{j theta3} - c e^{j theta4} - d e^{j theta1} = 0,
    theta3 = theta4 + gamma,  b(t) the varying (signed) length from B to A.

Link 4 is the slotted link pivoted at O4: it reaches from O4 to B (length c)
and carries the slide line through B at the fixed angle gamma to O4B. The
block (link 3) is pinned to the crank at A and slides on that line, so
omega3 = omega4 and alpha3 = alpha4.

Position. With r = A - O4, |b e^{j gamma} + c| = |r| = s gives
    b = -c cos gamma + sigma sqrt(s^2 - c^2 sin^2 gamma)
``open`` takes sigma = +1 (the larger b), ``crossed`` sigma = -1; then
theta4 = arg(r) - arg(b e^{j gamma} + c). Not assemblable where
s < c |sin gamma| (the slide line cannot reach A).

Derivatives. Differentiating n times,

    b^(n) e3 + j x (b e3 + c e4) = K_n

with x = omega4, alpha4, jerk4 and K_n the known terms (eqs. 7.21-7.27 for
n = 2; K_2 holds the Coriolis term 2 b' omega3 j e3). Projecting on e3 and
j e3:
    x     = Im(K_n conj e3) / (b + c cos gamma)
    b^(n) = Re(K_n conj e3) - x c sin gamma
The position is singular where b + c cos gamma = 0 (A at the foot of the
perpendicular from the slide line to O4's circle: a limit position).
"""

import numpy as np

from .common import (
    EPS,
    OK,
    Floats,
    Motion,
    acc_term,
    angles,
    as_input,
    classify,
    in_pieces,
    jerk_term,
    length_unit,
    masked,
    outputs,
    over_the_pivot,
    piecewise,
    scale_lengths,
    slider,
    where,
    without_float_warnings,
)

CIRCUITS = {"open": 1.0, "crossed": -1.0}


@outputs
class InvertedSliderCrankMotion(Motion):
    """What :func:`solve` returns: links 3 and 4 and the block's position b along the
    slide line, position to jerk; ``gamma`` echoed."""

    OUTPUTS = angles(3, 4) + slider("b")
    EXTRA = ("gamma",)


@without_float_warnings
def solve(
    a: float,
    c: float,
    d: float,
    gamma: float,
    theta2: Floats,
    omega2: Floats,
    alpha2: Floats = 0.0,
    jerk2: Floats = 0.0,
    theta1: float = 0.0,
    circuit: str = "open",
    order: int = 3,
) -> InvertedSliderCrankMotion:
    """Inverted slider-crank kinematics from position to jerk.

    Parameters
    ----------
    a : float
        Crank length O2A [m].
    c : float
        Length O4B of link 4 [m], >= 0 (0: the block slides on a line through O4).
    d : float
        Ground length O2O4 [m].
    gamma : float
        Fixed angle from link 4 (O4->B) to the slide line [rad], signed.
    theta2, omega2, alpha2, jerk2 : float or array
        Crank angle [rad] and its derivatives [rad/s, rad/s^2, rad/s^3].
    theta1 : float
        Ground angle [rad].

    Returns
    -------
    InvertedSliderCrankMotion
        theta3, theta4 [rad] (theta3 = theta4 + gamma); omega3 = omega4;
        alpha3 = alpha4; jerk3 = jerk4; b [m], b_dot, b_ddot, b_dddot;
        ``status``; ``condition`` = |b + c cos gamma| / |A - O4|; ``roundoff``
        (see :func:`accelab.solver.kernels.fourbar.solve`).
    """
    unit = length_unit(a, c, d)  # scale-free: lengths near 1, exactly
    out = _solve(
        a / unit, c / unit, d / unit, gamma, theta2, omega2, alpha2, jerk2, theta1, circuit, order
    )
    return scale_lengths(out, slider("b"), unit)


def _solve(a, c, d, gamma, theta2, omega2, alpha2, jerk2, theta1, circuit, order):
    """:func:`solve` with lengths of order 1 (see :func:`~.common.length_unit`)."""
    sigma = CIRCUITS[circuit]
    theta2 = as_input(theta2)
    order = min(order, 3)
    if piecewise(theta2, (omega2, alpha2, jerk2), (a, c, d, gamma, theta1)):
        return in_pieces(
            lambda t2, w2, a2, j2: _solve(a, c, d, gamma, t2, w2, a2, j2, theta1, circuit, order),
            theta2,
            omega2,
            alpha2,
            jerk2,
        )
    t2 = theta2 - theta1
    cos2, sin2 = np.cos(t2), np.sin(t2)
    cg, sg = np.cos(gamma), np.sin(gamma)
    rx = a * cos2 - d
    ry = a * sin2
    s = np.hypot(rx, ry)
    csg = c * sg
    span = a + c + d
    # gap = s - c |sin gamma|: how far A is from the nearest reach of the
    # slide line (0: the line is tangent there); within round-off below 0, 0
    gap = np.minimum(s - csg, s + csg)
    prod = where((gap <= 0) & (gap > -2.0 * EPS * span), 0.0, (s - csg) * (s + csg))
    root = np.sqrt(prod)
    b = -c * cg + sigma * root
    # e4 = r / (b e^{j gamma} + c) normalised; (px, py) = b e^{j gamma} + c has length s
    px, py = b * cg + c, b * sg
    c4 = (rx * px + ry * py) / (s * s)
    s4 = (ry * px - rx * py) / (s * s)
    condition = root / s
    status, roundoff = classify(gap, span)
    # A next to O4: each derivative divides by b + c cos gamma <= s once more
    status, roundoff = over_the_pivot(status, roundoff, s, span, order)
    c3 = c4 * cg - s4 * sg
    s3 = s4 * cg + c4 * sg
    theta4 = np.arctan2(s4, c4) + theta1
    theta3 = theta4 + gamma
    out = InvertedSliderCrankMotion(
        order=order,
        theta2=theta2,
        theta3=theta3,
        theta4=theta4,
        b=b,
        status=status,
        condition=condition,
        roundoff=roundoff,
        circuit=circuit,
        gamma=gamma,
    )
    # cos and sin of each link in the ground frame, for the points of the links
    out.directions = {"2": (cos2, sin2), "3": (c3, s3), "4": (c4, s4)}
    if order < 1:
        return out
    den = masked(status != OK, sigma * root)  # = b + c cos gamma

    def project(kx, ky):
        x = (ky * c3 - kx * s3) / den
        return x, kx * c3 + ky * s3 - x * csg

    # order 1: K = j a w2 e2
    k = a * omega2
    omega4, b_dot = project(-k * sin2, k * cos2)
    out.omega2, out.omega3, out.omega4, out.b_dot = omega2, omega4, omega4, b_dot
    if order < 2:
        return out
    # order 2: K = a(j al2 - w2^2) e2 - (2 j b' w - b w^2) e3 + c w^2 e4
    kx, ky = acc_term(a, cos2, sin2, omega2, alpha2)
    w2 = omega4 * omega4
    cor = 2.0 * b_dot * omega4
    kx = kx - (-b * w2 * c3 - cor * s3) + c * w2 * c4
    ky = ky - (-b * w2 * s3 + cor * c3) + c * w2 * s4
    alpha4, b_ddot = project(kx, ky)
    out.alpha2, out.alpha3, out.alpha4, out.b_ddot = alpha2, alpha4, alpha4, b_ddot
    if order < 3:
        return out
    # order 3: K = a(...)e2 - known part of (b e3)''' - known part of (c e4)'''
    kx, ky = jerk_term(a, cos2, sin2, omega2, alpha2, jerk2)
    re3 = -3.0 * b_dot * w2 - 3.0 * b * omega4 * alpha4
    im3 = 3.0 * b_ddot * omega4 + 3.0 * b_dot * alpha4 - b * w2 * omega4
    j4x, j4y = jerk_term(c, c4, s4, omega4, alpha4, 0.0)
    kx = kx - (re3 * c3 - im3 * s3) - j4x
    ky = ky - (re3 * s3 + im3 * c3) - j4y
    jerk4, b_dddot = project(kx, ky)
    out.jerk2, out.jerk3, out.jerk4, out.b_dddot = jerk2, jerk4, jerk4, b_dddot
    return out
