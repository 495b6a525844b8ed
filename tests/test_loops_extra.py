"""The vector-loop solver's fast sweep (coarse continuation plus a batched
Newton-Raphson between) against its own position-by-position walk, against
the closed-form fourbar on both assemblies, through ranges that cannot be
assembled, with deliberately bad guesses, against mpmath at 40 digits, and
through the batch contract; its errors and its tolerance knob."""

import json

import mpmath as mp
import numpy as np
import pytest

from solver import Q_
from solver.batch import solve_cases
from solver.errors import InvalidInput, NoConvergence, Singular
from solver.vectorloops import SINGULAR_CONDITION
from solver.kernels import fourbar as fourbar_kernel
from solver.vectorloops import VectorLoopLinkage, solve_loops_case as solve_case
from solver.vectorloops import sweep as sweep_module
from solver.vectorloops.description import read_description
from solver.vectorloops.examples import EXAMPLES, fivebar, fourbar
from solver.vectorloops.solve import solve, system_from_case

CYCLE = np.radians(np.linspace(0.0, 360.0, 361)[:-1])


def system_of(desc):
    return system_from_case(desc)


def rel_err(x, y):
    """Largest difference over the largest magnitude of the reference (NaN-aware)."""
    x, y = np.asarray(x), np.asarray(y)
    return np.nanmax(np.abs(x - y)) / max(np.nanmax(np.abs(y)), 1e-300)


def same_motion(a, b, rtol=1e-12):
    assert np.array_equal(a.status, b.status)
    assert np.array_equal(np.isnan(a.q), np.isnan(b.q))
    assert rel_err(a.q, b.q) <= rtol
    for x, y in zip(a.dth + a.dL + a.points, b.dth + b.dL + b.points):
        if np.isfinite(y).any():
            assert rel_err(x, y) <= rtol


def fourbar_desc(a, b, c, d, guess3, guess4):
    """A fourbar as loops with lengths in metres and guesses in radians."""
    return fourbar(a=f"{a} m", b=f"{b} m", c=f"{c} m", d=f"{d} m",
                   guess3=f"{guess3} rad", guess4=f"{guess4} rad")


def guesses_on(circuit, a, b, c, d, theta2, miss=0.1):
    """Guesses a little off the closed-form assembly at theta2 [rad]."""
    m = fourbar_kernel.solve(a, b, c, d, theta2, 1.0, circuit=circuit)
    return float(m.theta3) + miss, float(m.theta4) - miss


def on_circuit(motion, a, b, c, d, theta2, circuit, tol=1e-9):
    """Where the loops solution (R3, R4 angles) is the closed form's ``circuit``."""
    m = fourbar_kernel.solve(a, b, c, d, theta2, 1.0, circuit=circuit)
    return ((np.abs(np.exp(1j * motion.theta[:, 2]) - np.exp(1j * m.theta3)) < tol)
            & (np.abs(np.exp(1j * motion.theta[:, 3]) - np.exp(1j * m.theta4)) < tol))


# --- the batched sweep is the sequential walk, to round-off -------------------

SWEEPS = {
    "cycle": CYCLE,
    "two_turns_backwards": np.radians(np.linspace(720.0, 0.0, 1441)),
    "uneven_back_and_forth": np.radians(np.concatenate([
        np.sort(np.random.default_rng(7).uniform(0, 300, 400)),
        np.linspace(300, 100, 151), [100.0, 100.0, 100.5]])),
}


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
    original = sweep_module._Sweep.batch
    calls = {"walks": 0, "spoiled": False}

    def all_bad(self, intervals):
        original(self, intervals)
        if intervals and not calls["spoiled"]:   # spoil the end of the third interval
            a, b = intervals[2]
            self.q[b] += 1e-6
            calls["spoiled"] = True
        return intervals

    walk = sweep_module._Sweep.walk_dense

    def counting_walk(self, start, stop):
        calls["walks"] += 1
        return walk(self, start, stop)

    monkeypatch.setattr(sweep_module._Sweep, "batch", all_bad)
    monkeypatch.setattr(sweep_module._Sweep, "walk_dense", counting_walk)
    fast = solve(system, CYCLE, 10.0, -5.0, 40.0)
    assert calls["spoiled"] and calls["walks"] >= 3
    same_motion(fast, reference)


# --- branch continuity against the closed form ----------------------------------

