"""The data of a problem variant: statement, given values, figure, graded answers.

An :class:`Answer` is what one answer cell grades: the variable ``name`` the
student assigns, the ``unit`` the statement asks for, the batch ``cases`` it
depends on (label -> case dict in the batch format of the conventions page), and
an ``expr`` over those cases' outputs (see :mod:`accelab.exercises.expr`), evaluated in SI.
``kind`` is "number", "angle" (compared modulo 360 deg), "choice" (a word
picked from ``choices``; no expr is published) or "construction" (a polygon drawn
in the polygon builder; ``expr`` names the polygon, "velocity" or "acceleration").

Two views leave this module: :meth:`Problem.statement_view` is what a student's
kernel may hold (given values and what is asked, no cases, no exprs);
:meth:`Problem.public` adds the machine-readable cases and exprs for an outside
solver (``accelab variant``, instructor side). The key itself (numbers) is
computed only by :mod:`accelab.exercises.grader.key`.
"""

import json
from dataclasses import asdict, dataclass, field
from functools import lru_cache

from accelab.solver.batch import solve_case

from .student.answers import Asked


@dataclass
class Answer:
    """One graded answer of a variant: the variable ``name`` its answer cell assigns, in
    ``unit``, worked out from the batch ``cases`` by ``expr`` (or picked from ``choices``
    by ``basis`` and ``bins``); the module's text says each kind."""

    name: str
    unit: str
    description: str
    cases: dict
    expr: str = None
    kind: str = "number"
    choices: list = None
    quantity_required: bool = False  # a bare number is refused: the statement asks for units
    # choice answers: the SI value of ``basis`` picks choices[i] where
    # bins[i-1] <= value < bins[i]; kept out of the published variant
    basis: str = None
    bins: list = None

    def asked(self):
        """What the statement asks (no cases, no expr): the kernel's view."""
        return Asked(
            self.name,
            self.unit or "",
            self.description,
            self.kind,
            tuple(self.choices or ()),
            self.quantity_required,
        )

    def public(self):
        """The published form (``accelab variant``): no value, no choice rule."""
        out = {
            "name": self.name,
            "kind": self.kind,
            "unit": self.unit,
            "description": self.description,
            "cases": self.cases,
        }
        if self.kind == "choice":
            out["choices"] = list(self.choices)
        elif self.kind == "construction":  # the answer is a drawing of this polygon
            out["construction"] = self.expr
        else:
            out["expr"] = self.expr
            out["quantity_required"] = self.quantity_required
        return out


@dataclass
class Problem:
    """One student's variant of an exercise family: what the page says and what is graded.

    ``statement`` is the same for every student (Markdown, no numbers); ``given`` holds
    this variant's numbers as text with units (``{"p": "6.5 in"}``), ``answers`` its
    graded :class:`Answer` entries, ``figure`` what to draw (``{"mechanism": ...,
    "case": ...}``, empty for none) and ``seed`` the seed it was drawn from."""

    family: str
    title: str
    statement: str  # markdown, the same for every student (no numbers)
    given: dict  # symbol -> value text with unit, e.g. {"p": "6.5 in"}
    answers: list
    figure: dict = field(default_factory=dict)  # {"mechanism": ..., "case": ...} to draw
    seed: int = 0

    def public(self):
        return {
            "family": self.family,
            "title": self.title,
            "statement": self.statement,
            "given": dict(self.given),
            "answers": [a.public() for a in self.answers],
        }

    def statement_view(self):
        """What the student's kernel may hold: given values and what is asked."""
        return {
            "family": self.family,
            "title": self.title,
            "statement": self.statement,
            "given": dict(self.given),
            "asked": [a.asked().to_dict() for a in self.answers],
        }

    def to_dict(self):
        return asdict(self)


def solve_cases(cases):
    """Solve a label -> case map; raises ValueError naming the first failed case.

    Each distinct case is solved once per process (generation, key and figure
    of a variant share the outputs).
    """
    outputs = {}
    for label, case in cases.items():
        out = _solve_text(json.dumps(case, sort_keys=True))
        if not out.get("ok"):
            raise ValueError(f"case {label} failed: {out.get('error')}: {out.get('message')}")
        outputs[label] = dict(out)
    return outputs


@lru_cache(maxsize=4096)
def _solve_text(text):
    return solve_case(json.loads(text))
