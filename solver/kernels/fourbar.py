"""The pin-jointed fourbar, position to jerk, in closed form (unit-free).

Vector loop (Chapter 7, eq. 7.6; CONVENTIONS):
    a e^{j theta2} + b e^{j theta3} - c e^{j theta4} - d e^{j theta1} = 0

Position. With A = a e^{j theta2} and O4 = d e^{j theta1}, the triangle
A-B-O4 has sides b, c and s = |O4 - A|; B lies on the side of line A->O4
given by the circuit. ``open`` is the chapter's eq. 4.10b with the minus sign.

Derivatives. Differentiating the loop n times gives, at every order,

    K_n + j b x3 e^{j theta3} - j c x4 e^{j theta4} = 0

where x3, x4 are omega (n=1), alpha (n=2, eq. 7.12) or jerk (n=3, eqs.
7.34-7.39) of links 3 and 4 and K_n holds the already known terms. Dotting
with e^{j theta4} and e^{j theta3} eliminates one unknown each:

    x3 = (K_n . e4) / (b sin(theta3 - theta4))
    x4 = (K_n . e3) / (c sin(theta3 - theta4))

This is eq. 7.12 (and 6.18 for velocity) written without the chapter's
auxiliary constants A..F; the same 2x2 matrix serves every order.
"""

import numpy as np

from .common import (OK, Motion, acc_term, as_input, classify, jerk_term, masked, quiet,
                     triangle_angles)

CIRCUITS = {"open": 1.0, "crossed": -1.0}


def position(a, b, c, d, cos2, sin2, sigma):
    """Unit vectors of links 3 and 4 in the ground frame.

    Returns ``(c3, s3, c4, s4, S, gap)``: cos/sin of theta3 and theta4
    measured from the ground line, S = sin(theta3 - theta4), and the gap of
    the triangle A-B-O4 (the distance of |A - O4| from b + c or |b - c|,
    negative where the loop cannot close).
    """
    rx = d - a * cos2            # r = O4 - A
    ry = -a * sin2
    s = np.hypot(rx, ry)
    cos_psi, sin_psi, cos_chi, sin_chi, area4, gap = triangle_angles(s, b, c, a + b + c + d)
    ub_x, ub_y = rx / s, ry / s  # unit vector A -> O4
    # theta3 = beta + sigma psi ; theta4 = beta + pi - sigma chi
    sp = sigma * sin_psi
    c3 = ub_x * cos_psi - ub_y * sp
    s3 = ub_y * cos_psi + ub_x * sp
    sc = sigma * sin_chi
    c4 = -(ub_x * cos_chi + ub_y * sc)
    s4 = -(ub_y * cos_chi - ub_x * sc)
    S = -sigma * area4 / (2.0 * b * c)
    return c3, s3, c4, s4, S, gap


@quiet
def solve(a, b, c, d, theta2, omega2, alpha2=0.0, jerk2=0.0, theta1=0.0,
          circuit="open", order=3):
    """Fourbar kinematics from position to jerk.

    Parameters
    ----------
    a, b, c, d : float
        Crank, coupler, rocker and ground lengths [m] (any one length unit
        works, outputs follow it).
    theta2 : float or array
        Crank angle from the global x axis [rad].
    omega2, alpha2, jerk2 : float or array
        Crank angular velocity [rad/s], acceleration [rad/s^2], jerk [rad/s^3].
    theta1 : float
        Angle of the ground link O2->O4 [rad].
    circuit : {'open', 'crossed'}
    order : int
        Highest derivative computed: 0 position, 1 velocity, 2 acceleration,
        3 jerk (compute only what is needed).

    Returns
    -------
    Motion
        theta3, theta4 [rad]; omega3, omega4 [rad/s]; alpha3, alpha4
        [rad/s^2]; jerk3, jerk4 [rad/s^3]; ``status``; ``condition``
        (|sin(theta3 - theta4)|, the sine of the transmission angle) and
        ``roundoff``, the estimated relative round-off of the derivatives
        (positions where it exceeds :data:`~solver.kernels.common.MAX_ROUNDOFF`
        are ``singular``: within about 1e-7 rad of a toggle).

    Notes
    -----
    Chapter 7, eqs. 7.12-7.13 (acceleration) and 7.34-7.39 (jerk), derived
    here as described in the module docstring.
    """
    sigma = CIRCUITS[circuit]
    theta2 = as_input(theta2)
    t2 = theta2 - theta1
    cos2, sin2 = np.cos(t2), np.sin(t2)
    c3, s3, c4, s4, S, gap = position(a, b, c, d, cos2, sin2, sigma)
    condition = np.abs(S)
    status, roundoff = classify(gap, a + b + c + d)
    theta3 = np.arctan2(s3, c3) + theta1
    theta4 = np.arctan2(s4, c4) + theta1
    out = Motion(theta2=theta2, theta3=theta3, theta4=theta4, status=status,
                 condition=condition, roundoff=roundoff, circuit=circuit)
    # cos and sin of each link in the ground frame, for the points of the links
    out._unit = {"2": (cos2, sin2), "3": (c3, s3), "4": (c4, s4)}
    if order < 1:
        return out
    S = masked(status != OK, S)
    bS = b * S
    cS = c * S
    # order 1: K = j a omega2 e2
    k = a * omega2
    kx, ky = -k * sin2, k * cos2
    omega3 = (kx * c4 + ky * s4) / bS
    omega4 = (kx * c3 + ky * s3) / cS
    out.omega2, out.omega3, out.omega4 = omega2, omega3, omega4
    if order < 2:
        return out
    # order 2: K = a(j alpha2 - omega2^2) e2 - b omega3^2 e3 + c omega4^2 e4
    kx, ky = acc_term(a, cos2, sin2, omega2, alpha2)
    n3 = b * omega3 * omega3
    n4 = c * omega4 * omega4
    kx = kx - n3 * c3 + n4 * c4
    ky = ky - n3 * s3 + n4 * s4
    alpha3 = (kx * c4 + ky * s4) / bS
    alpha4 = (kx * c3 + ky * s3) / cS
    out.alpha2, out.alpha3, out.alpha4 = alpha2, alpha3, alpha4
    if order < 3:
        return out
    # order 3: K = a(...)e2 + b(-3 w3 a3 - j w3^3) e3 - c(-3 w4 a4 - j w4^3) e4
    kx, ky = jerk_term(a, cos2, sin2, omega2, alpha2, jerk2)
    j3x, j3y = jerk_term(b, c3, s3, omega3, alpha3, 0.0)
    j4x, j4y = jerk_term(c, c4, s4, omega4, alpha4, 0.0)
    kx = kx + j3x - j4x
    ky = ky + j3y - j4y
    out.jerk2 = jerk2
    out.jerk3 = (kx * c4 + ky * s4) / bS
    out.jerk4 = (kx * c3 + ky * s3) / cS
    return out
