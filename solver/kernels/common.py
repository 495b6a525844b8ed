"""What every closed-form kernel shares: status codes, the singularity
threshold, the result container, and the derivative terms of a rotating vector.

The derivative terms are the building blocks of every differentiated loop
equation. For a vector of constant length L at angle theta(t) (Chapter 7,
eqs. 7.2 and 7.33):

    z    = L e^{j theta}
    z'   = L (j omega) e^{j theta}
    z''  = L (j alpha - omega^2) e^{j theta}
    z''' = L (-3 omega alpha + j (jerk - omega^3)) e^{j theta}

and for a vector whose length b(t) also varies (a slider, eq. 7.19):

    z''  = (b'' - b omega^2 + j (b alpha + 2 b' omega)) e^{j theta}
    z''' = (b''' - 3 b' omega^2 - 3 b omega alpha
            + j (3 b'' omega + 3 b' alpha + b jerk - b omega^3)) e^{j theta}

Each helper returns the (x, y) components of such a term.
"""

import numpy as np

OK, NOT_ASSEMBLABLE, SINGULAR = 0, 1, 2
STATUS_NAMES = {OK: "ok", NOT_ASSEMBLABLE: "not_assemblable", SINGULAR: "singular"}

#: A position whose condition measure (1 best, 0 at a toggle) falls below this
#: is reported ``singular``. Relative round-off in the derivatives grows like
#: eps / condition**2 (about 1e-8 here), while the condition measure near a
#: limit position grows like the square root of the distance to it in theta2,
#: so only positions within about 1e-8 rad of a limit are refused. The
#: benchmark's stability study (Chart 2) charts this choice against the data.
SINGULAR_CONDITION = 1e-4


class Motion:
    """Kinematic state of a mechanism over one or many positions.

    Attributes are float arrays in SI units (rad, rad/s, rad/s^2, rad/s^3, m,
    m/s, ...), named as in the chapter (theta3, omega4, alpha3, jerk4, b_dot,
    d_ddot, ...), plus ``status`` (int8: 0 ok, 1 not assemblable, 2 singular)
    and ``condition`` (dimensionless; 1 is best, 0 is a toggle position).
    """

    def __init__(self, **fields):
        self.__dict__.update(fields)

    def __repr__(self):
        names = ", ".join(sorted(k for k in self.__dict__))
        return f"Motion({names})"

    def keys(self):
        return self.__dict__.keys()


def rotate(x, y, cos1, sin1):
    """Rotate components (x, y) by the ground angle theta1 (given its cos, sin)."""
    return x * cos1 - y * sin1, x * sin1 + y * cos1


def vel_term(L, cos, sin, omega):
    """Components of L j omega e^{j theta} [L/s]."""
    k = L * omega
    return -k * sin, k * cos


def acc_term(L, cos, sin, omega, alpha):
    """Components of L (j alpha - omega^2) e^{j theta} [L/s^2] (eq. 7.2)."""
    n = -L * omega * omega
    t = L * alpha
    return n * cos - t * sin, n * sin + t * cos


def jerk_term(L, cos, sin, omega, alpha, jerk):
    """Components of L (-3 omega alpha + j (jerk - omega^3)) e^{j theta} [L/s^3] (eq. 7.33)."""
    re = -3.0 * L * omega * alpha
    im = L * (jerk - omega * omega * omega)
    return re * cos - im * sin, re * sin + im * cos


def triangle_angles(s, b, c):
    """Interior angles of a triangle with sides s, b, c, robust near degeneracy.

    Returns ``(cos_psi, sin_psi, cos_chi, sin_chi, area4)`` where psi is the
    angle between sides s and b, chi between s and c, and ``area4`` is four
    times the area (NaN where the triangle cannot close: s > b + c or
    s < |b - c|). The area uses the factored Heron form, which keeps full
    relative accuracy as the triangle flattens (a toggle position).
    """
    prod = (s + b + c) * (s + b - c) * (s - b + c) * (b + c - s)
    with np.errstate(invalid="ignore"):
        area4 = np.sqrt(prod)
    ss = s * s
    bb = b * b
    cc = c * c
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_psi = (ss + bb - cc) / (2.0 * s * b)
        sin_psi = area4 / (2.0 * s * b)
        cos_chi = (ss + cc - bb) / (2.0 * s * c)
        sin_chi = area4 / (2.0 * s * c)
    return cos_psi, sin_psi, cos_chi, sin_chi, area4


def as_arrays(*values):
    """Broadcast inputs to float arrays of one shape; report whether all were scalars."""
    scalar = all(np.ndim(v) == 0 for v in values)
    arrays = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in values])
    return scalar, arrays
