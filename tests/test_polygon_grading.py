"""Constructions graded for real: `accelab assign` with the three polygon families,
submissions whose builder cells hold right, partly right, missing and forged
constructions, then `accelab grade` (nbgrader, the bubblewrap sandbox, feedback,
CSV).

The construction is read from the submitted notebook outside the sandbox, judged
step by step against the submitter's own key with partial credit, and shown in
the feedback as the drawing with the wrong steps marked. A forged or malformed
record is refused with the reason, earns nothing, and costs no other answer.
"""

import cmath
import copy
import csv
import json
import math
import os
import re

import _forked as forked
import nbformat
import pytest

from accelab.exercises.grader.key import key_for
from accelab.exercises.grader.sandbox import check_sandbox
from accelab.exercises.notebook import read_spec
from accelab.exercises.simulate import submit
from accelab.exercises.student.polygon.record import FORMAT, MIMETYPE, VERSION
from accelab.exercises.student.polygon.task import ideal_steps

#: one worker grades the course of the module fixture, once, for all the tests that read it
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("polygon-grade")]

FAMILIES = ["polygon_fourbar", "polygon_slidercrank", "polygon_coriolis"]


def accelab(*args, check=True):
    """``accelab ARGS`` in a process of its own (forked from this one: tests/_forked.py)."""
    proc = forked.run(list(args))
    if check:
        assert proc.returncode == 0, proc.stderr
    return proc


def ideal(course, student, k):
    """The finished construction of problem k for ``student`` (both polygons)."""
    key = key_for(read_spec(course, "A"), student)
    name = key.variant.problems[k - 1].answers[0].name
    task = key.values[name].task
    return task, [s for ph in task.phases.values() for s in ideal_steps(ph)]


def record(student, k, steps, **extra):
    out = {
        "format": FORMAT,
        "version": VERSION,
        "student": student,
        "problem": k,
        "family": FAMILIES[k - 1],
        "steps": steps,
    }
    out.update(extra)
    return out


def with_records(records, where="polygon{k}"):
    """An edit that puts each problem's record into the output of its builder cell
    (or of the cell ``where`` names), as the builder does when the notebook is saved."""

    def edit(nb):
        for k, data in records.items():
            gid = where.format(k=k)
            cell = next(
                c for c in nb.cells if c.metadata.get("nbgrader", {}).get("grade_id") == gid
            )
            cell.outputs = [
                nbformat.from_dict(
                    {
                        "output_type": "display_data",
                        "data": {"text/markdown": "*saved*", MIMETYPE: data},
                        "metadata": {},
                    }
                )
            ]
        return nb

    return edit


def flip(steps, name, phase="acceleration"):
    """The vector ``name`` turned round about its tail (a wrong sense)."""
    out = copy.deepcopy(steps)
    for s in out:
        if s["phase"] == phase and s["op"] == "vector" and s.get("name") == name:
            (tx, ty), (hx, hy) = s["tail"], s["tip"]
            s["tip"] = [2 * tx - hx, 2 * ty - hy]
    return out


def without(steps, name, phase="acceleration"):
    return [s for s in steps if not (s["phase"] == phase and s.get("name") == name)]


def forgot_coriolis(task, steps):
    """The classic inverted slider-crank mistake: no A_cor, and the line of A_slip
    drawn through the tip of A_A4^n instead (so the crossing and what follows move)."""
    ph = task.phase("acceleration")
    out = without(steps, "A_cor")
    tip = ph.term("A_A4^n").vector
    for s in out:
        if s["phase"] == "acceleration" and s["op"] == "line" and s["name"] == "A_slip":
            s["through"] = [tip.real, tip.imag]
    return out


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    reason = check_sandbox()
    assert reason is None, f"the sandbox must work in CI: {reason}"
    course = str(tmp_path_factory.mktemp("polygons") / "mech")
    roster = tmp_path_factory.mktemp("roster") / "roster.csv"
    students = ["right", "partly", "empty", "other", "forged", "moved"]
    roster.write_text("id\n" + "\n".join(students) + "\n")
    accelab(
        "assign", "--course", course, "--assignment", "A", "--families", ",".join(FAMILIES),
        "--roster", str(roster), "--release", "--due", "2040-01-01 00:00",
    )  # fmt: skip
    full = {k: record("right", k, ideal(course, "right", k)[1]) for k in (1, 2, 3)}
    submit(course, "A", "right", {}, edit=with_records(full))
    # partly right: problem 1 with a wrong sense of A_A^n and no A_B; problem 2 whole;
    # problem 3 with the Coriolis term forgotten; the velocity polygons all right
    t1, s1 = ideal(course, "partly", 1)
    t3, s3 = ideal(course, "partly", 3)
    partly = {
        1: record("partly", 1, without(flip(s1, "A_A^n"), "A_B")),
        2: record("partly", 2, ideal(course, "partly", 2)[1]),
        3: record("partly", 3, forgot_coriolis(t3, s3)),
    }
    submit(course, "A", "partly", {}, edit=with_records(partly))
    submit(course, "A", "empty", {})  # never drawn (or never saved)
    # another student's construction, as if copied
    submit(course, "A", "other", {}, edit=with_records(full))
    # forged records: too many steps (problem 1), bad numbers (2), deep nesting (3)
    step = ideal(course, "forged", 1)[1][0]
    garbled = copy.deepcopy(ideal(course, "forged", 2)[1])
    garbled[0]["tip"] = ["1e400", "x"]
    deep = []
    for _ in range(400):
        deep = [deep]
    forged = {
        1: record("forged", 1, [step] * 1000),
        2: record("forged", 2, garbled),
        3: record("forged", 3, deep),
    }
    submit(course, "A", "forged", {}, edit=with_records(forged))
    moved = {1: record("moved", 1, ideal(course, "moved", 1)[1])}
    submit(course, "A", "moved", {}, edit=with_records(moved, where="given{k}"))
    proc = accelab("grade", "--course", course, "--assignment", "A", "--quiet", check=False)
    with open(os.path.join(course, "grades_A.csv")) as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    return {"course": course, "rows": rows, "proc": proc, "tasks": {1: t1, 3: t3}}


