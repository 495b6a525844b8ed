"""An assignment built aside and swapped into the course whole (``accelab assign``).

A new course is built in a folder beside its place and renamed into it. In an
existing course (held with :func:`~.grader.lock.course_lock`), the build works
in ``COURSE/.accelab/staging-*`` on copies of what it changes (the gradebook,
by SQLite's backup, the roster, the assignment's source folder) and runs
nbgrader's generate_assignment there; only when all of it succeeded is it
swapped in: the assignment's ``source`` and ``release`` folders by rename, the
gradebook by SQLite's backup (one transaction, seen by every open connection),
the roster, the students' account names and a configuration the build changed
(or made) by an atomic replace. A failure during the swap (or of
release_assignment after it) puts the old ones back. A kill during the swap
leaves a journal, ``swap.json``, that the next ``accelab assign`` or ``grade``
on the course finishes (:func:`recover`); a staging folder without one is an
unfinished build, and is removed.
"""

import glob
import json
import os
import shutil
import sqlite3
import tempfile
from urllib.parse import quote

from .files import fault, write_atomic
from .nbgrader_run import nbgrader_here

JOURNAL = "swap.json"
#: the course's own records an assignment's build reads and adds to (the roster,
#: the students' account names), swapped in whole with it
KEPT = (os.path.join(".accelab", "roster.json"), os.path.join(".accelab", "accounts.json"))


def copy_gradebook(src, dest):
    """Copy the SQLite database ``src`` into ``dest`` with SQLite's backup: one
    transaction on ``dest``, consistent with writers of ``src``, and seen by
    every connection that has ``dest`` open (a formgrader's)."""
    try:
        source = sqlite3.connect(f"file:{quote(src)}?mode=ro", uri=True, timeout=60)
        try:
            target = sqlite3.connect(dest, timeout=60)
            try:
                source.backup(target)
            finally:
                target.close()
        finally:
            source.close()
    except sqlite3.Error as exc:
        raise ValueError(
            f"could not copy the gradebook {src} to {dest} ({exc}); nothing was changed. If "
            f"the disk is full, free some space; if {src} is damaged, restore it from a backup"
        ) from None


def _nbgrader_error(args, proc):
    """The lines of nbgrader's output that say what went wrong (no traceback)."""
    lines = [line.strip() for line in (proc.stderr or "").splitlines()]
    errors = [
        line
        for line in lines
        if ("| ERROR]" in line or "| CRITICAL]" in line)
        and "Traceback" not in line
        and "see the" not in line.lower()
    ]
    causes = [line for line in lines if line.split(":")[0].endswith(("Error", "Exception"))]
    text = (causes[-1:] or errors[-1:] or lines[-1:] or ["no message"])[0]
    return text[:400]


def run_nbgrader(root, *args):
    """``nbgrader ARGS`` on the course at ``root`` (its root and gradebook given
    on the command line, so that a configuration that names paths of its own
    cannot send the build into the real course), run in this process as the
    command runs it (:mod:`.nbgrader_run`). Raises a translated error."""
    from .assign import AssignError

    root = os.path.abspath(root)
    proc = nbgrader_here(
        root,
        *args,
        f"--CourseDirectory.root={root}",
        "--CourseDirectory.db_url=sqlite:///" + os.path.join(root, "gradebook.db"),
    )
    if proc.returncode == 0:
        return proc
    if "Cannot add or remove cells" in (proc.stderr or ""):
        assignment = args[1] if len(args) > 1 else "the assignment"
        raise AssignError(
            f"assignment {assignment!r} cannot be replaced with these settings: its new "
            f"notebook has other questions, and nbgrader's gradebook keeps the questions of a "
            f"notebook that has submissions. Nothing was changed. Use another assignment name "
            f"(e.g. --assignment {assignment}2), or, to drop every grade of {assignment}, "
            f"first run in the course folder: nbgrader db assignment remove {assignment} --force"
        )
    raise AssignError(
        f"nbgrader {' '.join(args[:2])} failed: {_nbgrader_error(args, proc)}. Nothing was "
        f"changed in the course"
    )


def build_new_course(course_dir, assignment, build, release):
    """Build a new course in a folder beside ``course_dir``, then rename it into
    place. Returns what ``build`` returns."""
    parent = os.path.dirname(os.path.abspath(course_dir))
    os.makedirs(parent, exist_ok=True)
    prefix = f".{os.path.basename(course_dir)}.accelab-new-"
    for left in glob.glob(os.path.join(glob.escape(parent), glob.escape(prefix) + "*")):
        pid = os.path.basename(left)[len(prefix) :].split("-")[0]
        if pid.isdigit() and not os.path.exists(f"/proc/{pid}"):  # its build was killed
            shutil.rmtree(left, ignore_errors=True)
    tmp = tempfile.mkdtemp(prefix=f"{prefix}{os.getpid()}-", dir=parent)
    try:
        path = build(tmp, lambda *args: run_nbgrader(tmp, *args))
        if release:
            run_nbgrader(tmp, "release_assignment", assignment, "--force")
        fault("assign-built")
        os.chmod(tmp, 0o700)  # a course folder is the instructor's alone (layout.py)
        try:
            os.rename(tmp, course_dir)
        except OSError:
            raise OSError(
                f"{course_dir} was made by something else while the course was built; "
                f"nothing was written into it: run the command again"
            ) from None
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return path


