"""Grades are data: every fault an instructor's machine can cause, tried on a
real course with nbgrader and the bubblewrap sandbox, against the grades of an
uninterrupted run of the same course.

Faults: kill -9 at each stage of a submission's grading and of the CSV, Ctrl-C,
two graders at once, a resubmission collected with its old time, a full disk (a
fault-injected write, and a small tmpfs when this machine can mount one), a
failing ``assign --force``, and broken course files. After each: the same
command (or ``--new``) finishes the job, the CSV and the gradebook equal the
uninterrupted run's, every feedback page is there, no sandbox process and no
temporary folder is left, and no submitted file changed. Until then, no grade
is shown that the uninterrupted run does not give.
"""

import csv
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import _forked as forked
import pytest
from nbformat.v4 import new_code_cell

from accelab.exercises.assign import assign
from accelab.exercises.grader.sandbox import check_sandbox
from accelab.exercises.notebook import read_spec
from accelab.exercises.simulate import key_code, submit

#: one worker builds and grades the reference course (the module fixture), once
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("faults")]

STUDENTS = ["ann", "bob", "cy"]


def build(course):
    """An ungraded course: rotation only; bob gets one answer wrong. (assign runs nbgrader's
    generate_assignment and release_assignment in this process, and leaves its working
    folder and import path as they were.)"""
    cwd = os.getcwd()
    assign(course, "A", ["rotation"], roster=STUDENTS, course_id="faults", release=True, say=print)
    assert os.getcwd() == cwd
    assert not [p for p in sys.path if p.startswith(os.path.dirname(course))], sys.path
    spec = read_spec(course, "A")
    for s in STUDENTS:
        code = key_code(spec, s)
        if s == "bob":
            name = next(n for n, a in spec_answers(spec, s).items() if a.kind != "choice")
            code[name] = code[name].replace("Q_(", "-Q_(", 1)
        submit(course, "A", s, code)


def slow_down(course, student, seconds):
    """A cell that sleeps in ``student``'s notebook (grades unchanged): a sandbox
    surely runs when a signal comes, or another grader starts."""
    import nbformat

    path = os.path.join(course, "submitted", student, "A", "A.ipynb")
    nb = nbformat.read(path, as_version=4)
    nb.cells.insert(2, new_code_cell(f"import time\ntime.sleep({seconds})"))
    nbformat.write(nb, path)


def spec_answers(spec, student):
    from accelab.exercises.assignment import build_variant

    return build_variant(spec, student).answers


def grader_env(tmp, fault=None):
    env = dict(os.environ, TMPDIR=str(tmp))
    env.pop("ACCELAB_FAULT", None)
    if fault:
        env["ACCELAB_FAULT"] = fault
    return env


def run(course, *args, fault=None, tmp, timeout=300):
    """``accelab grade`` in a process of its own (forked: tests/_forked.py), with
    TMPDIR ``tmp`` and ``fault`` injected."""
    env = grader_env(tmp, fault)
    return forked.run(
        ["grade", "--course", str(course), "--assignment", "A", "--quiet", *args],
        env=env,
        timeout=timeout,
    )


def here(course, *args, fault=None):
    """``accelab grade`` through accelab's entry point in this process (no
    interpreter to start), with what a subprocess run gives back."""
    return accelab_here(
        "grade", "--course", str(course), "--assignment", "A", "--quiet", *args, fault=fault
    )


def accelab_here(*argv, fault=None):
    """``accelab ARGV`` in this process; a CompletedProcess."""
    import contextlib
    import io

    from accelab.cli import main

    old = os.environ.pop("ACCELAB_FAULT", None)
    if fault:
        os.environ["ACCELAB_FAULT"] = fault
    out, err = io.StringIO(), io.StringIO()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = main(list(argv))
    finally:
        os.environ.pop("ACCELAB_FAULT", None)
        if old is not None:
            os.environ["ACCELAB_FAULT"] = old
    return subprocess.CompletedProcess(argv, status, out.getvalue(), err.getvalue())


