"""Accuracy of the closed forms against an independent 50-digit computation.

The reference (benchmarks/reference) solves each mechanism's vector loops in
mpmath, from its position by plain geometry, and differentiates the loops at
50 digits, so it shares neither formulas nor round-off with the kernels (and
is itself checked against numerical differentiation of the geometric position,
tests/test_benchmarks_reference.py).
At well-conditioned positions every output (angles, omega, alpha, jerk, the
sliders' d .. d_dddot and b .. b_dddot, points' R V A J, A_BA, the Coriolis
term, link 5 of the fivebar, points anywhere on any link) must agree to 1e-12
relative, on both circuits, with a rotated ground (theta1 != 0) and nonzero
input jerk, over hypothesis-drawn geometries (strategies in conftest.py) and
fixed cases. The loop-closure tests put each order's outputs back into the
differentiated loop equation written here with complex numbers.

The last tests run the batch solver on worked reference cases copied from
the project's shared reference set (tests/data/README.md).
"""

import cmath
import json
import math
from pathlib import Path

import _checks as check
import numpy as np
import pytest
from conftest import (
    examples,
    fivebars,
    fourbars,
    invertedslidercranks,
    points_on_links,
    slidercranks,
)
from hypothesis import example, given, settings
from hypothesis import strategies as st

import accelab.benchmarks.reference as ref
from accelab.solver.kernels import (
    OK,
    fivebar,
    fourbar,
    invertedslidercrank,
    points,
    rotation,
    slidercrank,
)

RTOL = 1e-12
#: below this fraction of the largest output of the same order and kind, an
#: output is compared to 1e-2 of that scale instead of to itself (alpha4 = 0 by
#: symmetry, omega4 = 0 at a rocker's extreme position): its round-off is a
#: few eps of the terms that cancel in it, not of itself
FLOOR = 1e-2
MOTION = ("theta2", "omega2", "alpha2", "jerk2", "theta1")
BASES = {
    "fourbar": {2: "O2", 3: "A", 4: "O4"},
    "invertedslidercrank": {2: "O2", 3: "A", 4: "O4"},
    "fivebar": {2: "O2", 3: "A", 4: "C", 5: "O5"},
    "slidercrank": {2: "O2", 3: "A"},
}
#: the outputs every kernel must report, and which of them each one has
ANGULAR = {"fourbar": "34", "slidercrank": "3", "invertedslidercrank": "34", "fivebar": "345"}
SLIDER = {"slidercrank": "d", "invertedslidercrank": "b"}


def run_kernel(mech, case, circuit):
    geo, mo = split(mech, case)
    args = (mo["theta2"], mo["omega2"], mo["alpha2"], mo["jerk2"], mo["theta1"], circuit)
    if mech == "fourbar":
        return fourbar.solve(geo["a"], geo["b"], geo["c"], geo["d"], *args)
    if mech == "slidercrank":
        return slidercrank.solve(geo["a"], geo["b"], geo["c"], *args)
    if mech == "invertedslidercrank":
        return invertedslidercrank.solve(geo["a"], geo["c"], geo["d"], geo["gamma"], *args)
    return fivebar.solve(
        geo["a"], geo["b"], geo["c"], geo["d"], geo["f"], geo["lam"], geo["phi"], *args
    )


def split(mech, case):
    geo = {k: v for k, v in case.items() if k not in MOTION}
    return geo, {k: case[k] for k in MOTION}


def vectors(L, m, k, offset=0.0):
    """R V A J of the vector L e^{j(theta_k + offset)} with the kernel's point helpers."""
    th, w, al, j = (getattr(m, n + k) for n in ("theta", "omega", "alpha", "jerk"))
    return (
        points.relative_position(L, th, offset),
        points.relative_velocity(L, th, w, offset),
        points.relative_acceleration(L, th, w, al, offset),
        points.relative_jerk(L, th, w, al, j, offset),
    )


