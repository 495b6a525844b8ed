"""What every unit-aware mechanism shares: argument conversion, the lazy
result object, and the errors raised for scalar inputs."""

import functools
import math

import numpy as np

from ..errors import InvalidInput, NotAssemblable, Singular
from ..kernels import OK, NOT_ASSEMBLABLE, SINGULAR, STATUS_NAMES, MAX_ROUNDOFF
from ..kernels import points
from ..units import Q_, quantity, to_si

#: name prefixes -> kind of quantity, longest prefix first
_KINDS = [("theta", "angle"), ("gamma", "angle"), ("delta", "angle"), ("phi", "angle"),
          ("omega", "angular_velocity"), ("alpha", "angular_acceleration"),
          ("jerk", "angular_jerk"), ("R_", "length"), ("V_", "velocity"),
          ("A_", "acceleration"), ("J_", "jerk")]
_SLIDER_KINDS = {"": "length", "_dot": "velocity", "_ddot": "acceleration",
                 "_dddot": "jerk"}
_DERIV = {0: "theta", 1: "omega", 2: "alpha", 3: "jerk"}
_VECTOR_ORDER = {"R": 0, "V": 1, "A": 2, "J": 3}


_EXACT = {"R": "length", "V": "velocity", "A": "acceleration", "J": "jerk", "p": "length",
          "lam": "dimensionless", "condition": "dimensionless"}


@functools.lru_cache(maxsize=1024)
def kind_of(name):
    """The kind of quantity a result attribute holds, from its name."""
    if name in _EXACT:
        return _EXACT[name]
    for prefix, kind in _KINDS:
        if name.startswith(prefix):
            return kind
    base, _, _ = name.partition("_")
    if len(base) == 1:  # d, d_dot, b_ddot, p ...
        return _SLIDER_KINDS[name[len(base):]]
    raise AttributeError(name)


def _fmt_angle(rad):
    return f"{math.degrees(float(rad)):.6g} deg"


