"""Problem families, registered once.

Each family is a module of this package with ``FAMILY`` (its name), ``TITLE``,
``DEFAULTS`` (the ranges it draws from: name -> (lo, hi, step, kind)) and
``generate_problem(seed, ranges=None, units="US") -> Problem``; :data:`REGISTRY`
holds one :class:`Family` entry for each, with what of the chapter it practises
and the course notebooks that teach it. ``accelab assign``, the practice
problems, the documentation's tables, the course's FAMILIES.md page and the
tests read the registry; adding a family is its module and one entry here
(CONTRIBUTING.md, "Add an exercise family").
"""

import importlib
from types import ModuleType
from typing import Any, NamedTuple

__all__ = ["Family", "REGISTRY", "FAMILIES", "generate"]


class Family(NamedTuple):
    """One problem family: ``name`` (its module's ``FAMILY``), ``module`` (the
    module of this package that generates it), ``chapter`` (what of the chapter
    it practises: sections, equations, figures; Markdown), ``asks`` (what the
    student finds; Markdown) and ``notebooks`` (the stems of the course notebooks
    that teach it, the main one first; each names the family back)."""

    name: str
    module: str
    chapter: str
    asks: str
    notebooks: tuple[str, ...]

    def load(self) -> ModuleType:
        """The family's module."""
        return importlib.import_module(f"{__name__}.{self.module}")

    @property
    def title(self) -> str:
        return self.load().TITLE

    @property
    def defaults(self) -> dict[str, tuple[Any, ...]]:
        """The ranges it draws from by default: name -> (lo, hi, step, kind), lengths in inches."""
        return self.load().DEFAULTS


# every family, in the order the command line, the documentation and the course list them
REGISTRY: dict[str, Family] = {
    f.name: f
    for f in (
        Family(
            "rotation",
            "rotation",
            "section 7.1, eqs. 7.1 to 7.6; problem 7-1",
            "a point on a body in pure rotation: its acceleration at two positions, in "
            "cartesian and polar form, and their difference (eq. 7.4)",
            ("01_rotating_point",),
        ),
        Family(
            "fourbar",
            "fourbar",
            "sections 7.2 and 7.3, Example 7-1, eqs. 7.7 to 7.13",
            r"a fourbar's $\alpha_3$, $\alpha_4$ and the accelerations of its pins",
            ("02_graphical_fourbar", "03_analytic_fourbar", "07_any_point"),
        ),
        Family(
            "coupler",
            "coupler",
            "section 7.5, eqs. 7.30 to 7.32 (Example 7-1, step 8)",
            "the acceleration of a coupler point",
            ("07_any_point", "02_graphical_fourbar"),
        ),
        Family(
            "slidercrank",
            "slidercrank",
            "section 7.3, eqs. 7.14 to 7.16",
            r"the connecting rod's $\alpha_3$ and the slider's acceleration",
            ("04_slider_crank_engine",),
        ),
        Family(
            "coriolis",
            "coriolis",
            "section 7.3, eqs. 7.17 to 7.27",
            r"the inverted slider-crank: $\alpha_4$, the Coriolis component and the slip "
            "acceleration",
            ("05_coriolis",),
        ),
        Family(
            "fivebar",
            "fivebar",
            "section 7.4, eqs. 7.28 and 7.29",
            r"the geared fivebar's $\alpha_3$ and $\alpha_4$",
            ("06_geared_fivebar",),
        ),
        Family(
            "jerk",
            "jerk",
            "section 7.7, eqs. 7.33 to 7.41",
            "a fourbar's angular jerks and the jerk of its rocker pin",
            ("09_jerk",),
        ),
        Family(
            "tolerance",
            "tolerance",
            "section 7.6, Table 7-1, Figure 7-10",
            "a ride's acceleration in g, judged against Table 7-1",
            ("08_human_tolerance",),
        ),
        Family(
            "polygon_fourbar",
            "polygon_fourbar",
            "section 7.2, Example 7-1, Figure 7-4: the graphical method",
            "a fourbar's velocity and acceleration polygons, constructed step by step in the "
            "polygon builder",
            ("02_graphical_fourbar",),
        ),
        Family(
            "polygon_slidercrank",
            "polygon_slidercrank",
            "section 7.2 applied to the slider-crank (section 7.3)",
            "a slider-crank's velocity and acceleration polygons, constructed step by step",
            ("02_graphical_fourbar",),
        ),
        Family(
            "polygon_coriolis",
            "polygon_coriolis",
            "sections 7.2 and 7.3: the inverted slider-crank's polygons with the Coriolis term",
            r"an inverted slider-crank's polygons, with the Coriolis term $2\omega V_{slip}$, "
            "constructed step by step",
            ("02_graphical_fourbar",),
        ),
    )
}

# family name -> its generator, ``generate_problem(seed, ranges=None, units="US")``
FAMILIES = {name: f.load().generate_problem for name, f in REGISTRY.items()}


def generate(family, seed, ranges=None, units="US"):
    """The variant of ``family`` for ``seed`` (see each module)."""
    if family not in FAMILIES:
        raise ValueError(f"unknown problem family {family!r}; use one of {', '.join(FAMILIES)}")
    return FAMILIES[family](seed, ranges=ranges, units=units)
