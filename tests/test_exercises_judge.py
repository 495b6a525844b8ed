"""Judging one answer (accelab.exercises.student.answers and accelab.exercises.grader.judge): form,
dimension, then value against the key, with hints that never show the key."""

import math

import pytest

from accelab.exercises.grader.judge import judge
from accelab.exercises.student.answers import MISSING, Asked, describe, read
from accelab.solver.units import Q_, ureg

ACC = Asked("A_B_mag", "in/s^2", "magnitude")
SIGNED = Asked("alpha3", "rad/s^2", "alpha3")
ANG = Asked("A_B_ang", "deg", "direction", kind="angle")
QTY = Asked("A_BA_mag", "in/s^2", "with unit", quantity_required=True)
CHOICE = Asked("verdict", "", "judge", kind="choice", choices=("gentle", "strong"))
OMEGA = Asked("omega3", "rad/s", "angular velocity")
EXPECTED = 100 * 0.0254  # 100 in/s^2 in SI


def grade(asked, value, expected, tolerance=0.01, angle_tolerance=1.0):
    return judge(asked, describe(value), expected, tolerance, angle_tolerance, ureg)


@pytest.mark.parametrize(
    "value, ok",
    [
        (100.0, True),
        (100.9, True),
        (101.1, False),
        (Q_(100, "in/s^2"), True),
        (Q_(2.54, "m/s^2"), True),
        (Q_(8.3333, "ft/s^2"), True),
        (Q_(2540, "mm/s^2"), True),
    ],
)
def test_value_within_relative_tolerance_in_any_unit(value, ok):
    assert grade(ACC, value, EXPECTED).ok is ok


def test_wrong_dimension_gets_nothing_and_names_both_dimensions():
    r = grade(ACC, Q_(100, "in/s"), EXPECTED)
    assert not r.ok and r.credit == 0
    assert "[length] / [time]" in r.message and "[length] / [time] ** 2" in r.message
    assert read(ACC, describe(Q_(3, "rad/s^2")), ureg).problem is not None


def test_sign_error_hint_and_units_hint():
    r = grade(SIGNED, Q_(-5.0, "rad/s^2"), 5.0)
    assert not r.ok and "sense of rotation" in r.message
    r = grade(ACC, 2.54, EXPECTED)  # bare SI number where in/s^2 is asked
    assert not r.ok and "m/s²" in r.message
    r = grade(ANG, -90.0 + 180.0, math.radians(-90.0))
    assert not r.ok and "opposite way" in r.message
    r = grade(ANG, math.radians(120.0), math.radians(120.0))  # radians typed as degrees
    assert not r.ok and "radians" in r.message


def test_negative_magnitude_gets_a_magnitude_hint():
    r = grade(ACC, Q_(-EXPECTED, "m/s^2"), EXPECTED)
    assert not r.ok and "never negative" in r.message and "sense of rotation" not in r.message


def test_angles_compare_modulo_a_turn_within_the_stated_band():
    assert grade(ANG, 270.0, math.radians(-90.0)).ok
    assert grade(ANG, Q_(-math.pi / 2, "rad"), math.radians(270.0)).ok
    assert grade(ANG, -89.1, math.radians(-90.0)).ok  # 0.9 deg off: inside 1 deg
    assert not grade(ANG, -88.8, math.radians(-90.0)).ok  # 1.2 deg off
    assert not grade(ANG, -86.0, math.radians(-90.0)).ok
    # the band is what the statement says, not the relative tolerance times 180 deg
    assert not grade(ANG, -87.0, math.radians(-90.0), tolerance=0.05).ok
    assert grade(ANG, -87.0, math.radians(-90.0), angle_tolerance=5.0).ok


def test_format_problems():
    assert "no variable `A_B_mag`" in grade(ACC, MISSING, EXPECTED).message
    assert "must be one number" in grade(ACC, "12", EXPECTED).message
    assert "single value" in grade(ACC, Q_([1.0, 2.0], "in/s^2"), EXPECTED).message
    assert "finite" in grade(ACC, float("inf"), EXPECTED).message
    assert "bare number" in grade(QTY, 100.0, EXPECTED).message
    assert grade(QTY, Q_(100, "in/s^2"), EXPECTED).ok
    assert grade(CHOICE, " Strong", "strong").ok
    assert "not one of" in grade(CHOICE, "fine", "strong").message
    assert not grade(CHOICE, "gentle", "strong").ok


def test_quantities_of_another_registry_are_accepted():
    import pint

    other = pint.UnitRegistry()
    assert grade(ACC, other.Quantity(100, "inch / second ** 2"), EXPECTED).ok


def test_messages_never_show_the_expected_value_and_nothing_goes_to_stderr(capfd):
    import warnings

    expected = 123.456789
    for value in (1.0, -expected, Q_(1, "m"), "x", float("nan")):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            msg = grade(SIGNED, value, expected).message
        assert "123.4" not in msg and "1.23" not in msg
    assert capfd.readouterr().err == ""


def test_units_that_mean_two_things_are_refused_with_both_readings():
    expected = 2 * math.pi * 10 / (2 * math.pi)  # 10 rad/s
    for unit in ("Hz", "1/s"):
        r = grade(OMEGA, Q_(10, unit), 10.0)
        assert not r.ok and "cycles or radians" in r.message and "rpm" in r.message
    assert grade(OMEGA, Q_(10, "rad/s"), expected).ok
    assert grade(OMEGA, Q_(60 / (2 * math.pi) * 10, "rpm"), 10.0).ok
    assert grade(OMEGA, Q_(10 / (2 * math.pi), "revolution/s"), 10.0).ok
    r = grade(ANG, Q_(30, ""), math.radians(30))
    assert not r.ok and "angle unit" in r.message
    r = grade(ACC, Q_(100, "rad * in/s^2"), EXPECTED)
    assert not r.ok and "drop the angle unit" in r.message


