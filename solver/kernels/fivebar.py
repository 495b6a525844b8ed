"""The geared fivebar, position to jerk, in closed form (unit-free).

Vector loop (docs/conventions.md#mechanisms; its first and second derivatives are eqs. 6.32a
and 7.28a):
    a e^{j theta2} + b e^{j theta3} - c e^{j theta4} - d e^{j theta5} - f e^{j theta1} = 0
    theta5 = lam theta2 + phi   (angles measured from the ground line O2->O5)

The gears make link 5 a known function of the input, so the loop has two
unknowns (theta3, theta4) like a fourbar whose "ground pivot" C = O5 + d e^{j theta5}
moves. The triangle A-B-C with sides b, c, s = |C - A| gives the position;
``open`` puts B on the same side of the line A->C as the fourbar's open
circuit puts B relative to A->O4 (as for the equivalent fourbar), ``crossed``
on the other side.

Derivatives (eq. 7.29 for n = 2): differentiating n times,

    K_n + j b x3 e^{j theta3} - j c x4 e^{j theta4} = 0

where K_n now also contains the fully known derivatives of d e^{j theta5}
(omega5 = lam omega2, alpha5 = lam alpha2, jerk5 = lam jerk2). Then, as for
the fourbar, x3 = (K_n . e4) / (b sin(theta3 - theta4)) and
x4 = (K_n . e3) / (c sin(theta3 - theta4)).
"""

import numpy as np

from .common import (
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
    triangle_angles,
    without_float_warnings,
)

CIRCUITS = {"open": 1.0, "crossed": -1.0}


@outputs
class FiveBarMotion(Motion):
    """What :func:`solve` returns: links 3, 4 and the geared link 5, position to jerk."""

    OUTPUTS = angles(3, 4, 5)


@without_float_warnings
def solve(
    a: float,
    b: float,
    c: float,
    d: float,
    f: float,
    lam: float,
    phi: float,
    theta2: Floats,
    omega2: Floats,
    alpha2: Floats = 0.0,
    jerk2: Floats = 0.0,
    theta1: float = 0.0,
    circuit: str = "open",
    order: int = 3,
) -> FiveBarMotion:
    """Geared fivebar kinematics from position to jerk.

    Parameters
    ----------
    a, b, c, d : float
        Lengths of crank 2 (O2A), coupler 3 (AB), coupler 4 (CB) and crank 5
        (O5C) [m].
    f : float
        Ground length O2O5 [m].
    lam : float
        Gear ratio theta5 / theta2 (signed; negative for external gears) [-].
    phi : float
        Phase angle of link 5 [rad].
    theta2, omega2, alpha2, jerk2 : float or array
        Input angle [rad] and its derivatives [rad/s, rad/s^2, rad/s^3].
    theta1 : float
        Ground angle [rad].

    Returns
    -------
    FiveBarMotion
        theta3, theta4, theta5 [rad]; omega3..5; alpha3..5; jerk3..5;
        ``status``; ``condition`` = |sin(theta3 - theta4)|; ``roundoff``
        (see :func:`accelab.solver.kernels.fourbar.solve`).
    """
    sigma = CIRCUITS[circuit]
    theta2 = as_input(theta2)
    order = min(order, 3)
    unit = length_unit(a, b, c, d, f)  # scale-free: lengths near 1, exactly
    a, b, c, d, f = a / unit, b / unit, c / unit, d / unit, f / unit
    if piecewise(theta2, (omega2, alpha2, jerk2), (a, b, c, d, f, lam, phi, theta1)):
        return in_pieces(
            lambda t2, w2, a2, j2: solve(
                a, b, c, d, f, lam, phi, t2, w2, a2, j2, theta1, circuit, order
            ),
            theta2,
            omega2,
            alpha2,
            jerk2,
        )
    t2 = theta2 - theta1
    t5 = lam * t2 + phi
    cos2, sin2 = np.cos(t2), np.sin(t2)
    cos5, sin5 = np.cos(t5), np.sin(t5)
    rx = f + d * cos5 - a * cos2  # r = C - A
    ry = d * sin5 - a * sin2
    s = np.hypot(rx, ry)
    span = a + b + c + d + f
    cos_psi, sin_psi, cos_chi, sin_chi, area4, gap = triangle_angles(s, b, c, span)
    ux, uy = rx / s, ry / s
    sp = sigma * sin_psi
    c3 = ux * cos_psi - uy * sp
    s3 = uy * cos_psi + ux * sp
    sc = sigma * sin_chi
    c4 = -(ux * cos_chi + uy * sc)
    s4 = -(uy * cos_chi - ux * sc)
    S = -sigma * area4 / (2.0 * b * c)
    condition = np.abs(S)
    status, roundoff = classify(gap, span)
    # A and C meeting (b = c): each derivative divides by a length <= |C - A| once more
    status, roundoff = over_the_pivot(status, roundoff, s, span, order)
    theta3 = np.arctan2(s3, c3) + theta1
    theta4 = np.arctan2(s4, c4) + theta1
    out = FiveBarMotion(
        order=order,
        theta2=theta2,
        theta3=theta3,
        theta4=theta4,
        theta5=t5 + theta1,
        status=status,
        condition=condition,
        roundoff=roundoff,
        circuit=circuit,
    )
    # cos and sin of each link in the ground frame, for the points of the links
    out.directions = {"2": (cos2, sin2), "3": (c3, s3), "4": (c4, s4), "5": (cos5, sin5)}
    if order < 1:
        return out
    S = masked(status != OK, S)
    bS, cS = b * S, c * S
    omega5 = lam * omega2
    # order 1: K = j a w2 e2 - j d w5 e5
    k2, k5 = a * omega2, d * omega5
    kx = -k2 * sin2 + k5 * sin5
    ky = k2 * cos2 - k5 * cos5
    omega3 = (kx * c4 + ky * s4) / bS
    omega4 = (kx * c3 + ky * s3) / cS
    out.omega2, out.omega3, out.omega4, out.omega5 = omega2, omega3, omega4, omega5
    if order < 2:
        return out
    alpha5 = lam * alpha2
    ax, ay = acc_term(a, cos2, sin2, omega2, alpha2)
    dx, dy = acc_term(d, cos5, sin5, omega5, alpha5)
    n3, n4 = b * omega3 * omega3, c * omega4 * omega4
    kx = ax - dx - n3 * c3 + n4 * c4
    ky = ay - dy - n3 * s3 + n4 * s4
    alpha3 = (kx * c4 + ky * s4) / bS
    alpha4 = (kx * c3 + ky * s3) / cS
    out.alpha2, out.alpha3, out.alpha4, out.alpha5 = alpha2, alpha3, alpha4, alpha5
    if order < 3:
        return out
    jerk5 = lam * jerk2
    ax, ay = jerk_term(a, cos2, sin2, omega2, alpha2, jerk2)
    dx, dy = jerk_term(d, cos5, sin5, omega5, alpha5, jerk5)
    j3x, j3y = jerk_term(b, c3, s3, omega3, alpha3, 0.0)
    j4x, j4y = jerk_term(c, c4, s4, omega4, alpha4, 0.0)
    kx = ax - dx + j3x - j4x
    ky = ay - dy + j3y - j4y
    out.jerk2, out.jerk5 = jerk2, jerk5
    out.jerk3 = (kx * c4 + ky * s4) / bS
    out.jerk4 = (kx * c3 + ky * s3) / cS
    return out
