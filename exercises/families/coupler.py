"""A coupler point of the fourbar (eq. 7.32): A_P of the point P at distance p from
A, at angle delta3 from line AB on the coupler."""

from ..problem import Answer, Problem
from .common import (
    FOURBAR_DEFAULTS,
    UNITS,
    draw_value,
    first_accepted,
    fmt,
    fourbar_case,
    given_of,
    ranges_for,
    sizable,
    solve_checked,
)

FAMILY = "coupler"
TITLE = "Acceleration of a coupler point"
DEFAULTS = dict(FOURBAR_DEFAULTS, p=(1.0, 6.0, 0.5, "length"), delta3=(-90.0, 90.0, 5.0, "angle"))
STATEMENT = (
    "A fourbar linkage ($a$ crank, $b$ coupler, $c$ rocker, $d$ ground along x, in the given "
    "circuit) carries a coupler point P at distance $p$ from the crank pin A, at the angle "
    "$\\delta_3$ from line AB (counter-clockwise positive). The crank is at $\\theta_2$ with "
    "$\\omega_2$ and $\\alpha_2$. Find the coupler's angular acceleration and the "
    "acceleration of P (eq. 7.32) in polar form."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L, acc = UNITS[units]["length"], UNITS[units]["acceleration"]

    def build(rng):
        case = fourbar_case(rng, r, L)
        case["p"] = fmt(draw_value(rng, r["p"], nonzero=True), L)
        case["delta3"] = fmt(draw_value(rng, r["delta3"]), "deg")
        out = solve_checked({"C": case})["C"]
        A_P = complex(*out["A_P"])
        sizable(
            (A_P, complex(*out["A_A"])),
            (out["alpha3"], max(abs(out["alpha3"]), out["omega3"] ** 2 + 1.0)),
        )
        c = {"C": case}
        answers = [
            Answer("alpha3", "rad/s^2", "angular acceleration of the coupler", c, "C.alpha3"),
            Answer("A_P_mag", acc, "magnitude of the acceleration of P", c, "abs(C.A_P)"),
            Answer(
                "A_P_ang",
                "deg",
                "direction of the acceleration of P",
                c,
                "angle(C.A_P)",
                kind="angle",
            ),
        ]
        given = given_of(
            case, ["a", "b", "c", "d", "p", "delta3", "theta2", "omega2", "alpha2", "circuit"]
        )
        return Problem(
            FAMILY, TITLE, STATEMENT, given, answers, figure={"mechanism": "fourbar", "case": case}
        )

    return first_accepted(FAMILY, seed, build, units)
