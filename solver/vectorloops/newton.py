"""Position of a vector-loop linkage by Newton-Raphson (unit-free).

The unknowns q (angles [rad] and slider lengths [m]) solve F(q, theta2) = 0,
with F the real and imaginary parts of every loop's signed sum of vectors
z_v = L_v e^{j theta_v}. The Jacobian is analytic:

    dz_v/dq = e^{j theta_v}                 for v's own unknown length
    dz_v/dq = k_v j L_v e^{j theta_v}       for the unknown angle v follows (ratio k_v)

and the same matrix serves the velocity, acceleration and jerk solves
(:mod:`.derivatives`).
"""

import numpy as np

from ..errors import NoConvergence

MAX_ITERATIONS = 50
MAX_ANGLE_STEP = 0.5      # [rad] per iteration: keeps Newton on the guessed assembly
MAX_LENGTH_STEP = 0.5     # [length scale] per iteration


class LoopSystem:
    """Index arrays of a :class:`~.description.LoopModel`, ready for fast evaluation."""

    def __init__(self, model):
        self.model = model
        m = model
        self.signs = m.signs
        self.n_loops = m.signs.shape[0]
        self.n_unknowns = m.n_unknowns
        self.vl = np.flatnonzero(m.length_unknown >= 0)        # vectors with unknown length
        self.il = m.length_unknown[self.vl]
        self.va = np.flatnonzero(m.angle_unknown >= 0)          # vectors on an unknown angle
        self.ia = m.angle_unknown[self.va]
        self.vin = np.flatnonzero(m.angle_input)                # vectors driven by theta2
        self.ratio = m.angle_ratio
        self.offset = m.angle_offset
        self.fixed_length = np.where(np.isnan(m.length), 0.0, m.length)
        self.scale = np.where(m.unknown_is_length, m.length_scale, 1.0)  # per unknown
        self.step_limit = np.where(m.unknown_is_length, MAX_LENGTH_STEP * m.length_scale,
                                   MAX_ANGLE_STEP)
        # dense maps from vectors to unknowns, for a Jacobian in real arithmetic
        nv, nu = len(self.fixed_length), self.n_unknowns
        self.Ma = np.zeros((nv, nu))
        self.Ma[self.va, self.ia] = self.ratio[self.va]
        self.Ml = np.zeros((nv, nu))
        self.Ml[self.vl, self.il] = 1.0
        self.k_in = np.where(m.angle_input, self.ratio, 0.0)

    # --- evaluation at one position ---------------------------------------
    def lengths_angles(self, q, theta2):
        """Lengths L_v [m] and angles theta_v [rad] of every vector."""
        L = self.fixed_length.copy()
        L[self.vl] = q[self.il]
        base = np.zeros(len(L))
        base[self.vin] = theta2
        base[self.va] = q[self.ia]
        return L, self.ratio * base + self.offset

    def residual(self, L, e):
        f = self.signs @ (L * e)
        return np.concatenate([f.real, f.imag])

    def jacobian(self, L, e):
        """Real Jacobian dF/dq, shape (2 n_loops, n_unknowns)."""
        return self._jacobian_real(L, e.real, e.imag)

    def _jacobian_real(self, L, c, s):
        # angle unknowns: k j L e = k L (-s + j c); length unknowns: e = c + j s
        re = (self.Ma * (-L * s)[:, None]) + self.Ml * c[:, None]
        im = (self.Ma * (L * c)[:, None]) + self.Ml * s[:, None]
        return np.vstack([self.signs @ re, self.signs @ im])

    def dF_dtheta2(self, L, e):
        k = self.k_in * L
        return np.concatenate([self.signs @ (-k * e.imag), self.signs @ (k * e.real)])

    def solve_position(self, q0, theta2):
        """Newton-Raphson from q0 to machine precision.

        Returns ``(q, iterations, residual_norm, J, slope)`` with ``slope`` =
        dq/dtheta2 there (the continuation predictor); raises NoConvergence
        (with the residual it reached) when the loops do not close.
        """
        q = np.array(q0, dtype=float)
        scale = self.scale
        limit = self.step_limit
        tol_res = 1e-13 * self.model.length_scale
        signs = self.signs
        res_norm = np.inf
        size = np.inf
        for it in range(1, MAX_ITERATIONS + 1):
            L, th = self.lengths_angles(q, theta2)
            c, s = np.cos(th), np.sin(th)
            F = np.concatenate([signs @ (L * c), signs @ (L * s)])
            res_norm = float(np.sqrt(F @ F))
            if size < 1e-8 and res_norm <= tol_res:
                # the last step was quadratic-small: q is at round-off
                J = self._jacobian_real(L, c, s)
                k = self.k_in * L
                dFdt = np.concatenate([signs @ (-k * s), signs @ (k * c)])
                slope = np.linalg.solve(J, -dFdt)
                return q, it - 1, res_norm, J, slope
            J = self._jacobian_real(L, c, s)
            try:
                dq = np.linalg.solve(J, -F)
            except np.linalg.LinAlgError:
                raise NoConvergence(
                    f"Newton-Raphson hit a singular Jacobian at theta2 = "
                    f"{np.degrees(theta2):.6g} deg (loop residual {res_norm:.3e} m): the guesses "
                    f"sit at a singular configuration; move them.", residual=res_norm,
                    iterations=it) from None
            size = float(np.max(np.abs(dq) / scale))
            big = np.abs(dq) > limit
            if big.any():  # damp: never leap to another assembly in one step
                dq *= np.min(limit[big] / np.abs(dq[big]))
                size = np.inf
            q += dq
        raise NoConvergence(
            f"Newton-Raphson did not close the loops at theta2 = {np.degrees(theta2):.6g} deg "
            f"after {MAX_ITERATIONS} iterations (loop residual {res_norm:.3e} m): the linkage "
            f"cannot be assembled there, or the guesses are too far from an assembly. Check "
            f"the lengths, or give guesses closer to the intended assembly.",
            residual=res_norm, iterations=MAX_ITERATIONS)


def condition(J, model):
    """Dimensionless conditioning of the Jacobian(s): the ratio of the smallest
    to the largest singular value after scaling each column to unit length
    (1 best, 0 singular). Works on one matrix or a stack."""
    norms = np.linalg.norm(J, axis=-2, keepdims=True)
    norms = np.where(norms == 0, 1.0, norms)
    sv = np.linalg.svd(J / norms, compute_uv=False)
    with np.errstate(invalid="ignore", divide="ignore"):
        return 2.0 * sv[..., -1] / sv[..., 0]
