"""The batch contract of ``accelab solve --cases`` (CONVENTIONS, "Batch contract").

A case is a dict like ``{"mechanism": "fourbar", "a": "2 in", ..., "theta2":
"30 deg", "omega2": "10 rad/s", "alpha2": "-5 rad/s^2"}``; its result is
``{"ok": true, "circuit": ..., outputs in SI}`` or ``{"ok": false, "error":
KIND, "message": ...}``. :func:`solve_case` never raises, so one bad case
never stops the others.
"""

from dataclasses import dataclass, field

from .errors import AccelabError, InvalidInput
from .units import to_si

MOTION = {"theta2": "angle", "omega2": "angular_velocity", "alpha2": "angular_acceleration",
          "jerk2": "angular_jerk"}
OPTIONAL_MOTION = {"jerk2"}

# mechanism -> {parameter: (kind, required, positive)}
GEOMETRY = {
    "fourbar": {"a": ("length", True, True), "b": ("length", True, True),
                "c": ("length", True, True), "d": ("length", True, True),
                "theta1": ("angle", False, False), "p": ("length", False, True),
                "delta3": ("angle", False, False)},
    "slidercrank": {"a": ("length", True, True), "b": ("length", True, True),
                    "c": ("length", False, False), "theta1": ("angle", False, False)},
    "invertedslidercrank": {"a": ("length", True, True), "c": ("length", True, False),
                            "d": ("length", True, True), "gamma": ("angle", True, False),
                            "theta1": ("angle", False, False)},
    "fivebar": {"a": ("length", True, True), "b": ("length", True, True),
                "c": ("length", True, True), "d": ("length", True, True),
                "f": ("length", True, True), "lam": ("dimensionless", True, False),
                "phi": ("angle", True, False), "theta1": ("angle", False, False)},
    "rotation": {"p": ("length", True, True)},
}
CIRCUITS = {"fourbar", "slidercrank", "invertedslidercrank", "fivebar"}
MECHANISM_NAMES = sorted(GEOMETRY) + ["loops"]


@dataclass
class CaseInput:
    """A batch case read and checked: the mechanism, its circuit, and every
    parameter in SI floats (m, rad, rad/s, ...)."""

    mechanism: str
    circuit: str = None
    params: dict = field(default_factory=dict)
    raw: dict = field(default_factory=dict)


def read_case(case):
    """Check a case dict and convert its quantities to SI.

    Raises
    ------
    InvalidInput
        Missing or unknown key, wrong dimension, non-finite or non-positive
        length, unknown mechanism or circuit; the message names the key.
    """
    if not isinstance(case, dict):
        raise InvalidInput(f"a case must be a JSON object, got {type(case).__name__}")
    mech = case.get("mechanism")
    if mech not in GEOMETRY:
        raise InvalidInput(f"unknown mechanism {mech!r}; use one of "
                           f"{', '.join(MECHANISM_NAMES)}", "mechanism")
    spec = GEOMETRY[mech]
    allowed = set(spec) | set(MOTION) | {"mechanism"} | ({"circuit"} if mech in CIRCUITS else set())
    unknown = sorted(set(case) - allowed)
    if unknown:
        raise InvalidInput(f"unknown key {unknown[0]!r} for a {mech} case; it takes "
                           f"{', '.join(sorted(allowed - {'mechanism'}))}", unknown[0])
    params = {}
    for name, (kind, required, positive) in list(spec.items()) + [
            (k, (v, k not in OPTIONAL_MOTION, False)) for k, v in MOTION.items()]:
        if name not in case:
            if required:
                raise InvalidInput(f"a {mech} case needs {name!r}", name)
            continue
        value = case[name]
        if kind == "dimensionless" and isinstance(value, bool):
            raise InvalidInput(f"{name} must be a number (got {value!r})", name)
        params[name] = to_si(value, name, kind, positive=positive)
        if not isinstance(params[name], float):
            raise InvalidInput(f"{name} must be a single value in a batch case", name)
    if mech == "fourbar" and "delta3" in params and "p" not in params:
        raise InvalidInput("delta3 is given without p: a coupler point needs both", "p")
    circuit = case.get("circuit", "open") if mech in CIRCUITS else None
    if mech in CIRCUITS and circuit not in ("open", "crossed"):
        raise InvalidInput(f"circuit must be 'open' or 'crossed' (got {circuit!r})", "circuit")
    return CaseInput(mech, circuit, params, case)


def build(ci):
    """The unit-aware mechanism object and solve() keyword arguments of a case.

    SI floats are passed as Quantities so the unit-aware layer sees one kind
    of input; the conversion factor is 1.
    """
    from .mechanisms import MECHANISMS
    from .units import quantity
    cls = MECHANISMS[ci.mechanism]
    geometry = {k: quantity(v, kind) for k, v in ci.params.items()
                if k in cls._geometry for kind in [cls._geometry[k][0]]}
    motion = {k: quantity(ci.params[k], MOTION[k]) for k in MOTION if k in ci.params}
    if ci.circuit:
        motion["circuit"] = ci.circuit
    if ci.mechanism == "fourbar" and "p" in ci.params:
        motion["p"] = quantity(ci.params["p"], "length")
        motion["delta3"] = quantity(ci.params.get("delta3", 0.0), "angle")
    return cls(**geometry), motion


def solve_case(case):
    """Solve one batch case; never raises (errors become error objects)."""
    try:
        if isinstance(case, dict) and case.get("mechanism") == "loops":
            try:
                from .vectorloops import solve_case as solve_loops
            except ImportError:
                raise InvalidInput("the 'loops' mechanism is not available in this build")
            return solve_loops(case)
        ci = read_case(case)
        mech, motion = build(ci)
        result = mech.solve(**motion)
        out = {"ok": True}
        if ci.circuit:
            out["circuit"] = ci.circuit
        out.update(result.to_dict())
        out["condition"] = result.condition
        return out
    except Exception as exc:  # noqa: BLE001 - one bad case never stops the batch
        return error_object(exc)


def error_object(exc):
    """The batch contract's error object for an exception raised by one case.

    Errors of the :class:`AccelabError` family give their own kind and message;
    anything else is a bug, reported as ``internal_error`` in the case so that
    the rest of the batch goes on.
    """
    if isinstance(exc, AccelabError):
        return {"ok": False, "error": exc.kind, "message": str(exc)}
    return {"ok": False, "error": "internal_error",
            "message": f"{type(exc).__name__}: {exc} (please report this case)"}


def solve_cases(cases):
    """Solve a list of cases in order (see :func:`solve_case`)."""
    return [solve_case(c) for c in cases]