def scores(g, student):
    row = g["rows"][student]
    return {k: float(v) for k, v in row.items() if k.startswith("p") and "_polygon" in k}


def feedback(g, student):
    path = os.path.join(g["course"], "feedback", student, "A", "A.html")
    text = open(path).read()
    text = re.sub(r"<(style|script)\b.*?</\1>", "", text, flags=re.S)
    return re.sub(r"\s+", " ", text)  # the feedback's text is wrapped for a phone


def test_the_assignment_has_a_builder_and_a_check_per_polygon(graded):
    nb = nbformat.read(os.path.join(graded["course"], "release", "A", "A.ipynb"), as_version=4)
    ids = [c.metadata.get("nbgrader", {}).get("grade_id") for c in nb.cells]
    for k in (1, 2, 3):
        assert f"polygon{k}" in ids
        for phase in ("velocity", "acceleration"):
            assert f"test_p{k}_{phase}_polygon" in ids
    assert not any(i and i.startswith("answer_") for i in ids)  # nothing to type
    assert "save the notebook before you" in " ".join(nb.cells[0].source.split())


def test_a_right_construction_gets_full_marks(graded):
    assert graded["proc"].returncode == 0, graded["proc"].stderr
    s = scores(graded, "right")
    assert len(s) == 6 and all(v == 1.0 for v in s.values()), s
    assert float(graded["rows"]["right"]["total"]) == 6.0
    # written into the notebook from the exact construction: the CSV says so
    assert "is the exact one to 1e-09 in every known vector" in graded["rows"]["right"]["notes"]


def test_partial_credit_per_step_and_the_wrong_steps_explained(graded):
    s = scores(graded, "partly")
    assert s["p1_velocity_polygon"] == s["p2_velocity_polygon"] == s["p3_velocity_polygon"] == 1
    assert s["p2_acceleration_polygon"] == 1.0
    assert 0.5 < s["p1_acceleration_polygon"] < 1.0
    assert 0.0 < s["p3_acceleration_polygon"] < s["p1_acceleration_polygon"]
    text = feedback(graded, "partly")
    assert "A_A^n has the wrong sense: A_A^n points from A toward O2" in text
    assert "A_B is not drawn" in text
    assert "the inverted slider-crank needs the Coriolis term" in text
    assert "perpendicular to the slide" in text
    assert "numbered as on your drawing" in text
    # the drawing itself, with the wrong steps marked
    assert text.count("data:image/png;base64,") >= 2


def test_the_feedback_never_states_an_expected_length_angle_or_value(graded):
    text = re.sub(r"data:image/png;base64,[A-Za-z0-9+/=]+", "", feedback(graded, "partly"))
    text = re.sub(r"<[^>]+>", " ", text)
    for task in graded["tasks"].values():
        for phase in task.phases.values():
            for t in phase.terms:
                size = abs(t.vector) * phase.factor
                angle = math.degrees(cmath.phase(t.vector)) % 360
                for shown in (f"{size:.4g}", f"{size:.3f}", f"{angle:.4g}", f"{angle:.1f}"):
                    if len(shown.strip("-0.")) >= 3:  # not a round number of the givens
                        assert not re.search(rf"(?<![\d.]){re.escape(shown)}(?![\d])", text), (
                            t.name,
                            shown,
                        )
            for r in phase.reads:
                assert f"{r.value:.4g}" not in text, r.name


def test_no_construction_saved_gets_zero_and_says_what_to_do(graded):
    s = scores(graded, "empty")
    assert all(v == 0.0 for v in s.values())
    assert "save the notebook before you submit" in feedback(graded, "empty")


def test_another_students_construction_is_judged_against_the_submitters_values(graded):
    s = scores(graded, "other")
    assert sum(s.values()) < 2.0, s
    assert "drawn for the values of 'right'" in graded["rows"]["other"]["notes"]


@pytest.mark.parametrize(
    "student,k,why",
    [
        ("forged", 1, "more than 200 steps"),
        ("forged", 2, "is not a number"),
        ("forged", 3, "is not a step"),
        ("moved", 1, "no construction was saved"),
    ],
)
def test_a_forged_construction_is_refused_with_the_reason(graded, student, k, why):
    s = scores(graded, student)
    assert s[f"p{k}_velocity_polygon"] == s[f"p{k}_acceleration_polygon"] == 0.0
    text = feedback(graded, student)
    assert f"p{k}_velocity_polygon: no credit" in text and why in text
    assert "Traceback" not in text


def test_every_submission_was_graded(graded):
    assert set(graded["rows"]) >= {"right", "partly", "empty", "other", "forged", "moved"}
    for row in graded["rows"].values():
        assert "not graded" not in row["notes"], row
    assert json.dumps(scores(graded, "right"))  # plain numbers in the CSV
