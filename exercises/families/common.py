"""What every problem family shares: unit systems, drawing rounded inputs within
ranges, and the accept-or-redraw loop that keeps only well-conditioned variants.
"""

import contextvars

import numpy as np

from accelab.solver.units import ureg

from ..problem import Problem, solve_cases
from ..seeding import rng_for

#: display units of each unit system
UNITS = {
    "US": {"length": "in", "acceleration": "in/s^2", "jerk": "in/s^3", "big_length": "ft"},
    "SI": {"length": "mm", "acceleration": "m/s^2", "jerk": "m/s^3", "big_length": "m"},
}
#: lengths of the default ranges are written in inches; SI ranges use these mm
#: per inch (a round 25, so SI variants get round millimetres)
MM_PER_IN = 25.0

#: a variant is kept only when every case's condition (1 best, 0 at a toggle)
#: is at least this: far above the solver's singular threshold (1e-4)
MIN_CONDITION = 0.2
MAX_ATTEMPTS = 500


class GenerationError(RuntimeError):
    """No acceptable variant within MAX_ATTEMPTS draws: the ranges are too tight
    or mostly unassemblable."""


class Reject(Exception):
    """Raised by a family's builder to ask for another draw."""


def check_units(units):
    if units not in UNITS:
        raise ValueError(f"units must be 'US' or 'SI' (got {units!r})")
    return UNITS[units]


def ranges_for(defaults, ranges, units):
    """Merge instructor ranges into the family defaults.

    ``defaults`` maps name -> (lo, hi, step, kind) with lengths in inches;
    for SI they are scaled to millimetres. ``ranges`` maps name -> (lo, hi) or
    (lo, hi, step), numbers in the display unit of ``units`` or quantity
    strings such as ("1 in", "3 in").
    """
    check_units(units)
    out = {}
    for name, (lo, hi, step, kind) in defaults.items():
        if kind == "length" and units == "SI":  # round millimetres: steps of 5 or 10 mm
            step = 5.0 * max(1, round(step * MM_PER_IN / 5.0))
            lo, hi = (step * round(v * MM_PER_IN / step) for v in (lo, hi))
        out[name] = (lo, hi, step, kind)
    for name, spec in (ranges or {}).items():
        if name not in out:
            raise ValueError(f"unknown range {name!r}; this family draws {', '.join(sorted(out))}")
        _, _, step, kind = out[name]
        lo, hi = spec[0], spec[1]
        if len(spec) > 2:
            step = float(spec[2])
        unit = display_unit(kind, units)
        lo, hi = (_in_unit(v, unit, name) for v in (lo, hi))
        if not hi >= lo:
            raise ValueError(f"range {name!r}: the upper end must not be below the lower end")
        out[name] = (lo, hi, step, kind)
    return out


def display_unit(kind, units):
    return {
        "length": UNITS[units]["length"],
        "big_length": UNITS[units]["big_length"],
        "angle": "deg",
        "omega": "rad/s",
        "alpha": "rad/s^2",
        "time": "s",
        "rpm": "rpm",
        "number": "",
    }[kind]


def _in_unit(value, unit, name):
    if isinstance(value, str):
        q = ureg.Quantity(value)
        try:
            return float(q.to(unit).magnitude) if unit else float(q.to("").magnitude)
        except Exception:  # noqa: BLE001 - pint raises many types; each means: not in this unit
            raise ValueError(f"range {name!r}: {value!r} is not convertible to {unit}") from None
    return float(value)


#: set while a self-study practice problem is drawn (:mod:`accelab.exercises.practice`)
PRACTICE = contextvars.ContextVar("practice", default=False)