LINKAGES = {"crank_rocker": (2.0, 6.0, 9.0, 7.0), "double_crank": (6.0, 7.0, 9.0, 2.0)}


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


# --- ranges that cannot be assembled ------------------------------------------------

NON_GRASHOF = (5.0, 3.5, 4.0, 6.0)   # a triple rocker: the crank reaches |theta2| <= 85.4 deg


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize("start", [0.0, 30.0, -40.0])
def test_sweep_masks_a_range_that_cannot_close_and_rejoins_its_assembly(circuit, start):
    a, b, c, d = NON_GRASHOF
    t2 = np.radians(np.linspace(start, start + 360.0, 361))
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on(circuit, a, b, c, d, t2[0])))
    m = solve(system, t2, 1.0)
    ref = fourbar_kernel.solve(a, b, c, d, t2, 1.0, circuit=circuit)
    ok = m.status == 0
    assert np.array_equal(ok, ref.status == 0)            # masked exactly where it cannot close
    assert 100 < ok.sum() < 250
    assert (m.status[~ok] == 1).all() and np.isnan(m.q[~ok]).all()
    assert on_circuit(m, a, b, c, d, t2, circuit)[ok].all()   # one assembly, both sides
    assert isinstance(m.message, NoConvergence) and m.message.residual > 1e-4
    assert "residual" in str(m.message)
    same_motion(m, solve(system, t2, 1.0, batch=False))


def test_unverifiable_reassembly_is_reported_not_returned():
    """With the crank geared at half the input speed the input has no period the
    solver can use, so after the gap no walk from a solved position reaches the
    far side without crossing the gap: those positions are masked with a
    message, never returned on the other assembly."""
    a, b, c, d = NON_GRASHOF
    desc = fourbar_desc(a, b, c, d, *guesses_on("open", a, b, c, d, 0.0))
    desc["vectors"]["G"] = {"length": "0 m", "angle": "input"}
    desc["vectors"]["R2"] = {"length": f"{a} m", "angle": {"follow": "G", "ratio": 0.5}}
    t2 = np.radians(np.concatenate([np.arange(0.0, 171.0), np.arange(200.0, 560.0, 2.0),
                                    np.arange(560.0, 721.0)]))
    m = solve(system_of(desc), t2, 1.0)
    ok = m.status == 0
    assert ok[:171].all()
    assert on_circuit(m, a, b, c, d, t2 / 2, "open")[ok].all()
    assert not ok[171:].any()
    assert "did not close" in str(m.message)       # the first failure: the gap itself
    sw = sweep_module._Sweep(system_of(desc), t2, system_of(desc).model.guess, 1e-13)
    sw.run()
    after = [str(e) for i, e in sw.errors.items() if np.degrees(t2[i]) >= 560]
    honest = [e for e in after if "not on the assembly this sweep follows" in e]
    assert len(after) == 161 and len(honest) > 150
    assert all(e in honest or "did not close" in e for e in after)


# --- deliberately bad guesses that land on the other assembly -------------------------

def _crossed_q(a, b, c, d, t):
    m = fourbar_kernel.solve(a, b, c, d, t, 1.0, circuit="crossed")
    return np.array([float(m.theta3), float(m.theta4)])


def _start_on_crossed_once(system, monkeypatch, a, b, c, d, thetas):
    """Make Newton-Raphson start from the crossed assembly, once at each of the
    given input angles: a deliberately bad guess. The sweep's own prediction is
    untouched, so it is what the converged solution is checked against."""
    bad = {float(t) for t in thetas}
    newton1, newton = system.newton1, system.newton

    def newton1_bad(q0, theta2, *args, **kw):
        if float(theta2) in bad:
            bad.discard(float(theta2))
            q0 = _crossed_q(a, b, c, d, float(theta2))
        return newton1(q0, theta2, *args, **kw)

    def newton_bad(q0, theta2, *args, **kw):
        q0 = np.array(q0, dtype=float)
        for k, t in enumerate(theta2):
            if float(t) in bad:
                bad.discard(float(t))
                q0[k] = _crossed_q(a, b, c, d, float(t))
        return newton(q0, theta2, *args, **kw)

    monkeypatch.setattr(system, "newton1", newton1_bad)
    monkeypatch.setattr(system, "newton", newton_bad)
    return bad


