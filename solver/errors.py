"""One exception family for everything the solver refuses to answer.

Every error carries a ``kind`` that is also the ``"error"`` field of the batch
contract (``invalid_input``, ``not_assemblable``, ``singular``), and a message
that says what to change.
"""

from typing import Any

__all__ = [
    "AccelabError",
    "InvalidInput",
    "NotAssemblable",
    "Singular",
    "NoConvergence",
    "error_object",
]


class AccelabError(Exception):
    """Base class of every error raised by accelab."""

    kind: str = "error"


class InvalidInput(AccelabError, ValueError):
    """A parameter is missing, has the wrong dimension, or an impossible value.

    ``parameter`` names the offending argument when there is one.
    """

    kind = "invalid_input"

    def __init__(self, message: str, parameter: str | None = None) -> None:
        super().__init__(message)
        self.parameter = parameter


class NotAssemblable(AccelabError):
    """The links cannot close their vector loop at this input position."""

    kind = "not_assemblable"


class Singular(AccelabError):
    """The position exists but the velocity/acceleration equations are singular
    or too ill-conditioned there to vouch for the numbers.

    ``condition`` is the solver's dimensionless condition measure at that
    position (1 is best, 0 is a toggle/limit position).
    """

    kind = "singular"

    def __init__(self, message: str, condition: float | None = None) -> None:
        super().__init__(message)
        self.condition = condition


class NoConvergence(NotAssemblable):
    """Newton-Raphson did not close the loops from the given guesses.

    ``residual`` is the norm of the loop residual it reached [m].
    """

    def __init__(
        self, message: str, residual: float | None = None, iterations: int | None = None
    ) -> None:
        super().__init__(message)
        self.residual = residual
        self.iterations = iterations


def error_object(exc: BaseException) -> dict[str, Any]:
    """The batch contract's error object for an exception raised by one case.

    Errors of the :class:`AccelabError` family give their own kind and message;
    anything else is a bug, reported as ``internal_error`` in the case so that
    the rest of the batch goes on.
    """
    if isinstance(exc, AccelabError):
        return {"ok": False, "error": exc.kind, "message": str(exc)}
    return {
        "ok": False,
        "error": "internal_error",
        "message": f"{type(exc).__name__}: {str(exc)[:200]} (please report this case)",
    }
