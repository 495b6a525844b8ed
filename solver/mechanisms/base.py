"""What every unit-aware mechanism shares: its parameters read once (from
the declarations of :mod:`accelab.solver.parameters`), the lazy result object, and
the errors raised for one position."""

import cmath
import functools
import math
from collections.abc import Mapping
from typing import Any, TypeVar

import numpy as np
import pint

from ..errors import InvalidInput, NotAssemblable, Singular
from ..kernels import MAX_ROUNDOFF, NOT_ASSEMBLABLE, OK, points
from ..parameters import MOTION, Declaration
from ..registry import PARAMETERS
from ..results import Kinematics
from ..units import SI_UNITS, QuantityLike, SIValue, parse_quantity, quantity, show, to_si

#: a point's spec: (base point or pivot, length parameter or SI length or function, theta key,
#: offset angle [rad])
_PointSpec = tuple[Any, Any, Any, float]
_M = TypeVar("_M", bound="Mechanism")

#: name prefixes -> kind of quantity, longest prefix first
_KINDS = [
    ("theta", "angle"),
    ("gamma", "angle"),
    ("delta", "angle"),
    ("phi", "angle"),
    ("omega", "angular_velocity"),
    ("alpha", "angular_acceleration"),
    ("jerk", "angular_jerk"),
    ("R_", "length"),
    ("V_", "velocity"),
    ("A_", "acceleration"),
    ("J_", "jerk"),
]
_SLIDER_KINDS = {"": "length", "_dot": "velocity", "_ddot": "acceleration", "_dddot": "jerk"}
_VECTOR_ORDER = {"R": 0, "V": 1, "A": 2, "J": 3}
_ANGLE_ORDER = {"theta": 0, "omega": 1, "alpha": 2, "jerk": 3}
_SUFFIX_ORDER = {"_dddot": 3, "_ddot": 2, "_dot": 1}
_EXACT = {
    "R": "length",
    "V": "velocity",
    "A": "acceleration",
    "J": "jerk",
    "p": "length",
    "lam": "dimensionless",
    "condition": "dimensionless",
}


@functools.lru_cache(maxsize=1024)
def kind_of(name: str) -> str:
    """The kind of quantity a result attribute holds, from its name."""
    if name in _EXACT:
        return _EXACT[name]
    for prefix, kind in _KINDS:
        if name.startswith(prefix):
            return kind
    base, _, _ = name.partition("_")
    if len(base) == 1 and name[len(base) :] in _SLIDER_KINDS:  # d, d_dot, b_ddot, p ...
        return _SLIDER_KINDS[name[len(base) :]]
    raise AttributeError(name)


@functools.lru_cache(maxsize=1024)
def order_of(name: str) -> int:
    """The derivative an output needs (0 position .. 3 jerk)."""
    for prefix, n in _ANGLE_ORDER.items():
        if name.startswith(prefix):
            return n
    head = name.partition("_")[0]
    if head in _VECTOR_ORDER:
        return _VECTOR_ORDER[head]
    for suffix, n in _SUFFIX_ORDER.items():
        if name.endswith(suffix):
            return n
    return 0


def check_order(order: Any) -> int:
    """``order`` as an int 0..3 (position .. jerk), or InvalidInput."""
    if isinstance(order, bool) or not isinstance(order, (int, np.integer)) or not 0 <= order <= 3:
        raise InvalidInput(
            f"order must be 0 (position), 1 (velocity), 2 (acceleration) or 3 "
            f"(jerk), got {show(order)}",
            "order",
        )
    return int(order)


#: (kernel's Motion class, order) -> its solved outputs of that order (see Result._verify)
_TOPS: dict[tuple[type, int], list[str]] = {}


def _fmt_angle(rad):
    return f"{math.degrees(float(rad)):.6g} deg"


