"""The state of a solved position, shared by every solver of the package.

Each position a solver answers for is ``OK``, ``NOT_ASSEMBLABLE`` (the links
cannot close the loops there) or ``SINGULAR`` (the position exists but its
velocity and acceleration equations are singular, or too ill-conditioned to
vouch for the numbers). :data:`STATUS_NAMES` gives each the name of the
batch contract's error kind (docs/conventions.md#error-kinds), the ``kind`` of the matching
exception in :mod:`accelab.solver.errors`.
"""

OK, NOT_ASSEMBLABLE, SINGULAR = 0, 1, 2
STATUS_NAMES = {OK: "ok", NOT_ASSEMBLABLE: "not_assemblable", SINGULAR: "singular"}

__all__ = ["OK", "NOT_ASSEMBLABLE", "SINGULAR", "STATUS_NAMES"]
