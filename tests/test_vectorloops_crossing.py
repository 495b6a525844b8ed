"""accelab.solver.vectorloops.crossing: change points, where two assemblies meet at a
singular position. A fourbar with s + l = p + q (a, b, c, d = 2, 5, 4, 3 in: 2 + 5 =
4 + 3) reaches a configuration with every link on the x axis at theta2 = 0 (mod 360
deg), where its open and crossed assemblies touch (Chapter 4's change point; the
benchmark found a sweep there silently continuing on the crossed assembly). Past it
either assembly is possible. The sweep must stay on the assembly with its orientation
(the sign of det J, which is the closed form's circuit) and say so, flag sampled
singular positions, and never report the other assembly as if nothing happened."""

import numpy as np
import pytest
from _vectorloops_helpers import (
    CHANGE_POINT,
    KITE,
    PARALLELOGRAM,
    circuit_of,
    fourbar_in,
    rel_err,
    same_away_from_singular,
    system_of,
)

from accelab.solver import Q_
from accelab.solver.errors import NoConvergence
from accelab.solver.kernels import fourbar as fourbar_kernel
from accelab.solver.vectorloops import SINGULAR_CONDITION, VectorLoopLinkage
from accelab.solver.vectorloops.examples import EXAMPLES, fourbar
from accelab.solver.vectorloops.solve import solve


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize(
    "start_deg, step_deg, n",
    [
        (np.degrees(0.05), 1.0, 360),  # the benchmark's sweep: past 360 at 360.86, 361.86
        (5.0, 1.0, 720),  # two turns: samples exactly on 360 and 720 deg
        (5.0, 7.3, 99),  # coarse
        (5.0, 40.0, 18),  # very coarse: one step jumps across
        (30.0, -0.5, 121),  # backwards through 0
    ],
)
def test_sweep_through_a_change_point_keeps_its_assembly_and_says_so(
    circuit, start_deg, step_deg, n
):
    t2 = np.radians(start_deg + step_deg * np.arange(n))
    desc = fourbar_in(*CHANGE_POINT, t2[0], circuit)
    m = solve(system_of(desc), t2, 10.0, -5.0, 40.0)
    ok = m.status == 0
    assert circuit_of(m, CHANGE_POINT, t2, circuit)[ok].all()  # never the other one
    near = np.abs(np.angle(np.exp(1j * t2))) < 1e-9  # sampled on the point
    assert np.array_equal(~ok, near)  # those flagged, only those
    assert (m.status[near] == 2).all() and (m.condition[near] < SINGULAR_CONDITION).all()
    crossings = int(
        np.floor((t2.max()) / (2 * np.pi))
        - np.floor(t2.min() / (2 * np.pi))
        + (np.abs(np.angle(np.exp(1j * t2.min()))) < 1e-9)
    )
    assert len(m.notes) == crossings >= 1
    assert all("equally possible" in note for note in m.notes.values())
    assert "passes a singular position" in str(m.message)
    same_away_from_singular(m, solve(system_of(desc), t2, 10.0, -5.0, 40.0, batch=False))


def test_the_benchmark_change_point_sweep_agrees_with_the_open_circuit():
    """The case issue 3 reported: from theta2 = 0.05 rad, 360 positions 1 deg apart;
    at 360.86 and 361.86 deg the sweep had continued on the crossed assembly. Now
    both are on the open one (to the closed form's 1e-12), the crossing noted there.
    Accelerations agree to 1e-10 away from the change point; within a degree of it
    (condition measure below 0.05, 2e-3 at 0.14 deg) round-off grows like
    1/condition**2 in both solvers."""
    t2 = np.radians(np.degrees(0.05) + np.arange(360.0))
    r = VectorLoopLinkage(**fourbar_in(*CHANGE_POINT, t2[0], "open")).solve(
        theta2=Q_(np.degrees(t2), "deg"), omega2="10 rad/s", alpha2="-5 rad/s^2"
    )
    ref = fourbar_kernel.solve(*CHANGE_POINT, t2, 10.0, -5.0, circuit="open")
    assert r.valid.all()
    for v, key in (("R3", "theta3"), ("R4", "theta4")):
        d = np.angle(np.exp(1j * (r.vectors[v].angle.m_as("rad") - getattr(ref, key))))
        assert np.abs(d).max() < 1e-12
    alpha4 = r.vectors["R4"].alpha.m_as("rad/s^2")
    far = r.condition >= 0.05
    assert rel_err(alpha4[far], ref.alpha4[far]) < 1e-10
    assert rel_err(alpha4, ref.alpha4) < 1e-7
    assert list(r.notes) == [358]  # 360.86 deg: the first position past it
    assert "near theta2 = 360 deg" in r.notes[358] and "change point" in r.message