class Result(Kinematics):
    """Kinematics of a mechanism at one or many input positions.

    Attributes are computed when first read and returned as Quantities:
    angles ``theta3`` [rad], ``omega3``, ``alpha3``, ``jerk3``; slider
    quantities (``d``, ``d_dot``, ``b_ddot`` ...); point vectors as complex
    Quantities: ``R_X``, ``V_X``, ``A_X``, ``J_X`` for each point X of the
    mechanism, ``A_XY = A_X - A_Y`` (eq. 7.4) for any two points, and the
    tangential and normal components ``A_X_t``, ``A_X_n`` of a point about
    its own base (``A_BA_t`` for B about A on link 3 ...). ``result[name]``
    is the same (:mod:`accelab.solver.results`).

    ``valid`` is True where the mechanism assembles and is not singular,
    ``status`` names each position's state, ``condition`` is the kernel's
    dimensionless condition measure (1 best, 0 at a toggle).
    """

    def __init__(
        self,
        mechanism: "Mechanism",
        motion: Any,
        scalar: bool,
        inputs: Mapping[str, Any],
        pts: Mapping[str, _PointSpec] | None = None,
    ) -> None:
        self._mech = mechanism
        self._pts = mechanism._points if pts is None else pts
        self._motion = motion
        self._scalar = scalar
        self._inputs = inputs
        self._cache: dict[Any, Any] = {}
        self._status = motion.status
        self._condition = motion.condition
        self._verified = ()

    # --- unit-free access -------------------------------------------------
    def si(self, name: str) -> SIValue:
        """The SI value (float, complex, or array) of an output, unit-free.

        Raises InvalidInput where it overflows float64 at a position the
        result vouches for (inputs too large for float64's range): never an
        answer of Infinity or NaN.
        """
        cache = self._cache
        if name in cache:
            return cache[name]
        value = self._motion.get(name)
        if value is not None and name in self._verified:  # checked when solved
            cache[name] = value
            return value
        if value is None:
            with np.errstate(all="ignore"):
                value = self._compute(name)
            if self._scalar and isinstance(value, np.ndarray):
                value = value[()]
        self._check_finite(name, value)
        cache[name] = value
        return value

    def _verify(self, names):
        """Check the kernel's highest-order outputs ``names`` and mark every
        output the kernel solved as checked: a value that overflows spreads
        to every higher derivative (each is computed from the ones below), so
        finite highest orders vouch for the lower ones."""
        motion = self._motion
        if self._scalar:
            for name in names:
                if not math.isfinite(getattr(motion, name)):
                    self._check_finite(name, getattr(motion, name))
        else:
            for name in names:
                self._check_finite(name, getattr(motion, name))
        self._verified = type(motion).SOLVED

    def _check_finite(self, name, value):
        if self._scalar:
            if cmath.isfinite(value) or self._motion.status != OK:
                return
        else:
            finite = np.isfinite(value)
            if finite.all() or not (~finite & (self._motion.status == OK)).any():
                return
        raise InvalidInput(
            f"{name} overflows float64: the inputs are too large for its range (up to about "
            f"1.8e308 in SI units). Give smaller speeds or lengths (the angles do not depend "
            f"on the scale of the lengths), or solve to a lower order",
            name,
        )

    def kind(self, name: str) -> str:
        return kind_of(name)

    def has_point(self, name: str) -> bool:
        """Whether this result has the point ``name`` (A, B, P ...)."""
        return name in self._pts

    def _compute(self, name):
        value = self._motion.get(name)
        if value is not None:
            return value
        if name in self._inputs:
            return self._inputs[name]
        if order_of(name) > self._motion.order and self._names(name):
            raise AttributeError(
                f"{name} was not computed: this result was solved with order="
                f"{self._motion.order}; solve with order={order_of(name)} or more to read it"
            )
        value = self._mech._extra(self, name)
        if value is not None:
            return value
        head, _, rest = name.partition("_")
        if head in _VECTOR_ORDER and rest:
            order = _VECTOR_ORDER[head]
            comp = None
            if rest.endswith("_t") or rest.endswith("_n"):
                rest, comp = rest[:-2], rest[-1]
            pts = self._pts
            if comp is None and rest in pts:
                return self._point(rest, order)
            # a relative vector X-Y named XY (e.g. BA)
            for x in pts:
                if rest.startswith(x) and rest[len(x) :] in pts:
                    y = rest[len(x) :]
                    if comp is not None:
                        if order != 2:
                            break
                        return self._component(x, y, comp)
                    return self._point(x, order) - self._point(y, order)
            if comp is not None and rest in pts and order == 2:
                return self._component(rest, pts[rest][0], comp)
        record = type(self._motion)
        if name in record.OUTPUTS:  # declared, and left empty by the kernel: its fault
            raise AttributeError(
                f"{name} is declared by {record.__name__} but the kernel did not fill it at "
                f"order {self._motion.order}: its solve() must set it (see CONTRIBUTING.md, "
                "Add a mechanism)"
            )
        raise AttributeError(
            f"{type(self._mech).__name__} results have no output {name!r}; "
            f"available: {', '.join(self.outputs())}"
        )

    def _names(self, name):
        """Whether ``name`` is an output this mechanism would give at some order."""
        everything = self._mech.outputs(self)
        if name in everything:
            return True
        head, _, rest = name.partition("_")
        return head in _VECTOR_ORDER and bool(rest)

    def _point(self, x, order):
        key = ("RVAJ"[order], x)
        if key in self._cache:
            return self._cache[key]
        base, length, theta_key, offset = self._pts[x]
        if callable(length):
            value = length(self, order)
        else:
            value = self._relative(length, theta_key, offset, order)
            if base in self._pts:
                value = value + self._point(base, order)
            elif order == 0:
                value = value + self._mech._pivot(base)
        self._cache[key] = value
        return value

    def _unit(self, theta_key, offset):
        """(e, j e) with e = e^{j(theta_k + offset)}, computed once per link and
        offset; from the kernel's own cos and sin of the link where it has them."""
        key = ("e", theta_key, offset)
        pair = self._cache.get(key)
        if pair is None:
            known = self._motion.directions.get(theta_key[len("theta") :])
            if known is not None and offset == 0.0:
                e = points.from_components(*known)
                theta1 = self._mech._si.get("theta1", 0.0)
                if theta1:
                    e = e * complex(math.cos(theta1), math.sin(theta1))
            else:
                e = points.unit(self._motion.get(theta_key), offset)
            pair = self._cache[key] = (e, 1j * e)
        return pair

    def _relative(self, length, theta_key, offset, order):
        n = theta_key[len("theta") :]
        m = self._motion
        theta = m.get(theta_key)
        e, je = self._unit(theta_key, offset)
        if order == 0:
            return points.relative_position(length, theta, offset, e)
        if order == 1:
            return points.relative_velocity(length, theta, m.get("omega" + n), offset, e, je)
        if order == 2:
            return points.relative_acceleration(
                length, theta, m.get("omega" + n), m.get("alpha" + n), offset, e, je
            )
        return points.relative_jerk(
            length, theta, m.get("omega" + n), m.get("alpha" + n), m.get("jerk" + n), offset, e, je
        )

    def _component(self, x, y, comp):
        rel = self._mech._relative.get(x + y)
        if rel is not None:
            length, theta_key, offset = rel
            length = self._mech._si[length]
        else:
            base, length, theta_key, offset = self._pts[x]
            if base != y or callable(length):
                raise AttributeError(
                    f"no tangential/normal split of A_{x}{y}: {x} and {y} "
                    f"are not two points of one rigid link"
                )
        n = theta_key[len("theta") :]
        m = self._motion
        t, nn = points.relative_acceleration_parts(
            length,
            m.get(theta_key),
            m.get("omega" + n),
            m.get("alpha" + n),
            offset,
            *self._unit(theta_key, offset),
        )
        return t if comp == "t" else nn

    def point(
        self, link: int, p: QuantityLike, delta: QuantityLike = 0, base: str | None = None
    ) -> "PointMotion":
        """Position to jerk of any point on a link (section 7.5, eqs. 7.30-7.32, 7.41).

        Parameters
        ----------
        link : int
            Link number (2 crank, 3 coupler, 4 output, 5 the fivebar's crank 5).
        p : Quantity or str
            Distance of the point from ``base`` [length].
        delta : Quantity or str
            Angle from the link's own line (the direction of theta_link) to
            the point [angle], counter-clockwise.
        base : str, optional
            The pin the point is measured from; defaults to the link's pivot
            or first pin (link 2: O2, link 3: A, link 4: O4 or C ...).

        Returns
        -------
        PointMotion
            R, V, A, J (complex Quantities, up to the order solved) and A_t,
            A_n, the tangential and normal parts of the acceleration
            difference from ``base``. Use it for a link's centre of gravity
            before F = m A.
        """
        bases = self._mech._link_bases
        if isinstance(link, bool) or link not in bases:
            raise InvalidInput(
                f"{type(self._mech).__name__} has no rotating link {show(link)}; "
                f"use one of {sorted(bases)}",
                "link",
            )
        pins = sorted(set(self._pts) | set(self._mech._pivots))
        if base is not None and (not isinstance(base, str) or base not in pins):
            raise InvalidInput(
                f"base must be a pin of the {type(self._mech).__name__}: one of "
                f"{', '.join(pins)} (got {show(base)})",
                "base",
            )
        base = base or bases[link]
        p_si = to_si(p, "p", "length")
        delta_si = to_si(delta, "delta", "angle")
        if not (np.ndim(p_si) == 0 and np.ndim(delta_si) == 0):
            raise InvalidInput("p and delta of a point must be single values", "p")
        key = f"theta{link}"
        parts = {}
        for order, letter in enumerate("RVAJ"[: self._motion.order + 1]):
            rel = self._relative(p_si, key, delta_si, order)
            if base in self._pts:
                rel = rel + self._point(base, order)
            elif order == 0:
                rel = rel + self._mech._pivot(base)
            parts[letter] = rel
        n = str(link)
        m = self._motion
        if m.order >= 2:
            parts["A_t"], parts["A_n"] = points.relative_acceleration_parts(
                p_si, m.get(key), m.get("omega" + n), m.get("alpha" + n), delta_si
            )
        if self._scalar:
            parts = {k: v[()] if isinstance(v, np.ndarray) else v for k, v in parts.items()}
        return PointMotion(parts)

    # --- unit-aware access ------------------------------------------------
    def __getattr__(self, name: str) -> pint.Quantity:
        if name.startswith("_"):
            raise AttributeError(name)
        value = self.si(name)
        return quantity(value, kind_of(name))

    def __dir__(self) -> list[str]:
        return sorted(set(super().__dir__()) | set(self.outputs()))

    def outputs(self) -> list[str]:
        """Names of the outputs this result reports (as the batch contract
        lists them), those of its order."""
        return [n for n in self._mech.outputs(self) if order_of(n) <= self._motion.order]

    @property
    def roundoff(self) -> float | np.ndarray:
        """Estimated relative round-off of the derivative outputs (float or
        array); above :data:`~accelab.solver.kernels.MAX_ROUNDOFF` a position is
        ``singular``. Zero for mechanisms without limit positions."""
        r = self._motion.roundoff
        return float(r) if self._scalar else np.broadcast_to(r, np.shape(self._motion.status))

    @property
    def circuit(self) -> str | None:
        """The assembly solved ('open', 'crossed'; None for a mechanism with one)."""
        return self._motion.circuit

    def __repr__(self) -> str:
        mech = type(self._mech).__name__
        if not self._scalar:
            n = np.size(self._motion.status)
            nv = int(np.sum(self._motion.status == OK))
            return f"<{mech} result: {n} positions, {nv} valid, circuit {self.circuit!r}>"
        parts = []
        for name in self.outputs()[:8]:
            parts.append(f"{name}={getattr(self, name):.5g~P}")
        return f"<{mech} result ({self.circuit}): " + ", ".join(parts) + " ...>"


