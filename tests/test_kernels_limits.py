"""Positions close to a limit (toggle) position: answered accurately or
reported ``singular``, never wrong.

For each mechanism that has limit positions (the fourbar's and the fivebar's
couplers collinear, |A - O4| = b + c or |b - c|; the slider-crank's rod
perpendicular to the slide; the inverted slider-crank's slide line tangent to
the reach of A) the exact limit angle is found at 50 digits
(tests/_mp_reference.py), the kernels are run at delta = 1e-1 .. 1e-12 rad of
theta2 from it on both sides, and every output is compared with the 50-digit
reference. What must hold (the project's reference check asks the same of the
batch solver):

* delta > 1e-4 rad: answered (status ok), within 1e-5 relative in every
  output, jerk included (we ask 2e-6, the bound MAX_ROUNDOFF with its
  measured gain gives);
* any delta: an answer is within that bound; otherwise ``singular``;
* past the limit (by more than round-off): ``not_assemblable``.

Errors are relative, but an output smaller than 1e-3 of the largest of its
order and kind is judged against that 1e-3 (the reference check's rule).
The links 2-3 collinear positions of a crank-rocker (the rocker's extremes,
omega4 = 0) are limit positions of the output only: nothing is singular
there, and the kernels answer them to full accuracy.
"""

import math

import _checks as check
import numpy as np
import pytest
from conftest import examples
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from mpmath import mp, mpf
from test_kernels_accuracy import kernel_outputs, run_kernel

import accelab.benchmarks.reference as ref
from accelab.solver.batch import solve_cases
from accelab.solver.kernels import NOT_ASSEMBLABLE, OK, SINGULAR

DELTAS = [10.0**-k for k in range(1, 13)]
MUST_ANSWER = 1e-4  # farther than this from a limit, refusing is wrong
BOUND = 2e-6  # what an answer must meet (the project asks 1e-5)
FLOOR = 1e-3
MOTION = dict(omega2=7.0, alpha2=-30.0, jerk2=400.0, theta1=0.35)

GEOMETRIES = [
    # fourbar, non-Grashof: outer limit (|A - O4| = b + c)
    ("fourbar", dict(a=4.0, b=3.0, c=2.0, d=5.0)),
    # fourbar, inner limit (|A - O4| = |b - c|)
    ("fourbar", dict(a=1.3, b=3.1, c=0.9, d=2.0)),
    # fourbar with a short rocker (c/a = 1/400): round-off grows fastest here
    ("fourbar", dict(a=0.68, b=0.6, c=0.0017, d=0.15, p=0.3, delta3=0.7)),
    ("slidercrank", dict(a=0.3, b=0.2, c=0.05)),
    ("slidercrank", dict(a=0.42, b=0.002, c=-0.29)),  # a rod 200 times shorter
    ("invertedslidercrank", dict(a=0.1, c=0.24, d=0.16, gamma=-2.1)),
    ("invertedslidercrank", dict(a=0.0316, c=0.0014, d=0.0326, gamma=1.485)),
    ("fivebar", dict(a=0.046, b=0.122, c=0.0615, d=0.148, f=0.2168, lam=-1.0, phi=-1.06)),
    ("fivebar", dict(a=0.7146, b=0.4384, c=0.002, d=0.3042, f=0.0016, lam=2.0, phi=3.1035)),
]


def _assembles(mech, geo, t2, circuit="open"):
    return ref.assembles(mech, geo, t2, circuit)


def limit_angles(mech, geo):
    """[(label, t2*, side)]: limit angles (ground frame, 50 digits) and the
    side (+1 / -1) of theta2 on which the linkage assembles."""
    with mp.workdps(ref.mechanisms.DPS):
        if mech == "fourbar":
            found = [
                (f"{kind}{'+-'[k]}", sign * t)
                for kind, (t, _) in ref.fourbar_limits(
                    geo["a"], geo["b"], geo["c"], geo["d"]
                ).items()
                for k, sign in enumerate((1, -1))
            ]
        elif mech == "slidercrank":
            found = [
                (f"{kind}{i}", t)
                for kind, ts in ref.slidercrank_limits(**geo).items()
                for i, t in enumerate(ts)
            ]
        elif mech == "invertedslidercrank":
            t = ref.invertedslidercrank_limit(**geo)
            found = [] if t is None else [("tangent+", t), ("tangent-", -t)]
        else:
            found = [
                (f"{kind}{i}", t)
                for i, (t, kind) in enumerate(ref.fivebar_limits(geo, -math.pi, math.pi))
            ]
        out = []
        for label, t in found:
            up, down = (_assembles(mech, geo, t + s * mpf("1e-6")) for s in (1, -1))
            if up != down:  # a limit with the loop closing on one side only
                out.append((label, t, 1 if up else -1))
        return out


