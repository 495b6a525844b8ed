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

#: the name the notebooks give the student's fresh problem, and the page's problem
MINE, EXAMPLE = "mine", "example"


class Shown(Practice):
    """A practice problem that says, where it is shown, how to check it: by the
    name of the variable that holds it in the notebook (``mine`` or ``example``)."""

    name = MINE

    def _how_to_check(self):
        first = next(iter(self.asked))
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