class Staging:
    """Build an assignment of an existing course aside; swap it in whole."""

    def __init__(self, course_dir, assignment):
        self.course = os.path.abspath(course_dir)
        self.assignment = assignment
        self.root = None
        self.steps = []

    def __enter__(self):
        recover(self.course)
        folder = os.path.join(self.course, ".accelab")
        os.makedirs(folder, exist_ok=True)
        self.root = tempfile.mkdtemp(prefix="staging-", dir=folder)
        return self

    def __exit__(self, *exc):
        if self.root and not os.path.exists(os.path.join(self.root, JOURNAL)):
            shutil.rmtree(self.root, ignore_errors=True)

    def _paths(self, rel):
        return (
            os.path.join(self.course, rel),
            os.path.join(self.root, rel),
            os.path.join(self.root, "old", rel),
        )

    def build(self, build, taken=()):
        """Copy into the staging folder what ``build`` reads and changes, and
        run ``build(root, run_nbgrader)`` there."""
        course, root, a = self.course, self.root, self.assignment
        for rel in ("nbgrader_config.py", *KEPT):
            if os.path.exists(os.path.join(course, rel)):
                os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
                shutil.copy2(os.path.join(course, rel), os.path.join(root, rel))
        if os.path.exists(os.path.join(course, "gradebook.db")):
            copy_gradebook(os.path.join(course, "gradebook.db"), os.path.join(root, "gradebook.db"))
        source = os.path.join(course, "source", a)
        if os.path.isdir(source):  # the instructor's own files beside the notebook are kept
            shutil.copytree(
                source,
                os.path.join(root, "source", a),
                symlinks=True,
                ignore=lambda folder, names: [
                    n for n in names if folder == source and n in (f"{a}.ipynb", "accelab.json")
                ],
            )
        return build(root, lambda *args: run_nbgrader(root, *args))

    def swap(self, release):
        """Swap the built assignment in; on a failure put the old one back."""
        a = self.assignment
        steps = [
            ["folder", os.path.join(kind, a)]
            for kind in ("source", "release")
            if os.path.isdir(os.path.join(self.root, kind, a))
        ]
        steps.append(["gradebook", "gradebook.db"])
        steps += [["file", rel] for rel in KEPT if os.path.exists(os.path.join(self.root, rel))]
        if not _same_bytes(*self._paths("nbgrader_config.py")[:2]):  # new, or given accelab's
            steps.append(["file", "nbgrader_config.py"])  # collect (layout.upgrade_config)
        for kind in ("source", "release", "submitted", "autograded", "feedback"):
            os.makedirs(os.path.join(self.course, kind), exist_ok=True)
        write_atomic(os.path.join(self.root, JOURNAL), json.dumps(steps))
        done = []
        try:
            for step in steps:
                self._do(step)
                done.append(step)
                fault("assign-swapping")
            if release:
                run_nbgrader(self.course, "release_assignment", a, "--force")
        except BaseException:
            for step in reversed(done):
                self._undo(step)
            os.unlink(os.path.join(self.root, JOURNAL))
            raise
        os.unlink(os.path.join(self.root, JOURNAL))

    def _do(self, step):
        kind, rel = step
        real, staged, aside = self._paths(rel)
        os.makedirs(os.path.dirname(aside), exist_ok=True)
        if kind == "folder":
            if not os.path.exists(staged):  # done before a kill (recover)
                return
            if os.path.exists(real) and not os.path.exists(aside):
                os.rename(real, aside)
            os.makedirs(os.path.dirname(real), exist_ok=True)
            os.rename(staged, real)
        elif kind == "gradebook":
            if os.path.exists(real) and not os.path.exists(aside):
                copy_gradebook(real, aside)
            copy_gradebook(staged, real)
        else:
            if os.path.exists(real) and not os.path.exists(aside):
                shutil.copy2(real, aside)
            with open(staged, "rb") as fh:
                write_atomic(real, fh.read())

    def _undo(self, step):
        kind, rel = step
        real, staged, aside = self._paths(rel)
        if kind == "folder":
            if os.path.exists(real):
                os.rename(real, staged)
            if os.path.exists(aside):
                os.rename(aside, real)
        elif kind == "gradebook":
            if os.path.exists(aside):
                copy_gradebook(aside, real)
            elif os.path.exists(real):  # the course had none
                os.unlink(real)
        elif os.path.exists(aside):
            with open(aside, "rb") as fh:
                write_atomic(real, fh.read())
        elif os.path.exists(real):
            os.unlink(real)


def _same_bytes(a, b):
    """True if the files ``a`` and ``b`` both exist and hold the same bytes."""
    try:
        with open(a, "rb") as fa, open(b, "rb") as fb:
            return fa.read() == fb.read()
    except OSError:
        return False


def recover(course_dir):
    """Finish a swap a kill interrupted (its journal is complete: every staged
    part was built) and remove unfinished builds. Call with the course lock held."""
    for folder in sorted(glob.glob(os.path.join(glob.escape(course_dir), ".accelab", "staging-*"))):
        journal = os.path.join(folder, JOURNAL)
        if os.path.exists(journal):
            with open(journal, encoding="utf-8") as fh:
                steps = json.load(fh)
            staging = Staging(course_dir, "")
            staging.root = folder
            for step in steps:
                staging._do(step)
        shutil.rmtree(folder, ignore_errors=True)
