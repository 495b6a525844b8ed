"""The worked cases whose constructions the README and the course show
(``accelab figures`` draws them into ``figures/``).

``EXAMPLE_7_1`` is the project's Example 7-1 fourbar (the chapter's example
gives no numbers; these are the ones the course uses throughout, with a
negative (CW) alpha2 and a positive (CCW) omega2 as in Figure 7-4), with a
coupler point P standing for the chapter's point C.
"""

from typing import Any

EXAMPLE_7_1 = {
    "mechanism": "fourbar",
    "a": "2 in",
    "b": "6 in",
    "c": "9 in",
    "d": "7 in",
    "theta2": "30 deg",
    "omega2": "10 rad/s",
    "alpha2": "-5 rad/s^2",
    "p": "3 in",
    "delta3": "30 deg",
    "circuit": "open",
}

SLIDER_CRANK = {
    "mechanism": "slidercrank",
    "a": "40 mm",
    "b": "120 mm",
    "c": "10 mm",
    "theta2": "60 deg",
    "omega2": "30 rad/s",
    "alpha2": "-200 rad/s^2",
    "circuit": "open",
}

INVERTED_SLIDER_CRANK = {
    "mechanism": "invertedslidercrank",
    "a": "40 mm",
    "c": "50 mm",
    "d": "100 mm",
    "gamma": "70 deg",
    "theta2": "60 deg",
    "omega2": "30 rad/s",
    "alpha2": "-200 rad/s^2",
    "circuit": "open",
}

GEARED_FIVEBAR = {
    "mechanism": "fivebar",
    "a": "40 mm",
    "b": "120 mm",
    "c": "110 mm",
    "d": "60 mm",
    "f": "150 mm",
    "lam": -2,
    "phi": "30 deg",
    "theta2": "45 deg",
    "omega2": "10 rad/s",
    "alpha2": "50 rad/s^2",
    "circuit": "open",
}

#: the slotted link of Figure 7-7 (SI: rad, rad/s, rad/s^2, m, m/s, m/s^2)
SLOTTED = {
    "theta2": 0.6981317007977318,
    "omega2": 10.0,
    "alpha2": -50.0,
    "p": 0.08,
    "p_dot": 0.5,
    "p_ddot": 3.0,
}

GALLERY: dict[str, dict[str, Any]] = {
    "graphical-fourbar": EXAMPLE_7_1,
    "graphical-slidercrank": SLIDER_CRANK,
    "graphical-invertedslidercrank": INVERTED_SLIDER_CRANK,
    "graphical-fivebar": GEARED_FIVEBAR,
    "graphical-slotted": SLOTTED,
}
#: the figures' titles: what each shows, and where the book shows its kind
TITLES = {
    "graphical-fourbar": "Example 7-1 fourbar (Figure 7-4), open circuit: the course's own numbers",
    "graphical-slidercrank": "Offset slider-crank, open circuit",
    "graphical-invertedslidercrank": "Inverted slider-crank (Figure 7-8), open circuit",
    "graphical-fivebar": "Geared fivebar (section 7.4), open circuit",
    "graphical-slotted": "Slotted link (Figure 7-7)",
}


def construction(name):
    """The construction of a gallery entry."""
    from . import construct_case, slotted

    case = GALLERY[name]
    con = slotted.construct(**case) if name == "graphical-slotted" else construct_case(case)
    con.title = TITLES.get(name, con.title)
    return con


def render(outdir, formats=("png", "svg"), names=None):
    """Draw the gallery's figures into ``outdir``; returns the paths written."""
    from .draw import save

    paths = []
    for name in names or GALLERY:
        paths += save(construction(name), outdir, name, formats)
    return paths