def kernel_outputs(mech, case, m, extra=()):
    """Every output of the kernel Motion ``m``, with point vectors built from it
    by accelab.solver.kernels.points: R_X, V_X, A_X, J_X, A_BA and the extra points."""
    geo, mo = split(mech, case)
    out = {}
    for k in ANGULAR[mech]:
        for n in ("theta", "omega", "alpha", "jerk"):
            out[n + k] = float(getattr(m, n + k))
    if mech in SLIDER:
        x = SLIDER[mech]
        for suffix in ("", "_dot", "_ddot", "_dddot"):
            out[x + suffix] = float(getattr(m, x + suffix))
    e1 = cmath.exp(1j * mo["theta1"])
    zero = (0j, 0j, 0j, 0j)
    pts = {"O2": zero}
    pts["A"] = vectors(geo["a"], m, "2")
    if mech in ("fourbar", "invertedslidercrank"):
        pts["O4"] = (geo["d"] * e1, 0j, 0j, 0j)
        pts["B"] = tuple(p + q for p, q in zip(pts["O4"], vectors(geo["c"], m, "4")))
    elif mech == "fivebar":
        pts["O5"] = (geo["f"] * e1, 0j, 0j, 0j)
        pts["C"] = tuple(p + q for p, q in zip(pts["O5"], vectors(geo["d"], m, "5")))
        pts["B"] = tuple(p + q for p, q in zip(pts["A"], vectors(geo["b"], m, "3")))
    else:
        pts["B"] = ((m.d + 1j * geo["c"]) * e1, m.d_dot * e1, m.d_ddot * e1, m.d_dddot * e1)
    if "p" in geo:
        pts["P"] = tuple(
            p + q for p, q in zip(pts["A"], vectors(geo["p"], m, "3", geo.get("delta3", 0.0)))
        )
    for name, link, p, delta in extra:
        base = pts[BASES[mech][link]]
        pts[name] = tuple(u + v for u, v in zip(base, vectors(p, m, str(link), delta)))
    for name, vecs in pts.items():
        if name.startswith("O"):
            continue
        for letter, v in zip("RVAJ", vecs):
            out[f"{letter}_{name}"] = complex(v)
    out["A_BA"] = out["A_B"] - out["A_A"]
    return out


def reference(mech, case, circuit, extra=()):
    geo, mo = split(mech, case)
    specs = [(name, link, BASES[mech][link], p, delta) for name, link, p, delta in extra]
    return ref.solve(
        mech,
        geo,
        mo["theta2"],
        mo["omega2"],
        mo["alpha2"],
        mo["jerk2"],
        mo["theta1"],
        circuit,
        specs,
    )


def point_terms(mech, want, extra):
    """The size of the terms each extra point's velocity, acceleration and jerk add up
    [SI]: its link's base point, then p omega; p alpha and p omega^2; p jerk, 3 p omega
    alpha and p omega^3 (eq. 7.40). A sum is no more accurate than its largest term allows:
    where the terms nearly cancel, the point's vector is small beside them and its error
    is judged against them (hypothesis found J_Q4 0.078 m/s^3 from terms of 0.92, off by
    2.4e-13 m/s^3: 3e-12 of itself, 3e-13 of its terms)."""
    out = {}
    for name, link, p, _delta in extra:
        base = BASES[mech][link]
        w, al, j = (float(abs(want[f"{n}{link}"])) for n in ("omega", "alpha", "jerk"))

        def size(x, base=base):  # the base point's vector (O2 is at rest)
            return float(abs(want[f"{x}_{base}"])) if f"{x}_{base}" in want else 0.0

        out[f"V_{name}"] = size("V") + p * w
        out[f"A_{name}"] = size("A") + p * (al + w * w)
        out[f"J_{name}"] = size("J") + p * (j + 3.0 * w * al + w**3)
    return out


def coupler_terms(want, geo):
    """The size of the terms from which omega3 .. jerk4 are worked out where links 3 and 4
    close a loop A + b e3 = C + c e4 (a fourbar: C is O4, at rest; a fivebar: C turns with
    link 5) [SI]: each order's known side K (A's and C's vectors, and links 3 and 4's terms
    of the lower orders: b omega3^2 ..., 3 b omega3 alpha3, b omega3^3 ...), as the sum of
    their sizes, over b sin(theta3 - theta4) for link 3 and c sin(theta3 - theta4) for link
    4: the projection of K on a link's normal is no more accurate than K's own terms allow.
    Where that projection nearly cancels, the output is small beside them and its error is
    judged against them. Hypothesis found a fivebar's jerk3 1.64 rad/s^3 from terms of 162,
    off by 4.6e-12 rad/s^3 (2.8e-12 of itself, 2.9e-14 of its terms; over 12 000 random
    fivebars the worst was 9.7e-14 of the terms), and a fourbar's alpha3 0.095 rad/s^2 from
    terms of 249, off by 1.2e-13 rad/s^2 (1.2e-12 of itself, 4.7e-16 of its terms)."""
    b, c = geo["b"], geo["c"]
    size = {k: float(abs(want[k])) for k in want if not k.startswith("theta")}
    sin34 = abs(math.sin(float(want["theta3"]) - float(want["theta4"])))
    w3, w4, a3, a4 = (size[k] for k in ("omega3", "omega4", "alpha3", "alpha4"))
    rest = dict.fromkeys(("V_C", "A_C", "J_C"), 0.0)  # a fourbar's O4
    size = {**rest, **size}
    known = {
        "omega": size["V_A"] + size["V_C"],
        "alpha": size["A_A"] + size["A_C"] + b * w3 * w3 + c * w4 * w4,
        "jerk": size["J_A"] + size["J_C"] + b * (3 * w3 * a3 + w3**3) + c * (3 * w4 * a4 + w4**3),
    }
    out = {}
    for name, k in known.items():
        out[name + "3"] = k / max(b * sin34, 1e-300)
        out[name + "4"] = k / max(c * sin34, 1e-300)
    return out


