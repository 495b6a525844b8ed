"""An independent reference for the closed-form kernels, at 50 significant digits.

Nothing here calls :mod:`solver`. Each mechanism's position is found by plain
geometry with mpmath (circle-circle intersections, a point on a line at a
given distance, the two roots of a quadratic), as a function of time through
the input's motion law

    theta2(t) = theta2 + omega2 t + alpha2 t^2 / 2 + jerk2 t^3 / 6,

and every derivative (omega, alpha, jerk; d_dot ... ; V, A, J of points) is
taken by high-precision numerical differentiation of that position
(:func:`mpmath.diff`, central differences with a step near 1e-55 s evaluated
at several hundred bits). So the reference shares with the kernels neither
their formulas nor their round-off.

The assembly (circuit) each function returns is fixed here by geometry:

* fourbar, fivebar: ``open`` puts B on the left of the line from A to O4
  (fivebar: from A to C); the chapter's eq. 4.10b with the minus sign
  (checked in tests/test_kernels_accuracy.py);
* slidercrank: ``open`` puts the slider on the +x side of the crank pin;
* invertedslidercrank: ``open`` is the assembly with the larger b.

Also here: the limit (toggle) angles of each mechanism at high precision, and
the checker's comparison rule (CONVENTIONS' batch reference check) used by the
near-limit and reference-case tests.
"""

import math

import mpmath
from mpmath import mp, mpf, mpc

DPS = 50
CIRCUIT_SIGN = {"open": 1, "crossed": -1}


def _expj(x):
    return mpc(mp.cos(x), mp.sin(x))


def _law(theta2, omega2, alpha2, jerk2):
    th, w, al, j = (mpf(v) for v in (theta2, omega2, alpha2, jerk2))
    return lambda t: th + w * t + al * t * t / 2 + j * t ** 3 / 6


def _circle_meet(p, r, q, s, sign):
    """Where the circle (centre p, radius r) meets the circle (q, s): the point
    on the left of p->q for sign +1, on the right for -1; None if they miss."""
    dist = abs(q - p)
    along = (r * r - s * s + dist * dist) / (2 * dist)
    h2 = r * r - along * along
    if h2 < 0:
        return None
    u = (q - p) / dist
    return p + u * (along + sign * 1j * mp.sqrt(h2))


# ---------------------------------------------------------------- positions
# Each returns (angles, values): angles as unit complex numbers e^{j theta},
# values (lengths, point positions) as mpf / mpc. t2 is theta2 - theta1 (the
# ground frame); the caller turns the result into the global frame.

def fourbar_position(g, t2, sign):
    A = g["a"] * _expj(t2)
    O4 = mpc(g["d"], 0)
    B = _circle_meet(A, g["b"], O4, g["c"], sign)
    if B is None:
        return None
    e3, e4 = (B - A) / g["b"], (B - O4) / g["c"]
    pts = {"A": A, "B": B, "O4": O4}
    if "p" in g:
        pts["P"] = A + g["p"] * e3 * _expj(g.get("delta3", 0))
    return {"2": _expj(t2), "3": e3, "4": e4}, {}, pts


def slidercrank_position(g, t2, sign):
    A = g["a"] * _expj(t2)
    h2 = g["b"] ** 2 - (A.imag - g["c"]) ** 2
    if h2 < 0:
        return None
    d = A.real + sign * mp.sqrt(h2)
    B = mpc(d, g["c"])
    return {"2": _expj(t2), "3": (A - B) / g["b"]}, {"d": d}, {"A": A, "B": B}


