"""accelab.benchmarks.reference, the one high-precision reference of the tests and
the benchmark, checked by an independent route: mpmath's numerical
differentiation (at high precision, along the input's motion law) of
positions found without the reference's derivative solves -- the geometric
positions of the closed-form mechanisms, and the loops' own Newton-Raphson
positions of the benchmark's linkages."""

import mpmath as mp
import numpy as np
import pytest
from mpmath import mpf

import accelab.benchmarks.reference as ref
from accelab.benchmarks import accuracy
from accelab.benchmarks.cases import MOTION, all_cases
from accelab.benchmarks.reference import LoopReference, cached
from accelab.benchmarks.reference.mechanisms import ANGLE_NAMES, POSITIONS, SLIDER_SUFFIX, expj


@pytest.fixture(scope="module")
def cases():
    return all_cases()


@pytest.mark.parametrize(
    "name, theta2", [("fourbar-open", 0.7), ("invertedslidercrank", 2.0), ("sixbar-slider", 1.1)]
)
def test_reference_derivatives_match_mpmath_differentiation(cases, name, theta2):
    """The reference's derivative solves against mpmath's own numerical
    differentiation of its position solution (an independent route)."""
    case = cases[name]
    ref = LoopReference(case)
    guess = (
        ref.start(case.guess) if name.startswith("sixbar") else ref.start(case.kernel_guess(theta2))
    )
    if name.startswith("sixbar"):  # continue from the case's guesses to theta2
        values = ref.sweep(np.linspace(case.span[0], theta2, 12), case.guess)
        guess = [
            values[f"{v}.{'theta' if k == 'angle' else 'length'}"][-1] for v, k in ref.unknowns
        ]
    w, al, jk = MOTION["omega2"], MOTION["alpha2"], MOTION["jerk2"]
    with mp.workdps(40):
        q = ref.solve_one(guess, theta2, w, al, jk, strict=True)

        def position(t, k):
            return ref.solve_one([float(x) for x in q[0]], t, 0, 0, 0, strict=True)[0][k]

        for k in range(len(ref.unknowns)):
            d1, d2, d3 = (
                mp.diff(lambda t, k=k: position(t, k), mp.mpf(theta2), n) for n in (1, 2, 3)
            )
            expect = [d1 * w, d2 * w**2 + d1 * al, d3 * w**3 + 3 * d2 * w * al + d1 * jk]
            for n in range(3):
                assert abs(q[n + 1][k] - expect[n]) <= 1e-20 * (1 + abs(expect[n]))


def test_reference_agrees_with_closed_forms(cases):
    for name in ("fourbar-crossed", "slidercrank", "fivebar"):
        case = cases[name]
        t2 = case.theta2(12)
        ref = cached(case, t2)
        errs = accuracy.relative_errors(
            {k: getattr(case.kernel(t2), k) for k in case.outputs}, ref, accuracy.scales(ref)
        )
        assert np.nanmax(accuracy.worst(errs)) < 1e-13


def _law(theta2, omega2, alpha2, jerk2):
    th, w, al, j = (mpf(v) for v in (theta2, omega2, alpha2, jerk2))
    return lambda t: th + w * t + al * t * t / 2 + j * t**3 / 6


def _by_differentiation(mechanism, g, theta2, motion, theta1, circuit, points=()):
    """Every output of ``mechanism`` as mpmath.diff of its geometric position
    along theta2(t) (angles kept continuous near t = 0)."""
    law = _law(mpf(theta2) - mpf(theta1), *motion)
    rot = expj(mpf(theta1))
    sign = ref.CIRCUIT_SIGN[circuit]
    g = {k: mpf(v) for k, v in g.items()}
    first = POSITIONS[mechanism](g, law(mpf(0)), sign)
    near = {k: float(mp.arg(e * rot)) for k, e in first[0].items()}

    def state(t):
        angles, values, pts = POSITIONS[mechanism](g, law(t), sign)
        out = {"theta" + k: near[k] + mp.arg(e * rot * expj(-near[k])) for k, e in angles.items()}
        out.update(values)
        out.update({"R_" + k: z * rot for k, z in pts.items()})
        for name, link, base, p, delta in points:
            origin = 0 if base == "O2" else out["R_" + base]
            out["R_" + name] = origin + mpf(p) * angles[str(link)] * rot * expj(mpf(delta))
        return out

    result = {}
    for name, value in state(mpf(0)).items():
        result[name] = value
        for n in (1, 2, 3):
            d = mp.diff(lambda t, name=name: state(t)[name], mpf(0), n)
            if name.startswith("theta"):
                result[ANGLE_NAMES[n] + name[5:]] = d
            elif name.startswith("R_"):
                result["RVAJ"[n] + name[1:]] = d
            else:
                result[name + SLIDER_SUFFIX[n]] = d
    return result