def near_limit(mech, geo, t_star, side, delta, circuit, motion=MOTION):
    """Status and errors of the kernel at ``delta`` from the limit on the
    assembling side (inside), and its status on the other side (past). None
    for a side where the reference does not agree that it assembles (inside)
    or does not (past): with short links another limit may be that near."""
    theta1 = motion["theta1"]
    with mp.workdps(ref.mechanisms.DPS):
        inside = float(t_star + side * mpf(delta) + theta1)
        past = float(t_star - side * mpf(delta) + theta1)
    want = ref.solve(
        mech, geo, inside, motion["omega2"], motion["alpha2"], motion["jerk2"], theta1, circuit
    )
    status, errors = None, {}
    if want is not None:
        case = dict(geo, theta2=inside, **motion)
        m = run_kernel(mech, case, circuit)
        status = int(m.status)
        if status == OK:
            errors = check.errors(kernel_outputs(mech, case, m), want, FLOOR)
    past_status = None
    if not _assembles(mech, geo, past - theta1, circuit):
        past_status = int(run_kernel(mech, dict(geo, theta2=past, **motion), circuit).status)
    return status, errors, past_status


def check_sweep(mech, geo, circuit, deltas=DELTAS, motion=MOTION):
    limits = limit_angles(mech, geo)
    assert limits, "the geometry of this test must have limit positions"
    refused_from = {}
    for label, t_star, side in limits:
        for delta in deltas:
            status, errors, past = near_limit(mech, geo, t_star, side, delta, circuit, motion)
            where = f"{mech} {label} ({circuit}) at delta {delta:.0e}"
            assert status is not None or delta >= 1e-3, f"{where}: reference does not assemble"
            if status is None:
                continue
            if delta > MUST_ANSWER:
                assert status == OK, f"{where}: refused ({status})"
            if status == OK:
                worst = max(errors, key=errors.get)
                assert errors[worst] <= BOUND, f"{where}: {worst} off by {errors[worst]:.1e}"
            else:
                assert status == SINGULAR, where
                refused_from[label] = max(refused_from.get(label, 0.0), delta)
            if past is None:
                assert delta >= 1e-3, f"{where}: reference assembles past the limit"
            elif delta >= 1e-10:
                assert past == NOT_ASSEMBLABLE, f"{where}, past the limit: status {past}"
            else:
                assert past != OK, f"{where}, past the limit: answered"
    return refused_from


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize(
    "mech, geo", GEOMETRIES, ids=[f"{m}-{i}" for i, (m, _) in enumerate(GEOMETRIES)]
)
def test_near_limit_answered_accurately_or_refused(mech, geo, circuit):
    refused_from = check_sweep(mech, geo, circuit)
    # and the refusal does not start far out: only within 1e-6 rad here
    assert all(d <= 1e-6 for d in refused_from.values()), refused_from


def test_limits_exist_in_every_fixed_geometry():
    kinds = {
        (mech, label.rstrip("+-0123456789"))
        for mech, geo in GEOMETRIES
        for label, _, _ in limit_angles(mech, geo)
    }
    assert {
        ("fourbar", "outer"),
        ("fourbar", "inner"),
        ("slidercrank", "upper"),
        ("slidercrank", "lower"),
        ("invertedslidercrank", "tangent"),
        ("fivebar", "outer"),
    } <= kinds


# ------------------------------------------------------------ at the limit itself