def csv_rows(course):
    path = os.path.join(course, "grades_A.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as fh:
        return {r["student"]: r for r in csv.DictReader(fh)}


def gradebook_scores(course):
    """student -> (grade name -> (auto, manual), late penalty)."""
    from nbgrader.api import Gradebook

    out = {}
    with Gradebook("sqlite:///" + os.path.join(course, "gradebook.db"), "faults") as gb:
        for s in STUDENTS:
            try:
                sub = gb.find_submission("A", s)
            except Exception:  # MissingEntry
                continue
            grades = {
                g.name: (g.auto_score, g.manual_score) for nb in sub.notebooks for g in nb.grades
            }
            out[s] = (grades, sub.late_submission_penalty)
    return out


def digest_tree(folder):
    found = {}
    for root, _, files in os.walk(folder):
        for f in files:
            path = os.path.join(root, f)
            with open(path, "rb") as fh:
                found[os.path.relpath(path, folder)] = hashlib.sha256(fh.read()).hexdigest()
    return found


def sandbox_processes(tmp):
    """The sandboxes of the graders run with TMPDIR ``tmp`` that are still alive:
    bubblewrap's command line names the passwd file it shows, which is in TMPDIR
    (its PID namespace and --die-with-parent take every process inside with it)."""
    found = []
    for pid in os.listdir("/proc"):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as fh:
                args = fh.read().split(b"\0")
        except OSError:
            continue
        if os.path.basename(args[0]) == b"bwrap" and any(os.fsencode(tmp) in a for a in args):
            found.append(pid)
    return found


def sandboxes_left(tmp, wait=10.0):
    """The sandboxes of :func:`sandbox_processes` still alive ``wait`` s after a grader was
    killed or interrupted (none alive: at once). bubblewrap's ``--die-with-parent`` takes
    them when the grader dies, but not at once: a fixed 0.3 s was too short once with the
    machine loaded (CI failed with one left, at the kill after "scored"); one that
    ``--die-with-parent`` missed stays for good."""
    deadline = time.monotonic() + wait
    alive = sandbox_processes(tmp)
    while alive and time.monotonic() < deadline:
        time.sleep(0.1)
        alive = sandbox_processes(tmp)
    return alive


def partial_files(course):
    return [
        os.path.join(root, f)
        for root, _, files in os.walk(course)
        for f in files
        if f.endswith(".part")
    ]


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The ungraded course, and the CSV and gradebook of one uninterrupted run."""
    reason = check_sandbox()
    assert reason is None, f"the sandbox must work in CI: {reason}"
    root = tmp_path_factory.mktemp("faults")
    ungraded = str(root / "ungraded")
    build(ungraded)
    graded = str(root / "graded")
    shutil.copytree(ungraded, graded, symlinks=True)
    proc = run(graded, tmp=tmp_path_factory.mktemp("tmp"))
    assert proc.returncode == 0, proc.stderr
    rows = csv_rows(graded)
    assert float(rows["ann"]["total"]) == float(rows["ann"]["max"])
    assert float(rows["bob"]["total"]) == float(rows["bob"]["max"]) - 1
    return {"ungraded": ungraded, "graded": graded, "rows": rows, "gb": gradebook_scores(graded)}


def course_from(reference, tmp_path, which="ungraded"):
    """A copy of the reference's course, and a TMPDIR of its own for its graders."""
    course = str(tmp_path / "course")
    shutil.copytree(reference[which], course, symlinks=True)
    os.makedirs(tmp_path / "tmp", exist_ok=True)
    return course, tmp_path / "tmp"


def shown_grades_are_true(course, reference):
    """Every total the course shows (its CSV on disk, and the table made from its
    records now) is the uninterrupted run's; a submission not graded shows none."""
    from accelab.exercises.grader.gradetable import rows_of

    _, rows = rows_of(course, "A")
    tables = [{r["student"]: r for r in rows}]
    on_disk = csv_rows(course)
    if on_disk:
        tables.append(on_disk)
    for table in tables:
        for s, row in table.items():
            total = row["total"]
            if total in (None, ""):
                assert "not graded" in row["notes"], row
            else:
                assert float(total) == float(reference["rows"][s]["total"]), (s, row)
            assert "could not be graded" not in row["notes"], row


def finished_like_reference(course, reference, tmp):
    """Same grades, same gradebook, every page, nothing left behind."""
    rows = csv_rows(course)
    assert rows == reference["rows"]
    assert gradebook_scores(course) == reference["gb"]
    for s in STUDENTS:
        page = os.path.join(course, "feedback", s, "A", "A.html")
        assert os.path.exists(page), page
        text = open(page).read()
        assert "Graded against the values of student " + s in text
        assert "could not be graded" not in text
    assert partial_files(course) == []
    assert [f for f in os.listdir(tmp) if f.startswith("accelab-etc-")] == []
    assert sandbox_processes(tmp) == []


# ---- kill -9 at every stage ----------------------------------------------------------------


def test_a_kill_at_any_stage_is_finished_by_running_again(reference, tmp_path):
    """kill -9 after a submission's outcome is saved and before the gradebook is
    written; after the gradebook, before its record; before its feedback;
    during its feedback; as its grading begins; while the CSV is written. Each
    leaves nothing that looks like a grade and is not; --new finishes it."""
    course, tmp = course_from(reference, tmp_path)
    submitted = digest_tree(os.path.join(course, "submitted"))
    stages = [  # in an order that leaves a submission to grade for each
        "grading-begun@2",
        "outcome-saved",
        "autograded",
        "scored",
        "feedback-unrenamed@2",
        "csv-unrenamed",
    ]
    for stage in stages:
        proc = run(course, "--new", fault=f"kill:{stage}", tmp=tmp)
        assert proc.returncode == -signal.SIGKILL, (stage, proc.returncode, proc.stderr[-2000:])
        assert sandboxes_left(tmp) == [], stage
        shown_grades_are_true(course, reference)
    assert partial_files(course)  # the CSV was being written when it was killed
    proc = run(course, "--new", tmp=tmp)
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    finished_like_reference(course, reference, tmp)
    assert digest_tree(os.path.join(course, "submitted")) == submitted
    proc = here(course, "--new")
    assert "0 submission(s) graded" in proc.stdout


# ---- Ctrl-C -----------------------------------------------------------------------------------


def test_ctrl_c_stops_at_once_keeps_nothing_partial_and_says_how_to_finish(reference, tmp_path):
    course, tmp = course_from(reference, tmp_path)
    slow_down(course, STUDENTS[-1], 8)
    proc = forked.Forked(
        ["grade", "--course", course, "--assignment", "A", "--jobs", "1"], env=grader_env(tmp)
    )
    state = os.path.join(course, ".accelab", "state", "A")
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:  # one done, the next running
        done = [f for f in os.listdir(state) if f.endswith(".json")] if os.path.isdir(state) else []
        if done and sandbox_processes(tmp):
            break
        time.sleep(0.05)
    assert proc.poll() is None, "grading ended before it could be interrupted"
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    seconds = time.monotonic() - sent
    print(f"\nCtrl-C: grading stopped {seconds:.1f} s after the signal")
    assert seconds < 8, seconds
    assert proc.returncode == 130, (proc.returncode, err)
    assert "interrupted (Ctrl-C)" in err and "--new" in err and "graded completely" in err, err
    assert "Traceback" not in err
    assert sandboxes_left(tmp) == []
    shown_grades_are_true(course, reference)
    for s in STUDENTS:  # no "submit again" page because the instructor interrupted
        page = os.path.join(course, "feedback", s, "A", "A.html")
        assert not os.path.exists(page) or "could not be graded" not in open(page).read()
    proc = here(course, "--new")
    assert proc.returncode == 0, proc.stderr
    finished_like_reference(course, reference, tmp)


# ---- two graders, and nbgrader beside them ----------------------------------------------------


def test_a_second_grader_or_assign_is_refused_while_nbgrader_export_works(reference, tmp_path):
    course, tmp = course_from(reference, tmp_path)
    slow_down(course, STUDENTS[0], 8)
    first = forked.Forked(
        ["grade", "--course", course, "--assignment", "A", "--jobs", "1", "--quiet"],
        env=grader_env(tmp),
    )
    lock = os.path.join(course, ".accelab", "lock")
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        try:
            if json.load(open(lock))["pid"] == first.pid:
                break
        except (OSError, ValueError, KeyError):
            pass
        time.sleep(0.05)
    second = here(course)
    assert second.returncode == 2, second.stderr
    assert "is busy" in second.stderr and f"process {first.pid}" in second.stderr, second.stderr
    assert "accelab grade" in second.stderr and "Traceback" not in second.stderr
    again = accelab_here(
        "assign", "--course", course, "--assignment", "B", "--families", "rotation"
    )
    assert again.returncode == 2 and "is busy" in again.stderr, again.stderr
    export = forked.run(["export"], cwd=course, program="nbgrader")
    assert export.returncode == 0, export.stderr[-2000:]
    out, err = first.communicate(timeout=300)
    assert first.returncode == 0, err
    assert csv_rows(course) == reference["rows"]
    assert gradebook_scores(course) == reference["gb"]
    assert not os.path.exists(os.path.join(course, "source", "B"))


# ---- a resubmission collected with its submit-time mtime; one student regraded ---------------


def test_new_grades_a_resubmission_by_content_and_one_student_alone(
    reference, tmp_path, monkeypatch
):
    from accelab.exercises.grader import nbgrader_step

    ran = []  # plans JudgeSubmission runs itself: none, each is handed over (PreparedRuns)
    real = nbgrader_step.run_plan
    monkeypatch.setattr(nbgrader_step, "run_plan", lambda *a, **k: ran.append(a) or real(*a, **k))
    assert not hasattr(nbgrader_step, "PREPARED")  # no run passes through a module's state
    course, _ = course_from(reference, tmp_path, "graded")
    path = os.path.join(course, "submitted", "bob", "A", "A.ipynb")
    before = os.stat(path)
    spec = read_spec(course, "A")
    submit(course, "A", "bob", key_code(spec, "bob"))  # now all right
    # nbgrader's `collect --update` copies the resubmission with its submit-time mtime,
    # older than the grading of the first one
    os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))
    stamp = os.path.join(course, "submitted", "bob", "A", "timestamp.txt")
    os.utime(stamp, ns=(before.st_atime_ns, before.st_mtime_ns))
    proc = here(course, "--new")
    assert proc.returncode == 0, proc.stderr
    assert "1 submission(s) graded" in proc.stdout, proc.stdout[-800:]
    rows = csv_rows(course)
    assert float(rows["bob"]["total"]) == float(rows["bob"]["max"])
    pages = {
        s: os.stat(os.path.join(course, "feedback", s, "A", "A.html")).st_mtime_ns for s in STUDENTS
    }
    proc = here(course, "--student", "ann")
    assert proc.returncode == 0, proc.stderr
    now = {
        s: os.stat(os.path.join(course, "feedback", s, "A", "A.html")).st_mtime_ns for s in STUDENTS
    }
    assert [s for s in STUDENTS if now[s] != pages[s]] == ["ann"]
    assert "0 submission(s) graded" in here(course, "--new").stdout
    assert ran == []


