"""``accelab demo``: first one worked case from the solver (Example 7-1's
fourbar), then the instructor's main job end to end in ``build/demo-course``: a
course with a sample roster, one randomized assignment, simulated submissions
(right, wrong, wrong units, crashing, and one that copies another student's
values), grading in the sandbox, feedback, and the grade table.

The demo deletes its course folder only if the demo made it (a marker file
inside says so); any other existing folder is refused.
"""

import cmath
import math
import os
import shutil
import time

from .assign import assign
from .grader.grade import grade
from .grader.gradetable import format_table, question_names
from .notebook import read_spec
from .simulate import key_code, submit

#: the file that marks a folder as made by ``accelab demo``
MARKER = ".accelab-demo"


class DemoError(RuntimeError):
    """The demo cannot run as asked; the message says why."""


ROSTER = [
    {"id": "ada", "first_name": "Ada", "last_name": "Lovelace"},
    {"id": "ben", "first_name": "Ben", "last_name": "Franklin"},
    {"id": "cai", "first_name": "Cai", "last_name": "Lun"},
    {"id": "dee", "first_name": "Dee", "last_name": "Dee"},
    {"id": "eve", "first_name": "Eve", "last_name": "Curie"},
    {"id": "fay", "first_name": "Fay", "last_name": "Wray"},
    {"id": "gus", "first_name": "Gus", "last_name": "Grissom"},
]


def worked_case(out):
    """Print Example 7-1 (Norton): fourbar a=2, b=6, c=9, d=7 in, theta2=30 deg,
    omega2=10 rad/s, alpha2=-5 rad/s^2, open circuit, solved by accelab.solver.FourBar."""
    from accelab.solver import FourBar

    r = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2", circuit="open"
    )
    out("Worked case (Example 7-1): fourbar a=2 in, b=6 in, c=9 in, d=7 in, open circuit,")
    out("theta2 = 30 deg, omega2 = 10 rad/s, alpha2 = -5 rad/s^2")
    rows = [
        ("theta3", r.theta3.to("deg")),
        ("theta4", r.theta4.to("deg")),
        ("omega3", r.omega3.to("rad/s")),
        ("omega4", r.omega4.to("rad/s")),
        ("alpha3", r.alpha3.to("rad/s^2")),
        ("alpha4", r.alpha4.to("rad/s^2")),
    ]
    for name, q in rows:
        out(f"  {name:<8} {q.magnitude:>10.3f} {q.units:~P}")
    for name in ("A_A", "A_B", "A_BA"):
        z = getattr(r, name).to("in/s^2").magnitude
        out(f"  {name:<8} {abs(z):>10.2f} in/s^2 at {math.degrees(cmath.phase(z)):7.2f} deg")
    out("")


def build_submissions(course, assignment):
    """ada right; ben wrong (sign errors); cai wrong units (bare SI numbers where
    the statement asks for US units); dee's notebook crashes in its first
    answer; eve right, as Quantities in SI units; fay copies ada's answers and
    loads ada's values in her notebook."""
    spec = read_spec(course, assignment)

    def wrong(a, q):
        return None if a.kind == "choice" else f"{a.name} = Q_({-q.magnitude!r}, {a.unit!r})"

    def other_units(a, q):
        if a.kind == "choice":
            return None
        si = q.to_base_units()
        if a.kind == "angle":
            return f"{a.name} = Q_({q.to('rad').magnitude!r}, 'rad')"
        return f"{a.name} = Q_({si.magnitude!r}, {format(si.units, '~')!r})"

    def bare_si(a, q):
        if a.kind == "choice" or a.quantity_required:
            return None
        return f"{a.name} = {q.to_base_units().magnitude!r}"

    def crash(a, q):
        return "raise RuntimeError('my calculation broke')" if "A_A_x" in a.name else None

    plans = {"ada": None, "ben": wrong, "cai": bare_si, "dee": crash, "eve": other_units}
    for student, transform in plans.items():
        submit(course, assignment, student, key_code(spec, student, transform))

    def load_ada(nb):
        from nbformat.v4 import new_code_cell

        nb.cells.insert(2, new_code_cell("v = load_variant(SPEC, 'ada')"))

    submit(course, assignment, "fay", key_code(spec, "ada"), edit=load_ada)
    plans["fay"] = "copy"
    return plans


def run_demo(course="build/demo-course", assignment="A", jobs=2, out=print, fresh=True):
    worked_case(out)
    if os.path.exists(course):
        if not os.path.exists(os.path.join(course, MARKER)):
            raise DemoError(
                f"{course} exists and was not made by accelab demo: choose another "
                "--course folder (the demo never deletes a folder it did not make)"
            )
        if fresh:
            shutil.rmtree(course)
    os.makedirs(course, mode=0o700, exist_ok=True)  # a course folder is the instructor's alone
    with open(os.path.join(course, MARKER), "w") as fh:
        fh.write("made by accelab demo; `accelab demo` may delete this folder\n")
    start = time.monotonic()
    out(
        f"Creating the course {course} (roster: {', '.join(s['id'] for s in ROSTER)}) and "
        f"assignment {assignment} ..."
    )
    assign(course, assignment, roster=ROSTER, course_id="accelab-demo", release=True)
    out(f"  source notebook and released notebook written ({time.monotonic() - start:.1f} s)")
    build_submissions(course, assignment)
    out(
        "Simulated submissions: ada right, ben sign errors, cai wrong units (bare SI numbers), "
        "dee crashes, eve right in SI units, fay copies ada's answers"
    )
    subs, path, rows, seconds, timings = grade(course, assignment, jobs=jobs)
    out(
        f"Graded {len(subs)} submissions in the sandbox, with feedback and CSV, in "
        f"{seconds:.1f} s ({jobs} at a time)\n"
    )
    out(format_table(rows, question_names(course, assignment)))
    out(f"\nper-question CSV: {path}")
    out(f"feedback: {os.path.join(course, 'feedback')}/<student>/{assignment}/{assignment}.html")
    out(
        f"grade again after adding submissions: accelab grade --course {course} "
        f"--assignment {assignment}"
    )
    return rows
