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
from solver.kernels import SINGULAR_CONDITION
from solver.kernels import fourbar as fourbar_kernel
from solver.vectorloops import VectorLoopLinkage, solve_case
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
