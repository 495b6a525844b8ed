"""``accelab draw FILE --out DIR``: the graphical construction of every case
of a batch file, drawn (PNG and SVG) and read off (JSON on stdout)."""

import argparse
import json
import os
import sys

from ..errors import InvalidInput, error_object
from ..registry import DRAWABLE
from ..results import finite_or_refused
from .io import read_batch

EPILOG = """example:
  echo '[{"mechanism": "fourbar", "a": "2 in", "b": "6 in", "c": "9 in", "d": "7 in",
          "theta2": "30 deg", "omega2": "10 rad/s", "alpha2": "-5 rad/s^2",
          "p": "3 in", "delta3": "30 deg"}]' > cases.json
  accelab draw cases.json --out build/draw

For case number N (from 1) it writes DIR/caseNNN-MECHANISM-linkage.{png,svg}
(the linkage to scale with the acceleration components, Figure 7-4a/d) and
DIR/caseNNN-MECHANISM-polygons.{png,svg} (velocity and acceleration polygons,
Figure 7-4b/c), and prints a JSON list with one object per case: the values
read off the construction in SI (alpha3, alpha4 or d_ddot, A_A, A_B, A_C,
A_P, A_coriolis ..., vectors as [x, y]) and the figure paths, or the error object
of 'accelab solve' ({"ok": false, "error": KIND, "message": ...}).
Mechanisms with a construction: MECHANISMS.
--step K draws only the first K steps of each construction.

exit status: 0 every case drawn, 1 some case reported an error, 2 FILE unusable.""".replace(
    "MECHANISMS", ", ".join(DRAWABLE)
)


def register(sub):
    p = sub.add_parser(
        "draw",
        help="graphical acceleration analysis of a batch of cases "
        "(velocity and acceleration polygons)",
        description="Construct the velocity and acceleration polygons of each "
        "case (Chapter 7, section 7.2), draw them, and print the "
        "values read off the construction.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "cases",
        metavar="FILE",
        nargs="?",
        help="JSON list of cases in the batch format ('-' for stdin)",
    )
    p.add_argument(
        "--cases",
        dest="cases_option",
        metavar="FILE",
        help="the same, as in 'accelab solve --cases'",
    )
    p.add_argument(
        "--out",
        metavar="DIR",
        default="drawings",
        help="directory for the figures (default: drawings)",
    )
    p.add_argument(
        "--format", default="png,svg", help="comma-separated figure formats (default: png,svg)"
    )
    p.add_argument(
        "--step", type=int, default=None, help="draw only the first STEP steps of each construction"
    )
    p.add_argument(
        "--jobs",
        type=int,
        default=0,
        help="worker processes for large batches (default: one per CPU; 1: none)",
    )
    p.set_defaults(func=run)


def draw_case(case, outdir, stem, formats=("png", "svg"), step=None):
    """Construct, draw and read one case; never raises (errors become error objects)."""
    try:
        from ..graphical import construct_case
        from ..graphical.draw import save

        con = construct_case(case)
        if step is not None and not 0 <= step <= len(con.steps):
            raise InvalidInput(
                f"--step must be between 0 and {len(con.steps)} for this "
                f"{con.mechanism} construction (got {step})",
                "step",
            )
        out = {"ok": True}
        if con.circuit:
            out["circuit"] = con.circuit
        out.update(con.to_dict())
        out = finite_or_refused(out)
        if out["ok"]:
            out["figures"] = save(con, outdir, f"{stem}-{con.mechanism}", formats, step)
        return out
    except Exception as exc:  # noqa: BLE001 - one bad case never stops the batch
        return error_object(exc)


def run(args):
    args.cases = args.cases or args.cases_option
    if not args.cases:
        print("accelab draw: give a batch FILE (see accelab draw --help)", file=sys.stderr)
        return 2
    cases, problem = read_batch(args.cases)
    if problem:
        print(f"accelab draw: cannot use {args.cases}: {problem}", file=sys.stderr)
        return 2
    formats = tuple(f.strip().lower() for f in args.format.split(",") if f.strip())
    bad = [f for f in formats if f not in ("png", "svg", "pdf")]
    if bad or not formats:
        print(
            f"accelab draw: unknown format {bad[0] if bad else args.format!r}; "
            "use png, svg or pdf (e.g. --format png,svg)",
            file=sys.stderr,
        )
        return 2
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as exc:
        print(f"accelab draw: cannot create {args.out}: {exc}", file=sys.stderr)
        return 2
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "accelab"
    jobs = args.jobs if args.jobs > 0 else (os.cpu_count() or 1)
    work = [(c, args.out, f"case{i:03d}", formats, args.step) for i, c in enumerate(cases, 1)]
    if jobs > 1 and len(cases) >= 4:
        results = _parallel(work, jobs)
    else:
        results = [draw_case(*w) for w in work]
    # a JSON list, one case per line (as readable as JSON lines, and one document)
    sys.stdout.write("[\n" + ",\n".join(json.dumps(r, allow_nan=False) for r in results) + "\n]\n")
    return 0 if all(r.get("ok") for r in results) else 1


def _draw_one(work):
    return draw_case(*work)


def _parallel(work, jobs):
    """Draw cases in worker processes (figures are independent); results in order."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    try:
        ctx = multiprocessing.get_context("fork")
    except ValueError:  # no fork on this platform
        return [draw_case(*w) for w in work]
    with ProcessPoolExecutor(max_workers=min(jobs, len(work)), mp_context=ctx) as pool:
        return list(pool.map(_draw_one, work, chunksize=max(1, len(work) // (4 * jobs))))
