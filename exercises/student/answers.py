"""Reading a student's answer: what a variable holds, then whether its form and
dimension fit what the statement asks.

This is the one place where an answer is read. It runs on both sides of the
grading line, on plain data:

* in the student's kernel, :func:`describe` turns the Python object a variable
  holds into a small JSON-able report (``state``, ``magnitude``, ``units`` or
  ``text``); the notebook's visible check and the sandboxed report both use it;
* :func:`read` turns such a report into the value in SI units (or the chosen
  word), or a message that says what to fix. The grader calls it on the report
  that came out of the sandbox; it never sees the student's objects.

Neither side holds an expected value: :class:`Asked` is what the statement asks
for (name, unit, kind), nothing more. Judging the value is the grader's job
(:mod:`accelab.exercises.grader.judge`).
"""

import math
import numbers
from dataclasses import asdict, dataclass, field

from accelab.solver.units import read_units

#: longest unit text a report carries and answer text read from a report [characters]
#: (a unit text is then read by :func:`accelab.solver.units.read_units`, which takes
#: at most :data:`accelab.solver.units.MAX_TEXT` characters)
MAX_UNITS = 200
MAX_TEXT = 200


@dataclass(frozen=True)
class Asked:
    """One graded quantity as the statement asks for it (no value).

    ``kind`` is ``"number"``, ``"angle"`` (a direction, judged modulo 360 deg) or
    ``"choice"`` (one of ``choices``). ``unit`` is the unit a bare number is read
    in; ``quantity_required`` refuses a bare number.
    """

    name: str
    unit: str
    description: str
    kind: str = "number"
    choices: tuple = field(default_factory=tuple)
    quantity_required: bool = False

    def to_dict(self):
        out = asdict(self)
        out["choices"] = list(self.choices)
        return out

    @classmethod
    def from_dict(cls, data):
        return cls(
            name=str(data["name"]),
            unit=str(data.get("unit") or ""),
            description=str(data.get("description", "")),
            kind=str(data.get("kind", "number")),
            choices=tuple(data.get("choices") or ()),
            quantity_required=bool(data.get("quantity_required", False)),
        )


@dataclass(frozen=True)
class Reading:
    """An answer read from a report: ``si`` (float, SI units) or ``word``, or
    ``problem`` (a message for the student) when it cannot be judged.
    ``bare`` says the student gave a plain number (read in the asked unit)."""

    name: str
    si: float = None
    word: str = None
    bare: bool = False
    raw: float = None  # the number as typed (bare numbers), for unit hints
    problem: str = None

    @property
    def ok(self):
        return self.problem is None


MISSING = object()


def describe(value):
    """What a variable holds, as plain data (never the object itself).

    Runs in the student's kernel. Every attribute access is guarded: a value
    whose ``magnitude`` or ``__float__`` raises is reported as unreadable.
    """
    if value is MISSING:
        return {"state": "missing"}
    if isinstance(value, str):
        return {"state": "text", "text": value[:MAX_TEXT]}
    if value is None or isinstance(value, bool):
        return {"state": "other", "type": type(value).__name__}
    try:
        if hasattr(value, "magnitude") and hasattr(value, "units"):
            units = str(value.units)[:MAX_UNITS]
            return dict(_number(value.magnitude), state="quantity", units=units)
        if isinstance(value, numbers.Real) or _is_numpy_real(value):
            return dict(_number(value), state="number")
        if isinstance(value, (list, tuple, dict, set)) or hasattr(value, "shape"):
            return {"state": "array", "type": type(value).__name__[:60]}
        if isinstance(value, numbers.Complex):
            return {"state": "complex"}
    except Exception as exc:  # noqa: BLE001 - a student's object whose attributes raise anything
        return {"state": "unreadable", "type": type(exc).__name__[:60]}
    return {"state": "other", "type": type(value).__name__[:60]}


def _is_numpy_real(value):
    kind = getattr(getattr(value, "dtype", None), "kind", None)
    return kind in ("i", "u", "f") and getattr(value, "shape", None) == ()


def _number(magnitude):
    """{"magnitude": float} or {"shape"/"complex"/"nonfinite": ...}."""
    shape = getattr(magnitude, "shape", ())
    if shape not in ((), None):
        return {"shape": [int(n) for n in shape][:4]}
    if isinstance(magnitude, (list, tuple)):
        return {"shape": [len(magnitude)]}
    if (
        isinstance(magnitude, complex)
        or getattr(getattr(magnitude, "dtype", None), "kind", None) == "c"
    ):
        return {"complex": True}
    try:
        x = float(magnitude)
    except OverflowError:
        return {"nonfinite": "overflow"}
    if not math.isfinite(x):
        return {"nonfinite": str(x)}
    return {"magnitude": x}


def _example(asked):
    if asked.unit:
        return f"{asked.name} = Q_(12.5, {asked.unit!r})"
    return f"{asked.name} = 1.25"


def _radian_power(units):
    """Power of the radian in a unit's root form: 1 for rad, deg, rpm's rev/min
    and rad/s; 0 for Hz, 1/s and lengths."""
    return dict(units.to_root_units().unit_items()).get("radian", 0)