def slide_terms(want, geo):
    """The size of the terms from which an inverted slider-crank's omega4 .. jerk4 (and
    link 3's, the same) are worked out [SI]: each order's known side K_n of
    b^(n) e3 + j x (b e3 + c e4) = K_n (A's vector; the Coriolis term 2 b' omega; the
    lower orders' 3 b' omega^2, 3 b omega alpha, 3 b'' omega, 3 b' alpha, b omega^3; link
    4's c omega^2, c (omega^3 + 3 omega alpha)), as the sum of their sizes, over
    b + c cos gamma (eqs. 7.20-7.27). Where the projection cancels, the output is small
    beside them and its error is judged against them. Hypothesis found jerk4 -0.5 rad/s^3
    (a = d, c = 0: the block turns at omega2 / 2) from terms of 198, off by 1.9e-12 rad/s^3:
    3.8e-12 of itself, 9.6e-15 of its terms, the pivot's (span / b)^3 round-off (see the
    kernel's over_the_pivot); over 8000 random ones the worst was 2.0e-14 of the terms. The
    slide's b_dot .. b_dddot are Re(K_n conj e3) - x c sin gamma: judged against K_n's terms
    and x's (hypothesis found b_dddot -1.74 m/s^3 from terms of 4.4e4, off by 8.5e-12 m/s^3)."""
    c, gamma = geo["c"], geo["gamma"]
    size = {k: float(abs(want[k])) for k in want if not k.startswith("theta")}
    b, b1, b2 = size["b"], size["b_dot"], size["b_ddot"]
    w, al = size["omega4"], size["alpha4"]
    known = {
        "omega": size["V_A"],
        "alpha": size["A_A"] + b * w * w + 2 * b1 * w + c * w * w,
        "jerk": size["J_A"]
        + 3 * b1 * w * w
        + 3 * b * w * al
        + 3 * b2 * w
        + 3 * b1 * al
        + b * w**3
        + c * (w**3 + 3 * w * al),
    }
    den = max(abs(float(want["b"]) + c * math.cos(gamma)), 1e-300)
    out = {name + k: size_k / den for name, size_k in known.items() for k in "34"}
    # b^(n) = Re(K_n conj e3) - x c sin gamma: K_n's terms, and x's times c |sin gamma|
    lean = c * abs(math.sin(gamma)) / den
    for name, dots in (("omega", "_dot"), ("alpha", "_ddot"), ("jerk", "_dddot")):
        out["b" + dots] = known[name] * (1.0 + lean)
    return out


def assert_agree(got, want, rtol=RTOL, floor=FLOOR, expected=None, terms=None):
    """Every output of ``got`` agrees with ``want`` (see _checks.errors); an output named
    in ``terms`` (:func:`point_terms`) is judged against its terms where they are larger."""
    missing = set(expected or ()) - set(got)
    assert not missing, f"kernel did not report {sorted(missing)}"
    err = check.errors(got, want, floor)
    sizes = check.scales(want)
    for k, size in (terms or {}).items():
        if k in err:
            judged = max(float(abs(want[k])), floor * sizes.get(check._group(k), 0.0))
            err[k] *= judged / max(judged, size, 1e-30)
    assert set(err) >= set(expected or ()), "reference lacks outputs"
    bad = {k: f"{e:.1e}" for k, e in err.items() if not e <= rtol}
    assert not bad, f"outputs off (relative error): {bad}"
    return err


def expected_outputs(mech, extra=(), coupler=False):
    names = [n + k for k in ANGULAR[mech] for n in ("theta", "omega", "alpha", "jerk")]
    if mech in SLIDER:
        names += [SLIDER[mech] + s for s in ("", "_dot", "_ddot", "_dddot")]
    pts = ["A", "B"] + (["C"] if mech == "fivebar" else []) + (["P"] if coupler else [])
    pts += [e[0] for e in extra]
    return names + [f"{x}_{p}" for p in pts for x in "RVAJ"] + ["A_BA"]


# ------------------------------------------------------------ random geometries

circuits = st.sampled_from(["open", "crossed"])

#: alpha3 0.095 rad/s^2 of terms of 249 (d = 0.05, see coupler_terms); hypothesis found it
SMALL_ALPHA3 = {
    "a": 1.2477683047683652,
    "b": 0.36429800252880484,
    "c": 1.5601309585821281,
    "d": 0.05,
    "theta1": 2.7760303704096145,
    "theta2": -2.6839925337471326,
    "omega2": -3.0,
    "alpha2": 0.0,
    "jerk2": -1.0,
}
ON_EACH_LINK = [("Q2", 2, 1.0, 0.0), ("Q3", 3, 1.0, 0.0), ("Q4", 4, 1.0, 0.0)]


