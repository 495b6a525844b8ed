"""``accelab solve``: one mechanism from the command line, or a batch file."""

import argparse
import json
import math
import sys

import numpy as np

from ..batch import GEOMETRY, MOTION, build, read_case, solve_cases
from ..errors import AccelabError
from ..mechanisms.base import kind_of
from ..units import Q_, ureg

EPILOG = """examples:
  accelab solve fourbar a="2 in" b="6 in" c="9 in" d="7 in" theta2="30 deg" \\
      omega2="10 rad/s" alpha2="-5 rad/s^2"
  accelab solve slidercrank a="40 mm" b="120 mm" c="0 mm" theta2="60 deg" \\
      omega2="3000 rpm" alpha2="0 rad/s^2" --json
  accelab solve --cases cases.json        # the batch contract; '-' reads stdin

mechanisms and their parameters:
""" + "\n".join(f"  {m}: {', '.join(GEOMETRY[m])}, theta2, omega2, alpha2, jerk2"
                + (", circuit=open|crossed" if m != "rotation" else "") for m in GEOMETRY) + """
  loops: a JSON description (see CONVENTIONS); use --cases

exit status: 0 every case solved, 1 some case reported an error, 2 unusable input."""


def register(sub):
    p = sub.add_parser("solve", help="solve a mechanism (position to jerk) or a batch of cases",
                       description="Solve a linkage from position to jerk. Give a mechanism "
                                   "and its quantities as name=value with units, or --cases FILE.",
                       epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mechanism", nargs="?", help="fourbar, slidercrank, invertedslidercrank, "
                                                "fivebar or rotation")
    p.add_argument("values", nargs="*", metavar="name=value",
                   help='quantities with units, e.g. a="2 in" theta2="30 deg"')
    p.add_argument("--cases", metavar="FILE", help="JSON list of cases ('-' for stdin); "
                                                    "prints a JSON list of results")
    p.add_argument("--json", action="store_true", help="print JSON (SI units) instead of a table")
    p.set_defaults(func=run)


def run(args):
    if args.cases:
        return run_batch(args.cases)
    if not args.mechanism:
        print("accelab solve: give a mechanism and its values, or --cases FILE "
              "(see accelab solve --help)", file=sys.stderr)
        return 2
    case = {"mechanism": args.mechanism}
    for item in args.values:
        name, eq, value = item.partition("=")
        if not eq:
            print(f"accelab solve: {item!r} is not name=value (e.g. theta2=\"30 deg\")",
                  file=sys.stderr)
            return 2
        case[name.strip()] = _number_or_text(name.strip(), value.strip())
    case.setdefault("alpha2", "0 rad/s^2")
    try:
        ci = read_case(case)
        mech, motion = build(ci)
        result = mech.solve(**motion)
    except AccelabError as exc:
        if args.json:
            print(json.dumps({"ok": False, "error": exc.kind, "message": str(exc)}))
        else:
            print(f"{exc.kind}: {exc}", file=sys.stderr)
        return 1
    if args.json:
        out = {"ok": True, **({"circuit": ci.circuit} if ci.circuit else {}),
               **result.to_dict()}
        print(json.dumps(out, indent=2))
    else:
        print(table(ci, result))
    return 0


def _number_or_text(name, value):
    if name == "lam":
        try:
            return float(value)
        except ValueError:
            return value
    return value


def run_batch(path):
    try:
        text = sys.stdin.read() if path == "-" else open(path).read()
        cases = json.loads(text)
        if not isinstance(cases, list):
            raise ValueError("the file must hold a JSON list of case objects")
    except (OSError, ValueError) as exc:
        print(f"accelab solve --cases: cannot use {path}: {exc}", file=sys.stderr)
        return 2
    results = solve_cases(cases)
    json.dump(results, sys.stdout)
    sys.stdout.write("\n")
    return 0 if all(r.get("ok") for r in results) else 1


def display_units(case):
    """Units to show each kind of output in, taken from what the user typed."""
    def unit_of(key, default):
        try:
            return Q_(case[key]).units if key in case else ureg(default).units
        except Exception:
            return ureg(default).units
    length = next((unit_of(k, "m") for k in ("a", "p", "b", "c", "d") if k in case), ureg.m)
    return {"angle": unit_of("theta2", "deg"), "angular_velocity": unit_of("omega2", "rad/s"),
            "angular_acceleration": unit_of("alpha2", "rad/s**2"),
            "angular_jerk": unit_of("jerk2", "rad/s**3"), "length": length,
            "velocity": length / ureg.s, "acceleration": length / ureg.s ** 2,
            "jerk": length / ureg.s ** 3, "dimensionless": ureg.dimensionless}


def table(ci, result):
    """A readable table of every output, in the units the user gave."""
    units = display_units(ci.raw)
    title = f"{ci.mechanism}" + (f" ({ci.circuit} circuit)" if ci.circuit else "")
    lines = [title, "-" * len(title)]
    for name in result.outputs():
        q = getattr(result, name)
        u = units[kind_of(name)]
        if u == ureg.rad / ureg.s ** 2 and kind_of(name) == "angular_acceleration":
            pass
        v = q.to(u).magnitude
        ustr = f"{u:~P}"
        if np.iscomplexobj(v):
            mag, ang = abs(v), math.degrees(np.angle(v))
            lines.append(f"{name:<12} {mag:>14.6g} {ustr:<10} at {ang:8.3f} deg   "
                         f"(x {v.real:.6g}, y {v.imag:.6g})")
        else:
            lines.append(f"{name:<12} {float(v):>14.6g} {ustr}")
    lines.append(f"{'condition':<12} {result.condition:>14.3g}   (1 best, 0 at a toggle)")
    return "\n".join(lines)
