"""Velocity, acceleration and jerk of a solved vector-loop linkage (unit-free).

Differentiating each loop n times gives J q^(n) = -K_n: the same Jacobian as
the position solve, with K_n the known part of the n-th derivative of every
vector. For z = L e^{j theta} with L and theta both functions of time:

    z'   = (L' + j L w) e^{j theta}
    z''  = (L'' - L w^2 + j (L al + 2 L' w)) e^{j theta}
    z''' = (L''' - 3 L' w^2 - 3 L w al + j (3 L'' w + 3 L' al + L jk - L w^3)) e^{j theta}

(w, al, jk the first three derivatives of theta). The known part K_n is the
same expression with the unknowns' n-th derivatives set to zero. All
positions are solved at once (a stack of small linear systems): exact, no
iteration.
"""

import numpy as np

from .newton import solve_stack
from .products import rows_times


def vector_derivative(n, L, dL, th_d, e):
    """n-th time derivative (n = 1..3) of z = L e^{j theta}.

    ``dL`` = [L', L'', L'''] and ``th_d`` = [w, al, jk] (arrays, missing
    higher entries may be zero); ``e`` = e^{j theta}.
    """
    w = th_d[0]
    if n == 1:
        return (dL[0] + 1j * L * w) * e
    al = th_d[1]
    if n == 2:
        return (dL[1] - L * w * w + 1j * (L * al + 2.0 * dL[0] * w)) * e
    jk = th_d[2]
    return (
        dL[2]
        - 3.0 * dL[0] * w * w
        - 3.0 * L * w * al
        + 1j * (3.0 * dL[1] * w + 3.0 * dL[0] * al + L * jk - L * w * w * w)
    ) * e


def solve_derivatives(system, q, theta2, inputs, order=3):
    """Derivatives of the unknowns and of every vector at N solved positions.

    Parameters
    ----------
    system : LoopSystem
    q : array (N, n_unknowns)
        Solved positions.
    theta2 : array (N,)
    inputs : list of arrays (N,)
        [omega2, alpha2, jerk2] of the input [rad/s, rad/s^2, rad/s^3].
    order : int
        Highest derivative (1..3).

    Returns
    -------
    dict
        ``q_d``: list of (N, n_unknowns) arrays [q', q'', q''']; ``L``,
        ``theta``, ``e`` (N, n_vectors); ``dL``, ``dth``: lists of
        (N, n_vectors) derivatives of every vector's length and angle;
        ``J``: the Jacobians (N, 2 n_loops, n_unknowns), rows the real and
        imaginary part of each loop in turn.
    """
    s = system
    N = q.shape[0]
    nv = s.n_vectors
    L, theta = s.vectors(q, theta2)
    L = np.array(L)  # (N, nv), writable
    c, sn = np.cos(theta), np.sin(theta)
    e = c + 1j * sn
    J = s.evaluate_lt(L, c, sn)[1]  # rows: (real, imaginary) of each loop
    dL = [np.zeros((N, nv)) for _ in range(3)]
    dth = [np.zeros((N, nv)) for _ in range(3)]
    q_d = []
    signs_T = s.signs.T.astype(complex)
    for n in range(1, order + 1):
        # the input's share of theta_v^(n); unknowns' n-th derivatives still zero
        dth[n - 1][:, s.vin] = s.ratio[s.vin] * inputs[n - 1][:, None]
        K = rows_times(vector_derivative(n, L, dL, dth, e), signs_T)  # (N, n_loops) complex
        rhs = -K.view(np.float64)  # interleaved re, im
        x = solve_stack(J, rhs[..., None])[0][..., 0]  # NaN where J is singular
        q_d.append(x)
        dL[n - 1][:, s.vl] = x[:, s.il]
        dth[n - 1][:, s.va] = s.ratio[s.va] * x[:, s.ia]
    return {"q_d": q_d, "L": L, "theta": theta, "e": e, "dL": dL, "dth": dth, "J": J}


def point_motion(system, d, order=3):
    """R, V, A, J [m, m/s, m/s^2, m/s^3] of every named point, as complex (N, n_points)."""
    signs = system.model.point_signs
    z = [d["L"] * d["e"]] + [
        vector_derivative(n, d["L"], d["dL"], d["dth"], d["e"]) for n in range(1, order + 1)
    ]
    return [rows_times(z_n, signs.T.astype(complex)) for z_n in z]
