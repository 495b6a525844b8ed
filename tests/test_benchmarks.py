"""The benchmark: a tiny smoke run and its JSON, the reference it trusts, and
the failure modes its stability study found (near a toggle every answer is
accurate or refused; Newton-Raphson's failures are reported; a sweep never
lands silently on the other assembly). Nothing here asserts a time."""

import json
import math

import numpy as np
import pytest

from accelab.benchmarks.cases import all_cases, description
from accelab.benchmarks.reference import at_points, toggle_angle
from accelab.benchmarks.run import run_benchmark
from accelab.benchmarks.stability import STUDY_CASE, near_toggle, newton_guesses
from accelab.solver import Q_, FourBar, NoConvergence, NotAssemblable, Singular, VectorLoopLinkage

#: the benchmark (the tiny run) and the study near a toggle: built once, in one worker
pytestmark = pytest.mark.xdist_group("benchmarks")
#: an answer near a toggle must be this close to the reference, or refused
NEAR_TOGGLE_TOLERANCE = 1e-6


@pytest.fixture(scope="module")
def cases():
    return all_cases()


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench")
    data = run_benchmark(
        str(out), mode="tiny", peers=False, charts=True, log=lambda *a: None, formats=("png",)
    )
    return out, data


# --- the smoke run and its JSON -----------------------------------------------------
def test_tiny_run_writes_json_and_charts(tiny):
    out, data = tiny
    on_disk = json.loads((out / "bench.json").read_text())
    assert on_disk["mode"] == "tiny"
    for key in (
        "machine",
        "config",
        "cases",
        "methods",
        "results",
        "stability",
        "newton",
        "scaling",
        "units",
        "goals",
        "elapsed_s",
    ):
        assert key in on_disk, key
    assert on_disk["machine"]["numpy"] and on_disk["machine"]["python"]
    for stem in ("bench-speed-accuracy", "bench-stability", "bench-scaling"):
        assert (out / f"{stem}.png").stat().st_size > 10_000
    assert list((out / "reference").glob("reference-fourbar-open-*.json"))


def test_every_case_solved_by_its_methods(tiny, cases):
    _, data = tiny
    rows = {(r["case"], r["method"]): r for r in data["results"]}
    assert {c["name"] for c in data["cases"]} == set(cases)
    for name, case in cases.items():
        loops = rows[(name, "loops")]
        assert loops["flagged"] == 0 and loops["worst"] < 1e-12, (name, loops)
        if case.mechanism == "loops":
            assert "skipped" in rows[(name, "kernels")]
            continue
        for method in ("kernels", "units", "scalar"):
            r = rows[(name, method)]
            assert r["flagged"] == 0, (name, method)
            assert r["worst"] < 1e-13, (name, method, r["worst"])
            assert r["us_per_position"] > 0
            assert set(r["per_output"]) == set(case.outputs)
        fd = rows[(name, "fd-h1e-03")]
        assert 1e-9 < fd["worst"] < 0.1  # truncation error: finite differences are not exact
    graphical = rows[("fourbar-open", "graphical")]
    assert graphical["order"] == 2 and "jerk3" not in graphical["per_output"]
    assert graphical["worst"] < 1e-12


def test_goals_listed_with_measurements(tiny):
    _, data = tiny
    goals = {g["goal"]: g for g in data["goals"]}
    assert any("unit-aware" in g for g in goals)
    accuracy_goal = next(g for k, g in goals.items() if "worst relative error" in k)
    assert accuracy_goal["met"] and accuracy_goal["measured"] <= 1e-13
    assert any(k.startswith("general solver, sixbar") for k in goals)
    for g in goals.values():
        assert isinstance(g["met"], bool) and g["measured"] is not None


def test_cli_registered():
    from accelab.cli import build_parser

    args = build_parser().parse_args(["bench", "--quick", "--out", "x"])
    assert args.quick and args.out == "x" and callable(args.func)


# --- failure modes: near a toggle ----------------------------------------------------------
@pytest.fixture(scope="module")
def study():
    return near_toggle(n=9, methods=("kernels", "loops", "graphical"))


def test_near_toggle_answers_are_accurate_or_refused(study):
    """No silent wrong numbers: every answer within 1e-6 of the 60-digit
    reference, down to 1e-15 rad from the toggle; what is not, is refused."""
    for key, m in study["methods"].items():
        for delta, err, refused in zip(study["delta"], m["errors"], m["refused"]):
            if not refused:
                assert err <= NEAR_TOGGLE_TOLERANCE, (key, delta, err)
        assert not m["refused"][0], key  # 0.3 rad away: answered
        assert m["errors"][0] < 1e-13, key  # ... and to full accuracy
        assert m["refused"][-1], key  # 1e-15 rad away: refused


