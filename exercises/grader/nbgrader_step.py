"""accelab's steps inside nbgrader, installed by the course's nbgrader_config.py.

* :class:`JudgeSubmission` takes the place of nbgrader's ``Execute`` in
  ``nbgrader autograde`` (and so in formgrader's autograde button): it runs the
  sanitized notebook in the sandbox (or takes the run ``accelab grade`` already
  made of the very same plan, handed to it in its configuration:
  :class:`PreparedRuns`), judges every answer against the submitter's key
  in this process, and writes outputs and verdicts into the notebook. nbgrader's
  own ``SaveAutoGrades`` then scores the test cells and writes the gradebook:
  after the sandbox is gone, from the grader's process.
* :class:`DropDuplicateIds` and :class:`RestoreCellRoles` mend what nbgrader's
  sanitizing steps leave to break a whole submission (a copied cell, forged
  cell metadata): such a change costs only the cells it touches.
  :class:`QuoteStudentText` keeps a student's HTML out of the pages the
  instructor opens.
* :class:`CleanFeedback` makes feedback show error messages without tracebacks.
"""

import json
import os
import re
import threading

import nbformat
from nbgrader.preprocessors import NbGraderPreprocessor
from traitlets import Bool, Float, Instance, Integer

from ..files import fault, write_atomic
from ..nbgrader_course import roster_ids
from ..notebook import read_spec
from .construction import records_of
from .intake import notes_of, submissions
from .key import key_for
from .outcome import judge_run, shown_ids, write_notebook
from .plan import fingerprint, plan_of
from .schema_once import check_schemas_once
from .shared_engine import share_engines
from .state import outcome_path, submission_hash
from .stop import HALT, Interruptible, Stopped
from .supervisor import Limits, run_plan

# nbgrader checks its metadata schema once per process, not once per cell (.schema_once),
# and its gradebooks compile each query once per process (.shared_engine): set here, so
# that nbgrader's own autograde and formgrader (the course's config imports this) do too
check_schemas_once()
share_engines()

_KEYS = {}
_LOCK = threading.Lock()


class PreparedRuns:
    """The sandboxed runs one ``accelab grade`` made ahead of nbgrader's autograde,
    handed to :class:`JudgeSubmission` explicitly: through the configuration of
    the grading run's own nbgrader API (``JudgeSubmission.prepared``), never
    through a module's state. A run is keyed by the submission and the
    fingerprint of its plan, and taken once (a notebook that differs is run
    again). traitlets copies configuration values; this handle is shared, not
    copied."""

    def __init__(self):
        self._runs = {}
        self._lock = threading.Lock()

    def put(self, assignment, student, steps, run):
        with self._lock:
            self._runs[(assignment, student, fingerprint(steps))] = run

    def take(self, assignment, student, steps):
        """The run made of exactly this plan, or None."""
        with self._lock:
            return self._runs.pop((assignment, student, fingerprint(steps)), None)

    def clear(self):
        with self._lock:
            self._runs.clear()

    def __len__(self):
        with self._lock:
            return len(self._runs)

    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self


def cached_key(spec, student):
    """The key of ``student``, computed once per grading process."""
    token = (json.dumps(spec, sort_keys=True), student)
    with _LOCK:
        if token in _KEYS:
            return _KEYS[token]
    key = key_for(spec, student)
    with _LOCK:
        _KEYS[token] = key
    return key


def other_keys(spec, course_dir, me):
    """Keys of the other students of the course (roster and submitters) and of
    the self-study variant, to tell whose values a wrong answer holds."""
    roster = roster_ids(course_dir)
    ids = {"self-study", *roster}
    for assignment in (spec.get("assignment"),) if isinstance(spec, dict) else ():
        ids.update(submissions(course_dir, str(assignment), roster)[0])
    ids.discard(me)
    return {s: cached_key(spec, s) for s in sorted(ids)}


def limits_of(step):
    return Limits(
        cell_seconds=step.cell_timeout,
        total_seconds=step.time_limit,
        cpu_seconds=int(step.time_limit) + 5,
        memory_bytes=step.memory_mb << 20,
        processes=step.processes,
    )


#: the largest submitted notebook the grader reads [MB]: a released notebook is well
#: under 1 MB and a worked one with its figures a few MB; a larger file is not read
#: (parsed, it would take several times its size of the grader's memory)
MAX_NOTEBOOK_MB = 50


class NotebookTooLarge(ValueError):
    """A submitted notebook larger than :data:`MAX_NOTEBOOK_MB`."""


class NotebookUnreadable(ValueError):
    """A submission that is no notebook the grader reads; its message says why
    without quoting the file (which may be any file a link pointed to)."""


