"""The ``"mechanism": "loops"`` case of the batch contract (docs/conventions.md#batch-format), which
:func:`accelab.solver.batch.solve_case` hands over to :func:`solve_loops_case`."""

from typing import Any

import numpy as np

from ..errors import InvalidInput, error_object
from ..parameters import MOTION
from ..results import as_plain, finite_or_refused
from ..status import NOT_ASSEMBLABLE, OK
from ..units import to_si
from .solve import solve, system_from_case

KEYS = {"mechanism", "vectors", "loops", "points"} | {p.name for p in MOTION}


def read_motion(case):
    """theta2, omega2, alpha2, jerk2 of a loops case in SI (the declared
    parameters of :data:`accelab.solver.parameters.MOTION`, with their defaults)."""
    values = {}
    for p in MOTION:
        if p.name not in case:
            if p.required:
                raise InvalidInput(f"a loops case needs {p.name!r} ({p.meaning})", p.name)
            values[p.name] = p.default
            continue
        values[p.name] = to_si(case[p.name], p.name, p.kind)
        if not isinstance(values[p.name], float):
            raise InvalidInput(f"{p.name} must be a single value in a batch case", p.name)
    return values


def result_dict(system, motion, i=0):
    """One position of a solved Motion as the batch contract's result object."""
    model = system.model
    vectors = {}
    for v, name in enumerate(model.names):
        th = float(motion.theta[i, v])
        entry = {
            "angle": float(np.remainder(th + np.pi, 2 * np.pi) - np.pi),
            "omega": float(motion.dth[0][i, v]),
            "alpha": float(motion.dth[1][i, v]),
            "jerk": float(motion.dth[2][i, v]),
        }
        if model.length_unknown[v] >= 0:
            entry.update(
                length=float(motion.L[i, v]),
                length_dot=float(motion.dL[0][i, v]),
                length_ddot=float(motion.dL[1][i, v]),
                length_dddot=float(motion.dL[2][i, v]),
            )
        vectors[name] = entry
    points = {
        name: {key: as_plain(motion.points[n][i, p]) for n, key in enumerate("RVAJ")}
        for p, name in enumerate(model.point_names)
    }
    return {
        "ok": True,
        "vectors": vectors,
        "points": points,
        "iterations": int(motion.iterations[i]),
        "condition": float(motion.condition[i]),
    }


def solve_loops_case(case: Any) -> dict[str, Any]:
    """Solve one loops case; never raises (errors become error objects)."""
    try:
        unknown = sorted((k for k in case if k not in KEYS), key=str)
        if unknown:
            raise InvalidInput(
                f"unknown key {unknown[0]!r} in a loops case; it takes "
                f"{', '.join(sorted(KEYS - {'mechanism'}))}",
                unknown[0],
            )
        system = system_from_case(case)
        m = read_motion(case)
        motion = solve(system, m["theta2"], m["omega2"], m["alpha2"], m["jerk2"])
        if motion.status[0] != OK:
            kind = "not_assemblable" if motion.status[0] == NOT_ASSEMBLABLE else "singular"
            return {"ok": False, "error": kind, "message": str(motion.message)}
        return finite_or_refused(result_dict(system, motion))
    except Exception as exc:  # noqa: BLE001 - one bad case never stops the batch
        return error_object(exc)
