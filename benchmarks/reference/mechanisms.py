"""The closed-form mechanisms in the reference: written as their vector loops
(docs/conventions.md#mechanisms) and solved by :class:`~.loops.LoopReference`, the same code
that solves every other linkage.

Each mechanism's position is first found by plain geometry in mpmath
(circle-circle intersections, a point on a line at a given distance, the two
roots of a quadratic), which also fixes the assembly (circuit) by geometry:

* fourbar, fivebar: ``open`` puts B on the left of the line from A to O4
  (fivebar: from A to C), the chapter's eq. 4.10b with the minus sign;
* slidercrank: ``open`` puts the slider on the +x side of the crank pin;
* invertedslidercrank: ``open`` is the assembly with the larger b.

That position starts the loops' Newton-Raphson (which then has nothing left
to do but confirm it), and velocity, acceleration and jerk come from the
differentiated loops. None of this shares formulas or round-off with the
closed-form kernels; tests/test_benchmarks_reference.py checks the
derivatives against mpmath's numerical differentiation of the geometric
position.
"""

from types import SimpleNamespace

from mpmath import mp, mpc, mpf

from .loops import LoopReference

DPS = 50
CIRCUIT_SIGN = {"open": 1, "crossed": -1}
ANGLE_NAMES = ("theta", "omega", "alpha", "jerk")
SLIDER_SUFFIX = ("", "_dot", "_ddot", "_dddot")
VECTOR_NAMES = ("R", "V", "A", "J")


def expj(x):
    return mpc(mp.cos(x), mp.sin(x))


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
# Each returns (angles, values, points): link angles as unit complex numbers
# e^{j theta}, values (lengths) and points as mpf / mpc, in the ground frame
# (t2 is theta2 - theta1); None where the mechanism cannot be assembled.


def fourbar_position(g, t2, sign):
    A = g["a"] * expj(t2)
    O4 = mpc(g["d"], 0)
    B = _circle_meet(A, g["b"], O4, g["c"], sign)
    if B is None:
        return None
    e3, e4 = (B - A) / g["b"], (B - O4) / g["c"]
    return {"2": expj(t2), "3": e3, "4": e4}, {}, {"A": A, "B": B, "O4": O4}


def slidercrank_position(g, t2, sign):
    A = g["a"] * expj(t2)
    h2 = g["b"] ** 2 - (A.imag - g["c"]) ** 2
    if h2 < 0:
        return None
    d = A.real + sign * mp.sqrt(h2)
    B = mpc(d, g["c"])
    return {"2": expj(t2), "3": (A - B) / g["b"]}, {"d": d}, {"A": A, "B": B}


def invertedslidercrank_position(g, t2, sign):
    """O4 B = c e^{j t4}; A lies on the line through B at t3 = t4 + gamma, at
    the signed distance b from B. |A - O4|^2 = b^2 + 2 b c cos(gamma) + c^2 is
    a quadratic in b; ``open`` takes the larger root."""
    A = g["a"] * expj(t2)
    O4 = mpc(g["d"], 0)
    s2 = abs(A - O4) ** 2
    c, gamma = g["c"], g["gamma"]
    p, q = 2 * c * mp.cos(gamma), c * c - s2
    disc = p * p / 4 - q
    if disc < 0:
        return None
    b = -p / 2 + sign * mp.sqrt(disc)
    e4 = (A - O4) / (c + b * expj(gamma))
    e4 = e4 / abs(e4)
    B = O4 + c * e4
    return ({"2": expj(t2), "3": e4 * expj(gamma), "4": e4}, {"b": b}, {"A": A, "B": B, "O4": O4})


def fivebar_position(g, t2, sign):
    t5 = g["lam"] * t2 + g["phi"]
    A = g["a"] * expj(t2)
    C = g["f"] + g["d"] * expj(t5)
    B = _circle_meet(A, g["b"], C, g["c"], sign)
    if B is None:
        return None
    return (
        {"2": expj(t2), "3": (B - A) / g["b"], "4": (B - C) / g["c"], "5": expj(t5)},
        {},
        {"A": A, "B": B, "C": C, "O5": mpc(g["f"], 0)},
    )


POSITIONS = {
    "fourbar": fourbar_position,
    "slidercrank": slidercrank_position,
    "invertedslidercrank": invertedslidercrank_position,
    "fivebar": fivebar_position,
}


def assembles(mechanism, geometry, t2, circuit="open", dps=DPS):
    """Whether the loop closes at t2 (ground frame), by the position alone."""
    with mp.workdps(dps):
        g = {k: mpf(v) for k, v in geometry.items()}
        return POSITIONS[mechanism](g, mpf(t2), CIRCUIT_SIGN[circuit]) is not None