def invertedslidercrank_position(g, t2, sign):
    """O4 B = c e^{j t4}; A lies on the line through B at t3 = t4 + gamma, at
    the signed distance b from B. |A - O4|^2 = b^2 + 2 b c cos(gamma) + c^2 is
    a quadratic in b; ``open`` takes the larger root."""
    A = g["a"] * _expj(t2)
    O4 = mpc(g["d"], 0)
    s2 = abs(A - O4) ** 2
    c, gamma = g["c"], g["gamma"]
    # b^2 + (2 c cos gamma) b + (c^2 - s^2) = 0
    p, q = 2 * c * mp.cos(gamma), c * c - s2
    disc = p * p / 4 - q
    if disc < 0:
        return None
    b = -p / 2 + sign * mp.sqrt(disc)
    e4 = (A - O4) / (c + b * _expj(gamma))
    e4 = e4 / abs(e4)
    B = O4 + c * e4
    return ({"2": _expj(t2), "3": e4 * _expj(gamma), "4": e4}, {"b": b},
            {"A": A, "B": B, "O4": O4})


def fivebar_position(g, t2, sign):
    t5 = g["lam"] * t2 + g["phi"]
    A = g["a"] * _expj(t2)
    C = g["f"] + g["d"] * _expj(t5)
    B = _circle_meet(A, g["b"], C, g["c"], sign)
    if B is None:
        return None
    return ({"2": _expj(t2), "3": (B - A) / g["b"], "4": (B - C) / g["c"], "5": _expj(t5)},
            {}, {"A": A, "B": B, "C": C, "O5": mpc(g["f"], 0)})


POSITIONS = {"fourbar": fourbar_position, "slidercrank": slidercrank_position,
             "invertedslidercrank": invertedslidercrank_position, "fivebar": fivebar_position}
SLIDER = {"slidercrank": "d", "invertedslidercrank": "b"}
ANGLE_NAMES = ("theta", "omega", "alpha", "jerk")
SLIDER_SUFFIX = ("", "_dot", "_ddot", "_dddot")
VECTOR_NAMES = ("R", "V", "A", "J")


def solve(mechanism, geometry, theta2, omega2, alpha2=0.0, jerk2=0.0, theta1=0.0,
          circuit="open", extra_points=(), dps=DPS):
    """Position to jerk of ``mechanism`` by geometry and numerical differentiation.

    Parameters
    ----------
    geometry : dict
        Lengths [m] and angles [rad] as the kernel takes them (fourbar: a, b,
        c, d and optionally p, delta3; slidercrank: a, b, c; invertedslidercrank:
        a, c, d, gamma; fivebar: a, b, c, d, f, lam, phi).
    extra_points : sequence of (name, link, base, p, delta)
        Further points: at distance p from point ``base`` ('O2' for the
        origin, else a point name), at angle delta from link ``link``'s line.

    Returns
    -------
    dict or None
        theta_k, omega_k, alpha_k, jerk_k for every link k (global angles,
        continuous near the value at t = 0); the slider d.. or b..; for every
        point X: R_X, V_X, A_X, J_X (mpc); A_BA. None when the mechanism
        cannot be assembled at theta2.
    """
    with mp.workdps(dps):
        g = {k: mpf(v) for k, v in geometry.items()}
        rot = _expj(mpf(theta1))
        law = _law(mpf(theta2) - mpf(theta1), omega2, alpha2, jerk2)
        position = POSITIONS[mechanism]
        sign = CIRCUIT_SIGN[circuit]
        first = position(g, law(mpf(0)), sign)
        if first is None:
            return None
        # reference angles (floats) so that the angles stay continuous in t
        ref = {k: float(mp.arg(e * rot)) for k, e in first[0].items()}
        cache = {}

        def state(t):
            key = (t, mp.prec)
            if key not in cache:
                found = position(g, law(t), sign)
                angles, values, pts = found
                out = {}
                for k, e in angles.items():
                    out["theta" + k] = ref[k] + mp.arg(e * rot * _expj(-ref[k]))
                out["theta2"] = law(t) + mpf(theta1)   # the input itself, unwrapped
                for k, v in values.items():
                    out[k] = v
                for k, z in pts.items():
                    out["R_" + k] = z * rot
                for name, link, base, p, delta in extra_points:
                    e = angles[str(link)] * rot * _expj(mpf(delta))
                    origin = 0 if base == "O2" else out["R_" + base]
                    out["R_" + name] = origin + mpf(p) * e
                cache[key] = out
            return cache[key]

        result = {}
        for name, value in state(mpf(0)).items():
            result[name] = value
            for n in (1, 2, 3):
                deriv = mpmath.diff(lambda t, name=name: state(t)[name], mpf(0), n)
                if name.startswith("theta"):
                    result[ANGLE_NAMES[n] + name[5:]] = deriv
                elif name.startswith("R_"):
                    result[VECTOR_NAMES[n] + name[1:]] = deriv
                else:
                    result[name + SLIDER_SUFFIX[n]] = deriv
        if "A_A" in result and "A_B" in result:
            result["A_BA"] = result["A_B"] - result["A_A"]
        return result