def test_describe_reports_plain_data_and_survives_hostile_objects():
    class Evil:
        @property
        def magnitude(self):
            raise RuntimeError("boom")

        units = "m"

    assert describe(Evil())["state"] == "unreadable"
    assert describe(MISSING) == {"state": "missing"}
    assert describe(True)["state"] == "other"
    assert describe("x" * 10000)["text"] == "x" * 200
    assert describe(10**400)["nonfinite"] == "overflow"
    assert describe(Q_(1 + 2j, "m"))["complex"]
    import numpy as np

    assert describe(np.float32(2.5)) == {"state": "number", "magnitude": 2.5}
    assert describe(np.array([1.0, 2.0]))["state"] == "array"
    assert "inch" in describe(Q_(3, "in"))["units"]


def test_reading_gives_si_once():
    r = read(ACC, describe(Q_(100, "in/s^2")), ureg)
    assert r.ok and r.si == pytest.approx(EXPECTED) and not r.bare
    r = read(ACC, describe(100), ureg)
    assert r.ok and r.bare and r.raw == 100 and r.si == pytest.approx(EXPECTED)
    r = read(ACC, {"state": "quantity", "magnitude": 1.0, "units": "(" * 5000}, ureg)
    assert not r.ok and "cannot read" in r.problem


# ---- a report is the student's: the kernel can send anything ------------------------

FORGED = [
    {},
    {"state": None},
    {"state": ["number"]},
    {"state": "number"},
    {"state": "number", "magnitude": [1, 2]},
    {"state": "number", "magnitude": {"a": 1}},
    {"state": "number", "magnitude": "100"},
    {"state": "number", "magnitude": True},
    {"state": "number", "magnitude": 10**400},
    {"state": "number", "magnitude": None},
    {"state": "quantity", "magnitude": 100.0, "units": ["in/s^2"]},
    {"state": "quantity", "magnitude": 100.0, "units": "in/s^2" * 10000},
    {"state": "quantity", "magnitude": 100.0, "units": {"in": 1}},
    {"state": "other", "type": "x" * 1_000_000},
    {"state": "other", "type": [[["deep"]]]},
    {"state": "number", "magnitude": 1.0, "nonfinite": "z" * 1_000_000},
    {"state": "text", "text": ["gentle"]},
    {"state": "text", "text": "g" * 1_000_000},
]


@pytest.mark.parametrize("report", FORGED, ids=range(len(FORGED)))
@pytest.mark.parametrize("asked", [ACC, ANG, QTY, CHOICE], ids=lambda a: a.name)
def test_a_forged_report_is_refused_briefly_and_never_raises(asked, report):
    verdict = judge(asked, report, EXPECTED if asked is not CHOICE else "gentle", 0.01, 1.0, ureg)
    assert not verdict.ok and verdict.credit == 0
    assert len(verdict.message) < 600, verdict.message[:700]


# ---- unit texts: the one bounded reader ---------------------------------------------

HOSTILE_UNITS = [
    "m/s**2 * 9**9**8",  # a power of a power: hours of arithmetic
    "m/s**2 * 9**9**6",
    "((9**99*2)**99*2)**99 * m/s**2",  # a powered group that holds a power
    "(((((m)))))/s**2",  # nested too deep
    "m/s**2*dB",  # pint parses it but cannot use it
    "m/s**2 * degC",
    "in/s^2" + " " * 200,
]


@pytest.mark.parametrize("units", HOSTILE_UNITS)
def test_a_hostile_unit_text_costs_its_answer_only_and_is_read_at_once(units):
    import time

    start = time.thread_time()  # CPU time of this thread: the work, not the machine's load
    verdict = judge(
        ACC, {"state": "quantity", "magnitude": 1.0, "units": units}, EXPECTED, 0.01, 1.0, ureg
    )
    assert time.thread_time() - start < 0.2
    assert not verdict.ok and (
        "cannot read" in verdict.message
        or "cannot be converted" in verdict.message
        or "dimension" in verdict.message
    )


def test_the_grader_reads_a_report_once_however_large_the_class():
    """Whose values a wrong answer holds is asked of every other student's key: each
    report is read once (the same bounded reader), then compared."""
    import time
    from types import SimpleNamespace

    from accelab.exercises.grader import outcome as oc
    from accelab.exercises.grader.judge import wrong

    asked = {f"a{k}": ACC for k in range(11)}
    reports = {
        n: {"state": "quantity", "magnitude": 1.0, "units": "m/s**2 * 9**9**6"} for n in asked
    }
    variant = SimpleNamespace(tolerance=0.01, angle_tolerance=1.0)
    me = SimpleNamespace(student="me", variant=variant, values={n: EXPECTED for n in asked})
    others = {
        f"s{k}": SimpleNamespace(values={n: EXPECTED * (k + 2) for n in asked}) for k in range(300)
    }
    run = SimpleNamespace(refused=[], loaded=[], reports=reports)
    result = SimpleNamespace(verdicts={n: wrong(n, "x") for n in asked})
    calls = []
    real = oc.read
    oc.read = lambda *a: calls.append(1) or real(*a)
    try:
        start = time.thread_time()
        oc._whose_values(me, run, others, [], result, asked)
        assert time.thread_time() - start < 1.0
    finally:
        oc.read = real
    assert len(calls) <= len(asked)