# ---------------------------------------------------------------- as loops
def _loops(mechanism, g, th1):
    """(vectors, loops, points, links, slider) of a mechanism in the global
    frame: vectors in SI mpf, points as signed sums of vector names, the
    vector of each link, and the slider's vector (its length is d or b)."""
    if mechanism == "fourbar":
        vectors = {
            "R1": {"length": g["d"], "angle": th1},
            "R2": {"length": g["a"], "angle": "input"},
            "R3": {"length": g["b"], "angle": "unknown"},
            "R4": {"length": g["c"], "angle": "unknown"},
        }
        return (
            vectors,
            ["R2 + R3 - R4 - R1"],
            {"A": "R2", "B": "R2 + R3", "O4": "R1"},
            {2: "R2", 3: "R3", 4: "R4"},
            None,
        )
    if mechanism == "slidercrank":
        vectors = {
            "R1": {"length": "unknown", "angle": th1},
            "R2": {"length": g["a"], "angle": "input"},
            "R3": {"length": g["b"], "angle": "unknown"},
            "R4": {"length": g["c"], "angle": th1 + mp.pi / 2},
        }
        return (
            vectors,
            ["R2 - R3 - R4 - R1"],
            {"A": "R2", "B": "R1 + R4"},
            {2: "R2", 3: "R3"},
            ("R1", "d"),
        )
    if mechanism == "invertedslidercrank":
        vectors = {
            "R1": {"length": g["d"], "angle": th1},
            "R2": {"length": g["a"], "angle": "input"},
            "R4": {"length": g["c"], "angle": "unknown"},
            "R3": {"length": "unknown", "angle": {"follow": "R4", "offset": g["gamma"]}},
        }
        return (
            vectors,
            ["R2 - R3 - R4 - R1"],
            {"A": "R2", "B": "R1 + R4", "O4": "R1"},
            {2: "R2", 3: "R3", 4: "R4"},
            ("R3", "b"),
        )
    if mechanism == "fivebar":
        vectors = {
            "R1": {"length": g["f"], "angle": th1},
            "R2": {"length": g["a"], "angle": "input"},
            "R3": {"length": g["b"], "angle": "unknown"},
            "R4": {"length": g["c"], "angle": "unknown"},
            "R5": {
                "length": g["d"],
                "angle": {
                    "follow": "R2",
                    "ratio": g["lam"],
                    "offset": g["phi"] + th1 * (1 - g["lam"]),
                },
            },
        }
        return (
            vectors,
            ["R2 + R3 - R4 - R5 - R1"],
            {"A": "R2", "B": "R2 + R3", "C": "R1 + R5", "O5": "R1"},
            {2: "R2", 3: "R3", 4: "R4", 5: "R5"},
            None,
        )
    raise ValueError(f"no loops for {mechanism!r}")


def solve(
    mechanism,
    geometry,
    theta2,
    omega2,
    alpha2=0.0,
    jerk2=0.0,
    theta1=0.0,
    circuit="open",
    extra_points=(),
    dps=DPS,
):
    """Position to jerk of a closed-form mechanism, by its loops in mpmath.

    Parameters
    ----------
    geometry : dict
        Lengths [m] and angles [rad] as the kernel takes them (fourbar: a, b,
        c, d and optionally p, delta3 (a coupler point P on link 3);
        slidercrank: a, b, c; invertedslidercrank: a, c, d, gamma; fivebar:
        a, b, c, d, f, lam, phi).
    extra_points : sequence of (name, link, base, p, delta)
        Further points: at distance p from point ``base`` ('O2' for the
        origin, else a point name), at angle delta from link ``link``'s line.

    Returns
    -------
    dict or None
        theta_k, omega_k, alpha_k, jerk_k for every link k (mpf); the slider
        d .. d_dddot or b .. b_dddot; for every point X: R_X, V_X, A_X, J_X
        (mpc); A_BA. None when the mechanism cannot be assembled at theta2.
    """
    with mp.workdps(dps):
        g = {k: mpf(v) for k, v in geometry.items()}
        th1, t2 = mpf(theta1), mpf(theta2)
        found = POSITIONS[mechanism](g, t2 - th1, CIRCUIT_SIGN[circuit])
        if found is None:
            return None
        angles, values, _ = found
        vectors, loops, points, links, slider = _loops(mechanism, g, th1)
        if "p" in g:
            vectors["RP"] = {
                "length": g["p"],
                "angle": {"follow": "R3", "offset": g.get("delta3", mpf(0))},
            }
            points["P"] = "R2 + RP"
        for name, link, base, p, delta in extra_points:
            vectors[f"E{name}"] = {
                "length": mpf(p),
                "angle": {"follow": links[link], "offset": mpf(delta)},
            }
            points[name] = (points[base] + " + " if base != "O2" else "") + f"E{name}"
        ref = LoopReference(
            SimpleNamespace(name=mechanism, vectors=vectors, loops=loops, outputs={})
        )
        start = []
        for vec, kind in ref.unknowns:
            if kind == "angle":
                link = next(k for k, v in links.items() if v == vec)
                start.append(mp.arg(angles[str(link)]) + th1)
            else:
                start.append(values[slider[1]])
        motion = [mpf(x) for x in (omega2, alpha2, jerk2)]
        q = ref.solve_one(start, t2, *motion, strict=True)
        state = ref.state(q, [t2] + motion)
        out = {}
        for k, vec in links.items():
            L, th, _ = state[vec]
            for n in range(4):
                out[ANGLE_NAMES[n] + str(k)] = th[n]
        if slider:
            L, _, _ = state[slider[0]]
            for n in range(4):
                out[slider[1] + SLIDER_SUFFIX[n]] = L[n]
        for name, terms in points.items():
            for n in range(4):
                out[VECTOR_NAMES[n] + "_" + name] = ref.sum(state, ref.parse(terms), n)
        out["A_BA"] = out["A_B"] - out["A_A"]
        return out