class Result:
    """Kinematics of a mechanism at one or many input positions.

    Attributes are computed when first read and returned as Quantities:
    angles ``theta3`` [rad], ``omega3``, ``alpha3``, ``jerk3``; slider
    quantities (``d``, ``d_dot``, ``b_ddot`` ...); point vectors as complex
    Quantities: ``R_X``, ``V_X``, ``A_X``, ``J_X`` for each point X of the
    mechanism, ``A_XY = A_X - A_Y`` (eq. 7.4) for any two points, and the
    tangential and normal components ``A_X_t``, ``A_X_n`` of a point about
    its own base (``A_BA_t`` for B about A on link 3 ...).

    ``valid`` is True where the mechanism assembles and is not singular,
    ``status`` names each position's state, ``condition`` is the kernel's
    dimensionless condition measure (1 best, 0 at a toggle).
    """

    def __init__(self, mechanism, motion, scalar, inputs, pts=None):
        self._mech = mechanism
        self._pts = mechanism._points if pts is None else pts
        self._motion = motion
        self._scalar = scalar
        self._inputs = inputs
        self._cache = {}

    # --- unit-free access -------------------------------------------------
    def si(self, name):
        """The SI value (float, complex, or array) of an output, unit-free."""
        cache = self._cache
        if name in cache:
            return cache[name]
        value = self._compute(name)
        if self._scalar and isinstance(value, np.ndarray):
            value = value[()]
        cache[name] = value
        return value

    def _compute(self, name):
        motion = self._motion.__dict__
        if name in motion:
            return motion[name]
        if name in self._inputs:
            return self._inputs[name]
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
                if rest.startswith(x) and rest[len(x):] in pts:
                    y = rest[len(x):]
                    if comp is not None:
                        if order != 2:
                            break
                        return self._component(x, y, comp)
                    return self._point(x, order) - self._point(y, order)
            if comp is not None and rest in pts and order == 2:
                return self._component(rest, pts[rest][0], comp)
        raise AttributeError(f"{type(self._mech).__name__} results have no output {name!r}; "
                             f"available: {', '.join(self.outputs())}")

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
            m = self._motion.__dict__
            known = m.get("_unit", {}).get(theta_key[len("theta"):])
            if known is not None and offset == 0.0:
                e = points.from_components(*known)
                theta1 = getattr(self._mech, "_theta1", 0.0)
                if theta1:
                    e = e * complex(math.cos(theta1), math.sin(theta1))
            else:
                e = points.unit(m[theta_key], offset)
            pair = self._cache[key] = (e, 1j * e)
        return pair

    def _relative(self, length, theta_key, offset, order):
        n = theta_key[len("theta"):]
        m = self._motion.__dict__
        theta = m[theta_key]
        e, je = self._unit(theta_key, offset)
        if order == 0:
            return points.relative_position(length, theta, offset, e)
        if order == 1:
            return points.relative_velocity(length, theta, m["omega" + n], offset, e, je)
        if order == 2:
            return points.relative_acceleration(length, theta, m["omega" + n], m["alpha" + n],
                                                offset, e, je)
        return points.relative_jerk(length, theta, m["omega" + n], m["alpha" + n], m["jerk" + n],
                                    offset, e, je)

    def _component(self, x, y, comp):
        rel = self._mech._relative.get(x + y)
        if rel is not None:
            length, theta_key, offset = rel
            length = getattr(self._mech, "_" + length)
        else:
            base, length, theta_key, offset = self._pts[x]
            if base != y or callable(length):
                raise AttributeError(f"no tangential/normal split of A_{x}{y}: {x} and {y} "
                                     f"are not two points of one rigid link")
        n = theta_key[len("theta"):]
        m = self._motion.__dict__
        t, nn = points.relative_acceleration_parts(length, m[theta_key], m["omega" + n],
                                                  m["alpha" + n], offset,
                                                  *self._unit(theta_key, offset))
        return t if comp == "t" else nn

    def point(self, link, p, delta=0, base=None):
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
            R, V, A, J (complex Quantities) and A_t, A_n, the tangential and
            normal parts of the acceleration difference from ``base``. Use it
            for a link's centre of gravity before F = m A.
        """
        bases = self._mech._link_bases
        if link not in bases:
            raise InvalidInput(f"{type(self._mech).__name__} has no rotating link {link}; "
                               f"use one of {sorted(bases)}", "link")
        base = base or bases[link]
        p_si = to_si(p, "p", "length")
        delta_si = to_si(delta, "delta", "angle")
        key = f"theta{link}"
        parts = {}
        for order, letter in enumerate("RVAJ"):
            rel = self._relative(p_si, key, delta_si, order)
            if base in self._pts:
                rel = rel + self._point(base, order)
            elif order == 0:
                rel = rel + self._mech._pivot(base)
            parts[letter] = rel
        n = str(link)
        m = self._motion.__dict__
        parts["A_t"], parts["A_n"] = points.relative_acceleration_parts(
            p_si, m[key], m["omega" + n], m["alpha" + n], delta_si)
        if self._scalar:
            parts = {k: v[()] if isinstance(v, np.ndarray) else v for k, v in parts.items()}
        return PointMotion(parts)

    # --- unit-aware access ------------------------------------------------
    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        value = self.si(name)
        return quantity(value, kind_of(name))

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self.outputs()))

    def outputs(self):
        """Names of the outputs this result reports (as the batch contract lists them)."""
        return list(self._mech.outputs(self))

    @property
    def valid(self):
        """True where the result can be vouched for (bool or bool array)."""
        v = self._motion.status == OK
        return bool(v) if self._scalar else v

    @property
    def status(self):
        """'ok', 'not_assemblable' or 'singular' (a str, or an array of str)."""
        s = np.vectorize(STATUS_NAMES.get, otypes=[object])(self._motion.status)
        return str(s[()]) if self._scalar else s

    @property
    def condition(self):
        """Dimensionless condition measure (1 best, 0 at a toggle): the sine
        of the transmission angle, or its analogue for each mechanism."""
        c = self._motion.condition
        return float(c) if self._scalar else c

    @property
    def roundoff(self):
        """Estimated relative round-off of the derivative outputs (float or
        array); above :data:`~solver.kernels.MAX_ROUNDOFF` a position is
        ``singular``. Zero for mechanisms without limit positions."""
        r = getattr(self._motion, "roundoff", 0.0)
        return float(r) if self._scalar else np.broadcast_to(r, np.shape(self._motion.status))

    @property
    def circuit(self):
        return self._motion.circuit

    def to_dict(self, names=None):
        """SI values as plain Python (vectors as [x, y]; arrays as lists)."""
        out = {}
        for name in names or self.outputs():
            v = self.si(name)
            if np.iscomplexobj(v):
                v = np.stack([np.real(v), np.imag(v)], axis=-1).tolist()
            elif isinstance(v, np.ndarray):
                v = v.tolist()
            else:
                v = float(v)
            out[name] = v
        return out

    def __repr__(self):
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

    _KINDS = {"R": "length", "V": "velocity", "A": "acceleration", "A_t": "acceleration",
              "A_n": "acceleration", "J": "jerk"}

    def __init__(self, parts):
        self._si = parts

    def si(self, name):
        return self._si[name]

    def __getattr__(self, name):
        if name.startswith("_") or name not in self._KINDS:
            raise AttributeError(name)
        return quantity(self._si[name], self._KINDS[name])

    def __repr__(self):
        return "<PointMotion " + ", ".join(f"{k}={getattr(self, k):.5g~P}" for k in self._KINDS) + ">"


class Mechanism:
    """Base of the unit-aware mechanisms.

    Subclasses declare ``_geometry`` (name -> (kind, positive, default)),
    ``_points`` (point -> (base point or pivot key, length attribute, theta
    key, offset)), ``_outputs`` and implement ``_kernel``.
    """

    _geometry = {}
    _points = {}
    _relative = {}  # "XY" -> (length attribute, theta key, offset) for X, Y on one link
    _link_bases = {}  # link number -> the pin a point on it is measured from
    _outputs = ()
    _circuits = ("open", "crossed")
    _link_words = ""

    def __init__(self, **geometry):
        unknown = set(geometry) - set(self._geometry)
        if unknown:
            raise InvalidInput(f"{type(self).__name__} has no parameter "
                               f"{', '.join(sorted(unknown))}; it takes "
                               f"{', '.join(self._geometry)}", sorted(unknown)[0])
        self._given = {}
        for name, (kind, positive, default) in self._geometry.items():
            value = geometry.get(name, default)
            if value is None:
                raise InvalidInput(f"{type(self).__name__} needs {name} "
                                   f"(e.g. {name}='2 in')", name)
            self._given[name] = value
            setattr(self, "_" + name, to_si(value, name, kind, positive=positive))
        self._points = {k: self._resolve_point(v) for k, v in type(self)._points.items()}
        self._validate()

    def _resolve_point(self, spec):
        base, length, theta_key, offset = spec
        if isinstance(length, str):
            length = getattr(self, "_" + length)
        return base, length, theta_key, offset

    def _validate(self):
        """Hook for geometry checks beyond positivity."""

    def __getattr__(self, name):
        if name.startswith("_") or name not in type(self)._geometry:
            raise AttributeError(name)
        return quantity(getattr(self, "_" + name), self._geometry[name][0])

    def __repr__(self):
        args = ", ".join(f"{k}={v!r}" for k, v in self._given.items())
        return f"{type(self).__name__}({args})"

    def _show(self, si_length):
        """A length [m] written in the unit the user gave the geometry in."""
        for name, (kind, _, _) in self._geometry.items():
            if kind == "length" and name in self._given:
                given = self._given[name]
                try:
                    unit = (Q_(given) if isinstance(given, str) else given).units
                    return f"{Q_(si_length, 'm').to(unit).magnitude:.6g} {unit:~}"
                except Exception:
                    break
        return f"{si_length:.6g} m"

    def _given_text(self, name):
        given = self._given[name]
        return given if isinstance(given, str) else f"{given:~}"

    def _pivot(self, key):
        """Position of a fixed pivot (complex, SI)."""
        return 0.0 + 0.0j

    def _extra(self, result, name):
        """Mechanism-specific outputs (Coriolis term, slider point ...)."""
        return None

    def outputs(self, result):
        return self._outputs

    # --- solving ----------------------------------------------------------
    def _motion_inputs(self, theta2, omega2, alpha2, jerk2):
        inputs = {
            "theta2": to_si(theta2, "theta2", "angle"),
            "omega2": to_si(omega2, "omega2", "angular_velocity"),
            "alpha2": to_si(alpha2, "alpha2", "angular_acceleration"),
            "jerk2": to_si(jerk2, "jerk2", "angular_jerk"),
        }
        arrays = {k: v.shape for k, v in inputs.items() if type(v) is not float}
        if not arrays or len(arrays) == 1 and "theta2" in arrays:  # the common cases
            return inputs
        shapes = {k: np.shape(v) for k, v in inputs.items()}
        try:
            shape = np.broadcast_shapes(*shapes.values())
        except ValueError:
            raise InvalidInput("theta2, omega2, alpha2 and jerk2 must be scalars or arrays of "
                               "one shape (got shapes " + ", ".join(
                                   f"{k} {v}" for k, v in shapes.items()) + ")",
                               "omega2") from None
        if shape != shapes["theta2"]:  # the sweep runs over theta2's shape
            inputs["theta2"] = np.broadcast_to(inputs["theta2"], shape)
        return inputs

    def _check_circuit(self, circuit):
        if circuit not in self._circuits:
            raise InvalidInput(f"circuit must be one of {', '.join(map(repr, self._circuits))} "
                               f"(got {circuit!r})", "circuit")

    def _finish(self, motion, inputs, raise_errors=True, pts=None):
        scalar = np.ndim(motion.status) == 0
        result = Result(self, motion, scalar, inputs, pts)
        if scalar and raise_errors and motion.status != OK:
            self._raise(motion, inputs)
        return result

    def _raise(self, motion, inputs):
        where = f"theta2 = {_fmt_angle(inputs['theta2'])}"
        if motion.status == NOT_ASSEMBLABLE:
            raise NotAssemblable(f"{type(self).__name__} cannot be assembled at {where}: "
                                 f"{self._not_assemblable_reason(motion, inputs)}")
        roundoff = float(getattr(motion, "roundoff", np.inf))
        cost = ("exactly there" if not np.isfinite(roundoff) else
                f"round-off would spoil about {roundoff:.1e} of each output, more than the "
                f"{MAX_ROUNDOFF:g} the solver vouches for")
        raise Singular(f"{type(self).__name__} is at (or within round-off of) a limit position "
                       f"at {where}: {self._singular_reason()} (condition "
                       f"{float(motion.condition):.2e}), so its velocity and acceleration "
                       f"equations are singular or nearly so ({cost}). Move theta2 "
                       f"away from the limit (about 1e-6 rad is enough), or pass an array of "
                       f"theta2 to get a validity mask instead of this error.",
                       condition=float(motion.condition))

    def _not_assemblable_reason(self, motion, inputs):
        return "the links cannot close the vector loop. Change theta2 or the link lengths."

    def _singular_reason(self):
        return "the output links are collinear"
