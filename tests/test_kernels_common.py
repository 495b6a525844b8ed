"""accelab.solver.kernels.common: long sweeps are solved piece by piece
(:func:`~accelab.solver.kernels.common.pieces`) to keep their work arrays in the
cache, by the fourbar's in-place path or by :func:`in_pieces` for the other
closed forms: the answers must be the same bits as one whole-array
evaluation and as the scalar solves, across piece boundaries, for every
output and the links' directions (cos, sin)."""

import numpy as np
import pytest

from accelab.solver.kernels import common, fivebar, fourbar, invertedslidercrank, slidercrank

ORDER3 = (
    "theta3",
    "theta4",
    "omega3",
    "omega4",
    "alpha3",
    "alpha4",
    "jerk3",
    "jerk4",
    "status",
    "condition",
    "roundoff",
)


def same(x, y):
    x, y = np.asarray(x), np.asarray(y)
    return x.shape == y.shape and x.dtype == y.dtype and np.array_equal(x, y, equal_nan=True)


def sweep(n, seed=0):
    """Crank angles over several turns, array omega2, and a few positions that
    do not assemble (the geometry below is a triple rocker)."""
    rng = np.random.default_rng(seed)
    return rng.uniform(-7.0, 7.0, n), rng.uniform(-40.0, 40.0, n)


@pytest.mark.parametrize("circuit", ["open", "crossed"])
@pytest.mark.parametrize("block", [1000, None])
def test_fourbar_in_place_pieces_match_whole_array_and_scalars(monkeypatch, circuit, block):
    if block:
        monkeypatch.setattr(common, "PIECE", block)
    n = 2 * common.PIECE + 123
    theta2, omega2 = sweep(n)
    args = (5.0, 4.0, 6.0, 3.5, theta2, omega2, -30.0, 400.0, 0.35, circuit)
    blocks = fourbar.solve(*args)
    assert set(np.unique(blocks.status)) >= {0, 1}
    monkeypatch.setattr(fourbar, "MIN_IN_PLACE", 10**9)  # one whole-array evaluation
    whole = fourbar.solve(*args)
    for name in ORDER3:
        assert same(getattr(blocks, name), getattr(whole, name)), name
    for link in "234":
        for x, y in zip(blocks.directions[link], whole.directions[link]):
            assert same(x, y), link
    for i in (0, common.PIECE - 1, common.PIECE, n - 1):
        one = fourbar.solve(
            5.0, 4.0, 6.0, 3.5, float(theta2[i]), float(omega2[i]), -30.0, 400.0, 0.35, circuit
        )
        for name in ORDER3:
            assert np.array_equal(getattr(one, name), getattr(blocks, name)[i], equal_nan=True), (
                i,
                name,
            )


@pytest.mark.parametrize("order", [0, 1, 2])
def test_fourbar_in_place_lower_orders_and_shapes(monkeypatch, order):
    monkeypatch.setattr(common, "PIECE", 700)
    monkeypatch.setattr(fourbar, "MIN_IN_PLACE", 0)
    theta2 = np.linspace(-4.0, 4.0, 3 * 1001).reshape(3, 1001)
    blocks = fourbar.solve(2.0, 6.0, 9.0, 7.0, theta2, 10.0, -5.0, order=order)
    monkeypatch.setattr(fourbar, "MIN_IN_PLACE", 10**9)
    whole = fourbar.solve(2.0, 6.0, 9.0, 7.0, theta2, 10.0, -5.0, order=order)
    assert blocks.keys() == whole.keys() and blocks.order == whole.order == order
    for name in ORDER3[: 2 + 2 * order] + ORDER3[-3:]:
        assert same(getattr(blocks, name), getattr(whole, name)), name


KERNELS = [
    (slidercrank, dict(a=0.3, b=0.2, c=0.05)),
    (invertedslidercrank, dict(a=0.1, c=0.24, d=0.16, gamma=-2.1)),
    (fivebar, dict(a=0.7146, b=0.4384, c=0.3, d=0.3042, f=0.2, lam=2.0, phi=3.1)),
]


@pytest.mark.parametrize("kernel, geo", KERNELS, ids=lambda k: getattr(k, "__name__", ""))
def test_other_kernels_pieces_match_whole_array(monkeypatch, kernel, geo):
    theta2, omega2 = sweep(5000, seed=1)
    kw = dict(theta2=theta2, omega2=omega2, alpha2=-30.0, jerk2=400.0, theta1=0.35)
    whole = kernel.solve(**geo, **kw)
    monkeypatch.setattr(common, "PIECE", 900)
    monkeypatch.setattr(common, "MIN_PIECEWISE", 0)
    pieces = kernel.solve(**geo, **kw)
    assert pieces.keys() == whole.keys()
    for name in whole.keys() + ["directions"]:
        x, y = getattr(pieces, name), getattr(whole, name)
        if name == "directions":
            assert x.keys() == y.keys()
            assert all(same(u, v) for k in x for u, v in zip(x[k], y[k]))
        elif isinstance(y, np.ndarray):
            assert same(x, y), name
        else:
            assert x == y, name
    assert pieces.omega2 is omega2 and pieces.theta2 is theta2
