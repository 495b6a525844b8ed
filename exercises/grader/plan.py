"""What of a submission runs in the sandbox, in order: its code cells, and at
each test cell a report of the answer that cell tests.

The plan is made from the notebook as nbgrader sanitized it (outputs cleared,
duplicated cell ids removed, locked and test cells restored from the source
notebook, deleted test cells put back), so it is the same whether it is made
ahead of nbgrader (to run submissions in parallel) or inside its autograde.
Test cells themselves never run: a student cannot make them pass.
"""

import hashlib
import json
from dataclasses import dataclass

TEST_PREFIX = "test_"
ANSWER_PREFIX = "answer_"


@dataclass(frozen=True)
class Step:
    """One step: run a code cell (``kind == "code"``), or report the answer
    that a test cell tests (``kind == "report"``). ``index`` is the cell's
    position in the notebook."""

    index: int
    kind: str
    source: str = ""
    name: str = ""
    grade_id: str = ""


def grade_id(cell):
    return cell.get("metadata", {}).get("nbgrader", {}).get("grade_id", "") or ""


def is_test(cell):
    meta = cell.get("metadata", {}).get("nbgrader", {})
    return bool(meta.get("grade")) and grade_id(cell).startswith(TEST_PREFIX)


def plan_of(nb):
    """The steps of a (sanitized) notebook."""
    steps = []
    for index, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        gid = grade_id(cell)
        if is_test(cell):
            steps.append(Step(index, "report", name=gid[len(TEST_PREFIX) :], grade_id=gid))
        else:
            steps.append(Step(index, "code", source=cell.source, grade_id=gid))
    return steps


def fingerprint(steps):
    """A digest of the plan: the same plan, the same run."""
    data = json.dumps([[s.index, s.kind, s.source, s.name] for s in steps])
    return hashlib.sha256(data.encode("utf-8")).hexdigest()


def answer_cells(steps):
    """name -> index of the step whose cell is ``answer_<name>``."""
    return {
        s.grade_id[len(ANSWER_PREFIX) :]: k
        for k, s in enumerate(steps)
        if s.grade_id.startswith(ANSWER_PREFIX)
    }