def _point_in_rotation(L, theta, omega, alpha, jerk, dps):
    """R, V, A, J of L(t) e^{j theta(t)} (derivatives of L and theta given),
    and the parts of A along e^{j theta} and across it."""
    with mp.workdps(dps):
        th = [mpf(x) for x in (theta, omega, alpha, jerk)]
        L = [mpf(x) for x in L]
        e = expj(th[0])
        z = [LoopReference.dz(L, th, e, n) for n in range(4)]
        return z, e


def rotating_point(p, theta, omega, alpha=0.0, jerk=0.0, dps=DPS):
    """R, V, A, J of the point p e^{j theta(t)}; A_t and A_n as the parts of A
    along the tangent j e^{j theta} and along e^{j theta}."""
    (R, V, A, J), e = _point_in_rotation([p, 0, 0, 0], theta, omega, alpha, jerk, dps)
    with mp.workdps(dps):
        w = A * mp.conj(e)
        return {"R": R, "V": V, "A": A, "J": J, "A_n": w.real * e, "A_t": w.imag * 1j * e}


def slotted_link(theta, omega, alpha, jerk, p, p_dot, p_ddot, p_dddot, dps=DPS):
    """A block at the distance p(t) along a link turning as theta(t).

    A is split as the chapter does (eq. 7.19) but from the derivatives alone:
    the point of the link under the block (fixed radius p(0)) gives V_t, A_t,
    A_n; the slip is p'' e^{j theta} (V_slip = p' e^{j theta}); the Coriolis
    part is whatever of A remains.
    """
    (R, V, A, J), e = _point_in_rotation(
        [p, p_dot, p_ddot, p_dddot], theta, omega, alpha, jerk, dps
    )
    (_, V_t, A_fixed, _), _ = _point_in_rotation([p, 0, 0, 0], theta, omega, alpha, jerk, dps)
    with mp.workdps(dps):
        w = A_fixed * mp.conj(e)
        out = {
            "R": R,
            "V": V,
            "A": A,
            "J": J,
            "V_t": V_t,
            "V_slip": V - V_t,
            "A_n": w.real * e,
            "A_t": w.imag * 1j * e,
            "A_slip": mpf(p_ddot) * e,
        }
        out["A_coriolis"] = A - A_fixed - out["A_slip"]
        return out


def batch_branch(
    mechanism, geometry, theta2, omega2, alpha2=0.0, jerk2=0.0, theta1=0.0, circuit="open", dps=DPS
):
    """The reference as the batch solver reports it: SI floats, vectors as
    [x, y], named as in docs/conventions.md#outputs (with a coupler point P: A_P, J_P ...; for
    the inverted slider-crank also A_coriolis, A_slip, V_slip and A_A4, the
    acceleration of the point of link 4 under A). None if not assemblable."""
    args = (mechanism, geometry, theta2, omega2, alpha2, jerk2, theta1, circuit)
    want = solve(*args, dps=dps)
    if want is None:
        return None
    if mechanism == "invertedslidercrank":
        with mp.workdps(dps):
            rel = (want["R_A"] - want["R_O4"]) * expj(-want["theta4"])
            want = solve(*args, extra_points=[("A4", 4, "O4", abs(rel), mp.arg(rel))], dps=dps)
            e3 = expj(want["theta3"])
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