# ---- a full disk ------------------------------------------------------------------------------


def test_a_failed_csv_write_keeps_the_old_csv_whole_and_says_which_file(reference, tmp_path):
    course, _ = course_from(reference, tmp_path, "graded")
    path = os.path.join(course, "grades_A.csv")
    old = open(path, "rb").read()
    proc = here(course, "--student", "bob", "--jobs", "2", fault="enospc:grades_A.csv")
    assert proc.returncode == 2, proc.stderr
    assert path in proc.stderr and "No space left on device" in proc.stderr, proc.stderr
    assert "--new" in proc.stderr and "Traceback" not in proc.stderr
    assert open(path, "rb").read() == old
    assert partial_files(course) == []


def test_a_failed_feedback_write_keeps_the_old_pages_and_new_finishes(reference, tmp_path):
    course, tmp = course_from(reference, tmp_path, "graded")
    pages = digest_tree(os.path.join(course, "feedback"))
    csv_before = open(os.path.join(course, "grades_A.csv"), "rb").read()
    proc = here(course, "--jobs", "2", fault="enospc:/feedback/")
    assert proc.returncode == 2, proc.stderr
    assert os.path.join(course, "feedback") in proc.stderr, proc.stderr
    assert "No space left on device" in proc.stderr and "--new" in proc.stderr
    assert "Traceback" not in proc.stderr
    kept = os.path.join(course, "grades_A.csv")
    assert f"the CSV was not rewritten (the old one is kept: {kept})" in proc.stderr
    assert digest_tree(os.path.join(course, "feedback")) == pages
    assert open(os.path.join(course, "grades_A.csv"), "rb").read() == csv_before
    shown_grades_are_true(course, reference)
    proc = here(course, "--new")
    assert proc.returncode == 0, proc.stderr
    finished_like_reference(course, reference, tmp)


