"""``accelab grade``: every submission run in a sandbox (in parallel), judged
outside it, scored into nbgrader's gradebook, given feedback, and tabled in a
per-question CSV over the whole roster.

0. What a submission is (:mod:`.intake`, :func:`take_in`): links and special
   files set aside, its time read (:func:`submission_time`).
1. Each submission is sanitized by nbgrader's own preprocessors (locked and test
   cells restored from the source notebook), turned into a plan, and run in its
   sandbox, ``jobs`` at a time (:mod:`.supervisor`).
2. ``nbgrader autograde`` runs in this process, on each submission as soon as
   its run is done (while the next ones run); its execution step,
   :class:`~.nbgrader_step.JudgeSubmission`, takes each prepared run (handed to
   it in the API's configuration, :class:`~.nbgrader_step.PreparedRuns`; it runs
   the plan itself if the notebook differs), judges it against the submitter's key
   and lets nbgrader score the test cells and write the gradebook. Then the
   submission's feedback page is written (:mod:`.feedback`).
3. A notebook that cannot be read gets 0 in the gradebook, with the reason in
   its feedback and in the CSV.
4. The CSV (:mod:`.gradetable`).

Grades are data. One grading runs per course at a time (:mod:`.lock`). Each
submission's record (:mod:`.state`) says which files, by content, were graded
and how far; a grading that did not end is never shown as a grade, and running
the same command again (or ``--new``) finishes it. Every file is replaced whole
(:mod:`accelab.exercises.files`). Ctrl-C ends the sandboxes at once and keeps
nothing partial (:mod:`.stop`). A failure that is not the student's (a full
disk, a busy gradebook, nbgrader's own error) never becomes a 0.
"""

import os
import queue
import re
import shlex
import sys
import time
import warnings
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field

from ..files import WriteError, fault, remove_partial, write_atomic
from ..nbgrader_course import ensure_path, roster_ids
from ..notebook import read_spec
from ..staging import recover
from . import intake
from .feedback import FeedbackPages, feedback_folder
from .lock import course_lock
from .nbgrader_step import (
    NotebookTooLarge,
    NotebookUnreadable,
    PreparedRuns,
    cached_key,
    command_for,
    read_submission,
    save_outcome,
)
from .orphans import stop_left_behind
from .outcome import Outcome
from .plan import plan_of
from .state import submission_hash, to_do, write_state
from .stop import HALT, NAMES, received, stoppable, wait_for
from .supervisor import Limits, run_plan


@dataclass
class Submission:
    """One student's submission as the grading run saw it."""

    student: str
    readable: bool = True
    problem: str = ""  # why it could not be graded
    prepared: bool = False
    seconds: float = 0.0
    graded: bool = False
    notes: list = field(default_factory=list)
    digest: str = ""  # content hash of the files as they were read (state.content_hash)
    stopped: bool = False  # cut short by a stop: nothing of it was kept
    failed: bool = False  # not graded, and not the student's doing: ``problem`` says why


class GradingStopped(Exception):
    """A signal (Ctrl-C) stopped the run; the message says what was done and how
    to finish. ``status`` is the exit status (128 + the signal)."""

    def __init__(self, message, status=130):
        super().__init__(message)
        self.status = status


class GradingFailed(RuntimeError):
    """An error that ends the run (a file that cannot be written, a full disk);
    the message names it and the next step."""


def submitters(course_dir, assignment):
    """The ids of ``submitted/`` with a submission of ``assignment``: folders named by
    a roster id (:func:`.intake.submissions`; the others are refused with a note)."""
    return intake.submissions(course_dir, assignment)[0]


#: what a course's nbgrader_config.py written by accelab 0.1 imports (before the
#: layers moved into the one ``accelab`` package)
OLD_CONFIG_IMPORT = re.compile(r"^\s*from exercises\.grader", re.M)


def check_config_version(course_dir):
    """Refuse, in one line that says how to update it, a course whose
    ``nbgrader_config.py`` was written by accelab 0.1 (CHANGELOG, 0.2.0)."""
    path = os.path.join(course_dir, "nbgrader_config.py")
    try:
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
    except (OSError, UnicodeDecodeError):
        return
    if OLD_CONFIG_IMPORT.search(text):
        raise ValueError(
            f"{path} was written by accelab 0.1 and imports 'exercises.grader'; "
            f"update it with: sed -i 's/from exercises\\./from accelab.exercises./' "
            f"{path}"
        )


