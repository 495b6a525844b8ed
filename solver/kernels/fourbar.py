"""The pin-jointed fourbar, position to jerk, in closed form (unit-free).

Vector loop (eq. 4.5c, repeated in section 7.3; docs/conventions.md#mechanisms):
    a e^{j theta2} + b e^{j theta3} - c e^{j theta4} - d e^{j theta1} = 0

Position. With A = a e^{j theta2} and O4 = d e^{j theta1}, the triangle
A-B-O4 has sides b, c and s = |O4 - A|; B lies on the side of line A->O4
given by the circuit. ``open`` is the chapter's eq. 4.10b with the minus sign.
With r = O4 - A, the law of cosines and Heron's area (4 x area = H) give the
links' unit vectors without any angle (sigma = +1 open, -1 crossed):

    e3 = (r (s^2 + b^2 - c^2) + sigma j r H) / (2 b s^2)
    e4 = -(r (s^2 - b^2 + c^2) - sigma j r H) / (2 c s^2)

Derivatives. Differentiating the loop n times gives, at every order,

    K_n + j b x3 e^{j theta3} - j c x4 e^{j theta4} = 0

where x3, x4 are omega (n=1, eq. 6.14c), alpha (n=2, eq. 7.7) or jerk (n=3,
eq. 7.34) of links 3 and 4 and K_n holds the already known terms. Dotting
with e^{j theta4} and e^{j theta3} eliminates one unknown each:

    x3 = (K_n . e4) / (b sin(theta3 - theta4))
    x4 = (K_n . e3) / (c sin(theta3 - theta4))

This is the solution of eqs. 7.11 (eq. 7.12) and of eqs. 7.35 (eqs. 7.36-7.39)
written without the chapter's auxiliary constants; the same 2x2 matrix
serves every order. With
Lk (j x_k - w_k^2) e_k for the acceleration of a link (eq. 7.2) and
Lk (-3 w_k x_k + j (j_k - w_k^3)) e_k for its jerk (eq. 7.40):

    K_1 = j a omega2 e2
    K_2 = a (j alpha2 - omega2^2) e2 - b omega3^2 e3 + c omega4^2 e4
    K_3 = a (-3 omega2 alpha2 + j (jerk2 - omega2^3)) e2 - 3 b omega3 alpha3 e3
          + 3 c omega4 alpha4 e4 - j b omega3^3 e3 + j c omega4^3 e4

The last two terms of K_3 are perpendicular to e3 and e4 and dot to
b omega3^3 S with e4 and to c omega4^3 S with e3 (S = sin(theta3 - theta4)):
they add omega3^3 to jerk3 and omega4^3 to jerk4 and stay out of the dot
products. Each K_n is summed as one vector (x and y) before both dot
products, so that its rounding acts as one small change of K_n shared by x3
and x4. (Dotting term by term gives alpha3 and alpha4 independent rounding
where the terms of K_2 cancel; the jerk, which depends on both, then lost up
to 2.5e-12 relative on 1500 of the tests' well-conditioned fourbars, against
3.6e-13 this way.)

Two implementations of these formulas, the same operations in the same
order: :func:`solve` (plain expressions, for one position in Python floats
and for short arrays) and :func:`_solve_in_place` (sweeps of
:data:`MIN_IN_PLACE` positions or more, in pieces of
:data:`~accelab.solver.kernels.common.PIECE` positions with every operation writing
into a few preallocated work arrays, so that they stay in the cache). The
benchmark shows the second is needed (10^5 positions: 0.11 against 0.14
us/position); tests/test_kernels_common.py checks that both give the same bits.
"""

import threading

import numpy as np

from . import common
from .common import (
    EPS,
    MAX_ROUNDOFF,
    OK,
    ROUNDOFF_GAIN,
    SINGULAR,
    Floats,
    Motion,
    angles,
    as_input,
    classify,
    length_unit,
    masked,
    outputs,
    over_the_pivot,
    pieces,
    pivot_fraction,
    same_shapes,
    without_float_warnings,
)

CIRCUITS = {"open": 1.0, "crossed": -1.0}


@outputs
class FourbarMotion(Motion):
    """What :func:`solve` returns: links 3 and 4, position to jerk."""

    OUTPUTS = angles(3, 4)


