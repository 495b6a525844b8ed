"""accelab's exercise subcommands: ``assign``, ``variant``, ``grade``, ``demo``.

The application layer calls :func:`register` with its subparsers.
"""

import argparse
import json
import os
import sys

from .families import FAMILIES


def _families(text):
    names = [f.strip() for f in text.split(",") if f.strip()]
    bad = [f for f in names if f not in FAMILIES]
    if bad:
        raise argparse.ArgumentTypeError(
            f"unknown family {bad[0]!r}; use some of {','.join(FAMILIES)}"
        )
    return names


def _positive(text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of at least 1")
    return value


def register(subparsers):
    fmt = argparse.RawDescriptionHelpFormatter
    p = subparsers.add_parser(
        "assign",
        help="write a randomized assignment into an nbgrader course",
        description="Write an nbgrader source notebook (statement, figure, locked parameter "
        "cell, answer and test cells) for a randomized assignment, creating the "
        "course directory and its sqlite gradebook if needed, after checking that "
        "every student on the roster gets a valid problem; then run nbgrader "
        "generate_assignment (and release_assignment with --release). An "
        "assignment that has submissions is replaced only with --force.",
        epilog="example:\n  accelab assign --course mycourse --assignment A "
        "--families rotation,fourbar,tolerance --units US --roster roster.csv "
        "--due '2026-12-01 17:00' --release",
        formatter_class=fmt,
    )
    p.add_argument("--course", required=True, help="course directory (created if missing)")
    p.add_argument("--assignment", required=True, help="assignment name, e.g. A")
    p.add_argument(
        "--families",
        type=_families,
        default=None,
        help=f"comma-separated problem families: {','.join(FAMILIES)} "
        "(default rotation,fourbar,tolerance)",
    )
    p.add_argument("--units", choices=["US", "SI"], default="US")
    p.add_argument(
        "--tolerance", type=float, default=0.01, help="relative tolerance of numbers (0.01 = 1%%)"
    )
    p.add_argument(
        "--angle-tolerance",
        type=float,
        default=1.0,
        help="band of directions (angles) [deg], default 1",
    )
    p.add_argument(
        "--ranges",
        default=None,
        help='JSON: family -> {name: [lo, hi]}, e.g. \'{"rotation": {"p": ["2 in", "6 in"]}}\'',
    )
    p.add_argument(
        "--roster",
        default=None,
        help="CSV with a column id (first_name, last_name, email optional)",
    )
    p.add_argument("--course-id", default=None, help="nbgrader course id (new course only)")
    p.add_argument(
        "--exchange",
        default=None,
        help="nbgrader's exchange folder, outside the course folder, where students fetch and "
        "hand in (new course only; default: a folder 'exchange' beside the course folder)",
    )
    p.add_argument(
        "--due",
        default=None,
        help="due date, e.g. '2026-12-01 17:00' (UTC); "
        "nbgrader's late-submission policy applies after it",
    )
    p.add_argument(
        "--timeout",
        type=int,
        default=10,
        help="time limit of one cell when graded [s] (new course only)",
    )
    p.add_argument(
        "--time-limit",
        type=int,
        default=60,
        help="time limit of a whole submission when graded [s] (new course only)",
    )
    p.add_argument("--no-generate", action="store_true", help="only write the source notebook")
    p.add_argument("--release", action="store_true", help="also run release_assignment")
    p.add_argument(
        "--force",
        action="store_true",
        help="replace an assignment that already has submissions (keeps the old "
        "settings in COURSE/.accelab/replaced/ and prints the changes)",
    )
    p.set_defaults(func=run_assign)

    p = subparsers.add_parser(
        "variant",
        help="print one student's problem (no answers) for an outside solver",
        description="Print a student's variant (instructor side: it reads the course folder): "
        "given values, and for each graded answer its name, unit, the batch cases "
        "it depends on and the expr over their outputs.",
        epilog="example:\n"
        "  accelab variant --course mycourse --assignment A --student alice --json",
        formatter_class=fmt,
    )
    p.add_argument("--course", required=True)
    p.add_argument("--assignment", required=True)
    p.add_argument("--student", required=True)
    p.add_argument("--json", action="store_true", help="JSON output (default: readable text)")
    p.set_defaults(func=run_variant)

    p = subparsers.add_parser(
        "grade",
        help="grade submissions in a sandbox, then feedback and a per-question CSV",
        description="Run every submission of an assignment in a bubblewrap sandbox (in "
        "parallel), judge its answers outside it against the submitter's own key, "
        "score them into nbgrader's gradebook, generate feedback, and export a "
        "per-question CSV over the whole roster.",
        epilog="examples:\n  accelab grade --course build/demo-course --assignment A\n"
        "  accelab grade --course build/demo-course --assignment A --student ada\n"
        "  accelab grade --course build/demo-course --assignment A --new",
        formatter_class=fmt,
    )
    p.add_argument("--course", required=True)
    p.add_argument("--assignment", required=True)
    p.add_argument(
        "--student",
        action="append",
        default=None,
        help="grade (again) only this student; may be repeated",
    )
    p.add_argument(
        "--new",
        action="store_true",
        help="grade only what is not completely graded yet, or was handed in again since "
        "(compared by content); also finishes an interrupted run",
    )
    p.add_argument("--jobs", type=_positive, default=2, help="submissions run at a time")
    p.add_argument("--csv", default=None, help="CSV path (default COURSE/grades_A.csv)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument(
        "--unsafe-no-sandbox",
        action="store_true",
        help="grade without a sandbox: a submission can then read the course "
        "(keys, source notebooks, gradebook) and change other students' "
        "grades; only for notebooks you trust",
    )
    p.set_defaults(func=run_grade)

    p = subparsers.add_parser(
        "demo",
        help="worked case, then the instructor's job end to end in build/demo-course",
        description="Print a worked case from the solver, then create a course with a sample "
        "roster and a randomized assignment, simulate submissions (honest and "
        "dishonest), grade them in the sandbox, generate feedback and print the "
        "grade table.",
        epilog="example:\n  accelab demo\n"
        "  accelab grade --course build/demo-course --assignment A",
        formatter_class=fmt,
    )
    p.add_argument(
        "--course",
        default="build/demo-course",
        help="folder for the demo course: created by the demo, or one it created "
        "before (any other existing folder is refused)",
    )
    p.add_argument("--jobs", type=_positive, default=2)
    p.set_defaults(func=run_demo)


def _note(message):
    print(f"accelab: note: {message}", file=sys.stderr)


def _fail(message):
    print(f"accelab: error: {message}", file=sys.stderr)
    return 2


def _say(message):
    print(f"accelab: {message}", file=sys.stderr)


def _check_course(course):
    """Before grading: the course folder made private, and what is unsafe about its
    exchange said (:func:`accelab.exercises.layout.check`)."""
    from .grader.grade import load_config
    from .layout import check
    from .nbgrader_course import roster_ids

    check(course, load_config(os.path.abspath(course)), roster_ids(course), say=_say)


def run_assign(args):
    from .assign import assign
    from .nbgrader_course import read_roster

    try:
        ranges = json.loads(args.ranges) if args.ranges else None
        roster = read_roster(args.roster, say=_note) if args.roster else ()
        path = assign(
            args.course,
            args.assignment,
            args.families,
            args.units,
            args.tolerance,
            ranges,
            roster,
            args.course_id,
            generate=not args.no_generate,
            release=args.release,
            timeout=args.timeout,
            angle_tolerance=args.angle_tolerance,
            due=args.due,
            force=args.force,
            time_limit=args.time_limit,
            exchange=args.exchange,
            say=_say,
        )
    except json.JSONDecodeError as exc:
        return _fail(f"--ranges is not JSON: {exc}")
    except (ValueError, OSError, RuntimeError) as exc:
        return _fail(str(exc))
    print(f"wrote {path}")
    return 0


def run_variant(args):
    from .variant import dumps, format_text, variant_json

    try:
        v = variant_json(args.course, args.assignment, args.student)
    except (ValueError, OSError, RuntimeError) as exc:
        return _fail(str(exc))
    print(dumps(v) if args.json else format_text(v))
    return 0


def run_grade(args):
    from .grader.grade import GradingStopped, grade
    from .grader.gradetable import format_table, question_names
    from .grader.intake import refusals
    from .grader.sandbox import SandboxUnavailable

    release = os.path.join(args.course, "release", args.assignment)
    if not os.path.isdir(release):
        return _fail(
            f"no released assignment {args.assignment!r} in {args.course}; run "
            f"accelab assign --course {args.course} --assignment {args.assignment} "
            "--release first"
        )
    try:
        _check_course(args.course)
        subs, path, rows, seconds, timings = grade(
            args.course,
            args.assignment,
            students=args.student,
            only_new=args.new,
            jobs=args.jobs,
            unsafe=args.unsafe_no_sandbox,
            show_progress=not args.quiet,
            csv_path=args.csv,
        )
    except SandboxUnavailable as exc:
        return _fail(
            f"no sandbox to grade in: {exc}. Without one a submission could read the "
            "source notebooks and the gradebook and change other students' grades; "
            "to grade anyway, only notebooks you trust, pass --unsafe-no-sandbox"
        )
    except GradingStopped as exc:
        print(f"accelab: {exc}", file=sys.stderr)
        return exc.status
    except (ValueError, OSError, RuntimeError) as exc:
        return _fail(str(exc))
    for line in refusals(args.course, args.assignment):
        _say(line)
    try:
        names = question_names(args.course, args.assignment)
    except (OSError, ValueError):
        names = [n for n in rows[0] if n not in _NOT_QUESTIONS] if rows else []
    print(format_table(rows, names))
    spent = ", ".join(f"{k} {v:.1f} s" for k, v in timings.items())
    failed = [s for s in subs if s.failed]
    done = f"{len(subs) - len(failed)} submission(s) graded" + (
        f", {len(failed)} not graded (see below)" if failed else ""
    )
    print(f"\n{done} in {seconds:.1f} s ({spent}); CSV: {path}")
    for sub in subs:  # what the instructor must do about a submission that is not graded
        if sub.failed:
            print(f"accelab: student {sub.student}: not graded: {sub.problem}", file=sys.stderr)
        for note in sub.notes:
            print(f"accelab: student {sub.student}: {note}", file=sys.stderr)
    return 0 if all(s.graded for s in subs) else 1


_NOT_QUESTIONS = ("student", "score", "late_penalty", "total", "max", "notes")


def run_demo(args):
    from .demo import DemoError
    from .demo import run_demo as demo

    try:
        demo(args.course, jobs=args.jobs)
    except DemoError as exc:
        return _fail(str(exc))
    return 0