def _diffs(f, n_max=3):
    """f(0), f'(0) .. f^(n_max)(0) of a function of time t [s]."""
    return [f(mpf(0))] + [mpmath.diff(f, mpf(0), n) for n in range(1, n_max + 1)]


def rotating_point(p, theta, omega, alpha=0.0, jerk=0.0, dps=DPS):
    """R, V, A, J of the point p e^{j theta(t)}; A_t and A_n as the parts of A
    along the tangent j e^{j theta} and along e^{j theta}."""
    with mp.workdps(dps):
        law = _law(theta, omega, alpha, jerk)
        R, V, A, J = _diffs(lambda t: mpf(p) * _expj(law(t)))
        e = _expj(law(mpf(0)))
        along = (A * mp.conj(e)).real
        across = (A * mp.conj(e)).imag
        return {"R": R, "V": V, "A": A, "J": J, "A_n": along * e, "A_t": across * 1j * e}


def slotted_link(theta, omega, alpha, jerk, p, p_dot, p_ddot, p_dddot, dps=DPS):
    """A block at the distance p(t) along a link turning as theta(t).

    A is split as the chapter does (eq. 7.19) but from differentiation alone:
    the point of the link under the block (fixed radius p(0)) gives V_t, A_t,
    A_n; the slip is p'' e^{j theta} (V_slip = p' e^{j theta}); the Coriolis
    part is whatever of A remains.
    """
    with mp.workdps(dps):
        law = _law(theta, omega, alpha, jerk)
        dist = _law(p, p_dot, p_ddot, p_dddot)
        R, V, A, J = _diffs(lambda t: dist(t) * _expj(law(t)))
        _, V_t, A_fixed, _ = _diffs(lambda t: mpf(p) * _expj(law(t)))
        e = _expj(law(mpf(0)))
        w = A_fixed * mp.conj(e)
        out = {"R": R, "V": V, "A": A, "J": J, "V_t": V_t, "V_slip": V - V_t,
               "A_n": w.real * e, "A_t": w.imag * 1j * e, "A_slip": mpf(p_ddot) * e}
        out["A_coriolis"] = A - A_fixed - out["A_slip"]
        return out


def batch_branch(mechanism, geometry, theta2, omega2, alpha2=0.0, jerk2=0.0, theta1=0.0,
                 circuit="open", dps=DPS):
    """The reference as the batch solver reports it: SI floats, vectors as
    [x, y], named as in CONVENTIONS (with a coupler point P: A_P, J_P ...; for
    the inverted slider-crank also A_coriolis, A_slip, V_slip and A_A4, the
    acceleration of the point of link 4 under A). None if not assemblable."""
    args = (mechanism, geometry, theta2, omega2, alpha2, jerk2, theta1, circuit)
    want = solve(*args, dps=dps)
    if want is None:
        return None
    if mechanism == "invertedslidercrank":
        with mp.workdps(dps):
            rel = (want["R_A"] - want["R_O4"]) * _expj(-want["theta4"])
            want = solve(*args, extra_points=[("A4", 4, "O4", abs(rel), mp.arg(rel))], dps=dps)
            e3 = _expj(want["theta3"])
            want["A_slip"] = want["b_ddot"] * e3
            want["V_slip"] = want["b_dot"] * e3
            want["A_coriolis"] = want["A_A"] - want["A_A4"] - want["A_slip"]
    if "R_P" in want:
        want["A_PA"] = want["A_P"] - want["A_A"]
    out = {}
    for k, v in want.items():
        if k.endswith("O4") or k.endswith("O5") or k[-1:] == "2" and k[:-1] in ANGLE_NAMES:
            continue
        out[k] = [float(v.real), float(v.imag)] if isinstance(v, mpc) else float(v)
    out["circuit"] = circuit
    return out


