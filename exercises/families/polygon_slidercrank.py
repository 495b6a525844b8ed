"""The slider-crank's polygons by construction (section 7.2 applied to the
slider-crank of section 7.3): the slider's acceleration lies along the slide, the
rod's tangential component across the rod (see :mod:`accelab.exercises.families.polygon`)."""

from . import slidercrank
from .common import UNITS, draw_value, fmt, ranges_for
from .polygon import generate

FAMILY = "polygon_slidercrank"
TITLE = "The slider-crank's polygons, constructed"
DEFAULTS = slidercrank.DEFAULTS


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    length = UNITS[units]["length"]

    def draw_case(rng):
        return {
            "mechanism": "slidercrank",
            "a": fmt(draw_value(rng, r["a"], nonzero=True), length),
            "b": fmt(draw_value(rng, r["b"], nonzero=True), length),
            "c": fmt(draw_value(rng, r["c"]), length),
            "theta2": fmt(draw_value(rng, r["theta2"]), "deg"),
            "omega2": fmt(draw_value(rng, r["omega2"], nonzero=True, signed=True), "rad/s"),
            "alpha2": fmt(draw_value(rng, r["alpha2"], nonzero=True, signed=True), "rad/s^2"),
            "circuit": "open",
        }

    return generate(FAMILY, TITLE, draw_case, seed, units)