def _counting(monkeypatch, name):
    calls = {"n": 0}
    method = getattr(sweep_module._Sweep, name)

    def counted(self, *args):
        calls["n"] += 1
        return method(self, *args)

    monkeypatch.setattr(sweep_module._Sweep, name, counted)
    return calls


def test_a_step_that_lands_on_the_other_assembly_is_caught(monkeypatch):
    a, b, c, d = LINKAGES["crank_rocker"]
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on("open", a, b, c, d, 0.0)))
    bad = _start_on_crossed_once(system, monkeypatch, a, b, c, d, CYCLE[[40, 41, 200]])
    subdivided = _counting(monkeypatch, "subdivide")
    m = solve(system, CYCLE, 1.0, batch=False)
    assert not bad and subdivided["n"] == 3
    assert (m.status == 0).all() and on_circuit(m, a, b, c, d, CYCLE, "open").all()


def test_batched_guesses_that_land_on_the_other_assembly_are_caught(monkeypatch):
    a, b, c, d = LINKAGES["crank_rocker"]
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on("open", a, b, c, d, 0.0)))
    sw = sweep_module._Sweep(system, CYCLE, system.model.guess, 1e-13)
    sw.run()
    inner = np.flatnonzero(~sw.sequential)[[5, 6, 150]]      # positions the batch solves
    bad = _start_on_crossed_once(system, monkeypatch, a, b, c, d, CYCLE[inner])
    walks = _counting(monkeypatch, "walk_dense")
    m = solve(system, CYCLE, 1.0)
    assert not bad and walks["n"] == 2
    assert (m.status == 0).all() and on_circuit(m, a, b, c, d, CYCLE, "open").all()


# --- high precision: mpmath at 40 digits ------------------------------------------------

def _mp_solver(desc):
    """q(theta2) of a description, by mpmath.findroot on the loop equations alone."""
    model = read_description(desc)

    def closure(theta2):
        def f(*q):
            z = []
            for v in range(len(model.names)):
                lu, au = model.length_unknown[v], model.angle_unknown[v]
                L = q[lu] if lu >= 0 else mp.mpf(model.length[v])
                base = theta2 if model.angle_input[v] else (q[au] if au >= 0 else 0)
                th = mp.mpf(model.angle_ratio[v]) * base + mp.mpf(model.angle_offset[v])
                z.append(L * mp.mpc(mp.cos(th), mp.sin(th)))
            out = []
            for row in model.signs:
                s = mp.fsum(int(k) * zv for k, zv in zip(row, z) if k)
                out += [mp.re(s), mp.im(s)]
            return out
        return f

    def q_at(theta2, start):
        q = mp.findroot(closure(theta2), [mp.mpf(x) for x in start],
                        tol=mp.mpf(10) ** (-2 * mp.mp.dps + 10))
        q = [q[i] for i in range(len(start))]
        assert max(abs(r) for r in closure(theta2)(*q)) < mp.mpf(10) ** (-mp.mp.dps + 5)
        return q

    return model, q_at


def test_sixbar_slider_derivatives_against_mpmath_finite_differences():
    """Velocity, acceleration and jerk of every unknown (theta3, theta4, theta5 and
    the slider's S) at coarse and batched positions of a full-cycle sweep, against
    central differences of 40-digit positions along theta2(t) = t0 + w t + a t^2/2
    + j t^3/6."""
    desc = EXAMPLES["sixbar_slider"]()
    w, al, jk = 12.0, -30.0, 500.0
    r = VectorLoopLinkage(**desc).solve(theta2=Q_(np.degrees(CYCLE), "deg"), omega2=f"{w} rad/s",
                                        alpha2=f"{al} rad/s^2", jerk2=f"{jk} rad/s^3")
    assert r.valid.all()
    model, q_at = _mp_solver(desc)
    got = {}
    for u, name in enumerate(model.unknown_names):
        v, what = name.split(".")
        keys = (("length", "length_dot", "length_ddot", "length_dddot") if what == "length"
                else ("angle", "omega", "alpha", "jerk"))
        got[u] = [getattr(r.vectors[v], k).to_base_units().m for k in keys]
    old = mp.mp.dps
    mp.mp.dps = 40
    try:
        h = mp.mpf(10) ** -8
        for i in (0, 37, 181, 300):
            t0 = mp.mpf(float(CYCLE[i]))
            start = [got[u][0][i] for u in range(model.n_unknowns)]
            qs = {k: q_at(t0 + w * (k * h) + al * (k * h) ** 2 / 2 + jk * (k * h) ** 3 / 6, start)
                  for k in (-2, -1, 0, 1, 2)}
            for u in range(model.n_unknowns):
                f = {k: qs[k][u] for k in qs}
                ref = [f[0], (f[1] - f[-1]) / (2 * h), (f[1] - 2 * f[0] + f[-1]) / h ** 2,
                       (f[2] - 2 * f[1] + 2 * f[-1] - f[-2]) / (2 * h ** 3)]
                for n in range(4):
                    scale = max(abs(float(ref[n])), w ** n * 1e-2)
                    assert abs(got[u][n][i] - float(ref[n])) <= 1e-10 * scale, \
                        (model.unknown_names[u], n, i, got[u][n][i], float(ref[n]))
    finally:
        mp.mp.dps = old


