"""``accelab assign``: write an assignment's source notebook into a course and,
optionally, run nbgrader's generate_assignment and release_assignment.

Before anything is written, every student on the roster gets their variant
drawn (a student with no valid problem stops the command with the reason). An
assignment that already has submissions is not changed unless ``force`` is
given: new settings would silently regrade everyone against new values. With
``force`` the old settings are kept in ``.accelab/replaced/<A>-<time>.json`` and
the changes are reported.

All or nothing: the assignment is built in a staging folder (a new course in a
folder beside it; an existing one in ``COURSE/.accelab/staging-*`` with a copy
of its gradebook), nbgrader's generate_assignment included, and swapped in only
when it is complete (:mod:`.staging`). On any failure the course is exactly as
it was.
"""

import datetime
import json
import os

from .assignment import DEFAULT_ANGLE_TOLERANCE, build_variant, make_spec
from .families.common import GenerationError
from .files import write_atomic
from .layout import prepare as prepare_layout
from .layout import private_course, upgrade_config
from .nbgrader_course import (
    check_ids,
    course_id_of,
    create_course,
    ensure_path,
    gradebook,
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
    """Create the assignment; returns the source notebook path. On any failure
    (AssignError, ValueError, OSError, RuntimeError) the course is as before.

    The course folder is private to the instructor and the exchange
    (``exchange``, for a new course; default a folder ``exchange`` beside the
    course) laid out as nbgrader expects (:func:`accelab.exercises.layout.prepare`):
    repaired before anything is built (a repair of permissions is kept whatever
    follows); an older configuration gets accelab's collect in the staged copy,
    swapped in with the rest."""
    from .grader.lock import course_lock
    from .staging import Staging, build_new_course

    course_dir = os.path.abspath(course_dir)
    exists = os.path.isdir(course_dir)
    if exists and os.path.exists(os.path.join(course_dir, "nbgrader_config.py")):
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
    when = due_date(due) if due is not None else None
    new_ids = [str(s["id"] if isinstance(s, dict) else s) for s in roster]
    check_ids([(f"roster entry {k}", sid) for k, sid in enumerate(new_ids, 1)])
    old_ids = roster_ids(course_dir) if exists else []
    _check_case_clashes(old_ids, new_ids)
    ids = list(dict.fromkeys([*old_ids, *new_ids]))
    check_roster(spec, ["preview", *ids])

    accounts = accounts_of(roster, ids)
    layout = {"exchange": exchange}
    upgraded = []  # said once the new version is in

    def build(root, nbgrader_run):
        """Everything of the assignment, written into ``root``."""
        config = os.path.join(course_dir, "nbgrader_config.py")
        upgrade_config(root, upgraded.append, named=config)  # an older course's (staged copy)
        create_course(
            root,
            course_id,
            roster,
            timeout=timeout,
            time_limit=time_limit,
            exchange=layout["exchange"],
        )
        path = write_source(root, spec, title)
        if when is not None:
            set_due(root, course_id, assignment, when)
        if generate or release:
            nbgrader_run("generate_assignment", assignment, "--force")
        return os.path.join(course_dir, os.path.relpath(path, root))

    if not exists:
        layout["exchange"] = prepare_layout(
            course_dir, course_id, exchange, accounts, say, new=True
        )
        path = build_new_course(course_dir, assignment, build, release)
        private_course(course_dir, accounts, say)  # built aside with mode 700
        return path
    with course_lock(course_dir, f"accelab assign --assignment {assignment}"):
        layout["exchange"] = prepare_layout(
            course_dir, course_id, exchange, accounts, say, upgrade=False
        )
        spec_path = os.path.join(course_dir, "source", assignment, "accelab.json")
        taken = submissions_of(course_dir, assignment)
        keep, diff = None, []
        if os.path.exists(spec_path):
            old = _read_old_spec(spec_path)
            diff = changes(old, spec) if old is not None else ["the old settings are damaged"]
            if taken and not force:
                raise AssignError(
                    f"assignment {assignment!r} already has {len(taken)} submission(s) "
                    f"({', '.join(taken[:5])}{', ...' if len(taken) > 5 else ''}); writing it "
                    "again would regrade them against new values"
                    + (f" ({'; '.join(diff)})" if diff else "")
                    + ". Use another assignment name, or --force to replace it anyway (the old "
                    "settings are kept)."
                )
            if taken:
                stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
                keep = os.path.join(
                    course_dir, ".accelab", "replaced", f"{assignment}-{stamp}.json"
                )
        with Staging(course_dir, assignment) as staging:
            path = staging.build(build, taken)
            if keep:
                with open(spec_path, "rb") as fh:
                    write_atomic(keep, fh.read())
            staging.swap(release)
        for message in upgraded:
            say(message)
        if keep:
            say(
                f"replaced assignment {assignment!r} with {len(taken)} submission(s); old "
                f"settings kept in {keep}; changes: {'; '.join(diff) or 'none'}"
            )
        return path


def accounts_of(roster, ids):
    """The account names of a roster's students (an ``account`` column, else the id)."""
    names = [str(r.get("account") or r["id"]) for r in roster if isinstance(r, dict)]
    return list(dict.fromkeys([*names, *ids]))


def _read_old_spec(path):
    try:
        with open(path, encoding="utf-8") as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


def _check_case_clashes(old_ids, new_ids):
    known = {sid.casefold(): sid for sid in old_ids}
    clashes = [
        f"{sid!r} (the course has {known[sid.casefold()]!r})"
        for sid in new_ids
        if sid.casefold() in known and known[sid.casefold()] != sid
    ]
    if clashes:
        raise AssignError(
            f"the roster has ids equal but for letter case to students the course already has: "
            f"{', '.join(clashes[:10])}; use the course's spelling of each id"
        )


def due_date(due):
    """The due date (``"2026-12-01 17:00"``, UTC unless it says) as a naive UTC datetime."""
    try:
        when = datetime.datetime.fromisoformat(str(due))
    except ValueError:
        raise AssignError(
            f"due date {due!r} is not a date and time like '2026-12-01 17:00'"
        ) from None
    if when.tzinfo is not None:
        when = when.astimezone(datetime.timezone.utc).replace(tzinfo=None)
    return when


def set_due(course_dir, course_id, assignment, due):
    """Record the due date (``"2026-12-01 17:00"``, UTC unless it says, or a
    datetime) in the gradebook, where nbgrader's late-submission policy reads it."""
    when = due if isinstance(due, datetime.datetime) else due_date(due)
    ensure_path()
    with gradebook(course_dir, course_id) as gb:
        gb.update_or_create_assignment(assignment, duedate=when)
