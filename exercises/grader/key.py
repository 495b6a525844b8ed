"""The answer key of one student: computed here, in the grader's process, and
nowhere else.

Each distinct batch case of the variant is solved once; every answer's expr is
evaluated over those outputs (the same evaluator that the published variant's
exprs are defined by, so the key and ``accelab variant --json`` cannot
disagree).
"""

from dataclasses import dataclass

from ..assignment import Variant, build_variant
from ..expr import evaluate
from ..problem import solve_cases
from ..silence import silenced


@dataclass
class Key:
    """The expected value of every answer of one student's variant: an SI float
    (numbers, angles in rad), the right word (choices), or the construction to
    judge a drawing against (:class:`~accelab.exercises.grader.construction.ConstructionKey`)."""

    student: str
    variant: Variant
    values: dict

    @property
    def asked(self):
        return {name: a.asked() for name, a in self.variant.answers.items()}


def key_value(answer, outputs=None):
    """The correct answer of one :class:`~accelab.exercises.problem.Answer`: a float in
    SI, or the right choice. ``outputs`` (label -> batch result) may be given."""
    if answer.kind == "construction":  # judged step by step (.construction)
        from .construction import ConstructionKey

        (case,) = answer.cases.values()
        return ConstructionKey(dict(case), answer.expr)
    outputs = outputs if outputs is not None else solve_cases(answer.cases)
    if answer.kind == "choice":
        value = float(evaluate(answer.basis, outputs))
        for choice, upper in zip(answer.choices, list(answer.bins) + [float("inf")]):
            if value < upper:
                return choice
    value = evaluate(answer.expr, outputs)
    if isinstance(value, complex):
        raise ValueError(
            f"expr {answer.expr!r} of {answer.name} is a vector; "
            "use abs(), angle(), real() or imag()"
        )
    return float(value)


def key_of(variant):
    """The :class:`Key` of a built variant."""
    with silenced():
        values = {name: key_value(a) for name, a in variant.answers.items()}
    return Key(variant.student, variant, values)


def key_for(spec, student):
    """The :class:`Key` of ``student`` for the assignment ``spec``."""
    with silenced():
        return key_of(build_variant(spec, student))
