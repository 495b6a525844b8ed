"""What the tests of accelab.solver.vectorloops share: example linkages, comparisons,
the closed-form fourbar's assemblies, and the loops closed in mpmath by the
project's one high-precision reference (accelab.benchmarks.reference)."""

import numpy as np

from accelab.benchmarks.cases import from_example
from accelab.benchmarks.reference import LoopReference
from accelab.solver import Q_
from accelab.solver.kernels import fourbar as fourbar_kernel
from accelab.solver.vectorloops import VectorLoopLinkage
from accelab.solver.vectorloops import sweep as sweep_module
from accelab.solver.vectorloops.description import read_description
from accelab.solver.vectorloops.examples import EXAMPLES, fourbar
from accelab.solver.vectorloops.solve import system_from_case

MOTION = dict(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3")


ANGLES = Q_(np.linspace(0, 350, 36), "deg")


def close(x, y, rtol=1e-12):
    x, y = np.asarray(x), np.asarray(y)
    scale = np.max(np.abs(y))
    return np.max(np.abs(x - y)) <= rtol * scale


def sweep(name, **kw):
    return VectorLoopLinkage(**EXAMPLES[name](**kw)).solve(
        theta2=ANGLES, omega2="10 rad/s", alpha2="-5 rad/s^2", jerk2="40 rad/s^3"
    )


CYCLE = np.radians(np.linspace(0.0, 360.0, 361)[:-1])


def system_of(desc):
    return system_from_case(desc)


def rel_err(x, y):
    """Largest difference over the largest magnitude of the reference (NaN-aware)."""
    x, y = np.asarray(x), np.asarray(y)
    return np.nanmax(np.abs(x - y)) / max(np.nanmax(np.abs(y)), 1e-300)


def same_motion(a, b, rtol=1e-12):
    assert np.array_equal(a.status, b.status)
    assert np.array_equal(np.isnan(a.q), np.isnan(b.q))
    assert rel_err(a.q, b.q) <= rtol
    for x, y in zip(a.dth + a.dL + a.points, b.dth + b.dL + b.points):
        if np.isfinite(y).any():
            assert rel_err(x, y) <= rtol


def fourbar_desc(a, b, c, d, guess3, guess4):
    """A fourbar as loops with lengths in metres and guesses in radians."""
    return fourbar(
        a=f"{a} m",
        b=f"{b} m",
        c=f"{c} m",
        d=f"{d} m",
        guess3=f"{guess3} rad",
        guess4=f"{guess4} rad",
    )


def guesses_on(circuit, a, b, c, d, theta2, miss=0.1):
    """Guesses a little off the closed-form assembly at theta2 [rad]."""
    m = fourbar_kernel.solve(a, b, c, d, theta2, 1.0, circuit=circuit)
    return float(m.theta3) + miss, float(m.theta4) - miss


def on_circuit(motion, a, b, c, d, theta2, circuit, tol=1e-9):
    """Where the loops solution (R3, R4 angles) is the closed form's ``circuit``."""
    m = fourbar_kernel.solve(a, b, c, d, theta2, 1.0, circuit=circuit)
    return (np.abs(np.exp(1j * motion.theta[:, 2]) - np.exp(1j * m.theta3)) < tol) & (
        np.abs(np.exp(1j * motion.theta[:, 3]) - np.exp(1j * m.theta4)) < tol
    )


SWEEPS = {
    "cycle": CYCLE,
    "two_turns_backwards": np.radians(np.linspace(720.0, 0.0, 1441)),
    "uneven_back_and_forth": np.radians(
        np.concatenate(
            [
                np.sort(np.random.default_rng(7).uniform(0, 300, 400)),
                np.linspace(300, 100, 151),
                [100.0, 100.0, 100.5],
            ]
        )
    ),
}


LINKAGES = {"crank_rocker": (2.0, 6.0, 9.0, 7.0), "double_crank": (6.0, 7.0, 9.0, 2.0)}


NON_GRASHOF = (5.0, 3.5, 4.0, 6.0)  # a triple rocker: the crank reaches |theta2| <= 85.4 deg


def crossed_q(a, b, c, d, t):
    m = fourbar_kernel.solve(a, b, c, d, t, 1.0, circuit="crossed")
    return np.array([float(m.theta3), float(m.theta4)])


def start_on_crossed_once(system, monkeypatch, a, b, c, d, thetas):
    """Make Newton-Raphson start from the crossed assembly, once at each of the
    given input angles: a deliberately bad guess. The sweep's own prediction is
    untouched, so it is what the converged solution is checked against."""
    bad = {float(t) for t in thetas}
    newton1, newton = system.newton1, system.newton

    def newton1_bad(q0, theta2, *args, **kw):
        if float(theta2) in bad:
            bad.discard(float(theta2))
            q0 = crossed_q(a, b, c, d, float(theta2))
        return newton1(q0, theta2, *args, **kw)

    def newton_bad(q0, theta2, *args, **kw):
        q0 = np.array(q0, dtype=float)
        for k, t in enumerate(theta2):
            if float(t) in bad:
                bad.discard(float(t))
                q0[k] = crossed_q(a, b, c, d, float(t))
        return newton(q0, theta2, *args, **kw)

    monkeypatch.setattr(system, "newton1", newton1_bad)
    monkeypatch.setattr(system, "newton", newton_bad)
    return bad


def counting(monkeypatch, name, owner=sweep_module.Sweep):
    """Count the calls of ``owner.name`` (a method of Sweep, or a function of a
    module such as accelab.solver.vectorloops.assembly)."""
    calls = {"n": 0}
    method = getattr(owner, name)

    def counted(*args):
        calls["n"] += 1
        return method(*args)

    monkeypatch.setattr(owner, name, counted)
    return calls


def mp_solver(desc):
    """The project's reference (accelab.benchmarks.reference: Newton-Raphson in mpmath on
    the loop equations alone) for a description: ``(model, q_at, points_at)``
    with ``q_at(theta2, start)`` the unknowns in the order of
    ``model.unknown_names`` and ``points_at(theta2, q)`` every named point."""
    model = read_description(desc)
    ref = LoopReference(from_example("test", "", desc))
    order = [ref.index[(vec, what)] for vec, what in (u.split(".") for u in model.unknown_names)]
    terms = [ref.parse(desc["points"][name]) for name in model.point_names]

    def q_at(theta2, start):
        guess = [None] * len(order)
        for u, k in enumerate(order):
            guess[k] = start[u]
        q = ref.position(guess, theta2)
        return [q[k] for k in order]

    def points_at(theta2, q):
        q_ref = [None] * len(order)
        for u, k in enumerate(order):
            q_ref[k] = q[u]
        state = ref.state([q_ref], [theta2])
        return [ref.sum(state, t, 0) for t in terms]

    return model, q_at, points_at


def jet_of_vector(L, th):
    """Taylor coefficients (in t) of z = L e^{j theta} to third order, from the
    derivatives [f, f', f'', f'''] of L and theta: an independent composition."""
    l0, l1, l2, l3 = L[0], L[1], L[2] / 2, L[3] / 6
    u1, u2, u3 = 1j * th[1], 1j * th[2] / 2, 1j * th[3] / 6
    e0 = np.exp(1j * th[0])
    e = [e0, e0 * u1, e0 * (u2 + u1 * u1 / 2), e0 * (u3 + u1 * u2 + u1**3 / 6)]
    lj = [l0, l1, l2, l3]
    return [sum(lj[k] * e[n - k] for k in range(n + 1)) * [1, 1, 2, 6][n] for n in range(4)]


BATCH_MOTION = {
    "theta2": "50 deg",
    "omega2": "15 rad/s",
    "alpha2": "-20 rad/s^2",
    "jerk2": "300 rad/s^3",
}


def xy(v):
    return complex(*v)


CHANGE_POINT = (2.0, 5.0, 4.0, 3.0)  # [in]


PARALLELOGRAM = (1.0, 3.0, 1.0, 3.0)  # change points at 0 and 180 deg


KITE = (2.0, 5.0, 5.0, 2.0)  # a = d, b = c: at 0 deg A sits on O4


def fourbar_in(a, b, c, d, theta2, circuit):
    """The fourbar in inches as loops, guesses exactly on the closed form's circuit."""
    m = fourbar_kernel.solve(a, b, c, d, theta2, 1.0, circuit=circuit)
    return fourbar(
        a=f"{a} in",
        b=f"{b} in",
        c=f"{c} in",
        d=f"{d} in",
        guess3=f"{float(m.theta3)!r} rad",
        guess4=f"{float(m.theta4)!r} rad",
    )


def circuit_of(motion, linkage, t2, circuit):
    return on_circuit(motion, *linkage, t2, circuit, tol=1e-8)


def same_away_from_singular(a, b, cond=0.05):
    """Like same_motion, to 1e-12 where the condition measure is at least ``cond``;
    nearer the singular position round-off grows like a power of 1/condition (the
    square for acceleration, the cube for jerk), so there to 1e-5."""
    assert np.array_equal(a.status, b.status)
    ok = a.status == 0
    far = ok & (a.condition >= cond)
    for x, y in zip([a.q] + a.dth + a.dL + a.points, [b.q] + b.dth + b.dL + b.points):
        if np.isfinite(y[ok]).any():
            assert rel_err(x[far], y[far]) <= 1e-12
            assert rel_err(x[ok], y[ok]) <= 1e-5
