"""accelab.solver.vectorloops.sweep: the fast sweep (coarse continuation plus a batched
Newton-Raphson between) against its own position-by-position walk, one assembly
through whole cycles, and how many positions the batch solves."""

import numpy as np
import pytest
from _vectorloops_helpers import (
    CYCLE,
    LINKAGES,
    SWEEPS,
    close,
    counting,
    fourbar_desc,
    guesses_on,
    on_circuit,
    rel_err,
    same_motion,
    start_on_crossed_once,
    sweep,
    system_of,
)

from accelab.solver import Q_, FourBar
from accelab.solver.kernels import fourbar as fourbar_kernel
from accelab.solver.vectorloops import VectorLoopLinkage
from accelab.solver.vectorloops import sweep as sweep_module
from accelab.solver.vectorloops.examples import EXAMPLES
from accelab.solver.vectorloops.solve import solve


def test_sweep_follows_one_assembly_and_masks():
    # crossed-circuit guesses stay crossed over the whole cycle
    desc = EXAMPLES["fourbar"](guess3="-60 deg", guess4="-100 deg")
    r = VectorLoopLinkage(**desc).solve(
        theta2=Q_(np.linspace(0, 720, 721), "deg"), omega2="1 rad/s"
    )
    closed = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2=Q_(np.linspace(0, 720, 721), "deg"), omega2="1 rad/s", circuit="crossed"
    )
    assert r.valid.all()
    assert close(np.exp(1j * r.vectors["R4"].angle.m), np.exp(1j * closed.theta4.m))
    # a non-Grashof linkage: mask where it cannot reach, never a jump
    desc = EXAMPLES["fourbar"](
        a="5 in", b="3 in", c="4 in", d="6 in", guess3="100 deg", guess4="60 deg"
    )
    r = VectorLoopLinkage(**desc).solve(theta2=Q_(np.linspace(0, 70, 71), "deg"), omega2="1 rad/s")
    fb = FourBar(a="5 in", b="3 in", c="4 in", d="6 in")
    ok = r.valid
    assert ok.sum() > 10
    for circuit in ("open", "crossed"):
        c = fb.solve(
            theta2=Q_(np.linspace(0, 70, 71), "deg")[ok], omega2="1 rad/s", circuit=circuit
        )
        if close(np.exp(1j * r.vectors["R4"].angle.m[ok]), np.exp(1j * c.theta4.m), 1e-9):
            break
    else:
        pytest.fail("the sweep matches neither assembly throughout")


def test_sixbar_cycle_iteration_counts():
    r = sweep("watt2_sixbar")
    assert r.valid.all()
    assert r.iterations.max() <= 8
    assert np.median(r.iterations) <= 3


@pytest.mark.parametrize("name", sorted(EXAMPLES))
@pytest.mark.parametrize("sweep", sorted(SWEEPS))
def test_batched_sweep_equals_sequential(name, sweep):
    system = system_of(EXAMPLES[name]())
    t2 = SWEEPS[sweep]
    inputs = dict(omega2=10.0, alpha2=-5.0, jerk2=40.0)
    fast = solve(system, t2, **inputs)
    slow = solve(system, t2, batch=False, **inputs)
    assert (fast.status == 0).all()
    same_motion(fast, slow)


def test_forced_fallbacks_and_restart_give_the_same_sweep(monkeypatch):
    """Every batched interval walked again, and one coarse position spoiled so
    the walk disagrees and the chain restarts there: still the same sweep."""
    system = system_of(EXAMPLES["sixbar_slider"]())
    reference = solve(system, CYCLE, 10.0, -5.0, 40.0, batch=False)
    original = sweep_module.Sweep.batch
    calls = {"walks": 0, "spoiled": False}

    def all_bad(self, intervals):
        original(self, intervals)
        if intervals and not calls["spoiled"]:  # spoil the end of the third interval
            a, b = intervals[2]
            self.record.q[b] += 1e-6
            calls["spoiled"] = True
        return intervals

    walk = sweep_module.Sweep.walk_dense

    def counting_walk(self, start, stop):
        calls["walks"] += 1
        return walk(self, start, stop)

    monkeypatch.setattr(sweep_module.Sweep, "batch", all_bad)
    monkeypatch.setattr(sweep_module.Sweep, "walk_dense", counting_walk)
    fast = solve(system, CYCLE, 10.0, -5.0, 40.0)
    assert calls["spoiled"] and calls["walks"] >= 3
    same_motion(fast, reference)


@pytest.mark.parametrize("linkage", sorted(LINKAGES))
@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize("step_deg", [0.5, 10.0])
def test_fourbar_keeps_its_assembly_through_full_cycles(linkage, circuit, step_deg):
    a, b, c, d = LINKAGES[linkage]
    t2 = np.radians(np.arange(0.0, 720.0 + step_deg / 2, step_deg))
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on(circuit, a, b, c, d, 0.0)))
    m = solve(system, t2, 10.0, -5.0, 40.0)
    ref = fourbar_kernel.solve(a, b, c, d, t2, 10.0, -5.0, 40.0, circuit=circuit)
    assert (m.status == 0).all() and (ref.status == 0).all()
    assert on_circuit(m, a, b, c, d, t2, circuit, 1e-12).all()
    for n, key in enumerate(("omega", "alpha", "jerk")):
        assert rel_err(m.dth[n][:, 2], getattr(ref, key + "3")) <= 1e-12
        assert rel_err(m.dth[n][:, 3], getattr(ref, key + "4")) <= 1e-12


def test_batched_guesses_that_land_on_the_other_assembly_are_caught(monkeypatch):
    a, b, c, d = LINKAGES["crank_rocker"]
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on("open", a, b, c, d, 0.0)))
    sw = sweep_module.Sweep(system, CYCLE, system.model.guess, 1e-13)
    sw.run()
    inner = np.flatnonzero(~sw.record.sequential)[[5, 6, 150]]  # positions the batch solves
    bad = start_on_crossed_once(system, monkeypatch, a, b, c, d, CYCLE[inner])
    walks = counting(monkeypatch, "walk_dense")
    m = solve(system, CYCLE, 1.0)
    assert not bad and walks["n"] == 2
    assert (m.status == 0).all() and on_circuit(m, a, b, c, d, CYCLE, "open").all()


def test_non_finite_input_angles_are_masked_with_a_reason():
    t2 = np.radians(np.linspace(0.0, 100.0, 101))
    t2[[0, 50]] = np.inf, np.nan
    m = solve(system_of(EXAMPLES["sixbar_slider"]()), t2, 1.0)
    assert list(np.flatnonzero(m.status)) == [0, 50]
    assert "not a finite angle" in str(m.message)


def test_full_cycle_iteration_counts():
    for name in ("sixbar_slider", "watt2_sixbar", "fourbar"):
        r = VectorLoopLinkage(**EXAMPLES[name]()).solve(
            theta2=Q_(np.degrees(CYCLE), "deg"), omega2="10 rad/s"
        )
        assert r.valid.all()
        assert r.iterations.mean() <= 2.5 and r.iterations.max() <= 8


def test_short_sweeps_solve_most_positions_in_the_batch():
    """At 72 positions (5 deg apart) the coarse chain takes a minority of the
    positions, so a short sweep costs about what a long one does per position."""
    system = system_of(EXAMPLES["watt2_sixbar"]())
    for n in (72, 100):
        t2 = np.radians(np.linspace(0.0, 360.0, n, endpoint=False))
        sw = sweep_module.Sweep(system, t2, system.model.guess, 1e-13)
        sw.run()
        assert (sw.record.status == 0).all() and sw.record.sequential.sum() < n / 3
