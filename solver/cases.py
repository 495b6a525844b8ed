"""A case of the batch format (docs/conventions.md#batch-format), read once.

A case is a dict like ``{"mechanism": "fourbar", "a": "2 in", ..., "theta2":
"30 deg", "omega2": "10 rad/s", "alpha2": "-5 rad/s^2"}``: the mechanism, its
quantities as text with units (or Quantities), and optionally ``circuit``.
:func:`read_case` checks it against the mechanism's declared parameters
(its entry of :mod:`accelab.solver.registry`) and converts every quantity to an SI float, the
only conversion on its way to the kernels; the command line reads its
``name=value`` arguments into the same dict.
"""

from dataclasses import dataclass, field
from typing import Any

from .errors import InvalidInput
from .registry import BATCH_MECHANISMS, PARAMETERS
from .units import parse_quantity, to_si

__all__ = ["Case", "read_case", "MECHANISM_NAMES"]

MECHANISM_NAMES = list(BATCH_MECHANISMS) + ["loops"]
#: the key under which a reader of JSON lists the keys a case gave twice
#: (accelab.solver.cli.io), so that such a case is refused instead of the last value
#: silently winning
DUPLICATES = "__duplicate_keys__"


@dataclass
class Case:
    """A case read and checked.

    ``params`` holds every parameter in SI floats (m, rad, rad/s, ...),
    defaults included; ``given`` the case as the user wrote it; ``units``
    the unit the user wrote each quantity in (for showing results back in
    them).
    """

    mechanism: str
    circuit: str | None = None
    params: dict[str, float] = field(default_factory=dict)
    given: dict[str, Any] = field(default_factory=dict)
    units: dict[str, Any] = field(default_factory=dict)

    def geometry(self) -> dict[str, float]:
        """The constructor's parameters (SI)."""
        return {
            p.name: self.params[p.name]
            for p in PARAMETERS[self.mechanism].geometry
            if p.name in self.params
        }

    def point(self) -> dict[str, float]:
        """The extra ``solve`` parameters given (the coupler point), SI."""
        return {
            p.name: self.params[p.name]
            for p in PARAMETERS[self.mechanism].point
            if p.name in self.params
        }

    def motion(self) -> dict[str, float]:
        """theta2, omega2, alpha2, jerk2 in SI."""
        return {k: self.params[k] for k in ("theta2", "omega2", "alpha2", "jerk2")}


def check_mechanism(case: Any) -> str:
    """The case's mechanism name (one of :data:`MECHANISM_NAMES`), or
    InvalidInput naming the choices."""
    if not isinstance(case, dict):
        raise InvalidInput(
            f'a case must be a JSON object like {{"mechanism": "fourbar", '
            f"...}}, got {type(case).__name__}"
        )
    twice = case.get(DUPLICATES)
    if twice:
        raise InvalidInput(
            f"the case gives {', '.join(map(repr, twice[:3]))} more than once; give each key once",
            str(twice[0]),
        )
    mech = case.get("mechanism")
    if not isinstance(mech, str) or mech not in MECHANISM_NAMES:
        shown = repr(mech) if isinstance(mech, str) else f"a {type(mech).__name__}"
        if isinstance(mech, str) and len(mech) > 40:
            shown = f"a name of {len(mech)} characters"
        raise InvalidInput(
            f"unknown mechanism {shown}; use one of {', '.join(MECHANISM_NAMES)}", "mechanism"
        )
    return mech


def read_case(case: Any) -> Case:
    """Check a case dict and convert its quantities to SI.

    Raises
    ------
    InvalidInput
        Missing or unknown key, wrong dimension, non-finite or non-positive
        length, unknown mechanism or circuit; the message names the key.
    """
    mech = check_mechanism(case)
    if mech == "loops":
        raise InvalidInput(
            "a 'loops' case is a description of vectors, read by "
            "accelab.solver.vectorloops (accelab.solver.batch.solve_case takes both)",
            "mechanism",
        )
    spec = PARAMETERS[mech]
    allowed = set(spec.names()) | {"mechanism"} | ({"circuit"} if spec.circuits else set())
    unknown = sorted(k for k in case if k not in allowed)
    if unknown:
        name = unknown[0] if isinstance(unknown[0], str) else repr(unknown[0])
        if len(name) > 40:
            name = name[:37] + "..."
        raise InvalidInput(
            f"unknown key {name!r} for a {mech} case; it takes "
            f"{', '.join(sorted(allowed - {'mechanism'}))}",
            name,
        )
    params, units = {}, {}
    for p in spec.every():
        if p.name not in case:
            if p.required:
                raise InvalidInput(f"a {mech} case needs {p.name!r} ({p.meaning})", p.name)
            if p.default is not None:
                params[p.name] = p.default
            continue
        q = parse_quantity(case[p.name], p.kind, p.name)
        value = to_si(q, p.name, p.kind, positive=p.positive)
        if not isinstance(value, float):
            raise InvalidInput(f"{p.name} must be a single value in a case (got an array)", p.name)
        params[p.name] = value
        units[p.name] = getattr(q, "units", None)
    if mech == "fourbar" and "delta3" in case and "p" not in case:
        raise InvalidInput("delta3 is given without p: a coupler point needs both", "p")
    circuit = None
    if spec.circuits:
        circuit = case.get("circuit", spec.circuits[0])
        if not isinstance(circuit, str) or circuit not in spec.circuits:
            shown = (
                repr(circuit)
                if isinstance(circuit, str) and len(circuit) <= 40
                else f"a {type(circuit).__name__}"
            )
            raise InvalidInput(f"circuit must be 'open' or 'crossed' (got {shown})", "circuit")
    return Case(mech, circuit, params, case, units)
