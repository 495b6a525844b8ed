"""The general vector-loop solver (section 7.8): against the closed forms,
against an independent mpmath solution of the loop equations, its errors,
and its sweeps."""

import json

import mpmath as mp
import numpy as np
import pytest

from solver import FourBar, GearedFiveBar, InvertedSliderCrank, Q_, SliderCrank
from solver.batch import solve_case as batch_solve
from solver.errors import InvalidInput, NoConvergence, NotAssemblable
from solver.vectorloops import VectorLoopLinkage, solve_loops_case as solve_case
from solver.vectorloops.description import read_description
from solver.vectorloops.examples import EXAMPLES

MOTION = dict(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3")
ANGLES = Q_(np.linspace(0, 350, 36), "deg")


def close(x, y, rtol=1e-12):
    x, y = np.asarray(x), np.asarray(y)
    scale = np.max(np.abs(y))
    return np.max(np.abs(x - y)) <= rtol * scale


def sweep(name, **kw):
    return VectorLoopLinkage(**EXAMPLES[name](**kw)).solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3")


def test_fourbar_as_loops_matches_closed_form():
    loops = sweep("fourbar")
    closed = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3",
        p="3 in", delta3="40 deg")
    assert loops.valid.all() and closed.valid.all()
    for k, n in (("omega", "3"), ("alpha", "3"), ("jerk", "3"), ("omega", "4"), ("alpha", "4"),
                 ("jerk", "4")):
        assert close(getattr(loops.vectors["R" + n], k).m, getattr(closed, k + n).m)
    assert close(np.exp(1j * loops.vectors["R4"].angle.m), np.exp(1j * closed.theta4.m))
    for v in "RVAJ":
        assert close(getattr(loops.points["P"], v).m, getattr(closed, v + "_P").m)
        assert close(getattr(loops.points["B"], v).m, getattr(closed, v + "_B").m)


def test_slidercrank_as_loops_matches_closed_form():
    loops = sweep("slidercrank")
    closed = SliderCrank(a="40 mm", b="120 mm", c="10 mm").solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3")
    s = loops.vectors["R1"]
    for k, c in (("length", "d"), ("length_dot", "d_dot"), ("length_ddot", "d_ddot"),
                 ("length_dddot", "d_dddot")):
        assert close(getattr(s, k).m, getattr(closed, c).m)
    for k in ("omega", "alpha", "jerk"):
        assert close(getattr(loops.vectors["R3"], k).m, getattr(closed, k + "3").m)
    assert close(loops.points["B"].A.m, closed.A_B.m)


def test_inverted_slidercrank_as_loops_matches_closed_form():
    loops = sweep("invertedslidercrank")
    closed = InvertedSliderCrank(a="4 in", c="3 in", d="8 in", gamma="90 deg").solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3")
    b = loops.vectors["R3"]
    for k, c in (("length", "b"), ("length_dot", "b_dot"), ("length_ddot", "b_ddot"),
                 ("length_dddot", "b_dddot")):
        assert close(getattr(b, k).m, getattr(closed, c).m)
    for k in ("omega", "alpha", "jerk"):
        assert close(getattr(loops.vectors["R4"], k).m, getattr(closed, k + "4").m)
    assert close(loops.points["B"].A.m, closed.A_B.m)


def test_geared_fivebar_as_loops_matches_closed_form():
    loops = sweep("fivebar")
    closed = GearedFiveBar(a="1 in", b="4 in", c="4 in", d="1 in", f="3 in", lam=-2,
                           phi="30 deg").solve(theta2=ANGLES, omega2="10 rad/s",
                                               alpha2="-5 rad/s^2", jerk2="40 rad/s^3")
    assert closed.valid.all()
    for n in "34":
        for k in ("omega", "alpha", "jerk"):
            assert close(getattr(loops.vectors["R" + n], k).m, getattr(closed, k + n).m)
    for v in "AJ":
        assert close(getattr(loops.points["B"], v).m, getattr(closed, v + "_B").m)
        assert close(getattr(loops.points["C"], v).m, getattr(closed, v + "_C").m)