def test_a_failed_run_with_no_csv_before_says_none_was_written(reference, tmp_path):
    course, _ = course_from(reference, tmp_path, "graded")
    os.unlink(os.path.join(course, "grades_A.csv"))
    proc = here(course, "--student", "bob", "--jobs", "2", fault="enospc:/feedback/")
    assert proc.returncode == 2, proc.stderr
    assert "no CSV was written (there was none before)" in proc.stderr, proc.stderr
    assert "old one is kept" not in proc.stderr
    assert not os.path.exists(os.path.join(course, "grades_A.csv"))


def _mount_tmpfs(where, size):
    os.makedirs(where, exist_ok=True)
    proc = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(where)],
        capture_output=True,
        text=True,
    )
    return proc.returncode == 0


def test_a_full_disk_keeps_every_file_whole_and_new_finishes(reference, tmp_path):
    """The course on a small tmpfs, filled up: grading fails, says so, and keeps the
    old CSV and pages whole; with space again, --new finishes it."""
    mount, tmp = tmp_path / "disk", tmp_path / "tmp"
    tmp.mkdir()
    if not _mount_tmpfs(mount, "48m"):
        pytest.skip("this machine cannot mount a tmpfs (the fault-injected tests cover it)")
    try:
        course = str(mount / "course")
        shutil.copytree(reference["graded"], course, symlinks=True)
        csv_before = open(os.path.join(course, "grades_A.csv"), "rb").read()
        pages = digest_tree(os.path.join(course, "feedback"))
        filler = mount / "filler"
        with open(filler, "wb") as fh:  # fill the disk to the last block
            try:
                while True:
                    fh.write(b"\0" * (1 << 16))
                    fh.flush()
            except OSError:
                pass
        proc = here(course, "--jobs", "2")
        assert proc.returncode == 2, (proc.returncode, proc.stdout[-500:], proc.stderr)
        assert "No space left on device" in proc.stderr or "disk is full" in proc.stderr
        assert "--new" in proc.stderr and "Traceback" not in proc.stderr
        assert open(os.path.join(course, "grades_A.csv"), "rb").read() == csv_before
        now = digest_tree(os.path.join(course, "feedback"))
        assert {k: v for k, v in now.items() if k.endswith(".html")} == {
            k: v for k, v in pages.items() if k.endswith(".html")
        }
        shown_grades_are_true(course, reference)
        os.unlink(filler)
        proc = here(course, "--new")
        assert proc.returncode == 0, proc.stderr
        finished_like_reference(course, reference, tmp)
    finally:
        subprocess.run(["umount", "-l", str(mount)], capture_output=True)


