"""The fourbar's polygons by construction (section 7.2, Example 7-1, Figure 7-4):
the student builds the velocity and acceleration polygons in the polygon builder;
the construction is the answer (see :mod:`accelab.exercises.families.polygon`)."""

from .common import FOURBAR_DEFAULTS, UNITS, fourbar_case, ranges_for
from .polygon import generate

FAMILY = "polygon_fourbar"
TITLE = "The fourbar's polygons, constructed (Example 7-1)"
DEFAULTS = FOURBAR_DEFAULTS


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    length = UNITS[units]["length"]
    return generate(FAMILY, TITLE, lambda rng: fourbar_case(rng, r, length), seed, units)
