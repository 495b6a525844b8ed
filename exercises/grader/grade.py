"""``accelab grade``: every submission run in a sandbox (in parallel), judged
outside it, scored into nbgrader's gradebook, given feedback, and tabled in a
per-question CSV over the whole roster.

1. Each submission is sanitized by nbgrader's own preprocessors (locked and test
   cells restored from the source notebook), turned into a plan, and run in its
   sandbox, ``jobs`` at a time (:mod:`.supervisor`).
2. ``nbgrader autograde`` runs in this process, on each submission as soon as
   its run is done (while the next ones run); its execution step,
   :class:`~.nbgrader_step.JudgeSubmission`, takes each prepared run (or runs the
   plan itself if the notebook differs), judges it against the submitter's key
   and lets nbgrader score the test cells and write the gradebook.
3. A notebook that cannot be read gets 0 in the gradebook, with the reason in
   its feedback and in the CSV.
4. ``nbgrader generate_feedback``; then the CSV (:mod:`.gradetable`).
"""

import os
import queue
import re
import sys
import time
import warnings
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field

from ..nbgrader_course import ensure_path
from ..notebook import read_spec
from . import intake
from .nbgrader_step import (
    _LOCK,
    PREPARED,
    NotebookTooLarge,
    NotebookUnreadable,
    cached_key,
    command_for,
    outcome_path,
    read_submission,
    save_outcome,
)
from .outcome import Outcome
from .plan import fingerprint, plan_of
from .sandbox import sandbox
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
    """The course's nbgrader configuration, with its root set."""
    from traitlets.config.loader import PyFileConfigLoader

    check_config_version(course_dir)
    config = PyFileConfigLoader("nbgrader_config.py", path=course_dir).load_config()
    config.CourseDirectory.root = course_dir
    return config


def api_for(course_dir):
    from nbgrader.apps import NbGraderAPI
    from nbgrader.coursedir import CourseDirectory

    ensure_path()
    config = load_config(course_dir)
    return NbGraderAPI(CourseDirectory(config=config), config=config), config


def submitted_path(course_dir, assignment, student):
    return os.path.join(course_dir, "submitted", student, assignment, f"{assignment}.ipynb")


def is_new(course_dir, assignment, student):
    """True if the submission was not graded since it was last submitted."""
    done = outcome_path(course_dir, assignment, student)
    if not os.path.exists(done):
        return True
    folder = os.path.dirname(submitted_path(course_dir, assignment, student))
    newest = max(
        (os.path.getmtime(os.path.join(folder, f)) for f in os.listdir(folder)), default=0.0
    )
    return newest > os.path.getmtime(done)


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


def prepare(config, course_dir, assignment, spec, student, command, limits, slots):
    """Read, sanitize, plan and run one submission in its sandbox."""
    sub = Submission(student)
    try:
        nb = read_submission(submitted_path(course_dir, assignment, student))
    except FileNotFoundError:
        sub.readable, sub.problem = False, f"no {assignment}.ipynb in the submission"
        return sub
    except (NotebookTooLarge, NotebookUnreadable) as exc:
        sub.readable, sub.problem = False, str(exc)
        return sub
    except Exception as exc:  # noqa: BLE001 - an OSError or worse: nothing of the file is quoted
        sub.readable = False
        sub.problem = f"the notebook cannot be read ({type(exc).__name__})"
        return sub
    try:
        nb = sanitize(config, course_dir, assignment, student, nb)
    except Exception:  # noqa: BLE001 - nbgrader says what is wrong when it autogrades it
        return sub
    steps = plan_of(nb)
    key = cached_key(spec, student)
    slot = slots.get()
    try:
        run = run_plan(steps, key.variant.statement(), command, limits, slot=slot)
    finally:
        slots.put(slot)
    with _LOCK:
        PREPARED[(course_dir, assignment, student, fingerprint(steps))] = run
    sub.prepared, sub.seconds = True, run.seconds
    return sub


