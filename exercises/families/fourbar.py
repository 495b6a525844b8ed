"""The fourbar (section 7.3, eqs. 7.12): alpha3, alpha4, A_A and A_B for a given
crank position, angular velocity and angular acceleration."""

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

FAMILY = "fourbar"
TITLE = "Accelerations in a fourbar linkage"
DEFAULTS = FOURBAR_DEFAULTS
STATEMENT = (
    "A fourbar linkage has crank $a$ (link 2), coupler $b$ (link 3), rocker $c$ (link 4) and "
    "ground link $d$ along the x axis, in the given circuit. The crank is at $\\theta_2$ and "
    "turns with $\\omega_2$ and $\\alpha_2$ (counter-clockwise positive). Find the angular "
    "accelerations of the coupler and the rocker (eq. 7.12) and the accelerations of the "
    "crank pin A and the rocker pin B."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L, acc = UNITS[units]["length"], UNITS[units]["acceleration"]

    def build(rng):
        case = fourbar_case(rng, r, L)
        out = solve_checked({"L": case})["L"]
        w2 = abs(out["omega3"]) + abs(out["omega4"]) + 1.0
        scale = max(abs(out["alpha3"]), abs(out["alpha4"]), w2 * w2)
        sizable(
            (out["alpha3"], scale),
            (out["alpha4"], scale),
            (abs(complex(*out["A_B"])), abs(complex(*out["A_A"]))),
        )
        c = {"L": case}
        answers = [
            Answer("alpha3", "rad/s^2", "angular acceleration of the coupler", c, "L.alpha3"),
            Answer("alpha4", "rad/s^2", "angular acceleration of the rocker", c, "L.alpha4"),
            Answer("A_A_mag", acc, "magnitude of the acceleration of A", c, "abs(L.A_A)"),
            Answer("A_B_mag", acc, "magnitude of the acceleration of B", c, "abs(L.A_B)"),
            Answer(
                "A_B_ang",
                "deg",
                "direction of the acceleration of B",
                c,
                "angle(L.A_B)",
                kind="angle",
            ),
        ]
        given = given_of(case, ["a", "b", "c", "d", "theta2", "omega2", "alpha2", "circuit"])
        return Problem(
            FAMILY, TITLE, STATEMENT, given, answers, figure={"mechanism": "fourbar", "case": case}
        )

    return first_accepted(FAMILY, seed, build, units)