#: fewer positions than this are solved by plain whole-array expressions, whose
#: fixed cost per call is lower (the same formulas: the same bits); from here
#: on the in-place path, piece by piece (its 13 work arrays, kept between
#: calls, and its part of the 16 outputs stay in the cache)
MIN_IN_PLACE = 2000
_KEPT = threading.local()


def position(
    a: float, b: float, c: float, d: float, cos2: Floats, sin2: Floats, sigma: float
) -> tuple[Floats, Floats, Floats, Floats, Floats, Floats]:
    """Unit vectors of links 3 and 4 from the ground link (floats or arrays).

    Returns ``(c3, s3, c4, s4, area4, gap)``: cos/sin of theta3 and theta4
    measured from the ground line, four times the area of the triangle
    A-B-O4 (Heron, factored; NaN where it cannot close), and its gap (the
    distance of |A - O4| from b + c or |b - c|, negative where the loop
    cannot close). A gap within round-off below zero is taken as zero: the
    toggle position itself.
    """
    scalar = np.ndim(cos2) == 0
    rx = d - a * cos2  # r = O4 - A
    ry = -a * sin2
    ss = rx * rx + ry * ry
    s = np.sqrt(ss)
    bmc, bpc = b - c, b + c
    f2, f3, f4 = s + bmc, s - bmc, bpc - s
    f23 = s - abs(bmc)  # = min(f2, f3)
    prod: Floats = (s + bpc) * f2 * f3 * f4
    tol = 2.0 * EPS * (a + b + c + d)
    if scalar:
        gap = f23 if f23 <= f4 else f4
        if -tol < gap <= 0.0:
            prod = 0.0
    else:
        gap = np.minimum(f23, f4)
        if not gap.min(initial=np.inf) > 0.0:  # a limit position, or past one
            prod = np.where((gap <= 0.0) & (gap > -tol), 0.0, prod)
    area4 = np.sqrt(prod)
    k = b * b - c * c
    inv3 = (0.5 / b) / ss
    inv4 = (-0.5 / c) / ss
    rxh = rx * area4
    ryh = ry * area4
    P = ss + k
    Q = ss - k
    c3 = (rx * P - sigma * ryh) * inv3
    s3 = (ry * P + sigma * rxh) * inv3
    c4 = (rx * Q + sigma * ryh) * inv4
    s4 = (ry * Q - sigma * rxh) * inv4
    return c3, s3, c4, s4, area4, gap


def _coefficients(a, omega2, alpha2, jerk2):
    """The crank's terms of K_1..K_3 (floats, or arrays for array inputs): a omega2,
    -a omega2, -a omega2^2, a alpha2, -3 a omega2 alpha2 and a (jerk2 - omega2^3)."""
    mk = -a * omega2
    return (
        a * omega2,
        mk,
        mk * omega2,
        a * alpha2,
        -3.0 * a * omega2 * alpha2,
        a * (jerk2 - omega2 * omega2 * omega2),
    )


