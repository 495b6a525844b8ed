"""The nbgrader source notebook of an assignment.

Cells, in order: instructions (with the exact rules the grader judges by); the
locked parameter cell (grade_id ``parameters``) that loads the student's values
from the student id (the spec in it is the same for every student); per problem
a locked statement with a figure of the linkage and a locked cell showing that
student's given values; per graded quantity an answer cell (grade_id
``answer_<name>``) and a test cell (grade_id ``test_<name>``, one point) with
the visible check of form and dimension.

No cell holds or computes an answer: there is no solution in the source and no
hidden test. The grader judges each value outside the notebook, against the key
it computes for the submitter (:mod:`accelab.exercises.grader`). Source and released
notebook have the same locked cells.
"""

import base64
import json
import os

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

from .assignment import DEFAULT_ANGLE_TOLERANCE, build_variant, check_spec
from .figure import statement_figure

PREVIEW_STUDENT = "preview"


def _meta(grade_id, *, solution=False, grade=False, locked=False, points=None):
    nb = {
        "grade": grade,
        "grade_id": grade_id,
        "locked": locked,
        "schema_version": 3,
        "solution": solution,
        "task": False,
    }
    if points is not None:
        nb["points"] = points
    meta = {"nbgrader": nb}
    if locked:
        meta.update(deletable=False, editable=False)
    return meta


def _md(text, grade_id, **extra):
    cell = new_markdown_cell(text, metadata=_meta(grade_id, locked=True))
    cell.update(extra)
    return cell


def _code(source, grade_id, **kw):
    return new_code_cell(source, metadata=_meta(grade_id, **kw))


INSTRUCTIONS = """# {title}

Each student gets their own values: the cell below loads yours, the values of the student
that nbgrader will collect your submission as ({student_hint}), and says whose they are, so
run it first. `v.given(k)` gives the values of problem k as Quantities,
ready for the solver (for example `g = v.given(1); FourBar(a=g["a"], b=g["b"], c=g["c"],
d=g["d"])`).

In each answer cell assign your result to the named variable, either as a Quantity in any
unit of the right dimension, e.g. `alpha3 = Q_(-12.3, "rad/s^2")` (`ureg` and `Q_` are ready),
or as a bare number in the unit given in brackets; where the statement says so, give a
Quantity. Angles are measured counter-clockwise from +x; omega and alpha are positive
counter-clockwise.

**How your answers are judged.** The cell after each answer checks now that the variable
exists and has the right form and dimension, and that this notebook shows your own values;
so does *Validate*, which therefore passes with wrong numbers too. The values are judged when
the assignment is graded, outside this notebook, against the exact value for your own values:

- a number is right when it is within {tol} of the exact value (|yours - exact| <= {tol} of
  |exact|), in any unit of the right dimension;
- a direction (an angle) is right when it is within {angle_tol} deg of the exact direction,
  either way (modulo 360 deg);
- a word is right when it is the right one of the words listed.
"""

ANSWER_TEMPLATE = (
    "# your answer: {name} = ...   ({description} [{unit}])\n"
    "### BEGIN SOLUTION\n# the grader computes the key "
    "for each student (accelab variant shows the problem)\n### END SOLUTION\n"
)
TEST_TEMPLATE = (
    "from accelab.exercises.student.runtime import check_format\n"
    "check_format({name!r}, globals())\n"
)
#: problem k of a polygon family: the builder (its construction is the answer, kept
#: in this cell's output when the notebook is saved) and the visible check of each polygon
_BUILDER_CELL = (
    "from accelab.exercises.student.polygon import PolygonBuilder\n"
    "PolygonBuilder.for_assignment(v, {k}).show()\n"
)
_CONSTRUCTION_CHECK = (
    "from accelab.exercises.student.polygon import check_construction\n"
    "check_construction({name!r})\n"
)
_CONSTRUCTION_RULE = """- a construction (a polygon drawn in the polygon builder) earns the
  fraction of its steps that are right: a direction within {angle_tol} deg, a length or a
  point within 2% of the polygon's largest vector, a value read off within what the drawing
  allows. It is read from the notebook as you saved it: **save the notebook before you
  submit**.
"""