def read_submission(path):
    """A submitted notebook: a regular file of at most MAX_NOTEBOOK_MB in the
    notebook format.

    Raises FileNotFoundError, NotebookTooLarge or NotebookUnreadable, each with
    a message for the student that quotes nothing of the file.
    """
    if os.path.islink(path):
        raise NotebookUnreadable(
            "the notebook cannot be read: it is a link to another file, not a notebook"
        )
    size = os.path.getsize(path) / 1e6
    if size > MAX_NOTEBOOK_MB:
        raise NotebookTooLarge(
            f"the notebook is {size:.0f} MB, more than the {MAX_NOTEBOOK_MB} MB the grader "
            f"reads; clear its outputs (Kernel > Restart Kernel and Clear All Outputs), save "
            f"it and submit again"
        )
    try:
        return nbformat.read(path, as_version=4)
    except UnicodeDecodeError:
        why = "it is not text in UTF-8, as a notebook is"
    except nbformat.reader.NotJSONError:
        why = "it is not a JSON file, as a notebook saved by Jupyter is"
    except RecursionError:
        why = "it is nested too deeply to be a notebook"
    except (nbformat.ValidationError, ValueError, KeyError, TypeError, AttributeError):
        why = "it does not follow the notebook format"
    raise NotebookUnreadable(f"the notebook cannot be read: {why}")


def submitted_notebook(course_dir, assignment, student, notebook):
    path = os.path.join(course_dir, "submitted", student, assignment, f"{notebook}.ipynb")
    try:
        return read_submission(path)
    except Exception:  # noqa: BLE001 - only its shown ids are read from it: none then
        return None


class JudgeSubmission(NbGraderPreprocessor):
    """Run in the sandbox, judge outside it (in place of nbgrader's Execute)."""

    cell_timeout = Float(10.0, help="Seconds one cell may run [s]").tag(config=True)
    time_limit = Float(
        60.0, help="Seconds the whole submission may run, restarts included [s]"
    ).tag(config=True)
    memory_mb = Integer(1536, help="Address space of each process [MiB]").tag(config=True)
    processes = Integer(64, help="Processes the submission may have").tag(config=True)
    unsafe_no_sandbox = Bool(
        False,
        help="Run submissions without a sandbox: a submission can "
        "then read the course (keys, hidden tests, gradebook) and change "
        "other students' grades",
    ).tag(config=True)
    prepared = Instance(
        PreparedRuns,
        allow_none=True,
        help="The runs accelab grade made ahead of this step (set by accelab grade for its "
        "own autograde calls; none in nbgrader's own commands)",
    ).tag(config=True)

    def preprocess(self, nb, resources):
        info = resources["nbgrader"]
        student, assignment = info["student"], info["assignment"]
        course_dir = os.path.abspath(self.config.CourseDirectory.root or ".")
        spec = read_spec(course_dir, assignment)
        steps = plan_of(nb)
        run = self.prepared.take(assignment, student, steps) if self.prepared is not None else None
        key = cached_key(spec, student)
        if run is None:
            run = run_plan(
                steps, key.variant.statement(), command_for(self.unsafe_no_sandbox), limits_of(self)
            )
            if HALT.is_set():  # cut short by Ctrl-C: no grade, and nbgrader keeps nothing
                raise Stopped(f"grading of {student} was stopped")
        submitted = submitted_notebook(
            course_dir, assignment, student, info.get("notebook", assignment)
        )
        shown = shown_ids(submitted) if submitted is not None else []
        records = records_of(submitted) if submitted is not None else {}
        outcome = judge_run(key, steps, run, other_keys(spec, course_dir, student), shown, records)
        outcome.notes += notes_of(course_dir, assignment, student)  # who and when
        write_notebook(nb, steps, run, outcome)
        digest = submission_hash(course_dir, assignment, student)
        save_outcome(course_dir, assignment, outcome, digest)
        fault("outcome-saved")
        return nb, resources


def command_for(unsafe):
    """The sandbox command builder, or the explicitly unsafe one; either starts
    no sandbox once grading is stopping (:class:`~.stop.Interruptible`)."""
    from .sandbox import sandbox

    if unsafe:
        from .unsandboxed import UnsandboxedCommand

        return Interruptible(UnsandboxedCommand())
    return Interruptible(sandbox())


def save_outcome(course_dir, assignment, outcome, digest=None):
    """Write the outcome (replaced whole), with ``digest``, the content hash of
    the submission it judged (:func:`~.state.content_hash`)."""
    data = outcome.to_dict()
    data["submission"] = digest
    write_atomic(
        outcome_path(course_dir, assignment, outcome.student),
        json.dumps(data, indent=1),
        stage="outcome",
    )


