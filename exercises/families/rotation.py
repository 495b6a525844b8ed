"""Problem 7-1 style: a point on a body in pure rotation (section 7.1, eq. 7.2).

The point at radius p is at angle theta_A (position A) with angular velocity
omega and constant angular acceleration alpha; after dt it is at position B with
theta_B = theta_A + omega dt + alpha dt^2 / 2 and omega_B = omega + alpha dt.
Graded: A_A in cartesian form, A_B in polar form, and |A_BA| = |A_B - A_A|
(eq. 7.4), which the statement asks for with its unit.
"""

import math

from ..problem import Answer, Problem
from .common import (
    UNITS,
    Reject,
    draw_value,
    first_accepted,
    fmt,
    ranges_for,
    sizable,
    solve_checked,
)

FAMILY = "rotation"
TITLE = "A point on a body in pure rotation"
DEFAULTS = {
    "p": (2.0, 12.0, 0.5, "length"),
    "theta_A": (0.0, 355.0, 5.0, "angle"),
    "omega": (20.0, 200.0, 10.0, "omega"),
    "alpha": (50.0, 800.0, 50.0, "alpha"),
    "dt": (0.005, 0.02, 0.001, "time"),
}
STATEMENT = (
    "A point at radius $p$ is on a body in pure rotation about the origin, with angular "
    "velocity $\\omega$ and a constant angular acceleration $\\alpha$ (counter-clockwise "
    "positive) when it is at position A, where its position vector makes the angle "
    "$\\theta_A$ with the x axis. It takes the time $\\Delta t$ to reach position B. "
    "Find the acceleration of the point at A (cartesian form), at B (polar form), and the "
    "acceleration difference $\\mathbf{A}_{BA} = \\mathbf{A}_B - \\mathbf{A}_A$ (eq. 7.4)."
)


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    L, acc = UNITS[units]["length"], UNITS[units]["acceleration"]

    def build(rng):
        p = draw_value(rng, r["p"], nonzero=True)
        theta_A = draw_value(rng, r["theta_A"])
        omega = draw_value(rng, r["omega"], nonzero=True, signed=True)
        alpha = draw_value(rng, r["alpha"], nonzero=True, signed=True)
        dt = draw_value(rng, r["dt"], nonzero=True)
        omega_B = omega + alpha * dt
        if omega_B * omega <= 0:  # keep one sense of rotation between A and B
            raise Reject()
        theta_B = theta_A + math.degrees(omega * dt + 0.5 * alpha * dt * dt)
        case = {"mechanism": "rotation", "p": fmt(p, L)}
        cases = {
            "A": dict(
                case,
                theta2=fmt(theta_A, "deg"),
                omega2=fmt(omega, "rad/s"),
                alpha2=fmt(alpha, "rad/s^2"),
            ),
            "B": dict(
                case,
                theta2=fmt(theta_B, "deg"),
                omega2=fmt(omega_B, "rad/s"),
                alpha2=fmt(alpha, "rad/s^2"),
            ),
        }
        out = solve_checked(cases)
        A_A = complex(*out["A"]["A"])
        A_B = complex(*out["B"]["A"])
        sizable((A_A.real, A_A), (A_A.imag, A_A), (A_B - A_A, A_B))
        both = {"A": cases["A"], "B": cases["B"]}
        answers = [
            Answer(
                "A_A_x", acc, "x component of the acceleration at A", {"A": cases["A"]}, "real(A.A)"
            ),
            Answer(
                "A_A_y", acc, "y component of the acceleration at A", {"A": cases["A"]}, "imag(A.A)"
            ),
            Answer(
                "A_B_mag", acc, "magnitude of the acceleration at B", {"B": cases["B"]}, "abs(B.A)"
            ),
            Answer(
                "A_B_ang",
                "deg",
                "direction of the acceleration at B (from +x, CCW)",
                {"B": cases["B"]},
                "angle(B.A)",
                kind="angle",
            ),
            Answer(
                "A_BA_mag",
                acc,
                "magnitude of A_BA = A_B - A_A, as a Quantity with its unit",
                both,
                "abs(B.A - A.A)",
                quantity_required=True,
            ),
        ]
        given = {
            "p": fmt(p, L),
            "theta_A": fmt(theta_A, "deg"),
            "omega": fmt(omega, "rad/s"),
            "alpha": fmt(alpha, "rad/s^2"),
            "dt": fmt(dt, "s"),
        }
        return Problem(
            FAMILY,
            TITLE,
            STATEMENT,
            given,
            answers,
            figure={"mechanism": "rotation", "case": cases["A"], "case_B": cases["B"]},
        )

    return first_accepted(FAMILY, seed, build, units)