def build_notebook(spec, title=None):
    """The source notebook (an nbformat node) of ``spec``."""
    check_spec(spec)
    preview = build_variant(spec, PREVIEW_STUDENT)
    title = title or f"Assignment {spec['assignment']}: acceleration analysis"
    angle_tol = f"{spec.get('angle_tolerance', DEFAULT_ANGLE_TOLERANCE):g}"
    instructions = INSTRUCTIONS.format(
        title=title,
        student_hint=(
            "your JupyterHub user name; without JupyterHub, the account you fetched the "
            "assignment from; else the id you set in `ACCELAB_STUDENT`"
        ),
        tol=f"{100 * spec['tolerance']:g}%",
        angle_tol=angle_tol,
    )
    if any(a.kind == "construction" for p in preview.problems for a in p.answers):
        instructions += _CONSTRUCTION_RULE.format(angle_tol=f"{DEFAULT_ANGLE_TOLERANCE:g}")
    cells = [_md(instructions, "instructions")]
    cells.append(
        _code(
            "from accelab.exercises.student.runtime import ureg, Q_, load_variant\n"
            f"SPEC = {json.dumps(spec, sort_keys=True)}\n"
            "v = load_variant(SPEC)\n",
            "parameters",
            locked=True,
        )
    )
    for k, problem in enumerate(preview.problems, start=1):
        png = base64.b64encode(statement_figure(problem)).decode("ascii")
        rows = "\n".join(
            f"| `{a.name}` | {a.description} | "
            + (
                "drawn in the builder"
                if a.kind == "construction"
                else f"{a.unit or ('one of ' + ', '.join(a.choices) if a.choices else '-')}"
            )
            + " |"
            for a in problem.answers
        )
        text = (
            f"## Problem {k}: {problem.title}\n\n{problem.statement}\n\n"
            f"![figure](attachment:figure{k}.png)\n\n"
            f"| variable | quantity | unit |\n|---|---|---|\n{rows}\n"
        )
        cells.append(_md(text, f"problem{k}", attachments={f"figure{k}.png": {"image/png": png}}))
        cells.append(_code(f"v.show({k})", f"given{k}", locked=True))
        if any(a.kind == "construction" for a in problem.answers):
            cells.append(_code(_BUILDER_CELL.format(k=k), f"polygon{k}", locked=True))
        for a in problem.answers:
            if a.kind == "construction":
                cells.append(
                    _code(
                        _CONSTRUCTION_CHECK.format(name=a.name),
                        f"test_{a.name}",
                        grade=True,
                        locked=True,
                        points=1,
                    )
                )
                continue
            unit = a.unit or "text"
            cells.append(
                _code(
                    ANSWER_TEMPLATE.format(description=a.description, unit=unit, name=a.name),
                    f"answer_{a.name}",
                    solution=True,
                )
            )
            cells.append(
                _code(
                    TEST_TEMPLATE.format(name=a.name),
                    f"test_{a.name}",
                    grade=True,
                    locked=True,
                    points=1,
                )
            )
    nb = new_notebook(cells=cells)
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nb.metadata["language_info"] = {"name": "python"}
    return nb


def write_source(course_dir, spec, title=None):
    """Write ``source/<A>/<A>.ipynb`` and ``source/<A>/accelab.json``; returns the notebook path."""
    folder = os.path.join(course_dir, "source", spec["assignment"])
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "accelab.json"), "w") as fh:
        json.dump(spec, fh, indent=1, sort_keys=True)
    path = os.path.join(folder, f"{spec['assignment']}.ipynb")
    nbformat.write(build_notebook(spec, title), path)
    return path


def read_spec(course_dir, assignment):
    """The spec that ``accelab assign`` stored for ``assignment``."""
    path = os.path.join(course_dir, "source", assignment, "accelab.json")
    if not os.path.exists(path):
        raise FileNotFoundError(
            f"no assignment {assignment!r} in {course_dir} (missing {path}); "
            f"create it with: accelab assign --course {course_dir} "
            f"--assignment {assignment}"
        )
    with open(path) as fh:
        return check_spec(json.load(fh))
