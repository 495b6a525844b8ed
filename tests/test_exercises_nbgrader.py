"""End to end: nbgrader really runs (generate, release, autograde, feedback, export)
on a course made by ``accelab assign``, with submissions that are right (filled
by an outside check from ``accelab variant`` and an independent solver), right
in other units, swapped between students, wrong, wrong in dimension, crashing,
looping, tampered, and unreadable."""

import csv
import glob
import json
import os
import subprocess
import sys
import time

import nbformat
import pytest

from exercises.autograde import question_names
from exercises.simulate import submit

from _exercises_helpers import answers_code

pytestmark = pytest.mark.slow

SECRET = "s3cr3t-instructor-token"
ACCELAB = [sys.executable, "-m", "solver"]
OTHER_UNIT = {"in/s^2": "ft/s^2", "deg": "rad", "rad/s^2": "deg/s^2", "g_0": "m/s^2"}
DIMENSION = {"in/s^2": "in/s", "deg": "m", "rad/s^2": "rad/s", "g_0": "N"}


def accelab(*args):
    proc = subprocess.run([*ACCELAB, *args], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def outside(course, student):
    """Answer code for ``student`` from the published variant and the independent solver."""
    return answers_code(json.loads(accelab("variant", "--course", course, "--assignment", "A",
                                           "--student", student, "--json")))


def _cell(nb, gid):
    return next(c for c in nb.cells if c.metadata.get("nbgrader", {}).get("grade_id") == gid)


def rewrite(code, fn):
    """Apply fn(name, line) to each answer line (choice answers too)."""
    return {n: fn(n, line) for n, line in code.items()}


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    course = str(tmp_path_factory.mktemp("course") / "mech")
    roster = tmp_path_factory.mktemp("roster") / "roster.csv"
    roster.write_text("id,first_name,last_name\nann,Ann,A\nhal,Hal,H\n")
    accelab("assign", "--course", course, "--assignment", "A", "--course-id", "e2e",
            "--roster", str(roster), "--timeout", "4", "--release")
    units = {a["name"]: a["unit"] for a in
             json.loads(accelab("variant", "--course", course, "--assignment", "A",
                                "--student", "ann", "--json"))["answers"]}
    ann = outside(course, "ann")
    submit(course, "A", "ann", ann)
    hal = outside(course, "hal")
    hal["p1_A_A_x"] = ("import os\nprint('env:', os.environ.get('ACCELAB_TEST_SECRET', "
                       "'no-secret'))\n" + hal["p1_A_A_x"])
    submit(course, "A", "hal", hal)
    submit(course, "A", "bo", ann)                                         # swapped variant

    def wrong_dim(name, line):
        if units[name] == "":
            return f"{name} = 3.0"
        return line.replace(f"{units[name]!r})", f"{DIMENSION[units[name]]!r})")
    submit(course, "A", "cy", rewrite(outside(course, "cy"), wrong_dim))

    def other_units(name, line):
        return line if units[name] == "" else f"{line}.to({OTHER_UNIT[units[name]]!r})"
    submit(course, "A", "di", rewrite(outside(course, "di"), other_units))
    submit(course, "A", "ed", rewrite(outside(course, "ed"),                 # sign errors
                                      lambda n, l: l if units[n] == "" else l.replace("Q_(", "-Q_(")))
    flo = outside(course, "flo")
    flo["p1_A_A_x"] = "raise ZeroDivisionError('oops')"
    submit(course, "A", "flo", flo)
    gus = outside(course, "gus")
    gus["p2_alpha3"] = "while True:\n    pass"
    submit(course, "A", "gus", gus)
    ivy = outside(course, "ivy")
    ivy["p2_alpha4"] = ivy["p2_alpha4"].replace("p2_alpha4 =", "alpha_4 =")  # renamed variable

    def tamper(nb):
        nb.cells.remove(_cell(nb, "test_p1_A_A_y"))                           # deleted test
        _cell(nb, "test_p2_alpha3").source = "pass  # trust me"              # altered test
        return nb
    submit(course, "A", "ivy", ivy, edit=tamper)
    os.makedirs(os.path.join(course, "submitted", "jo", "A"))
    with open(os.path.join(course, "submitted", "jo", "A", "A.ipynb"), "w") as fh:
        fh.write('{"cells": [ this is not json')

    env = dict(os.environ, ACCELAB_TEST_SECRET=SECRET)
    start = time.monotonic()
    proc = subprocess.run([*ACCELAB, "grade", "--course", course, "--assignment", "A",
                           "--jobs", "2"], capture_output=True, text=True, env=env)
    seconds = time.monotonic() - start
    print(f"\naccelab grade: 10 submissions in {seconds:.1f} s on {os.cpu_count()} cores")
    assert proc.returncode == 1, proc.stderr   # jo's notebook is unreadable
    with open(os.path.join(course, "grades_A.csv")) as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    return course, rows, proc


def score(rows, student):
    names = [k for k in rows[student] if k not in ("student", "total", "max", "notes")]
    return {n: float(rows[student][n]) for n in names}


def test_released_notebook_has_answer_cells_and_no_solutions_or_hidden_tests(graded):
    course, rows, _ = graded
    nb = nbformat.read(os.path.join(course, "release", "A", "A.ipynb"), as_version=4)
    text = json.dumps(nb)
    assert "BEGIN HIDDEN" not in text and "check_value" not in text
    assert "v.solution" not in text and "BEGIN SOLUTION" not in text
    names = question_names(course, "A")
    assert len(names) == 12
    for n in names:
        meta = _cell(nb, f"answer_{n}").metadata["nbgrader"]
        assert meta["solution"] and not meta["grade"]
        assert _cell(nb, f"test_{n}").metadata["nbgrader"]["points"] == 1
    assert _cell(nb, "parameters").metadata["nbgrader"]["locked"]
    assert "attachment:figure1.png" in _cell(nb, "problem1").source


def test_outside_check_gets_full_marks(graded):
    course, rows, _ = graded
    for s in ("ann", "hal"):
        assert all(v == 1.0 for v in score(rows, s).values()), rows[s]
        assert rows[s]["total"] == "12.0" and rows[s]["notes"] == ""


def test_other_units_get_full_marks(graded):
    assert all(v == 1.0 for v in score(graded[1], "di").values())


def test_swapped_variant_and_wrong_dimension_get_zero(graded):
    assert sum(score(graded[1], "bo").values()) == 0.0
    assert sum(score(graded[1], "cy").values()) == 0.0


def test_sign_errors_lose_the_numbers_only(graded):
    s = score(graded[1], "ed")
    assert s["p3_verdict"] == 1.0 and sum(s.values()) == 1.0


def test_crash_and_endless_loop_cost_one_question_each(graded):
    s = score(graded[1], "flo")
    assert s["p1_A_A_x"] == 0.0 and sum(s.values()) == 11.0
    s = score(graded[1], "gus")
    assert s["p2_alpha3"] == 0.0 and sum(s.values()) == 11.0


def test_tampering_costs_points_and_is_reported(graded):
    course, rows, _ = graded
    s = score(rows, "ivy")
    assert s["p1_A_A_y"] == 0.0          # deleted test cell: put back failing
    assert s["p2_alpha3"] == 1.0         # altered test cell: restored, graded as usual
    assert s["p2_alpha4"] == 0.0         # renamed variable
    assert sum(s.values()) == 10.0
    assert "test cell test_p1_A_A_y was deleted" in rows["ivy"]["notes"]
    assert "test_p2_alpha3 was altered" in rows["ivy"]["notes"]
    assert "manual" not in rows["ivy"]["notes"]


def test_unreadable_notebook_is_reported_not_graded(graded):
    course, rows, proc = graded
    assert rows["jo"]["total"] == "0.0"
    assert "cannot be read" in rows["jo"]["notes"] and "autograde failed" in rows["jo"]["notes"]
    assert "jo" in proc.stdout


def test_kernel_environment_is_clean_and_carries_the_student(graded):
    course = graded[0]
    nb = nbformat.read(os.path.join(course, "autograded", "hal", "A", "A.ipynb"), as_version=4)
    out = json.dumps(nb)
    assert "env: no-secret" in out and SECRET not in out
    assert "student `hal`" in json.dumps(_cell(nb, "given1").outputs)


def test_feedback_hides_hidden_tests_and_expected_values(graded):
    course = graded[0]
    files = glob.glob(os.path.join(course, "feedback", "*", "A", "A.html"))
    assert len(files) == 9
    for path in files:
        html = open(path).read()
        assert "BEGIN HIDDEN" not in html and "check_value" not in html
        assert "value check is hidden" in html
    from exercises.notebook import read_spec
    from exercises.runtime import load_variant
    spec = read_spec(course, "A")
    # bo gave another student's values; flo and gus gave none for one answer each
    for student, only in (("bo", None), ("flo", "p1_A_A_x"), ("gus", "p2_alpha3")):
        html = open(os.path.join(course, "feedback", student, "A", "A.html")).read()
        nv = load_variant(spec, student)
        for name, a in nv.answers.items():
            if a.kind != "choice" and only in (None, name):
                q = nv.solution(name).magnitude
                for text in (repr(q), f"{q:.6g}", f"{q:.5g}"):
                    assert text not in html, (student, name, text)
    html = open(os.path.join(course, "feedback", "ed", "A", "A.html")).read()
    assert "sense of rotation" in html
    html = open(os.path.join(course, "feedback", "cy", "A", "A.html")).read()
    assert "wrong dimension" in html


def test_grading_again_gives_the_same_grades(graded):
    course, rows, _ = graded
    proc = subprocess.run([*ACCELAB, "grade", "--course", course, "--assignment", "A",
                           "--quiet"], capture_output=True, text=True)
    assert proc.returncode == 1
    with open(os.path.join(course, "grades_A.csv")) as fh:
        again = {r["student"]: r for r in csv.DictReader(fh)}
    assert again == rows
