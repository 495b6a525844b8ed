"""The ``accelab`` command: one parser, the subcommands of every layer.

Each layer that has commands exposes ``register(subparsers)``, which adds
its parsers and sets ``func`` on each to the function that runs it (it
returns the exit status). This module only puts them together, in the order
``accelab --help`` lists them, and runs the one asked for.
"""

import argparse
import errno
import importlib
import os
import sys

from accelab import lazy_iri

#: the layers' command modules, in --help order: imported by :func:`main`, not with this
#: module, so that a Ctrl-C while they load (the console script imports this module
#: first) is said in one line like any other
LAYERS = ("accelab.solver.cli", "accelab.benchmarks.cli", "accelab.exercises.cli")
#: the course layer's commands (``accelab course``) join when that module
#: exists; it is imported by name so that its absence alone is tolerated
#: (any other error while importing it is raised, never hidden)
OPTIONAL_LAYERS = ("accelab.course.cli",)

EPILOG = """examples:
  accelab solve fourbar a="2 in" b="6 in" c="9 in" d="7 in" theta2="30 deg" omega2="10 rad/s" alpha2="-5 rad/s^2"
  accelab solve --cases cases.json
  accelab demo
run 'accelab COMMAND --help' for each command's options and an example."""  # noqa: E501 - one command a user copies


def layers():
    """The modules whose ``register`` adds subcommands, in --help order."""
    found = [importlib.import_module(name) for name in LAYERS]
    for name in OPTIONAL_LAYERS:
        try:
            found.append(importlib.import_module(name))
        except ModuleNotFoundError as exc:
            if exc.name not in _parents(name):  # a missing module *inside* it is a bug
                raise
    return found


def _parents(name):
    """``"accelab.course.cli"`` -> ``{"course", "accelab.course.cli"}``."""
    parts = name.split(".")
    return {".".join(parts[:k]) for k in range(1, len(parts) + 1)}


def build_parser():
    parser = argparse.ArgumentParser(
        prog="accelab",
        description="Acceleration analysis of planar linkages: solve, draw, benchmark, "
        "and generate and grade exercises.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for layer in layers():
        layer.register(sub)
    return parser


def main(argv=None):
    """Run ``accelab`` with ``argv`` (default: the command line); returns the exit status.

    No traceback reaches the user: a reader that leaves (``| head``) ends the
    command quietly, an output that cannot be written (a full disk) is said
    in one line with exit status 2, Ctrl-C exits with 130, and anything else
    unexpected is reported as an internal error to report, with status 1.
    """
    # before anything imports numpy: its OpenBLAS starts a thread per core that spins about
    # 0.1 cpu-s (a third of a one-case `accelab solve`) and is never used, the commands' work
    # being elementwise over arrays of angles and small solves; a value the user set is kept
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    try:
        lazy_iri.defer_iri_grammar()  # before any command imports nbformat (0.8 s saved)
        parser = build_parser()
    except KeyboardInterrupt:  # Ctrl-C while the commands load
        print("accelab: interrupted", file=sys.stderr)
        return 130
    args, extra = parser.parse_known_args(argv)
    if extra:  # name=value after an option (accelab solve fourbar --json a="2 in" ...)
        if getattr(args, "intermixed", False) and all(
            "=" in e and not e.startswith("-") for e in extra
        ):
            args.values = list(args.values) + extra
        else:
            parser.error(f"unrecognized arguments: {' '.join(e[:60] for e in extra)}")
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        status = args.func(args) or 0
        sys.stdout.flush()
        return status
    except KeyboardInterrupt:
        print("accelab: interrupted", file=sys.stderr)
        return 130
    except OSError as exc:
        if exc.errno not in (errno.EPIPE, errno.ENOSPC, errno.EDQUOT, errno.EIO, errno.EFBIG):
            return _internal(exc)
        _silence_stdout()
        if exc.errno == errno.EPIPE:  # e.g. piped into head: the reader left, nothing to say
            return 0
        print(f"accelab: cannot write the output: {exc.strerror}", file=sys.stderr)
        return 2
    except Exception as exc:  # noqa: BLE001 - no traceback ever reaches a user
        return _internal(exc)


def _internal(exc):
    print(
        f"accelab: internal error, please report it with the command you ran: "
        f"{type(exc).__name__}: {str(exc)[:300]}",
        file=sys.stderr,
    )
    return 1


def _silence_stdout():
    """Point stdout at the null device, so that what is left in its buffer
    goes nowhere at exit instead of failing again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass
