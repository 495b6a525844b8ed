"""The package's one pint registry and the conversions at the unit boundary.

Everything below this layer works in SI floats (m, rad, s). Quantities enter
through :func:`parse_quantity` and :func:`to_si` (one conversion per
argument, never per array element) and leave through :func:`quantity`.

The reading rules, the same wherever a quantity is read (the Python API, the
batch format, the command line, a student's graded answer):

* text is at most :data:`MAX_TEXT` characters, so that any field is read in
  bounded time (pint's parser grows with the square of the length); its
  parentheses nest at most :data:`MAX_NESTING` deep, a power's exponent is a
  plain number of one or two digits, and neither a power nor a group that holds
  one is raised to a power again (``9**9**9`` or ``((9**99)*2)**99`` would run
  for hours);
* a quantity needs the dimension of its parameter; an angle needs angle
  units (a bare ``"30"`` could be degrees or radians); a bare number is
  accepted only for a plain number (a ratio) and for zero;
* units that mean two things are refused with both readings: a frequency
  (Hz) for an angular velocity (10 Hz is 10 rad/s to pint, but 10 rev/s to
  most readers), and an angle or percent for a plain ratio;
* values are finite, and stay finite in SI.
"""

import math
import numbers
import re
from functools import lru_cache
from typing import Any, TypeAlias

import numpy as np
import pint
from pint.util import UnitsContainer

from .errors import InvalidInput
from .unitcache import new_registry

__all__ = [
    "ureg",
    "Q_",
    "parse_quantity",
    "read_units",
    "to_si",
    "quantity",
    "KINDS",
    "SI_UNITS",
    "MAX_TEXT",
    "show",
    "QuantityLike",
    "SIValue",
]

#: what the unit-aware API reads as a quantity: a Quantity, text with units
#: ("30 deg", "10 rad/s"), or a bare number where no unit is needed (a ratio, zero)
QuantityLike: TypeAlias = pint.Quantity | str | float | int | np.ndarray
#: a value in SI units, unit-free: a float, a complex number (a vector x + jy) or an array
SIValue: TypeAlias = float | complex | np.ndarray

#: The package's one pint registry: every Quantity that accelab reads or
#: returns belongs to it (a Quantity of another registry is converted once).
ureg: pint.UnitRegistry = new_registry()  # pint's parse of its definitions kept on disk
ureg.define("rev = revolution")  # '10 rev/s', the unambiguous way to say 10 Hz of a crank
pint.set_application_registry(ureg)
#: ``Q_(value, unit)``: a Quantity of :data:`ureg`, e.g. ``Q_(30, "deg")``.
Q_ = ureg.Quantity

#: the longest text read as a quantity or as units [characters]
MAX_TEXT = 100
#: the deepest nesting of parentheses read
MAX_NESTING = 4

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
# the same units as pint's public UnitsContainer, which its Quantity constructor takes
# directly (a little faster than a Unit, for the many outputs a result wraps)
_SI_CONTAINERS = {
    kind: UnitsContainer(dict(Q_(1.0, unit).unit_items())) for kind, unit in SI_UNITS.items()
}
_DIMS = {
    kind: ureg.get_dimensionality(dim) if dim else ureg.get_dimensionality("")
    for kind, (dim, _, _, _) in KINDS.items()
}
_ANGULAR = {"angular_velocity", "angular_acceleration", "angular_jerk"}
# a power in a unit expression: its exponent must be a plain number of at most
# two digits, and not itself raised to a power ('9**9**9' would take forever)
_POWER = re.compile(r"(\*\*|\^)")
_EXPONENT = re.compile(r"\s*\(?\s*[+-]?\s*\d{1,2}(\.\d*)?\s*\)?")


def show(value: Any) -> str:
    """The user's value as it reads in a message: text quoted, a long one cut
    (with its length), a Quantity or number as written."""
    if isinstance(value, str):
        if len(value) > 40:
            return f"a text of {len(value)} characters starting {value[:20]!r}"
        return repr(value)
    if isinstance(value, pint.Quantity):
        return f"{value:~}" if np.ndim(value.magnitude) == 0 else f"an array in {value.units:~}"
    if isinstance(value, np.ndarray):
        return f"an array of {value.size} numbers"
    text = repr(value)
    return text if len(text) <= 40 else f"a {type(value).__name__}"


@lru_cache(maxsize=1024)
def _factor(units, kind):
    """Multiplier from ``units`` to the SI unit of ``kind``, or None when the
    dimensions differ (cached per unit, so a conversion costs a multiply)."""
    if ureg.get_dimensionality(units) != _DIMS[kind]:
        return None
    return Q_(1.0, units).to(SI_UNITS[kind]).magnitude


@lru_cache(maxsize=1024)
def _unit_names(units):
    """The names of the units a Unit is made of (e.g. ('hertz',))."""
    return tuple(name for name, _ in Q_(1.0, units).unit_items())


@lru_cache(maxsize=1024)
def _is_angle_unit(units):
    """Whether ``units`` measure an angle (degree, radian, revolution ...):
    dimensionless to pint, but a multiple of the radian."""
    items = dict(Q_(1.0, units).to_root_units().unit_items())
    return items == {"radian": 1}


def _check_text(text, name, kind):
    """Refuse, before pint sees it, a text whose reading could take long: too long,
    nested too deep, or with a power of a power (the one rule for every text read)."""
    example = KINDS[kind][2] if kind in KINDS else "'m/s^2'"
    if len(text) > MAX_TEXT:
        raise InvalidInput(
            f"{name} is a text of {len(text)} characters; a quantity is at most "
            f"{MAX_TEXT} (e.g. {name}={example})",
            name,
        )
    for m in _POWER.finditer(text):
        after = _EXPONENT.match(text, m.end())
        if not after or text[after.end() :].lstrip().startswith(("**", "^")):
            raise InvalidInput(
                f"{name} = {show(text)} raises to a power that is not a plain "
                f"number of one or two digits; write units like 's^2' "
                f"(e.g. {name}={example})",
                name,
            )
    _check_groups(text, name, example)


def _check_groups(text, name, example):
    """Parentheses nest at most MAX_NESTING deep, and a group that holds a power
    is not raised to a power again."""
    open_groups = []  # per open group: whether it holds a power
    k = 0
    while k < len(text):
        ch = text[k]
        if ch == "(":
            open_groups.append(False)
            if len(open_groups) > MAX_NESTING:
                raise InvalidInput(
                    f"{name} = {show(text)} nests parentheses more than {MAX_NESTING} deep "
                    f"(e.g. {name}={example})",
                    name,
                )
        elif ch == ")" and open_groups:
            held = open_groups.pop()
            rest = text[k + 1 :].lstrip()
            if held and rest.startswith(("**", "^")):
                raise InvalidInput(
                    f"{name} = {show(text)} raises a group that holds a power to a power "
                    f"again; write units like 's^2' (e.g. {name}={example})",
                    name,
                )
            if held and open_groups:
                open_groups[-1] = True
        elif text.startswith(("**", "^"), k) and open_groups:
            open_groups[-1] = True
        k += 1


@lru_cache(maxsize=4096)
def _parse_text(text):
    """Parse a quantity string once; the same text is common (defaults, batch files)."""
    return Q_(text)


def _reason(exc):
    """Why pint could not read a text, in words (pint's own text where it has some)."""
    if isinstance(exc, pint.UndefinedUnitError):
        return str(exc).strip() or "an unknown unit"
    return "it is not a number followed by units"


@lru_cache(maxsize=4096)
def _parse_units(text):
    """Parse a unit text once, and check that it has a dimension and a root form
    (a logarithmic unit such as dB parses but has neither)."""
    units = ureg.parse_units(text) if text not in ("", "dimensionless") else ureg.Unit("")
    units.dimensionality  # noqa: B018 - raises for units pint parses but cannot use
    Q_(1.0, units).to_root_units()
    return units


def read_units(text: Any, name: str = "units") -> pint.Unit:
    """Read a unit text, such as ``"in/s^2"`` or pint's ``"inch / second ** 2"``,
    by the same rules as :func:`parse_quantity` (at most :data:`MAX_TEXT`
    characters, bounded nesting, no power of a power), in bounded time.

    This is the one reader of every unit text the package does not write itself:
    a quantity's text in ``accelab solve`` (through :func:`parse_quantity`) and a
    student's answer as the grader reads it. The same text is read once.

    Returns
    -------
    pint.Unit of :data:`ureg`

    Raises
    ------
    InvalidInput
        A text that is not a string, too long, nested too deep, with a power of a
        power, or units this registry cannot read or use (an unknown name, a
        logarithmic unit such as dB). The message shows the text once, cut.
    """
    if not isinstance(text, str):
        raise InvalidInput(f"{name} must be a unit text (got {type(text).__name__})", name)
    _check_text(text, name, None)
    try:
        return _parse_units(text.strip())
    except Exception as exc:  # noqa: BLE001 - pint raises many unrelated types
        raise InvalidInput(
            f"{name} = {show(text)} could not be read as units "
            f"({_unit_reason(exc)}); write units like 'm/s^2'",
            name,
        ) from None


def _unit_reason(exc):
    if isinstance(exc, pint.UndefinedUnitError) and "delta_" not in str(exc):
        return str(exc).strip() or "an unknown unit"
    if isinstance(exc, (pint.UndefinedUnitError, pint.OffsetUnitCalculusError)):
        return "a unit with no plain conversion, such as dB"
    return "not a product of units and powers"


def parse_quantity(value: QuantityLike, kind: str, name: str) -> pint.Quantity | float | np.ndarray:
    """Read ``value`` as a quantity of ``kind``: the one reading rule of the package.

    Parameters
    ----------
    value : str, pint.Quantity, or number
        Text such as ``"2 in"`` or ``"600 rpm"`` (at most :data:`MAX_TEXT`
        characters), a Quantity (of this or another pint registry; scalar or
        array), or a bare number (a plain ratio, or zero).
    kind : str
        One of :data:`KINDS`: ``'length'``, ``'angle'``, ``'angular_velocity'``,
        ``'dimensionless'`` ...
    name : str
        The parameter's name, for the messages.

    Returns
    -------
    pint.Quantity of :data:`ureg`, or the number itself for a bare number.

    Raises
    ------
    InvalidInput
        Unreadable or too long text; the wrong dimension (saying which one it
        has, degrees included); an angle without angle units; units with two
        readings (Hz for an angular quantity; an angle or percent for a
        plain number), with both readings and how to say which; a complex,
        masked or object value. The message shows the user's text once.
    """
    example = KINDS[kind][2]
    if isinstance(value, str):
        text = value.strip()
        _check_text(value, name, kind)
        if not text:
            raise InvalidInput(
                f"{name} is empty; give a number with units (e.g. {name}={example})", name
            )
        try:
            q = _parse_text(text)
        except Exception as exc:  # noqa: BLE001 - pint raises many unrelated types: InvalidInput says which
            raise InvalidInput(
                f"{name} = {show(value)} could not be read as a quantity "
                f"({_reason(exc)}). Example: {name}={example}",
                name,
            ) from None
    elif isinstance(value, pint.Quantity):
        q = value
        if not isinstance(value, Q_):  # another registry: read its units by name
            try:
                q = Q_(value.magnitude, str(value.units))
            except Exception as exc:  # noqa: BLE001 - any failure means: units this registry cannot read
                raise InvalidInput(
                    f"{name} = {show(value)} comes from another pint "
                    f"registry whose units this one cannot read "
                    f"({_reason(exc)}); build it with accelab.solver.Q_",
                    name,
                ) from None
    elif isinstance(value, (bool, np.bool_)):
        raise InvalidInput(
            f"{name} must be {KINDS[kind][3]}, not a truth value ({value!r}). "
            f"Example: {name}={example}",
            name,
        )
    else:
        _check_number(value, name, kind)
        return value
    _check_magnitude(q.magnitude, name, kind, value)
    _check_units(q, name, kind, value)
    return q


def _check_number(value, name, kind):
    if isinstance(value, np.ma.MaskedArray):
        raise InvalidInput(
            f"{name} is a masked array; pass the positions you want as a plain "
            f"array (masked values cannot be solved or left out silently)",
            name,
        )
    if isinstance(value, (list, tuple)) and not all(
        isinstance(x, numbers.Real) and not isinstance(x, bool) for x in value
    ):
        raise InvalidInput(
            f"{name} must be one quantity like {KINDS[kind][2]} (got a "
            f"{type(value).__name__}: {show(value)})",
            name,
        )
    if isinstance(value, (numbers.Complex, np.ndarray, list, tuple)):
        _check_magnitude(value, name, kind, value)
        return
    raise InvalidInput(
        f"{name} must be {KINDS[kind][3]} (got {type(value).__name__} "
        f"{show(value)}). Example: {name}={KINDS[kind][2]}",
        name,
    )


def _check_magnitude(mag, name, kind, value):
    if isinstance(mag, np.ma.MaskedArray):
        raise InvalidInput(
            f"{name} is a masked array; pass the positions you want as a plain "
            f"array (masked values cannot be solved or left out silently)",
            name,
        )
    if isinstance(mag, (complex, np.complexfloating)) or (
        isinstance(mag, np.ndarray) and np.iscomplexobj(mag)
    ):
        raise InvalidInput(
            f"{name} = {show(value)} is complex; give a real value (e.g. {name}={KINDS[kind][2]})",
            name,
        )
    if isinstance(mag, np.ndarray) and mag.dtype.kind not in "biuf":
        raise InvalidInput(f"{name} must hold numbers (got an array of {mag.dtype})", name)


def _check_units(q, name, kind, value):
    dim, si, example, words = KINDS[kind]
    units = q.units
    factor = _factor(units, kind)
    if factor is None:
        if q.dimensionless and _is_angle_unit(units):
            given = f"angle units ({units:~})"
        elif q.dimensionless:
            given = "no units" if not _unit_names(units) else f"no dimension ({units:~})"
        else:
            given = f"the dimension {q.dimensionality} of {units:~}"
        raise InvalidInput(
            f"{name} must be {words} (got {show(value)}, which has {given}). "
            f"Example: {name}={example}",
            name,
        )
    names = _unit_names(units)
    if kind == "angle" and not _is_angle_unit(units):
        if not names and isinstance(value, str):
            raise InvalidInput(
                f"{name} needs angle units (a bare {show(value)} could be degrees or radians). "
                f"Example: {name}={example}",
                name,
            )
        if names:
            raise InvalidInput(
                f"{name} must be an angle (got {show(value)}, whose units "
                f"{units:~} are not angle units). Example: {name}={example}",
                name,
            )
    if kind in _ANGULAR and any(n.endswith("hertz") for n in names):
        mag = q.magnitude
        one = float(np.ravel(mag)[0]) if np.size(mag) else 0.0
        as_rad = one * factor
        per = {"angular_velocity": "s", "angular_acceleration": "s^2", "angular_jerk": "s^3"}[kind]
        raise InvalidInput(
            f"{name} = {show(value)} has two readings: {as_rad:.6g} rad/{per} (a hertz taken "
            f"as one radian per second) or {as_rad * 2 * math.pi:.6g} rad/{per} (a hertz taken "
            f"as one revolution per second). Say which: write rad/{per}, or rev/{per}"
            + (" (or rpm)" if kind == "angular_velocity" else ""),
            name,
        )
    if kind == "dimensionless" and names:
        mag = q.magnitude
        one = float(np.ravel(mag)[0]) if np.size(mag) else 0.0
        what = "an angle unit" if _is_angle_unit(units) else f"the unit {units:~}"
        raise InvalidInput(
            f"{name} is a plain number, but {show(value)} has {what}, so it has two readings: "
            f"{one:.6g} (the number written) or {one * factor:.6g} (converted by its unit). "
            f"Write the number alone, e.g. {name}=-2",
            name,
        )
    if not names and kind not in ("dimensionless", "angle") and isinstance(value, str):
        raise InvalidInput(f"{name} needs units. Example: {name}={example}", name)