def load_config(course_dir):
    """The course's nbgrader configuration, with its root set. Raises ValueError
    (naming the file and what to do) for a file that does not load."""
    from traitlets.config.loader import PyFileConfigLoader

    check_config_version(course_dir)
    path = os.path.join(course_dir, "nbgrader_config.py")
    if not os.path.exists(path):
        raise ValueError(
            f"{course_dir} has no nbgrader_config.py, so it is no course made by accelab assign; "
            f"check the --course folder"
        )
    try:
        config = PyFileConfigLoader("nbgrader_config.py", path=course_dir).load_config()
    except Exception as exc:  # noqa: BLE001 - it is Python: any error of the instructor's
        where = f" (line {exc.lineno})" if getattr(exc, "lineno", None) else ""
        raise ValueError(
            f"{path} cannot be loaded{where}: {type(exc).__name__}: {str(exc)[:300]}; fix it "
            f"(`python {shlex.quote(path)}` shows the error), or restore it from a backup"
        ) from None
    config.CourseDirectory.root = course_dir
    return config


def api_for(course_dir, prepared=None):
    """nbgrader's API on the course, and the course's configuration; ``prepared``
    (a :class:`~.nbgrader_step.PreparedRuns`) is handed to its JudgeSubmission."""
    from nbgrader.apps import NbGraderAPI
    from nbgrader.coursedir import CourseDirectory

    ensure_path()
    config = load_config(course_dir)
    if prepared is not None:
        config.JudgeSubmission.prepared = prepared
    return NbGraderAPI(CourseDirectory(config=config), config=config), config


def load_spec(course_dir, assignment):
    """The assignment's specification; ValueError naming the file if it is damaged."""
    path = os.path.join(course_dir, "source", assignment, "accelab.json")
    try:
        return read_spec(course_dir, assignment)
    except FileNotFoundError:
        raise
    except (ValueError, UnicodeDecodeError) as exc:
        if not isinstance(exc, UnicodeDecodeError) and not type(exc).__name__.endswith(
            "DecodeError"
        ):
            raise  # the spec's own check says what is wrong with it
        raise ValueError(
            f"the assignment's specification {path} is damaged ({exc}); restore it from a "
            f"backup (a replaced one is kept in {os.path.join(course_dir, '.accelab', 'replaced')}"
            f"), or write the assignment again with accelab assign --force and the options it "
            f"was made with"
        ) from None


def check_gradebook(config, course_dir):
    """ValueError (naming the file and what to do) if the course's sqlite
    gradebook is missing or is no database; nbgrader would otherwise make a new,
    empty one, or fail on every submission."""
    import sqlite3
    from urllib.parse import quote

    url = str(config.CourseDirectory.db_url or "")
    if not url.startswith("sqlite:///"):
        return
    path = url[len("sqlite:///") :]
    if not os.path.exists(path):
        raise ValueError(
            f"the gradebook {path} is missing; restore it from a backup (nbgrader's "
            f"grades are in it), or make a new, empty one with accelab assign --force"
        )
    try:
        db = sqlite3.connect(f"file:{quote(path)}?mode=ro", uri=True, timeout=30)
        try:
            db.execute("select count(*) from sqlite_master").fetchone()
        finally:
            db.close()
    except sqlite3.Error as exc:
        raise ValueError(
            f"the gradebook {path} cannot be read ({exc}); restore it from a backup"
        ) from None


def submitted_path(course_dir, assignment, student):
    return os.path.join(course_dir, "submitted", student, assignment, f"{assignment}.ipynb")


def take_in(course_dir, assignment, students):
    """Make each submission of ``students`` what nbgrader may read, and read its
    time (:func:`.intake.prepare`): links and special files set aside, a
    malformed, missing or future ``timestamp.txt`` set aside and noted. Run with
    the course held, before the submissions' contents are hashed (what is set
    aside is no part of what is graded). Stops early on Ctrl-C."""
    for student in students:
        if HALT.is_set():
            return
        intake.prepare(course_dir, assignment, student)


