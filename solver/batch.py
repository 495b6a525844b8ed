"""Solving cases of the batch format: the one path from a case to its answer.

``accelab solve --cases FILE`` and ``accelab solve MECHANISM name=value ...``
both come here: :func:`read_case` (:mod:`accelab.solver.cases`) checks the case and
converts it to SI floats once; :func:`solve` builds the unit-aware mechanism
from those floats and solves it; :func:`result_object` writes the batch
contract's answer. :func:`solve_case` does all three and never raises, so
one bad case never stops the others. A ``"loops"`` case goes to the
vector-loop solver (:func:`accelab.solver.vectorloops.solve_loops_case`).
"""

from typing import Any

from .cases import Case, check_mechanism, read_case
from .errors import error_object
from .mechanisms import MECHANISMS, Result
from .results import finite_or_refused
from .vectorloops import solve_loops_case

__all__ = [
    "read_case",
    "solve",
    "solve_case",
    "solve_cases",
    "result_object",
    "error_object",
    "Case",
]


def solve(case: Case) -> Result:
    """The :class:`~accelab.solver.mechanisms.Result` of a case read by :func:`read_case`.

    Raises the :class:`~accelab.solver.errors.AccelabError` family (not assemblable,
    singular ...).
    """
    mech = MECHANISMS[case.mechanism].from_si(case.geometry(), given=case.given, units=case.units)
    point: dict[str, Any] = case.point()  # p, delta3: only a mechanism that declares them has them
    return mech.solve_si(case.motion(), circuit=case.circuit, **point)


def result_object(case: Case, result: Result) -> dict[str, Any]:
    """The batch contract's answer for a solved case: ``{"ok": true, "circuit":
    ..., outputs in SI (vectors as [x, y]), "condition": ...}``."""
    out: dict[str, Any] = {"ok": True}
    if case.circuit:
        out["circuit"] = case.circuit
    out.update(result.to_dict())
    out["condition"] = result.condition
    return finite_or_refused(out)


def solve_case(case: Any) -> dict[str, Any]:
    """Solve one batch case (a dict of docs/conventions.md#batch-format, or anything a
    JSON reader gave); never raises (errors become error objects)."""
    try:
        if check_mechanism(case) == "loops":
            return solve_loops_case(case)
        c = read_case(case)
        return result_object(c, solve(c))
    except Exception as exc:  # noqa: BLE001 - one bad case never stops the batch
        return error_object(exc)


def solve_cases(cases: list[Any]) -> list[dict[str, Any]]:
    """Solve a list of cases in order (see :func:`solve_case`)."""
    return [solve_case(c) for c in cases]
