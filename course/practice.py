"""The practice block of a course notebook: the problem a student sees, and the
checks of that very problem.

Every topic notebook ends its lesson the same way::

    mine = practice("fourbar")          # a fresh problem, shown by this cell
    mine.check("alpha4", Q_(-31.4, "rad/s^2"))   # the answers cell: checks that problem

and, for the documentation site (where nothing can be typed), a problem of a
fixed seed with its answers folded::

    example = practice("fourbar", seed=5)
    example.answers()

Two names, never one: the student's problem is ``mine`` and only the cell that
draws it assigns it, so that after Run All, and whatever cells ran since, the
answers cell checks the problem its notebook shows above it (the page's problem
is ``example``). The problem itself and its checks are
:class:`accelab.exercises.practice.Practice`'s: drawn apart from every graded
problem, checked with the grader's own rules.
"""

from accelab.exercises.practice import Practice, fresh_seed

__all__ = ["practice", "Shown"]

#: the mechanisms of the polygon families, in words
MECHANISM = {
    "fourbar": "a fourbar",
    "slidercrank": "a slider-crank",
    "invertedslidercrank": "an inverted slider-crank with its Coriolis component",
}

#: the name the notebooks give the student's fresh problem, and the page's problem
MINE, EXAMPLE = "mine", "example"


class Shown(Practice):
    """A practice problem that says, where it is shown, how to check it: by the
    name of the variable that holds it in the notebook (``mine`` or ``example``)."""

    name = MINE

    def _how_to_check(self):
        first = next(iter(self.asked))
        if self.asked[first].kind == "construction":
            return self._how_to_construct()
        unit = self.asked[first].unit
        value = f"Q_(..., {unit!r})" if unit else repr(self.asked[first].choices[0])
        if self.name == MINE:
            where = (
                f"in the cell below with `{self.name}.check({first!r}, {value})`: `{self.name}` "
                f"is this problem (seed {self.seed}; after a restart, `{self.name} = "
                f"practice({self.family!r}, seed={self.seed})` brings it back)"
            )
        else:
            where = (
                f"with `{self.name}.check({first!r}, {value})` (the problem of seed {self.seed})"
            )
        return (
            f"Check each answer {where}. Numbers are right within {100 * self.tolerance:g}%, "
            f"directions within {self.angle_tolerance:g} deg; `{self.name}.answers()` shows "
            "every answer, for after you tried."
        )

    def _how_to_construct(self):
        """How to answer a problem whose answers are constructions (the polygon families):
        in its polygon builder, which checks each step; nothing is typed into a check."""
        from accelab.exercises.student.polygon.task import BAND_DEG, LENGTH_FRACTION

        again = f"`practice({self.family!r}, seed={self.seed}).builder()`"
        if self.name == MINE:
            where = f"(`.builder()`; after a restart, {again} brings this problem back)"
        else:
            where = f"({again} in a notebook: the problem of seed {self.seed})"
        return (
            f"Construct both polygons in the polygon builder of this problem {where}: each "
            f"step is checked as you make it, directions within {BAND_DEG:g} deg and lengths "
            f"within {100 * LENGTH_FRACTION:g}% of the polygon's largest vector. The builder's "
            "**Show the next step** helps when you are stuck; `.answers()` shows the finished "
            "constructions, for after you tried."
        )

    def answers(self):
        """Every answer, for after you tried. A problem whose answers are constructions
        (the polygon families) shows its finished polygons as one figure under the table
        (on a page of the site, in the rendition that fits the screen)."""
        if any(a.kind == "construction" for a in self.asked.values()):
            return _Constructions(self)
        return super().answers()


class _Constructions:
    """The answers of a construction problem: a table naming them, then the finished
    construction as a figure (a picture in a table cell would have no caption and no
    room on a phone)."""

    def __init__(self, problem):
        self._problem = problem

    def _repr_markdown_(self):
        from .polygons import finished_markdown

        p = self._problem
        rows = "\n".join(
            f"| `{name}` | {a.description} | {_shown(p, name)} |" for name, a in p.asked.items()
        )
        first = next(n for n, a in p.asked.items() if a.kind == "construction")
        task = p._key.values[first].task
        alt = (
            f"The finished velocity and acceleration polygons of the practice problem of seed "
            f"{p.seed}, {MECHANISM.get(task.mechanism, task.mechanism)}, one scale each."
        )
        return (
            f"**Answers** (seed {p.seed})\n\n| answer | quantity | value |\n|---|---|---|\n"
            f"{rows}\n\n{finished_markdown(task, alt)}"
        )

    def __repr__(self):
        p = self._problem
        return "\n".join(f"{name} = {_shown(p, name)}" for name in p.asked)


def _shown(problem, name):
    """An answer of ``problem`` as its answers table shows it."""
    asked = problem.asked[name]
    if asked.kind == "construction":
        return f"the finished {name.replace('_', ' ')}, drawn below"
    value = problem.reveal(name)
    return value if asked.kind == "choice" else f"{value.magnitude:.4g} {asked.unit}"


def practice(family, seed=None, units="US", show=True):
    """Draw a practice problem of ``family`` (a fresh one, or the one of ``seed``),
    show it where the cell runs, and return it.

    Assign a fresh problem to ``mine`` and the page's problem of a fixed seed to
    ``example``; ``mine.check(name, value)`` then always checks the problem shown.

    Parameters
    ----------
    family : str
        A graded exercise family (``"fourbar"``, ``"jerk"``, ...).
    seed : int, optional
        The problem of this seed (the same every time); a fresh one if omitted.
    units : str
        ``"US"`` or ``"SI"`` given values.
    show : bool
        Display the problem (in a notebook: its statement, figure and tables).
    """
    problem = Shown(family, fresh_seed() if seed is None else seed, units)
    problem.name = MINE if seed is None else EXAMPLE
    if show:
        _display(problem)
    return problem


def _display(problem):
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:  # plain Python
        print(repr(problem))
        return
    if get_ipython() is None:
        print(repr(problem))
    else:
        display(problem)