def _mp_positions(case, t2):
    """Independent: solve the loop equations with mpmath.findroot (its own
    Jacobian by finite differences), from the float solution as the start."""
    model = read_description(case)
    names = model.names

    def vectors(q, theta2):
        q = [mp.re(x) for x in q]
        out = []
        for v in range(len(names)):
            L = q[model.length_unknown[v]] if model.length_unknown[v] >= 0 else mp.mpf(model.length[v])
            base = theta2 if model.angle_input[v] else (
                q[model.angle_unknown[v]] if model.angle_unknown[v] >= 0 else 0)
            th = mp.mpf(model.angle_ratio[v]) * base + mp.mpf(model.angle_offset[v])
            out.append(L * mp.mpc(mp.cos(th), mp.sin(th)))
        return out

    def equations(theta2):
        def f(*q):
            z = vectors(q, theta2)
            res = []
            for row in model.signs:
                s = mp.fsum(int(k) * zv for k, zv in zip(row, z) if k)
                res += [mp.re(s), mp.im(s)]
            return res
        return f

    def points(theta2, start):
        q = mp.findroot(equations(theta2), start, tol=mp.mpf(10) ** (-2 * mp.mp.dps + 10))
        q = [q[i] for i in range(len(start))] if len(start) > 1 else [q]
        z = vectors(q, theta2)
        return [mp.fsum(int(k) * zv for k, zv in zip(row, z) if k) for row in model.point_signs], q

    return points, model


@pytest.mark.parametrize("name", ["sixbar_slider", "watt2_sixbar"])
def test_sixbar_against_mpmath_differentiation(name):
    """Position to jerk of every point of a sixbar, against mpmath: Newton at 40
    digits on the loop equations alone, then derivatives by numerical
    differentiation along theta2(t) = t0 + w t + a t^2/2 + j t^3/6."""
    case = dict(EXAMPLES[name](), mechanism="loops", theta2="57 deg", omega2="12 rad/s",
                alpha2="-30 rad/s^2", jerk2="500 rad/s^3")
    res = solve_case(case)
    assert res["ok"], res
    mp.mp.dps = 40
    points, model = _mp_positions(case, None)
    t0, w, a, j = mp.radians(57), mp.mpf(12), mp.mpf(-30), mp.mpf(500)
    # start from the float solution
    q0 = []
    for u in model.unknown_names:
        vname, what = u.split(".")
        q0.append(mp.mpf(res["vectors"][vname]["length" if what == "length" else "angle"]))
    state = {"q": q0}

    def point(k):
        def f(t):
            pts, q = points(t0 + w * t + a * t * t / 2 + j * t ** 3 / 6, state["q"])
            return pts[k]
        return f

    for k, pname in enumerate(model.point_names):
        f = point(k)
        derivs = [f(mp.mpf(0))] + [mp.diff(f, mp.mpf(0), n, h=mp.mpf(10) ** -8) for n in (1, 2, 3)]
        for n, key in enumerate("RVAJ"):
            ref = complex(derivs[n])
            got = complex(*res["points"][pname][key])
            scale = max(abs(ref), 1e-3)
            assert abs(got - ref) <= 1e-11 * scale, (pname, key, got, ref)
    mp.mp.dps = 15


def test_batch_dispatches_loops_and_reports_every_vector():
    case = dict(EXAMPLES["sixbar_slider"](), mechanism="loops", **MOTION)
    res = batch_solve(case)
    assert res["ok"] and res["iterations"] >= 1
    assert set(res["vectors"]) == set(case["vectors"])
    assert {"length", "length_dot", "length_ddot", "length_dddot"} <= set(res["vectors"]["S"])
    assert set(res["points"]["D"]) == {"R", "V", "A", "J"}
    assert res["points"]["D"]["A"][1] == pytest.approx(0, abs=1e-9)   # D stays on its line
    json.dumps(res)


