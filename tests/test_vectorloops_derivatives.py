"""accelab.solver.vectorloops.derivatives: velocity, acceleration and jerk of every vector
and point, against mpmath at 40 digits and against the differentiated loops' closure."""

import mpmath as mp
import numpy as np
import pytest
from _vectorloops_helpers import CYCLE, jet_of_vector, mp_solver, system_of

from accelab.solver import Q_
from accelab.solver.vectorloops import VectorLoopLinkage
from accelab.solver.vectorloops import solve_loops_case as solve_case
from accelab.solver.vectorloops.examples import EXAMPLES
from accelab.solver.vectorloops.solve import solve


@pytest.mark.parametrize("name", ["sixbar_slider", "watt2_sixbar"])
def test_sixbar_against_mpmath_differentiation(name):
    """Position to jerk of every point of a sixbar, against mpmath: Newton at 40
    digits on the loop equations alone, then derivatives by numerical
    differentiation along theta2(t) = t0 + w t + a t^2/2 + j t^3/6."""
    case = dict(
        EXAMPLES[name](),
        mechanism="loops",
        theta2="57 deg",
        omega2="12 rad/s",
        alpha2="-30 rad/s^2",
        jerk2="500 rad/s^3",
    )
    res = solve_case(case)
    assert res["ok"], res
    mp.mp.dps = 40
    model, q_at, points_at = mp_solver(case)
    t0, w, a, j = mp.radians(57), mp.mpf(12), mp.mpf(-30), mp.mpf(500)
    # start from the float solution
    q0 = []
    for u in model.unknown_names:
        vname, what = u.split(".")
        q0.append(mp.mpf(res["vectors"][vname]["length" if what == "length" else "angle"]))
    state = {"q": q0}

    def point(k):
        def f(t):
            theta2 = t0 + w * t + a * t * t / 2 + j * t**3 / 6
            return points_at(theta2, q_at(theta2, state["q"]))[k]

        return f

    for k, pname in enumerate(model.point_names):
        f = point(k)
        derivs = [f(mp.mpf(0))] + [mp.diff(f, mp.mpf(0), n, h=mp.mpf(10) ** -8) for n in (1, 2, 3)]
        for n, key in enumerate("RVAJ"):
            ref = complex(derivs[n])
            got = complex(*res["points"][pname][key])
            scale = max(abs(ref), 1e-3)
            assert abs(got - ref) <= 1e-11 * scale, (pname, key, got, ref)
    mp.mp.dps = 15


def test_sixbar_slider_derivatives_against_mpmath_finite_differences():
    """Velocity, acceleration and jerk of every unknown (theta3, theta4, theta5 and
    the slider's S) at coarse and batched positions of a full-cycle sweep, against
    central differences of 40-digit positions along theta2(t) = t0 + w t + a t^2/2
    + j t^3/6."""
    desc = EXAMPLES["sixbar_slider"]()
    w, al, jk = 12.0, -30.0, 500.0
    r = VectorLoopLinkage(**desc).solve(
        theta2=Q_(np.degrees(CYCLE), "deg"),
        omega2=f"{w} rad/s",
        alpha2=f"{al} rad/s^2",
        jerk2=f"{jk} rad/s^3",
    )
    assert r.valid.all()
    model, q_at, _ = mp_solver(desc)
    got = {}
    for u, name in enumerate(model.unknown_names):
        v, what = name.split(".")
        keys = (
            ("length", "length_dot", "length_ddot", "length_dddot")
            if what == "length"
            else ("angle", "omega", "alpha", "jerk")
        )
        got[u] = [getattr(r.vectors[v], k).to_base_units().m for k in keys]
    old = mp.mp.dps
    mp.mp.dps = 40
    try:
        h = mp.mpf(10) ** -8
        for i in (0, 37, 181, 300):
            t0 = mp.mpf(float(CYCLE[i]))
            start = [got[u][0][i] for u in range(model.n_unknowns)]
            qs = {
                k: q_at(t0 + w * (k * h) + al * (k * h) ** 2 / 2 + jk * (k * h) ** 3 / 6, start)
                for k in (-2, -1, 0, 1, 2)
            }
            for u in range(model.n_unknowns):
                f = {k: qs[k][u] for k in qs}
                ref = [
                    f[0],
                    (f[1] - f[-1]) / (2 * h),
                    (f[1] - 2 * f[0] + f[-1]) / h**2,
                    (f[2] - 2 * f[1] + 2 * f[-1] - f[-2]) / (2 * h**3),
                ]
                for n in range(4):
                    scale = max(abs(float(ref[n])), w**n * 1e-2)
                    assert abs(got[u][n][i] - float(ref[n])) <= 1e-10 * scale, (
                        model.unknown_names[u],
                        n,
                        i,
                        got[u][n][i],
                        float(ref[n]),
                    )
    finally:
        mp.mp.dps = old


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_every_differentiated_loop_closes(name):
    desc = EXAMPLES[name]()
    system = system_of(desc)
    m = solve(system, CYCLE, 10.0, -5.0, 40.0)
    assert (m.status == 0).all()
    signs = system.model.signs
    jets = [
        jet_of_vector(
            [m.L[:, v]] + [x[:, v] for x in m.dL], [m.theta[:, v]] + [x[:, v] for x in m.dth]
        )
        for v in range(signs.shape[1])
    ]
    for loop in signs:
        for n in range(4):
            terms = np.array([k * jets[v][n] for v, k in enumerate(loop) if k])
            closure = np.abs(terms.sum(axis=0))
            assert (closure <= 1e-12 * np.abs(terms).sum(axis=0).max()).all(), (n, closure.max())
