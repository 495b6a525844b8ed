"""accelab.solver.vectorloops.solve: singular positions carry their condition measure."""

import json

import pytest
from _vectorloops_helpers import fourbar_desc

from accelab.solver.errors import Singular
from accelab.solver.vectorloops import (
    SINGULAR_CONDITION,
    VectorLoopLinkage,
)
from accelab.solver.vectorloops import (
    solve_loops_case as solve_case,
)


def test_singular_carries_the_condition_number():
    # a parallelogram at its change point: every link on the x axis at theta2 = 0
    desc = fourbar_desc(1.0, 3.0, 1.0, 3.0, 0.05, 0.09)
    with pytest.raises(Singular) as info:
        VectorLoopLinkage(**desc).solve(theta2="0 deg", omega2="1 rad/s")
    assert 0 <= info.value.condition < SINGULAR_CONDITION
    assert "condition number" in str(info.value)
    res = solve_case(
        dict(
            json.loads(json.dumps(desc)),
            mechanism="loops",
            theta2="0 deg",
            omega2="1 rad/s",
            alpha2="0 rad/s^2",
        )
    )
    assert res["ok"] is False and res["error"] == "singular"
