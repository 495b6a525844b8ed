"""A standard nbgrader course directory with accelab's configuration.

``create_course(root, course_id, roster)`` writes ``nbgrader_config.py``, the
embedded sqlite gradebook (``gradebook.db``) with the roster's students, and the
roster itself (``.accelab/roster.json``: the CSV covers every student on it).
The config puts :class:`accelab.exercises.grader.nbgrader_step.JudgeSubmission` in place
of nbgrader's execution step, so that however autograde is started (``accelab
grade``, ``nbgrader autograde``, formgrader) a submission runs in the sandbox and
is judged outside it.
"""

import csv
import json
import os
import subprocess
import sys

from .ids import RULE, id_problem

#: a Jupyter data folder for ``JUPYTER_PATH``: nbconvert's ``mathjax`` macro that loads MathJax
#: from the Jupyter server itself (jupyter-server-mathjax), so that formgrader and the feedback
#: pages typeset their equations offline (nbgrader's templates otherwise fetch it from a CDN)
#:
#: :meta hide-value:
JUPYTER_DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "jupyter")

CONFIG = """\
# nbgrader configuration written by `accelab assign` (accelab exercises).
import os

from nbconvert.preprocessors import ClearMetadataPreprocessor, CSSHTMLHeaderPreprocessor
from nbgrader.preprocessors import (AssignLatePenalties, CheckCellMetadata, GetGrades,
                                    LimitOutput, SaveAutoGrades)

from accelab.exercises.grader.collect import AccelabCollect
from accelab.exercises.grader.nbgrader_step import CleanFeedback, JudgeSubmission, sanitize_steps
from accelab.exercises.layout import FORMGRADER_TEMPLATES, TEMPLATES

c = get_config()  # noqa: F821
HERE = os.path.dirname(os.path.abspath(__file__))
c.CourseDirectory.course_id = {course_id!r}
c.CourseDirectory.root = HERE
c.CourseDirectory.db_url = "sqlite:///" + os.path.join(HERE, "gradebook.db")
# the exchange, outside this folder (which is private to the instructor): students'
# own nbgrader configuration names the same folder
c.Exchange.root = {exchange!r}
# collect: the submitter is the account that owns the submission's folder in the exchange,
# its time the exchange's record, and only regular files are collected (never a link)
c.ExchangeFactory.collect = AccelabCollect
# formgrader's submission page shows the student's id and names escaped (nbgrader's prints
# them as HTML)
c.HTMLExporter.extra_template_basedirs = [TEMPLATES, FORMGRADER_TEMPLATES]
c.HTMLExporter.extra_template_paths = [FORMGRADER_TEMPLATES]
c.CourseDirectory.ignore = [".ipynb_checkpoints", "*.pyc", "__pycache__", "feedback", ".accelab"]

# nbgrader's sanitizing, mended: a copied cell or forged cell metadata costs only
# the cells it touches, never the whole submission
c.Autograde.sanitize_preprocessors = sanitize_steps()
# autograde: each submission runs in a sandbox; its answers are judged outside it,
# against the submitter's key (JudgeSubmission takes the place of Execute)
c.Autograde.autograde_preprocessors = [JudgeSubmission, ClearMetadataPreprocessor, LimitOutput,
                                       SaveAutoGrades, AssignLatePenalties, CheckCellMetadata]
c.JudgeSubmission.cell_timeout = {timeout}
c.JudgeSubmission.time_limit = {time_limit}
# a deleted test cell comes back, and the answer it tests is judged as usual
c.OverwriteCells.add_missing_cells = True
c.OverwriteCells.missing_cell_notification = "# test cell {{cell_id}} was deleted and put back\\n"
# feedback: error messages without tracebacks
c.GenerateFeedback.preprocessors = [GetGrades, CSSHTMLHeaderPreprocessor, CleanFeedback]
# the released answer cells start empty (an undefined answer gets a clear message)
c.ClearSolutions.code_stub = {{"python": "# YOUR ANSWER HERE"}}
"""


