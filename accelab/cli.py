"""The ``accelab`` command: one parser, the subcommands of every layer.

Each layer that has commands exposes ``register(subparsers)``, which adds
its parsers and sets ``func`` on each to the function that runs it (it
returns the exit status). This module only puts them together, in the order
``accelab --help`` lists them, and runs the one asked for.
"""

import argparse
import importlib

import benchmarks.cli
import exercises.cli
import solver.cli

#: the course layer's commands (``accelab course``) join when that module
#: exists; it is imported by name so that its absence alone is tolerated
#: (any other error while importing it is raised, never hidden)
OPTIONAL_LAYERS = ("course.cli",)

EPILOG = """examples:
  accelab solve fourbar a="2 in" b="6 in" c="9 in" d="7 in" theta2="30 deg" omega2="10 rad/s" alpha2="-5 rad/s^2"
  accelab solve --cases cases.json
  accelab demo
run 'accelab COMMAND --help' for each command's options and an example."""


def layers():
    """The modules whose ``register`` adds subcommands, in --help order."""
    found = [solver.cli, benchmarks.cli, exercises.cli]
    for name in OPTIONAL_LAYERS:
        try:
            found.append(importlib.import_module(name))
        except ModuleNotFoundError as exc:
            if exc.name not in _parents(name):   # a missing module *inside* it is a bug
                raise
    return found


def _parents(name):
    """``"course.cli"`` -> ``{"course", "course.cli"}``."""
    parts = name.split(".")
    return {".".join(parts[:k]) for k in range(1, len(parts) + 1)}


def build_parser():
    parser = argparse.ArgumentParser(
        prog="accelab",
        description="Acceleration analysis of planar linkages: solve, draw, benchmark, "
                    "and generate and grade exercises.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for layer in layers():
        layer.register(sub)
    return parser


def main(argv=None):
    """Run ``accelab`` with ``argv`` (default: the command line); returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return args.func(args) or 0
    except BrokenPipeError:  # e.g. piped into head: the reader left, nothing to say
        return 0
