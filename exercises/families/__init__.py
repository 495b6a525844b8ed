"""Problem families: each module has ``generate_problem(seed, ranges=None, units="US")
-> Problem``. :data:`FAMILIES` maps the family name to that generator."""

from . import (
    coriolis,
    coupler,
    fivebar,
    fourbar,
    jerk,
    polygon_coriolis,
    polygon_fourbar,
    polygon_slidercrank,
    rotation,
    slidercrank,
    tolerance,
)

FAMILIES = {
    m.FAMILY: m.generate_problem
    for m in (
        rotation,
        fourbar,
        coupler,
        slidercrank,
        coriolis,
        fivebar,
        jerk,
        tolerance,
        polygon_fourbar,
        polygon_slidercrank,
        polygon_coriolis,
    )
}


def generate(family, seed, ranges=None, units="US"):
    """The variant of ``family`` for ``seed`` (see each module)."""
    if family not in FAMILIES:
        raise ValueError(f"unknown problem family {family!r}; use one of {', '.join(FAMILIES)}")
    return FAMILIES[family](seed, ranges=ranges, units=units)
