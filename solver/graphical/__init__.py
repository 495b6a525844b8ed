"""Graphical acceleration analysis (Chapter 7, section 7.2): velocity and
acceleration polygons constructed step by step, and drawn.

The constructions are an independent method: from the link lengths and the
input motion alone they draw the linkage to scale (arcs and lines), then
place known vectors tip to tail and intersect the construction lines of the
vectors whose direction only is known, exactly as Example 7-1 does. They
never call the analytic solver; the tests compare the two.

>>> from accelab.solver.graphical import construct_case
>>> con = construct_case({"mechanism": "fourbar", "a": "2 in", "b": "6 in", "c": "9 in",
...                       "d": "7 in", "theta2": "30 deg", "omega2": "10 rad/s",
...                       "alpha2": "-5 rad/s^2"})
>>> round(con.values["alpha4"], 4)
39.4252
"""

from ..registry import DRAWABLE, PARAMETERS
from ..registry import construction as construction_of
from . import fivebar, fourbar, invertedslidercrank, slidercrank, slotted
from .construction import Arrow, Construction, Line, Linkage, Step

__all__ = [
    "construct",
    "construct_case",
    "DRAWABLE",
    "Construction",
    "Step",
    "Arrow",
    "Line",
    "Linkage",
    "fivebar",
    "fourbar",
    "slidercrank",
    "invertedslidercrank",
    "slotted",
]

#: the range the constructions draw: lengths (non-zero) between these [m] and
#: |omega2| up to MAX_RATE [rad/s], |alpha2| up to its square, keep every vector
#: of a construction (lengths times rates squared, and their squares) within
#: float64. The analytic solver (accelab solve) answers any scale.
LENGTH_RANGE = (1e-50, 1e50)
MAX_RATE = 1e50


def _check_range(mechanism, params):
    """InvalidInput for a parameter outside what the constructions draw."""
    from ..errors import InvalidInput

    decl = PARAMETERS.get(mechanism)
    lengths = [p.name for p in decl.geometry + decl.point if p.kind == "length"] if decl else []
    lo, hi = LENGTH_RANGE
    for name in lengths:
        x = abs(params.get(name) or 0.0)
        if x and not lo <= x <= hi:
            raise InvalidInput(
                f"the graphical construction draws lengths between {lo:g} and "
                f"{hi:g} m, and {name} is {x:.3g} m; 'accelab solve' answers any "
                f"scale",
                name,
            )
    for name, limit in (("omega2", MAX_RATE), ("alpha2", MAX_RATE**2)):
        if abs(params.get(name, 0.0)) > limit:
            raise InvalidInput(
                f"the graphical construction draws |{name}| up to {limit:g} (SI), "
                f"and {name} is {params[name]:.3g}; 'accelab solve' answers it",
                name,
            )


def construct(mechanism, circuit=None, **params):
    """Build the construction of ``mechanism`` from SI parameters (the names
    of the batch format: a, b, c, d, theta1, theta2, omega2, alpha2, p,
    delta3, gamma). ``jerk2`` is accepted and ignored (no jerk polygon).
    The registry (:mod:`accelab.solver.registry`) names each mechanism's construction."""
    from ..errors import InvalidInput

    params = dict(params)
    params.pop("jerk2", None)
    _check_range(mechanism, params)
    build = construction_of(mechanism) if isinstance(mechanism, str) else None
    if build is not None:
        return build(**params, **({"circuit": circuit} if circuit else {}))
    raise InvalidInput(
        f"there is no graphical construction for {mechanism!r}; draw one of "
        f"{', '.join(DRAWABLE)} (use 'accelab solve' for the others)",
        "mechanism",
    )


def construct_case(case):
    """Construction of one batch case (docs/conventions.md#batch-format, read by
    :func:`accelab.solver.cases.read_case`). Raises the AccelabError family."""
    from ..cases import check_mechanism, read_case
    from ..errors import InvalidInput

    if check_mechanism(case) == "loops":
        raise InvalidInput(
            "there is no graphical construction for 'loops'; draw one of "
            f"{', '.join(DRAWABLE)} (use 'accelab solve' for it)",
            "mechanism",
        )
    c = read_case(case)
    params = dict(c.params)
    if "p" not in params:
        params.pop("delta3", None)
    con = construct(c.mechanism, c.circuit, **params)
    con.units = units_of_case(case)
    return con


#: length units that make a case "US" (its drawings in in, in/s, in/s^2)
_US_LENGTHS = ("in", "inch", "inches", "ft", "foot", "feet")


def units_of_case(case):
    """``"US"`` if the case gives its lengths in inches or feet, else ``"SI"``
    (the drawings follow: in, in/s and in/s^2, or mm, m/s and m/s^2)."""
    for key in ("a", "b", "c", "d", "f", "p"):
        value = case.get(key) if isinstance(case, dict) else None
        if isinstance(value, str):
            unit = value.strip().split()[-1].lower() if value.strip() else ""
            return "US" if unit in _US_LENGTHS else "SI"
    return "SI"
