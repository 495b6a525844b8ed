"""The geared fivebar (section 7.4, eqs. 7.28): alpha3 and alpha4 for a crank
driving link 5 through gears of ratio lam and phase phi."""

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

FAMILY = "fivebar"
TITLE = "Accelerations in a geared fivebar linkage"
DEFAULTS = {
    "a": (1.0, 3.0, 0.5, "length"),
    "b": (4.0, 9.0, 0.5, "length"),
    "c": (4.0, 9.0, 0.5, "length"),
    "d": (1.0, 3.0, 0.5, "length"),
    "f": (4.0, 9.0, 0.5, "length"),
    "phi": (0.0, 355.0, 5.0, "angle"),
    "theta2": (0.0, 355.0, 5.0, "angle"),
    "omega2": (5.0, 40.0, 5.0, "omega"),
    "alpha2": (5.0, 100.0, 5.0, "alpha"),
}
RATIOS = [-2.5, -2.0, -1.5, 1.5, 2.0, 2.5]
STATEMENT = (
    "A geared fivebar linkage has crank $a$ (link 2, pinned at the origin), links $b$ (3), "
    "$c$ (4) and $d$ (5, pinned at the end of the ground link $f$ along x), in the given "
    "circuit. Gears couple link 5 to the crank: $\\theta_5 = \\lambda \\theta_2 + \\phi$. The "
    "crank is at $\\theta_2$ with $\\omega_2$ and $\\alpha_2$. Find the angular accelerations "
    "of links 3 and 4."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L = UNITS[units]["length"]

    def build(rng):
        case = {"mechanism": "fivebar"}
        for k in "abcdf":
            case[k] = fmt(draw_value(rng, r[k], nonzero=True), L)
        case.update(
            lam=float(RATIOS[int(rng.integers(len(RATIOS)))]),
            phi=fmt(draw_value(rng, r["phi"]), "deg"),
            theta2=fmt(draw_value(rng, r["theta2"]), "deg"),
            omega2=fmt(draw_value(rng, r["omega2"], nonzero=True, signed=True), "rad/s"),
            alpha2=fmt(draw_value(rng, r["alpha2"], nonzero=True, signed=True), "rad/s^2"),
            circuit="open" if rng.random() < 0.5 else "crossed",
        )
        out = solve_checked({"F": case})["F"]
        scale = max(abs(out["alpha3"]), abs(out["alpha4"]), out["omega3"] ** 2 + 1.0)
        sizable((out["alpha3"], scale), (out["alpha4"], scale))
        f = {"F": case}
        answers = [
            Answer("alpha3", "rad/s^2", "angular acceleration of link 3", f, "F.alpha3"),
            Answer("alpha4", "rad/s^2", "angular acceleration of link 4", f, "F.alpha4"),
        ]
        return Problem(
            FAMILY,
            TITLE,
            STATEMENT,
            given_of(
                case,
                ["a", "b", "c", "d", "f", "lam", "phi", "theta2", "omega2", "alpha2", "circuit"],
            ),
            answers,
            figure={"mechanism": "fivebar", "case": case},
        )

    return first_accepted(FAMILY, seed, build, units)
