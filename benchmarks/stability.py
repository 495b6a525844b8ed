"""The stability study: accuracy near a toggle (limit) position, and how
Newton-Raphson behaves as its starting guess worsens.

Near a toggle the fourbar's derivatives grow without bound (omega like
delta^-1/2, jerk like delta^-5/2 in the distance delta from the toggle in
theta2), and round-off in the position is amplified with them. A method
must then either answer accurately or refuse (NaN and a ``singular``
status); a wrong number returned silently is the failure this study looks
for. The case is the non-Grashof fourbar of :mod:`.cases`, whose crank
reaches a toggle at theta2 = acos((a^2 + d^2 - (b - c)^2) / 2ad); the
reference there is mpmath at 60 digits, each point from its own accurate
guess (:func:`.reference.at_points`).

:func:`near_toggle` gives, per method, the relative error (as
:mod:`.accuracy` defines it, worst over the outputs) at each distance, and
whether the method refused. :func:`newton_guesses` perturbs the guesses of
the general solver by a growing angle in random directions and counts the
outcomes: the intended assembly, the other assembly (a branch jump), or no
convergence (reported as an error).
"""

import math

import numpy as np

from . import accuracy
from .cases import MOTION, all_cases
from .reference import at_points, cached, toggle_angle

STUDY_CASE = "fourbar-nongrashof-open"


def distances(n):
    """``n`` distances from the toggle [rad], 1e-15 .. 0.3, log-spaced."""
    return np.logspace(-15, math.log10(0.3), n)


def near_toggle(
    n=29,
    methods=("kernels", "loops", "fd", "graphical", "mechanism"),
    fd_step=1e-4,
    case_name=STUDY_CASE,
    cache_dir=None,
):
    """Error against distance to the toggle, per method.

    Parameters
    ----------
    n : int
        Number of distances (log-spaced, 1e-15 .. 0.3 rad).
    methods : tuple of str
        Any of ``kernels`` (closed forms), ``loops`` (the general solver
        along the points, far to near), ``fd`` (finite differences of the
        closed-form position, step ``fd_step``), ``graphical`` and
        ``mechanism`` (the peer, if installed).
    cache_dir : str, optional
        Where the reference of the cycle (for the output scales) is cached.

    Returns
    -------
    dict
        ``delta`` (true distances [rad], from the 60-digit toggle angle),
        ``theta2`` [rad], ``condition`` (the kernel's), ``roundoff`` (the
        kernel's estimate, if it gives one), and per method ``errors``
        (worst relative error, NaN where refused) and ``refused`` (bool).
    """
    import mpmath as mp

    case = all_cases()[case_name]
    p = case.params
    lim = toggle_angle(p["a"], p["b"], p["c"], p["d"])
    d = distances(n)[::-1]  # far to near: the order a sweep meets them
    theta2 = np.array([float(lim) + x for x in d])
    with mp.workdps(60):
        delta = np.array([float(mp.mpf(float(t)) - lim) for t in theta2])
    kern = case.kernel(theta2)
    guesses = [{"R3": float(kern.theta3[i]), "R4": float(kern.theta4[i])} for i in range(n)]
    ref = at_points(case, theta2, guesses)
    cyc = case.theta2(181)
    scale = accuracy.scales(cached(case, cyc, cache_dir))
    out = {
        "case": case_name,
        "delta": delta.tolist(),
        "theta2": theta2.tolist(),
        "toggle_theta2": float(lim),
        "condition": np.asarray(kern.condition).tolist(),
        "methods": {},
    }
    if hasattr(kern, "roundoff"):
        out["roundoff"] = np.asarray(kern.roundoff, dtype=float).tolist()
    for key in methods:
        values = _values(key, case, theta2, fd_step)
        if values is None:
            continue
        errs = accuracy.relative_errors(values, ref, scale)
        w = accuracy.worst(errs)
        out["methods"][key] = {
            "errors": [None if np.isnan(x) else float(x) for x in w],
            "refused": np.isnan(w).tolist(),
            "label": _LABELS[key] + (f" (h = {fd_step:g} rad)" if key == "fd" else ""),
        }
    return out


_LABELS = {
    "kernels": "closed forms (unit-free and unit-aware alike)",
    "loops": "vector loops (sweep)",
    "fd": "finite differences",
    "graphical": "graphical construction",
    "mechanism": "mechanism (peer, fsolve)",
    "kimech": "kimech (peer)",
}


