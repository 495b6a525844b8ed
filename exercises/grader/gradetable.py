"""The grade table: one row per student on the roster and per submitter, one
column per question, read from nbgrader's gradebook (the only record of
scores), with the late penalty applied as nbgrader's policy set it, and notes
from the grading (whose values a notebook showed, cells that failed, damage).
"""

import csv
import io
import os
import warnings

import nbformat

from ..files import write_atomic
from ..nbgrader_course import course_id_of, gradebook, roster_ids
from . import intake
from .nbgrader_step import read_submission
from .plan import TEST_PREFIX
from .state import grading_status


def question_names(course_dir, assignment):
    """Graded quantity names, in notebook order (from the released notebook)."""
    path = os.path.join(course_dir, "release", assignment, f"{assignment}.ipynb")
    try:
        nb = nbformat.read(path, as_version=4)
    except FileNotFoundError:
        raise
    except Exception as exc:  # noqa: BLE001 - any damage of the file: said with its name
        raise ValueError(
            f"the released notebook {path} cannot be read ({type(exc).__name__}); make it "
            f"again with: nbgrader generate_assignment {assignment} --force (in the course "
            f"folder)"
        ) from None
    names = []
    for cell in nb.cells:
        meta = cell.metadata.get("nbgrader", {})
        gid = meta.get("grade_id", "")
        if meta.get("grade") and gid.startswith(TEST_PREFIX):
            names.append(gid[len(TEST_PREFIX) :])
    return names


def damage(course_dir, assignment, student):
    """What the student changed in cells they may not change, as notes."""
    release = os.path.join(course_dir, "release", assignment, f"{assignment}.ipynb")
    path = os.path.join(course_dir, "submitted", student, assignment, f"{assignment}.ipynb")
    try:
        nb = read_submission(path)
        ref = nbformat.read(release, as_version=4)
    except Exception:  # noqa: BLE001 - a notebook that cannot be read has its own note
        return []
    seen, notes, forged = {}, [], []
    for cell in nb.cells:
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
        if gid:
            seen[gid] = seen.get(gid, 0) + 1
    for gid, count in seen.items():
        if count > 1:
            notes.append(f"cell {gid} appears {count} times (the last one was graded)")
    got = {c.metadata.get("nbgrader", {}).get("grade_id"): c for c in nb.cells}
    for cell in ref.cells:
        meta = cell.metadata.get("nbgrader", {})
        gid = meta.get("grade_id")
        if not gid:
            continue
        if gid not in got:
            what = (
                "test cell"
                if meta.get("grade")
                else ("answer cell" if meta.get("solution") else "locked cell")
            )
            notes.append(
                f"{what} {gid} was deleted"
                + (" (put back and graded)" if meta.get("grade") else "")
            )
        elif meta.get("locked") and got[gid].source.strip() != cell.source.strip():
            notes.append(f"locked cell {gid} was altered (restored before grading)")
        elif _role(got[gid]) != _role(cell):
            forged.append(gid)
    if forged:
        notes.append(
            f"the nbgrader metadata of {len(forged)} cell(s) was changed ("
            f"{', '.join(forged[:3])}{', ...' if len(forged) > 3 else ''}; restored "
            f"before grading)"
        )
    known = {c.metadata.get("nbgrader", {}).get("grade_id") for c in ref.cells}
    invented = sorted(g for g in seen if g not in known)
    if invented:
        notes.append(
            f"cells with grade ids the assignment does not have: "
            f"{', '.join(invented[:5])} (not graded)"
        )
    return notes


def _role(cell):
    """A cell's nbgrader role: what it is graded as, and for how many points."""
    meta = cell.metadata.get("nbgrader", {})
    return (
        cell.cell_type,
        bool(meta.get("grade")),
        bool(meta.get("solution")),
        bool(meta.get("locked")),
        float(meta.get("points", 0) or 0),
    )


