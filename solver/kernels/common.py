"""What every closed-form kernel shares: the refusal rule (round-off near a
limit position), the result record (:class:`Motion`), solving long sweeps in
pieces, and the derivative terms of a rotating vector.

The derivative terms are the building blocks of every differentiated loop
equation. For a vector of constant length L at angle theta(t) (Chapter 7,
eqs. 7.2 and 7.40):

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

import functools
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING, Any, ClassVar, ParamSpec, TypeAlias, TypeGuard, TypeVar

import numpy as np

from ..status import NOT_ASSEMBLABLE, OK, SINGULAR

EPS = float(np.finfo(float).eps)

#: what the kernels take and give: a float, or an array of floats (SI: m, rad, s)
Floats: TypeAlias = float | np.ndarray
_P = ParamSpec("_P")
_R = TypeVar("_R")

#: The closed-form kernels refuse (report ``singular``) a position where the
#: estimated relative round-off of their outputs exceeds this. Near a limit
#: position every output follows from one small "gap" (the distance of
#: |A - O4| from b + c or |b - c| in the fourbar; of |a sin theta2 - c| from b
#: in the slider-crank; ...), computed with an absolute error of about
#: eps * span (span: the sum of the link lengths that enter it). The outputs
#: grow like gap**(-1/2) (omega) .. gap**(-5/2) (jerk), so their relative
#: error is about ROUNDOFF_GAIN * eps * span / gap: that is ``Motion.roundoff``.
#: Measured against the 50-digit reference (benchmarks/reference.py:
#: about 850 random geometries, lengths spread over three decades, theta2 from
#: 1e-3 to 1e-11 rad from a limit, all four mechanisms) the worst output's
#: error was at most 1.1 (fourbar, fivebar, inverted slider-crank) and 2.5
#: (slider-crank) times eps * span / gap, hence the gain 4. Refusing above
#: 1e-6 keeps every answer at least ten times inside the 1e-5 that near-limit
#: answers must meet (the worst seen was 5e-7), and answers every position
#: farther than about 1e-8 rad (typical) .. 1e-6 rad (lengths three decades
#: apart) from a limit; none was refused farther than 1e-6 rad. The sine of
#: the transmission angle (``condition``) alone would not do: at condition
#: 1.3e-4 a fourbar with c/a = 1/400 was 1.1e-5 wrong in jerk4, and a
#: slider-crank with b/a = 1/400 was 8.9e-6 wrong at condition 1.6e-4.
MAX_ROUNDOFF = 1e-6
ROUNDOFF_GAIN = 4.0


#: |A - O4| / span below which :func:`over_the_pivot` refuses outputs of each order
_PIVOT_FRACTIONS = {n: float((ROUNDOFF_GAIN * EPS / MAX_ROUNDOFF) ** (1.0 / n)) for n in (1, 2, 3)}


def pivot_fraction(order: int) -> float:
    """|A - O4| / span below which :func:`over_the_pivot` refuses outputs of ``order``
    (1e-9 for a velocity, 3e-5 for an acceleration, 1e-3 for a jerk)."""
    return _PIVOT_FRACTIONS[min(max(order, 1), 3)]


def over_the_pivot(status: Any, roundoff: Any, s: Any, span: float, order: int) -> tuple[Any, Any]:
    """``(status, roundoff)`` with the round-off of a pin passing over a pivot.

    Where the crank pin A nears the pivot O4 (s = |A - O4| -> 0; reachable only where
    a = d, and in the fourbar b = c too), or in the geared fivebar the crank pins A and C
    meet (s = |C - A|, b = c), the direction of the link between them is 0/0, and each
    derivative divides by a length no larger than s once more: an order-n output carries a
    round-off of about eps (span / s)^n of its scale, even where the output stays finite
    (the kite and the isosceles inverted slider-crank turn link 4 at omega2 / 2 exactly).
    :func:`classify`'s estimate, eps span / gap, holds where the outputs grow toward a limit,
    not here: with A 1e-5 m from O4 (a = d = 1 m) jerk4 came out -2.5e3 rad/s^3 for 0.
    ``ROUNDOFF_GAIN * eps * (span / s)^order`` (measured: 3 to 5 times eps (span / s)^n) is
    taken as the round-off where larger, and a position SINGULAR where it passes
    :data:`MAX_ROUNDOFF`: about 1e-3 span from O4 for a jerk, 3e-5 for an acceleration.

    Parameters
    ----------
    status, roundoff : int8 and float (or arrays)
        From :func:`classify`.
    s : float or array
        Distance between the pin and the pivot (or pin) it passes [m, kernel's lengths].
    span : float
        Sum of the mechanism's lengths [m, the same measure].
    order : int
        Highest derivative solved (1 velocity .. 3 jerk); 0 adds nothing.

    Returns
    -------
    status, roundoff
        SINGULAR where the pivot's round-off passes MAX_ROUNDOFF (an OK position only), and
        the larger of the two estimates [-].
    """
    if order < 1 or not np.min(s, initial=np.inf) < span * pivot_fraction(order):
        return status, roundoff  # no position that near: nothing to add (the usual case)
    pivot = ROUNDOFF_GAIN * EPS * (span / s) ** order
    status = where((status == OK) & ~(pivot <= MAX_ROUNDOFF), np.int8(SINGULAR), status)
    return status, np.maximum(roundoff, pivot)


def classify(gap: Any, span: float) -> tuple[Any, Any]:
    """Status and estimated relative round-off of positions from their gap.

    Parameters
    ----------
    gap : float or array
        Distance of the position from its nearest limit, in the kernel's
        length measure [m]: >= 0 where the loop closes, NaN or < 0 where not.
    span : float
        Sum of the lengths that enter the gap [m] (its absolute round-off is
        about eps * span).

    Returns
    -------
    status : int8 (array)
        OK; SINGULAR where the round-off estimate exceeds
        :data:`MAX_ROUNDOFF`, including a gap within round-off of zero on
        either side (the kernels then take the limit position itself);
        NOT_ASSEMBLABLE where the gap is clearly negative.
    roundoff : float (array)
        ROUNDOFF_GAIN * eps * span / gap (inf at and past a limit).
    """
    tol = 2.0 * EPS * span
    if np.ndim(gap) == 0:  # one position: plain floats are ten times faster
        gap = float(gap)
        roundoff = ROUNDOFF_GAIN * EPS * span / gap if gap > 0 else math.inf
        code = NOT_ASSEMBLABLE if not gap > -tol else OK if roundoff <= MAX_ROUNDOFF else SINGULAR
        return np.int8(code), roundoff
    if gap.size and gap.min() > 0.0:  # every position closes (the usual sweep): fewer passes
        roundoff = ROUNDOFF_GAIN * EPS * span / gap
        if roundoff.max() <= MAX_ROUNDOFF:
            return np.zeros(gap.shape, dtype=np.int8), roundoff
        return np.where(roundoff <= MAX_ROUNDOFF, OK, SINGULAR).astype(np.int8), roundoff
    with np.errstate(divide="ignore", invalid="ignore"):
        roundoff = np.where(gap > 0, ROUNDOFF_GAIN * EPS * span / gap, np.inf)
    status = np.where(
        gap > -tol, np.where(roundoff <= MAX_ROUNDOFF, OK, SINGULAR), NOT_ASSEMBLABLE
    ).astype(np.int8)
    return status, roundoff


def length_unit(*lengths: Floats) -> float:
    """A power of two near the longest of ``lengths`` [m] (1.0 if none is
    finite and non-zero).

    The kernels divide every length by it before they compute and multiply
    the lengths they return by it after: dividing by a power of two is exact,
    and every formula is homogeneous in the lengths, so this changes no bit of
    any answer whose intermediate values stay within float64, and makes the
    geometry scale-free: a linkage scaled by any factor float64 can hold gives
    the same angles (the squares and fourth powers of the lengths that enter
    the formulas would otherwise overflow beyond about 1e77 m and underflow
    below 1e-77 m).
    """
    m = 0.0
    for x in lengths:
        x = abs(x) if type(x) is float else float(np.max(np.abs(x)))
        if x > m:
            m = x
    if not 0.0 < m < math.inf:
        return 1.0
    return math.ldexp(1.0, math.frexp(m)[1])


def scale_lengths(motion: "_MotionT", names: Iterable[str], unit: float) -> "_MotionT":
    """Multiply the outputs ``names`` of ``motion`` (a Motion; lengths and their
    derivatives) by ``unit`` [m], the :func:`length_unit` the kernel divided by;
    returns ``motion``."""
    if unit != 1.0:
        for name in names:
            value = getattr(motion, name)
            if value is not None:
                setattr(motion, name, value * unit)
    return motion


def as_input(x: Any) -> Floats:
    """A float for a scalar, else a float ndarray (the kernels keep a single
    position in Python floats: numpy's 0-d arrays cost a microsecond an operation)."""
    if type(x) is float:
        return x
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def where(cond, a, b):
    """np.where that stays a scalar for a scalar condition."""
    if np.ndim(cond) == 0:
        return a if cond else b
    return np.where(cond, a, b)


def masked(bad, x):
    """``x`` with NaN where ``bad`` (positions whose derivatives are refused)."""
    if np.ndim(bad) == 0:
        return math.nan if bad else x
    return np.where(bad, np.nan, x) if bad.any() else x


def without_float_warnings(func: Callable[_P, _R]) -> Callable[_P, _R]:
    """Run a kernel with numpy's floating-point warnings off: NaN marks the
    positions that do not assemble, and the status says so; an overflow
    (inputs too large for float64's range) is refused by the unit-aware layer
    and the batch, which check the outputs they give."""

    @functools.wraps(func)
    def wrapper(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return func(*args, **kwargs)

    return wrapper


#: the input motion every closed-form kernel echoes in its Motion [rad, rad/s, rad/s^2, rad/s^3]
INPUTS = ("theta2", "omega2", "alpha2", "jerk2")


def angles(*links: int) -> tuple[str, ...]:
    """The angular outputs of ``links`` (3, 4 ...), position to jerk, in the order
    results report them (docs/conventions.md#outputs): ``angles(3, 4)`` is theta3,
    theta4, omega3, omega4, alpha3, alpha4, jerk3, jerk4 [rad, rad/s, rad/s^2, rad/s^3]."""
    return tuple(f"{q}{k}" for q in ("theta", "omega", "alpha", "jerk") for k in links)


def slider(name: str) -> tuple[str, ...]:
    """A varying length and its derivatives: ``slider("d")`` is d, d_dot, d_ddot,
    d_dddot [m, m/s, m/s^2, m/s^3]."""
    return tuple(name + s for s in ("", "_dot", "_ddot", "_dddot"))


@dataclass(eq=False, slots=True)
class Motion:
    """Kinematic state of a mechanism over one or many positions (SI floats).

    Each kernel declares what it computes with :func:`outputs`, a subclass
    whose fields are exactly the kernel's: its ``OUTPUTS`` (link angles and
    their derivatives ``theta3`` .. ``jerk4`` [rad, rad/s, rad/s^2, rad/s^3],
    a slider's ``d`` .. ``d_dddot`` [m, m/s, ...], or a point's vectors
    ``R`` .. ``J``, complex), the input motion it echoes (``theta2`` ..
    ``jerk2``) and its ``EXTRA`` fields; a field not computed at the order
    asked stays None, and a name the kernel did not declare cannot be set
    (AttributeError: no output is ever lost silently). Results read the
    declaration: ``OUTPUTS`` are the names they report, ``SOLVED`` those
    the overflow check vouches for when the result is made.

    Always: ``status`` (int8 per position, :mod:`accelab.solver.status`),
    ``condition`` (dimensionless; 1 best, 0 at a toggle), ``roundoff``
    (estimated relative round-off of the derivatives) and ``order``, the
    highest derivative computed (0 position .. 3 jerk). ``directions`` maps a
    link number ("2", "3" ...) to the cosine and sine of its angle measured
    from the ground link, ``theta_k - theta1``, which the kernel computed anyway
    (the points of the links are built from them, then turned by ``theta1``
    in :mod:`accelab.solver.mechanisms.base`).
    """

    status: Any
    condition: Any = 1.0
    roundoff: Any = 0.0
    order: int = 3
    circuit: str | None = None
    directions: dict[str, tuple[Any, Any]] = field(default_factory=dict)

    #: the outputs a result of this kernel reports, in their order
    OUTPUTS: ClassVar[tuple[str, ...]] = ()
    #: the real outputs the kernel solves its loop for (checked for overflow when a
    #: result is made, see Result._verify); by default all of OUTPUTS
    SOLVED: ClassVar[frozenset[str]] = frozenset()
    #: fields beyond the inputs and OUTPUTS (a constant the result reads back ...)
    EXTRA: ClassVar[tuple[str, ...]] = ()
    #: every field, the kinematic ones and the bookkeeping above
    NAMES: ClassVar[frozenset[str]] = frozenset(
        ("status", "condition", "roundoff", "order", "circuit", "directions")
    )

    if TYPE_CHECKING:  # the fields are each kernel's declaration (outputs): any name to mypy

        def __init__(self, status: Any, **values: Any) -> None: ...
        def __getattr__(self, name: str) -> Any: ...
        def __setattr__(self, name: str, value: Any) -> None: ...

    def get(self, name: str) -> Any:
        """The field ``name``, or None when this kernel has no such field
        (or it was not computed at this order)."""
        return getattr(self, name) if name in self.NAMES else None

    def keys(self) -> list[str]:
        """The names of the fields that hold values."""
        return [f.name for f in fields(self) if getattr(self, f.name) is not None]


_MotionT = TypeVar("_MotionT", bound=Motion)


def outputs(cls: type[_MotionT]) -> type[_MotionT]:
    """Make ``cls``, a subclass of :class:`Motion` that sets ``OUTPUTS`` (and
    perhaps ``SOLVED``, ``EXTRA``), the record of one kernel: a dataclass
    whose fields are the inputs, the outputs and the extras, None by default
    (with ``__slots__``: setting an undeclared name raises). The fourbar's is
    ``@outputs class FourbarMotion(Motion)`` with ``OUTPUTS = angles(3, 4)``.
    """
    names = tuple(dict.fromkeys(INPUTS + tuple(cls.OUTPUTS) + tuple(cls.EXTRA)))
    cls.__annotations__ = {n: Any for n in names}
    for n in names:
        setattr(cls, n, None)
    if "SOLVED" not in vars(cls):
        cls.SOLVED = frozenset(cls.OUTPUTS)
    cls.NAMES = Motion.NAMES | frozenset(names)
    return dataclass(eq=False, slots=True)(cls)


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
    """Components of L (-3 omega alpha + j (jerk - omega^3)) e^{j theta} [L/s^3] (eq. 7.40)."""
    re = -3.0 * L * omega * alpha
    im = L * (jerk - omega * omega * omega)
    return re * cos - im * sin, re * sin + im * cos


def triangle_angles(s, b, c, span):
    """Interior angles of a triangle with sides s, b, c, robust near degeneracy.

    Returns ``(cos_psi, sin_psi, cos_chi, sin_chi, area4, gap)`` where psi is
    the angle between sides s and b, chi between s and c, ``area4`` is four
    times the area, and ``gap`` = min(s + b - c, s - b + c, b + c - s), the
    distance from the nearest degenerate (collinear) triangle: negative where
    the triangle cannot close (area4 NaN there). The area uses the factored
    Heron form, which keeps the relative accuracy of the gap as the triangle
    flattens (a toggle position). A gap within round-off (2 eps span) below
    zero is taken as zero: the toggle position itself. Call it with numpy's
    invalid/divide warnings off (see :func:`without_float_warnings`).
    """
    f2 = s + b - c
    f3 = s - b + c
    f4 = b + c - s
    gap = np.minimum(np.minimum(f2, f3), f4)
    prod = where((gap <= 0) & (gap > -2.0 * EPS * span), 0.0, (s + b + c) * f2 * f3 * f4)
    area4 = np.sqrt(prod)
    ss = s * s
    bb = b * b
    cc = c * c
    cos_psi = (ss + bb - cc) / (2.0 * s * b)
    sin_psi = area4 / (2.0 * s * b)
    cos_chi = (ss + cc - bb) / (2.0 * s * c)
    sin_chi = area4 / (2.0 * s * c)
    return cos_psi, sin_psi, cos_chi, sin_chi, area4, gap


#: positions per piece when a kernel solves a long sweep piece by piece
#: (:func:`in_pieces`; the fourbar's in-place path works in pieces of the
#: same size). A piece's temporaries are 64 kB each (8192 float64), so a
#: piece's working set stays in the CPU's caches and its arrays are reused
#: from the heap without page faults. The reason holds for any
#: current CPU, not one machine; at 10^5 positions pieces of 8192 were 5-15 %
#: faster than whole arrays (slider-crank, inverted slider-crank, fivebar) and
#: as fast (fourbar), and 4096, 16384 and 32768 no better (README, "Speed").
PIECE = 8192
#: sweeps shorter than this are solved as whole arrays: below some 5 x 10^4
#: positions the pieces' fixed cost and copies made them slower
MIN_PIECEWISE = 65536


def pieces(n):
    """The slices of :data:`PIECE` positions that cover ``n`` positions."""
    return [slice(start, min(start + PIECE, n)) for start in range(0, n, PIECE)]


def piecewise(
    theta2: Floats, motion: Iterable[Any], others: Iterable[Any]
) -> TypeGuard[np.ndarray]:
    """Whether :func:`in_pieces` takes a sweep: theta2 an array of at least
    :data:`MIN_PIECEWISE` positions, each of ``motion`` (omega2, alpha2,
    jerk2) a scalar or an array of theta2's shape, and ``others`` (lengths,
    angles) scalars."""
    if not isinstance(theta2, np.ndarray) or theta2.size < max(MIN_PIECEWISE, PIECE + 1):
        return False
    return same_shapes(theta2, motion, others)


def same_shapes(theta2, motion, others):
    """Each of ``motion`` a scalar or of theta2's shape, and ``others`` scalars."""
    shape = theta2.shape
    return all(np.ndim(x) == 0 or np.shape(x) == shape for x in motion) and all(
        np.ndim(x) == 0 for x in others
    )


def in_pieces(
    solve: Callable[..., _MotionT], theta2: np.ndarray, omega2: Any, alpha2: Any, jerk2: Any
) -> _MotionT:
    """A kernel's Motion over a long sweep, solved :data:`PIECE` positions at a time.

    ``solve(theta2, omega2, alpha2, jerk2)`` solves one piece (the same
    vectorized formulas, so the same bits as one whole-array call). Fields of
    one value per position (and the links' ``directions``) are gathered into
    arrays of theta2's shape; everything else is taken from the first piece,
    and the inputs are the caller's own.
    """
    shape = theta2.shape
    flat = theta2.reshape(-1)
    n = flat.size
    motion = [np.ravel(x) if np.ndim(x) else x for x in (omega2, alpha2, jerk2)]
    inputs = {"theta2": theta2, "omega2": omega2, "alpha2": alpha2, "jerk2": jerk2}

    def solved(sl):
        return solve(flat[sl], *(x[sl] if np.ndim(x) else x for x in motion))

    slices = pieces(n)
    first = solved(slices[0])
    one_each = (min(n, PIECE),)  # the shape of a field with one value per position

    def per_position(v):
        return isinstance(v, np.ndarray) and v.shape == one_each

    full = {
        k: np.empty(n, getattr(first, k).dtype)
        for k in first.keys()
        if k not in inputs and per_position(getattr(first, k))
    }
    gathered = {
        k: [np.empty(n) if per_position(x) else x for x in v] for k, v in first.directions.items()
    }
    names = [f.name for f in fields(first)]
    out = type(first)(**{k: (None if k in full else getattr(first, k)) for k in names})
    for sl in slices:
        part = first if sl is slices[0] else solved(sl)
        for k, v in full.items():
            v[sl] = getattr(part, k)
        for k, parts in gathered.items():
            for whole, piece in zip(parts, part.directions[k]):
                if whole is not piece:
                    whole[sl] = piece
    for k, v in full.items():
        setattr(out, k, v.reshape(shape))
    out.directions = {
        k: tuple(x.reshape(shape) if isinstance(x, np.ndarray) else x for x in v)
        for k, v in gathered.items()
    }
    for k, v in inputs.items():
        if getattr(out, k) is not None:
            setattr(out, k, v)
    return out
