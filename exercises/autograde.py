"""``accelab grade``: autograde every submission in parallel processes (with a
progress bar), then generate feedback, then export a per-question CSV.

Each submission is graded by its own ``nbgrader autograde`` process, so a
student's crash, endless loop (cut by the per-cell timeout) or damaged notebook
costs that student only. Before grading, each submission is compared with the
released notebook: deleted or altered test cells and missing answer cells are
reported (nbgrader puts deleted test cells back as failing cells, restores
altered ones, and scores them as usual). Grading again gives the same grades.
"""

import csv
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import nbformat

from .course import course_id_of, gradebook, nbgrader

LOCK_RETRIES = 4


@dataclass
class Outcome:
    student: str
    ok: bool
    seconds: float
    problems: list = field(default_factory=list)   # damage found in the submission
    error: str = ""


def students_of(course_dir, assignment):
    root = os.path.join(course_dir, "submitted")
    if not os.path.isdir(root):
        return []
    return sorted(s for s in os.listdir(root)
                  if os.path.isdir(os.path.join(root, s, assignment)))


def _cells(nb):
    return {c.metadata.get("nbgrader", {}).get("grade_id"): c for c in nb.cells
            if c.metadata.get("nbgrader", {}).get("grade_id")}


def inspect_submission(course_dir, assignment, student):
    """What is wrong with a submission's notebook, as a list of messages."""
    release = os.path.join(course_dir, "release", assignment, f"{assignment}.ipynb")
    path = os.path.join(course_dir, "submitted", student, assignment, f"{assignment}.ipynb")
    if not os.path.exists(path):
        return [f"no {assignment}.ipynb in the submission"]
    try:
        nb = nbformat.read(path, as_version=4)
    except Exception as exc:
        return [f"the notebook cannot be read ({type(exc).__name__}: {exc})"]
    if not os.path.exists(release):
        return []
    ref = _cells(nbformat.read(release, as_version=4))
    got = _cells(nb)
    problems = []
    for gid, cell in ref.items():
        meta = cell.metadata["nbgrader"]
        if gid not in got:
            what = "test cell" if meta.get("grade") else (
                "answer cell" if meta.get("solution") else "locked cell")
            problems.append(f"{what} {gid} was deleted")
        elif meta.get("locked") and got[gid].source.strip() != cell.source.strip():
            problems.append(f"locked cell {gid} was altered (restored before grading)")
    return problems


def _autograde_one(course_dir, assignment, student):
    start = time.monotonic()
    for attempt in range(LOCK_RETRIES + 1):
        proc = nbgrader(course_dir, "autograde", assignment, "--student", student, "--force",
                        check=False)
        if proc.returncode == 0:
            return True, time.monotonic() - start, ""
        if "database is locked" not in proc.stderr or attempt == LOCK_RETRIES:
            break
        time.sleep(0.5 * (attempt + 1))
    tail = [line for line in proc.stderr.splitlines() if "ERROR" in line or "Error" in line]
    return False, time.monotonic() - start, (tail[-1] if tail else proc.stderr[-300:]).strip()


def progress(done, total, width=30, stream=None):
    stream = stream or sys.stderr
    filled = int(width * done / max(total, 1))
    stream.write(f"\rautograding [{'#' * filled}{'.' * (width - filled)}] {done}/{total}")
    if done == total:
        stream.write("\n")
    stream.flush()


def autograde_all(course_dir, assignment, jobs=2, show_progress=True, students=None):
    """Autograde each submission in its own process, ``jobs`` at a time."""
    course_dir = os.path.abspath(course_dir)
    students = students or students_of(course_dir, assignment)
    outcomes = {s: Outcome(s, False, 0.0, inspect_submission(course_dir, assignment, s))
                for s in students}
    done = 0
    if show_progress:
        progress(0, len(students))
    with ThreadPoolExecutor(max_workers=max(1, int(jobs))) as pool:
        futures = {pool.submit(_autograde_one, course_dir, assignment, s): s for s in students}
        from concurrent.futures import as_completed
        for fut in as_completed(futures):
            s = futures[fut]
            ok, seconds, error = fut.result()
            outcomes[s].ok, outcomes[s].seconds, outcomes[s].error = ok, seconds, error
            done += 1
            if show_progress:
                progress(done, len(students))
    return [outcomes[s] for s in students]


def feedback(course_dir, assignment):
    nbgrader(os.path.abspath(course_dir), "generate_feedback", assignment, "--force")


def question_names(course_dir, assignment):
    """Graded quantity names, in notebook order (from the released notebook)."""
    path = os.path.join(course_dir, "release", assignment, f"{assignment}.ipynb")
    nb = nbformat.read(path, as_version=4)
    return [gid[len("test_"):] for gid, c in _cells(nb).items()
            if c.metadata["nbgrader"].get("grade") and gid.startswith("test_")]


def scores(course_dir, assignment, students=None):
    """Per student: {question: score} from the gradebook (score 0 where a cell
    needed manual grading: accelab never leaves a grade to manual review)."""
    names = question_names(course_dir, assignment)
    out = {}
    with gradebook(course_dir, course_id_of(course_dir)) as gb:
        for s in students or students_of(course_dir, assignment):
            try:
                sub = gb.find_submission(assignment, s)
            except Exception:
                continue
            row = {n: 0.0 for n in names}
            manual = []
            for nb in sub.notebooks:
                for g in nb.grades:
                    name = g.name[len("test_"):] if g.name.startswith("test_") else g.name
                    if g.needs_manual_grade:
                        manual.append(name)
                    if name in row:
                        row[name] = float(g.score or 0.0)
            out[s] = (row, manual)
    return names, out


def export_csv(course_dir, assignment, outcomes, path=None):
    """Write the per-question CSV; returns (path, rows)."""
    course_dir = os.path.abspath(course_dir)
    path = path or os.path.join(course_dir, f"grades_{assignment}.csv")
    names, table = scores(course_dir, assignment, [o.student for o in outcomes])
    rows = []
    for o in outcomes:
        row, manual = table.get(o.student, ({n: 0.0 for n in names}, []))
        notes = list(o.problems)
        if not o.ok:
            notes.append(f"autograde failed: {o.error}")
        if manual:
            notes.append("flagged for manual grading by nbgrader: " + ", ".join(manual))
        rows.append({"student": o.student, **row, "total": sum(row.values()),
                     "max": float(len(names)), "notes": "; ".join(notes)})
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=["student", *names, "total", "max", "notes"])
        w.writeheader()
        w.writerows(rows)
    return path, rows


def format_table(rows, names):
    """The grade table as text: one line per student."""
    short = {n: n for n in names}
    head = f"{'student':<12} " + " ".join(f"{short[n][:11]:>11}" for n in names) + \
        f" {'total':>7}  notes"
    lines = [head, "-" * len(head)]
    for r in rows:
        lines.append(f"{r['student']:<12} " + " ".join(f"{r[n]:>11g}" for n in names)
                     + f" {r['total']:>4g}/{r['max']:g}  {r['notes']}")
    return "\n".join(lines)


def grade(course_dir, assignment, jobs=2, show_progress=True, csv_path=None):
    """The whole job: autograde, feedback, CSV. Returns (outcomes, csv path, rows, seconds)."""
    start = time.monotonic()
    outcomes = autograde_all(course_dir, assignment, jobs, show_progress)
    if any(o.ok for o in outcomes):
        feedback(course_dir, assignment)
    path, rows = export_csv(course_dir, assignment, outcomes, csv_path)
    return outcomes, path, rows, time.monotonic() - start
