"""accelab.solver.vectorloops.joints: where two joints of a loop meet, right or refused.

A kite fourbar (a = d, b = c) as vector loops: at theta2 = theta1 the crank pin A sits on
the pivot O4 and links 3 and 4 fold onto each other. The motion stays smooth there, but
the direction of the diagonal from O4 to A is 0/0, and each derivative divides by its
length once more: at a Jacobian condition measure of 5e-4 (A 1e-3 m from O4) the jerk
came out 1.7e-4 of its scale off, and at 1.5e-4 2e-2 off, both answered as right (the
fixed SINGULAR_CONDITION, 1e-4, refused only nearer). Each case below is right against
the 50-digit reference within 2e-6 of its scale, or refused, saying which joints meet and
how far to move. So is the geared fivebar whose crank pins A and C meet.
"""

import math

import pytest

import accelab.benchmarks.reference as ref
from accelab.solver.vectorloops import solve_loops_case
from accelab.solver.vectorloops.joints import diagonals
from accelab.solver.vectorloops.solve import system_from_case

KITE = {"a": 1.0, "b": 2.0, "c": 2.0, "d": 1.0}
#: a kite whose links 3 and 4 are short beside the crank: the Jacobian's condition measure
#: stays 1e-2 where its jerk is already 3.6e-6 off
SHORT_KITE = {"a": 5.0, "b": 0.3, "c": 0.3, "d": 5.0}
#: |A - O4| over the lengths' sum beyond which refusing is wrong (refused within ~1e-3)
MUST_ANSWER = 2e-3
#: what an answer must meet, of its scale (as near a limit: tests/test_kernels_limits.py)
BOUND = 2e-6


def fourbar_loops(geo, theta1, theta2, guess3, guess4, omega2=1.0):
    a, b, c, d = (geo[k] for k in "abcd")
    return {
        "mechanism": "loops",
        "vectors": {
            "R1": {"length": f"{d!r} m", "angle": f"{theta1!r} rad"},
            "R2": {"length": f"{a!r} m", "angle": "input"},
            "R3": {"length": f"{b!r} m", "angle": "unknown", "guess": f"{guess3!r} rad"},
            "R4": {"length": f"{c!r} m", "angle": "unknown", "guess": f"{guess4!r} rad"},
        },
        "loops": ["R2 + R3 - R4 - R1"],
        "theta2": f"{theta2!r} rad",
        "omega2": f"{omega2!r} rad/s",
        "alpha2": "0 rad/s^2",
    }


def test_each_diagonal_of_a_loop_once():
    case = fourbar_loops(KITE, 0.0, 1.0, 1.0, 1.0)
    labels = sorted(label for label, _, _ in diagonals(system_from_case(case).model))
    # A to O4 by way of B (links 3 and 4, which turn with the unknowns); O2 to B runs along
    # the crank, and its end meeting the other divides by nothing
    assert labels == ["R3 - R4"], labels


@pytest.mark.parametrize(
    "geo, theta1",
    [(KITE, t) for t in (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 1e-5, 0.0)]
    + [(SHORT_KITE, t) for t in (2e-2, 1e-2, 3e-3, 1e-3, 6e-4, 1e-4, 0.0)],
    ids=lambda v: "short" if v is SHORT_KITE else "kite" if v is KITE else repr(v),
)
def test_a_pin_over_a_pivot_is_answered_right_or_refused(geo, theta1):
    near = ref.solve("fourbar", geo, 0.0, 1.0, 0.0, 0.0, max(theta1, 1e-2), "open")
    case = fourbar_loops(
        geo, theta1, 0.0, float(near["theta3"]) + 0.02, float(near["theta4"]) + 0.02
    )
    res = solve_loops_case(case)
    span = sum(geo.values())
    s = 2 * geo["a"] * math.sin(theta1 / 2)  # |A - O4|
    if not res["ok"]:
        assert res["error"] == "singular", res
        assert s < MUST_ANSWER * span, f"refused with |A - O4| = {s} m: {res['message']}"
        message = res["message"]
        assert "two joints of the loop 'R2 + R3 - R4 - R1' meet" in message, message
        assert "Move theta2 until the two joints are at least" in message, message
        assert "round-off in the jerk" in message, message
        return
    want = ref.solve("fourbar", geo, 0.0, 1.0, 0.0, 0.0, theta1, "open")
    for vector, n in (("R3", "3"), ("R4", "4")):
        got = res["vectors"][vector]
        assert math.isclose(got["angle"] % (2 * math.pi), float(want["theta" + n]) % (2 * math.pi))
        for key in ("omega", "alpha", "jerk"):
            exact = float(want[key + n])
            assert abs(got[key] - exact) <= BOUND * max(abs(exact), 1.0), (vector, key, got, exact)


def test_joints_meeting_where_the_equations_stay_well_conditioned_are_answered():
    """The other kite (a = b, c = d) has a branch on which B stays on the pivot O2 while
    link 3 turns with the crank: the diagonal O2-B is zero all along, but links 3 and 4 are
    not aligned and nothing divides by it. omega3 = omega2 and link 4 stands still."""
    geo = {"a": 1.0, "b": 1.0, "c": 2.0, "d": 2.0}
    theta2 = math.pi / 2
    case = fourbar_loops(geo, 0.0, theta2, theta2 + math.pi + 0.01, math.pi - 0.01, 3.0)
    res = solve_loops_case(case)
    assert res["ok"], res
    r3, r4 = res["vectors"]["R3"], res["vectors"]["R4"]
    assert math.isclose(r3["omega"], 3.0, rel_tol=1e-12)
    assert abs(r4["omega"]) < 1e-12 and abs(r4["alpha"]) < 1e-11 and abs(r4["jerk"]) < 1e-10


#: the geared fivebar whose crank pins A and C meet at theta2 = 0 (b = c, a = d, f = 2a)
FIVEBAR = {"a": 1.0, "b": 2.0, "c": 2.0, "d": 1.0, "f": 2.0, "lam": -2.0, "phi": math.pi}


@pytest.mark.parametrize("theta2", [1e-1, 1e-2, 3e-3, 1e-3, 1e-4, 1e-5])
def test_two_crank_pins_meeting_are_answered_right_or_refused(theta2):
    from accelab.solver.vectorloops.examples import fivebar

    far = ref.solve("fivebar", FIVEBAR, max(theta2, 1e-2), 1.0, 0.0, 0.0, 0.0, "open")
    desc = fivebar(
        **{k: f"{FIVEBAR[k]!r} m" for k in "abcdf"},
        lam=FIVEBAR["lam"],
        phi=f"{FIVEBAR['phi']!r} rad",
        guess3=f"{float(far['theta3']) + 0.02!r} rad",
        guess4=f"{float(far['theta4']) + 0.02!r} rad",
    )
    case = dict(desc, mechanism="loops", theta2=f"{theta2!r} rad", omega2="1 rad/s")
    res = solve_loops_case(dict(case, alpha2="0 rad/s^2"))
    if not res["ok"]:
        assert res["error"] == "singular", res
        assert theta2 < 1e-2, f"refused at {theta2} rad: {res['message']}"
        assert "two joints of the loop 'R2 + R3 - R4 - R5 - R1' meet" in res["message"], res
        return
    want = ref.solve("fivebar", FIVEBAR, theta2, 1.0, 0.0, 0.0, 0.0, "open")
    for vector, n in (("R3", "3"), ("R4", "4")):
        for key in ("omega", "alpha", "jerk"):
            exact = float(want[key + n])
            got = res["vectors"][vector][key]
            assert abs(got - exact) <= BOUND * max(abs(exact), 1.0), (vector, key, got, exact)
