"""``accelab figures --out figures``: regenerate every figure that the README
and the course show (``make figures`` runs it)."""

import argparse
import sys

EPILOG = """example:
  accelab figures --out figures                 # everything (what make figures runs)
  accelab figures --out /tmp/f --only graphical-fourbar --format png

figures (each as NAME-linkage and NAME-polygons):
  graphical-fourbar              Example 7-1 (Figure 7-4): fourbar with coupler point P
  graphical-slidercrank          offset slider-crank
  graphical-invertedslidercrank  inverted slider-crank with its Coriolis component (Figure 7-8)
  graphical-fivebar              geared fivebar (section 7.4): A_B found from A and from C
  graphical-slotted              block in a rotating slotted link (Figure 7-7)"""


def register(sub):
    p = sub.add_parser(
        "figures",
        help="regenerate the figures of the README and the course",
        description="Draw every figure that the README and the course show.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--out", metavar="DIR", default="figures", help="output directory (default: figures)"
    )
    p.add_argument(
        "--only", metavar="NAME", action="append", help="draw only this figure (repeatable)"
    )
    p.add_argument("--format", default="png,svg", help="comma-separated formats (default: png,svg)")
    p.set_defaults(func=run)


def run(args):
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "accelab"  # stable ids: diffs show real changes
    from ..graphical.gallery import GALLERY, render

    unknown = [n for n in args.only or [] if n not in GALLERY]
    if unknown:
        print(
            f"accelab figures: unknown figure {unknown[0]!r}; choose from {', '.join(GALLERY)}",
            file=sys.stderr,
        )
        return 2
    formats = tuple(f.strip().lower() for f in args.format.split(",") if f.strip())
    if not formats or any(f not in ("png", "svg", "pdf") for f in formats):
        print(
            f"accelab figures: --format takes png, svg or pdf (got {args.format!r})",
            file=sys.stderr,
        )
        return 2
    for path in render(args.out, formats, args.only):
        print(path)
    return 0
