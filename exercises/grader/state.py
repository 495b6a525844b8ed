"""What became of each submission: which handed-in files (by content) were
graded, and how far.

One small record per submission, ``COURSE/.accelab/state/<A>/<student>.json``,
replaced whole at each step:

* ``grading``: a grading of these files began and has not ended; nothing of it
  counts as a grade (a kill, a full disk or Ctrl-C stopped it);
* ``scored``: the gradebook, the autograded notebook and the outcome are
  written; the feedback page is not yet;
* ``done``: the feedback page too;
* ``failed``: it could not be graded for a reason that is not the student's
  (``problem`` says which); nothing of it counts as a grade.

The files are compared by their content (a SHA-256 over the names and bytes of
everything in ``submitted/<student>/<A>/``), never by their times: nbgrader's
``collect --update`` keeps a resubmission's submit-time mtime.
"""

import hashlib
import json
import os
import stat

from ..files import write_atomic

STAGES = ("grading", "scored", "done", "failed")
#: folders of a submission that are no part of what was handed in
SKIP = {".ipynb_checkpoints", "__pycache__"}


def content_hash(folder):
    """SHA-256 of the names, kinds and bytes of everything under ``folder``
    (links are not followed; a link counts by where it points). None if the
    folder does not exist."""
    if not os.path.isdir(folder):
        return None
    digest = hashlib.sha256()
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if d not in SKIP)
        links = [d for d in dirs if os.path.islink(os.path.join(root, d))]
        for name in sorted(files + links):
            path = os.path.join(root, name)
            rel = os.path.relpath(path, folder)
            try:
                info = os.lstat(path)
            except OSError:
                continue
            digest.update(rel.encode("utf-8", "surrogateescape") + b"\0")
            if stat.S_ISLNK(info.st_mode):
                digest.update(b"link\0" + os.fsencode(os.readlink(path)) + b"\0")
            elif stat.S_ISREG(info.st_mode):
                digest.update(b"file\0")
                _add_file(digest, path)
            else:  # a device, pipe or socket is never opened
                digest.update(b"special\0")
    return digest.hexdigest()


def _add_file(digest, path):
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        digest.update(b"unreadable\0")
        return
    with os.fdopen(fd, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            digest.update(block)
    digest.update(b"\0")


def submission_folder(course_dir, assignment, student):
    return os.path.join(course_dir, "submitted", student, assignment)


def submission_hash(course_dir, assignment, student):
    return content_hash(submission_folder(course_dir, assignment, student))


def state_path(course_dir, assignment, student):
    return os.path.join(course_dir, ".accelab", "state", assignment, f"{student}.json")


def read_state(course_dir, assignment, student):
    """The record of ``student``'s submission, or None (none yet, or damaged:
    either way it is graded again)."""
    try:
        with open(state_path(course_dir, assignment, student), encoding="utf-8") as fh:
            data = json.load(fh)
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("stage") not in STAGES:
        return None
    return data


def write_state(course_dir, assignment, student, digest, stage, problem=""):
    """Record that ``student``'s files of content ``digest`` reached ``stage``."""
    assert stage in STAGES, stage
    record = {"hash": digest, "stage": stage}
    if problem:
        record["problem"] = problem
    write_atomic(
        state_path(course_dir, assignment, student),
        json.dumps(record, indent=1),
        stage=f"state-{stage}",
        durable=False,  # a record lost to a power cut is read as none: graded again
    )


def outcome_path(course_dir, assignment, student):
    """Where the grader keeps a submission's outcome (notes, verdicts): in the
    course folder, which no sandbox sees, and never released."""
    return os.path.join(course_dir, ".accelab", "outcomes", assignment, f"{student}.json")


class DamagedRecord(ValueError):
    """A grading record of the course that cannot be read."""


def read_outcome(course_dir, assignment, student):
    """The outcome of ``student``'s grading (a dict), or None if there is none.
    Raises :class:`DamagedRecord` if the file is there but cannot be read."""
    path = outcome_path(course_dir, assignment, student)
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as fh:
            data = json.load(fh)
        if not isinstance(data, dict) or not isinstance(data.get("notes", []), list):
            raise ValueError("not an outcome")
    except (OSError, ValueError) as exc:
        raise DamagedRecord(f"its outcome file {path} is damaged ({exc})") from None
    return data


def grading_status(course_dir, assignment, student, digest=None):
    """Whether ``student``'s submission, as it is now, is graded: (outcome or
    None, note). A grading that began and did not end, failed, or judged other
    files than those now submitted is not a grade."""
    digest = digest or submission_hash(course_dir, assignment, student)
    again = "grade it with: accelab grade --new"
    record = read_state(course_dir, assignment, student)
    if record is not None and record.get("hash") == digest:
        if record["stage"] == "grading":
            return None, f"not graded yet: its grading was interrupted; {again}"
        if record["stage"] == "failed":
            return None, f"not graded: {record.get('problem') or 'it could not be graded'}"
    try:
        outcome = read_outcome(course_dir, assignment, student)
    except DamagedRecord as exc:
        return None, f"not graded: {exc}; {again}"
    if outcome is None:
        return None, f"not graded yet; {again}"
    if outcome.get("submission") != digest:
        return None, f"not graded yet: handed in again since it was graded; {again}"
    if record is not None and record.get("hash") == digest and record["stage"] == "scored":
        return outcome, "its feedback page is not written yet (accelab grade --new writes it)"
    return outcome, ""


def to_do(course_dir, assignment, student, digest=None):
    """What ``accelab grade --new`` still has to do for ``student``: "grade"
    (not graded completely, or changed since), "feedback" (graded, its feedback
    page missing) or "" (nothing)."""
    digest = digest or submission_hash(course_dir, assignment, student)
    record = read_state(course_dir, assignment, student)
    if record is None or record.get("hash") != digest:
        return "grade"
    if record["stage"] not in ("scored", "done"):
        return "grade"
    outcome, _ = grading_status(course_dir, assignment, student, digest)
    if outcome is None:
        return "grade"
    page = os.path.join(course_dir, "feedback", student, assignment, f"{assignment}.html")
    return "" if record["stage"] == "done" and os.path.exists(page) else "feedback"
