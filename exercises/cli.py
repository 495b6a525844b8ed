"""accelab's exercise subcommands: ``assign``, ``variant``, ``grade``, ``demo``."""

import argparse
import json
import sys

from .families import FAMILIES


def _families(text):
    names = [f.strip() for f in text.split(",") if f.strip()]
    bad = [f for f in names if f not in FAMILIES]
    if bad:
        raise argparse.ArgumentTypeError(f"unknown family {bad[0]!r}; use some of "
                                         f"{','.join(FAMILIES)}")
    return names


def register(subparsers):
    fmt = argparse.RawDescriptionHelpFormatter
    p = subparsers.add_parser(
        "assign", help="write a randomized assignment into an nbgrader course",
        description="Write an nbgrader source notebook (statement, figure, locked parameter "
                    "cell, answer and test cells) for a randomized assignment, creating the "
                    "course directory and its sqlite gradebook if needed; then run nbgrader "
                    "generate_assignment (and release_assignment with --release).",
        epilog="example:\n  accelab assign --course mycourse --assignment A "
               "--families rotation,fourbar,tolerance --units US --roster roster.csv --release",
        formatter_class=fmt)
    p.add_argument("--course", required=True, help="course directory (created if missing)")
    p.add_argument("--assignment", required=True, help="assignment name, e.g. A")
    p.add_argument("--families", type=_families, default=None,
                   help=f"comma-separated problem families: {','.join(FAMILIES)} "
                        "(default rotation,fourbar,tolerance)")
    p.add_argument("--units", choices=["US", "SI"], default="US")
    p.add_argument("--tolerance", type=float, default=0.01, help="relative tolerance (0.01 = 1%%)")
    p.add_argument("--ranges", default=None,
                   help='JSON: family -> {name: [lo, hi]}, e.g. \'{"rotation": {"p": ["2 in", "6 in"]}}\'')
    p.add_argument("--roster", default=None, help="CSV with a column id (first_name, last_name, "
                   "email optional)")
    p.add_argument("--course-id", default=None, help="nbgrader course id (new course only)")
    p.add_argument("--timeout", type=int, default=10, help="per-cell time limit in autograde [s]")
    p.add_argument("--no-generate", action="store_true", help="only write the source notebook")
    p.add_argument("--release", action="store_true", help="also run release_assignment")
    p.set_defaults(func=run_assign)

    p = subparsers.add_parser(
        "variant", help="print one student's variant (no answers) for an outside solver",
        description="Print a student's variant: given values, and for each graded answer its "
                    "name, unit, the batch cases it depends on and the expr over their outputs.",
        epilog="example:\n  accelab variant --course mycourse --assignment A --student alice --json",
        formatter_class=fmt)
    p.add_argument("--course", required=True)
    p.add_argument("--assignment", required=True)
    p.add_argument("--student", required=True)
    p.add_argument("--json", action="store_true", help="JSON output (default: readable text)")
    p.set_defaults(func=run_variant)

    p = subparsers.add_parser(
        "grade", help="autograde all submissions, then feedback and a per-question CSV",
        description="Autograde every submission of an assignment in parallel processes (with "
                    "a progress bar), generate feedback, and export a per-question CSV.",
        epilog="example:\n  accelab grade --course build/demo-course --assignment A --jobs 2",
        formatter_class=fmt)
    p.add_argument("--course", required=True)
    p.add_argument("--assignment", required=True)
    p.add_argument("--jobs", type=int, default=2, help="parallel autograde processes")
    p.add_argument("--csv", default=None, help="CSV path (default COURSE/grades_A.csv)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=run_grade)

    p = subparsers.add_parser(
        "demo", help="worked case, then the instructor's job end to end in build/demo-course",
        description="Print a worked case from the solver, then create a course with a sample "
                    "roster and a randomized assignment, simulate submissions, autograde, "
                    "generate feedback and print the grade table.",
        epilog="example:\n  accelab demo\n  accelab grade --course build/demo-course --assignment A",
        formatter_class=fmt)
    p.add_argument("--course", default="build/demo-course")
    p.add_argument("--jobs", type=int, default=2)
    p.set_defaults(func=run_demo)


def _fail(message):
    print(f"accelab: error: {message}", file=sys.stderr)
    return 2


def run_assign(args):
    from .assign import assign
    from .course import read_roster
    try:
        ranges = json.loads(args.ranges) if args.ranges else None
        roster = read_roster(args.roster) if args.roster else ()
        path = assign(args.course, args.assignment, args.families, args.units, args.tolerance,
                      ranges, roster, args.course_id, generate=not args.no_generate,
                      release=args.release, timeout=args.timeout)
    except (ValueError, OSError, RuntimeError) as exc:
        return _fail(str(exc))
    print(f"wrote {path}")
    return 0


def run_variant(args):
    from .variant import dumps, format_text, variant_json
    try:
        v = variant_json(args.course, args.assignment, args.student)
    except (ValueError, OSError) as exc:
        return _fail(str(exc))
    print(dumps(v) if args.json else format_text(v))
    return 0


def run_grade(args):
    import os
    from .autograde import format_table, grade, question_names
    release = os.path.join(args.course, "release", args.assignment)
    if not os.path.isdir(release):
        return _fail(f"no released assignment {args.assignment!r} in {args.course}; run "
                     f"accelab assign --course {args.course} --assignment {args.assignment} first")
    outcomes, path, rows, seconds = grade(args.course, args.assignment, args.jobs,
                                          not args.quiet, args.csv)
    print(format_table(rows, question_names(args.course, args.assignment)))
    print(f"\n{len(outcomes)} submissions graded in {seconds:.1f} s; CSV: {path}")
    return 0 if all(o.ok for o in outcomes) else 1


def run_demo(args):
    from .demo import run_demo as demo
    demo(args.course, jobs=args.jobs)
    return 0
