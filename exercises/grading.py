"""Grading one answer: format, then dimension, then value.

* format: the variable exists, is one finite number or a Quantity (a bare
  number is read in the unit the statement asks for, unless the answer needs
  a Quantity), or one of the choices;
* dimension: compared with the asked unit's; a wrong dimension earns nothing
  and the message names both dimensions;
* value: within a relative tolerance (default 1%) of the solver's value;
  angles modulo 360 deg within tolerance x 180 deg. A value right but for its
  sign gets a hint about the sense of rotation; a bare number that would be
  right in SI units gets a hint about units.

Nothing here writes to stderr (nbgrader scores a test cell that does as zero):
warnings are silenced and stray writes captured.
"""

import contextlib
import io
import math
import numbers
import warnings
from dataclasses import dataclass

from solver.units import ureg

DEFAULT_TOLERANCE = 0.01


@dataclass
class Check:
    """The outcome for one answer: ``credit`` in [0, 1] and a message for the
    student (never containing the expected value)."""

    name: str
    ok: bool
    credit: float
    message: str


@contextlib.contextmanager
def quiet():
    """No warnings and no stderr output inside."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with contextlib.redirect_stderr(io.StringIO()):
            yield


def _unit_text(unit):
    return unit if unit else "a plain number"


def _dim_text(dim):
    text = str(dim)
    return "dimensionless" if text in ("dimensionless", "") else text


def _example(answer):
    return f"{answer.name} = Q_(12.5, {answer.unit!r})" if answer.unit else f"{answer.name} = 1.25"


def as_quantity(answer, value):
    """(Quantity, None) for a usable value, else (None, message) about its format."""
    name = answer.name
    if hasattr(value, "magnitude") and hasattr(value, "units"):
        try:  # a Quantity, perhaps from another registry: rebuild it on ours
            q = value if getattr(value, "_REGISTRY", None) is ureg else \
                ureg.Quantity(value.magnitude, str(value.units))
        except Exception:
            return None, f"`{name}` has units {value.units!s} that this course cannot read"
        magnitude = q.magnitude
    elif isinstance(value, numbers.Real) and not isinstance(value, bool):
        if answer.quantity_required:
            return None, (f"`{name}` is a bare number, but the statement asks for it with "
                          f"its unit: write e.g. `{_example(answer)}`")
        q = ureg.Quantity(float(value), answer.unit or "")
        magnitude = float(value)
    elif value is None:
        return None, f"`{name}` is None: assign your answer to it"
    else:
        return None, (f"`{name}` must be a number or a Quantity (got {type(value).__name__}); "
                      f"for example `{_example(answer)}`")
    try:
        magnitude = float(magnitude)
    except (TypeError, ValueError):
        return None, f"`{name}` must be a single value, not an array or a list"
    if not math.isfinite(magnitude):
        return None, f"`{name}` is not a finite number ({magnitude})"
    return ureg.Quantity(magnitude, q.units), None


def check_format(answer, value, defined=True):
    """A message if the value's format or dimension is wrong, else None."""
    with quiet():
        return _check_format(answer, value, defined)


def _check_format(answer, value, defined):
    if not defined:
        return (f"no variable `{answer.name}` is defined: assign your answer to `{answer.name}` "
                "in its answer cell (check the spelling; run the cell)")
    if answer.kind == "choice":
        if not isinstance(value, str):
            return f"`{answer.name}` must be a string, one of {answer.choices}"
        if value.strip().lower() not in answer.choices:
            return f"`{answer.name}` = {value!r} is not one of {answer.choices}"
        return None
    q, message = as_quantity(answer, value)
    if message:
        return message
    expected = ureg.Quantity(1.0, answer.unit or "").dimensionality
    if q.dimensionality != expected:
        return (f"`{answer.name}` has the dimension {_dim_text(q.dimensionality)} ({q.units:~}), "
                f"but the statement asks for {_dim_text(expected)} (in "
                f"{_unit_text(answer.unit)}): no credit for a wrong dimension")
    return None


def grade(answer, value, expected, tolerance=DEFAULT_TOLERANCE, defined=True):
    """Grade ``value`` against ``expected`` (SI float, or the right choice).

    Returns a :class:`Check`; its message says what to check, never the value.
    """
    with quiet():
        return _grade(answer, value, expected, tolerance, defined)


def _grade(answer, value, expected, tolerance, defined):
    name = answer.name
    problem = _check_format(answer, value, defined)
    if problem:
        return Check(name, False, 0.0, problem)
    if answer.kind == "choice":
        if value.strip().lower() == expected:
            return Check(name, True, 1.0, f"{name}: right")
        return Check(name, False, 0.0, f"{name}: not the right judgement; compare your "
                     "acceleration in g with the levels given in the statement")
    q, _ = as_quantity(answer, value)
    got = float(q.to_base_units().magnitude)
    pct = f"{100 * tolerance:g}%"
    if answer.kind == "angle":
        raw = float(value) if isinstance(value, numbers.Real) else None
        return _grade_angle(name, got, expected, tolerance, raw)
    if _close(got, expected, tolerance):
        return Check(name, True, 1.0, f"{name}: right (within {pct})")
    if _close(-got, expected, tolerance) and _is_magnitude(answer):
        return Check(name, False, 0.0, (
            f"{name}: the size is right, but a magnitude is never negative: give |A|, the "
            "length of the vector, and leave its direction to the angle."))
    if _close(-got, expected, tolerance):
        return Check(name, False, 0.0, (
            f"{name}: the size is right but the sign is wrong. Check the sense of rotation: "
            "angles, omega and alpha are positive counter-clockwise, and a vector's components "
            "follow the +x and +y axes."))
    message = f"{name}: not within {pct} of the solver's value."
    if isinstance(value, numbers.Real) and answer.unit:
        base = ureg.Quantity(1.0, answer.unit).to_base_units().units
        if _close(float(value), expected, tolerance) and str(base) != answer.unit:
            message += (f" Your bare number would be right in {base:~P}; the statement asks "
                        f"for {answer.unit}: convert it, or give a Quantity.")
            return Check(name, False, 0.0, message)
    message += (" Check the given values and units, the circuit (branch), and each "
                "term of the acceleration (tangential, normal, Coriolis).")
    return Check(name, False, 0.0, message)


def _is_magnitude(answer):
    return answer.name.endswith("_mag") or answer.description.lower().startswith("magnitude")


def _close(got, expected, tolerance):
    return abs(got - expected) <= tolerance * abs(expected)


def _grade_angle(name, got, expected, tolerance, raw=None):
    def wrap(x):
        return (x + math.pi) % (2 * math.pi) - math.pi
    limit = tolerance * math.pi
    if abs(wrap(got - expected)) <= limit:
        return Check(name, True, 1.0, f"{name}: right (within {math.degrees(limit):.3g} deg)")
    if abs(wrap(got - expected - math.pi)) <= limit:
        return Check(name, False, 0.0, (
            f"{name}: your direction points the opposite way. Check the sense of rotation "
            "(counter-clockwise positive) and the signs of the components before taking "
            "the angle (use the quadrant of both components, as atan2 does)."))
    if raw is not None and abs(wrap(raw - expected)) <= limit:  # radians typed as degrees
        return Check(name, False, 0.0, f"{name}: your number would be right in radians; the "
                     "statement asks for degrees (or give a Quantity, e.g. Q_(1.2, 'rad')).")
    return Check(name, False, 0.0, f"{name}: the direction is off by more than "
                 f"{math.degrees(limit):.3g} deg; measure it counter-clockwise from +x.")