@given(
    case=fourbars(),
    circuit=circuits,
    extra=points_on_links([2, 3, 4]),
    p=st.floats(0.01, 2.0),
    delta3=st.floats(-math.pi, math.pi),
)
@example(case=SMALL_ALPHA3, circuit="open", extra=ON_EACH_LINK, p=1.0, delta3=0.0)
def test_fourbar_matches_reference(case, circuit, extra, p, delta3):
    case = dict(case, p=p, delta3=delta3)
    m = run_kernel("fourbar", case, circuit)
    assert m.status == OK
    want = reference("fourbar", case, circuit, extra)
    assert_agree(
        kernel_outputs("fourbar", case, m, extra),
        want,
        expected=expected_outputs("fourbar", extra, coupler=True),
        terms={**point_terms("fourbar", want, extra), **coupler_terms(want, case)},
    )


@given(case=slidercranks(), circuit=circuits, extra=points_on_links([2, 3]))
def test_slidercrank_matches_reference(case, circuit, extra):
    m = run_kernel("slidercrank", case, circuit)
    assert m.status == OK
    want = reference("slidercrank", case, circuit, extra)
    assert_agree(
        kernel_outputs("slidercrank", case, m, extra),
        want,
        expected=expected_outputs("slidercrank", extra),
        terms=point_terms("slidercrank", want, extra),
    )


#: a = d, the slider on the line through O4 and the crank at rest: alpha4 = 0 exactly, from
#: terms of size a omega2^2 / b that cancel (b = 0.22 a); hypothesis found it
ISOSCELES = {
    "a": 0.0546875,
    "c": 0.0,
    "d": 0.0546875,
    "gamma": 0.0,
    "theta1": 0.0,
    "theta2": 0.2265625,
    "omega2": -1.0,
    "alpha2": 0.0,
    "jerk2": -1.0,
}

#: a = d again: J_Q4 (0.078 m/s^3) is what is left of terms of 0.92; hypothesis found it
CANCELLING_J_Q4 = dict(
    ISOSCELES, a=1.0, d=1.0, theta1=1.1875, theta2=0.9375, omega2=-1.5, alpha2=0.0, jerk2=-1.0
)
#: a = d once more: jerk4 -0.5 rad/s^3 from terms of 198 (see slide_terms); hypothesis found it
HALF_JERK4 = dict(ISOSCELES, a=0.25, d=0.25, theta2=0.25, omega2=-3.0)
#: b_dddot -1.74 m/s^3 from terms of 4.4e4 (see slide_terms); hypothesis found it
SMALL_B_DDDOT = {
    "a": 1.75,
    "c": 1.6875 * abs(1.75 * cmath.exp(-3j) - 0.05),
    "d": 0.05,
    "gamma": 0.25268025514207865,
    "theta1": 3.0,
    "theta2": 0.0,
    "omega2": -17.5,
    "alpha2": 0.5,
    "jerk2": -4881.0,
}


@given(case=invertedslidercranks(), circuit=circuits, extra=points_on_links([2, 3, 4]))
@example(case=ISOSCELES, circuit="open", extra=[("Q2", 2, 1.0, 0.0), ("Q4", 4, 1.0, 0.0)])
@example(case=CANCELLING_J_Q4, circuit="open", extra=[("Q2", 2, 1.0, 0.0), ("Q4", 4, 1.0, 0.0)])
@example(case=HALF_JERK4, circuit="open", extra=ON_EACH_LINK)
@example(case=SMALL_B_DDDOT, circuit="crossed", extra=ON_EACH_LINK)
def test_invertedslidercrank_matches_reference(case, circuit, extra):
    m = run_kernel("invertedslidercrank", case, circuit)
    assert m.status == OK
    # the block turns with link 4
    assert m.omega3 == m.omega4 and m.alpha3 == m.alpha4 and m.jerk3 == m.jerk4
    want = reference("invertedslidercrank", case, circuit, extra)
    # omega4, alpha4 and jerk4 (eqs. 7.20-7.27) are sums of terms over b, the length O4A: an
    # output that cancels to zero carries the round-off of terms a/b times the group's scale
    ratio = max(1.0, case["a"] / max(float(abs(want["b"])), 1e-300))
    assert_agree(
        kernel_outputs("invertedslidercrank", case, m, extra),
        want,
        floor=FLOOR * ratio,
        expected=expected_outputs("invertedslidercrank", extra),
        terms={**point_terms("invertedslidercrank", want, extra), **slide_terms(want, case)},
    )


