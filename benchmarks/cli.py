"""``accelab bench``: the speed-against-accuracy benchmark (``make bench``), a
subcommand that :mod:`accelab.cli` registers."""

import argparse

EPILOG = """examples:
  accelab bench --out build/bench                      # the full run (what make bench runs)
  accelab bench --quick --out /tmp/bench               # under a minute
  accelab bench --out build/bench --figures figures    # also refresh the README's charts
  accelab bench --out build/bench --redraw             # redraw the charts from bench.json

It writes OUT/bench.json (every case by every method: time per position,
worst relative error per output, positions refused; the stability study near
a toggle; Newton-Raphson against its starting guess; cost against positions
and loops; the cost of units; the goals; machine and versions) and the charts
bench-speed-accuracy, bench-stability and bench-scaling (PNG and SVG). The
mpmath reference of each cycle is cached in OUT/reference/.

It needs mpmath (the high-precision reference); the peer packages
(pylinkage, mechanism, kimech) are measured when installed. Both come with
the bench extra: pip install -e ".[bench]"."""

#: what a measuring run cannot do without (module -> what it is for)
NEEDS = {"mpmath": "the high-precision reference every error is measured against"}
INSTALL = 'pip install -e ".[bench]"'


def register(sub):
    p = sub.add_parser(
        "bench",
        help="benchmark speed against accuracy of every method",
        description="Time and check every way accelab (and peer packages) "
        "solve a fixed set of linkages, against an mpmath reference.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--out",
        metavar="DIR",
        default="build/bench",
        help="output directory (default: build/bench)",
    )
    p.add_argument("--figures", metavar="DIR", help="where the charts go (default: OUT)")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument(
        "--quick",
        action="store_true",
        help="72 positions per cycle, 3 repeats, up to 10^5 positions (< 1 min)",
    )
    mode.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)
    p.add_argument("--no-peers", action="store_true", help="skip the peer packages")
    p.add_argument("--no-charts", action="store_true", help="write the JSON only")
    p.add_argument(
        "--redraw",
        action="store_true",
        help="measure nothing: redraw the charts from OUT/bench.json",
    )
    p.add_argument(
        "--report",
        action="store_true",
        help="measure nothing: print OUT/bench.json's tables as Markdown",
    )
    p.set_defaults(func=run)


def missing(names=NEEDS):
    """The modules of ``names`` this installation lacks."""
    import importlib.util

    return [name for name in names if importlib.util.find_spec(name) is None]


def run(args):
    import sys
    import warnings

    if args.redraw or args.report:
        import json
        import os

        path = os.path.join(args.out, "bench.json")
        if not os.path.exists(path):
            print(
                f"accelab bench: no {path} to read; run 'accelab bench --out {args.out}' first",
                file=sys.stderr,
            )
            return 2
        with open(path) as f:
            data = json.load(f)
        if args.report:
            from .report import markdown

            print(markdown(data))
        if args.redraw:
            from .charts import draw_all

            for p in draw_all(data, args.figures or args.out):
                print(f"wrote {p}")
        return 0
    lacking = missing()
    if lacking:
        print(
            "accelab bench: this installation has no "
            + ", ".join(f"{name} ({NEEDS[name]})" for name in lacking)
            + f"; install it with: {INSTALL}",
            file=sys.stderr,
        )
        return 2
    if not args.no_peers:
        from .peers import PEERS

        absent = missing(PEERS)
        if absent:
            print(
                f"accelab bench: {', '.join(absent)} not installed, so not measured "
                f"(all the peers come with: {INSTALL})",
                file=sys.stderr,
            )
    from .run import run_benchmark

    mode = "tiny" if args.tiny else "quick" if args.quick else "full"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # peers warn about their own convergence
        data = run_benchmark(
            args.out,
            mode=mode,
            figures=args.figures,
            peers=not args.no_peers,
            charts=not args.no_charts,
        )
    return 0 if data["results"] else 1