def submission_time(course_dir, assignment, student):
    """When ``student`` handed in ``assignment``, as the grader takes it: (a naive
    UTC datetime or None, notes for the instructor).

    The one place that answers it, from what :func:`take_in` (that is,
    :func:`.intake.prepare`) recorded: the exchange's own record, made by
    accelab's collect for this very notebook, with ``timestamp.txt`` only
    cross-checked (a mismatch is a note); else a sound ``timestamp.txt``. A
    malformed, missing or future one gives None (graded as on time) and a note;
    nbgrader's late penalty then reads the ``timestamp.txt`` intake left (the
    exchange's time, or none). Late work is noted in the grade table under every
    policy (:mod:`.gradetable`).
    """
    record = intake.read_record(course_dir, assignment, student) or {}
    when = intake.parse_time(str(record.get("time") or ""))
    return when, intake.notes_of(course_dir, assignment, student)


def sanitize(config, course_dir, assignment, student, nb):
    """The notebook as nbgrader's autograde sanitizes it (same preprocessors)."""
    from .nbgrader_step import sanitize_steps

    resources = {
        "nbgrader": {
            "db_url": config.CourseDirectory.db_url,
            "assignment": assignment,
            "notebook": assignment,
            "student": student,
        }
    }
    for cls in sanitize_steps():
        nb, resources = cls(config=config).preprocess(nb, resources)
    return nb


def prepare(config, course_dir, assignment, spec, student, command, limits, slots, runs):
    """Read, sanitize, plan and run one submission in its sandbox (a worker
    thread); the run goes into ``runs`` (:class:`~.nbgrader_step.PreparedRuns`),
    for JudgeSubmission. A run cut short by a stop is dropped."""
    sub = Submission(student)
    if HALT.is_set():
        sub.stopped = True
        return sub
    sub.digest = submission_hash(course_dir, assignment, student) or ""
    try:
        nb = read_submission(submitted_path(course_dir, assignment, student))
    except FileNotFoundError:
        sub.readable, sub.problem = False, f"no {assignment}.ipynb in the submission"
        return sub
    except (NotebookTooLarge, NotebookUnreadable) as exc:
        sub.readable, sub.problem = False, str(exc)
        return sub
    except Exception as exc:  # noqa: BLE001 - an OSError or worse: nothing of it is quoted
        sub.readable = False
        sub.problem = f"the notebook cannot be read ({type(exc).__name__})"
        return sub
    try:
        nb = sanitize(config, course_dir, assignment, student, nb)
    except Exception:  # noqa: BLE001 - nbgrader's autograde says what is wrong with it
        return sub
    steps = plan_of(nb)
    key = cached_key(spec, student)
    slot = slots.get()
    try:
        run = run_plan(steps, key.variant.statement(), command, limits, slot=slot)
    finally:
        slots.put(slot)
    if HALT.is_set():  # its sandbox may have been killed under it
        sub.stopped = True
        return sub
    runs.put(assignment, student, steps, run)
    sub.prepared, sub.seconds = True, run.seconds
    return sub


def progress(done, total, stream=None, width=30):
    stream = stream or sys.stderr
    filled = int(width * done / max(total, 1))
    stream.write(f"\rgrading [{'#' * filled}{'.' * (width - filled)}] {done}/{total}")
    if done == total:
        stream.write("\n")
    stream.flush()


def _jobs(jobs):
    try:
        jobs = int(jobs)
    except (TypeError, ValueError):
        jobs = 0
    if jobs < 1:
        raise ValueError("--jobs must be a whole number of at least 1 (submissions run at a time)")
    return jobs


def choose(course_dir, assignment, students):
    """The submitters to grade: all, or the ones named (each must have handed in)."""
    everyone = submitters(course_dir, assignment)
    if not students:
        return everyone
    named = list(dict.fromkeys(str(s) for s in students))
    missing = [s for s in named if s not in everyone]
    if missing:
        have = ", ".join(everyone[:8]) + (", ..." if len(everyone) > 8 else "")
        raise ValueError(
            f"no submission of {assignment} from {', '.join(repr(s) for s in missing)} in "
            f"{os.path.join(course_dir, 'submitted')} (submissions from: {have or 'nobody yet'}); "
            f"check the id, or collect first: nbgrader collect {assignment}"
        )
    return named


