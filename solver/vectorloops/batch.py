"""The ``"mechanism": "loops"`` case of the batch contract (CONVENTIONS)."""

import numpy as np

from ..errors import AccelabError, InvalidInput
from ..kernels import NOT_ASSEMBLABLE, OK
from ..units import to_si
from .solve import solve, system_from_case

KEYS = {"mechanism", "vectors", "loops", "points", "theta2", "omega2", "alpha2", "jerk2"}
MOTION = (("theta2", "angle", True), ("omega2", "angular_velocity", True),
          ("alpha2", "angular_acceleration", True), ("jerk2", "angular_jerk", False))


def read_motion(case):
    values = {}
    for name, kind, required in MOTION:
        if name not in case:
            if required:
                raise InvalidInput(f"a loops case needs {name!r}", name)
            values[name] = 0.0
            continue
        values[name] = to_si(case[name], name, kind)
        if not isinstance(values[name], float):
            raise InvalidInput(f"{name} must be a single value in a batch case", name)
    return values


def _xy(z):
    return [float(z.real), float(z.imag)]


def result_dict(system, motion, i=0):
    """One position of a solved Motion as the batch contract's result object."""
    model = system.model
    vectors = {}
    for v, name in enumerate(model.names):
        th = float(motion.theta[i, v])
        entry = {"angle": float(np.remainder(th + np.pi, 2 * np.pi) - np.pi),
                 "omega": float(motion.dth[0][i, v]), "alpha": float(motion.dth[1][i, v]),
                 "jerk": float(motion.dth[2][i, v])}
        if model.length_unknown[v] >= 0:
            entry.update(length=float(motion.L[i, v]), length_dot=float(motion.dL[0][i, v]),
                         length_ddot=float(motion.dL[1][i, v]),
                         length_dddot=float(motion.dL[2][i, v]))
        vectors[name] = entry
    points = {name: {key: _xy(motion.points[n][i, p]) for n, key in enumerate("RVAJ")}
              for p, name in enumerate(model.point_names)}
    return {"ok": True, "vectors": vectors, "points": points,
            "iterations": int(motion.iterations[i]), "condition": float(motion.condition[i])}


def solve_case(case):
    """Solve one loops case; never raises (errors become error objects)."""
    try:
        unknown = sorted(set(case) - KEYS)
        if unknown:
            raise InvalidInput(f"unknown key {unknown[0]!r} in a loops case; it takes "
                               f"{', '.join(sorted(KEYS - {'mechanism'}))}", unknown[0])
        system = system_from_case(case)
        m = read_motion(case)
        motion = solve(system, m["theta2"], m["omega2"], m["alpha2"], m["jerk2"])
        if motion.status[0] != OK:
            kind = "not_assemblable" if motion.status[0] == NOT_ASSEMBLABLE else "singular"
            return {"ok": False, "error": kind, "message": str(motion.message)}
        return result_dict(system, motion)
    except AccelabError as exc:
        return {"ok": False, "error": exc.kind, "message": str(exc)}
    except Exception as exc:  # a bug: keep the batch going
        return {"ok": False, "error": "internal_error",
                "message": f"{type(exc).__name__}: {exc} (please report this case)"}
