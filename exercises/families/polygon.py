"""What the three polygon families share (``polygon_fourbar``,
``polygon_slidercrank``, ``polygon_coriolis``): the graphical method of section 7.2
done by the student in the polygon builder, whose answer is the construction itself.

A variant is a position of the mechanism drawn from the ranges of the family of
the same mechanism (``fourbar``, ``slidercrank``, ``coriolis``), kept only when
its construction is well drawn: every vector of each polygon at least
:data:`MIN_VECTOR` of the polygon's largest (so each can be laid and judged at one
scale), the two construction lines crossing at :data:`MIN_CROSSING` degrees or
more (so the crossing is sharp). The
two answers, ``velocity_polygon`` and ``acceleration_polygon``, are judged step by
step by :mod:`accelab.exercises.student.polygon.rules` against the submitter's own
construction, one point each with partial credit per step.
"""

import math

from accelab.solver.errors import AccelabError

from ..problem import Answer, Problem
from ..student.polygon.task import ANSWER_SUFFIX, FAMILY_MECHANISM, task_of_case
from .common import Reject, first_accepted, given_of, solve_checked

#: the smallest vector of a polygon, as a fraction of its largest
MIN_VECTOR = 0.04
#: the smallest angle at which the two construction lines cross [deg]
MIN_CROSSING = 20.0

STATEMENT = (
    "Construct the velocity polygon, then the acceleration polygon, of this position with "
    "the polygon builder below, as Example 7-1 and Figure 7-4 do: lay the known vectors tip "
    "to tail from the pole, draw the construction lines of the vectors whose direction alone "
    "is known, mark where they cross, draw the vectors that close the polygon, and read off "
    "the unknowns. Your construction is your answer: each step is judged, directions within "
    "1 deg and lengths within 2% of the polygon's largest vector."
)
GIVEN = {
    "fourbar": ["a", "b", "c", "d", "theta2", "omega2", "alpha2", "circuit"],
    "slidercrank": ["a", "b", "c", "theta2", "omega2", "alpha2"],
    "invertedslidercrank": ["a", "c", "d", "gamma", "theta2", "omega2", "alpha2", "circuit"],
}


def well_drawn(task):
    """Reject unless every polygon of ``task`` can be drawn and judged at one scale."""
    for phase in task.phases.values():
        big = phase.largest
        if any(abs(t.vector) < MIN_VECTOR * big for t in phase.terms + phase.resultants):
            raise Reject()
        u1, u2 = (t.vector for t in phase.unknowns)
        sin = abs((u1.conjugate() * u2).imag) / (abs(u1) * abs(u2))
        if sin < math.sin(math.radians(MIN_CROSSING)):
            raise Reject()


def generate(family, title, draw_case, seed, units):
    """The variant of ``family`` for ``seed``: ``draw_case(rng)`` draws a batch case."""
    mechanism = FAMILY_MECHANISM[family]

    def build(rng):
        case = draw_case(rng)
        if case["mechanism"] != mechanism:
            raise ValueError(f"{family} draws a {mechanism}")
        solve_checked({"K": case})
        try:
            task = task_of_case(case)
        except (AccelabError, ValueError):  # the construction refuses it (a toggle)
            raise Reject() from None
        well_drawn(task)
        k = {"K": case}
        answers = [
            Answer(
                ANSWER_SUFFIX[phase],
                "",
                f"the {phase} polygon (your construction in the builder)",
                k,
                phase,
                kind="construction",
            )
            for phase in ("velocity", "acceleration")
        ]
        return Problem(
            family,
            title,
            STATEMENT,
            given_of(case, GIVEN[mechanism]),
            answers,
            figure={"mechanism": mechanism, "case": case},
        )

    return first_accepted(family, seed, build, units)
