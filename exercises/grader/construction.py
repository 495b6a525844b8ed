"""Grading a construction answer (the polygon families): read outside the sandbox,
judged against the submitter's own key, shown back as the student's drawing.

The construction is not in the kernel: the builder keeps it in an output of its
own cell (grade id ``polygon<k>``, mimetype
:data:`~accelab.exercises.student.polygon.record.MIMETYPE`), which the student
saves with the notebook and nbgrader's submit and collect carry. So the grader
reads it from the **submitted** notebook (nbgrader's sanitizing clears outputs
before grading), in its own process, with the one bounded reader
(:func:`~accelab.exercises.student.polygon.record.read_record`): a record of the
wrong shape, size or content is refused with the reason and earns nothing. Each
polygon is judged with the same rules as the builder's practice feedback
(:mod:`accelab.exercises.student.polygon.rules`) against the construction of the
submitter's own values, with partial credit: the fraction of its steps that are
right. The feedback shows the student's drawing with each wrong step marked
(a numbered red badge) and explained.
"""

import base64
import json
import re
import textwrap
from dataclasses import dataclass
from functools import lru_cache

from ..student.polygon.figure import construction_png
from ..student.polygon.record import MIMETYPE, RecordError, read_record
from ..student.polygon.rules import judge_phase
from ..student.polygon.task import task_of_case
from .judge import Verdict

#: the grade id of problem k's builder cell
BUILDER_ID = re.compile(r"^polygon(\d{1,3})$")
#: most outputs of a builder cell the grader looks through
MAX_OUTPUTS = 50
#: the feedback's text is wrapped at this width (it reads on a phone)
WIDTH = 72
#: a drawing whose every known vector is the exact one to this relative precision was
#: not drawn by hand or typed from a reading (the CSV says so; the grade is the same)
EXACT = 1e-9


@dataclass(frozen=True)
class ConstructionKey:
    """The key of a construction answer: the submitter's case and the polygon
    (``"velocity"`` or ``"acceleration"``); the exact construction is made from
    them when it is judged."""

    case: dict
    phase: str

    @property
    def task(self):
        return _task(json.dumps(self.case, sort_keys=True))


@lru_cache(maxsize=256)
def _task(text):
    return task_of_case(json.loads(text))


def records_of(nb):
    """``{k: Record or refusal message}`` for each builder cell of a (raw,
    submitted) notebook: the last record its outputs hold. A cell that appears
    twice counts once, the last one (as nbgrader keeps the last of a grade id)."""
    found = {}
    for cell in getattr(nb, "cells", []) or []:
        try:
            gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id", "")
        except AttributeError:
            continue
        m = BUILDER_ID.match(gid) if isinstance(gid, str) else None
        if not m or cell.get("cell_type") != "code":
            continue
        found[int(m.group(1))] = _record_in(cell.get("outputs"))
    return found


def _record_in(outputs):
    if not isinstance(outputs, list):
        return "the builder's cell has no outputs"
    if len(outputs) > MAX_OUTPUTS:
        return f"the builder's cell has more than {MAX_OUTPUTS} outputs"
    data = None
    for out in outputs:
        bundle = out.get("data") if isinstance(out, dict) else None
        if isinstance(bundle, dict) and MIMETYPE in bundle:
            data = bundle[MIMETYPE]
    if data is None:
        return (
            "no construction was saved with the notebook: draw it in the builder (run its "
            "cell in JupyterLab), then save the notebook before you submit"
        )
    try:
        return read_record(data)
    except RecordError as exc:
        return f"the construction saved with the notebook cannot be read: {exc}"
    except (RecursionError, TypeError, ValueError, AttributeError):
        return "the construction saved with the notebook cannot be read"


def problem_of(variant, name):
    """The 1-based number of the problem an answer belongs to."""
    for k, p in enumerate(variant.problems, start=1):
        if any(a.name == name for a in p.answers):
            return k
    raise KeyError(name)


