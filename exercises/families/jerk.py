"""Jerk in the fourbar (section 7.7, eqs. 7.34-7.37): the angular jerks of the
coupler and rocker and the linear jerk of B, for a crank with constant alpha2."""

from ..problem import Answer, Problem
from .common import (
    FOURBAR_DEFAULTS,
    UNITS,
    first_accepted,
    fourbar_case,
    given_of,
    ranges_for,
    sizable,
    solve_checked,
)

FAMILY = "jerk"
TITLE = "Jerk in a fourbar linkage"
DEFAULTS = FOURBAR_DEFAULTS
STATEMENT = (
    "A fourbar linkage ($a$ crank, $b$ coupler, $c$ rocker, $d$ ground along x, in the given "
    "circuit) is driven with the crank at $\\theta_2$, $\\omega_2$ and a constant "
    "$\\alpha_2$ (so the crank's angular jerk is zero). Find the angular jerks of the "
    "coupler and the rocker, and the magnitude of the linear jerk of the rocker pin B."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L, jerk = UNITS[units]["length"], UNITS[units]["jerk"]

    def build(rng):
        case = fourbar_case(rng, r, L)
        case["jerk2"] = "0 rad/s^3"
        out = solve_checked({"L": case})["L"]
        scale = max(abs(out["jerk3"]), abs(out["jerk4"]))
        sizable(
            (out["jerk3"], scale),
            (out["jerk4"], scale),
            (abs(complex(*out["J_B"])), abs(complex(*out["J_A"]))),
        )
        c = {"L": case}
        answers = [
            Answer("jerk3", "rad/s^3", "angular jerk of the coupler", c, "L.jerk3"),
            Answer("jerk4", "rad/s^3", "angular jerk of the rocker", c, "L.jerk4"),
            Answer("J_B_mag", jerk, "magnitude of the linear jerk of B", c, "abs(L.J_B)"),
        ]
        given = given_of(case, ["a", "b", "c", "d", "theta2", "omega2", "alpha2", "circuit"])
        return Problem(
            FAMILY, TITLE, STATEMENT, given, answers, figure={"mechanism": "fourbar", "case": case}
        )

    return first_accepted(FAMILY, seed, build, units)