def _jet_of_vector(L, th):
    """Taylor coefficients (in t) of z = L e^{j theta} to third order, from the
    derivatives [f, f', f'', f'''] of L and theta: an independent composition."""
    l0, l1, l2, l3 = L[0], L[1], L[2] / 2, L[3] / 6
    u1, u2, u3 = 1j * th[1], 1j * th[2] / 2, 1j * th[3] / 6
    e0 = np.exp(1j * th[0])
    e = [e0, e0 * u1, e0 * (u2 + u1 * u1 / 2), e0 * (u3 + u1 * u2 + u1 ** 3 / 6)]
    lj = [l0, l1, l2, l3]
    return [sum(lj[k] * e[n - k] for k in range(n + 1)) * [1, 1, 2, 6][n] for n in range(4)]


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_every_differentiated_loop_closes(name):
    desc = EXAMPLES[name]()
    system = system_of(desc)
    m = solve(system, CYCLE, 10.0, -5.0, 40.0)
    assert (m.status == 0).all()
    signs = system.model.signs
    jets = [_jet_of_vector([m.L[:, v]] + [x[:, v] for x in m.dL],
                           [m.theta[:, v]] + [x[:, v] for x in m.dth])
            for v in range(signs.shape[1])]
    for loop in signs:
        for n in range(4):
            terms = np.array([k * jets[v][n] for v, k in enumerate(loop) if k])
            closure = np.abs(terms.sum(axis=0))
            assert (closure <= 1e-12 * np.abs(terms).sum(axis=0).max()).all(), (n, closure.max())


# --- errors ----------------------------------------------------------------------------

def test_no_convergence_carries_the_residual():
    desc = EXAMPLES["fourbar"](d="17 in")
    with pytest.raises(NoConvergence) as info:
        VectorLoopLinkage(**desc).solve(theta2="30 deg", omega2="1 rad/s")
    assert info.value.residual > 0.1 * 0.0254 and f"{info.value.residual:.3e}" in str(info.value)
    m = solve(system_of(desc), np.radians([10.0, 20.0]), 1.0)
    assert (m.status == 1).all() and isinstance(m.message, NoConvergence)
    assert m.message.residual > 1e-4 and f"{m.message.residual:.3e}" in str(m.message)


def test_non_finite_input_angles_are_masked_with_a_reason():
    t2 = np.radians(np.linspace(0.0, 100.0, 101))
    t2[[0, 50]] = np.inf, np.nan
    m = solve(system_of(EXAMPLES["sixbar_slider"]()), t2, 1.0)
    assert list(np.flatnonzero(m.status)) == [0, 50]
    assert "not a finite angle" in str(m.message)


def test_singular_carries_the_condition_number():
    # a parallelogram at its change point: every link on the x axis at theta2 = 0
    desc = fourbar_desc(1.0, 3.0, 1.0, 3.0, 0.05, 0.09)
    with pytest.raises(Singular) as info:
        VectorLoopLinkage(**desc).solve(theta2="0 deg", omega2="1 rad/s")
    assert 0 <= info.value.condition < SINGULAR_CONDITION
    assert "condition number" in str(info.value)
    res = solve_case(dict(json.loads(json.dumps(desc)), mechanism="loops", theta2="0 deg",
                          omega2="1 rad/s", alpha2="0 rad/s^2"))
    assert res["ok"] is False and res["error"] == "singular"