def _wrapped(mark, text):
    """A numbered explanation, wrapped for a narrow feedback page."""
    return textwrap.fill(
        text, WIDTH, initial_indent=f"  {mark} ", subsequent_indent=" " * (len(mark) + 3)
    )


def judge_construction(name, key, record):
    """``(Verdict, outputs, note)`` of one construction answer: ``record`` is a
    Record, a refusal message, or None (no builder cell); ``outputs`` are the
    feedback's extra outputs (the drawing); ``note`` is for the CSV or ''."""
    if record is None:
        return (
            Verdict(
                name,
                False,
                0.0,
                f"{name}: no credit: the polygon builder's cell of this problem is missing "
                "from the notebook",
            ),
            [],
            "",
        )
    if isinstance(record, str):
        return Verdict(name, False, 0.0, f"{name}: no credit: {record}"), [], ""
    task = key.task
    phase = task.phase(key.phase)
    steps = [s for s in record.steps if s.phase == key.phase]
    j = judge_phase(phase, steps, list(task.phases.values()))
    wrong, lines = {}, []
    for result in j.results:
        if result.ok:
            continue
        if result.index is not None:
            wrong[result.index] = len(wrong) + 1
            lines.append(_wrapped(f"({wrong[result.index]})", result.message))
        else:
            lines.append(_wrapped("(-)", result.message))
    lines += [_wrapped("(note)", n) for n in j.notes]
    total = len(j.results)
    head = f"{name}: {j.right} of {total} steps of the {phase.title.lower()} right"
    if j.right == total:
        message = f"{head}."
    else:
        message = (
            textwrap.fill(
                f"{head} (credit {j.credit:.3g} of 1). Wrong or missing steps, numbered as "
                "on your drawing:",
                WIDTH,
            )
            + "\n"
            + "\n".join(lines)
        )
    outputs = []
    if steps:
        png = construction_png(task, steps, key.phase, wrong=wrong)
        outputs.append(
            {
                "output_type": "display_data",
                "data": {
                    "image/png": base64.b64encode(png).decode("ascii"),
                    "text/plain": f"<your {phase.title.lower()}, wrong steps marked>",
                },
                "metadata": {},
            }
        )
    return Verdict(name, j.right == total, round(j.credit, 4), message), outputs, ""


def _exact(key, record):
    """Whether every known vector of the polygon is drawn exactly (see :data:`EXACT`)."""
    phase = key.task.phase(key.phase)
    drawn = {s.name: s for s in record.steps if s.phase == key.phase and s.op == "vector"}
    knowns = [t for t in phase.terms if t.known]
    return len(knowns) >= 1 and all(
        t.name in drawn and abs(drawn[t.name].vector - t.vector) <= EXACT * abs(t.vector)
        for t in knowns
    )


def judge_constructions(key, records):
    """``(verdicts, outputs, notes)`` of every construction answer of the
    submitter's ``key`` (:class:`~accelab.exercises.grader.key.Key`), from
    ``records`` (:func:`records_of`)."""
    verdicts, outputs, notes = {}, {}, []
    seen, exact = set(), set()
    for name, answer in key.variant.answers.items():
        if answer.kind != "construction":
            continue
        k = problem_of(key.variant, name)
        record = records.get(k)
        verdict, extra, note = judge_construction(name, key.values[name], record)
        verdicts[name], outputs[name] = verdict, extra
        if note:
            notes.append(note)
        if not isinstance(record, (str, type(None))) and k not in exact:
            if _exact(key.values[name], record):
                exact.add(k)
                notes.append(
                    f"the construction of problem {k} is the exact one to {EXACT:g} in every "
                    "known vector: it was not drawn in the builder by hand (computed, or written "
                    "into the notebook)"
                )
        if (
            k not in seen
            and not isinstance(record, (str, type(None)))
            and record.student
            and record.student != key.student
        ):
            seen.add(k)
            notes.append(
                f"the construction of problem {k} was drawn for the values of "
                f"{record.student!r}, not the submitter's; it was judged against "
                f"{key.student}'s own values"
            )
    return verdicts, outputs, notes