@without_float_warnings
def solve(
    a: float,
    b: float,
    c: float,
    d: float,
    theta2: Floats,
    omega2: Floats,
    alpha2: Floats = 0.0,
    jerk2: Floats = 0.0,
    theta1: float = 0.0,
    circuit: str = "open",
    order: int = 3,
) -> FourbarMotion:
    """Fourbar kinematics from position to jerk.

    Parameters
    ----------
    a, b, c, d : float
        Crank, coupler, rocker and ground lengths [m] (any one length unit
        works; only their ratios matter, at any scale float64 holds).
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
    FourbarMotion
        theta3, theta4 [rad]; omega3, omega4 [rad/s]; alpha3, alpha4
        [rad/s^2]; jerk3, jerk4 [rad/s^3]; ``status``; ``condition``
        (|sin(theta3 - theta4)|, the sine of the transmission angle) and
        ``roundoff``, the estimated relative round-off of the derivatives
        (positions where it exceeds :data:`~accelab.solver.kernels.common.MAX_ROUNDOFF`
        are ``singular``: within about 1e-7 rad of a toggle).

    Notes
    -----
    Chapter 7, eqs. 7.7-7.12 (acceleration) and 7.34-7.39 (jerk), derived
    here as described in the module docstring.
    """
    sigma = CIRCUITS[circuit]
    theta2 = as_input(theta2)
    order = min(order, 3)
    unit = length_unit(a, b, c, d)  # scale-free: lengths near 1, exactly
    a, b, c, d = a / unit, b / unit, c / unit, d / unit
    span = a + b + c + d
    # A can come within the pivot's reach of O4 only where a = d and b = c nearly (a kite)
    kite = order > 0 and max(abs(a - d), abs(b - c)) < span * pivot_fraction(order)
    if (
        isinstance(theta2, np.ndarray)
        and theta2.size >= MIN_IN_PLACE
        and not kite
        and same_shapes(theta2, (omega2, alpha2, jerk2), (a, b, c, d, theta1))
    ):
        return _solve_in_place(
            float(a),
            float(b),
            float(c),
            float(d),
            theta2,
            omega2,
            alpha2,
            jerk2,
            float(theta1),
            sigma,
            circuit,
            order,
        )
    turned = np.ndim(theta1) > 0 or theta1 != 0.0
    t2 = theta2 - theta1 if turned else theta2
    cos2, sin2 = np.cos(t2), np.sin(t2)
    c3, s3, c4, s4, area4, gap = position(a, b, c, d, cos2, sin2, sigma)
    condition = area4 / (2.0 * b * c)
    status, roundoff = classify(gap, span)
    if kite:  # A next to O4: each derivative divides by a length <= |A - O4| once more
        s = np.hypot(d - a * cos2, a * sin2)
        status, roundoff = over_the_pivot(status, roundoff, s, span, order)
    theta3 = np.arctan2(s3, c3)
    theta4 = np.arctan2(s4, c4)
    if turned:
        theta3, theta4 = theta3 + theta1, theta4 + theta1
    out = FourbarMotion(
        order=order,
        theta2=theta2,
        theta3=theta3,
        theta4=theta4,
        status=status,
        condition=condition,
        roundoff=roundoff,
        circuit=circuit,
    )
    # cos and sin of each link from the ground link (theta_k - theta1), for the links' points
    out.directions = {"2": (cos2, sin2), "3": (c3, s3), "4": (c4, s4)}
    if order < 1:
        return out
    cond = masked(status != OK, condition)
    bS = cond * (-sigma * b)  # b sin(theta3 - theta4)
    cS = cond * (-sigma * c)
    k, mk, n, t, R2, I2 = _coefficients(a, omega2, alpha2, jerk2)
    # order 1: K = j a omega2 e2
    kx = mk * sin2
    ky = k * cos2
    omega3 = (kx * c4 + ky * s4) / bS
    omega4 = (kx * c3 + ky * s3) / cS
    out.omega2, out.omega3, out.omega4 = omega2, omega3, omega4
    if order < 2:
        return out
    # order 2: K = a (j alpha2 - omega2^2) e2 - b omega3^2 e3 + c omega4^2 e4
    p3 = omega3 * omega3
    p4 = omega4 * omega4
    n3 = p3 * b
    n4 = p4 * c
    kx = n * cos2 - t * sin2 - n3 * c3 + n4 * c4
    ky = n * sin2 + t * cos2 - n3 * s3 + n4 * s4
    alpha3 = (kx * c4 + ky * s4) / bS
    alpha4 = (kx * c3 + ky * s3) / cS
    out.alpha2, out.alpha3, out.alpha4 = alpha2, alpha3, alpha4
    if order < 3:
        return out
    # order 3: K = (R2 + j I2) e2 + R3 e3 - R4 e4, and the omega^3 terms apart
    R3 = omega3 * alpha3 * (-3.0 * b)
    R4 = omega4 * alpha4 * (-3.0 * c)
    kx = R2 * cos2 - I2 * sin2 + R3 * c3 - R4 * c4
    ky = R2 * sin2 + I2 * cos2 + R3 * s3 - R4 * s4
    out.jerk2 = jerk2
    out.jerk3 = (kx * c4 + ky * s4) / bS + p3 * omega3
    out.jerk4 = (kx * c3 + ky * s3) / cS + p4 * omega4
    return out