@pytest.mark.parametrize("change, words", [
    (lambda c: c["points"].update(E="R2 + R9"), "unknown vector 'R9'"),
    (lambda c: c["vectors"]["RP"].update(angle={"follow": "R7"}), "follows 'R7'"),
    (lambda c: c["vectors"]["R1"].update(angle="unknown", guess="0 deg"),
     "3 unknowns (R1.angle, R3.angle, R4.angle)"),
    (lambda c: c["vectors"]["R3"].update(angle={"follow": "RP"}), "R3 -> RP -> R3"),
    (lambda c: c["vectors"]["R4"].update(length="unknown"), "needs a guess length"),
    (lambda c: c["vectors"]["R4"].update(shape="round"), "unknown key(s) ['shape']"),
])
def test_malformed_descriptions_say_what_is_wrong(change, words):
    case = json.loads(json.dumps(dict(EXAMPLES["fourbar"](), mechanism="loops",
                                      theta2="30 deg", omega2="1 rad/s", alpha2="0 rad/s^2")))
    change(case)
    res = solve_case(case)
    assert res["ok"] is False and res["error"] == "invalid_input", res
    assert words in res["message"], res["message"]


# --- the tolerance knob --------------------------------------------------------------------

def test_tolerance_trades_iterations_for_accuracy():
    linkage = VectorLoopLinkage(**EXAMPLES["sixbar_slider"]())
    cycle = Q_(np.degrees(CYCLE), "deg")
    exact = linkage.solve(theta2=cycle, omega2="10 rad/s", alpha2="-5 rad/s^2")
    for tol in (1e-2, 1e-6, 1e-10):
        loose = linkage.solve(theta2=cycle, omega2="10 rad/s", alpha2="-5 rad/s^2", tol=tol)
        assert loose.valid.all()
        assert loose.iterations.mean() <= exact.iterations.mean()
        for v in ("R3", "R4", "R5"):
            assert np.max(np.abs(loose.vectors[v].angle.m - exact.vectors[v].angle.m)) <= tol
        assert rel_err(loose.vectors["S"].length_ddot.m, exact.vectors["S"].length_ddot.m) <= tol
    assert linkage.solve(theta2=cycle, omega2="10 rad/s", tol=1e-2).iterations.mean() < 1.5
    for bad in (0, -1e-9, 0.5, "tight"):
        with pytest.raises(InvalidInput, match="tol"):
            linkage.solve(theta2="10 deg", omega2="1 rad/s", tol=bad)


def test_full_cycle_iteration_counts():
    for name in ("sixbar_slider", "watt2_sixbar", "fourbar"):
        r = VectorLoopLinkage(**EXAMPLES[name]()).solve(theta2=Q_(np.degrees(CYCLE), "deg"),
                                                      omega2="10 rad/s")
        assert r.valid.all()
        assert r.iterations.mean() <= 2.5 and r.iterations.max() <= 8


def test_scalar_and_one_element_sweep_agree():
    linkage = VectorLoopLinkage(**EXAMPLES["watt2_sixbar"]())
    one = linkage.solve(theta2="57 deg", omega2="12 rad/s", alpha2="-30 rad/s^2")
    arr = linkage.solve(theta2=Q_([57.0], "deg"), omega2="12 rad/s", alpha2="-30 rad/s^2")
    assert one.valid and arr.valid.shape == (1,)
    for v in ("R3", "R5", "R6"):
        assert one.vectors[v].alpha.m == pytest.approx(arr.vectors[v].alpha.m[0], rel=1e-13)


# --- the batch contract: loops with a coupler point and a gear ratio -----------------------

MOTION = {"theta2": "50 deg", "omega2": "15 rad/s", "alpha2": "-20 rad/s^2", "jerk2": "300 rad/s^3"}


def _xy(v):
    return complex(*v)


