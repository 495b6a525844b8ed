"""`accelab assign` and `accelab demo` on the instructor's side: every roster
student checked, an assignment with submissions protected, the demo's folder.
The commands run as processes of their own, forked from this one (tests/_forked.py)."""

import json
import os

import _forked as forked

from accelab.exercises.assign import AssignError, assign
from accelab.exercises.simulate import key_code, submit


def test_assign_checks_every_roster_student_and_says_which_fails(tmp_path):
    course = str(tmp_path / "c")
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nann\nbob\n")
    proc = forked.run(
        [
            "assign",
            "--course",
            course,
            "--assignment",
            "A",
            "--roster",
            str(roster),
            "--families",
            "fourbar",
            "--ranges",
            json.dumps({"fourbar": {"a": [20, 20], "b": [1, 1], "c": [1, 1], "d": [3, 3]}}),
            "--no-generate",
        ]
    )
    assert proc.returncode == 2
    assert "gets no valid problem" in proc.stderr and "widen the ranges" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not os.path.exists(os.path.join(course, "source", "A", "A.ipynb"))


def test_an_assignment_with_submissions_is_replaced_only_when_forced(tmp_path):
    course = str(tmp_path / "c")
    assign(course, "A", ["rotation"], roster=["ann"], generate=False, say=lambda *a: None)
    from accelab.exercises.notebook import read_spec

    submit_spec = read_spec(course, "A")
    os.makedirs(os.path.join(course, "release", "A"))
    import nbformat

    from accelab.exercises.notebook import build_notebook

    nbformat.write(build_notebook(submit_spec), os.path.join(course, "release", "A", "A.ipynb"))
    submit(course, "A", "ann", key_code(submit_spec, "ann"))
    try:
        assign(course, "A", ["rotation"], units="SI", generate=False)
        raise AssertionError("assign replaced an assignment with submissions")
    except AssignError as exc:
        assert "already has 1 submission" in str(exc) and "units" in str(exc)
    said = []
    assign(course, "A", ["rotation"], units="SI", generate=False, force=True, say=said.append)
    folder = os.path.join(course, ".accelab", "replaced")
    kept = os.listdir(folder)
    assert len(kept) == 1 and kept[0].startswith("A-") and "units" in said[0]
    assert json.load(open(os.path.join(folder, kept[0])))["units"] == "US"


def test_demo_never_deletes_a_folder_it_did_not_make(tmp_path):
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "thesis.tex").write_text("years of work")
    proc = forked.run(["demo", "--course", str(folder)])
    assert proc.returncode == 2 and "was not made by accelab demo" in proc.stderr
    assert (folder / "thesis.tex").read_text() == "years of work"
