"""A point on a rotating link (section 7.1) and a block sliding on one
(the slotted link of Figure 7-7), unit-free.

Rotating point at radius p (eqs. 7.2, 7.3):
    R = p e^{j theta},  V = p omega j e^{j theta}
    A = A_t + A_n,  A_t = p alpha j e^{j theta},  A_n = -p omega^2 e^{j theta}
    J = p (-3 omega alpha + j (jerk - omega^3)) e^{j theta}

Block at the varying distance p(t) along a link rotating about the origin
(eq. 7.19): A = A_slip + A_coriolis + A_t + A_n with
    A_slip     = p'' e^{j theta}
    A_coriolis = 2 p' omega j e^{j theta}
and the jerk of the same variable-length vector (see common.py).
"""

import numpy as np

from .common import OK, Floats, Motion, outputs, without_float_warnings


@outputs
class RotatingPointMotion(Motion):
    """What :func:`rotating_point` returns: the point's vectors, complex."""

    OUTPUTS = ("R", "V", "A", "A_t", "A_n", "J")
    SOLVED = frozenset()  # complex vectors: checked for overflow where they are read


@outputs
class SlotMotion(Motion):
    """What :func:`slotted_link` returns: the block's vectors, complex."""

    OUTPUTS = ("R", "V", "V_t", "V_slip", "A", "A_t", "A_n", "A_coriolis", "A_slip", "J")
    SOLVED = frozenset()  # complex vectors: checked for overflow where they are read


@without_float_warnings
def rotating_point(
    p: Floats, theta: Floats, omega: Floats, alpha: Floats = 0.0, jerk: Floats = 0.0
) -> RotatingPointMotion:
    """Position to jerk of a point at radius ``p`` [m] on a link turning about
    the origin. Returns complex arrays R [m], V [m/s], A_t, A_n, A [m/s^2],
    J [m/s^3] in a :class:`RotatingPointMotion` (every position ``OK``: a point in rotation has no
    limit position)."""
    e = np.exp(1j * np.asarray(theta, dtype=float))
    je = 1j * e
    A_t = p * alpha * je
    A_n = -p * omega * omega * e
    return RotatingPointMotion(
        _all_ok(A_t),
        R=p * e,
        V=p * omega * je,
        A_t=A_t,
        A_n=A_n,
        A=A_t + A_n,
        J=p * (-3.0 * omega * alpha + 1j * (jerk - omega * omega * omega)) * e,
    )


def _all_ok(x):
    shape = np.shape(x)
    return np.zeros(shape, dtype=np.int8) if shape else np.int8(OK)


@without_float_warnings
def slotted_link(
    theta: Floats,
    omega: Floats,
    alpha: Floats,
    p: Floats,
    p_dot: Floats,
    p_ddot: Floats = 0.0,
    p_dddot: Floats = 0.0,
    jerk: Floats = 0.0,
) -> SlotMotion:
    """A block sliding along a rotating link (Figure 7-7, eq. 7.19).

    Parameters
    ----------
    theta, omega, alpha, jerk : float or array
        Angle of the link [rad] and its derivatives.
    p, p_dot, p_ddot, p_dddot : float or array
        Distance of the block from the pivot [m] and its derivatives
        (slip velocity [m/s], acceleration, jerk).

    Returns
    -------
    SlotMotion
        Complex R, V, A_t, A_n, A_coriolis, A_slip, A, J; the velocity parts
        V_t (p omega j e^{j theta}) and V_slip (p' e^{j theta}).
    """
    e = np.exp(1j * np.asarray(theta, dtype=float))
    je = 1j * e
    A_t = p * alpha * je
    A_n = -p * omega * omega * e
    A_coriolis = 2.0 * p_dot * omega * je
    A_slip = p_ddot * e
    w2 = omega * omega
    J = (
        p_dddot
        - 3.0 * p_dot * w2
        - 3.0 * p * omega * alpha
        + 1j * (3.0 * p_ddot * omega + 3.0 * p_dot * alpha + p * jerk - p * w2 * omega)
    ) * e
    return SlotMotion(
        _all_ok(A_t),
        R=p * e,
        V_t=p * omega * je,
        V_slip=p_dot * e,
        V=(p_dot + 1j * p * omega) * e,
        A_t=A_t,
        A_n=A_n,
        A_coriolis=A_coriolis,
        A_slip=A_slip,
        A=A_t + A_n + A_coriolis + A_slip,
        J=J,
    )