def test_batch_solves_loops_with_a_coupler_point_and_a_gear_ratio():
    geared = fivebar(lam=-2.5, phi="25 deg", guess3="60 deg", guess4="110 deg")
    geared["vectors"]["RP"] = {"length": "2.5 in", "angle": {"follow": "R3", "offset": "35 deg"}}
    geared["points"]["P"] = "R2 + RP"
    coupler = fourbar(p="3 in", delta3="40 deg")
    cases = [dict(geared, mechanism="loops", **MOTION),
             {"mechanism": "fivebar", "a": "1 in", "b": "4 in", "c": "4 in", "d": "1 in",
              "f": "3 in", "lam": -2.5, "phi": "25 deg", **MOTION},
             {"mechanism": "fivebar", "a": "1 in", "b": "4 in", "c": "4 in", "d": "1 in",
              "f": "3 in", "lam": -2.5, "phi": "25 deg", "circuit": "crossed", **MOTION},
             dict(coupler, mechanism="loops", **MOTION),
             {"mechanism": "fourbar", "a": "2 in", "b": "6 in", "c": "9 in", "d": "7 in",
              "p": "3 in", "delta3": "40 deg", **MOTION},
             dict(EXAMPLES["fourbar"](d="17 in"), mechanism="loops", **MOTION),
             dict(coupler, mechanism="loops", colour="red", **MOTION)]
    out = json.loads(json.dumps(solve_cases(json.loads(json.dumps(cases)))))
    loops5, open5, crossed5, loops4, closed4, far, typo = out
    assert loops5["ok"] and open5["ok"] and crossed5["ok"], (loops5, open5, crossed5)
    closed = [c for c in (open5, crossed5)
              if abs(np.exp(1j * c["theta4"]) - np.exp(1j * loops5["vectors"]["R4"]["angle"])) < 1e-9]
    assert len(closed) == 1
    closed = closed[0]
    for n in "345":
        for key in ("omega", "alpha", "jerk"):
            if key + n in closed:
                got, ref = loops5["vectors"]["R" + n][key], closed[key + n]
                assert got == pytest.approx(ref, rel=1e-8, abs=1e-8 * abs(closed["alpha3"]))
    for pt, key in (("B", "A_B"), ("C", "A_C"), ("A", "A_A")):
        assert abs(_xy(loops5["points"][pt]["A"]) - _xy(closed[key])) <= 1e-8 * abs(_xy(closed[key]))
    # the coupler point P, as a rigid point of link 3 (eq. 7.32): A_P = A_A + p (j alpha3 - omega3^2) e^{j(theta3 + delta)}
    p, delta = 2.5 * 0.0254, np.radians(35.0)
    a_p = _xy(closed["A_A"]) + p * (1j * closed["alpha3"] - closed["omega3"] ** 2) * np.exp(
        1j * (closed["theta3"] + delta))
    assert abs(_xy(loops5["points"]["P"]["A"]) - a_p) <= 1e-8 * abs(a_p)
    # the fourbar's coupler point against the closed form's A_P and J_P
    assert loops4["ok"] and closed4["ok"]
    for key in ("A", "J"):
        ref = _xy(closed4[key + "_P"])
        assert abs(_xy(loops4["points"]["P"][key]) - ref) <= 1e-8 * abs(ref)
    assert far["ok"] is False and far["error"] == "not_assemblable" and "residual" in far["message"]
    assert typo["ok"] is False and typo["error"] == "invalid_input"


# --- change points: two assemblies meet at a singular position -------------------------
# A fourbar with s + l = p + q (a, b, c, d = 2, 5, 4, 3 in: 2 + 5 = 4 + 3) reaches a
# configuration with every link on the x axis at theta2 = 0 (mod 360 deg), where its open
# and crossed assemblies touch (Chapter 4's change point; the benchmark's issue 3 found a
# sweep there silently continuing on the crossed assembly). Past it either assembly is
# possible. The sweep must stay on the assembly with its orientation (the sign of det J,
# which is the closed form's circuit) and say so, flag sampled singular positions, and
# never report the other assembly as if nothing happened.

CHANGE_POINT = (2.0, 5.0, 4.0, 3.0)           # [in]
PARALLELOGRAM = (1.0, 3.0, 1.0, 3.0)          # change points at 0 and 180 deg
KITE = (2.0, 5.0, 5.0, 2.0)                   # a = d, b = c: at 0 deg A sits on O4


def fourbar_in(a, b, c, d, theta2, circuit):
    """The fourbar in inches as loops, guesses exactly on the closed form's circuit."""
    m = fourbar_kernel.solve(a, b, c, d, theta2, 1.0, circuit=circuit)
    return fourbar(a=f"{a} in", b=f"{b} in", c=f"{c} in", d=f"{d} in",
                   guess3=f"{float(m.theta3)!r} rad", guess4=f"{float(m.theta4)!r} rad")


