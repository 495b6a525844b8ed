"""The solver library's subcommands of ``accelab``: ``solve``, ``draw``, ``figures``.

:func:`register` adds them to the command that the application layer
(:mod:`accelab.cli`) builds; each module here exposes its own ``register``
and the function that runs it. Nothing here knows the layers above.
"""

from . import draw, figures, solve

__all__ = ["register"]


def register(subparsers):
    """Add ``solve``, ``draw`` and ``figures`` to an argparse subparsers object."""
    for command in (solve, draw, figures):
        command.register(subparsers)
