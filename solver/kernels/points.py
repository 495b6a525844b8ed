"""Position to jerk of any point on any link (section 7.5, eqs. 7.30-7.32, 7.41).

A point X at distance L from a base point Y on link k, at the fixed angle
``offset`` from the link's reference line, moves with

    R_XY = L e^{j (theta_k + offset)}
    V_XY = L omega_k j e^{j (...)}
    A_XY = A_XY^t + A_XY^n = L alpha_k j e^{j (...)} - L omega_k^2 e^{j (...)}
    J_XY = L (-3 omega_k alpha_k + j (jerk_k - omega_k^3)) e^{j (...)}

and its absolute motion is that of Y plus these (eq. 7.4 and its analogues).
These helpers return complex arrays; they are called only for the points a
caller asks about.
"""

import numpy as np


def unit(theta, offset=0.0):
    """e^{j (theta + offset)} as a complex array."""
    t = np.asarray(theta, dtype=float) + offset
    return np.cos(t) + 1j * np.sin(t)


def relative_position(L, theta, offset=0.0):
    """R_XY = L e^{j(theta + offset)} [m]."""
    return L * unit(theta, offset)


def relative_velocity(L, theta, omega, offset=0.0):
    """V_XY = L omega j e^{j(theta + offset)} [m/s] (eq. 6.7)."""
    return 1j * L * omega * unit(theta, offset)


def relative_acceleration_parts(L, theta, omega, alpha, offset=0.0):
    """(A_XY^t, A_XY^n) [m/s^2]: tangential L alpha j e^{j..}, normal -L omega^2 e^{j..} (eq. 7.2)."""
    e = unit(theta, offset)
    return 1j * L * alpha * e, -L * omega * omega * e


def relative_acceleration(L, theta, omega, alpha, offset=0.0):
    """A_XY = L (j alpha - omega^2) e^{j(theta + offset)} [m/s^2] (eq. 7.2)."""
    return L * (1j * alpha - omega * omega) * unit(theta, offset)


def relative_jerk(L, theta, omega, alpha, jerk, offset=0.0):
    """J_XY = L (-3 omega alpha + j (jerk - omega^3)) e^{j(theta + offset)} [m/s^3] (eq. 7.41)."""
    return L * (-3.0 * omega * alpha + 1j * (jerk - omega ** 3)) * unit(theta, offset)