def test_near_toggle_unit_aware_scalar_raises_singular(cases):
    case = cases[STUDY_CASE]
    p = case.params
    lim = float(toggle_angle(p["a"], p["b"], p["c"], p["d"]))
    fourbar = FourBar(**{k: Q_(p[k], "m") for k in "abcd"})
    with pytest.raises(Singular) as err:
        fourbar.solve(theta2=Q_(lim + 1e-13, "rad"), omega2="10 rad/s")
    assert "limit position" in str(err.value) or "toggle" in str(err.value)
    r = fourbar.solve(
        theta2=Q_(lim + 1e-3, "rad"), omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="20 rad/s^3"
    )
    ref = at_points(case, [lim + 1e-3], [case.kernel_guess(lim + 1e-3)])
    assert abs(r.jerk4.m_as("rad/s^3") / ref["jerk4"][0] - 1) < 1e-9


# --- failure modes: Newton-Raphson ------------------------------------------------------
def test_newton_non_convergence_is_reported(cases):
    """Where the links cannot close, the general solver raises with the residual
    it reached (scalar) or marks the positions (sweep); never numbers."""
    case = cases[STUDY_CASE]
    p = case.params
    lim = float(toggle_angle(p["a"], p["b"], p["c"], p["d"]))
    linkage = VectorLoopLinkage(**description(case, case.kernel_guess(1.0)))
    with pytest.raises(NotAssemblable) as err:
        linkage.solve(theta2=Q_(lim - 0.1, "rad"), omega2="10 rad/s")
    assert isinstance(err.value, NoConvergence) and err.value.residual > 1e-4
    assert "did not close" in str(err.value)
    t = np.linspace(1.0, lim - 0.2, 20)
    r = linkage.solve(theta2=Q_(t, "rad"), omega2="10 rad/s")
    past = t < lim
    assert np.all(r.status[past] == "not_assemblable")
    assert np.all(np.isnan(r.vectors["R3"].angle.m_as("rad")[past]))
    assert np.all(r.valid[t > lim + 0.05])


def test_newton_guess_outcomes_never_silent():
    """As the starting guess worsens, Newton-Raphson reaches the intended
    assembly, jumps to the other, or reports failure -- it never returns a
    position that does not close the loops; good guesses always work."""
    res = newton_guesses(offsets=[1e-3, 0.3, 3.0], trials=6, seed=3)
    for p in res["points"]:
        assert p["wrong"] == [0.0, 0.0, 0.0]
        assert p["same"][0] == 1.0
        for k in range(3):
            assert abs(p["same"][k] + p["other"][k] + p["failed"][k] - 1) < 1e-12
    grashof = res["points"][0]
    assert grashof["same"][1] == 1.0  # 0.3 rad off, far from any toggle: still fine


def test_sweep_never_lands_silently_on_the_other_assembly(cases):
    """A sweep that runs into a toggle, past it (not assemblable) and back keeps
    the guessed assembly wherever it answers; so does a very coarse sweep."""
    case = cases[STUDY_CASE]
    p = case.params
    lim = float(toggle_angle(p["a"], p["b"], p["c"], p["d"]))
    t = np.concatenate([np.linspace(1.0, lim - 0.2, 25), np.linspace(lim - 0.2, 1.0, 25)])
    linkage = VectorLoopLinkage(**description(case, case.kernel_guess(1.0)))
    r = linkage.solve(theta2=Q_(t, "rad"), omega2="10 rad/s")
    ok = np.asarray(r.valid)
    assert ok.sum() >= 30
    theta3 = r.vectors["R3"].angle.m_as("rad")
    d = np.angle(np.exp(1j * (theta3 - case.kernel(t).theta3)))
    assert np.all(np.abs(d[ok]) < 1e-9)
    grashof = cases["fourbar-open"]
    t = np.linspace(0, 2 * math.pi, 5, endpoint=False) + 0.1  # 72 deg steps
    r = VectorLoopLinkage(**description(grashof, grashof.kernel_guess(t[0]))).solve(
        theta2=Q_(t, "rad"), omega2="10 rad/s"
    )
    d = np.angle(np.exp(1j * (r.vectors["R3"].angle.m_as("rad") - grashof.kernel(t).theta3)))
    assert np.all(np.asarray(r.valid)) and np.all(np.abs(d) < 1e-9)
