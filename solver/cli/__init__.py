"""The ``accelab`` command: one entry point, one module per subcommand.

Each subcommand module exposes ``register(subparsers)``, which adds its parser
and sets ``func`` to the function that runs it (returning the exit status).
"""

import argparse
import importlib
import sys

# (module, attribute holding register) in the order --help lists them.
SUBCOMMANDS = [
    "solver.cli.solve",
    "solver.cli.draw",
    "solver.cli.figures",
    "solver.cli.bench",
    "exercises.cli",
]

EPILOG = """examples:
  accelab solve fourbar a="2 in" b="6 in" c="9 in" d="7 in" theta2="30 deg" omega2="10 rad/s" alpha2="-5 rad/s^2"
  accelab solve --cases cases.json
  accelab demo
run 'accelab COMMAND --help' for each command's options and an example."""


def build_parser():
    parser = argparse.ArgumentParser(
        prog="accelab",
        description="Acceleration analysis of planar linkages: solve, draw, benchmark, "
                    "and generate and grade exercises.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in SUBCOMMANDS:
        try:
            module = importlib.import_module(name)
        except ModuleNotFoundError as exc:
            if exc.name and name.startswith(exc.name):  # a subcommand not built yet
                continue
            raise
        module.register(sub)
    return parser


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return args.func(args) or 0
    except BrokenPipeError:  # e.g. piped into head
        return 0


if __name__ == "__main__":
    sys.exit(main())
