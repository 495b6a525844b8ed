"""The parts that keep grades whole, each alone (fast): files replaced whole,
records by content, one grader per course, stopping, the roster's ids, no
process-wide swap of stderr, the sandbox's temporary folders. The faults
themselves, on a real course, are in test_grading_faults.py."""

import json
import os
import subprocess
import sys
import tempfile
import threading

import pytest

from accelab.exercises import files
from accelab.exercises.grader import stop
from accelab.exercises.grader.lock import CourseBusy, course_lock
from accelab.exercises.grader.state import content_hash, read_state, to_do, write_state
from accelab.exercises.nbgrader_course import check_ids, read_roster

# ---- files replaced whole ---------------------------------------------------------------------


def test_a_failed_write_keeps_the_old_file_and_names_it(tmp_path, monkeypatch):
    path = tmp_path / "grades_A.csv"
    files.write_atomic(path, "old,complete\n")
    monkeypatch.setenv("ACCELAB_FAULT", "enospc:grades_A")
    with pytest.raises(files.WriteError) as exc:
        files.write_atomic(path, "new" * 1000)
    assert str(path) in str(exc.value) and "No space left on device" in str(exc.value)
    assert "free some space" in str(exc.value)
    assert path.read_text() == "old,complete\n"
    assert os.listdir(tmp_path) == ["grades_A.csv"]


def test_a_write_keeps_the_files_mode_and_leftovers_are_swept(tmp_path):
    path = tmp_path / "page.html"
    files.write_atomic(path, "a")
    os.chmod(path, 0o640)
    files.write_atomic(path, "b")
    assert path.read_text() == "b" and (os.stat(path).st_mode & 0o777) == 0o640
    (tmp_path / ".page.html.x1y2_z3.part").write_text("cut")  # a writer killed mid-way
    (tmp_path / "notes.part").write_text("the instructor's")
    assert files.remove_partial(tmp_path) == 1
    assert sorted(os.listdir(tmp_path)) == ["notes.part", "page.html"]


# ---- records by content -----------------------------------------------------------------------


def test_content_hash_follows_the_bytes_never_the_file_times(tmp_path):
    folder = tmp_path / "sub"
    folder.mkdir()
    nb = folder / "A.ipynb"
    nb.write_text('{"cells": []}')
    first = content_hash(folder)
    stat = os.stat(nb)
    os.utime(nb, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**12))
    assert content_hash(folder) == first  # touched: the same
    nb.write_text('{"cells": [1]}')
    os.utime(nb, ns=(stat.st_atime_ns, stat.st_mtime_ns))  # collect --update keeps old times
    assert content_hash(folder) != first
    os.mkfifo(folder / "pipe")  # never opened (it would block)
    os.symlink("/etc/passwd", folder / "link")  # counted by where it points, not followed
    assert content_hash(folder) != first
    assert content_hash(tmp_path / "none") is None


def test_new_means_not_completely_graded_or_changed(tmp_path):
    course, a, s = str(tmp_path), "A", "ann"
    folder = tmp_path / "submitted" / s / a
    folder.mkdir(parents=True)
    (folder / "A.ipynb").write_text("{}")
    digest = content_hash(folder)
    assert to_do(course, a, s) == "grade"
    write_state(course, a, s, digest, "grading")
    assert to_do(course, a, s) == "grade"
    outcome = tmp_path / ".accelab" / "outcomes" / a / f"{s}.json"
    outcome.parent.mkdir(parents=True)
    outcome.write_text(json.dumps({"student": s, "notes": [], "submission": digest}))
    write_state(course, a, s, digest, "scored")
    assert to_do(course, a, s) == "feedback"
    write_state(course, a, s, digest, "done")
    assert to_do(course, a, s) == "feedback"  # its page is missing
    page = tmp_path / "feedback" / s / a / "A.html"
    page.parent.mkdir(parents=True)
    page.write_text("<html>")
    assert to_do(course, a, s) == ""
    outcome.write_text('{"student": "an')  # a damaged outcome: graded again
    assert to_do(course, a, s) == "grade"
    outcome.write_text(json.dumps({"student": s, "notes": [], "submission": digest}))
    (folder / "A.ipynb").write_text('{"resubmitted": 1}')
    assert to_do(course, a, s) == "grade"
    state = tmp_path / ".accelab" / "state" / a / f"{s}.json"
    state.write_text("{")
    assert read_state(course, a, s) is None and to_do(course, a, s) == "grade"