class PointMotion:
    """Position, velocity, acceleration and jerk of one point, as Quantities
    (``R``, ``V``, ``A``, ``J``, and ``A_t``, ``A_n`` about its base pin)."""

    _KINDS: dict[str, str] = {
        "R": "length",
        "V": "velocity",
        "A": "acceleration",
        "A_t": "acceleration",
        "A_n": "acceleration",
        "J": "jerk",
    }

    def __init__(self, parts: dict[str, SIValue]) -> None:
        self._si = parts

    def si(self, name: str) -> SIValue:
        """The SI value of ``name`` (``R`` [m], ``V`` [m/s], ``A``, ``A_t``,
        ``A_n`` [m/s^2], ``J`` [m/s^3]; complex: x + jy), unit-free."""
        return self._si[name]

    def __getattr__(self, name: str) -> pint.Quantity:
        if name.startswith("_") or name not in self._KINDS:
            raise AttributeError(name)
        if name not in self._si:
            raise AttributeError(
                f"{name} of the point was not computed at the order this "
                f"result was solved with; solve with a higher order"
            )
        return quantity(self._si[name], self._KINDS[name])

    def __repr__(self) -> str:
        return (
            "<PointMotion "
            + ", ".join(f"{k}={getattr(self, k):.5g~P}" for k in self._KINDS if k in self._si)
            + ">"
        )


