"""The data of a problem variant: statement, given values, figure, graded answers.

An :class:`Answer` is what one answer cell grades: the variable ``name`` the
student assigns, the ``unit`` the statement asks for, the batch ``cases`` it
depends on (label -> case dict in the batch format of CONVENTIONS), and an
``expr`` over those cases' outputs (see :mod:`exercises.expr`), evaluated in SI.
``kind`` is "number", "angle" (compared modulo 360 deg) or "choice" (a word
picked from ``choices``; no expr is published).
"""

from dataclasses import dataclass, field, asdict

from solver.batch import solve_case

from .expr import evaluate


@dataclass
class Answer:
    name: str
    unit: str
    description: str
    cases: dict
    expr: str = None
    kind: str = "number"
    choices: list = None
    quantity_required: bool = False   # a bare number is refused: the statement asks for units
    # choice answers: the SI value of ``basis`` picks choices[i] where
    # bins[i-1] <= value < bins[i]; kept out of the published variant
    basis: str = None
    bins: list = None

    def public(self):
        """The published form (``accelab variant``): no value, no choice rule."""
        out = {"name": self.name, "kind": self.kind, "unit": self.unit,
               "description": self.description, "cases": self.cases}
        if self.kind == "choice":
            out["choices"] = list(self.choices)
        else:
            out["expr"] = self.expr
            out["quantity_required"] = self.quantity_required
        return out


@dataclass
class Problem:
    family: str
    title: str
    statement: str            # markdown, the same for every student (no numbers)
    given: dict               # symbol -> value text with unit, e.g. {"p": "6.5 in"}
    answers: list
    figure: dict = field(default_factory=dict)   # {"mechanism": ..., "case": ...} to draw
    seed: int = 0

    def public(self):
        return {"family": self.family, "title": self.title, "statement": self.statement,
                "given": dict(self.given), "answers": [a.public() for a in self.answers]}

    def to_dict(self):
        return asdict(self)


def solve_cases(cases):
    """Solve a label -> case map; raises ValueError naming the first failed case."""
    outputs = {}
    for label, case in cases.items():
        out = solve_case(case)
        if not out.get("ok"):
            raise ValueError(f"case {label} failed: {out.get('error')}: {out.get('message')}")
        outputs[label] = out
    return outputs


def key_value(answer, outputs=None):
    """The correct answer: a float in SI (number, angle), or the right choice.

    ``outputs`` (label -> batch result) may be given to avoid solving again.
    """
    outputs = outputs if outputs is not None else solve_cases(answer.cases)
    if answer.kind == "choice":
        value = float(evaluate(answer.basis, outputs))
        for choice, upper in zip(answer.choices, list(answer.bins) + [float("inf")]):
            if value < upper:
                return choice
    value = evaluate(answer.expr, outputs)
    if isinstance(value, complex):
        raise ValueError(f"expr {answer.expr!r} of {answer.name} is a vector; "
                         "use abs(), angle(), real() or imag()")
    return float(value)