@pytest.mark.parametrize(
    "mech, geo", GEOMETRIES[:1] + GEOMETRIES[3:4] + GEOMETRIES[5:6] + GEOMETRIES[7:8]
)
def test_at_the_limit_and_within_roundoff_is_singular_with_a_position(mech, geo):
    """At the toggle itself (and within round-off of it, on either side) the
    kernel says singular, not not_assemblable, and still gives the position."""
    label, t_star, side = limit_angles(mech, geo)[0]
    for offset in (0.0, 1e-16, -1e-16, 4e-16, -4e-16):
        theta2 = float(t_star + mpf(offset))
        m = run_kernel(
            mech, dict(geo, theta2=theta2, omega2=1.0, alpha2=0.0, jerk2=0.0, theta1=0.0), "open"
        )
        assert m.status == SINGULAR, (label, offset, m.status)
        assert np.isfinite(m.theta3) and np.isnan(m.omega3)
        with mp.workdps(ref.mechanisms.DPS):
            want = ref.solve(mech, geo, t_star + side * mpf("1e-30"), 1.0)
        assert check.angle_error(m.theta3, want["theta3"]) < 1e-6


# ------------------------------------------------------------ the rocker's extremes


@pytest.mark.parametrize("circuit", ["open", "crossed"])
def test_rocker_extremes_are_not_singular(circuit):
    """A crank-rocker (Grashof, s + l < p + q) has its rocker's extreme
    positions where links 2 and 3 are collinear: omega4 passes through zero,
    the equations stay well conditioned, and every output is full accuracy."""
    geo = dict(a=0.04, b=0.12, c=0.09, d=0.1)
    limits = ref.fourbar_rocker_limits(**geo)
    assert set(limits) == {"extended", "folded"}
    extremes = 0
    for kind, angles in limits.items():
        for t_star in angles:
            omega4 = []
            for delta in (1e-1, 1e-3, 1e-6, 1e-9, 1e-12, -1e-12, -1e-9, -1e-6, -1e-3, -1e-1):
                theta2 = float(t_star + mpf(delta))
                case = dict(geo, theta2=theta2, omega2=30.0, alpha2=-50.0, jerk2=1e3, theta1=0.0)
                m = run_kernel("fourbar", case, circuit)
                assert m.status == OK
                want = ref.solve("fourbar", geo, theta2, 30.0, -50.0, 1e3, 0.0, circuit)
                errors = check.errors(kernel_outputs("fourbar", case, m), want, FLOOR)
                worst = max(errors, key=errors.get)
                assert errors[worst] < 1e-12, (kind, delta, worst, errors[worst])
                omega4.append(float(m.omega4))
            # on the circuit whose rocker is at its extreme there, omega4 changes sign
            with mp.workdps(ref.mechanisms.DPS):
                _, _, pts = ref.fourbar_position(
                    {k: mpf(v) for k, v in geo.items()}, t_star, ref.CIRCUIT_SIGN[circuit]
                )
                r = mpf(geo["a"]) + (1 if kind == "extended" else -1) * mpf(geo["b"])
                extreme = abs(abs(pts["B"]) - abs(r)) < 1e-20
            if extreme:
                extremes += 1
                assert omega4[0] * omega4[-1] < 0 and abs(omega4[4]) < 1e-9 * 30
    assert extremes == 2  # each circuit reaches both extremes, one per side of the ground


# ------------------------------------------------------------ random geometries

log_lengths = st.floats(math.log(0.01), 0.0).map(math.exp)
log_deltas = st.floats(-12.0, -1.0).map(lambda e: 10.0**e)


