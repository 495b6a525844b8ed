"""accelab.solver.vectorloops.products: matrix products that never start BLAS threads."""

import numpy as np
import pytest


@pytest.mark.parametrize(
    "shape", [(1, 48, 48), (29, 48, 48), (1000, 48, 48), (997, 32, 24), (10001, 12, 3)]
)
@pytest.mark.parametrize("kind", [float, complex])
def test_unthreaded_products_equal_matmul(shape, kind):
    from accelab.solver.vectorloops.products import BLAS_BLOCK, rows_times

    M, K, N = shape
    rng = np.random.default_rng(M)
    Y = rng.normal(size=(M, K)).astype(kind)
    B = rng.normal(size=(K, N)).astype(kind)
    if kind is complex:
        Y = Y + 1j * rng.normal(size=(M, K))
    assert np.allclose(rows_times(Y, B), Y @ B, rtol=1e-13, atol=1e-12)
    assert BLAS_BLOCK // (K * N) * K * N <= 65536
