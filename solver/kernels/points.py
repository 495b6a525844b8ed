"""Position to jerk of any point on any link (section 7.5, eqs. 7.30-7.32, 7.41).

A point X at distance L from a base point Y on link k, at the fixed angle
``offset`` from the link's reference line, moves with

    R_XY = L e^{j (theta_k + offset)}
    V_XY = L omega_k j e^{j (...)}
    A_XY = A_XY^t + A_XY^n = L alpha_k j e^{j (...)} - L omega_k^2 e^{j (...)}
    J_XY = L (-3 omega_k alpha_k + j (jerk_k - omega_k^3)) e^{j (...)}

and its absolute motion is that of Y plus these (eq. 7.4 and its analogues).
These helpers return complex arrays; they are called only for the points a
caller asks about. Each takes the unit vector e^{j(theta + offset)} as ``e``
(and j e^{j(...)} as ``je``) when the caller already has them: a sweep asks
for R, V, A, J of several points on one link, and one pair serves them all.
Each vector is formed as (real array) * e + (real array) * je, which costs
a third of complex coefficient arithmetic on arrays of a few hundred.
"""

import numpy as np


def unit(theta, offset=0.0):
    """e^{j (theta + offset)} as a complex array."""
    t = np.asarray(theta, dtype=float) + offset
    return from_components(np.cos(t), np.sin(t))


def from_components(cos, sin):
    """cos + j sin as a complex array (or complex scalar)."""
    if np.ndim(cos) == 0 and np.ndim(sin) == 0:
        return complex(cos, sin)
    out = np.empty(np.broadcast_shapes(np.shape(cos), np.shape(sin)), dtype=complex)
    out.real = cos
    out.imag = sin
    return out


def _pair(theta, offset, e, je):
    if e is None:
        e = unit(theta, offset)
    return e, (1j * e if je is None else je)


def relative_position(L, theta, offset=0.0, e=None):
    """R_XY = L e^{j(theta + offset)} [m]."""
    return L * (unit(theta, offset) if e is None else e)


def relative_velocity(L, theta, omega, offset=0.0, e=None, je=None):
    """V_XY = L omega j e^{j(theta + offset)} [m/s] (eq. 6.3)."""
    e, je = _pair(theta, offset, e, je)
    return (L * omega) * je


def relative_acceleration_parts(L, theta, omega, alpha, offset=0.0, e=None, je=None):
    """(A_XY^t, A_XY^n) [m/s^2]: tangential L alpha j e^{j..}, normal -L omega^2 e^{j..}
    (eq. 7.2)."""
    e, je = _pair(theta, offset, e, je)
    return (L * alpha) * je, (-L * omega * omega) * e


def relative_acceleration(L, theta, omega, alpha, offset=0.0, e=None, je=None):
    """A_XY = L (j alpha - omega^2) e^{j(theta + offset)} [m/s^2] (eq. 7.2)."""
    e, je = _pair(theta, offset, e, je)
    return (L * alpha) * je - (L * omega * omega) * e


def relative_jerk(L, theta, omega, alpha, jerk, offset=0.0, e=None, je=None):
    """J_XY = L (-3 omega alpha + j (jerk - omega^3)) e^{j(theta + offset)} [m/s^3] (eq. 7.40;
    J_X = J_Y + J_XY is eq. 7.41)."""
    e, je = _pair(theta, offset, e, je)
    return (-3.0 * L * omega * alpha) * e + (L * (jerk - omega * omega * omega)) * je