def progress(done, total, stream=None, width=30):
    stream = stream or sys.stderr
    filled = int(width * done / max(total, 1))
    stream.write(f"\rgrading [{'#' * filled}{'.' * (width - filled)}] {done}/{total}")
    if done == total:
        stream.write("\n")
    stream.flush()


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

    Raises :class:`~.sandbox.SandboxUnavailable` when there is no sandbox and
    ``unsafe`` is not set.
    """
    from .gradetable import export_csv

    start = time.monotonic()
    course_dir = os.path.abspath(course_dir)
    command = command_for(unsafe) if unsafe else sandbox()
    spec = read_spec(course_dir, assignment)
    api, config = api_for(course_dir)
    step = config.JudgeSubmission
    limits = limits or Limits(
        cell_seconds=float(step.get("cell_timeout", 10.0)),
        total_seconds=float(step.get("time_limit", 60.0)),
    )
    everyone = submitters(course_dir, assignment)
    chosen = [s for s in (students or everyone) if s in everyone]
    if only_new:
        chosen = [s for s in chosen if is_new(course_dir, assignment, s)]
    for student in chosen:  # links set aside, the time read: what nbgrader may read
        intake.prepare(course_dir, assignment, student)
    timings = {}
    slots = queue.Queue()
    for slot in range(max(1, int(jobs))):
        slots.put(slot)
    subs = {}
    t0 = time.monotonic()
    spent = {"sandbox runs": 0.0, "judging and gradebook (nbgrader autograde)": 0.0}
    if show_progress:
        progress(0, len(chosen))
    # each run is judged and scored as soon as it is done, while the next ones run
    with ThreadPoolExecutor(max_workers=max(1, int(jobs))) as pool, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        futures = {
            pool.submit(prepare, config, course_dir, assignment, spec, s, command, limits, slots): s
            for s in chosen
        }
        for n, fut in enumerate(as_completed(futures), start=1):
            try:
                sub = fut.result()
            except Exception:  # noqa: BLE001 - never one submission's failure for the whole class:
                sub = Submission(futures[fut])  # nbgrader's autograde tries it alone
            subs[sub.student] = sub
            if sub.readable:
                t1 = time.monotonic()
                result = api.autograde(assignment, sub.student, force=True, create=True)
                spent["judging and gradebook (nbgrader autograde)"] += time.monotonic() - t1
                sub.graded = bool(result.get("success"))
                if not sub.graded:
                    sub.problem = _last_error(result.get("log", ""))
            if show_progress:
                progress(n, len(chosen))
    timings["sandbox runs and judging, overlapped"] = time.monotonic() - t0
    timings["of which judging and gradebook (nbgrader autograde)"] = spent[
        "judging and gradebook (nbgrader autograde)"
    ]
    t0 = time.monotonic()
    for student in chosen:
        if not subs[student].graded:
            zero_and_explain(api, course_dir, assignment, student, subs[student].problem)
    graded = [s for s in chosen if subs[s].graded]
    if graded:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            api.generate_feedback(
                assignment, student_id=graded[0] if len(graded) == 1 else None, force=True
            )
    intake.clean_feedback(course_dir, assignment, everyone)
    timings["feedback"] = time.monotonic() - t0
    t0 = time.monotonic()
    path, rows = export_csv(course_dir, assignment, csv_path)
    timings["CSV"] = time.monotonic() - t0
    with _LOCK:
        for token in [t for t in PREPARED if t[0] == course_dir and t[1] == assignment]:
            PREPARED.pop(token, None)
    return [subs[s] for s in chosen], path, rows, time.monotonic() - start, timings


def _last_error(log):
    """The exception nbgrader's log ends its traceback with."""
    lines = [line.strip() for line in str(log).splitlines()]
    found = [line for line in lines if re.match(r"^[A-Za-z_.]*(Error|Exception)\b.*:", line)]
    return (found[-1] if found else "nbgrader could not autograde it")[:300]


def zero_and_explain(api, course_dir, assignment, student, problem):
    """A submission that could not be graded: 0 on every question in the
    gradebook, the reason in its outcome and in a feedback page."""
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
    save_outcome(course_dir, assignment, Outcome(student, notes=notes))
    folder = os.path.join(course_dir, "feedback", student, assignment)
    os.makedirs(folder, exist_ok=True)
    import html

    with open(os.path.join(folder, f"{assignment}.html"), "w") as fh:
        fh.write(
            f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{assignment}: feedback"
            f"</title></head><body><h1>{html.escape(assignment)}: 0 of {len(names)}</h1>"
            f"<p>Your submission could not be graded: {html.escape(reason)}.</p>"
            "<p>Submit the assignment's notebook again, as a notebook saved by Jupyter, "
            "starting from the released one.</p></body></html>\n"
        )
