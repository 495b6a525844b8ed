"""The whole benchmark: every case by every method, the stability study, the
scaling, the goals; written as ``bench.json`` with the charts beside it.

>>> from accelab.benchmarks.run import run_benchmark
>>> data = run_benchmark("build/bench", mode="quick")   # doctest: +SKIP
"""

import datetime
import json
import math
import os
import time

import numpy as np

from . import accuracy, scaling, stability
from .cases import CYCLE_MARGIN, ORDER_WORDS, all_cases
from .methods import NotApplicable, loop_tolerance_parameter, methods
from .peers import RANGE_NOTE, SLIDER_NOTE, installed
from .reference import DPS, cached
from .timing import machine, measure

#: settings of each mode: positions per cycle, repeats, stability points,
#: Newton offsets x trials, largest N of the scaling, positions of the loop count
MODES = {
    "full": dict(
        positions=360,
        repeats=7,
        toggle_points=43,
        newton_offsets=16,
        newton_trials=32,
        scaling_quick=False,
        loops_positions=360,
        peer_big=10**5,
    ),
    "quick": dict(
        positions=72,
        repeats=3,
        toggle_points=23,
        newton_offsets=10,
        newton_trials=12,
        scaling_quick=True,
        loops_positions=72,
        peer_big=10**4,
    ),
    "tiny": dict(
        positions=16,
        repeats=1,
        toggle_points=7,
        newton_offsets=3,
        newton_trials=3,
        scaling_quick=True,
        loops_positions=8,
        peer_big=None,
    ),
}

GOALS = {
    "kernel_speed": 0.2,  # [us/position] fourbar to jerk, unit-free, 10^5 positions
    "units_ratio": 1.5,  # unit-aware / unit-free at 360 positions
    "units_single": 100.0,  # [us] one unit-aware solve
    "accuracy": 1e-13,  # worst relative error away from limit positions
    "loops_speed": 50.0,  # [us/position] sixbar, general solver, to jerk
}


