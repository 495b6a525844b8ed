"""accelab.solver.vectorloops.walks and .assembly: ranges that cannot be assembled and
guesses that land on the other assembly are walked, never answered across a jump."""

import numpy as np
import pytest
from _vectorloops_helpers import (
    CYCLE,
    LINKAGES,
    NON_GRASHOF,
    counting,
    fourbar_desc,
    guesses_on,
    on_circuit,
    same_motion,
    start_on_crossed_once,
    system_of,
)

from accelab.solver.errors import NoConvergence
from accelab.solver.kernels import fourbar as fourbar_kernel
from accelab.solver.vectorloops import assembly as assembly_module
from accelab.solver.vectorloops import sweep as sweep_module
from accelab.solver.vectorloops.solve import solve


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize("start", [0.0, 30.0, -40.0])
def test_sweep_masks_a_range_that_cannot_close_and_rejoins_its_assembly(circuit, start):
    a, b, c, d = NON_GRASHOF
    t2 = np.radians(np.linspace(start, start + 360.0, 361))
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on(circuit, a, b, c, d, t2[0])))
    m = solve(system, t2, 1.0)
    ref = fourbar_kernel.solve(a, b, c, d, t2, 1.0, circuit=circuit)
    ok = m.status == 0
    assert np.array_equal(ok, ref.status == 0)  # masked exactly where it cannot close
    assert 100 < ok.sum() < 250
    assert (m.status[~ok] == 1).all() and np.isnan(m.q[~ok]).all()
    assert on_circuit(m, a, b, c, d, t2, circuit)[ok].all()  # one assembly, both sides
    assert isinstance(m.message, NoConvergence) and m.message.residual > 1e-4
    assert "residual" in str(m.message)
    same_motion(m, solve(system, t2, 1.0, batch=False))


def test_unverifiable_reassembly_is_reported_not_returned():
    """With the crank geared at half the input speed the input has no period the
    solver can use, so after the gap no walk from a solved position reaches the
    far side without crossing the gap: those positions are masked with a
    message, never returned on the other assembly."""
    a, b, c, d = NON_GRASHOF
    desc = fourbar_desc(a, b, c, d, *guesses_on("open", a, b, c, d, 0.0))
    desc["vectors"]["G"] = {"length": "0 m", "angle": "input"}
    desc["vectors"]["R2"] = {"length": f"{a} m", "angle": {"follow": "G", "ratio": 0.5}}
    t2 = np.radians(
        np.concatenate(
            [np.arange(0.0, 171.0), np.arange(200.0, 560.0, 2.0), np.arange(560.0, 721.0)]
        )
    )
    m = solve(system_of(desc), t2, 1.0)
    ok = m.status == 0
    assert ok[:171].all()
    assert on_circuit(m, a, b, c, d, t2 / 2, "open")[ok].all()
    assert not ok[171:].any()
    assert "did not close" in str(m.message)  # the first failure: the gap itself
    sw = sweep_module.Sweep(system_of(desc), t2, system_of(desc).model.guess, 1e-13)
    sw.run()
    after = [str(e) for i, e in sw.record.errors.items() if np.degrees(t2[i]) >= 560]
    honest = [e for e in after if "not on the assembly this sweep follows" in e]
    assert len(after) == 161 and len(honest) > 150
    assert all(e in honest or "did not close" in e for e in after)


def test_a_step_that_lands_on_the_other_assembly_is_caught(monkeypatch):
    a, b, c, d = LINKAGES["crank_rocker"]
    system = system_of(fourbar_desc(a, b, c, d, *guesses_on("open", a, b, c, d, 0.0)))
    bad = start_on_crossed_once(system, monkeypatch, a, b, c, d, CYCLE[[40, 41, 200]])
    subdivided = counting(monkeypatch, "subdivide", assembly_module)
    m = solve(system, CYCLE, 1.0, batch=False)
    assert not bad and subdivided["n"] == 3
    assert (m.status == 0).all() and on_circuit(m, a, b, c, d, CYCLE, "open").all()