def draw_value(rng, spec, nonzero=False, signed=False):
    """One value on the grid lo, lo+step, ..., hi (textbook precision).

    ``signed`` also flips the sign at random; ``nonzero`` redraws zero. Practice
    problems are drawn on the half-steps lo + step/2, lo + 3 step/2, ... instead,
    so that with the default ranges a practice problem is never a graded one.
    """
    lo, hi, step, _ = spec
    n = int(np.floor((hi - lo) / step + 1e-9))
    half = PRACTICE.get() and n > 0
    for _ in range(100):
        if half:
            value = round(lo + step * (int(rng.integers(0, n)) + 0.5), 10)
        else:
            value = round(lo + step * int(rng.integers(0, n + 1)), 10)
        if signed and rng.random() < 0.5:
            value = -value
        if not (nonzero and value == 0):
            return value
    raise Reject()


def fmt(value, unit):
    """Value text for a case or a statement: '6.5 in', '-500 rad/s^2'."""
    text = f"{value:.10g}"
    return f"{text} {unit}" if unit else text


def solve_checked(cases, min_condition=MIN_CONDITION):
    """Solve the cases; Reject unless every one is ok and well conditioned."""
    try:
        outputs = solve_cases(cases)
    except ValueError:
        raise Reject() from None  # a variant the solver refuses: draw another
    for out in outputs.values():
        if out.get("condition", 1.0) < min_condition:
            raise Reject()
    return outputs


def first_accepted(family, seed, build, units):
    """Draw with ``build(rng)`` until it returns a Problem; the rng is seeded by
    ``seed`` so the result is deterministic."""
    check_units(units)
    rng = rng_for(("practice" if PRACTICE.get() else "family", family, int(seed)))
    for _ in range(MAX_ATTEMPTS):
        try:
            problem = build(rng)
        except Reject:
            continue
        problem.seed = int(seed)
        return problem
    raise GenerationError(
        f"no well-conditioned {family} variant in {MAX_ATTEMPTS} draws; "
        "widen the ranges (or check that the linkage can assemble in them)"
    )


def sizable(*pairs):
    """Reject unless each (part, whole) has |part| >= 5% of |whole|: answers of
    sensible size, never a near-zero value that a 1% relative tolerance would
    make impossible to hit."""
    for part, whole in pairs:
        if not abs(part) >= 0.05 * abs(whole) or abs(whole) == 0:
            raise Reject()


__all__ = [
    "Problem",
    "Reject",
    "GenerationError",
    "UNITS",
    "ranges_for",
    "draw_value",
    "fmt",
    "solve_checked",
    "first_accepted",
    "sizable",
    "display_unit",
    "check_units",
]


FOURBAR_DEFAULTS = {
    "a": (1.0, 4.0, 0.5, "length"),
    "b": (3.0, 9.0, 0.5, "length"),
    "c": (3.0, 9.0, 0.5, "length"),
    "d": (4.0, 10.0, 0.5, "length"),
    "theta2": (0.0, 355.0, 5.0, "angle"),
    "omega2": (5.0, 50.0, 5.0, "omega"),
    "alpha2": (5.0, 100.0, 5.0, "alpha"),
}


def fourbar_case(rng, r, L):
    """A fourbar batch case drawn from the ranges ``r`` (lengths in unit ``L``);
    the circuit is drawn too."""
    return {
        "mechanism": "fourbar",
        "a": fmt(draw_value(rng, r["a"], nonzero=True), L),
        "b": fmt(draw_value(rng, r["b"], nonzero=True), L),
        "c": fmt(draw_value(rng, r["c"], nonzero=True), L),
        "d": fmt(draw_value(rng, r["d"], nonzero=True), L),
        "theta2": fmt(draw_value(rng, r["theta2"]), "deg"),
        "omega2": fmt(draw_value(rng, r["omega2"], nonzero=True, signed=True), "rad/s"),
        "alpha2": fmt(draw_value(rng, r["alpha2"], nonzero=True, signed=True), "rad/s^2"),
        "circuit": "open" if rng.random() < 0.5 else "crossed",
    }


def given_of(case, keys):
    """The statement's given values: the case's own strings for ``keys``."""
    return {k: case[k] for k in keys if k in case}