#: a jerk3 that is 1.64 rad/s^3 of terms of 162 (see coupler_terms); hypothesis found it
SMALL_JERK3 = {
    "a": 1.0859375,
    "b": 0.42414473096887334,
    "c": 0.6906723658998101,
    "d": 0.796875,
    "f": 0.0546875,
    "lam": 2.0,
    "phi": 1.0859375,
    "theta1": 3.141592653589793,
    "theta2": 1.921875,
    "omega2": -1.0,
    "alpha2": 0.0,
    "jerk2": -1.0,
}


@given(case=fivebars(), circuit=circuits, extra=points_on_links([2, 3, 4, 5]))
@example(case=SMALL_JERK3, circuit="open", extra=[("Q3", 3, 1.0, 0.0), ("Q5", 5, 1.0, 0.0)])
def test_fivebar_matches_reference(case, circuit, extra):
    m = run_kernel("fivebar", case, circuit)
    assert m.status == OK
    want = reference("fivebar", case, circuit, extra)
    assert_agree(
        kernel_outputs("fivebar", case, m, extra),
        want,
        expected=expected_outputs("fivebar", extra),
        terms={**point_terms("fivebar", want, extra), **coupler_terms(want, case)},
    )


# ------------------------------------------------------------ fixed cases

FIXED = [
    # the chapter's Example 7-1 proportions, rotated ground, input jerk
    ("fourbar", dict(a=2.0, b=6.0, c=9.0, d=7.0, p=3.1, delta3=0.5), 0.52, 10.0, -5.0, 30.0, 0.3),
    # Grashof crank-rocker near its rocker's extreme (omega4 near 0)
    ("fourbar", dict(a=0.04, b=0.12, c=0.09, d=0.1), 2.9, -300.0, 1e4, -2e5, -1.2),
    # non-Grashof: crank far from its limits
    ("fourbar", dict(a=4.0, b=3.0, c=2.0, d=5.0), 0.6, 7.0, -30.0, 100.0, 0.0),
    ("slidercrank", dict(a=0.04, b=0.12, c=0.01), 1.05, 314.159, 0.0, 0.0, 0.0),
    ("slidercrank", dict(a=0.3, b=0.2, c=-0.05), 0.6, -12.0, 40.0, 800.0, 0.9),
    ("invertedslidercrank", dict(a=0.1, c=0.24, d=0.16, gamma=-2.1), 2.6, 26.0, 380.0, -50.0, 0.2),
    ("invertedslidercrank", dict(a=0.1, c=0.0, d=0.25, gamma=0.0), -1.0, 5.0, 0.0, 0.0, 0.0),
    (
        "fivebar",
        dict(a=0.046, b=0.122, c=0.115, d=0.148, f=0.217, lam=-1.0, phi=-1.06),
        0.78,
        -9.5,
        335.0,
        1000.0,
        0.0,
    ),
    (
        "fivebar",
        dict(a=3.9, b=9.6, c=2.8, d=10.7, f=3.75, lam=-3.0, phi=0.845),
        0.9,
        -48.9,
        -222.0,
        0.0,
        -0.4,
    ),
]


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize("mech, geo, theta2, omega2, alpha2, jerk2, theta1", FIXED)
def test_fixed_cases_match_reference(mech, geo, theta2, omega2, alpha2, jerk2, theta1, circuit):
    case = dict(geo, theta2=theta2, omega2=omega2, alpha2=alpha2, jerk2=jerk2, theta1=theta1)
    m = run_kernel(mech, case, circuit)
    assert m.status == OK
    extra = [(f"Q{k}", k, 0.07, 0.4 * k) for k in BASES[mech]]
    assert_agree(
        kernel_outputs(mech, case, m, extra),
        reference(mech, case, circuit, extra),
        expected=expected_outputs(mech, extra, coupler="p" in geo),
    )


def test_open_circuit_is_the_chapter_minus_sign():
    """The reference's 'open' fourbar (B left of A->O4) is eq. 4.10b with the
    minus sign: theta4 = 2 atan((-B - sqrt(B^2 - 4AC)) / (2A))."""
    a, b, c, d = 2.0, 6.0, 9.0, 7.0
    k1, k2, k3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    for t2 in np.radians([10.0, 30.0, 100.0, 200.0, 300.0]):
        A = math.cos(t2) - k1 - k2 * math.cos(t2) + k3
        B = -2 * math.sin(t2)
        C = k1 - (k2 + 1) * math.cos(t2) + k3
        for circuit, sign in (("open", -1), ("crossed", 1)):
            t4 = 2 * math.atan((-B + sign * math.sqrt(B * B - 4 * A * C)) / (2 * A))
            want = ref.solve("fourbar", dict(a=a, b=b, c=c, d=d), t2, 1.0, circuit=circuit)
            assert check.angle_error(t4, want["theta4"]) < 1e-13
            assert (
                check.angle_error(
                    t4, fourbar.solve(a, b, c, d, t2, 1.0, circuit=circuit, order=0).theta4
                )
                < 1e-13
            )


