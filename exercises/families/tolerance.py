"""Human tolerance of acceleration (section 7.6, Table 7-1).

A passenger sits at radius R on the arm of an amusement ride that turns at
omega and is spinning up with alpha. Graded: the passenger's acceleration
expressed in g (standard gravity, 9.80665 m/s^2), and a judgement of it
against the everyday levels of Table 7-1.
"""

from ..problem import Answer, Problem
from .common import UNITS, Reject, draw_value, first_accepted, fmt, ranges_for, solve_checked

FAMILY = "tolerance"
TITLE = "Human tolerance: an amusement ride"
G0 = 9.80665  # [m/s^2] standard gravity
#: upper ends [g] of the verdicts (Table 7-1: hard automobile acceleration 0.5 g,
#: roller coaster 3.5 g, F-16 jet 9 g)
LEVELS = [0.5, 3.5, 9.0]
CHOICES = ["gentle", "strong", "extreme", "intolerable"]
DEFAULTS = {
    "R": (10.0, 60.0, 1.0, "big_length"),
    "omega": (4.0, 24.0, 1.0, "rpm"),
    "alpha": (0.1, 2.0, 0.1, "alpha"),
}
STATEMENT = (
    "A passenger of an amusement ride sits at the end of an arm of length $R$ that turns "
    "about a fixed vertical axis at $\\omega$ and is still speeding up with the angular "
    "acceleration $\\alpha$. Ignore gravity (the arm turns in a horizontal plane). "
    "Express the magnitude of the passenger's acceleration in g (standard gravity, "
    '9.80665 m/s$^2$), and judge it against Table 7-1: `"gentle"` below 0.5 g (like '
    'accelerating a car), `"strong"` from 0.5 g up to 3.5 g (panic stop to roller '
    'coaster), `"extreme"` from 3.5 g up to 9 g (beyond a roller coaster: fit, trained '
    'people only), `"intolerable"` from 9 g up.'
)


def generate_problem(seed, ranges=None, units="US"):
    defaults = dict(DEFAULTS)
    # the arm is in feet (US) or metres (SI): scale the foot range to round metres
    if units == "SI":
        defaults["R"] = (3.0, 18.0, 0.5, "big_length")
    else:
        defaults["R"] = (10.0, 60.0, 1.0, "big_length")
    r = ranges_for(defaults, ranges, units)
    big = UNITS[units]["big_length"]

    def build(rng):
        R = draw_value(rng, r["R"], nonzero=True)
        omega = draw_value(rng, r["omega"], nonzero=True)
        alpha = draw_value(rng, r["alpha"], nonzero=True)
        case = {
            "mechanism": "rotation",
            "p": fmt(R, big),
            "theta2": "0 deg",
            "omega2": fmt(omega, "rpm"),
            "alpha2": fmt(alpha, "rad/s^2"),
        }
        out = solve_checked({"R": case})
        g = abs(complex(*out["R"]["A"])) / G0
        if any(abs(g - level) < 0.05 * level for level in LEVELS) or g < 0.05:
            raise Reject()  # too near a boundary to judge fairly within the tolerance
        answers = [
            Answer(
                "A_g",
                "g_0",
                "magnitude of the passenger's acceleration in g",
                {"R": case},
                "abs(R.A)",
            ),
            Answer(
                "verdict",
                "",
                "one of " + ", ".join(f'"{c}"' for c in CHOICES),
                {"R": case},
                kind="choice",
                choices=list(CHOICES),
                basis="abs(R.A)",
                bins=[level * G0 for level in LEVELS],
            ),
        ]
        given = {"R": fmt(R, big), "omega": fmt(omega, "rpm"), "alpha": fmt(alpha, "rad/s^2")}
        return Problem(
            FAMILY, TITLE, STATEMENT, given, answers, figure={"mechanism": "rotation", "case": case}
        )

    return first_accepted(FAMILY, seed, build, units)