def to_si(
    value: QuantityLike, name: str, kind: str, *, positive: bool = False, nonzero: bool = False
) -> float | np.ndarray:
    """Convert ``value`` to SI floats (a float or a float ndarray).

    Parameters
    ----------
    value : pint.Quantity, str, or number
        As :func:`parse_quantity` reads it. Bare numbers are accepted only
        for ``kind='dimensionless'``, and a bare 0 for any kind (zero needs
        no unit).
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


#: (unit items, kind) -> factor to SI, for the units of Quantities already read once
#: by :func:`parse_quantity` (a Quantity's checks depend only on its units and kind)
_ACCEPTED: dict[tuple[Any, str], float] = {}


def _to_si(value, name, kind, positive, nonzero):
    dim, si, example, words = KINDS[kind]
    if type(value) is Q_:  # the common case: a Quantity of this registry
        mag = value.magnitude
        factor = _ACCEPTED.get((tuple(value.unit_items()), kind))
        if factor is not None and type(mag) is float:
            out = mag * factor if factor != 1.0 else mag
            if math.isfinite(out) and (out > 0 or not positive and not (nonzero and out == 0)):
                return out
        elif (
            factor is not None
            and type(mag) is np.ndarray
            and mag.dtype == np.float64
            and mag.ndim
            and not positive
            and not nonzero
        ):
            with np.errstate(over="ignore"):
                scaled = mag * factor if factor != 1.0 else mag
            if np.isfinite(scaled).all():
                return scaled
    if type(value) is int and value == 0 or type(value) is float and value == 0.0:
        if positive or nonzero:
            raise InvalidInput(f"{name} must be positive (got 0). Example: {name}={example}", name)
        return 0.0  # zero needs no unit
    q = parse_quantity(value, kind, name)
    if isinstance(q, pint.Quantity):
        mag = q.magnitude
        factor = _factor(q.units, kind)
        _ACCEPTED[(tuple(q.unit_items()), kind)] = factor
        out = mag * factor if factor != 1.0 else mag
        if isinstance(mag, (list, tuple)):
            out = np.asarray(mag, dtype=float) * factor
    elif kind == "dimensionless":
        out = value
    else:
        raise InvalidInput(
            f"{name} needs units (got the bare number {show(value)}). Example: {name}={example}, "
            f"or Q_({show(value)}, '{si or 'dimensionless'}')",
            name,
        )
    if type(out) is int:
        try:
            out = float(out)
        except OverflowError:
            raise InvalidInput(
                f"{name} = {show(value)} is too large for a float "
                f"(about 1.8e308 at most). Example: {name}={example}",
                name,
            ) from None
    if type(out) is float:  # fast path for scalars
        if not math.isfinite(out):
            raise InvalidInput(_not_finite(name, value, example, out), name)
        if positive and not out > 0:
            raise InvalidInput(
                f"{name} must be positive (got {show(value)}): a link length "
                f"is > 0. Example: {name}={example}",
                name,
            )
        if nonzero and out == 0:
            raise InvalidInput(f"{name} must not be zero (got {show(value)})", name)
        return float(out)
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            arr = np.asarray(out, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise InvalidInput(f"{name} must be numeric (got {show(value)})", name) from None
    if not np.all(np.isfinite(arr)):
        raise InvalidInput(_not_finite(name, value, example, arr), name)
    if positive and not np.all(arr > 0):
        raise InvalidInput(
            f"{name} must be positive (got {show(value)}): a link length is > 0. "
            f"Example: {name}={example}",
            name,
        )
    if nonzero and not np.all(arr != 0):
        raise InvalidInput(f"{name} must not be zero (got {show(value)})", name)
    return float(arr) if arr.ndim == 0 else arr


def _not_finite(name, value, example, si):
    given = value.magnitude if isinstance(value, pint.Quantity) else value
    if isinstance(value, str):
        try:
            given = _parse_text(value.strip()).magnitude
        except Exception:  # noqa: BLE001 - it was read before; only the wording depends on it
            given = np.nan
    with np.errstate(invalid="ignore"):
        overflowed = bool(np.all(np.isfinite(np.asarray(given, dtype=float))))
    if overflowed:
        return (
            f"{name} = {show(value)} is too large: it overflows a float in SI units. "
            f"Example: {name}={example}"
        )
    return f"{name} must be finite (got {show(value)}). Example: {name}={example}"


def quantity(si_value: SIValue, kind: str) -> pint.Quantity:
    """Wrap an SI float or array (real or complex) as one Quantity of :data:`ureg`."""
    return Q_(si_value, _SI_CONTAINERS[kind])