# ---- assign --force, all or nothing -----------------------------------------------------------


def _snapshot(course):
    import sqlite3

    files = digest_tree(course)
    files.pop(os.path.join(".accelab", "lock"), None)
    files.pop("gradebook.db", None)
    db = sqlite3.connect(os.path.join(course, "gradebook.db"))
    dump = "\n".join(db.iterdump())
    db.close()
    return files, dump


def test_a_failing_assign_force_leaves_the_course_exactly_as_it_was(reference, tmp_path):
    course, tmp = course_from(reference, tmp_path, "graded")
    before = _snapshot(course)
    cwd = os.getcwd()
    proc = accelab_here(
        "assign",
        "--course",
        course,
        "--assignment",
        "A",
        "--families",
        "rotation,fourbar",
        "--force",
        "--release",
    )
    assert proc.returncode == 2, proc.stderr
    assert "Nothing was changed" in proc.stderr and "nbgrader db assignment remove" in proc.stderr
    assert os.getcwd() == cwd  # nbgrader ran in this process, in the staged course
    assert not [p for p in sys.path if p.startswith(course)], sys.path
    assert "Traceback" not in proc.stderr
    assert _snapshot(course) == before
    assert [f for f in os.listdir(os.path.join(course, ".accelab")) if "staging" in f] == []
    proc = here(course, "--student", "ann")
    assert proc.returncode == 0, proc.stderr
    assert csv_rows(course) == reference["rows"]


