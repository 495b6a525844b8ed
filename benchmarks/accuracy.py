"""How far a method's numbers are from the reference.

The relative error of output x at one position is

    |x - x_ref| / max(|x_ref|, s)

where s is the median of |x_ref| over the case's whole benchmark cycle: a
plain relative error where x is of its usual size or larger (near a toggle
the derivatives grow without bound, and are judged against their own size),
and an error relative to the output's typical size where x passes through
zero (where a pointwise relative error means nothing). Angle differences are
taken modulo 2 pi. A position where a method returned NaN for any output
(it refused, or refused the derivatives, as a kernel does at a ``singular``
position) has no error; :func:`summary` counts it as flagged.
"""

import numpy as np


def scales(reference):
    """Median |value| of each output over a cycle (dict name -> float)."""
    return {k: float(np.median(np.abs(v))) for k, v in reference.items()}


def relative_errors(values, reference, scale, names=None):
    """Per-position relative error of every output (dict name -> array).

    Parameters
    ----------
    values, reference : dict name -> array
        The method's outputs and the reference's, same positions, SI.
    scale : dict name -> float
        The typical size of each output (see :func:`scales`).
    names : iterable, optional
        Outputs to compare (default: those present in both).
    """
    names = [k for k in (names or reference) if k in values and k in reference]
    out = {}
    for k in names:
        x = np.asarray(values[k], dtype=float)
        r = np.asarray(reference[k], dtype=float)
        diff = x - r
        if k.startswith("theta") or k.endswith(".theta"):
            diff = np.angle(np.exp(1j * diff))
        with np.errstate(invalid="ignore"):
            out[k] = np.abs(diff) / np.maximum(np.abs(r), scale[k])
    return out


def worst(errors):
    """Per-position worst error over the outputs; NaN where any output is NaN
    (the method refused that position, or part of it: a kernel that reports
    ``singular`` still gives the position but no derivatives)."""
    stack = np.vstack([np.asarray(e, dtype=float) for e in errors.values()])
    return np.max(stack, axis=0)  # NaN propagates


def summary(errors):
    """Worst error over positions and outputs, per output and overall, and
    the number of positions the method refused (NaN)."""
    per_output = {
        k: (float(np.nanmax(e)) if np.any(~np.isnan(e)) else None) for k, e in errors.items()
    }
    w = worst(errors)
    flagged = int(np.sum(np.isnan(w)))
    return {
        "worst": float(np.nanmax(w)) if flagged < w.size else None,
        "per_output": per_output,
        "flagged": flagged,
        "positions": int(w.size),
    }
