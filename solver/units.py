"""The package's one pint registry and the conversions at the unit boundary.

Everything below this layer works in SI floats (m, rad, s). Quantities enter
through :func:`to_si` (one conversion per argument, never per array element)
and leave through :func:`quantity`.
"""

from functools import lru_cache
import math
import numbers

import numpy as np
import pint

from .errors import InvalidInput

__all__ = ["ureg", "Q_", "to_si", "quantity", "KINDS"]

ureg = pint.UnitRegistry()
pint.set_application_registry(ureg)
Q_ = ureg.Quantity

# kind -> (pint dimensionality, SI unit, example for error messages, words)
KINDS = {
    "length": ("[length]", "m", "'2 in'", "a length"),
    "angle": ("", "rad", "'30 deg'", "an angle"),
    "angular_velocity": ("1/[time]", "rad/s", "'10 rad/s' or '600 rpm'", "an angular velocity"),
    "angular_acceleration": ("1/[time]**2", "rad/s**2", "'-5 rad/s^2'", "an angular acceleration"),
    "angular_jerk": ("1/[time]**3", "rad/s**3", "'0 rad/s^3'", "an angular jerk"),
    "velocity": ("[length]/[time]", "m/s", "'3 m/s'", "a velocity"),
    "acceleration": ("[length]/[time]**2", "m/s**2", "'9.81 m/s^2'", "an acceleration"),
    "jerk": ("[length]/[time]**3", "m/s**3", "'100 m/s^3'", "a linear jerk"),
    "time": ("[time]", "s", "'0.1 s'", "a time"),
    "dimensionless": ("", "", "'2' (a plain number)", "a plain number"),
}

SI_UNITS = {kind: ureg.Unit(si) for kind, (_, si, _, _) in KINDS.items()}
_DIMS = {kind: ureg.get_dimensionality(dim) if dim else ureg.get_dimensionality("")
         for kind, (dim, _, _, _) in KINDS.items()}


@lru_cache(maxsize=1024)
def _factor(units, kind):
    """Multiplier from ``units`` to the SI unit of ``kind``, or None when the
    dimensions differ (cached per unit, so a conversion costs a multiply)."""
    if ureg.get_dimensionality(units) != _DIMS[kind]:
        return None
    return Q_(1.0, units).to(SI_UNITS[kind]).magnitude


@lru_cache(maxsize=4096)
def _parse_text(text):
    """Parse a quantity string once; the same text is common (defaults, batch files)."""
    return Q_(text)


def _parse(value, name, kind):
    if isinstance(value, str):
        try:
            return _parse_text(value)
        except Exception as exc:  # pint raises several unrelated types
            raise InvalidInput(
                f"{name} could not be read as a quantity ({value!r}: {exc}). "
                f"Example: {name}={KINDS[kind][2]}", name) from None
    return value


def to_si(value, name, kind, *, positive=False, nonzero=False):
    """Convert ``value`` to SI floats (a float or a float ndarray).

    Parameters
    ----------
    value : pint.Quantity, str, or number
        A Quantity (scalar or wrapping an array) or a string pint parses.
        Bare numbers are accepted only for ``kind='dimensionless'``, and a
        bare 0 for any kind (zero needs no unit).
    name : str
        The parameter's name, used in error messages.
    kind : str
        One of :data:`KINDS` (``'length'``, ``'angle'``, ...).
    positive : bool
        Require every value > 0 (lengths of links).

    Raises
    ------
    InvalidInput
        With a message naming ``name``, what it needs and an example.
    """
    if type(value) is str:  # the same text recurs (defaults, batch files, loops)
        return _text_to_si(value, name, kind, positive, nonzero)
    return _to_si(value, name, kind, positive, nonzero)


@lru_cache(maxsize=4096)
def _text_to_si(value, name, kind, positive, nonzero):
    """:func:`to_si` of a string, remembered (a float; errors are not cached)."""
    return _to_si(value, name, kind, positive, nonzero)


def _to_si(value, name, kind, positive, nonzero):
    dim, si, example, words = KINDS[kind]
    if type(value) is int and value == 0 or type(value) is float and value == 0.0:
        if positive or nonzero:
            raise InvalidInput(f"{name} must be positive (got 0). Example: {name}={example}", name)
        return 0.0  # zero needs no unit
    q = _parse(value, name, kind)
    if isinstance(q, Q_):
        units = q._units
        factor = _factor(units, kind)
        if factor is None:
            given = ("no units" if q.dimensionless
                     else f"the dimension {q.dimensionality} of {q.units:~}")
            raise InvalidInput(
                f"{name} must be {words} (got {value!s}, which has {given}). "
                f"Example: {name}={example}", name)
        if not units and kind not in ("dimensionless", "angle"):
            raise InvalidInput(f"{name} needs units. Example: {name}={example}", name)
        if not units and kind == "angle" and isinstance(value, str):
            raise InvalidInput(
                f"{name} needs angle units (a bare {value!r} could be degrees or radians). "
                f"Example: {name}={example}", name)
        mag = q._magnitude
        out = mag * factor if factor != 1.0 else mag
    elif isinstance(value, (numbers.Real, np.ndarray, list, tuple)) and kind == "dimensionless":
        out = value
    elif isinstance(value, (numbers.Number, np.ndarray, list, tuple)):
        raise InvalidInput(
            f"{name} needs units (got the bare number {value!r}). Example: {name}={example}, "
            f"or Q_({value!r}, '{si or 'dimensionless'}')", name)
    else:
        raise InvalidInput(f"{name} must be {words} (got {type(value).__name__} {value!r}). "
                           f"Example: {name}={example}", name)
    if type(out) is float or type(out) is int:  # fast path for scalars
        if not math.isfinite(out):
            raise InvalidInput(f"{name} must be finite (got {value!s}). Example: {name}={example}",
                               name)
        if positive and not out > 0:
            raise InvalidInput(f"{name} must be positive (got {value!s}): a link length is > 0. "
                               f"Example: {name}={example}", name)
        if nonzero and out == 0:
            raise InvalidInput(f"{name} must not be zero (got {value!s})", name)
        return float(out)
    try:
        arr = np.asarray(out, dtype=float)
    except (TypeError, ValueError):
        raise InvalidInput(f"{name} must be numeric (got {value!r})", name) from None
    if not np.all(np.isfinite(arr)):
        raise InvalidInput(f"{name} must be finite (got {value!s}). Example: {name}={example}", name)
    if positive and not np.all(arr > 0):
        raise InvalidInput(f"{name} must be positive (got {value!s}): a link length is > 0. "
                           f"Example: {name}={example}", name)
    if nonzero and not np.all(arr != 0):
        raise InvalidInput(f"{name} must not be zero (got {value!s})", name)
    return float(arr) if arr.ndim == 0 else arr


_SI_CONTAINERS = {kind: unit._units for kind, unit in SI_UNITS.items()}
_PLAIN = (float, complex, np.ndarray, np.floating, np.complexfloating)


def quantity(si_value, kind):
    """Wrap an SI float or array (real or complex) as one Quantity.

    For the magnitudes the solver produces (floats, complex, ndarrays) the
    Quantity is assembled directly, as pint's own constructor would leave it
    (the registry's Quantity class, the magnitude untouched, the SI unit's
    container): a microsecond instead of twenty, which a sweep reading a
    dozen outputs notices. Anything else goes through ``Q_``.
    """
    if isinstance(si_value, _PLAIN):
        q = object.__new__(Q_)
        q._magnitude = si_value
        q._units = _SI_CONTAINERS[kind]
        return q
    return Q_(si_value, SI_UNITS[kind])
