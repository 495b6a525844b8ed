"""``accelab assign``: write an assignment's source notebook into a course and,
optionally, run nbgrader's generate_assignment and release_assignment.

Before anything is written, every student on the roster gets their variant
drawn (a student with no valid problem stops the command with the reason). An
assignment that already has submissions is not changed unless ``force`` is
given: new settings would silently regrade everyone against new values. With
``force`` the old settings are kept in ``.accelab/replaced/<A>-<time>.json`` and
the changes are reported.
"""

import datetime
import json
import os
import shutil

from .assignment import DEFAULT_ANGLE_TOLERANCE, build_variant, make_spec
from .families.common import GenerationError
from .layout import prepare as prepare_layout
from .nbgrader_course import (
    course_id_of,
    create_course,
    ensure_path,
    gradebook,
    nbgrader,
    roster_ids,
)
from .notebook import write_source
from .silence import silenced

DEFAULT_FAMILIES = ["rotation", "fourbar", "tolerance"]


class AssignError(ValueError):
    """The assignment cannot be written as asked; the message says why and what to do."""


def submissions_of(course_dir, assignment):
    """Students with a submission (collected or autograded) of ``assignment``."""
    found = set()
    for step in ("submitted", "autograded"):
        root = os.path.join(course_dir, step)
        if os.path.isdir(root):
            found.update(
                s for s in os.listdir(root) if os.path.isdir(os.path.join(root, s, assignment))
            )
    return sorted(found)


def check_roster(spec, students):
    """Draw every student's variant; AssignError naming the first that fails."""
    for student in students:
        try:
            with silenced():
                build_variant(spec, student)
        except (GenerationError, ValueError) as exc:
            raise AssignError(f"student {student!r} gets no valid problem: {exc}") from None


def changes(old, new):
    """The settings that differ between two specs, in words."""
    out = []
    for k in sorted(set(old) | set(new)):
        if old.get(k) != new.get(k):
            out.append(f"{k}: {json.dumps(old.get(k))} -> {json.dumps(new.get(k))}")
    return out


def assign(
    course_dir,
    assignment,
    families=None,
    units="US",
    tolerance=0.01,
    ranges=None,
    roster=(),
    course_id=None,
    generate=True,
    release=False,
    timeout=10,
    title=None,
    angle_tolerance=DEFAULT_ANGLE_TOLERANCE,
    due=None,
    force=False,
    time_limit=60,
    say=print,
    exchange=None,
):
    """Create the assignment; returns the source notebook path.

    The course folder is made private to the instructor and the exchange
    (``exchange``, for a new course; default a folder ``exchange`` beside the
    course) laid out as nbgrader expects, before anything is written
    (:func:`accelab.exercises.layout.prepare`)."""
    if os.path.exists(os.path.join(course_dir, "nbgrader_config.py")):
        course_id = course_id or course_id_of(course_dir)
    course_id = course_id or "accelab"
    spec = make_spec(
        course_id,
        assignment,
        families or DEFAULT_FAMILIES,
        units,
        tolerance,
        ranges,
        angle_tolerance,
    )
    ids = [str(s["id"] if isinstance(s, dict) else s) for s in roster]
    if os.path.isdir(course_dir):
        ids = list(dict.fromkeys([*roster_ids(course_dir), *ids]))
    check_roster(spec, ["preview", *ids])
    spec_path = os.path.join(course_dir, "source", assignment, "accelab.json")
    taken = submissions_of(course_dir, assignment) if os.path.isdir(course_dir) else []
    if os.path.exists(spec_path):
        with open(spec_path) as fh:
            old = json.load(fh)
        diff = changes(old, spec)
        if taken and not force:
            raise AssignError(
                f"assignment {assignment!r} already has {len(taken)} submission(s) "
                f"({', '.join(taken[:5])}{', ...' if len(taken) > 5 else ''}); writing it again "
                "would regrade them against new values"
                + (f" ({'; '.join(diff)})" if diff else "")
                + ". Use another assignment name, or --force to replace it anyway (the old "
                "settings are kept)."
            )
        if taken:
            stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
            keep = os.path.join(course_dir, ".accelab", "replaced", f"{assignment}-{stamp}.json")
            os.makedirs(os.path.dirname(keep), exist_ok=True)
            shutil.copy2(spec_path, keep)
            say(
                f"replacing assignment {assignment!r} with {len(taken)} submission(s); old "
                f"settings kept in {keep}; changes: {'; '.join(diff) or 'none'}"
            )
    exchange = prepare_layout(course_dir, course_id, exchange, accounts_of(roster, ids), say)
    create_course(
        course_dir, course_id, roster, timeout=timeout, time_limit=time_limit, exchange=exchange
    )
    path = write_source(course_dir, spec, title)
    if due is not None:
        set_due(course_dir, course_id, assignment, due)
    if generate or release:
        nbgrader(course_dir, "generate_assignment", assignment, "--force")
    if release:
        nbgrader(course_dir, "release_assignment", assignment, "--force")
    return path


def accounts_of(roster, ids):
    """The account names of a roster's students (an ``account`` column, else the id)."""
    names = [str(r.get("account") or r["id"]) for r in roster if isinstance(r, dict)]
    return list(dict.fromkeys([*names, *ids]))


def set_due(course_dir, course_id, assignment, due):
    """Record the due date (``"2026-12-01 17:00"``, UTC unless it says) in the
    gradebook, where nbgrader's late-submission policy reads it."""
    try:
        when = datetime.datetime.fromisoformat(str(due))
    except ValueError:
        raise AssignError(
            f"due date {due!r} is not a date and time like '2026-12-01 17:00'"
        ) from None
    if when.tzinfo is not None:
        when = when.astimezone(datetime.timezone.utc).replace(tzinfo=None)
    ensure_path()
    with gradebook(course_dir, course_id) as gb:
        gb.update_or_create_assignment(assignment, duedate=when)
