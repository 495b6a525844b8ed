"""Judging one answer, in the grader's process: the student's reading against
the key.

The rules, as every assignment states them:

* a number is right when ``|yours - exact| <= tolerance * |exact|`` (relative,
  default 1%), in whatever unit of the right dimension it was given;
* a direction (angle) is right when it is within ``angle_tolerance`` degrees of
  the exact direction, modulo 360 deg (default 1 deg);
* a word is right when it is the right one of the listed words.

A wrong answer's message says what to check (form, dimension, sign, size,
units, the opposite direction), never the expected value.
"""

import math
from dataclasses import dataclass

from ..student.answers import read


@dataclass(frozen=True)
class Verdict:
    """The grader's judgement of one answer: ``credit`` in [0, 1] and a message
    for the student (never containing the expected value)."""

    name: str
    ok: bool
    credit: float
    message: str


def right(name, detail):
    return Verdict(name, True, 1.0, f"{name}: right ({detail})")


def wrong(name, message):
    return Verdict(name, False, 0.0, message)


def judge(asked, report, expected, tolerance, angle_tolerance, ureg):
    """The :class:`Verdict` of one report (from the sandbox) for ``asked``.

    ``expected`` is the key: an SI float, or the right word.
    """
    return judge_reading(
        asked, read(asked, report, ureg), expected, tolerance, angle_tolerance, ureg
    )


def judge_reading(asked, reading, expected, tolerance, angle_tolerance, ureg):
    """:func:`judge` of a report already read (:func:`~accelab.exercises.student.answers.read`):
    a report is read once, however many keys it is compared with."""
    name = asked.name
    if not reading.ok:
        return wrong(name, f"{name}: {reading.problem}")
    if asked.kind == "choice":
        if reading.word == expected:
            return right(name, "the right judgement")
        return wrong(
            name,
            f"{name}: not the right judgement; compare your value with the "
            "levels the statement gives",
        )
    if asked.kind == "angle":
        return _judge_angle(name, reading, expected, angle_tolerance)
    return _judge_number(asked, reading, expected, tolerance, ureg)


def _close(got, expected, tolerance):
    return abs(got - expected) <= tolerance * abs(expected)


def _judge_number(asked, reading, expected, tolerance, ureg):
    name, got = asked.name, reading.si
    pct = f"{100 * tolerance:g}%"
    if _close(got, expected, tolerance):
        return right(name, f"within {pct}")
    if _close(-got, expected, tolerance):
        if asked.name.endswith("_mag") or asked.description.lower().startswith("magnitude"):
            return wrong(
                name,
                f"{name}: the size is right, but a magnitude is never negative: "
                "give |A|, the length of the vector, and leave its direction to the "
                "angle.",
            )
        return wrong(
            name,
            f"{name}: the size is right but the sign is wrong. Check the sense "
            "of rotation: angles, omega and alpha are positive counter-clockwise, and "
            "a vector's components follow the +x and +y axes.",
        )
    if reading.bare and asked.unit:
        base = ureg.Quantity(1.0, asked.unit).to_base_units().units
        if _close(reading.raw, expected, tolerance) and f"{base}" != asked.unit:
            return wrong(
                name,
                f"{name}: your bare number would be right in {base:~P}; the "
                f"statement asks for {asked.unit}: convert it, or give a Quantity.",
            )
    return wrong(
        name,
        f"{name}: not within {pct} of the exact value. "
        + _size_hint(got, expected)
        + " Check the given values and units, the circuit (branch), and each term of "
        "the acceleration (tangential, normal, Coriolis).",
    )


#: factors a unit or a formula slip multiplies an answer by, and what to check
FACTORS = [
    (2 * math.pi, "a factor of about 2 pi: check revolutions against radians"),
    (12.0, "a factor of about 12: check inches against feet"),
    (25.4, "a factor of about 25.4: check inches against millimetres"),
    (9.80665, "a factor of about 9.81: check g against m/s^2"),
    (2.0, "a factor of about 2: check for a doubled or a halved term"),
]


def _size_hint(got, expected):
    if got == 0 or expected == 0:
        return ""
    ratio = abs(got / expected)
    for factor, text in FACTORS:
        for r in (factor, 1 / factor):
            if abs(ratio - r) <= 0.02 * r:
                return f"Your value is off by {text}."
    exponent = math.log10(ratio)
    if abs(exponent - round(exponent)) < 0.01 and round(exponent) != 0:
        return f"Your value is off by a power of ten (10^{round(exponent)}): check units."
    return "Your value is too large in size." if ratio > 1 else "Your value is too small in size."


def _wrap(x):
    return (x + math.pi) % (2 * math.pi) - math.pi


def _judge_angle(name, reading, expected, angle_tolerance):
    band = math.radians(angle_tolerance)
    if abs(_wrap(reading.si - expected)) <= band:
        return right(name, f"within {angle_tolerance:g} deg")
    if abs(_wrap(reading.si - expected - math.pi)) <= band:
        return wrong(
            name,
            f"{name}: your direction points the opposite way. Check the sense of "
            "rotation (counter-clockwise positive) and the signs of the components "
            "before taking the angle (use the quadrant of both components, as atan2 "
            "does).",
        )
    if reading.bare and abs(_wrap(reading.raw - expected)) <= band:
        return wrong(
            name,
            f"{name}: your number would be right in radians; the statement asks "
            "for degrees (or give a Quantity, e.g. Q_(1.2, 'rad')).",
        )
    return wrong(
        name,
        f"{name}: the direction is off by more than {angle_tolerance:g} deg; "
        "measure it counter-clockwise from +x.",
    )
