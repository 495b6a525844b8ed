"""accelab.solver.vectorloops.straightline: the generated one-position Newton step,
against numpy's evaluation and, bit for bit, against the plain loops over the
same tables."""

import numpy as np
import pytest
from _vectorloops_helpers import system_of

from accelab.benchmarks.cases import eightbar
from accelab.solver.vectorloops.examples import EXAMPLES
from accelab.solver.vectorloops.newton import orientation
from accelab.solver.vectorloops.straightline import plain_step


@pytest.mark.parametrize("name", sorted(EXAMPLES) + ["eightbar"])
def test_straight_line_kernel_matches_the_batched_evaluation(name):
    """The generated one-position kernel against numpy's evaluation: residual, Newton
    step, dq/dtheta2 and orientation at random configurations."""
    system = system_of(eightbar() if name == "eightbar" else EXAMPLES[name]())
    rng = np.random.default_rng(5)
    for _ in range(20):
        q = system.model.guess + rng.normal(scale=0.3, size=system.n_unknowns) * system.scale
        t = float(rng.uniform(-np.pi, np.pi))
        res, orient, dq, slope = system.step(list(q), t)
        F, J, Ft = system.evaluate(q[None], np.array([t]))
        assert res == pytest.approx(np.linalg.norm(F[0]), rel=1e-12)
        assert orient == pytest.approx(float(orientation(J[0])), rel=1e-9, abs=1e-14)
        assert np.allclose(dq, np.linalg.solve(J[0], -F[0]), rtol=1e-9, atol=1e-13)
        assert np.allclose(slope, np.linalg.solve(J[0], -Ft[0]), rtol=1e-9, atol=1e-13)


@pytest.mark.parametrize("name", sorted(EXAMPLES) + ["eightbar"])
def test_generated_step_is_the_plain_step_bit_for_bit(name):
    """The generated code (the fast path) and the plain loops over the same
    tables give the same bits: residual, orientation, Newton step and slope."""
    system = system_of(eightbar() if name == "eightbar" else EXAMPLES[name]())
    rng = np.random.default_rng(7)
    nu = system.n_unknowns
    for _ in range(200):
        q = list(system.model.guess + rng.normal(0.0, 0.3, nu) * system.scale)
        theta2 = float(rng.uniform(-7.0, 7.0))
        fast = system.step(q, theta2)
        plain = plain_step(system.step_tables, nu, q, theta2)
        assert fast == plain