# ---------------------------------------------------------------- limit angles

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
        return abs(fl["f"] + fl["d"] * complex(math.cos(fl["lam"] * t + fl["phi"]),
                                               math.sin(fl["lam"] * t + fl["phi"]))
                   - fl["a"] * complex(math.cos(t), math.sin(t)))

    n = 4000
    grid = [lo + (hi - lo) * i / n for i in range(n + 1)]
    dist = [span(t) for t in grid]
    out = []
    with mp.workdps(dps):
        g = {k: mpf(v) for k, v in g.items()}

        def gap(t, s):
            A = g["a"] * _expj(t)
            C = g["f"] + g["d"] * _expj(g["lam"] * t + g["phi"])
            return abs(C - A) - s

        for kind, s in (("outer", g["b"] + g["c"]), ("inner", abs(g["b"] - g["c"]))):
            sf = float(s)
            for i in range(n):
                if (dist[i] - sf) * (dist[i + 1] - sf) < 0:
                    root = mp.findroot(lambda t: gap(t, s), (mpf(grid[i]), mpf(grid[i + 1])),
                                       solver="anderson")
                    out.append((root, kind))
    return out


def assembles(mechanism, geometry, t2, circuit="open", dps=DPS):
    """Whether the loop closes at t2 (ground frame), by the position alone."""
    with mp.workdps(dps):
        g = {k: mpf(v) for k, v in geometry.items()}
        return POSITIONS[mechanism](g, mpf(t2), CIRCUIT_SIGN[circuit]) is not None


# ---------------------------------------------------------------- comparison

def order_of(name):
    """Derivative order of an output: -1 angle, 0 position/length, 1..3."""
    if name.startswith("theta"):
        return -1
    for prefix, n in (("omega", 1), ("alpha", 2), ("jerk", 3), ("V_", 1), ("A_", 2),
                      ("J_", 3), ("R_", 0)):
        if name.startswith(prefix):
            return n
    for suffix, n in (("_dddot", 3), ("_ddot", 2), ("_dot", 1)):
        if name.endswith(suffix):
            return n
    return 0


def angle_error(x, y):
    """|x - y| modulo 2 pi [rad]."""
    return abs(math.remainder(float(x) - float(y), 2 * math.pi))


def _group(name):
    """(derivative order, 'angular' or 'linear') of an output."""
    return order_of(name), ("angular" if name[:5] in ("omega", "alpha") or
                            name.startswith("jerk") else "linear")


def scales(ref):
    """The largest magnitude of each (order, kind) group of outputs in ``ref``.
    Angular groups also count the products that enter them: omega_k^2 for
    order 2, |omega_k|^3 and |omega_k alpha_k| for order 3."""
    out = {}

    def grow(key, value):
        out[key] = max(out.get(key, 0.0), float(abs(value)))

    for k, v in ref.items():
        if k.startswith("theta"):
            continue
        grow(_group(k), v)
        if k.startswith("omega"):
            grow((2, "angular"), v * v)
            grow((3, "angular"), v ** 3)
            alpha = ref.get("alpha" + k[5:])
            if alpha is not None:
                grow((3, "angular"), v * alpha)
    return out