def test_slidercrank_open_puts_the_slider_right_of_the_crank_pin():
    m = slidercrank.solve(0.04, 0.12, 0.01, np.radians(60.0), 1.0, circuit="open")
    assert m.d > 0.04 * math.cos(math.radians(60.0)) and math.cos(m.theta3) < 0


def test_kernels_take_arrays_as_scalars():
    """A sweep gives, position by position, exactly the scalar answers."""
    theta2 = np.linspace(-3.0, 3.0, 7)
    for mech, geo, _, omega2, alpha2, jerk2, theta1 in FIXED:
        sweep = run_kernel(
            mech,
            dict(geo, theta2=theta2, omega2=omega2, alpha2=alpha2, jerk2=jerk2, theta1=theta1),
            "open",
        )
        for i, t in enumerate(theta2):
            one = run_kernel(
                mech,
                dict(geo, theta2=t, omega2=omega2, alpha2=alpha2, jerk2=jerk2, theta1=theta1),
                "open",
            )
            assert one.status == sweep.status[i]
            for name in ("theta3", "omega3", "alpha3", "jerk3"):
                assert np.array_equal(getattr(one, name), getattr(sweep, name)[i], equal_nan=True)


# ------------------------------------------------------------ loop closure


def derivative(L, th, w, al, j, n, Ld=0.0, Ldd=0.0, Lddd=0.0):
    """n-th time derivative of L(t) e^{j theta(t)} and the magnitudes of its terms."""
    e = cmath.exp(1j * th)
    terms = [
        [L],
        [Ld, 1j * L * w],
        [Ldd, 2j * Ld * w, 1j * L * al, -L * w * w],
        [
            Lddd,
            3j * Ldd * w,
            3j * Ld * al,
            -3 * Ld * w * w,
            1j * L * j,
            -3 * L * w * al,
            -1j * L * w**3,
        ],
    ][n]
    return sum(terms) * e, sum(abs(t) for t in terms)


def loop_residuals(mech, case, m):
    """Relative residual of the loop equation and its first three derivatives."""
    geo, mo = split(mech, case)
    t1 = mo["theta1"]
    k = {n + "2": mo[n + "2"] for n in ("theta", "omega", "alpha", "jerk")}
    for name in ("theta", "omega", "alpha", "jerk"):
        for link in ANGULAR[mech]:
            k[name + link] = float(getattr(m, name + link))

    def link(L, i, n, sign=1.0, **lengths):
        return tuple(
            sign * x if idx == 0 else x
            for idx, x in enumerate(
                derivative(
                    L, k["theta" + i], k["omega" + i], k["alpha" + i], k["jerk" + i], n, **lengths
                )
            )
        )

    def fixed(L, angle, n):
        return (L * cmath.exp(1j * angle) if n == 0 else 0j, abs(L))

    out = []
    for n in range(4):
        if mech == "fourbar":  # a e2 + b e3 - c e4 - d e1 = 0
            parts = [
                link(geo["a"], "2", n),
                link(geo["b"], "3", n),
                link(geo["c"], "4", n, -1.0),
                fixed(-geo["d"], t1, n),
            ]
        elif mech == "fivebar":  # a e2 + b e3 - c e4 - d e5 - f e1 = 0
            parts = [
                link(geo["a"], "2", n),
                link(geo["b"], "3", n),
                link(geo["c"], "4", n, -1.0),
                link(geo["d"], "5", n, -1.0),
                fixed(-geo["f"], t1, n),
            ]
        elif mech == "slidercrank":  # a e2 - b e3 - c e4 - d(t) e1 = 0, theta4 = theta1 + 90 deg
            dd = [float(getattr(m, "d" + s)) for s in ("", "_dot", "_ddot", "_dddot")]
            parts = [
                link(geo["a"], "2", n),
                link(geo["b"], "3", n, -1.0),
                fixed(-geo["c"], t1 + math.pi / 2, n),
                (-dd[n] * cmath.exp(1j * t1), abs(dd[n])),
            ]
        else:  # a e2 - b(t) e3 - c e4 - d e1 = 0
            bb = [float(getattr(m, "b" + s)) for s in ("", "_dot", "_ddot", "_dddot")]
            parts = [
                link(geo["a"], "2", n),
                link(bb[0], "3", n, -1.0, Ld=bb[1], Ldd=bb[2], Lddd=bb[3]),
                link(geo["c"], "4", n, -1.0),
                fixed(-geo["d"], t1, n),
            ]
        residual = abs(sum(p[0] for p in parts))
        out.append(residual / sum(p[1] for p in parts))
    return out