def read(asked, report, ureg):
    """The :class:`Reading` of ``report`` (from :func:`describe`) for ``asked``.

    ``ureg`` is the registry to read units with (the package's own).
    """
    if not isinstance(report, dict):
        report = {}
    name, state = asked.name, report.get("state")
    if not isinstance(state, str):
        state = "garbled"
    if state == "missing":
        return Reading(
            name,
            problem=(
                f"no variable `{name}` is defined: assign your answer to `{name}` in its answer "
                "cell (check the spelling, and run the cell)"
            ),
        )
    if asked.kind == "choice":
        if state != "text":
            return Reading(
                name, problem=f"`{name}` must be a word in quotes, one of {list(asked.choices)}"
            )
        word = str(report.get("text", ""))[:200].strip().lower()
        if word not in asked.choices:
            return Reading(
                name,
                problem=f"`{name}` = {_short(report.get('text'))} is not one "
                f"of {list(asked.choices)}",
            )
        return Reading(name, word=word)
    if state not in ("number", "quantity"):
        got = {
            "text": "a string",
            "array": "a list or an array",
            "complex": "a complex number",
            "unreadable": "a value that cannot be read",
            "garbled": "no readable report",
        }.get(state, _short(report.get("type", "something else"), quote=False))
        return Reading(
            name,
            problem=f"`{name}` must be one number or a Quantity (got {got}); "
            f"for example `{_example(asked)}`",
        )
    if "shape" in report:
        return Reading(name, problem=f"`{name}` must be a single value, not an array or a list")
    if report.get("complex"):
        return Reading(
            name,
            problem=f"`{name}` must be a real number, not a complex one: "
            "give a magnitude and a direction, or the x and y components",
        )
    try:
        x = (
            float(report["magnitude"])
            if type(report.get("magnitude")) in (int, float)
            else math.nan
        )
    except OverflowError:  # an integer beyond float64
        x = math.inf
    if "nonfinite" in report or not math.isfinite(x):
        return Reading(
            name,
            problem=f"`{name}` is not a finite number "
            f"({_short(report.get('nonfinite', 'no value'), quote=False)})",
        )
    asked_unit = ureg.Unit(asked.unit or "")
    if state == "number":
        if asked.quantity_required:
            return Reading(
                name,
                problem=(
                    f"`{name}` is a bare number, but the statement asks for it with its unit: "
                    f"write e.g. `{_example(asked)}`"
                ),
            )
        si = ureg.Quantity(x, asked_unit).to_base_units().magnitude
        return Reading(name, si=float(si), bare=True, raw=x)
    units = report.get("units", "")
    return _read_quantity(asked, x, units if isinstance(units, str) else "?", asked_unit, ureg)


def _short(value, quote=True, limit=60):
    """A value from a report as a message shows it: short, whatever it is."""
    text = repr(value) if quote else str(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _read_quantity(asked, x, units_text, asked_unit, ureg):
    """The reading of a Quantity's report: its unit text read by the package's one
    bounded reader (:func:`accelab.solver.units.read_units`); anything about the
    units that cannot be read or used costs this answer only."""
    name = asked.name
    try:
        units = read_units(units_text, name)
        want, got = asked_unit.dimensionality, units.dimensionality
    except Exception:  # noqa: BLE001 - InvalidInput, or pint's own for units it cannot use
        return Reading(
            name,
            problem=f"`{name}` has units {_short(units_text, limit=60)} that this course "
            f"cannot read; use units such as {asked.unit or 'a plain number'!r}",
        )
    if want != got:
        return Reading(
            name,
            problem=(
                f"`{name}` has the dimension {_dim_text(got)} ({units:~}), but the statement asks "
                f"for {_dim_text(want)} (in {asked.unit or 'a plain number'}): no credit for a "
                "wrong dimension"
            ),
        )
    try:
        want_rad = _radian_power(ureg.Quantity(1.0, asked_unit))
        got_rad = _radian_power(ureg.Quantity(1.0, units))
        si = ureg.Quantity(x, units).to_base_units().magnitude
    except Exception:  # noqa: BLE001 - an offset unit (degC) or one pint cannot convert
        return Reading(
            name,
            problem=f"`{name}` has units {units:~} that cannot be converted plainly; use "
            f"units such as {asked.unit or 'a plain number'!r}",
        )
    if want_rad != got_rad:
        return Reading(name, problem=_angle_unit_message(asked, units, want_rad, got_rad))
    if not isinstance(si, (int, float)) or not math.isfinite(si):
        return Reading(name, problem=f"`{name}` is not a finite number in SI units")
    return Reading(name, si=float(si))


def _angle_unit_message(asked, units, want_rad, got_rad):
    name = asked.name
    if want_rad > got_rad and want_rad == 1 and asked.kind == "angle":
        return (
            f"`{name}` is a direction, so it needs an angle unit (got {units:~}): write e.g. "
            f"`{name} = Q_(212.5, 'deg')` or a bare number in degrees"
        )
    if want_rad > got_rad:
        return (
            f"`{name}` is given in {units:~}, which could mean cycles or radians (a factor "
            f"of 2 pi apart): write it with an angle unit, e.g. in {asked.unit} or rpm "
            "(rev/min)"
        )
    return (
        f"`{name}` carries an angle unit ({units:~}) but the statement asks for "
        f"{asked.unit or 'a plain number'}: drop the angle unit"
    )


def _dim_text(dim):
    text = str(dim)
    return "dimensionless" if text in ("dimensionless", "") else text
