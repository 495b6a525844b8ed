"""Whose values a student's notebook shows: the student nbgrader will collect it as
(``accelab.exercises.student.identity``), and the visible checks (what Validate runs)
failing, with a sentence naming both, when the notebook shows someone else's values."""

import os
import pwd

import pytest

from accelab.exercises.student import runtime
from accelab.exercises.student.identity import identify

SPEC = {
    "course": "mech101",
    "assignment": "A",
    "units": "US",
    "tolerance": 0.01,
    "angle_tolerance": 1.0,
    "problems": [{"family": "tolerance"}],
}
ME = pwd.getpwuid(os.getuid()).pw_name


@pytest.fixture
def clean(monkeypatch, tmp_path):
    """No hub, no explicit id, no nbgrader configuration but the one a test writes (in the
    working folder, where nbgrader's Assignments panel looks too)."""
    for var in ("JUPYTERHUB_USER", "ACCELAB_STUDENT", "ACCELAB_STUDENT_ID"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setenv("JUPYTER_CONFIG_DIR", str(tmp_path / "no-config"))
    monkeypatch.setenv("JUPYTER_CONFIG_PATH", "")
    monkeypatch.setenv("JUPYTER_PLATFORM_DIRS", "1")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(
        "jupyter_core.paths.SYSTEM_CONFIG_PATH", [str(tmp_path / "none")], raising=False
    )
    monkeypatch.setattr(
        "jupyter_core.paths.ENV_CONFIG_PATH", [str(tmp_path / "none")], raising=False
    )
    runtime._state.update(grading=None, variant=None, refused=[], spec=None)
    yield tmp_path
    runtime._state.update(grading=None, variant=None, refused=[], spec=None)


def released(folder, student_id=None):
    """An nbgrader configuration whose exchange released mech101's A."""
    exchange = folder / "exchange"
    (exchange / "mech101" / "outbound" / "A").mkdir(parents=True)
    lines = ["c = get_config()", f"c.Exchange.root = {str(exchange)!r}"]
    if student_id:
        lines.append(f"c.CourseDirectory.student_id = {student_id!r}")
    (folder / "nbgrader_config.py").write_text("\n".join(lines) + "\n")


def test_the_hub_user_comes_first(clean, monkeypatch):
    released(clean)
    monkeypatch.setenv("ACCELAB_STUDENT", "someone")
    monkeypatch.setenv("JUPYTERHUB_USER", "ann")
    found = identify(SPEC)
    assert found.student == "ann" and "JupyterHub" in found.how


def test_in_an_assignment_the_exchange_decides(clean, monkeypatch):
    """Fetched through nbgrader's exchange: the account it submits from, even when an
    explicit id says otherwise; nbgrader's own configured student id when there is one."""
    released(clean)
    monkeypatch.setenv("ACCELAB_STUDENT", "someone-else")
    found = identify(SPEC)
    assert found.student == ME and "exchange" in found.how
    (clean / "nbgrader_config.py").write_text(
        (clean / "nbgrader_config.py").read_text() + "c.CourseDirectory.student_id = 'hal'\n"
    )
    assert identify(SPEC).student == "hal"
    assert identify({**SPEC, "assignment": "B"}).student == "someone-else"  # not released


def test_else_the_explicit_id_else_nobody(clean, monkeypatch):
    assert identify(SPEC).student is None
    assert runtime.student_id(SPEC) == runtime.SELF_STUDY
    monkeypatch.setenv("ACCELAB_STUDENT_ID", "ivy")  # the older spelling
    assert identify(SPEC).student == "ivy"
    monkeypatch.setenv("ACCELAB_STUDENT", "ann")
    assert identify(SPEC).student == "ann"


def test_the_notebook_says_whose_values_it_shows(clean, monkeypatch, capsys):
    monkeypatch.setenv("JUPYTERHUB_USER", "ann")
    v = runtime.load_variant(SPEC)
    assert v.student == "ann"
    assert "These are the values of student 'ann' (your JupyterHub user)" in capsys.readouterr().out
    runtime.check_format("verdict", {"verdict": "gentle"})  # passes


def test_checks_fail_naming_both_when_another_students_values_are_loaded(clean, monkeypatch):
    monkeypatch.setenv("JUPYTERHUB_USER", "ann")
    runtime.load_variant(SPEC, "hal")  # a cell the student added
    with pytest.raises(runtime.CheckFailed) as info:
        runtime.check_format("verdict", {"verdict": "gentle"})
    message = str(info.value)
    assert "values of student 'hal'" in message and "collect it as student 'ann'" in message
    # shown as its sentence, not as a traceback through the runtime
    lines = info.value._render_traceback_()
    assert len(lines) == 1 and message in lines[0]


def test_without_an_id_the_self_study_values_say_so_and_fail(clean, capsys):
    v = runtime.load_variant(SPEC)
    assert v.student == runtime.SELF_STUDY
    out = capsys.readouterr().out
    assert "SELF-STUDY" in out and "ACCELAB_STUDENT" in out
    with pytest.raises(runtime.CheckFailed, match="self-study values"):
        runtime.check_format("verdict", {"verdict": "gentle"})


def test_while_grading_nothing_changes(clean, monkeypatch, capsys):
    """In the grading sandbox the statement is the submitter's and the identity is not
    asked: the visible checks only look at the form."""
    from accelab.exercises.assignment import statement_of

    monkeypatch.setenv("ACCELAB_STUDENT_ID", "ann")
    runtime.set_grading_statement(statement_of(SPEC, "ann"))
    v = runtime.load_variant(SPEC)
    assert v.student == "ann" and capsys.readouterr().out == ""
    runtime.check_format("verdict", {"verdict": "gentle"})
    with pytest.raises(LookupError):
        runtime.load_variant(SPEC, "hal")