@pytest.mark.parametrize(
    "mech, strategy",
    [
        ("fourbar", fourbars()),
        ("slidercrank", slidercranks()),
        ("invertedslidercrank", invertedslidercranks()),
        ("fivebar", fivebars()),
    ],
)
def test_loop_closure_at_every_order(mech, strategy):
    @settings(max_examples=examples(200))
    @given(case=strategy, circuit=circuits)
    def check(case, circuit):
        m = run_kernel(mech, case, circuit)
        assert m.status == OK
        residuals = loop_residuals(mech, case, m)
        assert max(residuals) < 1e-13, residuals

    check()


# ------------------------------------------------------------ rotation, slotted link


@given(
    p=st.floats(0.01, 2.0),
    theta=st.floats(-math.pi, math.pi),
    omega=st.floats(-60, 60),
    alpha=st.floats(-800, 800),
    jerk=st.floats(-2e4, 2e4),
)
def test_rotating_point_matches_reference(p, theta, omega, alpha, jerk):
    got = rotation.rotating_point(p, theta, omega, alpha, jerk)
    want = ref.rotating_point(p, theta, omega, alpha, jerk)
    assert_agree(
        {k: complex(getattr(got, k)) for k in ("R", "V", "A", "A_t", "A_n", "J")},
        want,
        expected=("R", "V", "A", "A_t", "A_n", "J"),
    )


@given(
    theta=st.floats(-math.pi, math.pi),
    omega=st.floats(-60, 60),
    alpha=st.floats(-800, 800),
    jerk=st.floats(-2e4, 2e4),
    p=st.floats(0.01, 2.0),
    p_dot=st.floats(-5, 5),
    p_ddot=st.floats(-100, 100),
    p_dddot=st.floats(-1e3, 1e3),
)
def test_slotted_link_matches_reference(theta, omega, alpha, jerk, p, p_dot, p_ddot, p_dddot):
    names = ("R", "V", "V_t", "V_slip", "A", "A_t", "A_n", "A_coriolis", "A_slip", "J")
    got = rotation.slotted_link(theta, omega, alpha, p, p_dot, p_ddot, p_dddot, jerk)
    want = ref.slotted_link(theta, omega, alpha, jerk, p, p_dot, p_ddot, p_dddot)
    assert_agree({k: complex(getattr(got, k)) for k in names}, want, expected=names)


# ------------------------------------------------------------ unit-aware outputs


@given(case=invertedslidercranks(), circuit=circuits)
def test_coriolis_slip_and_link4_point(case, circuit):
    """A_A = A_A4 + A_slip + A_coriolis (eq. 7.21), every part against the
    reference: A_A4 is the acceleration of the point of link 4 under A,
    differentiated as a point fixed to link 4; A_slip = b'' e3; the Coriolis
    term is what remains, 2 b' omega3 j e3 (eq. 7.21c)."""
    from accelab.solver import Q_, InvertedSliderCrank

    geo, mo = split("invertedslidercrank", case)
    first = reference("invertedslidercrank", case, circuit)
    # the point of link 4 under A: distance |A - O4| from O4 at its angle to link 4
    rel = complex(first["R_A"] - first["R_O4"]) * cmath.exp(-1j * float(first["theta4"]))
    extra = [("A4", 4, abs(rel), cmath.phase(rel))]
    want = reference("invertedslidercrank", case, circuit, extra)
    e3 = cmath.exp(1j * float(want["theta3"]))
    want["A_slip"] = want["b_ddot"] * e3
    want["V_slip"] = want["b_dot"] * e3
    want["A_coriolis"] = want["A_A"] - want["A_A4"] - want["A_slip"]
    mech = InvertedSliderCrank(
        a=Q_(geo["a"], "m"),
        c=Q_(geo["c"], "m"),
        d=Q_(geo["d"], "m"),
        gamma=Q_(geo["gamma"], "rad"),
        theta1=Q_(mo["theta1"], "rad"),
    )
    r = mech.solve(
        theta2=Q_(mo["theta2"], "rad"),
        omega2=Q_(mo["omega2"], "rad/s"),
        alpha2=Q_(mo["alpha2"], "rad/s^2"),
        jerk2=Q_(mo["jerk2"], "rad/s^3"),
        circuit=circuit,
    )
    names = ("A_A", "A_A4", "A_slip", "V_slip", "A_coriolis", "A_B", "A_BA")
    got = {k: complex(r.si(k)) for k in names}
    # the Coriolis term is compared to the largest acceleration in the linkage
    scale = max(abs(complex(want[k])) for k in ("A_A", "A_A4", "A_slip"))
    for k in names:
        err = abs(got[k] - complex(want[k])) / max(abs(complex(want[k])), FLOOR * scale)
        assert err < RTOL, (k, err)