def test_an_assign_killed_while_it_swaps_is_finished_by_the_next_command(reference, tmp_path):
    from accelab.exercises.grader.lock import course_lock
    from accelab.exercises.staging import recover

    course, _ = course_from(reference, tmp_path, "graded")
    env = dict(os.environ, ACCELAB_FAULT="kill:assign-swapping")
    args = ["--course", course, "--assignment", "A", "--families", "rotation"]
    proc = forked.run(["assign", *args, "--units", "SI", "--force"], env=env)
    assert proc.returncode == -signal.SIGKILL, proc.stderr
    with course_lock(course, "test"):
        recover(course)
    assert read_spec(course, "A")["units"] == "SI"
    release = open(os.path.join(course, "release", "A", "A.ipynb")).read()
    source = open(os.path.join(course, "source", "A", "A.ipynb")).read()
    assert ("mm" in release) and ("mm" in source)
    assert [f for f in os.listdir(os.path.join(course, ".accelab")) if "staging" in f] == []


# ---- broken course files and bad arguments ---------------------------------------------------


def test_broken_course_files_are_named_with_what_to_do(reference, tmp_path, capsys):
    """Each refused in one line that names the file and what to do (run in this
    process: accelab's own entry point, as the command runs it)."""
    from accelab.cli import main

    course, _ = course_from(reference, tmp_path, "graded")

    def grade(*args):
        status = main(["grade", "--course", course, "--assignment", "A", "--quiet", *args])
        out, err = capsys.readouterr()
        return status, out, err

    def damaged(rel, text):
        path = os.path.join(course, rel)
        old = open(path, "rb").read()
        with open(path, "w") as fh:
            fh.write(text)
        return path, old

    cases = [
        (os.path.join("source", "A", "accelab.json"), '{"course": "faults",\n'),
        (os.path.join(".accelab", "roster.json"), '["ann",\n'),
        ("gradebook.db", "this is no database " * 100),
        ("nbgrader_config.py", "c = get_config()\nc.X.y = (\n"),
    ]
    for rel, text in cases:
        path, old = damaged(rel, text)
        status, _, err = grade()
        with open(path, "wb") as fh:
            fh.write(old)
        assert status == 2, (rel, err)
        assert path in err, (rel, err)
        assert "internal error" not in err and "Traceback" not in err
    # one damaged outcome costs only its student's row, and --new grades it again
    path, _ = damaged(os.path.join(".accelab", "outcomes", "A", "bob.json"), '{"student": "bo')
    status, _, err = grade("--student", "ann")
    assert status == 0, err
    rows = csv_rows(course)
    assert rows["ann"] == reference["rows"]["ann"]
    assert rows["bob"]["total"] == "" and path in rows["bob"]["notes"], rows["bob"]
    status, out, err = grade("--new")
    assert status == 0 and "1 submission(s) graded" in out, out[-600:]
    assert csv_rows(course) == reference["rows"]
    status, _, err = grade("--student", "nobody")
    assert status == 2 and "'nobody'" in err and "collect" in err, err
    for jobs in ("0", "two"):
        with pytest.raises(SystemExit) as exc:
            grade("--jobs", jobs)
        assert exc.value.code == 2 and "--jobs" in capsys.readouterr().err
