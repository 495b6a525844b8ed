"""From a sandboxed run to grades: each answer judged against the submitter's
key, the notes an instructor and a student need, and the notebook as nbgrader
scores it (a test cell with an error output scores 0, any other full points).
"""

import re
from dataclasses import asdict, dataclass, field

import nbformat

from accelab.solver.units import ureg

from ..student.answers import read
from .intake import shown
from .judge import Verdict, judge, judge_reading, wrong
from .plan import answer_cells

#: what the feedback calls each kind of cell failure
FAILED = {"error", "timeout", "died", "not_run"}
SHOWN = re.compile(r"\(student `([^`]{1,100})`\)")


@dataclass
class Outcome:
    """The grading of one submission."""

    student: str
    verdicts: dict = field(default_factory=dict)  # name -> Verdict
    notes: list = field(default_factory=list)  # for the CSV and the feedback
    seconds: float = 0.0

    @property
    def score(self):
        return sum(v.credit for v in self.verdicts.values())

    def to_dict(self):
        return {
            "student": self.student,
            "seconds": self.seconds,
            "notes": list(self.notes),
            "verdicts": {n: asdict(v) for n, v in self.verdicts.items()},
        }

    @classmethod
    def from_dict(cls, data):
        return cls(
            data["student"],
            {n: Verdict(**v) for n, v in data["verdicts"].items()},
            list(data["notes"]),
            float(data.get("seconds", 0.0)),
        )


def judge_run(key, steps, run, others=None, shown=()):
    """The :class:`Outcome` of ``run`` for the submitter whose ``key`` it is.

    ``others`` maps another student id -> that student's Key (to tell whose values
    a wrong answer holds); ``shown`` are the ids the submitted notebook's stored
    outputs say it showed.
    """
    variant = key.variant
    asked = key.asked
    answers = answer_cells(steps)
    outcome = Outcome(key.student, seconds=run.seconds)
    if run.error:
        outcome.notes.append(run.error)
    for name, a in asked.items():
        report = run.reports.get(name)
        cause = _cell_cause(run, answers.get(name))
        if report is None:
            step = next(
                (k for k, s in enumerate(steps) if s.kind == "report" and s.name == name), None
            )
            why = run.cells[step].message if step is not None else "its test cell is missing"
            outcome.verdicts[name] = wrong(
                name, f"{name}: no credit: its value could not be read ({why})"
            )
            continue
        verdict = judge(
            a, report, key.values[name], variant.tolerance, variant.angle_tolerance, ureg
        )
        if not verdict.ok and report.get("state") == "missing" and cause:
            verdict = wrong(name, f"{name}: no credit: its answer cell did not finish: {cause}")
        outcome.verdicts[name] = verdict
    outcome.notes += _whose_values(key, run, others or {}, shown, outcome, asked)
    return outcome


def _cell_cause(run, k):
    if k is None:
        return ""
    cell = run.cells.get(k)
    return cell.message if cell is not None and cell.status in FAILED else ""


def _whose_values(key, run, others, shown, outcome, asked):
    """Notes on values that are not the submitter's own."""
    notes = []
    me = key.student
    for who in dict.fromkeys(
        [*run.refused, *[s for s in run.loaded if s != me], *[s for s in shown if s != me]]
    ):
        notes.append(
            f"the notebook showed or asked for the values of {_whose(who, others)}, "
            f"not the submitter's; it was graded against {me}'s own values"
        )
    wrong_names = [n for n, v in outcome.verdicts.items() if not v.ok]
    # each wrong answer's report is read once (the one bounded reader), then compared
    # with every other student's key: the cost does not grow with the class times the text
    readings = {
        n: read(asked[n], run.reports.get(n), ureg)
        for n in wrong_names
        if isinstance(run.reports.get(n), dict) and asked[n].kind != "choice"
    }
    readings = {n: r for n, r in readings.items() if r.ok}
    for other, other_key in others.items():
        if other == me or not readings:
            continue
        hits = [n for n in readings if _matches(asked[n], readings[n], other_key, n, key.variant)]
        if hits and len(hits) >= max(1, len(wrong_names) // 2):
            notes.append(
                f"{len(hits)} answer(s) ({', '.join(hits)}) hold the values of "
                f"{_whose(other, others)}, not the submitter's own"
            )
    return notes


def _whose(student, others):
    if student == "self-study":
        return "the self-study variant"
    if student in others:
        return f"student {student}"
    return f"an unknown student id {shown(student)}"  # the kernel's text, shown safely


def _matches(asked, reading, other_key, name, variant):
    expected = other_key.values.get(name)
    if expected is None:
        return False
    verdict = judge_reading(
        asked, reading, expected, variant.tolerance, variant.angle_tolerance, ureg
    )
    return verdict.ok


def shown_ids(nb):
    """The student ids the notebook's stored given-value outputs name."""
    found = []
    for cell in nb.cells:
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id", "")
        if cell.cell_type != "code" or not str(gid).startswith("given"):
            continue
        for out in cell.get("outputs", []):
            data = out.get("data", {}) if isinstance(out, dict) else {}
            for text in (data.get("text/markdown"), data.get("text/plain"), out.get("text")):
                if isinstance(text, str):
                    found += SHOWN.findall(text)
    return list(dict.fromkeys(found))


def write_notebook(nb, steps, run, outcome):
    """Put the run's outputs and the verdicts into the notebook's cells."""
    _write(nb, steps, run, outcome)
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs = [nbformat.from_dict(o) for o in cell.outputs]
    return nb


def _write(nb, steps, run, outcome):
    for k, step in enumerate(steps):
        cell = nb.cells[step.index]
        cell.execution_count = None
        if step.kind == "report":
            verdict = outcome.verdicts.get(step.name)
            if verdict is None:
                cell.outputs = [
                    _error("NotGraded", f"{step.name} is not a graded answer of this assignment")
                ]
            elif verdict.ok:
                cell.outputs = [
                    {"output_type": "stream", "name": "stdout", "text": verdict.message + "\n"}
                ]
            else:
                cell.outputs = [_error("WrongAnswer", verdict.message)]
            continue
        result = run.cells[k]
        outputs = list(result.outputs)
        if result.status in ("timeout", "died", "not_run"):
            outputs.append(
                _error(
                    {"timeout": "CellTimeout", "died": "KernelDied", "not_run": "NotRun"}[
                        result.status
                    ],
                    result.message,
                )
            )
        cell.outputs = outputs
        if step.grade_id == "parameters":
            cell.outputs = [
                {"output_type": "stream", "name": "stdout", "text": _summary(outcome)}
            ] + cell.outputs
    return nb


def _summary(outcome):
    lines = [
        f"Graded against the values of student {outcome.student} (the submitter), "
        f"outside this notebook: {outcome.score:g} of {len(outcome.verdicts)} right."
    ]
    lines += [f"Note: {n}." for n in outcome.notes]
    return "\n".join(lines) + "\n"


def _error(ename, evalue):
    return {
        "output_type": "error",
        "ename": ename,
        "evalue": evalue,
        "traceback": [f"{ename}: {evalue}"],
    }


def reading_problem(asked, report):
    """The form/dimension problem of a report, or None (for tests and tools)."""
    return read(asked, report, ureg).problem