@given(case=fourbars(), circuit=circuits, extra=points_on_links([2, 3, 4]))
def test_result_point_on_any_link(case, circuit, extra):
    """Result.point(link, p, delta) (eqs. 7.30-7.32, 7.41) and A_t, A_n about its base."""
    from accelab.solver import Q_, FourBar

    geo, mo = split("fourbar", case)
    fb = FourBar(**{k: Q_(v, "m") for k, v in geo.items()}, theta1=Q_(mo["theta1"], "rad"))
    r = fb.solve(
        theta2=Q_(mo["theta2"], "rad"),
        omega2=Q_(mo["omega2"], "rad/s"),
        alpha2=Q_(mo["alpha2"], "rad/s^2"),
        jerk2=Q_(mo["jerk2"], "rad/s^3"),
        circuit=circuit,
    )
    want = reference("fourbar", case, circuit, extra)
    got = {}
    for name, link, p, delta in extra:
        pm = r.point(link, Q_(p, "m"), Q_(delta, "rad"))
        for letter in "RVAJ":
            got[f"{letter}_{name}"] = complex(pm.si(letter))
        # tangential and normal parts of the acceleration about the base pin
        k = str(link)
        w, al = float(want["omega" + k]), float(want["alpha" + k])
        e = cmath.exp(1j * (float(want["theta" + k]) + delta))
        want[f"A_{name}_t"], want[f"A_{name}_n"] = 1j * p * al * e, -p * w * w * e
        got[f"A_{name}_t"], got[f"A_{name}_n"] = complex(pm.si("A_t")), complex(pm.si("A_n"))
    assert_agree(got, want, expected=list(got))


@given(case=fivebars(), circuit=circuits)
def test_fivebar_link5_through_the_unit_layer(case, circuit):
    from accelab.solver import Q_, GearedFiveBar

    geo, mo = split("fivebar", case)
    fb = GearedFiveBar(
        **{k: Q_(v, "m") for k, v in geo.items() if k not in ("lam", "phi")},
        lam=geo["lam"],
        phi=Q_(geo["phi"], "rad"),
        theta1=Q_(mo["theta1"], "rad"),
    )
    r = fb.solve(
        theta2=Q_(mo["theta2"], "rad"),
        omega2=Q_(mo["omega2"], "rad/s"),
        alpha2=Q_(mo["alpha2"], "rad/s^2"),
        jerk2=Q_(mo["jerk2"], "rad/s^3"),
        circuit=circuit,
    )
    names = ["theta5", "omega5", "alpha5", "jerk5", "R_C", "V_C", "A_C", "J_C", "A_B", "J_B"]
    got = {k: (complex(r.si(k)) if k[1] == "_" else float(r.si(k))) for k in names}
    assert_agree(got, reference("fivebar", case, circuit), expected=names)


# ------------------------------------------------------------ reference cases (batch)

DATA = Path(__file__).parent / "data" / "reference_cases.json"


def test_batch_matches_reference_cases():
    """accelab.solver.batch.solve_cases against the worked reference cases, with the
    reference check's rules: 1e-8 relative (vectors by the length of the
    difference, small outputs against 1e-3 of the largest of their order),
    angles modulo 2 pi, the branch chosen by the positions, expected errors
    by kind."""
    from accelab.solver.batch import solve_cases

    cases = json.loads(DATA.read_text())
    results = solve_cases([c["input"] for c in cases])
    assert len(results) == len(cases)
    for case, res in zip(cases, results):
        expect = case["expect"]
        if "error" in expect:
            assert res["ok"] is False and res["error"] == expect["error"] and res["message"], case[
                "id"
            ]
            continue
        assert res["ok"], (case["id"], res)
        why = check.compare_to_branches(
            case["input"]["mechanism"], res, expect["ok"], 1e-8, case["input"].get("circuit")
        )
        assert not why, f"{case['id']}: {why}"


def test_fast_quantities_behave_as_pint_built_ones():
    """accelab.solver.units.quantity assembles Quantities without pint's constructor;
    they must be indistinguishable from Q_(value, unit)."""
    from accelab.solver.units import Q_, SI_UNITS, quantity

    for value in (2.5, -1.5 + 0.5j, np.array([1.0, 2.0]), np.array([1j, 2.0])):
        fast, slow = quantity(value, "acceleration"), Q_(value, SI_UNITS["acceleration"])
        assert type(fast) is type(slow) and fast.units == slow.units
        assert str(fast) == str(slow) and repr(fast) == repr(slow)
        assert np.array_equal(fast.to("ft/s^2").m, slow.to("ft/s^2").m)
        assert np.array_equal((fast * Q_(2.0, "s")).to("m/s").m, (slow * Q_(2.0, "s")).m)
        assert f"{fast:.3g~P}" == f"{slow:.3g~P}"