def resume_command(course_dir, assignment):
    return (
        f"accelab grade --course {shlex.quote(course_dir)} --assignment "
        f"{shlex.quote(assignment)} --new"
    )


def grade(
    course_dir,
    assignment,
    students=None,
    only_new=False,
    jobs=2,
    unsafe=False,
    show_progress=True,
    csv_path=None,
    limits=None,
):
    """The whole job. Returns (submissions, csv path, rows, seconds, timings).

    ``only_new``: only the submissions not completely graded, or changed since
    (by content). Raises :class:`~.sandbox.SandboxUnavailable` when there is no
    sandbox and ``unsafe`` is not set; :class:`~.lock.CourseBusy` when another
    accelab command holds the course; ValueError for a course file that cannot
    be used; :class:`GradingFailed` when the run cannot go on (a write error);
    :class:`GradingStopped` on Ctrl-C. In every case nothing partial is kept as
    a grade, and the same command finishes the job.
    """
    start = time.monotonic()
    course_dir = os.path.abspath(course_dir)
    jobs = _jobs(jobs)
    spec = load_spec(course_dir, assignment)
    runs = PreparedRuns()  # made in the workers, taken by JudgeSubmission in autograde
    api, config = api_for(course_dir, runs)
    check_gradebook(config, course_dir)
    roster_ids(course_dir)  # a damaged roster is said now, not once per submission
    _question_names(course_dir, assignment)  # and a damaged released notebook
    command = command_for(unsafe)  # SandboxUnavailable if the sandbox does not work here
    step = config.JudgeSubmission
    limits = limits or Limits(
        cell_seconds=float(step.get("cell_timeout", 10.0)),
        total_seconds=float(step.get("time_limit", 60.0)),
    )
    with course_lock(course_dir, f"accelab grade --assignment {assignment}"), stoppable():
        recover(course_dir)  # an `accelab assign` killed while it swapped a new version in
        for line in stop_left_behind():  # a grader killed before its sandbox could follow it
            sys.stderr.write(f"accelab: note: {line}\n")
        for folder, deep in ((course_dir, False), (os.path.join(course_dir, ".accelab"), True)):
            remove_partial(folder, deep)  # what a run killed while it wrote left beside
        remove_partial(os.path.join(course_dir, "feedback"))
        if csv_path:
            remove_partial(os.path.dirname(os.path.abspath(csv_path)), False)
        run = _Run(course_dir, assignment, spec, api, config, command, limits, show_progress, runs)
        run.csv_path = _csv_path(course_dir, assignment, csv_path)
        try:
            chosen = choose(course_dir, assignment, students)
            try:
                take_in(course_dir, assignment, chosen)  # before contents are hashed: --new
            except WriteError as exc:
                raise GradingFailed(
                    f"{exc}. Nothing was graded; once that is fixed, run: "
                    f"{resume_command(course_dir, assignment)}"
                ) from None
            subs, timings = run.go(chosen, only_new, jobs)
            t0 = time.monotonic()
            try:
                path, rows = _export(course_dir, assignment, csv_path)
            except WriteError as exc:
                raise GradingFailed(
                    f"{exc}. The grades are in the gradebook; once that is fixed, run: "
                    f"{resume_command(course_dir, assignment)} (it writes the CSV)"
                ) from None
            timings["CSV"] = time.monotonic() - t0
        except KeyboardInterrupt:  # a second Ctrl-C
            raise run.stopped(csv=False) from None
        if received() is not None:
            raise run.stopped(csv=True)
    return subs, path, rows, time.monotonic() - start, timings


def _question_names(course_dir, assignment):
    from .gradetable import question_names

    return question_names(course_dir, assignment)


def _csv_path(course_dir, assignment, csv_path):
    from .gradetable import csv_path_of

    return csv_path_of(course_dir, assignment, csv_path)


