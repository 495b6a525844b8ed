"""How cost grows with the work, and what units cost.

* :func:`positions` -- time per position against the number of positions
  (1 .. 10^6) for the fourbar, position to jerk (position to acceleration
  for the peers, which stop there), per method;
* :func:`loops` -- time per position of the general solver against the
  number of loops (fourbar 1, sixbar 2, eightbar 3);
* :func:`units` -- the unit-aware API against the unit-free layer at 1, 360
  and 10^5 positions.

All on the case ``fourbar-open`` of :mod:`.cases` unless said otherwise.
"""

import numpy as np

from .cases import all_cases, from_example
from .methods import NotApplicable, methods, unit_inputs, unit_mechanism
from .timing import measure

#: largest N each method is timed at (the slow ones stop early), full and quick
MAX_N = {
    "kernels": 10**6,
    "kernels-o2": 10**6,
    "units": 10**6,
    "scalar": 10**4,
    "loops": 10**4,
    "pylinkage": 10**6,
    "mechanism": 10**3,
    "kimech": 100,
}
QUICK_MAX_N = {
    "kernels": 10**5,
    "kernels-o2": 10**5,
    "units": 10**5,
    "scalar": 100,
    "loops": 1000,
    "pylinkage": 10**5,
    "mechanism": 10,
    "kimech": 10,
}
TINY_MAX_N = 100


def _sizes(max_n):
    return [n for n in (1, 10, 100, 1000, 10**4, 10**5, 10**6) if n <= max_n]


def positions(repeats=5, case_name="fourbar-open", quick=False, peers=True, tiny=False):
    """Time per position [us] against the number of positions, per method.

    At each number of positions the methods are timed in turn within each
    repeat (:func:`.timing.measure_interleaved`), so that other jobs on the
    machine do not tilt the comparison.

    Returns dict method key -> {"label", "order", "points": [{"N", "us", "us_min"}]}.
    """
    from .timing import measure_interleaved

    case = all_cases()[case_name]
    table = {m.key: m for m in methods(include_peers=peers)}
    chosen = (
        ["kernels", "units", "scalar"]
        + [k for k in table if k.startswith("loops")][:1]
        + [k for k in ("pylinkage", "mechanism", "kimech") if k in table]
        + ["kernels-o2"]
    )
    out, limits = {}, {}
    for key in chosen:
        m = table.get(key)
        out[key] = {
            "label": m.label if m else "closed forms, unit-free, to acceleration",
            "order": m.order if m else 2,
            "points": [],
        }
        family = key.split("-")[0] if key.startswith("loops") else key
        limits[key] = min((QUICK_MAX_N if quick else MAX_N)[family], TINY_MAX_N if tiny else 10**6)
    for n in _sizes(max(limits.values())):
        t2 = case.theta2(n)
        keys, fns = [], []
        for key in chosen:
            if n > limits[key]:
                continue
            try:
                fns.append(_runner(key, table.get(key), case, t2))
                keys.append(key)
            except NotApplicable:
                limits[key] = 0
        res = measure_interleaved(fns, repeats=repeats, min_time=0.02 if n < 10**5 else 0.0)
        for key, r in zip(keys, res):
            out[key]["points"].append(
                {"N": n, "us": r["median"] / n * 1e6, "us_min": r["min"] / n * 1e6}
            )
    return out


def _runner(key, m, case, t2):
    """The timed work of ``key`` at the crank angles ``t2`` (one angle: scalar input)."""
    if len(t2) == 1:
        x = float(t2[0])
        if key == "kernels":
            return lambda: case.kernel(x)
        if key == "kernels-o2":
            return lambda: case.kernel(x, order=2)
        if key == "units":
            return _unit_scalar(case, x)
    if key == "kernels-o2":
        return lambda: case.kernel(t2, order=2)
    run, _ = m.prepare(case, t2)
    return run


def _unit_scalar(case, theta2):
    mech = unit_mechanism(case)
    inputs = unit_inputs(theta2)
    names = [k for k in case.outputs]

    def run():
        r = mech.solve(**inputs, circuit=case.circuit)
        return {k: getattr(r, k) for k in names}

    return run


def units(sizes=(1, 360, 10**5), repeats=7, case_name="fourbar-open"):
    """Unit-aware against unit-free time [us per call] at each size, timed
    in turn within each repeat (:func:`.timing.measure_interleaved`); the
    ratio is the median of the per-repeat ratios.

    The unit-aware work: ``FourBar.solve`` with Quantity inputs (built
    beforehand) and every output read as a Quantity; the unit-free work:
    ``accelab.solver.kernels.fourbar.solve`` on floats. Also a single solve with
    string inputs (``theta2="30 deg"``), parsed by pint each time.
    """
    from .timing import measure_interleaved

    case = all_cases()[case_name]
    rows = []
    for n in sizes:
        t2 = case.theta2(n) if n > 1 else float(case.theta2(2)[1])
        free, aware = measure_interleaved(
            [lambda t2=t2: case.kernel(t2), _unit_scalar(case, t2)], repeats=repeats
        )
        rows.append(
            {
                "N": n,
                "unit_free_us": free["median"] * 1e6,
                "unit_aware_us": aware["median"] * 1e6,
                "ratio": aware["ratio"],
                "unit_free_min_us": free["min"] * 1e6,
                "unit_aware_min_us": aware["min"] * 1e6,
            }
        )
    mech = unit_mechanism(case)
    names = list(case.outputs)

    def strings():
        r = mech.solve(
            theta2="30 deg",
            omega2="10 rad/s",
            alpha2="-5 rad/s^2",
            jerk2="20 rad/s^3",
            circuit=case.circuit,
        )
        return {k: getattr(r, k) for k in names}

    single_str = measure(strings, repeats=repeats)["median"]
    return {"rows": rows, "single_string_inputs_us": single_str * 1e6}


def loops(n=360, repeats=5):
    """Time per position [us] of the general solver against the number of
    loops, position to jerk, over ``n`` positions of a full crank turn."""
    from accelab.solver import VectorLoopLinkage
    from accelab.solver.units import Q_
    from accelab.solver.vectorloops.examples import fourbar as fourbar_example

    from .cases import description

    cases = all_cases()
    chain = [
        from_example("fourbar-loops", "fourbar (1 loop)", fourbar_example()),
        cases["sixbar-watt2"],
        cases["sixbar-slider"],
        cases["eightbar"],
    ]
    from .timing import measure_interleaved

    runs = []
    for case in chain:
        linkage = VectorLoopLinkage(**description(case))
        inputs = unit_inputs(case.theta2(n))
        inputs["theta2"] = Q_(case.theta2(n), "rad")
        runs.append(lambda linkage=linkage, inputs=inputs: linkage.solve(**inputs))
    times = measure_interleaved(runs, repeats=repeats, min_time=0.0)
    rows = []
    for case, run, r in zip(chain, runs, times):
        res = run()
        rows.append(
            {
                "case": case.name,
                "title": case.title,
                "loops": len(case.loops),
                "unknowns": 2 * len(case.loops),
                "us": r["median"] / n * 1e6,
                "us_min": r["min"] / n * 1e6,
                "valid": int(np.sum(res.valid)),
                "mean_iterations": float(np.mean(res.iterations)),
            }
        )
    return rows