class Mechanism:
    """Base of the unit-aware mechanisms.

    Subclasses name their entry of the registry, :data:`accelab.solver.registry.REGISTRY`
    (``name``) and declare ``_points`` (point -> (base point or pivot key,
    length parameter, theta key, offset)), ``_pivots`` (fixed pins),
    ``_point_outputs`` (the outputs they build from the points, beyond the
    kernel's own: the kernel's record declares those, see
    :func:`accelab.solver.kernels.common.outputs`) and a ``solve``/``solve_si``
    pair: ``solve`` takes Quantities or text and converts them to SI once;
    ``solve_si`` takes SI floats (what the batch format has already read) and
    calls the kernel.
    """

    #: its name in the registry (accelab.solver.registry), set by each mechanism
    name: str = ""
    _points: dict[str, _PointSpec] = {}
    #: "XY" -> (length parameter, theta key, offset) for X, Y on one link
    _relative: dict[str, tuple[str, str, float]] = {}
    _link_bases: dict[int, str] = {}  # link number -> the pin a point on it is measured from
    _pivots: tuple[str, ...] = ("O2",)
    #: outputs built from the points (R_A, A_BA ...), reported after the kernel's
    _point_outputs: tuple[str, ...] = ()

    def __init__(self, **geometry: QuantityLike) -> None:
        decl = self.declaration()
        names = [p.name for p in decl.geometry]
        unknown = sorted(set(geometry) - set(names))
        if unknown:
            raise InvalidInput(
                f"{type(self).__name__} has no parameter "
                f"{', '.join(map(str, unknown))}; it takes {', '.join(names)}",
                unknown[0],
            )
        si, units = {}, {}
        for p in decl.geometry:
            if p.name not in geometry:
                if p.required:
                    raise InvalidInput(
                        f"{type(self).__name__} needs {p.name} ({p.meaning}), e.g. {p.name}='2 in'",
                        p.name,
                    )
                si[p.name] = p.default
                continue
            q = parse_quantity(geometry[p.name], p.kind, p.name)
            value = to_si(q, p.name, p.kind, positive=p.positive)
            if np.ndim(value):
                raise InvalidInput(
                    f"{p.name} must be a single value: a {type(self).__name__} object is one "
                    f"linkage (got an array). Sweep theta2 (an array) on one linkage, or make "
                    f"one object per geometry",
                    p.name,
                )
            si[p.name] = float(value)
            units[p.name] = getattr(q, "units", None)
        self._init(si, geometry, units)

    @classmethod
    def declaration(cls) -> Declaration:
        """This mechanism's parameters (:class:`accelab.solver.parameters.Declaration`), as its
        entry of the registry declares them."""
        return PARAMETERS[cls.name]

    @classmethod
    def from_si(
        cls: type[_M],
        geometry: Mapping[str, float],
        given: Mapping[str, Any] | None = None,
        units: Mapping[str, Any] | None = None,
    ) -> _M:
        """The mechanism from geometry already read into SI floats (the batch
        format's path: no second conversion). ``given`` holds the user's own
        values and ``units`` the units they were written in, for messages."""
        obj = cls.__new__(cls)
        si = {
            p.name: float(geometry[p.name]) if p.name in geometry else p.default
            for p in cls.declaration().geometry
        }
        missing = [p.name for p in cls.declaration().geometry if si[p.name] is None]
        if missing:
            raise InvalidInput(f"{cls.__name__} needs {missing[0]}", missing[0])
        obj._init(si, {k: v for k, v in (given or {}).items() if k in si}, units or {})
        return obj

    def _init(self, si, given, units):
        self._si = si
        for name, value in si.items():
            setattr(self, "_" + name, value)
        self._given = given
        self._units = units
        self._points = {k: self._resolve_point(v) for k, v in type(self)._points.items()}
        self._validate()

    def _resolve_point(self, spec):
        base, length, theta_key, offset = spec
        if isinstance(length, str):
            length = self._si[length]
        return base, length, theta_key, offset

    def _validate(self):
        """Hook for geometry checks beyond positivity."""

    def __getattr__(self, name: str) -> pint.Quantity:
        if name.startswith("_"):
            raise AttributeError(name)
        for p in type(self).declaration().geometry:
            if p.name == name:
                return quantity(self._si[name], p.kind)
        raise AttributeError(name)

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={self._given_text(k)!r}" for k in self._si)
        return f"{type(self).__name__}({args})"

    def _length_unit(self):
        """The unit of the first length the user gave (None: metres)."""
        for p in self.declaration().geometry:
            if p.kind == "length" and self._units.get(p.name) is not None:
                return self._units[p.name]
        return None

    def _show(self, si_length):
        """A length [m] written in the unit the user gave the geometry in."""
        unit = self._length_unit()
        if unit is None:
            return f"{si_length:.6g} m"
        value = quantity(float(si_length), "length").m_as(unit)
        return f"{value:.6g} {unit:~}"

    def _given_text(self, name):
        """A parameter as the user wrote it (text, or a Quantity in its units)."""
        given = self._given.get(name)
        if isinstance(given, str):
            return given.strip()
        if given is not None and hasattr(given, "units"):
            return f"{given:~}"
        kind = next(p.kind for p in self.declaration().geometry if p.name == name)
        if kind == "length":
            return self._show(self._si[name])
        unit = SI_UNITS[kind]
        return f"{self._si[name]:.6g} {unit:~}".strip()

    def _pivot(self, key):
        """Position of a fixed pivot (complex, SI)."""
        return 0.0 + 0.0j

    def _extra(self, result, name):
        """Mechanism-specific outputs (Coriolis term, slider point ...)."""
        return None

    def outputs(self, result: Result) -> tuple[str, ...]:
        """Names of every output a ``result`` of this mechanism can report, in
        the order of docs/conventions.md#outputs (SI units: m, rad, s): those its
        kernel declares (``OUTPUTS`` of the kernel's Motion), then the points'."""
        return type(result._motion).OUTPUTS + self._point_outputs

    # --- solving ----------------------------------------------------------
    def solve(
        self,
        theta2: QuantityLike,
        omega2: QuantityLike,
        alpha2: QuantityLike = 0,
        jerk2: QuantityLike = 0,
        circuit: str | None = None,
        order: int = 3,
    ) -> Result:
        """Solve at one or many input angles.

        Parameters
        ----------
        theta2 : Quantity or str, scalar or array
            Input (crank) angle from the global x axis [angle].
        omega2, alpha2, jerk2 : Quantity or str
            Its angular velocity [1/time], acceleration [1/time^2] and jerk
            [1/time^3]; scalars or arrays broadcast with theta2 (alpha2 and
            jerk2 default to 0).
        circuit : {'open', 'crossed'}, optional
            The assembly (see the class); 'open' by default.
        order : int
            Highest derivative to compute (0 position .. 3 jerk).

        Returns
        -------
        Result
            Lazy Quantities (see the class for the outputs).

        Raises
        ------
        NotAssemblable, Singular
            For a scalar theta2 that cannot be assembled or is at a limit
            position. Arrays get a ``valid`` mask instead.
        """
        circuit = self._circuit(circuit)
        return self.solve_si(self._motion_inputs(theta2, omega2, alpha2, jerk2), circuit, order)

    def solve_si(
        self, motion: Mapping[str, Any], circuit: str | None = None, order: int = 3
    ) -> Result:
        """:meth:`solve` from SI floats: ``motion`` holds theta2, omega2, alpha2
        and jerk2 [rad, rad/s, rad/s^2, rad/s^3] (what the batch format has
        already read)."""
        circuit = self._circuit(circuit)
        return self._finish(self._kernel(motion, circuit, check_order(order)), motion)

    def _kernel(self, motion, circuit, order):
        """The unit-free kernel's Motion for SI ``motion``."""
        raise NotImplementedError

    def _motion_inputs(self, theta2, omega2, alpha2, jerk2):
        inputs = {
            p.name: to_si(v, p.name, p.kind)
            for p, v in zip(MOTION, (theta2, omega2, alpha2, jerk2))
        }
        arrays = {k: v.shape for k, v in inputs.items() if isinstance(v, np.ndarray)}
        if not arrays or len(arrays) == 1 and "theta2" in arrays:  # the common cases
            return inputs
        shapes = {k: np.shape(v) for k, v in inputs.items()}
        try:
            shape = np.broadcast_shapes(*shapes.values())
        except ValueError:
            raise InvalidInput(
                "theta2, omega2, alpha2 and jerk2 must be scalars or arrays of "
                "one shape (got shapes " + ", ".join(f"{k} {v}" for k, v in shapes.items()) + ")",
                "omega2",
            ) from None
        if shape != shapes["theta2"]:  # the sweep runs over theta2's shape
            inputs["theta2"] = np.broadcast_to(inputs["theta2"], shape)
        return inputs

    def _circuit(self, circuit):
        """The circuit asked for (None: the first, 'open'), or InvalidInput."""
        circuits = self.declaration().circuits
        if circuit is None:
            return circuits[0] if circuits else None
        if not isinstance(circuit, str) or circuit not in circuits:
            if not circuits:
                raise InvalidInput(
                    f"a {type(self).__name__} has one assembly: give no circuit "
                    f"(got {show(circuit)})",
                    "circuit",
                )
            raise InvalidInput(
                f"circuit must be one of {', '.join(map(repr, circuits))} (got {show(circuit)})",
                "circuit",
            )
        return circuit

    def _finish(self, motion, inputs, raise_errors=True, pts=None):
        scalar = np.ndim(motion.status) == 0
        result = Result(self, motion, scalar, inputs, pts)
        if scalar and raise_errors and motion.status != OK:
            self._raise(motion, inputs)
        # an overflow of the kernel's outputs is refused now, not when read
        key = (type(motion), motion.order)
        top = _TOPS.get(key)
        if top is None:
            top = _TOPS[key] = sorted(
                n
                for n in type(motion).SOLVED
                if order_of(n) == motion.order and getattr(motion, n) is not None
            )
        result._verify(top)
        return result

    def _raise(self, motion, inputs):
        where = f"theta2 = {_fmt_angle(inputs['theta2'])}"
        if motion.status == NOT_ASSEMBLABLE:
            raise NotAssemblable(
                f"{type(self).__name__} cannot be assembled at {where}: "
                f"{self._not_assemblable_reason(motion, inputs)}"
            )
        roundoff = float(motion.roundoff) if motion.roundoff is not None else math.inf
        cost = (
            "exactly there"
            if not np.isfinite(roundoff)
            else f"round-off would spoil about {roundoff:.1e} of each output, more than the "
            f"{MAX_ROUNDOFF:g} the solver vouches for"
        )
        raise Singular(
            f"{type(self).__name__} is at (or within round-off of) a limit position "
            f"at {where}: {self._singular_reason(motion, inputs)} (condition "
            f"{float(motion.condition):.2e}), so its velocity and acceleration "
            f"equations are singular or nearly so ({cost}). "
            f"{self._singular_advice(motion, inputs)}, or pass an array of "
            f"theta2 to get a validity mask instead of this error.",
            condition=float(motion.condition),
        )

    def _not_assemblable_reason(self, motion, inputs):
        return "the links cannot close the vector loop. Change theta2 or the link lengths."

    def _singular_reason(self, motion, inputs):
        return "the output links are collinear"

    def _singular_advice(self, motion, inputs):
        return "Move theta2 away from the limit (about 1e-6 rad is enough)"