def _export(course_dir, assignment, csv_path):
    from .gradetable import export_csv

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return export_csv(course_dir, assignment, csv_path)


#: what in nbgrader's log says the disk (or the gradebook's) is full
DISK_FULL = re.compile(
    r"No space left on device|Errno 28\b|Errno 122\b|Disk quota exceeded|database or disk is full"
)
#: what in nbgrader's log says the gradebook could not be used
GRADEBOOK_ERROR = re.compile(r"sqlalchemy|sqlite3|database is locked|OperationalError")


def classify(result, assignment="A", student="ID"):
    """Why nbgrader's autograde did not succeed: (problem for the instructor,
    fatal). Fatal (a full disk) ends the run; anything else leaves this one
    submission ungraded (never a 0: it is not the student's doing)."""
    log = f"{result.get('log', '')}\n{result.get('error', '')}"
    last = _last_error(log)
    if DISK_FULL.search(log):
        lines = [line.strip() for line in log.splitlines() if DISK_FULL.search(line)]
        ours = [line for line in lines if "could not write" in line]  # a WriteError: the path
        if ours:
            return "could not write" + ours[0].split("could not write", 1)[1][:300], True
        return f"the disk is full ({lines[0][:300]})", True
    if GRADEBOOK_ERROR.search(log):
        return (
            f"the gradebook could not be written ({last}); it is not the student's doing: "
            f"grade it again with --new",
            False,
        )
    return (
        f"nbgrader could not autograde it ({last}); it is not the student's doing: look at "
        f"it with `nbgrader autograde {assignment} --student {student} --force` (in the course "
        f"folder) or in formgrader, then grade it again with --new",
        False,
    )


CHANGED = "the submission changed while it was graded (collected again?); grade it again with --new"