class DropDuplicateIds(NbGraderPreprocessor):
    """nbgrader's DeduplicateIds, mended: of cells that share a grade id the last
    one keeps it, and the others lose their nbgrader metadata entirely (nbgrader
    0.9 leaves an empty dict, on which its OverwriteCells fails with a
    KeyError and the whole submission is lost)."""

    def preprocess(self, nb, resources):
        seen = set()
        for cell in reversed(nb.cells):
            meta = cell.get("metadata", {})
            gid = meta.get("nbgrader", {}).get("grade_id") if "nbgrader" in meta else None
            if "nbgrader" in meta and not gid:
                del meta["nbgrader"]
            elif gid in seen:
                del meta["nbgrader"]
                meta.pop("deletable", None)
                meta.pop("editable", None)
            elif gid:
                seen.add(gid)
        return nb, resources


class RestoreCellRoles(NbGraderPreprocessor):
    """Every cell's nbgrader role as the instructor's source has it, whatever the
    submission's metadata says: grade, solution, task and locked flags and the
    points of each grade cell the gradebook knows; a cell with a grade id the
    gradebook does not know (or none) loses its nbgrader metadata.

    nbgrader's OverwriteCells restores a locked cell's source, type and points,
    but not its grade and solution flags: a test cell a student marked as a
    solution then fails its checksum check and the whole submission is lost
    ("Inconsistent checksums"); a cell a student invented keeps ``grade: true``
    without an id. Run before OverwriteCells, this leaves nothing for either.
    """

    def preprocess(self, nb, resources):
        from nbgrader.api import Gradebook

        info = resources["nbgrader"]
        with Gradebook(info["db_url"]) as gb:
            source = gb.find_notebook(info["notebook"], info["assignment"])
            locked = {c.name: bool(c.locked) for c in source.source_cells}
            points = {c.name: float(c.max_score) for c in source.grade_cells}
            solution = {c.name for c in source.solution_cells}
            task = {c.name for c in source.task_cells}
        for cell in nb.cells:
            meta = cell.get("metadata", {})
            if "nbgrader" not in meta:
                continue
            gid = meta["nbgrader"].get("grade_id")
            if gid not in locked:
                del meta["nbgrader"]
                continue
            role = {
                k: v
                for k, v in meta["nbgrader"].items()
                if k in ("grade_id", "schema_version", "checksum", "cell_type")
            }
            role.update(
                grade=gid in points, solution=gid in solution, task=gid in task, locked=locked[gid]
            )
            if gid in points:
                role["points"] = points[gid]
            meta["nbgrader"] = role
        return nb, resources


class QuoteStudentText(NbGraderPreprocessor):
    """What a student wrote outside code is shown as text, never as HTML.

    nbgrader's feedback and formgrader pages render markdown with raw HTML and
    ``javascript:`` links as they are, and raw cells as HTML: a ``<script>`` in a
    submission would run in the instructor's formgrader, with the instructor's
    rights over every grade. Every markdown or raw cell that is not a locked cell
    of the source (whose text OverwriteCells has put back) becomes a fenced text
    block: shown letter for letter, with nothing in it parsed or run.
    """

    def preprocess_cell(self, cell, resources, index):
        if cell.cell_type in ("markdown", "raw") and not cell.metadata.get("nbgrader", {}).get(
            "locked"
        ):
            text = cell.source
            longest = max((len(run) for run in re.findall(r"~+", text)), default=0)
            fence = "~" * max(3, longest + 1)
            cell.source = f"{fence}text\n{text}\n{fence}"
            if cell.cell_type == "raw":
                cell.cell_type = "markdown"
                cell.metadata.pop("raw_mimetype", None)
                cell.metadata.pop("format", None)
        return cell, resources


def sanitize_steps():
    """nbgrader's sanitizing steps as accelab runs them, in order: the same in
    ``accelab grade`` and in the course's nbgrader_config.py."""
    from nbgrader.preprocessors import (
        CheckCellMetadata,
        ClearOutput,
        OverwriteCells,
        OverwriteKernelspec,
    )

    return [
        ClearOutput,
        DropDuplicateIds,
        RestoreCellRoles,
        OverwriteKernelspec,
        OverwriteCells,
        QuoteStudentText,
        CheckCellMetadata,
    ]


class CleanFeedback(NbGraderPreprocessor):
    """Feedback only: every error shown as its message, without a traceback."""

    def preprocess_cell(self, cell, resources, index):
        if cell.cell_type == "code":
            for out in cell.get("outputs", []):
                if out.get("output_type") == "error":
                    out["traceback"] = [f"{out.get('ename')}: {out.get('evalue')}"]
        return cell, resources