@pytest.mark.parametrize("change, words", [
    (lambda c: c["loops"].append("R2 + Q"), "unknown vector 'Q'"),
    (lambda c: c["loops"].pop(), "add or remove loops"),
    (lambda c: c["vectors"]["R3"].pop("guess"), "needs a guess"),
    (lambda c: c["vectors"]["R5"].update(angle={"follow": "R6", "offset": "0 deg"}) or
     c["vectors"]["R6"].update(angle={"follow": "R5"}), "loops back on itself"),
    (lambda c: c["vectors"]["R4C"].update(angle={"follow": "nope"}), "not a vector"),
    (lambda c: c["vectors"]["R2"].update(length="2 s"), "must be a length"),
    (lambda c: c["vectors"]["R2"].update(angle="0 deg"), "driven by the input"),
    (lambda c: c.update(colour="red"), "unknown key"),
    (lambda c: c["points"].update(E="R2 +"), "cannot read"),
])
def test_malformed_descriptions(change, words):
    case = dict(EXAMPLES["watt2_sixbar"](), mechanism="loops", **MOTION)
    case = json.loads(json.dumps(case))
    change(case)
    res = solve_case(case)
    assert res["ok"] is False and res["error"] == "invalid_input", res
    assert words in res["message"]


def test_not_assemblable_reports_residual():
    desc = EXAMPLES["fourbar"](d="17 in")
    res = solve_case(dict(desc, mechanism="loops", **MOTION))
    assert res["error"] == "not_assemblable" and "residual" in res["message"]
    with pytest.raises(NoConvergence) as info:
        VectorLoopLinkage(**desc).solve(theta2="30 deg", omega2="1 rad/s")
    assert info.value.residual > 1e-3
    assert isinstance(info.value, NotAssemblable)


def test_singular_jacobian_reported():
    # fourbar at its limit: s = b + c  (a=4, b=3, c=2, d=5)
    t_lim = np.degrees(np.arccos((16 + 25 - 25) / 40))
    desc = EXAMPLES["fourbar"](a="4 m", b="3 m", c="2 m", d="5 m", guess3="-40 deg",
                               guess4="140 deg")
    res = solve_case(dict(desc, mechanism="loops", theta2=f"{t_lim - 1e-9} deg",
                          omega2="1 rad/s", alpha2="0 rad/s^2"))
    assert res["ok"] is False and res["error"] in ("singular", "not_assemblable"), res
    res = solve_case(dict(desc, mechanism="loops", theta2=f"{t_lim - 1e-3} deg",
                          omega2="1 rad/s", alpha2="0 rad/s^2"))
    assert res["ok"], res


def test_sweep_follows_one_assembly_and_masks():
    # crossed-circuit guesses stay crossed over the whole cycle
    desc = EXAMPLES["fourbar"](guess3="-60 deg", guess4="-100 deg")
    r = VectorLoopLinkage(**desc).solve(theta2=Q_(np.linspace(0, 720, 721), "deg"),
                                        omega2="1 rad/s")
    closed = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2=Q_(np.linspace(0, 720, 721), "deg"), omega2="1 rad/s", circuit="crossed")
    assert r.valid.all()
    assert close(np.exp(1j * r.vectors["R4"].angle.m), np.exp(1j * closed.theta4.m))
    # a non-Grashof linkage: mask where it cannot reach, never a jump
    desc = EXAMPLES["fourbar"](a="5 in", b="3 in", c="4 in", d="6 in", guess3="100 deg",
                               guess4="60 deg")
    r = VectorLoopLinkage(**desc).solve(theta2=Q_(np.linspace(0, 70, 71), "deg"),
                                        omega2="1 rad/s")
    fb = FourBar(a="5 in", b="3 in", c="4 in", d="6 in")
    ok = r.valid
    assert ok.sum() > 10
    for circuit in ("open", "crossed"):
        c = fb.solve(theta2=Q_(np.linspace(0, 70, 71), "deg")[ok], omega2="1 rad/s",
                     circuit=circuit)
        if close(np.exp(1j * r.vectors["R4"].angle.m[ok]), np.exp(1j * c.theta4.m), 1e-9):
            break
    else:
        pytest.fail("the sweep matches neither assembly throughout")


def test_unit_aware_scalar_result():
    r = VectorLoopLinkage(**EXAMPLES["sixbar_slider"]()).solve(**MOTION)
    assert r.valid and r.iterations >= 1
    assert r.vectors["S"].length_ddot.units == Q_(1, "m/s^2").units
    assert r.points["D"].A.check("[length]/[time]**2")


def test_sixbar_cycle_iteration_counts():
    r = sweep("watt2_sixbar")
    assert r.valid.all()
    assert r.iterations.max() <= 8
    assert np.median(r.iterations) <= 3