class _Run:
    """One grading run: the submissions it grades, in the order their sandboxed
    runs end, each carried through its stages (state.py) in this thread."""

    def __init__(self, course_dir, assignment, spec, api, config, command, limits, show, runs):
        self.course_dir, self.assignment, self.spec = course_dir, assignment, spec
        self.api, self.config, self.command, self.limits = api, config, command, limits
        self.runs = runs  # PreparedRuns: the workers put, JudgeSubmission (in api) takes
        self.show = show
        self.csv_path = None  # where the CSV is written (grade() sets it)
        self.subs = {}
        self.chosen = []
        self.pages = None
        self.spent = {"judging": 0.0, "feedback": 0.0}

    def go(self, chosen, only_new, jobs):
        course_dir, assignment = self.course_dir, self.assignment
        digests = {s: submission_hash(course_dir, assignment, s) or "" for s in chosen}
        todo = {s: "grade" for s in chosen}
        if only_new:
            todo = {s: to_do(course_dir, assignment, s, digests[s]) for s in chosen}
            chosen = [s for s in chosen if todo[s]]
        self.chosen = chosen
        timings = {}
        t0 = time.monotonic()
        slots = queue.Queue()
        for slot in range(jobs):
            slots.put(slot)
        pool = ThreadPoolExecutor(max_workers=jobs)
        futures = {}
        n = 0
        if self.show:
            progress(0, len(chosen))
        try:
            with warnings.catch_warnings():  # for the worker threads too (silence.py)
                warnings.simplefilter("ignore")
                args = (self.config, course_dir, assignment, self.spec)
                futures = {
                    pool.submit(prepare, *args, s, self.command, self.limits, slots, self.runs): s
                    for s in chosen
                    if todo[s] == "grade"
                }
                for s in [s for s in chosen if todo[s] == "feedback"]:  # while those run
                    if HALT.is_set():
                        break
                    self.subs[s] = self.feedback_only(Submission(s, digest=digests[s]))
                    n += 1
                    self._progress(n)
                for fut in as_completed(futures):
                    if HALT.is_set():
                        break
                    try:
                        sub = fut.result()
                    except Exception:  # noqa: BLE001 - one submission's failure is its own:
                        sub = Submission(futures[fut])  # nbgrader's autograde tries it alone
                        sub.digest = digests[sub.student]
                    if sub.stopped:
                        break
                    self.subs[sub.student] = sub
                    try:
                        self.finish(sub)
                    except (WriteError, GradingFailed):
                        raise
                    except Exception as exc:  # noqa: BLE001 - this submission's, said below
                        sub.failed = True
                        sub.problem = (
                            f"it could not be graded ({type(exc).__name__}: {str(exc)[:200]}); "
                            f"it is not the student's doing: grade it again with --new"
                        )
                    n += 1
                    self._progress(n)
        except WriteError as exc:
            raise GradingFailed(self._failed_message(str(exc))) from None
        finally:
            HALT.set()  # no sandbox starts now; one that runs is ended
            pool.shutdown(wait=False, cancel_futures=True)
            wait_for(lambda: any(not f.done() for f in futures))
            self.runs.clear()  # runs never judged (a stop, a failure) are not kept
            if self.show and n < len(chosen):
                sys.stderr.write("\n")
                sys.stderr.flush()
        timings["sandbox runs, judging and feedback, overlapped"] = time.monotonic() - t0
        timings["of which judging and gradebook (nbgrader autograde)"] = self.spent["judging"]
        timings["of which feedback"] = self.spent["feedback"]
        return [self.subs[s] for s in chosen if s in self.subs], timings

    def _progress(self, n):
        if self.show:
            progress(n, len(self.chosen))

    def _failed_message(self, what):
        done = sum(1 for s in self.subs.values() if s.graded)
        if self.csv_path and os.path.isfile(self.csv_path):
            csv_text = f"the CSV was not rewritten (the old one is kept: {self.csv_path})"
        else:
            csv_text = "no CSV was written (there was none before)"
        return (
            f"{what}. Grading stopped: {done} of {len(self.chosen)} submission(s) were graded "
            f"completely before it; nothing partial is kept as a grade, and {csv_text}. "
            f"Once that is fixed, run: "
            f"{resume_command(self.course_dir, self.assignment)}"
        )

    def stopped(self, csv):
        """The GradingStopped that tells the instructor what was done."""
        signum = received()
        done = sum(1 for s in self.subs.values() if s.graded)
        left = len(self.chosen) - done
        what = NAMES.get(signum, "a signal")
        csv_text = "the CSV shows what is graded" if csv else "the CSV was not written this time"
        return GradingStopped(
            f"interrupted ({what}): {done} of {len(self.chosen)} submission(s) graded "
            f"completely; {left} not yet, and nothing of them is kept as a grade ({csv_text}). "
            f"To finish, run: {resume_command(self.course_dir, self.assignment)}",
            128 + int(signum or 2),
        )

    def _feedback(self, sub):
        """Write ``sub``'s feedback page; False (with the problem said) if it could
        not be made for another reason than a write error (which ends the run)."""
        if self.pages is None:
            self.pages = FeedbackPages(self.api)
        t0 = time.monotonic()
        fault("feedback-begun")
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                self.pages.write(self.course_dir, self.assignment, sub.student)
        except WriteError:
            raise
        except Exception as exc:  # noqa: BLE001 - nbconvert's, said to the instructor
            sub.failed = True
            sub.problem = (
                f"graded, but its feedback page could not be made ({type(exc).__name__}: "
                f"{str(exc)[:200]}); make it with: accelab grade --new"
            )
            return False
        finally:
            self.spent["feedback"] += time.monotonic() - t0
        return True

    def feedback_only(self, sub):
        """A submission graded before whose feedback page is missing."""
        if self._feedback(sub):
            write_state(self.course_dir, self.assignment, sub.student, sub.digest, "done")
            sub.graded = True
        return sub

    def finish(self, sub):
        """Judge, score and give feedback to one submission whose run is done,
        recording each stage; a failure that is not the student's leaves it
        ungraded (never a 0)."""
        course_dir, assignment, student = self.course_dir, self.assignment, sub.student
        if not sub.digest:
            sub.digest = submission_hash(course_dir, assignment, student) or ""
        write_state(course_dir, assignment, student, sub.digest, "grading")
        fault("grading-begun")
        sub.notes += submission_time(course_dir, assignment, student)[1]  # who and when
        if not sub.readable:
            if submission_hash(course_dir, assignment, student) != sub.digest:
                sub.failed = True  # collect was writing it: no 0 for a file half copied
                sub.problem = CHANGED
                return
            try:
                zero_and_explain(self.api, course_dir, assignment, student, sub.problem, sub.digest)
            except WriteError:
                raise
            except Exception as exc:  # noqa: BLE001 - the gradebook's error, said below
                problem, fatal = classify(
                    {"error": f"{type(exc).__module__}.{exc!r}"}, assignment, student
                )
                if fatal:
                    message = self._failed_message(f"student {student}: {problem}")
                    raise GradingFailed(message) from None
                sub.failed, sub.problem = True, problem
                write_state(course_dir, assignment, student, sub.digest, "failed", problem)
                return
            write_state(course_dir, assignment, student, sub.digest, "done")
            return
        t1 = time.monotonic()
        result = self.api.autograde(assignment, student, force=True, create=True)
        self.spent["judging"] += time.monotonic() - t1
        if not result.get("success"):
            if HALT.is_set():  # stopped while it ran: nothing of it is a grade
                sub.stopped = True
                return
            problem, fatal = classify(result, assignment, student)
            if fatal:
                raise GradingFailed(self._failed_message(f"student {student}: {problem}"))
            sub.failed, sub.problem = True, problem
            write_state(course_dir, assignment, student, sub.digest, "failed", problem)
            return
        fault("autograded")
        judged = _judged_digest(course_dir, assignment, student)
        if judged != sub.digest:  # collect replaced it while it was graded
            sub.failed, sub.problem = True, CHANGED
            write_state(course_dir, assignment, student, judged or sub.digest, "grading")
            return
        write_state(course_dir, assignment, student, sub.digest, "scored")
        fault("scored")
        if self._feedback(sub):
            write_state(course_dir, assignment, student, sub.digest, "done")
            sub.graded = True


