"""accelab.solver.vectorloops.linkage (VectorLoopLinkage, LoopResult): the closed-form mechanisms
written as loops give the closed forms' answers; one position and its errors."""

import numpy as np
import pytest
from _vectorloops_helpers import ANGLES, MOTION, close, sweep

from accelab.solver import Q_, FourBar, GearedFiveBar, InvertedSliderCrank, SliderCrank
from accelab.solver.errors import NoConvergence, NotAssemblable
from accelab.solver.vectorloops import VectorLoopLinkage
from accelab.solver.vectorloops import solve_loops_case as solve_case
from accelab.solver.vectorloops.examples import EXAMPLES


def test_fourbar_as_loops_matches_closed_form():
    loops = sweep("fourbar")
    closed = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2=ANGLES,
        omega2="10 rad/s",
        alpha2="-5 rad/s^2",
        jerk2="40 rad/s^3",
        p="3 in",
        delta3="40 deg",
    )
    assert loops.valid.all() and closed.valid.all()
    for k, n in (
        ("omega", "3"),
        ("alpha", "3"),
        ("jerk", "3"),
        ("omega", "4"),
        ("alpha", "4"),
        ("jerk", "4"),
    ):
        assert close(getattr(loops.vectors["R" + n], k).m, getattr(closed, k + n).m)
    assert close(np.exp(1j * loops.vectors["R4"].angle.m), np.exp(1j * closed.theta4.m))
    for v in "RVAJ":
        assert close(getattr(loops.points["P"], v).m, getattr(closed, v + "_P").m)
        assert close(getattr(loops.points["B"], v).m, getattr(closed, v + "_B").m)


def test_slidercrank_as_loops_matches_closed_form():
    loops = sweep("slidercrank")
    closed = SliderCrank(a="40 mm", b="120 mm", c="10 mm").solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3"
    )
    s = loops.vectors["R1"]
    for k, c in (
        ("length", "d"),
        ("length_dot", "d_dot"),
        ("length_ddot", "d_ddot"),
        ("length_dddot", "d_dddot"),
    ):
        assert close(getattr(s, k).m, getattr(closed, c).m)
    for k in ("omega", "alpha", "jerk"):
        assert close(getattr(loops.vectors["R3"], k).m, getattr(closed, k + "3").m)
    assert close(loops.points["B"].A.m, closed.A_B.m)


def test_inverted_slidercrank_as_loops_matches_closed_form():
    loops = sweep("invertedslidercrank")
    closed = InvertedSliderCrank(a="4 in", c="3 in", d="8 in", gamma="90 deg").solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3"
    )
    b = loops.vectors["R3"]
    for k, c in (
        ("length", "b"),
        ("length_dot", "b_dot"),
        ("length_ddot", "b_ddot"),
        ("length_dddot", "b_dddot"),
    ):
        assert close(getattr(b, k).m, getattr(closed, c).m)
    for k in ("omega", "alpha", "jerk"):
        assert close(getattr(loops.vectors["R4"], k).m, getattr(closed, k + "4").m)
    assert close(loops.points["B"].A.m, closed.A_B.m)


def test_geared_fivebar_as_loops_matches_closed_form():
    loops = sweep("fivebar")
    closed = GearedFiveBar(
        a="1 in", b="4 in", c="4 in", d="1 in", f="3 in", lam=-2, phi="30 deg"
    ).solve(theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3")
    assert closed.valid.all()
    for n in "34":
        for k in ("omega", "alpha", "jerk"):
            assert close(getattr(loops.vectors["R" + n], k).m, getattr(closed, k + n).m)
    for v in "AJ":
        assert close(getattr(loops.points["B"], v).m, getattr(closed, v + "_B").m)
        assert close(getattr(loops.points["C"], v).m, getattr(closed, v + "_C").m)


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
    desc = EXAMPLES["fourbar"](
        a="4 m", b="3 m", c="2 m", d="5 m", guess3="-40 deg", guess4="140 deg"
    )
    res = solve_case(
        dict(
            desc,
            mechanism="loops",
            theta2=f"{t_lim - 1e-9} deg",
            omega2="1 rad/s",
            alpha2="0 rad/s^2",
        )
    )
    assert res["ok"] is False and res["error"] in ("singular", "not_assemblable"), res
    res = solve_case(
        dict(
            desc,
            mechanism="loops",
            theta2=f"{t_lim - 1e-3} deg",
            omega2="1 rad/s",
            alpha2="0 rad/s^2",
        )
    )
    assert res["ok"], res


def test_unit_aware_scalar_result():
    r = VectorLoopLinkage(**EXAMPLES["sixbar_slider"]()).solve(**MOTION)
    assert r.valid and r.iterations >= 1
    assert r.vectors["S"].length_ddot.units == Q_(1, "m/s^2").units
    assert r.points["D"].A.check("[length]/[time]**2")


def test_scalar_and_one_element_sweep_agree():
    linkage = VectorLoopLinkage(**EXAMPLES["watt2_sixbar"]())
    one = linkage.solve(theta2="57 deg", omega2="12 rad/s", alpha2="-30 rad/s^2")
    arr = linkage.solve(theta2=Q_([57.0], "deg"), omega2="12 rad/s", alpha2="-30 rad/s^2")
    assert one.valid and arr.valid.shape == (1,)
    for v in ("R3", "R5", "R6"):
        assert one.vectors[v].alpha.m == pytest.approx(arr.vectors[v].alpha.m[0], rel=1e-13)
