"""The offset slider-crank, position to jerk, in closed form (unit-free).

Vector loop (eq. 4.14b, repeated in section 7.3; docs/conventions.md#mechanisms):
    a e^{j theta2} - b e^{j theta3} - c e^{j theta4} - d e^{j theta1} = 0,
    theta4 = theta1 + 90 deg, c = slider offset (signed), d = slider position.

Position: the imaginary part gives sin(theta3) = (a sin theta2 - c) / b; the
``open`` circuit has the slider on the +x side of the crank pin, so
cos(theta3) < 0 (R3 points from B back to A). Then d = a cos theta2 - b cos theta3.

Derivatives: differentiating n times,

    K_n - j b x3 e^{j theta3} - d^(n) = 0

with K_n the known terms. The imaginary part gives
x3 = Im(K_n) / (b cos theta3) (omega3, alpha3, jerk3; eqs. 7.16c-d for n = 2),
the real part d^(n) = Re(K_n) + b x3 sin theta3 (eqs. 7.16b, e). The position is
singular where cos theta3 = 0: the coupler stands perpendicular to the slide.
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
    piecewise,
    scale_lengths,
    slider,
    where,
    without_float_warnings,
)

CIRCUITS = {"open": -1.0, "crossed": 1.0}


@outputs
class SliderCrankMotion(Motion):
    """What :func:`solve` returns: the connecting rod (link 3) and the slider's position d,
    position to jerk."""

    OUTPUTS = angles(3) + slider("d")


@without_float_warnings
def solve(
    a: float,
    b: float,
    c: float,
    theta2: Floats,
    omega2: Floats,
    alpha2: Floats = 0.0,
    jerk2: Floats = 0.0,
    theta1: float = 0.0,
    circuit: str = "open",
    order: int = 3,
) -> SliderCrankMotion:
    """Slider-crank kinematics from position to jerk.

    Parameters
    ----------
    a, b : float
        Crank and connecting-rod lengths [m].
    c : float
        Slider offset [m], signed, may be 0.
    theta2, omega2, alpha2, jerk2 : float or array
        Crank angle [rad] from the global x axis and its derivatives
        [rad/s, rad/s^2, rad/s^3].
    theta1 : float
        Angle of the slide axis [rad].
    circuit : {'open', 'crossed'}
    order : int
        Highest derivative computed (0..3).

    Returns
    -------
    SliderCrankMotion
        theta3 [rad], omega3, alpha3, jerk3; d [m] (slider position along the
        slide axis from O2), d_dot [m/s], d_ddot [m/s^2], d_dddot [m/s^3];
        ``status``; ``condition`` = |cos theta3 (relative to the slide)|;
        ``roundoff`` (see :func:`accelab.solver.kernels.fourbar.solve`).
    """
    unit = length_unit(a, b, c)  # scale-free: lengths near 1, exactly
    out = _solve(
        a / unit, b / unit, c / unit, theta2, omega2, alpha2, jerk2, theta1, circuit, order
    )
    return scale_lengths(out, slider("d"), unit)


def _solve(a, b, c, theta2, omega2, alpha2, jerk2, theta1, circuit, order):
    """:func:`solve` with lengths of order 1 (see :func:`~.common.length_unit`)."""
    sigma = CIRCUITS[circuit]
    theta2 = as_input(theta2)
    order = min(order, 3)
    if piecewise(theta2, (omega2, alpha2, jerk2), (a, b, c, theta1)):
        return in_pieces(
            lambda t2, w2, a2, j2: _solve(a, b, c, t2, w2, a2, j2, theta1, circuit, order),
            theta2,
            omega2,
            alpha2,
            jerk2,
        )
    t2 = theta2 - theta1
    cos2, sin2 = np.cos(t2), np.sin(t2)
    y = a * sin2 - c
    span = a + b + abs(c)
    # gap = b - |y|: how far the crank pin is from the rod's reach (0: rod
    # perpendicular to the slide); within round-off below 0, take it as 0
    gap = np.minimum(b - y, b + y)
    prod = where((gap <= 0) & (gap > -2.0 * EPS * span), 0.0, (b - y) * (b + y))
    c3 = sigma * np.sqrt(prod) / b
    s3 = masked(np.isnan(c3), np.minimum(np.maximum(y / b, -1.0), 1.0))
    condition = np.abs(c3)
    status, roundoff = classify(gap, span)
    theta3 = np.arctan2(s3, c3) + theta1
    d = a * cos2 - b * c3
    out = SliderCrankMotion(
        order=order,
        theta2=theta2,
        theta3=theta3,
        d=d,
        status=status,
        condition=condition,
        roundoff=roundoff,
        circuit=circuit,
    )
    # cos and sin of each link in the ground frame, for the points of the links
    out.directions = {"2": (cos2, sin2), "3": (c3, s3)}
    if order < 1:
        return out
    bc3 = b * masked(status != OK, c3)
    # order 1: K = j a omega2 e2
    k = a * omega2
    kx, ky = -k * sin2, k * cos2
    omega3 = ky / bc3
    d_dot = kx + b * omega3 * s3
    out.omega2, out.omega3, out.d_dot = omega2, omega3, d_dot
    if order < 2:
        return out
    # order 2: K = a(j alpha2 - w2^2) e2 + b w3^2 e3
    kx, ky = acc_term(a, cos2, sin2, omega2, alpha2)
    n3 = b * omega3 * omega3
    kx = kx + n3 * c3
    ky = ky + n3 * s3
    alpha3 = ky / bc3
    out.alpha2, out.alpha3 = alpha2, alpha3
    out.d_ddot = kx + b * alpha3 * s3
    if order < 3:
        return out
    # order 3: K = a(...)e2 - b(-3 w3 a3 - j w3^3) e3
    kx, ky = jerk_term(a, cos2, sin2, omega2, alpha2, jerk2)
    j3x, j3y = jerk_term(b, c3, s3, omega3, alpha3, 0.0)
    kx = kx - j3x
    ky = ky - j3y
    jerk3 = ky / bc3
    out.jerk2, out.jerk3 = jerk2, jerk3
    out.d_dddot = kx + b * jerk3 * s3
    return out