@st.composite
def near_limit_cases(draw):
    mech = draw(st.sampled_from(["fourbar", "slidercrank", "invertedslidercrank", "fivebar"]))
    if mech == "fourbar":
        geo = dict(
            a=draw(log_lengths), b=draw(log_lengths), c=draw(log_lengths), d=draw(log_lengths)
        )
    elif mech == "slidercrank":
        geo = dict(
            a=draw(log_lengths),
            b=draw(log_lengths),
            c=draw(st.sampled_from([-1.0, 1.0])) * draw(log_lengths),
        )
    elif mech == "invertedslidercrank":
        geo = dict(
            a=draw(log_lengths),
            c=draw(log_lengths),
            d=draw(log_lengths),
            gamma=draw(st.floats(-math.pi, math.pi)),
        )
    else:
        geo = dict(
            a=draw(log_lengths),
            b=draw(log_lengths),
            c=draw(log_lengths),
            d=draw(log_lengths),
            f=draw(log_lengths),
            lam=draw(st.sampled_from([-2.0, -1.0, -0.5, 0.5, 2.0])),
            phi=draw(st.floats(-math.pi, math.pi)),
        )
    limits = limit_angles(mech, geo)
    assume(limits)
    which = draw(st.integers(0, len(limits) - 1))
    sign = draw(st.sampled_from([-1.0, 1.0]))
    motion = dict(
        omega2=sign * draw(st.floats(0.5, 60.0)),
        alpha2=draw(st.floats(-800, 800)),
        jerk2=draw(st.floats(-2e4, 2e4)),
        theta1=draw(st.floats(-math.pi, math.pi)),
    )
    return (
        mech,
        geo,
        limits[which],
        draw(log_deltas),
        draw(st.sampled_from(["open", "crossed"])),
        motion,
    )


@settings(max_examples=examples(80))
@given(near_limit_cases())
def test_random_geometries_near_a_limit(case):
    """Lengths spread over two decades, any limit, delta from 1e-12 to 1e-1."""
    mech, geo, (label, t_star, side), delta, circuit, motion = case
    status, errors, past = near_limit(mech, geo, t_star, side, delta, circuit, motion)
    assume(status is not None)  # another limit nearer than delta
    if delta > MUST_ANSWER:
        assert status == OK
    if status == OK:
        worst = max(errors, key=errors.get)
        assert errors[worst] <= BOUND, (worst, errors[worst])
    else:
        assert status == SINGULAR
    assert past != OK


# ------------------------------------------------------------ through the batch

BATCH = [
    (
        "fourbar",
        {
            "a": "4 in",
            "b": "3 in",
            "c": "2 in",
            "d": "5 in",
            "theta1": "20 deg",
            "p": "1.5 in",
            "delta3": "30 deg",
        },
    ),
    ("slidercrank", {"a": "30 mm", "b": "20 mm", "c": "5 mm"}),
    ("invertedslidercrank", {"a": "100 mm", "c": "240 mm", "d": "160 mm", "gamma": "-120 deg"}),
    (
        "fivebar",
        {
            "a": "46 mm",
            "b": "122 mm",
            "c": "61.5 mm",
            "d": "148 mm",
            "f": "216.8 mm",
            "lam": -1,
            "phi": "-60 deg",
        },
    ),
]
METRES = {"in": mpf("0.0254"), "mm": mpf("0.001"), "deg": None}


def _si(text):
    """The exact SI value (50 digits) of a batch quantity string."""
    if not isinstance(text, str):
        return mpf(text)
    number, unit = text.split()
    value = mpf(number)
    return value * mp.pi / 180 if unit == "deg" else value * METRES[unit]