# ---- one grader per course --------------------------------------------------------------------


def test_a_second_command_on_the_course_is_refused_with_who_holds_it(tmp_path):
    course = str(tmp_path)
    with course_lock(course, "accelab grade --assignment A"):
        with pytest.raises(CourseBusy) as exc:
            with course_lock(course, "accelab assign --assignment B"):
                pass
        text = str(exc.value)
        assert "is busy" in text and "`accelab grade --assignment A`" in text
        assert f"process {os.getpid()}" in text and "run this command again" in text
    with course_lock(course, "accelab assign --assignment B"):  # released when done
        pass


def test_a_killed_holder_leaves_no_lock(tmp_path):
    code = (
        "import sys, time\n"
        "from accelab.exercises.grader.lock import course_lock\n"
        "with course_lock(sys.argv[1], 'holder'):\n"
        "    print('held', flush=True); time.sleep(60)\n"
    )
    proc = subprocess.Popen(
        [sys.executable, "-c", code, str(tmp_path)], stdout=subprocess.PIPE, text=True
    )
    assert proc.stdout.readline().strip() == "held"
    with pytest.raises(CourseBusy):
        with course_lock(str(tmp_path), "second"):
            pass
    proc.kill()
    proc.wait()
    with course_lock(str(tmp_path), "second"):
        pass


# ---- stopping ---------------------------------------------------------------------------------


def test_a_stop_ends_every_sandbox_and_starts_none(tmp_path):
    class Builder:
        def command(self, argv, slot=0, env=None, limits=None):
            return argv

    command = stop.Interruptible(Builder())
    other = subprocess.Popen(["cat"], stdin=subprocess.PIPE, start_new_session=True)
    with stop.stoppable():
        argv = command.command(["sleep", "60"])
        child = subprocess.Popen(argv, start_new_session=True)  # as the supervisor starts it
        stop.HALT.set()
        with pytest.raises(OSError):
            command.command(["sleep", "60"])
        # as grade does: rounds of end_sandboxes until the run is over (one round can miss a
        # sandbox still inside execve: its /proc cmdline is empty for that instant)
        stop.wait_for(lambda: child.poll() is None, seconds=10)
        assert child.wait(timeout=10) == -9
    assert not stop.HALT.is_set()  # cleared when the run ends
    assert other.poll() is None  # a child that is no sandbox is left alone
    other.communicate(b"")


# ---- the roster -------------------------------------------------------------------------------