def _values(key, case, theta2, h):
    from .methods import NotApplicable, methods

    table = {m.key: m for m in methods()}
    if key == "loops":
        m = next(m for k, m in table.items() if k.startswith("loops"))
    elif key == "fd":
        from .methods import Method, fd_with

        m = Method("fd", "fd", "fd", 3, fd_with(h))
    elif key in table:
        m = table[key]
    else:
        return None
    if key == "kimech":  # one solve per point: its sweep gives up whole at one failure
        return _one_by_one(m, case, theta2)
    try:
        run, extract = m.prepare(case, theta2)
        with np.errstate(all="ignore"):
            return extract(run())
    except NotApplicable:
        return None
    except Exception as exc:  # a peer that gives up on the whole sweep answers nothing
        if key in ("mechanism", "kimech"):
            names = [k for k, (_, _, n) in case.outputs.items() if n <= m.order]
            return {"_error": str(exc), **{k: np.full(len(theta2), np.nan) for k in names}}
        raise


def _one_by_one(m, case, theta2):
    names = [k for k, (_, _, n) in case.outputs.items() if n <= m.order]
    out = {k: np.full(len(theta2), np.nan) for k in names}
    for i, t in enumerate(theta2):
        try:
            run, extract = m.prepare(case, np.array([t]))
            with np.errstate(all="ignore"):
                values = extract(run())
        except Exception:  # noqa: BLE001 - raised: reported, so counted as refused
            continue
        for k, v in values.items():
            out[k][i] = v[0]
    return out


def newton_guesses(offsets=None, trials=24, seed=7, points=None):
    """Outcomes of the general solver as its starting guess worsens.

    At each point (case, theta2), the guesses of the unknown angles are the
    reference solution moved by ``offset`` [rad] in a random direction
    (``trials`` directions, seeded). Each solve ends as ``same`` (the
    intended assembly, within 1e-6 rad), ``other`` (it closed the loops on
    another assembly: a branch jump), ``failed`` (it raised NoConvergence,
    NotAssemblable or Singular: reported, not silent) or ``wrong`` (it
    returned numbers that do not close the loops: must never happen).

    Returns
    -------
    dict
        ``offsets`` [rad] and per point ``same``, ``other``, ``failed``,
        ``wrong`` (fractions per offset), with the point's description.
    """
    from accelab.solver import VectorLoopLinkage
    from accelab.solver.errors import AccelabError
    from accelab.solver.units import Q_

    from .cases import description

    cases = all_cases()
    offsets = np.logspace(-3, math.log10(math.pi), 16) if offsets is None else offsets
    if points is None:
        nag = cases[STUDY_CASE]
        lim = float(toggle_angle(**{k: nag.params[k] for k in "abcd"}))
        points = [
            ("fourbar-open", math.radians(30.0), "Grashof fourbar,\ntheta2 = 30 deg"),
            (STUDY_CASE, lim + 1e-4, "non-Grashof fourbar,\n1e-4 rad from its toggle"),
        ]
    rng = np.random.default_rng(seed)
    out = {"offsets": np.asarray(offsets).tolist(), "trials": trials, "points": []}
    for name, t2, text in points:
        case = cases[name]
        true = case.kernel_guess(t2)
        other_case = all_cases()[name]
        other_case.circuit = "crossed" if case.circuit == "open" else "open"
        other = other_case.kernel_guess(t2)
        counts = {k: [] for k in ("same", "other", "failed", "wrong")}
        unknown = sorted(true)
        for off in offsets:
            c = dict.fromkeys(counts, 0)
            for _ in range(trials):
                direction = rng.normal(size=len(unknown))
                direction /= np.linalg.norm(direction)
                guess = {u: true[u] + off * direction[k] for k, u in enumerate(unknown)}
                try:
                    r = VectorLoopLinkage(**description(case, guess)).solve(
                        theta2=Q_(t2, "rad"), omega2=Q_(MOTION["omega2"], "rad/s"), order=1
                    )
                    got = {u: r.vectors[u].angle.m_as("rad") for u in unknown}
                except AccelabError:
                    c["failed"] += 1
                    continue
                if _close(got, true):
                    c["same"] += 1
                elif _close(got, other):
                    c["other"] += 1
                else:
                    c["wrong"] += 1
            for k in counts:
                counts[k].append(c[k] / trials)
        out["points"].append({"case": name, "theta2": t2, "text": text, **counts})
    return out


def _close(got, want, tol=1e-6):
    return all(abs(math.remainder(got[u] - want[u], 2 * math.pi)) < tol for u in want)


def threshold_distance(study, key="kernels"):
    """The distance [rad] below which ``key`` refuses: the geometric mean of
    the nearest answered and the farthest refused point (None if it never
    refuses)."""
    m = study["methods"].get(key)
    if not m:
        return None
    d = np.asarray(study["delta"])
    refused = np.asarray(m["refused"])
    if not refused.any():
        return None
    far_refused = d[refused].max()
    answered = d[~refused & (d < far_refused * 1e6)]
    near_answered = (
        answered[answered > far_refused].min() if (answered > far_refused).any() else far_refused
    )
    return float(math.sqrt(far_refused * near_answered))
