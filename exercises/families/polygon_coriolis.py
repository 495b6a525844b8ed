"""The inverted slider-crank's polygons by construction, with the Coriolis
component (section 7.3, eqs. 7.19 and 7.21, Figure 7-8): the block slides on the
turning link 4, so its polygon needs 2 omega4 V_slip perpendicular to the slide
(see :mod:`accelab.exercises.families.polygon`)."""

from . import coriolis
from .common import UNITS, draw_value, fmt, ranges_for
from .polygon import generate

FAMILY = "polygon_coriolis"
TITLE = "The inverted slider-crank's polygons, constructed (with Coriolis)"
DEFAULTS = coriolis.DEFAULTS


def generate_problem(seed, ranges=None, units="US"):
    r = ranges_for(DEFAULTS, ranges, units)
    length = UNITS[units]["length"]

    def draw_case(rng):
        return {
            "mechanism": "invertedslidercrank",
            "a": fmt(draw_value(rng, r["a"], nonzero=True), length),
            "c": fmt(draw_value(rng, r["c"]), length),
            "d": fmt(draw_value(rng, r["d"], nonzero=True), length),
            "gamma": fmt(draw_value(rng, r["gamma"], nonzero=True), "deg"),
            "theta2": fmt(draw_value(rng, r["theta2"]), "deg"),
            "omega2": fmt(draw_value(rng, r["omega2"], nonzero=True, signed=True), "rad/s"),
            "alpha2": fmt(draw_value(rng, r["alpha2"], nonzero=True, signed=True), "rad/s^2"),
            "circuit": "open" if rng.random() < 0.5 else "crossed",
        }

    return generate(FAMILY, TITLE, draw_case, seed, units)