def test_roster_ids_that_cannot_be_ids_are_refused_with_their_rows(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text(
        "id,first_name\n../../etc/x,a\n,b\na+b,c\nBOB,d\nbob,e\nann,f\nann,g\n-x,h\nself-study,i\n"
    )
    with pytest.raises(ValueError) as exc:
        read_roster(roster)
    text = str(exc.value)
    for part in (
        "row 2: '../../etc/x'",
        "row 3: the id is empty",
        "row 4: 'a+b'",
        "row 5 and row 6: ids equal but for letter case ('BOB', 'bob')",
        "row 7 and row 8: the same id",
        "row 9: '-x' begins with '-'",
        "row 10: 'self-study' is reserved",
        str(roster),
    ):
        assert part in text, (part, text)


def test_a_bom_is_read_padding_is_removed_and_said_an_empty_roster_refused(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_bytes("\ufeffid , first_name\n padded ,Pat\nzoë,Zoë\n".encode())
    said = []
    rows = read_roster(roster, say=said.append)
    assert [r["id"] for r in rows] == ["padded", "zoë"] and rows[0]["first_name"] == "Pat"
    assert "' padded ' taken as 'padded'" in said[0]
    roster.write_text("id\n")
    with pytest.raises(ValueError, match="no students"):
        read_roster(roster)
    roster.write_text("name\nann\n")
    with pytest.raises(ValueError, match="needs a column 'id'"):
        read_roster(roster)
    check_ids([("row 2", "ann"), ("row 3", "ann@uni.edu"), ("row 4", "o.k_1-2")])


def test_assign_refuses_a_bad_roster_before_it_writes_anything(tmp_path, capsys):
    from accelab.cli import main

    roster = tmp_path / "roster.csv"
    roster.write_text("id\nann\nANN\n")
    course = tmp_path / "course"
    status = main(["assign", "--course", str(course), "--assignment", "A", "--roster", str(roster)])
    err = capsys.readouterr().err
    assert status == 2 and "row 2 and row 3" in err and "Traceback" not in err
    assert not course.exists()


# ---- messages are never swallowed -------------------------------------------------------------


def test_silencing_a_worker_never_takes_the_terminal_from_another_thread():
    from accelab.exercises import silence

    inside, leave = threading.Event(), threading.Event()
    mine = sys.stderr

    def worker():
        with silence.silenced():
            inside.set()
            leave.wait(10)

    thread = threading.Thread(target=worker)
    thread.start()
    assert inside.wait(10)
    try:
        assert sys.stderr is mine  # the progress bar and errors still reach the terminal
    finally:
        leave.set()
        thread.join()
    source = open(silence.__file__).read()
    assert "redirect_stderr" not in source and "sys.stderr =" not in source


# ---- the sandbox's temporary folders ----------------------------------------------------------


def test_passwd_folders_of_graders_that_are_gone_are_removed(tmp_path, monkeypatch):
    from accelab.exercises.grader import sandbox

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    dead = subprocess.Popen(["true"])
    dead.wait()
    gone = tmp_path / f"{sandbox.ETC_PREFIX}{dead.pid}-abc"
    alive = tmp_path / f"{sandbox.ETC_PREFIX}{os.getpid()}-def"
    other = tmp_path / "something-else"
    for folder in (gone, alive, other):
        folder.mkdir()
    sandbox.remove_stale_etc()
    assert not gone.exists() and alive.exists() and other.exists()
    code = (
        "from accelab.exercises.grader.sandbox import SandboxCommand\n"
        "print(SandboxCommand(bwrap='/usr/bin/bwrap')._etc_files())\n"
    )
    env = dict(os.environ, TMPDIR=str(tmp_path))
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    folder = proc.stdout.strip()
    assert os.path.basename(folder).startswith(sandbox.ETC_PREFIX)
    assert folder.startswith(str(tmp_path)) and not os.path.exists(folder)  # removed at exit


def test_working_folders_without_a_sandbox_are_removed(tmp_path, monkeypatch):
    """``--unsafe-no-sandbox``: the kernels' working folders are in one folder of the
    grading process, removed when it ends; a killed one's by the next grader."""
    from accelab.exercises.grader import unsandboxed

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    dead = subprocess.Popen(["true"])
    dead.wait()
    gone = tmp_path / f"{unsandboxed.PREFIX}{dead.pid}-abc"
    gone.mkdir()
    builder = unsandboxed.UnsandboxedCommand()
    first = builder.command(["python"], slot=0)
    second = builder.command(["python"], slot=1)
    work = [a.split("=", 1)[1] for cmd in (first, second) for a in cmd if a.startswith("HOME=")]
    assert len(set(work)) == 2 and os.path.dirname(work[0]) == os.path.dirname(work[1])
    assert os.path.basename(os.path.dirname(work[0])).startswith(
        f"{unsandboxed.PREFIX}{os.getpid()}-"
    )
    assert not gone.exists()
    code = (
        "from accelab.exercises.grader.unsandboxed import UnsandboxedCommand\n"
        "cmd = UnsandboxedCommand().command(['python'])\n"
        "print(next(a for a in cmd if a.startswith('HOME=')).split('=', 1)[1])\n"
    )
    env = dict(os.environ, TMPDIR=str(tmp_path))
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    folder = proc.stdout.strip()
    assert folder.startswith(str(tmp_path)) and os.path.basename(
        os.path.dirname(folder)
    ).startswith(unsandboxed.PREFIX)
    assert not os.path.exists(os.path.dirname(folder))  # removed at exit


@pytest.mark.parametrize(
    "sid",
    [
        "ann",
        "zoë",
        "ann@uni.edu",
        "o.k_1-2",
        "",
        "a+b",
        "a b",
        "../x",
        "-x",
        ".x",
        "~x",
        "a[1]",
        "a?",
        "x#y",
        "<b>",
        "self-study",
        "preview",
        "x" * 65,
        "\u202eevil",
        "a:b",
        "a=b",
        "l'x",
    ],
)
def test_the_roster_and_the_grader_agree_on_what_an_id_is(sid):
    """One rule (accelab.exercises.ids): an id the roster refuses is a folder name the
    grader refuses, and the other way round."""
    from accelab.exercises.grader import intake

    try:
        check_ids([("row 2", sid)])
        roster_ok = True
    except ValueError:
        roster_ok = False
    assert roster_ok == (intake.id_problem(sid, None) is None), sid
    assert roster_ok == (intake.id_problem(sid, [sid]) is None), sid