def ensure_path():
    """Put this Python's bin directory (where ``alembic`` lives: nbgrader's
    gradebook calls it) first on PATH, in this process and its children."""
    bindir = os.path.dirname(sys.executable)
    path = os.environ.get("PATH", "")
    if bindir not in path.split(os.pathsep):
        os.environ["PATH"] = bindir + os.pathsep + path


def gradebook(root, course_id):
    """nbgrader's Gradebook on the course's embedded sqlite database."""
    from nbgrader.api import Gradebook

    ensure_path()
    head_in_process()
    return Gradebook("sqlite:///" + os.path.join(os.path.abspath(root), "gradebook.db"), course_id)


def alembic_head():
    """The head revision of nbgrader's gradebook migrations, read in this process: what
    nbgrader's own ``get_alembic_version`` takes from the first line of ``alembic heads``
    (the same script directory, the same first revision), without the 1.8 s of a new
    ``alembic`` process every time a new gradebook is made."""
    from alembic.script import ScriptDirectory
    from nbgrader.dbutil import ALEMBIC_DIR

    return ScriptDirectory(ALEMBIC_DIR).get_revisions("heads")[0].revision


def head_in_process():
    """Make nbgrader's Gradebook read the migrations' head with :func:`alembic_head`
    (once per process; the value stamped into a new gradebook is the same)."""
    import nbgrader.api

    if nbgrader.api.get_alembic_version is not alembic_head:
        nbgrader.api.get_alembic_version = alembic_head


def nbgrader(course_dir, *args, check=True):
    """Run ``nbgrader ARGS`` in the course directory; returns the CompletedProcess.

    The venv's bin (where ``alembic`` lives) is put first on PATH.
    """
    env = dict(os.environ)
    bindir = os.path.dirname(sys.executable)
    env["PATH"] = bindir + os.pathsep + env.get("PATH", "")
    proc = subprocess.run(
        [sys.executable, "-m", "nbgrader", *args],
        cwd=course_dir,
        env=env,
        capture_output=True,
        text=True,
    )
    if check and proc.returncode != 0:
        raise RuntimeError(
            f"nbgrader {' '.join(args)} failed (exit {proc.returncode}):\n" + proc.stderr[-3000:]
        )
    return proc


def check_ids(ids, where="the roster"):
    """ValueError naming every id of ``ids`` (a list of (row label, id)) that
    cannot be a student id (:func:`accelab.exercises.ids.id_problem`, the rule
    collect and grade hold submitted ids to), and every two that are equal but
    for letter case."""
    problems = [
        f"{label}: " + (f"{sid!r} {why}" if sid else "the id is empty")
        for label, sid in ids
        if (why := id_problem(sid))
    ]
    seen = {}
    for label, sid in ids:
        key = sid.casefold()
        if key in seen:
            first_label, first = seen[key]
            same = "the same id" if first == sid else "ids equal but for letter case"
            problems.append(f"{first_label} and {label}: {same} ({first!r}, {sid!r})")
        else:
            seen[key] = (label, sid)
    if problems:
        raise ValueError(
            f"{where} cannot be used: "
            + "; ".join(problems[:10])
            + (f"; and {len(problems) - 10} more" if len(problems) > 10 else "")
            + f". {RULE[0].upper()}{RULE[1:]}, and each student is on it once; fix the file and "
            "run again"
        )