def errors(got, ref, floor=1e-3):
    """Error of each output in ``got`` relative to ``ref``.

    Angles: the absolute difference modulo 2 pi [rad]. Other outputs: |got -
    ref| / max(|ref|, floor * scale), where scale is the largest magnitude of
    the outputs of the same derivative order and kind (angular or linear;
    see :func:`scales`), so an output that passes through zero is judged
    against the size of its neighbours. Vectors compare by the length of the
    difference.
    """
    sizes = scales(ref)
    out = {}
    for k, v in got.items():
        if k not in ref:
            continue
        if k.startswith("theta"):
            out[k] = angle_error(v, ref[k])
            continue
        with mp.workdps(DPS):
            vector = isinstance(ref[k], (mpc, complex)) or isinstance(v, complex)
            got_mp = mpc(complex(v)) if vector else mpf(float(v))
            diff = float(abs(got_mp - (mpc(ref[k]) if vector else ref[k])))
        out[k] = diff / max(float(abs(ref[k])), floor * sizes.get(_group(k), 0.0), 1e-30)
    return out


#: outputs the reference check requires, and those that pick the branch
REQUIRED = {
    "fourbar": ["theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4", "jerk3", "jerk4",
                "A_A", "A_B"],
    "slidercrank": ["theta3", "omega3", "alpha3", "d", "d_dot", "d_ddot", "A_A", "A_B"],
    "invertedslidercrank": ["theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4",
                            "b", "b_dot", "b_ddot", "A_A", "A_B", "A_coriolis"],
    "fivebar": ["theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4", "A_A", "A_B", "A_C"],
    "rotation": ["A", "A_t", "A_n"],
}
BRANCH_KEYS = {"fourbar": ["theta3", "theta4"], "slidercrank": ["theta3", "d"],
               "invertedslidercrank": ["theta4", "b"], "fivebar": ["theta3", "theta4"],
               "rotation": []}


def _magnitude(v):
    return math.hypot(*v) if isinstance(v, list) else abs(v)


def _close(name, got, want, scale, rtol):
    if order_of(name) == -1:
        return isinstance(got, (int, float)) and angle_error(got, want) <= max(rtol, 1e-10) * 10
    tol = rtol * max(_magnitude(want), 1e-3 * scale)
    if isinstance(want, list):
        return (isinstance(got, list) and len(got) == 2
                and math.hypot(got[0] - want[0], got[1] - want[1]) <= tol)
    return isinstance(got, (int, float)) and abs(got - want) <= tol


def compare_to_branches(mech, result, branches, rtol, circuit=None):
    """'' when a batch result (SI, vectors as [x, y]) matches one of the
    expected branches to ``rtol``, else the reason. The rules of the
    project's reference check (shared/tools/check_reference.py): the branch
    is the one whose positions match to 1e-6; angles compare modulo 2 pi to
    10 rtol; other outputs to rtol relative, but never tighter than rtol
    times 1e-3 of the largest output of their derivative order."""
    if not result.get("ok"):
        return f"reported {result.get('error')}: {result.get('message')}"
    missing = [k for k in REQUIRED[mech] if k not in result]
    if missing:
        return f"missing outputs {missing}"
    found = [b for b in branches
             if all(_close(k, result.get(k), b[k], 1, 1e-6) for k in BRANCH_KEYS[mech])]
    if not found:
        return "positions match no branch"
    branch = found[0]
    if circuit and branch.get("circuit") and branch["circuit"] != circuit:
        return f"asked for {circuit}, got the {branch['circuit']} branch"
    scales = {}
    for k, v in branch.items():
        if isinstance(v, (int, float, list)) and not isinstance(v, bool):
            scales[order_of(k)] = max(scales.get(order_of(k), 0), _magnitude(v))
    bad = [k for k, v in branch.items() if k in result and not isinstance(v, str)
           and not _close(k, result[k], v, scales.get(order_of(k), 1), rtol)]
    return f"{bad} off, e.g. {bad[0]}: got {result[bad[0]]}, want {branch[bad[0]]}" if bad else ""