def circuit_of(motion, linkage, t2, circuit):
    return on_circuit(motion, *linkage, t2, circuit, tol=1e-8)


def same_away_from_singular(a, b, cond=0.05):
    """Like same_motion, to 1e-12 where the condition measure is at least ``cond``;
    nearer the singular position round-off grows like a power of 1/condition (the
    square for acceleration, the cube for jerk), so there to 1e-5."""
    assert np.array_equal(a.status, b.status)
    ok = a.status == 0
    far = ok & (a.condition >= cond)
    for x, y in zip([a.q] + a.dth + a.dL + a.points, [b.q] + b.dth + b.dL + b.points):
        if np.isfinite(y[ok]).any():
            assert rel_err(x[far], y[far]) <= 1e-12
            assert rel_err(x[ok], y[ok]) <= 1e-5


def test_orientation_tells_the_fourbar_circuits_apart():
    """det J over its column norms is sin(theta3 - theta4) for the fourbar's loop,
    opposite in sign on the two circuits."""
    a, b, c, d = LINKAGES["crank_rocker"]
    t2 = np.radians(np.arange(0.0, 360.0, 15.0))
    for circuit in ("open", "crossed"):
        system = system_of(fourbar_desc(a, b, c, d, *guesses_on(circuit, a, b, c, d, 0.0)))
        ref = fourbar_kernel.solve(a, b, c, d, t2, 1.0, circuit=circuit)
        q = np.stack([ref.theta3, ref.theta4], axis=1)
        *_, reason, _, orient = system.newton(q, t2)
        assert (reason == 0).all()
        assert np.allclose(orient, np.sin(ref.theta3 - ref.theta4), atol=1e-12)
        assert np.all(np.sign(orient) == (-1 if circuit == "open" else 1))


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize("start_deg, step_deg, n", [
    (np.degrees(0.05), 1.0, 360),       # the benchmark's sweep: past 360 at 360.86, 361.86
    (5.0, 1.0, 720),                    # two turns: samples exactly on 360 and 720 deg
    (5.0, 7.3, 99),                     # coarse
    (5.0, 40.0, 18),                    # very coarse: one step jumps across
    (30.0, -0.5, 121),                  # backwards through 0
])
def test_sweep_through_a_change_point_keeps_its_assembly_and_says_so(circuit, start_deg,
                                                                      step_deg, n):
    t2 = np.radians(start_deg + step_deg * np.arange(n))
    desc = fourbar_in(*CHANGE_POINT, t2[0], circuit)
    m = solve(system_of(desc), t2, 10.0, -5.0, 40.0)
    ok = m.status == 0
    assert circuit_of(m, CHANGE_POINT, t2, circuit)[ok].all()       # never the other one
    near = np.abs(np.angle(np.exp(1j * t2))) < 1e-9                 # sampled on the point
    assert np.array_equal(~ok, near)                                # those flagged, only those
    assert (m.status[near] == 2).all() and (m.condition[near] < SINGULAR_CONDITION).all()
    crossings = int(np.floor((t2.max()) / (2 * np.pi)) - np.floor(t2.min() / (2 * np.pi))
                    + (np.abs(np.angle(np.exp(1j * t2.min()))) < 1e-9))
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
        theta2=Q_(np.degrees(t2), "deg"), omega2="10 rad/s", alpha2="-5 rad/s^2")
    ref = fourbar_kernel.solve(*CHANGE_POINT, t2, 10.0, -5.0, circuit="open")
    assert r.valid.all()
    for v, key in (("R3", "theta3"), ("R4", "theta4")):
        d = np.angle(np.exp(1j * (r.vectors[v].angle.m_as("rad") - getattr(ref, key))))
        assert np.abs(d).max() < 1e-12
    alpha4 = r.vectors["R4"].alpha.m_as("rad/s^2")
    far = r.condition >= 0.05
    assert rel_err(alpha4[far], ref.alpha4[far]) < 1e-10
    assert rel_err(alpha4, ref.alpha4) < 1e-7
    assert list(r.notes) == [358]             # 360.86 deg: the first position past it
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
    assert np.isfinite(m.q[0]).all()                     # the position itself stands
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
    second = fourbar_kernel.solve(a, b, c, d, float(first.theta4) + np.radians(off - 10.0), 1.0,
                                  circuit="open")
    for name, value in (("R3", first.theta3), ("R4", first.theta4),
                        ("R5", second.theta3 + np.radians(10.0)),
                        ("R6", second.theta4 + np.radians(10.0))):
        desc["vectors"][name]["guess"] = f"{float(value)!r} rad"
    for step in (1.0, 13.0):
        t2 = t0 + np.radians(np.arange(0.0, 720.0, step))
        m = solve(system_of(desc), t2, 10.0)
        ref = fourbar_kernel.solve(a, b, c, d, m.theta[:, 4] - np.radians(10.0), 1.0,
                                   circuit="open")
        assert (m.status == 0).all()
        assert np.allclose(np.exp(1j * m.theta[:, 6]), np.exp(1j * (ref.theta4 + np.radians(10.0))),
                           atol=1e-9)
        assert len(m.notes) == 4                 # two flat positions per turn, two turns


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
    from solver.kernels import slidercrank as slider_kernel
    t2 = np.radians(np.arange(5.0, 725.0, 1.0))
    ref = slider_kernel.solve(0.04, 0.04, 0.0, t2, 1.0, circuit="open")
    desc = EXAMPLES["slidercrank"](a="40 mm", b="40 mm", c="0 mm",
                                   guess3=f"{float(ref.theta3[0])!r} rad",
                                   guess_d=f"{float(ref.d[0])!r} m")
    m = solve(system_of(desc), t2, 1.0)
    ok = m.status == 0
    assert list(np.degrees(t2[~ok]).round(6)) == [90.0, 270.0, 450.0, 630.0]
    assert np.abs(m.L[ok, 3] - ref.d[ok]).max() < 1e-12
    assert len(m.notes) == 4