def rows_of(course_dir, assignment):
    """The table rows (dicts), roster first, then other submitters."""
    names = question_names(course_dir, assignment)
    roster = roster_ids(course_dir)
    submitters, refused = intake.submissions(course_dir, assignment, roster)
    students = list(dict.fromkeys([*roster, *submitters]))
    rows = []
    with warnings.catch_warnings(), gradebook(course_dir, course_id_of(course_dir)) as gb:
        warnings.simplefilter("ignore")
        for student in students:
            row = {n: 0.0 for n in names}
            notes, penalty, graded = [], 0.0, True
            if student not in submitters:
                notes.append("no submission")
            else:
                if roster and student not in roster:
                    notes.append("not on the roster")
                try:
                    sub = gb.find_submission(assignment, student)
                except Exception:  # noqa: BLE001 - MissingEntry or worse: "not graded yet"
                    sub = None
                outcome, status = grading_status(course_dir, assignment, student)
                if sub is None and outcome is not None:
                    outcome, status = None, "not graded yet: not in the gradebook"
                if status:
                    notes.append(status)
                if outcome is None:  # never a number the grader cannot vouch for
                    row, graded = {n: None for n in names}, False
                else:
                    for nb in sub.notebooks:
                        for g in nb.grades:
                            name = (
                                g.name[len(TEST_PREFIX) :]
                                if g.name.startswith(TEST_PREFIX)
                                else g.name
                            )
                            if name in row:
                                row[name] = float(g.score or 0.0)
                    penalty = float(sub.late_submission_penalty or 0.0)
                    if penalty or float(sub.total_seconds_late or 0.0) > 0:  # under every policy
                        notes.append(
                            f"late by {_duration(sub.total_seconds_late)}"
                            + (f": penalty {penalty:g}" if penalty else ": no penalty")
                        )
                    notes += [str(n) for n in outcome.get("notes", [])]
                notes += [  # who and when (intake), said whether or not it is graded yet
                    n for n in intake.notes_of(course_dir, assignment, student) if n not in notes
                ]
                notes += damage(course_dir, assignment, student)
            score = sum(row.values()) if graded else None
            rows.append(
                {
                    "student": student,
                    **row,
                    "score": score,
                    "late_penalty": penalty if graded else None,
                    "total": max(0.0, score - penalty) if graded else None,
                    "max": float(len(names)),
                    "notes": "; ".join(notes),
                }
            )
    for folder, reason in refused:  # named safely; never graded, never in the gradebook
        rows.append(
            {
                "student": folder,
                **{n: 0.0 for n in names},
                "score": 0.0,
                "late_penalty": 0.0,
                "total": 0.0,
                "max": float(len(names)),
                "notes": f"not graded: the folder submitted/{folder}/ was refused: {reason}",
            }
        )
    return names, rows


def _duration(seconds):
    seconds = float(seconds or 0)
    if seconds >= 86400:
        return f"{seconds / 86400:.1f} days"
    if seconds >= 3600:
        return f"{seconds / 3600:.1f} hours"
    return f"{seconds / 60:.0f} minutes"


def csv_path_of(course_dir, assignment, path=None):
    """Where the CSV is written: ``path``, else ``grades_<assignment>.csv`` in the course."""
    return path or os.path.join(course_dir, f"grades_{assignment}.csv")


def export_csv(course_dir, assignment, path=None):
    """Write the CSV (replaced whole: a failed write keeps the old one); returns
    (path, rows). A submission that is not graded has empty score cells."""
    path = csv_path_of(course_dir, assignment, path)
    names, rows = rows_of(course_dir, assignment)
    text = io.StringIO(newline="")
    writer = csv.DictWriter(
        text, fieldnames=["student", *names, "score", "late_penalty", "total", "max", "notes"]
    )
    writer.writeheader()
    writer.writerows({k: _cell_text(v) for k, v in row.items()} for row in rows)
    write_atomic(path, text.getvalue(), stage="csv")
    return path, rows


def _cell_text(value):
    """A value as a spreadsheet reads it safely: text that a spreadsheet would take
    for a formula (a student id or a note from a submission may begin with "=")
    gets a leading apostrophe; numbers are written as they are."""
    if isinstance(value, str) and value[:1] in ("=", "+", "-", "@", "\t", "\r"):
        return "'" + value
    return "" if value is None else value


def format_table(rows, names):
    """The grade table as text: one line per student."""
    head = f"{'student':<12} " + " ".join(f"{n[:11]:>11}" for n in names) + f" {'total':>7}  notes"
    lines = [head, "-" * len(head)]
    for r in rows:
        total = "-" if r["total"] is None else f"{r['total']:g}"
        lines.append(
            f"{r['student']:<12} "
            + " ".join(f"{'-' if r[n] is None else format(r[n], 'g'):>11}" for n in names)
            + f" {total:>4}/{r['max']:g}  {r['notes']}"
        )
    return "\n".join(lines)
