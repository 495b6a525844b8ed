"""One visual scheme for every graphical construction.

Each kind of vector component has a colour from the Okabe-Ito palette (safe
for the common colour-vision deficiencies) AND its own line style and width,
so the figures also read in greyscale or on a black-and-white printout:

============  ===============  ==========  =========================
kind          colour           line        meaning
============  ===============  ==========  =========================
normal        blue             solid       centripetal, r omega^2 toward the centre
tangential    vermillion       dashed      r alpha, perpendicular to the radius
coriolis      bluish green     dash-dot    2 omega x V_slip
slip          reddish purple   dotted      along the slide
resultant     black            solid, bold absolute vectors that close a polygon
velocity      orange           solid       velocity-polygon vectors
============  ===============  ==========  =========================

Construction lines (pp, qq, rr) are thin grey long-dashed lines. In a walk
through a construction, what the step being shown adds lies on a pale yellow band.
"""

from typing import Any

OKABE_ITO = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky": "#56B4E9",
    "green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "purple": "#CC79A7",
}

COMPONENT = {
    "normal": {
        "color": OKABE_ITO["blue"],
        "linestyle": "-",
        "linewidth": 1.8,
        "label": "normal (centripetal)",
    },
    "tangential": {
        "color": OKABE_ITO["vermillion"],
        "linestyle": (0, (5, 2.5)),
        "linewidth": 1.8,
        "label": "tangential",
    },
    "coriolis": {
        "color": OKABE_ITO["green"],
        "linestyle": (0, (6, 2, 1.5, 2)),
        "linewidth": 2.0,
        "label": "Coriolis",
    },
    "slip": {
        "color": OKABE_ITO["purple"],
        "linestyle": (0, (1.5, 1.5)),
        "linewidth": 2.2,
        "label": "slip",
    },
    "resultant": {
        "color": OKABE_ITO["black"],
        "linestyle": "-",
        "linewidth": 2.6,
        "label": "resultant (absolute)",
    },
    "velocity": {
        "color": OKABE_ITO["orange"],
        "linestyle": "-",
        "linewidth": 1.8,
        "label": "velocity",
    },
    "known": {"color": "#555555", "linestyle": "-", "linewidth": 1.5, "label": "known"},
}

CONSTRUCTION_LINE: dict[str, Any] = {"color": "#8c8c8c", "linestyle": (0, (8, 4)), "linewidth": 0.9}
#: the pale band under what the step being shown adds (a walk through a construction)
HIGHLIGHT: dict[str, Any] = {
    "color": "#FFD84D",
    "alpha": 0.55,
    "linewidth": 9.0,
    "solid_capstyle": "round",
    "zorder": 2.5,
}
LINK: dict[str, Any] = {
    "color": "#4d4d4d",
    "linewidth": 4.0,
    "solid_capstyle": "round",
    "zorder": 2,
}
COUPLER_FILL: dict[str, Any] = {
    "facecolor": "#d9d9d9",
    "edgecolor": "#4d4d4d",
    "linewidth": 1.2,
    "zorder": 1,
}
PIN: dict[str, Any] = {
    "s": 38,
    "facecolor": "white",
    "edgecolor": "#222222",
    "linewidths": 1.3,
    "zorder": 5,
}
GROUND_HATCH = "////"
FONT_SIZE = 11
LABEL_SIZE = 12
TITLE_SIZE = 12
DPI = 150


def component(kind):
    """Style of a vector kind (see the table in the module docstring)."""
    return COMPONENT[kind]