def _solve_in_place(a, b, c, d, theta2, omega2, alpha2, jerk2, theta1, sigma, circuit, order):
    """:func:`solve` over an array of positions, piece by piece, in place.

    The same operations as :func:`solve` and :func:`position` in the same
    order (so the same bits), each writing into a work array of the piece.
    """
    shape = theta2.shape
    t2all = theta2.reshape(-1)
    n = t2all.size
    motion = [np.ravel(x) if np.ndim(x) else x for x in (omega2, alpha2, jerk2)]
    varying = any(np.ndim(x) for x in motion)
    if not varying:
        coef = _coefficients(a, *motion)
    names = [
        "theta3",
        "theta4",
        "cos2",
        "sin2",
        "c3",
        "s3",
        "c4",
        "s4",
        "condition",
        "roundoff",
    ] + ["omega3", "omega4", "alpha3", "alpha4", "jerk3", "jerk4"][: 2 * order]
    res = {k: np.empty(n) for k in names}
    status = np.empty(n, dtype=np.int8)
    span = a + b + c + d
    tol = 2.0 * EPS * span
    gain = ROUNDOFF_GAIN * EPS * span  # as in classify
    bmc, bpc = b - c, b + c
    abs_bmc = abs(bmc)
    bbcc = b * b - c * c
    h3, h4 = 0.5 / b, -0.5 / c
    two_bc = 2.0 * b * c
    mb, mc = -sigma * b, -sigma * c
    m3b, m3c = -3.0 * b, -3.0 * c
    plus, minus = (np.add, np.subtract) if sigma > 0 else (np.subtract, np.add)
    work = _work()
    for sl in pieces(n):
        rx, ry, ss, s, f2, f3, f4, gap, P, Q, inv3, inv4, t = work[:, : sl.stop - sl.start]
        cos2, sin2 = res["cos2"][sl], res["sin2"][sl]
        c3, s3, c4, s4 = res["c3"][sl], res["s3"][sl], res["c4"][sl], res["s4"][sl]
        condition, roundoff = res["condition"][sl], res["roundoff"][sl]
        st = status[sl]
        t2 = t2all[sl]
        if theta1:
            t2 = np.subtract(t2, theta1, out=t)
        np.cos(t2, out=cos2)
        np.sin(t2, out=sin2)
        # position (see position())
        np.multiply(cos2, a, out=rx)
        np.subtract(d, rx, out=rx)
        np.multiply(sin2, -a, out=ry)
        np.multiply(rx, rx, out=ss)
        np.multiply(ry, ry, out=t)
        np.add(ss, t, out=ss)
        np.sqrt(ss, out=s)
        np.add(s, bmc, out=f2)
        np.subtract(s, bmc, out=f3)
        np.subtract(bpc, s, out=f4)
        np.subtract(s, abs_bmc, out=gap)
        np.minimum(gap, f4, out=gap)
        prod = np.add(s, bpc, out=s)
        prod *= f2
        prod *= f3
        prod *= f4
        gmin = gap.min()
        if not gmin > 0.0:  # a limit position, or past one, in this piece
            np.copyto(prod, 0.0, where=(gap <= 0.0) & (gap > -tol))
        area4 = np.sqrt(prod, out=prod)
        np.divide(area4, two_bc, out=condition)
        np.divide(h3, ss, out=inv3)
        np.divide(h4, ss, out=inv4)
        rxh = np.multiply(rx, area4, out=f2)
        ryh = np.multiply(ry, area4, out=f3)
        np.add(ss, bbcc, out=P)
        np.subtract(ss, bbcc, out=Q)
        np.multiply(rx, P, out=c3)
        minus(c3, ryh, out=c3)
        c3 *= inv3
        np.multiply(ry, P, out=s3)
        plus(s3, rxh, out=s3)
        s3 *= inv3
        np.multiply(rx, Q, out=c4)
        plus(c4, ryh, out=c4)
        c4 *= inv4
        np.multiply(ry, Q, out=s4)
        minus(s4, rxh, out=s4)
        s4 *= inv4
        # status and round-off (see classify)
        if gmin > 0.0:
            np.divide(gain, gap, out=roundoff)
            ok = roundoff.max() <= MAX_ROUNDOFF
            if ok:
                st.fill(OK)
            else:
                np.copyto(st, np.where(roundoff <= MAX_ROUNDOFF, OK, SINGULAR))
        else:
            ok = False
            st[...], roundoff[...] = classify(gap, span)
        th3, th4 = res["theta3"][sl], res["theta4"][sl]
        np.arctan2(s3, c3, out=th3)
        np.arctan2(s4, c4, out=th4)
        if theta1:
            th3 += theta1
            th4 += theta1
        if order < 1:
            continue
        # derivatives (see solve())
        if varying:
            coef = _coefficients(a, *(x[sl] if np.ndim(x) else x for x in motion))
        ka, mk, nn, tt, R2, I2 = coef
        bS = np.multiply(condition, mb, out=P)
        cS = np.multiply(condition, mc, out=Q)
        if not ok:
            bad = st != OK
            bS[bad] = np.nan
            cS[bad] = np.nan
        kx, ky = rx, ry
        np.multiply(sin2, mk, out=kx)
        np.multiply(cos2, ka, out=ky)
        w3, w4 = res["omega3"][sl], res["omega4"][sl]
        _solve2(kx, ky, c3, s3, c4, s4, bS, cS, w3, w4, t)
        if order < 2:
            continue
        p3, p4, n3, n4 = ss, inv3, inv4, f2
        np.multiply(w3, w3, out=p3)
        np.multiply(w4, w4, out=p4)
        np.multiply(p3, b, out=n3)
        np.multiply(p4, c, out=n4)
        _rotating(nn, tt, cos2, sin2, kx, ky, t)
        np.multiply(n3, c3, out=t)
        kx -= t
        np.multiply(n4, c4, out=t)
        kx += t
        np.multiply(n3, s3, out=t)
        ky -= t
        np.multiply(n4, s4, out=t)
        ky += t
        a3, a4 = res["alpha3"][sl], res["alpha4"][sl]
        _solve2(kx, ky, c3, s3, c4, s4, bS, cS, a3, a4, t)
        if order < 3:
            continue
        R3, R4 = n3, n4
        np.multiply(w3, a3, out=R3)
        R3 *= m3b
        np.multiply(w4, a4, out=R4)
        R4 *= m3c
        _rotating(R2, I2, cos2, sin2, kx, ky, t)
        np.multiply(R3, c3, out=t)
        kx += t
        np.multiply(R4, c4, out=t)
        kx -= t
        np.multiply(R3, s3, out=t)
        ky += t
        np.multiply(R4, s4, out=t)
        ky -= t
        j3, j4 = res["jerk3"][sl], res["jerk4"][sl]
        _solve2(kx, ky, c3, s3, c4, s4, bS, cS, j3, j4, t)
        np.multiply(p3, w3, out=t)
        j3 += t
        np.multiply(p4, w4, out=t)
        j4 += t
    res = {k: v.reshape(shape) for k, v in res.items()}
    out = FourbarMotion(
        order=order,
        theta2=theta2,
        theta3=res["theta3"],
        theta4=res["theta4"],
        status=status.reshape(shape),
        condition=res["condition"],
        roundoff=res["roundoff"],
        circuit=circuit,
    )
    out.directions = {
        "2": (res["cos2"], res["sin2"]),
        "3": (res["c3"], res["s3"]),
        "4": (res["c4"], res["s4"]),
    }
    if order >= 1:
        out.omega2, out.omega3, out.omega4 = omega2, res["omega3"], res["omega4"]
    if order >= 2:
        out.alpha2, out.alpha3, out.alpha4 = alpha2, res["alpha3"], res["alpha4"]
    if order >= 3:
        out.jerk2, out.jerk3, out.jerk4 = jerk2, res["jerk3"], res["jerk4"]
    return out


def _work():
    """The piece's 13 work arrays, kept from call to call (one set per thread):
    fresh arrays would cost the page faults of new memory at every call."""
    work = getattr(_KEPT, "work", None)
    if work is None or work.shape[1] != common.PIECE:
        work = _KEPT.work = np.empty((13, common.PIECE))
    return work


def _rotating(re, im, cos2, sin2, kx, ky, t):
    """kx, ky = the components of (re + j im) e^{j theta2}, in place:
    re cos2 - im sin2 and re sin2 + im cos2."""
    np.multiply(cos2, re, out=kx)
    np.multiply(sin2, im, out=t)
    kx -= t
    np.multiply(sin2, re, out=ky)
    np.multiply(cos2, im, out=t)
    ky += t


def _solve2(kx, ky, c3, s3, c4, s4, bS, cS, x3, x4, t):
    """x3 = (K . e4) / (b S), x4 = (K . e3) / (c S), in place."""
    np.multiply(kx, c4, out=x3)
    np.multiply(ky, s4, out=t)
    x3 += t
    x3 /= bS
    np.multiply(kx, c3, out=x4)
    np.multiply(ky, s3, out=t)
    x4 += t
    x4 /= cS