# --- speed: short sweeps batched, small BLAS calls, the straight-line kernel ------------

def test_short_sweeps_solve_most_positions_in_the_batch():
    """At 72 positions (5 deg apart) the coarse chain takes a minority of the
    positions, so a short sweep costs about what a long one does per position."""
    system = system_of(EXAMPLES["watt2_sixbar"]())
    for n in (72, 100):
        t2 = np.radians(np.linspace(0.0, 360.0, n, endpoint=False))
        sw = sweep_module._Sweep(system, t2, system.model.guess, 1e-13)
        sw.run()
        assert (sw.status == 0).all() and sw.sequential.sum() < n / 3


@pytest.mark.parametrize("shape", [(1, 48, 48), (29, 48, 48), (1000, 48, 48), (997, 32, 24),
                                   (10001, 12, 3)])
@pytest.mark.parametrize("kind", [float, complex])
def test_unthreaded_products_equal_matmul(shape, kind):
    from solver.vectorloops.products import BLAS_BLOCK, rows_times
    M, K, N = shape
    rng = np.random.default_rng(M)
    Y = rng.normal(size=(M, K)).astype(kind)
    B = rng.normal(size=(K, N)).astype(kind)
    if kind is complex:
        Y = Y + 1j * rng.normal(size=(M, K))
    assert np.allclose(rows_times(Y, B), Y @ B, rtol=1e-13, atol=1e-12)
    assert BLAS_BLOCK // (K * N) * K * N <= 65536


@pytest.mark.parametrize("name", sorted(EXAMPLES) + ["eightbar"])
def test_straight_line_kernel_matches_the_batched_evaluation(name):
    """The generated one-position kernel against numpy's evaluation: residual, Newton
    step, dq/dtheta2 and orientation at random configurations."""
    from benchmarks.cases import eightbar
    from solver.vectorloops.newton import orientation
    system = system_of(eightbar() if name == "eightbar" else EXAMPLES[name]())
    rng = np.random.default_rng(5)
    for _ in range(20):
        q = system.model.guess + rng.normal(scale=0.3, size=system.n_unknowns) * system.scale
        t = float(rng.uniform(-np.pi, np.pi))
        res, orient, dq, slope = system._kernel(list(q), t)
        F, J, Ft = system.evaluate(q[None], np.array([t]))
        assert res == pytest.approx(np.linalg.norm(F[0]), rel=1e-12)
        assert orient == pytest.approx(float(orientation(J[0])), rel=1e-9, abs=1e-14)
        assert np.allclose(dq, np.linalg.solve(J[0], -F[0]), rtol=1e-9, atol=1e-13)
        assert np.allclose(slope, np.linalg.solve(J[0], -Ft[0]), rtol=1e-9, atol=1e-13)
