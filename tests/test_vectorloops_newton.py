"""accelab.solver.vectorloops.newton: Newton-Raphson's errors, its tolerance, and the
orientation that tells the assemblies apart."""

import numpy as np
import pytest
from _vectorloops_helpers import CYCLE, LINKAGES, fourbar_desc, guesses_on, rel_err, system_of

from accelab.solver import Q_
from accelab.solver.errors import InvalidInput, NoConvergence
from accelab.solver.kernels import fourbar as fourbar_kernel
from accelab.solver.vectorloops import VectorLoopLinkage
from accelab.solver.vectorloops.examples import EXAMPLES
from accelab.solver.vectorloops.solve import solve


def test_no_convergence_carries_the_residual():
    desc = EXAMPLES["fourbar"](d="17 in")
    with pytest.raises(NoConvergence) as info:
        VectorLoopLinkage(**desc).solve(theta2="30 deg", omega2="1 rad/s")
    assert info.value.residual > 0.1 * 0.0254 and f"{info.value.residual:.3e}" in str(info.value)
    m = solve(system_of(desc), np.radians([10.0, 20.0]), 1.0)
    assert (m.status == 1).all() and isinstance(m.message, NoConvergence)
    assert m.message.residual > 1e-4 and f"{m.message.residual:.3e}" in str(m.message)


def test_tolerance_trades_iterations_for_accuracy():
    linkage = VectorLoopLinkage(**EXAMPLES["sixbar_slider"]())
    cycle = Q_(np.degrees(CYCLE), "deg")
    exact = linkage.solve(theta2=cycle, omega2="10 rad/s", alpha2="-5 rad/s^2")
    for tol in (1e-2, 1e-6, 1e-10):
        loose = linkage.solve(theta2=cycle, omega2="10 rad/s", alpha2="-5 rad/s^2", tol=tol)
        assert loose.valid.all()
        assert loose.iterations.mean() <= exact.iterations.mean()
        for v in ("R3", "R4", "R5"):
            assert np.max(np.abs(loose.vectors[v].angle.m - exact.vectors[v].angle.m)) <= tol
        assert rel_err(loose.vectors["S"].length_ddot.m, exact.vectors["S"].length_ddot.m) <= tol
    assert linkage.solve(theta2=cycle, omega2="10 rad/s", tol=1e-2).iterations.mean() < 1.5
    for bad in (0, -1e-9, 0.5, "tight"):
        with pytest.raises(InvalidInput, match="tol"):
            linkage.solve(theta2="10 deg", omega2="1 rad/s", tol=bad)


def test_orientation_tells_the_fourbar_circuits_apart():
    """det J over its column norms is sin(theta3 - theta4) for the fourbar's loop,
    opposite in sign on the two circuits."""
    a, b, c, d = LINKAGES["crank_rocker"]
    t2 = np.radians(np.arange(0.0, 360.0, 15.0))
    for circuit in ("open", "crossed"):
        system = system_of(fourbar_desc(a, b, c, d, *guesses_on(circuit, a, b, c, d, 0.0)))
        ref = fourbar_kernel.solve(a, b, c, d, t2, 1.0, circuit=circuit)
        q = np.stack([ref.theta3, ref.theta4], axis=1)
        *_, reason, _, orient = system.newton(q, t2)
        assert (reason == 0).all()
        assert np.allclose(orient, np.sin(ref.theta3 - ref.theta4), atol=1e-12)
        assert np.all(np.sign(orient) == (-1 if circuit == "open" else 1))


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_one_position_and_stacked_newton_reach_the_same_solutions(name):
    """newton1 (one position, the generated step) and newton (a stack, numpy)
    are one iteration: from the same guesses they stop for the same reason,
    after the same steps, at the same solution (to round-off)."""
    system = system_of(EXAMPLES[name]())
    rng = np.random.default_rng(11)
    nu = system.n_unknowns
    guesses = system.model.guess + rng.normal(0.0, 0.05, (40, nu)) * system.scale
    thetas = np.radians(rng.uniform(0.0, 360.0, 40))
    stack = system.newton(guesses, thetas)
    for k in range(40):
        one = system.newton1(list(guesses[k]), float(thetas[k]))
        assert one.reason == stack.reason[k] and one.iterations == stack.iterations[k], k
        if one.reason == 0:
            assert np.max(np.abs(np.array(one.q) - stack.q[k]) / system.scale) < 1e-12
            assert np.sign(one.orient) == np.sign(stack.orient[k])
