"""Practice with instant feedback, for self-study: a problem of one of the
graded families, with a check that says at once whether an answer is right and,
if not, what to look at (form, dimension, sign, size, units).

It is separate from graded work: practice values are drawn from their own seeds
and on the half-steps of the families' grids, so that a practice problem is
never a graded one (with the default ranges), and the check works only on the
problem it drew. Inside the grading sandbox this module is not there at all.

>>> from accelab.exercises.practice import practice
>>> p = practice("fourbar", seed=7)        # the same problem every time with seed 7
>>> p.check("alpha3", Q_(-120, "rad/s^2"))  # prints right, or why not
"""

import base64
import random

from accelab.solver.units import Q_, ureg

from .assignment import DEFAULT_ANGLE_TOLERANCE, DEFAULT_TOLERANCE, Variant
from .families import FAMILIES, generate
from .families.common import PRACTICE
from .grader.judge import judge
from .grader.key import key_of
from .silence import silenced
from .student.answers import describe

__all__ = ["practice", "Practice"]


class Practice:
    """One practice problem: its statement, given values and checks.

    Use :func:`practice` to draw one.
    """

    def __init__(
        self,
        family,
        seed,
        units="US",
        tolerance=DEFAULT_TOLERANCE,
        angle_tolerance=DEFAULT_ANGLE_TOLERANCE,
    ):
        if family not in FAMILIES:
            raise ValueError(f"unknown problem family {family!r}; use one of {', '.join(FAMILIES)}")
        self.family, self.seed, self.units = family, int(seed), units
        self.tolerance, self.angle_tolerance = float(tolerance), float(angle_tolerance)
        token = PRACTICE.set(True)
        try:
            with silenced():
                self.problem = generate(family, self.seed, units=units)
        finally:
            PRACTICE.reset(token)
        spec = {
            "course": "practice",
            "assignment": family,
            "units": units,
            "tolerance": self.tolerance,
            "angle_tolerance": self.angle_tolerance,
            "problems": [{"family": family}],
        }
        self._key = key_of(Variant(spec, f"practice-{self.seed}", [self.problem]))
        self.asked = {a.name: a.asked() for a in self.problem.answers}

    @property
    def given(self):
        """The given values as Quantities (words such as the circuit stay strings)."""
        out = {}
        for symbol, text in self.problem.given.items():
            try:
                out[symbol] = Q_(text)
            except Exception:  # noqa: BLE001 - pint raises many types for a word: it stays text
                out[symbol] = text
        return out

    def check(self, name, value):
        """Say whether ``value`` is right for the answer ``name``; returns True or False.

        ``value`` is a Quantity in any unit of the right dimension, a bare number
        in the asked unit, or (for a choice) one of the words.
        """
        if name not in self.asked:
            raise KeyError(
                f"this problem has no answer {name!r}; its answers are {', '.join(self.asked)}"
            )
        with silenced():
            verdict = judge(
                self.asked[name],
                describe(value),
                self._key.values[name],
                self.tolerance,
                self.angle_tolerance,
                ureg,
            )
        print(verdict.message)
        return verdict.ok

    def reveal(self, name):
        """The answer ``name`` in the asked unit (for after you tried)."""
        a = self.asked[name]
        value = self._key.values[name]
        if a.kind == "choice":
            return value
        return Q_(value, Q_(1.0, a.unit or "").to_base_units().units).to(a.unit or "")

    def answers(self):
        """Every answer, for after you tried: shown as a table in a notebook or on
        the course's pages (where nothing can be typed, so a reader checks by eye)."""
        return _Answers(self)

    def _figure_png(self):
        from .figure import statement_figure

        try:
            with silenced():
                return statement_figure(self.problem, shared=False)
        except Exception:  # noqa: BLE001 - the figure is an extra: the problem shows without it
            return None

    def _repr_markdown_(self):
        rows = "\n".join(f"| {k} | {v} |" for k, v in self.problem.given.items())
        asked = "\n".join(
            f"| `{a.name}` | {a.description} | {a.unit or ('one of ' + ', '.join(a.choices))} |"
            for a in self.asked.values()
        )
        png = self._figure_png()
        figure = (
            f"\n![Schematic of the linkage of this problem](data:image/png;base64,"
            f"{base64.b64encode(png).decode('ascii')})\n"
            if png
            else ""
        )
        first = next(iter(self.asked))
        return (
            f"**Practice: {self.problem.title}** (family `{self.family}`, seed "
            f"{self.seed}; not graded)\n\n{self.problem.statement}\n{figure}\n"
            f"| given | value |\n|---|---|\n{rows}\n\n"
            f"| answer | quantity | unit |\n|---|---|---|\n{asked}\n\n"
            f"Check an answer with `p.check({first!r}, Q_(..., "
            f"{self.asked[first].unit!r}))`; numbers are right within "
            f"{100 * self.tolerance:g}%, directions within {self.angle_tolerance:g} deg."
        )

    def __repr__(self):
        given = ", ".join(f"{k} = {v}" for k, v in self.problem.given.items())
        return (
            f"Practice({self.family!r}, seed={self.seed}): {self.problem.title}; given "
            f"{given}; answers {', '.join(self.asked)}"
        )


def practice(family, seed=None, units="US"):
    """A practice problem of ``family`` (a fresh one each call, or the one of
    ``seed``, so you can come back to it)."""
    if seed is None:
        seed = random.SystemRandom().randrange(1, 10**6)
    return Practice(family, seed, units)


class _Answers:
    """The answers of a :class:`Practice` problem as a table."""

    def __init__(self, problem):
        self._problem = problem

    def _rows(self):
        p = self._problem
        for name, a in p.asked.items():
            value = p.reveal(name)
            shown = value if a.kind == "choice" else f"{value.magnitude:.4g} {a.unit}"
            yield name, a.description, shown

    def _repr_markdown_(self):
        rows = "\n".join(f"| `{n}` | {d} | {v} |" for n, d, v in self._rows())
        return (
            f"**Answers** (seed {self._problem.seed})\n\n| answer | quantity | value |\n"
            f"|---|---|---|\n{rows}"
        )

    def __repr__(self):
        return "\n".join(f"{n} = {v}" for n, _, v in self._rows())