@pytest.mark.parametrize("mech, geo", BATCH, ids=[m for m, _ in BATCH])
def test_batch_near_limits_with_the_reference_check_rules(mech, geo):
    """Cases as the reference check sends them (strings in inches, mm, deg,
    rpm), a delta away from a limit, compared by its rules at 1e-5 with both
    assemblies offered (the other one first); refusing is allowed only
    within 1e-4 rad."""
    with mp.workdps(ref.mechanisms.DPS):
        g = {k: _si(v) for k, v in geo.items()}
        theta1 = g.pop("theta1", mpf(0))
        limits = limit_angles(mech, g)
        cases, expected = [], []
        for label, t_star, side in limits[:2]:
            for delta in (1e-2, 1e-3, 1e-4, 3e-5, 1e-6, 1e-8, 1e-10, 1e-12):
                for circuit in ("open", "crossed"):
                    theta2 = repr(float(mp.degrees(t_star + side * mpf(delta) + theta1)))
                    case = dict(
                        geo,
                        mechanism=mech,
                        theta2=f"{theta2} deg",
                        omega2="300 rpm",
                        alpha2="-2000 deg/s^2",
                        jerk2="400 rad/s^3",
                        circuit=circuit,
                    )
                    motion = (
                        _si(f"{theta2} deg"),
                        mpf(300) * 2 * mp.pi / 60,
                        mpf(-2000) * mp.pi / 180,
                        mpf(400),
                        theta1,
                    )
                    other = "crossed" if circuit == "open" else "open"
                    branches = [ref.batch_branch(mech, g, *motion, c) for c in (other, circuit)]
                    cases.append(case)
                    expected.append(
                        (
                            f"{label} {circuit} {delta:.0e}",
                            delta,
                            [b for b in branches if b is not None],
                        )
                    )
    results = solve_cases(cases)
    answered = 0
    for (name, delta, branches), res in zip(expected, results):
        if res.get("ok") is False and res.get("error") == "singular":
            assert delta <= MUST_ANSWER, f"{name}: refused"
            assert "limit position" in res["message"]
            continue
        why = check.compare_to_branches(mech, res, branches, 1e-5)
        assert not why, f"{name}: {why}"
        answered += 1
    assert answered >= len(cases) // 2


# ------------------------------------------------------------ the crank pin over the pivot
#: a = d: A passes over O4 at theta2 = theta1, where link 4's direction is 0/0. With c = 0 the
#: slide line through O4 and A turns at omega2 / 2 exactly (an inscribed angle); in the fourbar
#: b = c as well (a kite), links 3 and 4 folded there
OVER_THE_PIVOT = {
    "invertedslidercrank": {"a": 1.0, "c": 0.0, "d": 1.0, "gamma": math.pi / 2},
    "fourbar": {"a": 1.0, "b": 2.0, "c": 2.0, "d": 1.0},
    # the geared fivebar's crank pins A and C meet at theta2 = 0 (b = c)
    "fivebar": {"a": 1.0, "b": 2.0, "c": 2.0, "d": 1.0, "f": 2.0, "lam": -2.0, "phi": math.pi},
}
UNITS = {"gamma": "rad", "phi": "rad", "lam": ""}


@pytest.mark.parametrize("mech", sorted(OVER_THE_PIVOT))
@pytest.mark.parametrize("theta1", [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 0.0])
def test_a_crank_pin_over_the_pivot_is_answered_right_or_refused(theta1, mech):
    """Each derivative divides by a length no larger than |A - O4| once more, so its
    round-off grows like (span / |A - O4|)^n whether or not the output grows: with A 1e-5 m
    from O4 jerk4 came out -2.5e3 rad/s^3 for 0 and was answered as right. Now it is right
    (within the near-limit rule, 1e-5, against the 50-digit reference) or refused with the
    distance and how far to move."""
    geo = OVER_THE_PIVOT[mech]
    case = {"mechanism": mech, **{k: f"{v!r} {UNITS.get(k, 'm')}" for k, v in geo.items()}}
    case.update(theta1=f"{theta1!r} rad", theta2="0 rad", omega2="1 rad/s", alpha2="0 rad/s^2")
    if mech == "fivebar":  # A and C meet at theta2 = 0: approach them by theta2
        case.update(theta1="0 rad", theta2=f"{theta1!r} rad")
        theta2, theta1 = theta1, 0.0
    else:
        theta2 = 0.0
    (r,) = solve_cases([case])
    if not r["ok"]:
        assert r["error"] == "singular", r
        assert max(theta1, theta2) <= 1e-3, f"refused so far from the pivot: {r['message']}"
        if mech == "fivebar":
            assert "crank pins A and C come within" in r["message"], r
            assert "until A and C are at least" in r["message"], r
        else:
            assert "from the pivot O4" in r["message"] and "rad from theta1" in r["message"], r
        return
    want = ref.solve(mech, geo, theta2, 1.0, 0.0, 0.0, theta1, "open")
    for name in ("omega4", "alpha4", "jerk4"):
        scale = max(abs(float(want[name])), 1.0)
        assert abs(r[name] - float(want[name])) < 1e-5 * scale, (name, r[name], want[name])
