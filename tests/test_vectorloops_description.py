"""accelab.solver.vectorloops.description: malformed descriptions say what is wrong."""

import json

import pytest
from _vectorloops_helpers import MOTION

from accelab.solver.vectorloops import solve_loops_case as solve_case
from accelab.solver.vectorloops.examples import EXAMPLES


@pytest.mark.parametrize(
    "change, words",
    [
        (lambda c: c["loops"].append("R2 + Q"), "unknown vector 'Q'"),
        (lambda c: c["loops"].pop(), "add or remove loops"),
        (lambda c: c["vectors"]["R3"].pop("guess"), "needs a guess"),
        (
            lambda c: (
                c["vectors"]["R5"].update(angle={"follow": "R6", "offset": "0 deg"})
                or c["vectors"]["R6"].update(angle={"follow": "R5"})
            ),
            "loops back on itself",
        ),
        (lambda c: c["vectors"]["R4C"].update(angle={"follow": "nope"}), "not a vector"),
        (lambda c: c["vectors"]["R2"].update(length="2 s"), "must be a length"),
        (lambda c: c["vectors"]["R2"].update(angle="0 deg"), "driven by the input"),
        (lambda c: c.update(colour="red"), "unknown key"),
        (lambda c: c["points"].update(E="R2 +"), "cannot read"),
    ],
)
def test_malformed_descriptions(change, words):
    case = dict(EXAMPLES["watt2_sixbar"](), mechanism="loops", **MOTION)
    case = json.loads(json.dumps(case))
    change(case)
    res = solve_case(case)
    assert res["ok"] is False and res["error"] == "invalid_input", res
    assert words in res["message"]


@pytest.mark.parametrize(
    "change, words",
    [
        (lambda c: c["points"].update(E="R2 + R9"), "unknown vector 'R9'"),
        (lambda c: c["vectors"]["RP"].update(angle={"follow": "R7"}), "follows 'R7'"),
        (
            lambda c: c["vectors"]["R1"].update(angle="unknown", guess="0 deg"),
            "3 unknowns (R1.angle, R3.angle, R4.angle)",
        ),
        (lambda c: c["vectors"]["R3"].update(angle={"follow": "RP"}), "R3 -> RP -> R3"),
        (lambda c: c["vectors"]["R4"].update(length="unknown"), "needs a guess length"),
        (lambda c: c["vectors"]["R4"].update(shape="round"), "unknown key(s) ['shape']"),
    ],
)
def test_malformed_descriptions_say_what_is_wrong(change, words):
    case = json.loads(
        json.dumps(
            dict(
                EXAMPLES["fourbar"](),
                mechanism="loops",
                theta2="30 deg",
                omega2="1 rad/s",
                alpha2="0 rad/s^2",
            )
        )
    )
    change(case)
    res = solve_case(case)
    assert res["ok"] is False and res["error"] == "invalid_input", res
    assert words in res["message"], res["message"]
