"""Matrix products over a stack of positions that never start BLAS threads.

``Y @ B`` goes to the BLAS library numpy was built with (OpenBLAS in the
wheels), which shares one product among threads once m * n * k passes a
threshold (2.6e5 in OpenBLAS's default build). The vector-loop solver's
products are many rows (positions) times a small matrix: 1000 positions of
the eightbar times its 48 x 48 matrix is 2.3e6, so OpenBLAS starts threads.
On an idle machine that gains nothing measurable; on a loaded one the
threads wait for busy cores, and one call took 9-15 ms instead of 0.13 ms.

:func:`rows_times` cuts the rows into blocks so that every BLAS call stays
below a quarter of that threshold (single-threaded in any OpenBLAS build),
and hands all blocks to numpy in one call: a 3-D stack times a matrix is a
loop of BLAS calls in C, one per block.
"""

import numpy as np

#: largest m * n * k of one BLAS call [-]: OpenBLAS threads a gemm only above
#: 65536 * GEMM_MULTITHREAD_THRESHOLD (4 by default, at least 1)
BLAS_BLOCK = 65536


def rows_times(Y, B):
    """``Y @ B`` for Y (M, K) and B (K, N), in single-threaded BLAS calls.

    Equal to ``Y @ B`` to round-off; real or complex.
    """
    M, K = Y.shape
    N = B.shape[1]
    m = max(1, BLAS_BLOCK // max(1, K * N))
    if M <= m:
        return Y @ B
    Y = np.ascontiguousarray(Y)
    out = np.empty((M, N), dtype=np.result_type(Y, B))
    full = M - M % m
    np.matmul(Y[:full].reshape(-1, m, K), B, out=out[:full].reshape(-1, m, N))
    if full < M:
        np.matmul(Y[full:], B, out=out[full:])
    return out
