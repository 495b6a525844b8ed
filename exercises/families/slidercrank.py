"""The offset slider-crank (section 7.3, eqs. 7.16-7.17): the coupler's angular
acceleration and the slider's acceleration."""

from ..problem import Answer, Problem
from .common import (
    UNITS,
    draw_value,
    first_accepted,
    fmt,
    given_of,
    ranges_for,
    sizable,
    solve_checked,
)

FAMILY = "slidercrank"
TITLE = "Accelerations in a slider-crank"
DEFAULTS = {
    "a": (1.0, 3.0, 0.5, "length"),
    "b": (5.0, 12.0, 0.5, "length"),
    "c": (-1.0, 1.0, 0.5, "length"),
    "theta2": (0.0, 355.0, 5.0, "angle"),
    "omega2": (10.0, 100.0, 10.0, "omega"),
    "alpha2": (10.0, 200.0, 10.0, "alpha"),
}
STATEMENT = (
    "An offset slider-crank has crank $a$, connecting rod $b$ and slider offset $c$ (the "
    "slider moves along the x axis, with its pin on the +x side of the crank pin). The crank "
    "is at $\\theta_2$ with $\\omega_2$ and $\\alpha_2$ (counter-clockwise positive). Find the "
    "connecting rod's angular acceleration and the slider's acceleration along x (positive "
    "toward +x)."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L, acc = UNITS[units]["length"], UNITS[units]["acceleration"]

    def build(rng):
        case = {
            "mechanism": "slidercrank",
            "a": fmt(draw_value(rng, r["a"], nonzero=True), L),
            "b": fmt(draw_value(rng, r["b"], nonzero=True), L),
            "c": fmt(draw_value(rng, r["c"]), L),
            "theta2": fmt(draw_value(rng, r["theta2"]), "deg"),
            "omega2": fmt(draw_value(rng, r["omega2"], nonzero=True, signed=True), "rad/s"),
            "alpha2": fmt(draw_value(rng, r["alpha2"], nonzero=True, signed=True), "rad/s^2"),
            "circuit": "open",
        }
        out = solve_checked({"S": case})["S"]
        sizable(
            (out["alpha3"], max(abs(out["alpha3"]), out["omega3"] ** 2 + 1.0)),
            (out["d_ddot"], abs(complex(*out["A_A"]))),
        )
        c = {"S": case}
        answers = [
            Answer(
                "alpha3", "rad/s^2", "angular acceleration of the connecting rod", c, "S.alpha3"
            ),
            Answer("A_slider", acc, "acceleration of the slider along x", c, "S.d_ddot"),
        ]
        return Problem(
            FAMILY,
            TITLE,
            STATEMENT,
            given_of(case, ["a", "b", "c", "theta2", "omega2", "alpha2"]),
            answers,
            figure={"mechanism": "slidercrank", "case": case},
        )

    return first_accepted(FAMILY, seed, build, units)