def _judged_digest(course_dir, assignment, student):
    """The content hash of the files JudgeSubmission judged (in its outcome)."""
    from .state import DamagedRecord, read_outcome

    try:
        outcome = read_outcome(course_dir, assignment, student)
    except DamagedRecord:
        return None
    return (outcome or {}).get("submission")


def _last_error(log):
    """The exception nbgrader's log ends its traceback with (not nbgrader's own
    "see the traceback above")."""
    lines = [line.strip() for line in str(log).splitlines()]
    found = [
        line
        for line in lines
        if re.match(r"^[A-Za-z_.]*(Error|Exception)\b.*:", line) and "NbGraderException" not in line
    ]
    return (found[-1] if found else "nbgrader could not autograde it")[:300]


def zero_and_explain(api, course_dir, assignment, student, problem, digest=None):
    """A submission that could not be read: 0 on every question in the
    gradebook, the reason in its outcome and in a feedback page."""
    import html

    from nbgrader.api import MissingEntry

    from ..nbgrader_course import course_id_of, gradebook

    reason = problem or "it could not be graded"
    names = []
    with warnings.catch_warnings(), gradebook(course_dir, course_id_of(course_dir)) as gb:
        warnings.simplefilter("ignore")
        try:
            gb.find_student(student)
        except MissingEntry:
            gb.add_student(student)
        sub = gb.update_or_create_submission(assignment, student)
        for nb in sub.notebooks:
            for g in nb.grades:
                g.auto_score = 0.0
                g.needs_manual_grade = False
                names.append(g.name)
        gb.db.commit()
    notes = [f"not graded: {reason}", *intake.notes_of(course_dir, assignment, student)]
    save_outcome(course_dir, assignment, Outcome(student, notes=notes), digest)
    folder = feedback_folder(course_dir, assignment, student)
    write_atomic(
        os.path.join(folder, f"{assignment}.html"),
        f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{assignment}: feedback"
        f"</title></head><body><h1>{html.escape(assignment)}: 0 of {len(names)}</h1>"
        f"<p>Your submission could not be graded: {html.escape(reason)}.</p>"
        "<p>Submit the assignment's notebook again, as a notebook saved by Jupyter, "
        "starting from the released one.</p></body></html>\n",
        mode=0o644,
        stage="feedback",
    )
    intake.clean_feedback_of(course_dir, assignment, student)  # only what the grader wrote
