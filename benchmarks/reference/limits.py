"""Limit (toggle) positions of the closed-form mechanisms, at high precision:
the crank angles where the links that close each loop fall into line, by the
law of cosines (or a root search for the geared fivebar)."""

import math

from mpmath import mp, mpf

from .mechanisms import DPS, expj


def fourbar_limits(a, b, c, d, dps=DPS):
    """Crank angles t2 (from the ground line, in [0, pi]) where links 3 and 4
    are collinear: |A - O4| = b + c ('outer') or |b - c| ('inner'). Returns
    {kind: (t2, side)} where side = -1 means the linkage assembles for t2
    below the limit, +1 above it."""
    out = {}
    with mp.workdps(dps):
        a, b, c, d = (mpf(v) for v in (a, b, c, d))
        for kind, s, side in (("outer", b + c, -1), ("inner", abs(b - c), +1)):
            cos_t = (a * a + d * d - s * s) / (2 * a * d)
            if -1 < cos_t < 1:
                out[kind] = (mp.acos(cos_t), side)
    return out


def fourbar_rocker_limits(a, b, c, d, dps=DPS):
    """Crank angles (from the ground line) where links 2 and 3 are collinear:
    the rocker's extreme positions, where omega4 = 0 and nothing is singular.
    B then lies on the crank's line at the signed distance r = a + b
    ('extended') or a - b ('folded') from O2, and |B - O4| = c. Returns
    {kind: [t2, -t2]}."""
    out = {}
    with mp.workdps(dps):
        a, b, c, d = (mpf(v) for v in (a, b, c, d))
        for kind, r in (("extended", a + b), ("folded", a - b)):
            cos_t = (r * r + d * d - c * c) / (2 * r * d)
            if -1 < cos_t < 1:
                t = mp.acos(cos_t)
                out[kind] = [t, -t]
    return out


def slidercrank_limits(a, b, c, dps=DPS):
    """Crank angles where the rod stands perpendicular to the slide:
    a sin(t2) - c = +b ('upper') or -b ('lower'). Returns {kind: [t2, ...]}
    with both solutions of each in (-pi, pi]."""
    out = {}
    with mp.workdps(dps):
        a, b, c = (mpf(v) for v in (a, b, c))
        for kind, y in (("upper", c + b), ("lower", c - b)):
            sin_t = y / a
            if -1 < sin_t < 1:
                t = mp.asin(sin_t)
                other = (mp.pi - t) if t > 0 else (-mp.pi - t)
                out[kind] = [t, other]
    return out


def invertedslidercrank_limit(a, c, d, gamma, dps=DPS):
    """Crank angle t2 in [0, pi] where the slide line is tangent to the crank
    pin's circle about O4 reachable: |A - O4| = c |sin gamma|. The linkage
    assembles for t2 above it."""
    with mp.workdps(dps):
        a, c, d, gamma = (mpf(v) for v in (a, c, d, gamma))
        s = c * abs(mp.sin(gamma))
        cos_t = (a * a + d * d - s * s) / (2 * a * d)
        if -1 < cos_t < 1:
            return mp.acos(cos_t)
    return None


def fivebar_limits(g, lo, hi, dps=DPS):
    """Input angles t2 in [lo, hi] where the couplers b, c are collinear
    (|C - A| = b + c or |b - c|): bracketed on a grid in floats, then
    refined at high precision. Returns [(t2, kind)]."""
    fl = {k: float(v) for k, v in g.items()}

    def span(t):
        return abs(
            fl["f"]
            + fl["d"]
            * complex(math.cos(fl["lam"] * t + fl["phi"]), math.sin(fl["lam"] * t + fl["phi"]))
            - fl["a"] * complex(math.cos(t), math.sin(t))
        )

    n = 4000
    grid = [lo + (hi - lo) * i / n for i in range(n + 1)]
    dist = [span(t) for t in grid]
    out = []
    with mp.workdps(dps):
        g = {k: mpf(v) for k, v in g.items()}

        def gap(t, s):
            A = g["a"] * expj(t)
            C = g["f"] + g["d"] * expj(g["lam"] * t + g["phi"])
            return abs(C - A) - s

        for kind, s in (("outer", g["b"] + g["c"]), ("inner", abs(g["b"] - g["c"]))):
            sf = float(s)
            for i in range(n):
                if (dist[i] - sf) * (dist[i + 1] - sf) < 0:
                    bracket = (mpf(grid[i]), mpf(grid[i + 1]))
                    root = mp.findroot(lambda t, s=s: gap(t, s), bracket, solver="anderson")
                    out.append((root, kind))
    return out


def toggle_angle(a, b, c, d, dps=60):
    """Crank angle [rad] (an mpf, from the ground line) of the fourbar's toggle
    where |O4 - A| = |b - c| (links 3 and 4 folded)."""
    return fourbar_limits(a, b, c, d, dps)["inner"][0]