def read_roster(path, say=None):
    """Students from a CSV with a column ``id`` (and optional first_name,
    last_name, email); a UTF-8 byte order mark is read as none.

    Ids padded with spaces are taken without them (``say`` is told). Raises
    ValueError naming the rows of ids that cannot be student ids (see
    :func:`check_ids`), and for a roster without an ``id`` column or without
    students.
    """
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:
            reader = csv.DictReader(fh)
            fields = [str(f).strip() for f in (reader.fieldnames or [])]
            reader.fieldnames = fields
            rows = list(reader)
    except UnicodeDecodeError:
        raise ValueError(f"{path}: the roster is not text in UTF-8; save it as UTF-8 CSV") from None
    except csv.Error as exc:
        raise ValueError(f"{path}: the roster is not a CSV file ({exc})") from None
    if "id" not in fields:
        raise ValueError(
            f"{path}: the roster needs a column 'id' (got {fields or 'no header'}); its first "
            f"line must name the columns, e.g. id,first_name,last_name,email"
        )
    labelled, padded = [], []
    for k, row in enumerate(rows, start=2):
        raw = row.get("id") or ""
        sid = raw.strip()
        if sid != raw and sid:
            padded.append(f"row {k}: {raw!r} taken as {sid!r}")
        row["id"] = sid
        labelled.append((f"row {k}", sid))
    if not rows:
        raise ValueError(f"{path}: the roster has no students (only a header, or nothing)")
    check_ids(labelled, where=f"the roster {path}")
    if padded and say:
        say(f"{path}: spaces around ids removed: {'; '.join(padded[:10])}")
    return rows


def default_exchange(root):
    """Where a new course's exchange goes unless told: a folder ``exchange`` beside
    the course folder (outside it; nbgrader's exchange holds many courses)."""
    return os.path.join(os.path.dirname(os.path.abspath(root)), "exchange")


def create_course(root, course_id="accelab", roster=(), timeout=10, time_limit=60, exchange=None):
    """Create (or update) the course directory at ``root``; returns its path.

    ``roster`` is a list of ids or dicts with ``id`` and optional names (and
    ``account``, the student's account name where it is not the id). An existing
    nbgrader_config.py is kept (the instructor may have edited it). ``exchange``
    is the exchange folder a new course's configuration names (default
    :func:`default_exchange`).
    """
    root = os.path.abspath(root)
    for sub in ("source", "release", "submitted", "autograded", "feedback"):
        os.makedirs(os.path.join(root, sub), exist_ok=True)
    config = os.path.join(root, "nbgrader_config.py")
    if not os.path.exists(config):
        with open(config, "w") as fh:
            fh.write(
                CONFIG.format(
                    course_id=course_id,
                    timeout=float(timeout),
                    time_limit=float(time_limit),
                    exchange=os.path.abspath(exchange or default_exchange(root)),
                )
            )
    ids = roster_ids(root)
    with gradebook(root, course_id) as gb:
        for student in roster:
            info = dict(student) if isinstance(student, dict) else {"id": student}
            sid = info.pop("id")
            info = {k: v for k, v in info.items() if k in ("first_name", "last_name", "email")}
            gb.update_or_create_student(sid, **info)
            ids.append(str(sid))
    write_roster(root, ids)
    from .grader.intake import save_accounts

    save_accounts(root, roster)
    return root


def roster_ids(root):
    """The ids on the course's roster (in the order they were added). Raises
    ValueError naming the file if it is damaged."""
    path = os.path.join(root, ".accelab", "roster.json")
    if not os.path.exists(path):
        return []
    try:
        with open(path, encoding="utf-8") as fh:
            ids = json.load(fh)
        if not isinstance(ids, list):
            raise ValueError("not a list of ids")
    except (OSError, ValueError) as exc:
        raise ValueError(
            f"the course's roster {path} is damaged ({exc}); restore it from a backup, or "
            f'write it again: a JSON list of the student ids, e.g. ["ann", "bob"]'
        ) from None
    return [str(s) for s in ids]


def write_roster(root, ids):
    from .files import write_atomic

    path = os.path.join(root, ".accelab", "roster.json")
    write_atomic(path, json.dumps(list(dict.fromkeys(ids)), indent=1))


def course_id_of(root):
    """The course id written in the course's nbgrader_config.py."""
    import re

    with open(os.path.join(root, "nbgrader_config.py")) as fh:
        m = re.search(r"course_id\s*=\s*['\"]([^'\"]+)['\"]", fh.read())
    return m.group(1) if m else "accelab"