CLOSED_FORMS = [
    (
        "fourbar",
        dict(a=0.05, b=0.15, c=0.23, d=0.18, p=0.07, delta3=0.6),
        0.5,
        "open",
        [("Q", 4, "O4", 0.1, -0.3)],
    ),
    ("fourbar", dict(a=0.05, b=0.15, c=0.23, d=0.18), 2.5, "crossed", []),
    ("slidercrank", dict(a=0.04, b=0.12, c=-0.01), 2.0, "open", [("Q", 3, "A", 0.05, 0.2)]),
    (
        "invertedslidercrank",
        dict(a=0.1, c=0.24, d=0.16, gamma=-2.1),
        2.4,
        "crossed",
        [("A4", 4, "O4", 0.2, 0.4)],
    ),
    (
        "fivebar",
        dict(a=0.0254, b=0.1016, c=0.1016, d=0.0254, f=0.0762, lam=-2.0, phi=0.52),
        0.7,
        "open",
        [("Q", 5, "O5", 0.05, 1.0)],
    ),
]


@pytest.mark.parametrize("mechanism, geometry, theta2, circuit, points", CLOSED_FORMS)
def test_closed_forms_by_loops_match_numerical_differentiation(
    mechanism, geometry, theta2, circuit, points
):
    """The reference's loop derivatives of every link, slider and point, with
    a turned ground and non-zero input jerk, against mpmath.diff of positions
    found by geometry alone (50 digits)."""
    motion = (12.0, -30.0, 400.0)
    with mp.workdps(50):
        want = _by_differentiation(mechanism, geometry, theta2, motion, 0.3, circuit, points)
        got = ref.solve(
            mechanism, geometry, theta2, *motion, theta1=0.3, circuit=circuit, extra_points=points
        )
        compared = 0
        for k, v in want.items():
            if k not in got or k.endswith("2") and k[:-1] in ANGLE_NAMES:
                continue
            diff = abs(got[k] - v)
            if k.startswith("theta"):
                diff = abs(mp.arg(expj(got[k] - v)))
            assert diff <= mpf(10) ** -30 * (1 + abs(v)), (k, got[k], v)
            compared += 1
        assert compared >= 16


def test_rotating_point_and_slotted_link_match_numerical_differentiation():
    with mp.workdps(50):
        law, dist = _law(0.4, 7.0, -3.0, 50.0), _law(0.2, 1.5, -0.5, 4.0)
        R = [mp.diff(lambda t: dist(t) * expj(law(t)), mpf(0), n) for n in range(4)]
        got = ref.slotted_link(0.4, 7.0, -3.0, 50.0, 0.2, 1.5, -0.5, 4.0)
        for n, key in enumerate("RVAJ"):
            assert abs(got[key] - R[n]) <= mpf(10) ** -30 * (1 + abs(R[n])), key
        fixed = [mp.diff(lambda t: mpf(0.2) * expj(law(t)), mpf(0), n) for n in range(4)]
        got = ref.rotating_point(0.2, 0.4, 7.0, -3.0, 50.0)
        for n, key in enumerate("RVAJ"):
            assert abs(got[key] - fixed[n]) <= mpf(10) ** -30 * (1 + abs(fixed[n])), key
        assert abs(got["A_t"] + got["A_n"] - got["A"]) <= mpf(10) ** -40