def _clean(x):
    """JSON-safe: numpy scalars to Python, NaN/inf to None."""
    if isinstance(x, dict):
        return {str(k): _clean(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_clean(v) for v in x]
    if isinstance(x, np.ndarray):
        return _clean(x.tolist())
    if isinstance(x, (np.floating, float)):
        x = float(x)
        return x if math.isfinite(x) else None
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    return x


def cycle_results(cases, method_list, n, repeats, ref_dir, log):
    """Every case by every method on its cycle of ``n`` positions."""
    rows = []
    _warm_up(cases, n)
    for case in cases.values():
        theta2 = case.theta2(n)
        ref = cached(case, theta2, ref_dir)
        scale = accuracy.scales(ref)
        for m in method_list:
            row = {
                "case": case.name,
                "method": m.key,
                "label": m.label,
                "family": m.family,
                "order": m.order,
                "setting": m.setting,
                "positions": n,
            }
            try:
                run, extract = m.prepare(case, theta2)
                with np.errstate(all="ignore"):
                    t = measure(run, repeats=repeats, min_time=0.02)
                    values = extract(t.pop("result"))
            except NotApplicable as exc:
                rows.append(dict(row, skipped=str(exc)))
                continue
            except Exception as exc:  # a peer that fails on a case is reported, not fatal
                if not m.family.startswith("peer"):
                    raise
                rows.append(dict(row, skipped=f"failed: {type(exc).__name__}: {exc}"))
                log(f"  {case.name:27s} {m.key:14s} failed: {exc}")
                continue
            errs = accuracy.relative_errors(values, ref, scale)
            s = accuracy.summary(errs)
            row.update(us_per_position=t["median"] / n * 1e6, time_s=t, outputs=sorted(errs), **s)
            rows.append(row)
            log(
                f"  {case.name:27s} {m.key:14s} {row['us_per_position']:10.3f} us/pos   "
                f"worst {_fmt(s['worst'])}  refused {s['flagged']}/{n}"
            )
    return rows


def _warm_up(cases, n, seconds=1.0):
    """Run the closed forms for about a second before timing anything: the
    first measurements of a fresh process otherwise come out slow (caches,
    the CPU's clock ramping up)."""
    t0 = time.perf_counter()
    work = [(c, c.theta2(n)) for c in cases.values() if c.mechanism != "loops"]
    while work and time.perf_counter() - t0 < seconds:
        for case, theta2 in work:
            case.kernel(theta2)


def _fmt(x):
    return "   -    " if x is None else f"{x:.2e}"


def peer_comparison(n_values, repeats):
    """The fourbar on the peers' work (position to acceleration), ours and
    theirs, timed in turn within each repeat."""
    from .timing import measure_interleaved

    cases = all_cases()
    case = cases["fourbar-open"]
    table = {m.key: m for m in methods()}
    out = []
    for n in n_values:
        t2 = case.theta2(n)
        fns = [lambda t2=t2: case.kernel(t2, order=2), lambda t2=t2: case.kernel(t2)]
        keys = []
        for key in ("pylinkage", "mechanism"):  # kimech (ms per position): see the cycles
            if key in table and (key == "pylinkage" or n <= 1000):
                run, _ = table[key].prepare(case, t2)
                fns.append(run)
                keys.append(key)
        res = measure_interleaved(fns, repeats=repeats, min_time=0.01)
        row = {
            "N": n,
            "kernels_to_acceleration_us": res[0]["median"] / n * 1e6,
            "kernels_to_jerk_us": res[1]["median"] / n * 1e6,
        }
        for key, r in zip(keys, res[2:]):
            row[f"{key}_us"] = r["median"] / n * 1e6
            row[f"{key}_over_ours"] = r["ratio"]  # their time / ours, median per repeat
        out.append(row)
    return out


def goals(data):
    """The issue's goals against the measured figures."""
    res = [r for r in data["results"] if r.get("worst") is not None or r.get("flagged")]
    out = []

    def add(goal, target, measured, met, note=""):
        out.append({"goal": goal, "target": target, "measured": measured, "met": met, "note": note})

    pos = data["scaling"]["positions"].get("kernels", {}).get("points", [])
    big = [p for p in pos if p["N"] == 10**5]
    if big:
        us = big[0]["us"]
        add(
            "fourbar position to jerk, unit-free, 10^5 positions [us/position]",
            f"<= {GOALS['kernel_speed']}",
            round(us, 4),
            us <= GOALS["kernel_speed"],
            f"fastest repeat {big[0].get('us_min', us):.3g}",
        )
    peers = data.get("peer_comparison") or []
    if peers:
        verdicts = []
        met = True
        for row in peers:
            for key in ("pylinkage", "mechanism", "kimech"):
                if f"{key}_us" in row:
                    ours = row["kernels_to_acceleration_us"]
                    ratio = row.get(f"{key}_over_ours") or row[f"{key}_us"] / ours
                    met &= ratio > 1
                    verdicts.append(
                        f"N={row['N']}: ours {ours:.3g} vs {key} "
                        f"{row[key + '_us']:.3g} us/pos ({ratio:.3g}x)"
                    )
        for r in data["results"]:
            if r["case"] == "fourbar-open" and r["method"] == "kimech" and r.get("worst"):
                ours = next(
                    x
                    for x in data["results"]
                    if x["case"] == "fourbar-open" and x["method"] == "kernels"
                )["us_per_position"]
                met &= ours < r["us_per_position"]
                verdicts.append(
                    f"N={r['positions']} (cycle, ours to jerk): ours {ours:.3g} vs "
                    f"kimech {r['us_per_position']:.3g} us/pos"
                )
        if verdicts:
            add(
                "fourbar faster than every peer on the same work (position to acceleration)",
                "faster",
                "; ".join(verdicts),
                met,
            )
    units = {r["N"]: r for r in data["units"]["rows"]}
    if 360 in units:
        u = units[360]
        add(
            "unit-aware / unit-free time, 360 positions",
            f"<= {GOALS['units_ratio']}",
            round(u["ratio"], 3),
            u["ratio"] <= GOALS["units_ratio"],
            f"{u['unit_aware_us']:.0f} against {u['unit_free_us']:.0f} us per call; fastest "
            f"repeats {u.get('unit_aware_min_us', 0):.0f} against "
            f"{u.get('unit_free_min_us', 0):.0f} us",
        )
    if 1 in units:
        us = units[1]["unit_aware_us"]
        add(
            "one unit-aware solve, position to jerk [us]",
            f"<= {GOALS['units_single']}",
            round(us, 1),
            us <= GOALS["units_single"],
            f"fastest repeat {units[1].get('unit_aware_min_us', us):.0f} us; unit-free kernel "
            f"alone: {units[1]['unit_free_us']:.1f} us; with string inputs "
            f"{data['units']['single_string_inputs_us']:.1f} us",
        )
    closed = [r for r in res if r["method"] in ("kernels", "units")]
    if closed:
        worst = max(r["worst"] for r in closed if r["worst"] is not None)
        where = max((r for r in closed if r["worst"] is not None), key=lambda r: r["worst"])
        refused = sum(r["flagged"] for r in closed)
        add(
            "worst relative error away from limit positions, every output to jerk "
            "(closed forms, all closed-form cases)",
            f"<= {GOALS['accuracy']:g}",
            float(f"{worst:.3g}"),
            worst <= GOALS["accuracy"] and refused == 0,
            f"worst in {where['case']}; cycles stop {math.degrees(CYCLE_MARGIN):g} deg from "
            f"toggles; {refused} positions refused",
        )
    six = [r for r in res if r["case"].startswith("sixbar") and r["method"] == "loops"]
    for r in six:
        loose = [x for x in res if x["case"] == r["case"] and x["method"].startswith("loops-")]
        note = (
            f"{r['positions']} positions of a full turn, default tolerance, fastest repeat "
            f"{r['time_s']['min'] / r['positions'] * 1e6:.1f} us"
        )
        if loose:
            best = min(loose, key=lambda x: x["us_per_position"])
            note += (
                f"; fastest setting {best['method']}: {best['us_per_position']:.1f} us, "
                f"worst error {_fmt(best['worst']).strip()}"
            )
        add(
            f"general solver, {r['case']}, position to jerk [us/position]",
            f"<= {GOALS['loops_speed']}",
            round(r["us_per_position"], 1),
            r["us_per_position"] <= GOALS["loops_speed"],
            note,
        )
    return out


def run_benchmark(
    out, mode="quick", figures=None, peers=True, charts=True, log=print, formats=("png", "svg")
):
    """Run everything and write ``out/bench.json`` and the charts.

    Parameters
    ----------
    out : str
        Output directory (also holds the reference cache, ``out/reference``).
    mode : {'quick', 'full', 'tiny'}
        ``full`` (360 positions per cycle, 7 repeats, up to 10^6 positions),
        ``quick`` (72 positions, 3 repeats, up to 10^5: under a minute),
        ``tiny`` (the tests' smoke run).
    figures : str, optional
        Where the charts go (default: ``out``).
    peers : bool
        Measure the peer packages if installed.
    charts, formats
        Draw the charts, in these formats.
    """
    cfg = MODES[mode]
    t_start = time.perf_counter()
    os.makedirs(out, exist_ok=True)
    ref_dir = os.path.join(out, "reference")
    cases = all_cases()
    method_list = methods(include_peers=peers)
    data = {
        "version": 1,
        "mode": mode,
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": machine(),
        "config": dict(
            cfg,
            reference_dps=DPS,
            cycle_margin_deg=math.degrees(CYCLE_MARGIN),
            loop_tolerance_parameter=loop_tolerance_parameter(),
        ),
        "error_measure": accuracy.__doc__.strip(),
        "cases": [],
        "methods": [m.describe() for m in method_list],
    }
    for case in cases.values():
        data["cases"].append(
            {
                "name": case.name,
                "title": case.title,
                "mechanism": case.mechanism,
                "circuit": case.circuit,
                "positions": cfg["positions"],
                "span_rad": list(case.span),
                "full_turn": case.full_turn,
                "limits_rad": case.limits,
                "loops": len(case.loops),
                "outputs": list(case.outputs),
            }
        )
    data["peers"] = {
        "installed": installed() if peers else {},
        "notes": {
            "kimech": [
                "body coordinates solved with scipy, to acceleration; measured on the fourbars"
            ],
            "pylinkage": [SLIDER_NOTE, RANGE_NOTE],
            "mechanism": [
                "solves position, velocity and acceleration by "
                "scipy.optimize.fsolve at every position; no jerk; "
                "measured on the fourbars and the slider-crank"
            ],
        },
    }
    if loop_tolerance_parameter() is None:
        data["peers"]["notes"]["loops"] = (
            "accelab.solver.VectorLoopLinkage.solve has no convergence "
            "tolerance argument yet: measured at its default"
        )
    log(
        f"accelab bench ({mode}): {len(cases)} cases x {len(method_list)} methods, "
        f"{cfg['positions']} positions per cycle"
    )
    data["results"] = cycle_results(
        cases, method_list, cfg["positions"], cfg["repeats"], ref_dir, log
    )
    log("stability near a toggle ...")
    st_methods = ("kernels", "loops", "fd", "graphical") + (
        ("mechanism", "kimech") if peers else ()
    )
    st = stability.near_toggle(n=cfg["toggle_points"], methods=st_methods, cache_dir=ref_dir)
    st["title"] = cases[st["case"]].title
    st["thresholds"] = _thresholds(st)
    data["stability"] = st
    log("Newton-Raphson against its starting guess ...")
    offsets = np.logspace(-3, math.log10(math.pi), cfg["newton_offsets"])
    data["newton"] = stability.newton_guesses(offsets=offsets, trials=cfg["newton_trials"])
    log("scaling ...")
    quick = cfg["scaling_quick"]
    data["scaling"] = {
        "positions": scaling.positions(
            repeats=max(cfg["repeats"], 3), quick=quick, peers=peers, tiny=mode == "tiny"
        ),
        "loops": scaling.loops(n=cfg["loops_positions"], repeats=max(cfg["repeats"], 2)),
        "loops_positions": cfg["loops_positions"],
    }
    data["units"] = scaling.units(
        sizes=(1, 360) if mode == "tiny" else (1, 360, 10**5), repeats=max(cfg["repeats"], 3)
    )
    if peers and installed():
        sizes = [cfg["positions"]] + ([cfg["peer_big"]] if cfg["peer_big"] else [])
        data["peer_comparison"] = peer_comparison(sizes, repeats=max(cfg["repeats"], 3))
    data["goals"] = goals(data)
    data["elapsed_s"] = time.perf_counter() - t_start
    data = _clean(data)
    path = os.path.join(out, "bench.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
    log(f"wrote {path}")
    if charts:
        from .charts import draw_all

        for p in draw_all(data, figures or out, formats):
            log(f"wrote {p}")
    for g in data["goals"]:
        log(
            f"  [{'met ' if g['met'] else 'MISS'}] {g['goal']}: {g['measured']} "
            f"(goal {g['target']})"
        )
    log(f"done in {time.perf_counter() - t_start:.1f} s")
    return data


def _thresholds(st):
    """Where the closed forms start refusing, and where their condition
    measure crosses the solver's SINGULAR_CONDITION, on the distance axis."""
    from accelab.solver.kernels import common
    from accelab.solver.vectorloops import SINGULAR_CONDITION

    out = {}
    d = stability.threshold_distance(st, "kernels")
    if d:
        out["kernels"] = d
        out["kernels_text"] = (
            f"closed forms refuse below here\n(estimated round-off > {common.MAX_ROUNDOFF:g})"
        )
    delta = np.asarray(st["delta"])
    cond = np.asarray(st["condition"], dtype=float)
    ok = np.isfinite(cond) & (cond > 0)
    if ok.sum() > 2:
        # condition ~ k sqrt(delta) near the toggle: fit k on the nearest points
        near = ok & (delta < 1e-3)
        if near.sum() >= 2:
            k = float(np.median(cond[near] / np.sqrt(delta[near])))
            out["condition"] = (SINGULAR_CONDITION / k) ** 2
            out["condition_text"] = f"condition = SINGULAR_CONDITION\n({SINGULAR_CONDITION:g})"
    errs = st["methods"].get("kernels", {}).get("errors", [])
    answered = [(x, e) for x, e in zip(delta, errs) if e is not None]
    if answered:
        out["kernels_worst_answered"] = max(e for _, e in answered)
        out["kernels_nearest_answered"] = min(x for x, _ in answered)
        within = [x for x, e in answered if e <= GOALS["accuracy"]]
        out["kernels_goal_distance"] = min(within) if within else None
        # the farthest distance where the error exceeds the goal
        beyond = [x for x, e in answered if e > GOALS["accuracy"]]
        out["kernels_error_exceeds_goal_below"] = max(beyond) if beyond else None
    return out


__all__ = ["run_benchmark", "MODES", "GOALS", "ORDER_WORDS"]
