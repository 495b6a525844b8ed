"""``accelab bench``: the speed-against-accuracy benchmark (``make bench``)."""

import argparse

EPILOG = """examples:
  accelab bench --out build/bench                      # the full run (what make bench runs)
  accelab bench --quick --out /tmp/bench               # under a minute
  accelab bench --out build/bench --figures figures    # also refresh the README's charts

It writes OUT/bench.json (every case by every method: time per position,
worst relative error per output, positions refused; the stability study near
a toggle; Newton-Raphson against its starting guess; cost against positions
and loops; the cost of units; the goals; machine and versions) and the charts
bench-speed-accuracy, bench-stability and bench-scaling (PNG and SVG). The
mpmath reference of each cycle is cached in OUT/reference/. Peer packages
(pylinkage, mechanism) are measured when installed: pip install -e ".[bench]"."""


def register(sub):
    p = sub.add_parser("bench", help="benchmark speed against accuracy of every method",
                       description="Time and check every way accelab (and peer packages) "
                                   "solve a fixed set of linkages, against an mpmath reference.",
                       epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", metavar="DIR", default="build/bench",
                   help="output directory (default: build/bench)")
    p.add_argument("--figures", metavar="DIR", help="where the charts go (default: OUT)")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--quick", action="store_true",
                      help="72 positions per cycle, 3 repeats, up to 10^5 positions (< 1 min)")
    mode.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)
    p.add_argument("--no-peers", action="store_true", help="skip the peer packages")
    p.add_argument("--no-charts", action="store_true", help="write the JSON only")
    p.set_defaults(func=run)


def run(args):
    import warnings
    from ..bench.run import run_benchmark
    mode = "tiny" if args.tiny else "quick" if args.quick else "full"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # peers warn about their own convergence
        data = run_benchmark(args.out, mode=mode, figures=args.figures, peers=not args.no_peers,
                             charts=not args.no_charts)
    return 0 if data["results"] else 1
