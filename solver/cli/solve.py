"""``accelab solve``: one mechanism from the command line, or a batch file.

Both go the batch format's one way (:mod:`accelab.solver.batch`): the command line's
``name=value`` arguments become a case dict, read once by
:func:`~accelab.solver.cases.read_case` and solved by :func:`~accelab.solver.batch.solve`;
``--json`` prints exactly the batch answer, the table shows the same numbers
in the units the user wrote.
"""

import argparse
import math
import sys

import numpy as np

from ..batch import read_case, result_object, solve, solve_cases
from ..errors import AccelabError, error_object
from ..mechanisms.base import kind_of
from ..registry import BATCH_MECHANISMS, PARAMETERS
from ..units import SI_UNITS
from .io import read_batch, write_json

EPILOG = (
    """examples:
  accelab solve fourbar a="2 in" b="6 in" c="9 in" d="7 in" theta2="30 deg" \\
      omega2="10 rad/s" alpha2="-5 rad/s^2"
  accelab solve slidercrank a="40 mm" b="120 mm" c="0 mm" theta2="60 deg" \\
      omega2="3000 rpm" alpha2="0 rad/s^2" --json
  accelab solve --cases cases.json        # the batch contract; '-' reads stdin

mechanisms and their parameters (alpha2 and jerk2 default to 0):
"""
    + "\n".join(
        f"  {m}: {', '.join(p.name for p in PARAMETERS[m].geometry + PARAMETERS[m].point)}"
        f", theta2, omega2, alpha2, jerk2"
        + (", circuit=open|crossed" if PARAMETERS[m].circuits else "")
        for m in BATCH_MECHANISMS
    )
    + """
  loops: a JSON description (see docs/conventions.md#vector-loop-format); use --cases

exit status: 0 every case solved, 1 some case reported an error, 2 unusable input."""
)


def register(sub):
    p = sub.add_parser(
        "solve",
        help="solve a mechanism (position to jerk) or a batch of cases",
        description="Solve a linkage from position to jerk. Give a mechanism "
        "and its quantities as name=value with units, or --cases FILE.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("mechanism", nargs="?", help=", ".join(BATCH_MECHANISMS))
    p.add_argument(
        "values",
        nargs="*",
        metavar="name=value",
        help='quantities with units, e.g. a="2 in" theta2="30 deg"',
    )
    p.add_argument(
        "--cases",
        metavar="FILE",
        help="JSON list of cases ('-' for stdin); prints a JSON list of results",
    )
    p.add_argument("--json", action="store_true", help="print JSON (SI units) instead of a table")
    p.set_defaults(func=run, intermixed=True)


def run(args):
    if args.cases:
        if args.mechanism or args.values:
            print(
                "accelab solve: give either a mechanism with name=value quantities, or "
                "--cases FILE, not both (the file names each case's mechanism)",
                file=sys.stderr,
            )
            return 2
        return run_batch(args.cases)
    if not args.mechanism:
        print(
            "accelab solve: give a mechanism and its values, or --cases FILE "
            "(see accelab solve --help)",
            file=sys.stderr,
        )
        return 2
    case = {"mechanism": args.mechanism}
    for item in args.values:
        name, eq, value = item.partition("=")
        name = name.strip()
        if not eq or not name:
            print(
                f'accelab solve: {item[:60]!r} is not name=value (e.g. theta2="30 deg")',
                file=sys.stderr,
            )
            return 2
        if name in case:
            print(f"accelab solve: {name} is given twice; give each quantity once", file=sys.stderr)
            return 2
        case[name] = _number_or_text(name, value.strip())
    try:
        c = read_case(case)
        result = solve(c)
    except AccelabError as exc:
        if args.json:
            write_json(error_object(exc))
        else:
            print(f"{exc.kind}: {exc}", file=sys.stderr)
        return 1
    answer = result_object(c, result)
    if args.json:
        write_json(answer, indent=2)
    elif not answer["ok"]:
        print(f"{answer['error']}: {answer['message']}", file=sys.stderr)
    else:
        sys.stdout.write(table(c, result) + "\n")
    return 0 if answer["ok"] else 1


def _number_or_text(name, value):
    """The fivebar's gear ratio is a plain number; everything else is text."""
    if name == "lam":
        try:
            return float(value)
        except ValueError:
            return value
    return value


def run_batch(path):
    cases, problem = read_batch(path)
    if problem:
        print(f"accelab solve --cases: cannot use {path}: {problem}", file=sys.stderr)
        return 2
    results = solve_cases(cases)
    write_json(results)
    return 0 if all(r.get("ok") for r in results) else 1


def display_units(case):
    """Units to show each kind of output in, from the units the user wrote
    (as :func:`~accelab.solver.cases.read_case` read them)."""

    def unit_of(key, kind):
        unit = case.units.get(key)
        return unit if unit is not None else SI_UNITS[kind]

    length = next(
        (case.units[k] for k in ("a", "p", "b", "c", "d") if case.units.get(k) is not None),
        SI_UNITS["length"],
    )
    return {
        "angle": unit_of("theta2", "angle")
        if case.units.get("theta2") is not None
        else case_unit("deg"),
        "angular_velocity": unit_of("omega2", "angular_velocity"),
        "angular_acceleration": unit_of("alpha2", "angular_acceleration"),
        "angular_jerk": unit_of("jerk2", "angular_jerk"),
        "length": length,
        "velocity": length / SI_UNITS["time"],
        "acceleration": length / SI_UNITS["time"] ** 2,
        "jerk": length / SI_UNITS["time"] ** 3,
        "dimensionless": SI_UNITS["dimensionless"],
    }


def case_unit(text):
    from ..units import ureg

    return ureg.Unit(text)


def table(case, result):
    """A readable table of every output, in the units the user gave."""
    units = display_units(case)
    title = f"{case.mechanism}" + (f" ({case.circuit} circuit)" if case.circuit else "")
    lines = [title, "-" * len(title)]
    for name in result.outputs():
        u = units[kind_of(name)]
        v = result[name].m_as(u)
        ustr = f"{u:~P}"
        if np.iscomplexobj(v):
            mag, ang = abs(v), math.degrees(np.angle(v))
            lines.append(
                f"{name:<12} {mag:>14.6g} {ustr:<10} at {ang:8.3f} deg   "
                f"(x {v.real:.6g}, y {v.imag:.6g})"
            )
        else:
            lines.append(f"{name:<12} {float(v):>14.6g} {ustr}")
    lines.append(f"{'condition':<12} {result.condition:>14.3g}   (1 best, 0 at a toggle)")
    return "\n".join(lines)
