"""Coriolis acceleration in the inverted slider-crank (section 7.3, eqs. 7.21): the
block on link 3 slides along link 4; graded are alpha4, the Coriolis component
2 b_dot omega3 j e^{j theta3} (eq. 7.21c) and the slip acceleration b_ddot."""

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

FAMILY = "coriolis"
TITLE = "Coriolis acceleration in an inverted slider-crank"
DEFAULTS = {
    "a": (1.0, 4.0, 0.5, "length"),
    "c": (0.0, 2.0, 0.5, "length"),
    "d": (4.0, 10.0, 0.5, "length"),
    "gamma": (60.0, 120.0, 5.0, "angle"),
    "theta2": (0.0, 355.0, 5.0, "angle"),
    "omega2": (5.0, 50.0, 5.0, "omega"),
    "alpha2": (5.0, 100.0, 5.0, "alpha"),
}
STATEMENT = (
    "An inverted slider-crank has crank $a$ (link 2) pinned at the origin and ground link "
    "$d$ along x to the pivot of link 4. The block (link 3), pinned to the crank at A, slides "
    "along link 4; $c$ is the perpendicular offset of the slide from the pivot and $\\gamma$ "
    "the constant angle between links 3 and 4, in the given circuit. The crank is at "
    "$\\theta_2$ with $\\omega_2$ and $\\alpha_2$. Find the angular acceleration of link 4, "
    "the magnitude of the Coriolis component of the acceleration of the block (eq. 7.21c), "
    "and the slip acceleration $\\ddot b$ along the slide (positive as $b$ grows)."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L, acc = UNITS[units]["length"], UNITS[units]["acceleration"]

    def build(rng):
        case = {
            "mechanism": "invertedslidercrank",
            "a": fmt(draw_value(rng, r["a"], nonzero=True), L),
            "c": fmt(draw_value(rng, r["c"]), L),
            "d": fmt(draw_value(rng, r["d"], nonzero=True), L),
            "gamma": fmt(draw_value(rng, r["gamma"], nonzero=True), "deg"),
            "theta2": fmt(draw_value(rng, r["theta2"]), "deg"),
            "omega2": fmt(draw_value(rng, r["omega2"], nonzero=True, signed=True), "rad/s"),
            "alpha2": fmt(draw_value(rng, r["alpha2"], nonzero=True, signed=True), "rad/s^2"),
            "circuit": "open" if rng.random() < 0.5 else "crossed",
        }
        out = solve_checked({"K": case})["K"]
        A_A = abs(complex(*out["A_A"]))
        sizable(
            (out["alpha4"], max(abs(out["alpha4"]), out["omega4"] ** 2 + 1.0)),
            (abs(complex(*out["A_coriolis"])), A_A),
            (out["b_ddot"], A_A),
        )
        k = {"K": case}
        answers = [
            Answer("alpha4", "rad/s^2", "angular acceleration of link 4", k, "K.alpha4"),
            Answer(
                "A_cor_mag", acc, "magnitude of the Coriolis acceleration", k, "abs(K.A_coriolis)"
            ),
            Answer("b_ddot", acc, "slip acceleration along the slide", k, "K.b_ddot"),
        ]
        return Problem(
            FAMILY,
            TITLE,
            STATEMENT,
            given_of(case, ["a", "c", "d", "gamma", "theta2", "omega2", "alpha2", "circuit"]),
            answers,
            figure={"mechanism": "invertedslidercrank", "case": case},
        )

    return first_accepted(FAMILY, seed, build, units)