@pytest.mark.parametrize("linkage, zeros", [(CHANGE_POINT, [0]), (PARALLELOGRAM, [0, 180])])
def test_sweep_starting_on_a_change_point_flags_it_and_continues(linkage, zeros):
    """The guesses at the change point sit where both assemblies meet, so they choose
    neither: the first position is flagged singular, the rest solved on one assembly
    throughout (whichever Newton-Raphson reaches first), with a note saying so."""
    t2 = np.radians(np.arange(0.0, 360.0, 1.0))
    m = solve(system_of(fourbar_in(*linkage, 0.0, "open")), t2, 10.0)
    flagged = np.flatnonzero(m.status)
    assert list(np.degrees(t2[flagged]).round(9)) == zeros
    assert (m.status[flagged] == 2).all() and np.isnan(m.dth[0][flagged]).all()
    assert np.isfinite(m.q[0]).all()  # the position itself stands
    ok = m.status == 0
    on = [circuit_of(m, linkage, t2, c)[ok].all() for c in ("open", "crossed")]
    assert any(on)
    assert "starts on a singular position" in m.notes[1] and "starts on" in str(m.message)


def test_guesses_at_a_singular_configuration_still_choose_nothing():
    """At an input angle that is not singular, guesses that are (every link on the x
    axis) cannot pick an assembly: refused, not silently solved."""
    desc = fourbar(a="2 in", b="5 in", c="4 in", d="3 in", guess3="0 deg", guess4="0 deg")
    with pytest.raises(NoConvergence, match="singular configuration"):
        VectorLoopLinkage(**desc).solve(theta2="30 deg", omega2="1 rad/s")
    m = solve(system_of(desc), np.radians([30.0, 31.0, 32.0]), 1.0)
    assert (m.status == 1).all() and "singular configuration" in str(m.message)


def test_change_point_in_the_second_loop_of_a_sixbar():
    """The Watt II sixbar with its second fourbar (4, 8, 5, 9 in: 4 + 9 = 8 + 5)
    folded flat twice per crank turn: the sweep keeps that loop's circuit."""
    desc = EXAMPLES["watt2_sixbar"]()
    a, b, c, d = 4.0, 8.0, 5.0, 9.0
    t0 = np.radians(160.0)
    first = fourbar_kernel.solve(2.0, 6.0, 9.0, 7.0, t0, 1.0, circuit="open")
    # R4C's angle is theta4 + off; the second loop folds flat where that is 190 deg
    off = 190.0 - 138.2
    desc["vectors"]["R4C"] = {"length": "4 in", "angle": {"follow": "R4", "offset": f"{off} deg"}}
    desc["vectors"]["R6"]["length"] = "5 in"
    second = fourbar_kernel.solve(
        a, b, c, d, float(first.theta4) + np.radians(off - 10.0), 1.0, circuit="open"
    )
    for name, value in (
        ("R3", first.theta3),
        ("R4", first.theta4),
        ("R5", second.theta3 + np.radians(10.0)),
        ("R6", second.theta4 + np.radians(10.0)),
    ):
        desc["vectors"][name]["guess"] = f"{float(value)!r} rad"
    for step in (1.0, 13.0):
        t2 = t0 + np.radians(np.arange(0.0, 720.0, step))
        m = solve(system_of(desc), t2, 10.0)
        ref = fourbar_kernel.solve(
            a, b, c, d, m.theta[:, 4] - np.radians(10.0), 1.0, circuit="open"
        )
        assert (m.status == 0).all()
        assert np.allclose(
            np.exp(1j * m.theta[:, 6]), np.exp(1j * (ref.theta4 + np.radians(10.0))), atol=1e-9
        )
        assert len(m.notes) == 4  # two flat positions per turn, two turns


def test_assembly_lost_past_a_degenerate_change_point_is_flagged_not_returned():
    """A kite (a = d, b = c) at theta2 = 0 puts A on O4: the coupler and rocker
    coincide and may turn together, so past that position the assembly with the
    orientation followed is not a continuation of it. Positions past it are
    flagged singular with a message; none is reported on the other assembly."""
    t2 = np.radians(np.arange(300.0, 420.0, 1.0))
    for circuit in ("open", "crossed"):
        m = solve(system_of(fourbar_in(*KITE, t2[0], circuit)), t2, 1.0)
        ok = m.status == 0
        assert ok[t2 < 2 * np.pi - 1e-9].all() and not ok[t2 > 2 * np.pi + 1e-9].any()
        assert (m.status[~ok] == 2).all()
        assert circuit_of(m, KITE, t2, circuit)[ok].all()
        assert "cannot find the assembly it followed" in str(m.message)


def test_isosceles_slider_crank_keeps_its_assembly():
    """a = b with no offset: the slider passes the crank pivot at 90 and 270 deg,
    where both assemblies meet; the sweep stays on the open one."""
    from accelab.solver.kernels import slidercrank as slider_kernel

    t2 = np.radians(np.arange(5.0, 725.0, 1.0))
    ref = slider_kernel.solve(0.04, 0.04, 0.0, t2, 1.0, circuit="open")
    desc = EXAMPLES["slidercrank"](
        a="40 mm",
        b="40 mm",
        c="0 mm",
        guess3=f"{float(ref.theta3[0])!r} rad",
        guess_d=f"{float(ref.d[0])!r} m",
    )
    m = solve(system_of(desc), t2, 1.0)
    ok = m.status == 0
    assert list(np.degrees(t2[~ok]).round(6)) == [90.0, 270.0, 450.0, 630.0]
    assert np.abs(m.L[ok, 3] - ref.d[ok]).max() < 1e-12
    assert len(m.notes) == 4
