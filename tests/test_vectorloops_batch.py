"""accelab.solver.vectorloops.batch: the batch contract's "loops" mechanism."""

import json

import numpy as np
import pytest
from _vectorloops_helpers import BATCH_MOTION, MOTION, xy

from accelab.solver.batch import solve_case as batch_solve
from accelab.solver.batch import solve_cases
from accelab.solver.vectorloops.examples import EXAMPLES, fivebar, fourbar


def test_batch_dispatches_loops_and_reports_every_vector():
    case = dict(EXAMPLES["sixbar_slider"](), mechanism="loops", **MOTION)
    res = batch_solve(case)
    assert res["ok"] and res["iterations"] >= 1
    assert set(res["vectors"]) == set(case["vectors"])
    assert {"length", "length_dot", "length_ddot", "length_dddot"} <= set(res["vectors"]["S"])
    assert set(res["points"]["D"]) == {"R", "V", "A", "J"}
    assert res["points"]["D"]["A"][1] == pytest.approx(0, abs=1e-9)  # D stays on its line
    json.dumps(res)


def test_batch_solves_loops_with_a_coupler_point_and_a_gear_ratio():
    geared = fivebar(lam=-2.5, phi="25 deg", guess3="60 deg", guess4="110 deg")
    geared["vectors"]["RP"] = {"length": "2.5 in", "angle": {"follow": "R3", "offset": "35 deg"}}
    geared["points"]["P"] = "R2 + RP"
    coupler = fourbar(p="3 in", delta3="40 deg")
    cases = [
        dict(geared, mechanism="loops", **BATCH_MOTION),
        {
            "mechanism": "fivebar",
            "a": "1 in",
            "b": "4 in",
            "c": "4 in",
            "d": "1 in",
            "f": "3 in",
            "lam": -2.5,
            "phi": "25 deg",
            **BATCH_MOTION,
        },
        {
            "mechanism": "fivebar",
            "a": "1 in",
            "b": "4 in",
            "c": "4 in",
            "d": "1 in",
            "f": "3 in",
            "lam": -2.5,
            "phi": "25 deg",
            "circuit": "crossed",
            **BATCH_MOTION,
        },
        dict(coupler, mechanism="loops", **BATCH_MOTION),
        {
            "mechanism": "fourbar",
            "a": "2 in",
            "b": "6 in",
            "c": "9 in",
            "d": "7 in",
            "p": "3 in",
            "delta3": "40 deg",
            **BATCH_MOTION,
        },
        dict(EXAMPLES["fourbar"](d="17 in"), mechanism="loops", **BATCH_MOTION),
        dict(coupler, mechanism="loops", colour="red", **BATCH_MOTION),
    ]
    out = json.loads(json.dumps(solve_cases(json.loads(json.dumps(cases)))))
    loops5, open5, crossed5, loops4, closed4, far, typo = out
    assert loops5["ok"] and open5["ok"] and crossed5["ok"], (loops5, open5, crossed5)
    closed = [
        c
        for c in (open5, crossed5)
        if abs(np.exp(1j * c["theta4"]) - np.exp(1j * loops5["vectors"]["R4"]["angle"])) < 1e-9
    ]
    assert len(closed) == 1
    closed = closed[0]
    for n in "345":
        for key in ("omega", "alpha", "jerk"):
            if key + n in closed:
                got, ref = loops5["vectors"]["R" + n][key], closed[key + n]
                assert got == pytest.approx(ref, rel=1e-8, abs=1e-8 * abs(closed["alpha3"]))
    for pt, key in (("B", "A_B"), ("C", "A_C"), ("A", "A_A")):
        assert abs(xy(loops5["points"][pt]["A"]) - xy(closed[key])) <= 1e-8 * abs(xy(closed[key]))
    # the coupler point P, as a rigid point of link 3 (eq. 7.32):
    # A_P = A_A + p (j alpha3 - omega3^2) e^{j(theta3 + delta)}
    p, delta = 2.5 * 0.0254, np.radians(35.0)
    a_p = xy(closed["A_A"]) + p * (1j * closed["alpha3"] - closed["omega3"] ** 2) * np.exp(
        1j * (closed["theta3"] + delta)
    )
    assert abs(xy(loops5["points"]["P"]["A"]) - a_p) <= 1e-8 * abs(a_p)
    # the fourbar's coupler point against the closed form's A_P and J_P
    assert loops4["ok"] and closed4["ok"]
    for key in ("A", "J"):
        ref = xy(closed4[key + "_P"])
        assert abs(xy(loops4["points"]["P"][key]) - ref) <= 1e-8 * abs(ref)
    assert far["ok"] is False and far["error"] == "not_assemblable" and "residual" in far["message"]
    assert typo["ok"] is False and typo["error"] == "invalid_input"
