"""The reference along the benchmark's cycles, cached, and at single points
near a toggle (where the assembly must come from an accurate position).

The reference of a cycle is cached as JSON (:func:`cached`), keyed by the
case, the crank angles and the precision, so a rerun costs nothing.
"""

import hashlib
import json
import os

import mpmath as mp
import numpy as np

from ..cases import MOTION
from .loops import DPS, LoopReference


def cycle_key(case, theta2, dps=DPS, motion=None):
    """A hash of everything the reference of a cycle depends on."""
    blob = json.dumps(
        {
            "vectors": case.vectors,
            "loops": case.loops,
            "guess": case.guess,
            "outputs": case.outputs,
            "theta2": [float(t).hex() for t in theta2],
            "dps": dps,
            "motion": dict(MOTION, **(motion or {})),
            "version": 2,
        },
        sort_keys=True,
        default=str,
    )
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def cached(case, theta2, cache_dir=None, dps=DPS):
    """Reference outputs of ``case`` along ``theta2`` (dict name -> float
    array), read from ``cache_dir`` when computed before."""
    key = cycle_key(case, theta2, dps)
    path = os.path.join(cache_dir, f"reference-{case.name}-{key}.json") if cache_dir else None
    if path and os.path.exists(path):
        with open(path) as f:
            data = json.load(f)
    else:
        data = LoopReference(case).sweep(theta2, case.guess, dps=dps)
        if path:
            os.makedirs(cache_dir, exist_ok=True)
            with open(path, "w") as f:
                json.dump(data, f)
    return {k: np.array(v, dtype=float) for k, v in data.items()}


def at_points(case, theta2, guesses, dps=60, motion=None):
    """Reference at separate crank angles (no continuation), each from its own
    guess (dict vector -> float), iterated to full precision: for points near
    a toggle, where the assembly must come from an accurate position.
    Raises ArithmeticError if Newton-Raphson left the guessed assembly.
    Returns dict name -> float array."""
    ref = LoopReference(case)
    m = dict(MOTION, **(motion or {}))
    out = {k: [] for k in case.outputs}
    with mp.workdps(dps):
        for t, g in zip(theta2, guesses):
            start = ref.start(g)
            q = ref.solve_one(start, float(t), m["omega2"], m["alpha2"], m["jerk2"], strict=True)
            for k, u in enumerate(ref.unknowns):
                if abs(float(q[0][k]) - start[k]) > 1e-5:
                    raise ArithmeticError(
                        f"{case.name}: the reference left the guessed "
                        f"assembly at theta2 = {float(t)!r} ({u})"
                    )
            ref.record(out, q, float(t), m)
    return {k: np.array([float(x) for x in v]) for k, v in out.items()}
