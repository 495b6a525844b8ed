"""The instructor's workflow of the README, end to end, with nbgrader's real
exchange: assign and release; two students fetch, work and submit; the
instructor collects, grades (sandbox), releases feedback; the students fetch it;
the gradebook is exported."""

import csv
import json
import os
import subprocess
import sys

import nbformat
import pytest
from _exercises_helpers import answers_code

from accelab.exercises.variant import variant_json

pytestmark = pytest.mark.slow


def run(args, cwd, user=None, check=True):
    env = dict(os.environ)
    env.pop("JUPYTERHUB_USER", None)
    if user:  # each student has a home of their own (nbgrader keeps its cache there)
        env["USER"] = env["LOGNAME"] = user
        env["HOME"] = cwd
        env.pop("JUPYTER_DATA_DIR", None)
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")
    proc = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True)
    if check:
        assert proc.returncode == 0, (args, proc.stdout[-2000:], proc.stderr[-3000:])
    return proc


def nbgrader(*args, cwd, user=None):
    """nbgrader as the instructor, or as ``user`` (one machine account plays every
    student here, so the student id is given as nbgrader allows: --student)."""
    extra = ["--student", user] if user and args[0] in ("submit", "fetch_feedback") else []
    return run([sys.executable, "-m", "nbgrader", *args, *extra], cwd, user)


def accelab(*args, cwd):
    return run([sys.executable, "-m", "accelab", *args], cwd)


def student_config(home, exchange):
    os.makedirs(home, exist_ok=True)
    with open(os.path.join(home, "nbgrader_config.py"), "w") as fh:
        fh.write(
            f"c = get_config()\nc.CourseDirectory.course_id = 'mech101'\n"
            f"c.Exchange.root = {exchange!r}\n"
        )


def work(home, student, course):
    """The student opens the fetched notebook and writes answers in its answer cells."""
    path = os.path.join(home, "A", "A.ipynb")
    nb = nbformat.read(path, as_version=4)
    code = answers_code(json.loads(json.dumps(variant_json(course, "A", student))))
    for cell in nb.cells:
        gid = cell.metadata.get("nbgrader", {}).get("grade_id", "")
        if gid.startswith("answer_") and gid[len("answer_") :] in code:
            cell.source = code[gid[len("answer_") :]]
    if student == "hal":  # one wrong answer
        first = next(
            c
            for c in nb.cells
            if c.metadata.get("nbgrader", {}).get("grade_id", "").startswith("answer_")
        )
        first.source = first.source.replace("Q_(", "-Q_(")
    nbformat.write(nb, path)


def test_assign_release_fetch_submit_collect_grade_feedback_export(tmp_path):
    course = str(tmp_path / "course")
    exchange = str(tmp_path / "exchange")
    os.makedirs(exchange)
    os.chmod(exchange, 0o777)
    roster = tmp_path / "roster.csv"
    roster.write_text("id,first_name,last_name\nann,Ann,A\nhal,Hal,H\nivy,Ivy,I\n")
    accelab(
        "assign",
        "--course",
        course,
        "--assignment",
        "A",
        "--course-id",
        "mech101",
        "--roster",
        str(roster),
        "--families",
        "rotation,fourbar",
        cwd=str(tmp_path),
    )
    with open(os.path.join(course, "nbgrader_config.py"), "a") as fh:
        fh.write(f"c.Exchange.root = {exchange!r}\n")
    nbgrader("release_assignment", "A", "--force", cwd=course)
    for student in ("ann", "hal"):
        home = str(tmp_path / student)
        student_config(home, exchange)
        listing = (
            nbgrader("list", cwd=home, user=student).stdout
            + nbgrader("list", cwd=home, user=student).stderr
        )
        assert "mech101 A" in listing
        nbgrader("fetch_assignment", "A", cwd=home, user=student)
        work(home, student, course)
        nbgrader("submit", "A", cwd=home, user=student)
    nbgrader("collect", "A", cwd=course)
    assert sorted(os.listdir(os.path.join(course, "submitted"))) == ["ann", "hal"]

    proc = accelab("grade", "--course", course, "--assignment", "A", "--quiet", cwd=course)
    assert "2 submission(s) graded" in proc.stdout
    with open(os.path.join(course, "grades_A.csv")) as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    n = float(rows["ann"]["max"])
    assert float(rows["ann"]["total"]) == n and float(rows["hal"]["total"]) == n - 1
    assert "no submission" in rows["ivy"]["notes"]

    nbgrader("release_feedback", "A", cwd=course)
    for student in ("ann", "hal"):
        home = str(tmp_path / student)
        nbgrader("fetch_feedback", "A", cwd=home, user=student)
        pages = [
            os.path.join(root, f)
            for root, _, files in os.walk(os.path.join(home, "A"))
            for f in files
            if f.endswith(".html")
        ]
        assert len(pages) == 1, f"feedback fetched for {student}: {pages}"
        text = open(pages[0]).read()
        assert "Graded against the values of student " + student in text

    nbgrader("export", cwd=course)
    with open(os.path.join(course, "grades.csv")) as fh:
        exported = {r["student_id"]: r for r in csv.DictReader(fh)}
    assert float(exported["ann"]["score"]) == n and float(exported["hal"]["score"]) == n - 1
