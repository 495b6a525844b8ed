"""Position of a vector-loop linkage by Newton-Raphson (unit-free).

The unknowns q (angles [rad] and slider lengths [m]) solve F(q, theta2) = 0,
with F the real and imaginary parts of every loop's signed sum of vectors
z_v = L_v e^{j theta_v}. The Jacobian is analytic:

    dz_v/dq = e^{j theta_v}                 for v's own unknown length
    dz_v/dq = k_v j L_v e^{j theta_v}       for the unknown angle v follows (ratio k_v)

and the same matrix serves the velocity, acceleration and jerk solves
(:mod:`.derivatives`).

Everything here works on a stack of M positions at once (M = 1 for one
position): F, the Jacobian and dF/dtheta2 of all M come from one real
matrix product ``[L cos, cos, L sin, sin] @ B`` with a matrix B built once
per linkage (in BLAS calls small enough never to start threads:
:mod:`.products`), and the M small Newton systems are solved by one stacked
``np.linalg.solve``.

Each solved position also gets its *orientation*: det J over the product of
J's column norms, in [-1, 1]. Its sign tells the assemblies apart (for a
fourbar it is the sign of sin(theta3 - theta4): open and crossed have
opposite signs), it can change along a continuous path only where J is
singular, and its size says how far the position is from a singular one
(:mod:`.sweep` follows one sign).
"""

import dataclasses
import math
from typing import NamedTuple

import numpy as np

from ..errors import InvalidInput, NoConvergence
from ..kernels.common import length_unit
from .products import rows_times
from .straightline import compile_kernel

#: A position whose condition measure (1 best, 0 singular; see :func:`condition`)
#: falls below this is reported ``singular``: its Jacobian is too close to
#: singular to vouch for velocity and acceleration. (The closed-form kernels
#: decide by their round-off estimate instead: :data:`~accelab.solver.kernels.common.MAX_ROUNDOFF`.)
SINGULAR_CONDITION = 1e-4

MAX_ITERATIONS = 50
MAX_ANGLE_STEP = 0.5  # [rad] per iteration: keeps Newton on the guessed assembly
MAX_LENGTH_STEP = 0.5  # [length scale] per iteration
DEFAULT_TOL = 1e-13  # loop residual / length scale that Newton gets below
STEP_TOL_FACTOR = 1e-8 / math.sqrt(DEFAULT_TOL)  # last step <= this * sqrt(tol)
#: a loop residual this small (times the length scale) is round-off: Newton stops
#: there whatever its step (at a singular root the step stalls near 1e-8 in noise)
ROUNDOFF_RESIDUAL = 1e-14

# reasons a position did not converge
CONVERGED, NOT_CLOSED, SINGULAR_STEP = 0, 1, 2
#: an orientation (det J over the product of its column norms) smaller than
#: this in size has no trustworthy sign: round-off in det J is about
#: n eps times that product
ORIENTATION_FLOOR = 1e-10


class NewtonResult(NamedTuple):
    """What Newton-Raphson returns for one position (lists / floats) or a
    stack of M positions (arrays with a first axis of M)."""

    q: object  #: the solution (the last iterate where not converged)
    iterations: object  #: Newton steps taken
    residual: object  #: loop residual norm at the last evaluation [m]
    reason: object  #: CONVERGED, NOT_CLOSED or SINGULAR_STEP
    slope: object  #: dq/dtheta2 at the solution (None / NaN where not converged)
    orient: object  #: the orientation at the solution (NaN where not converged)


def check_tol(tol):
    """The convergence tolerance as a float in (0, 1e-2], or InvalidInput."""
    try:
        tol = float(tol)
    except (TypeError, ValueError):
        raise InvalidInput(f"tol must be a plain number like 1e-13 (got {tol!r})", "tol") from None
    if not 0 < tol <= 1e-2:
        raise InvalidInput(
            f"tol must be in (0, 1e-2], a loop residual relative to the longest "
            f"link (got {tol!r}); the default is {DEFAULT_TOL:g}",
            "tol",
        )
    return tol


def step_tolerance(tol):
    """Largest Newton step [scaled] that ends the iteration at tolerance
    ``tol``: 1e-8 at the default 1e-13, growing like sqrt(tol). Newton's error
    and loop residual after a step of size s are of order s**2 (times the
    length scale), 1e-16 at the default, below ``tol`` at any tolerance."""
    return STEP_TOL_FACTOR * math.sqrt(tol)


class LoopSystem:
    """Index arrays of a :class:`~.description.LoopModel`, ready for fast evaluation.

    Lengths inside are the model's divided by ``unit``, a power of two near its
    longest length (:func:`accelab.solver.kernels.common.length_unit`): exact, and the
    solver is then the same at any scale float64 holds (``model`` is the
    normalized model, ``si_model`` the one read; :func:`.solve.solve` multiplies
    the lengths it returns by ``unit``).
    """

    def __init__(self, model):
        self.si_model = model
        self.unit = unit = length_unit(model.length_scale)
        guess = np.where(model.unknown_is_length, model.guess / unit, model.guess)
        self.model = model = dataclasses.replace(
            model, length=model.length / unit, guess=guess, length_scale=model.length_scale / unit
        )
        m = model
        self.signs = m.signs
        self.n_loops = nl = m.signs.shape[0]
        self.n_unknowns = nu = m.n_unknowns
        self.vl = np.flatnonzero(m.length_unknown >= 0)  # vectors with unknown length
        self.il = m.length_unknown[self.vl]
        self.va = np.flatnonzero(m.angle_unknown >= 0)  # vectors on an unknown angle
        self.ia = m.angle_unknown[self.va]
        self.vin = np.flatnonzero(m.angle_input)  # vectors driven by theta2
        self.ratio = m.angle_ratio
        self.offset = m.angle_offset
        self.fixed_length = np.where(np.isnan(m.length), 0.0, m.length)
        self.scale = np.where(m.unknown_is_length, m.length_scale, 1.0)  # per unknown
        self.step_limit = np.where(
            m.unknown_is_length, MAX_LENGTH_STEP * m.length_scale, MAX_ANGLE_STEP
        )
        # dense maps from vectors to unknowns, for a Jacobian in real arithmetic
        nv = len(self.fixed_length)
        self.n_vectors = nv
        self.Ma = np.zeros((nv, nu))
        self.Ma[self.va, self.ia] = self.ratio[self.va]
        self.Ml = np.zeros((nv, nu))
        self.Ml[self.vl, self.il] = 1.0
        self.k_in = np.where(m.angle_input, self.ratio, 0.0)
        # gathers: base angle of every vector from [q, theta2, 0]; length from q or fixed
        self.base_index = np.full(nv, nu + 1)
        self.base_index[self.vin] = nu
        self.base_index[self.va] = self.ia
        self.length_index = np.zeros(nv, dtype=int)
        self.length_index[self.vl] = self.il
        self.length_mask = np.zeros(nv)
        self.length_mask[self.vl] = 1.0
        # B maps the row [L cos, cos, L sin, sin] (one entry per vector) of one
        # position to column blocks of 2 n_loops each: F; dF/dq_0 ... dF/dq_{nu-1};
        # dF/dtheta2 (rows of each block: real and imaginary part of each loop).
        Bc = np.zeros((2 * nv, nu + 2, nl), dtype=complex)  # acting on [z, e]
        Bc[:nv, 0, :] = m.signs.T
        Bc[:nv, 1 : nu + 1, :] = 1j * self.Ma[:, :, None] * m.signs.T[:, None, :]
        Bc[nv:, 1 : nu + 1, :] = self.Ml[:, :, None] * m.signs.T[:, None, :]
        Bc[:nv, nu + 1, :] = 1j * self.k_in[:, None] * m.signs.T
        # real form: (yr + j yi)(br + j bi) = (yr br - yi bi) + j (yr bi + yi br)
        B = np.zeros((2, 2 * nv, nu + 2, nl, 2))
        B[0, :, :, :, 0], B[0, :, :, :, 1] = Bc.real, Bc.imag
        B[1, :, :, :, 0], B[1, :, :, :, 1] = -Bc.imag, Bc.real
        self.B = B.reshape(4 * nv, (nu + 2) * 2 * nl)
        # the input angle's period: 2 pi when every driven vector turns an integer
        # number of times per crank turn (a gear ratio like -2), else none
        k = self.ratio[self.vin]
        self.period = 2 * np.pi if np.all(k == np.round(k)) else None
        self._step_tables()

    def _step_tables(self):
        """Plain-Python tables for :meth:`newton1` (one position, no numpy): per
        vector its base index, ratio, offset, length (or unknown index) and the
        rows and columns it adds to (F, J, dF/dtheta2); and from them the
        straight-line kernel of one Newton step (:mod:`.straightline`)."""
        m = self.model
        rows = []
        for v in range(self.n_vectors):
            fterms, aterms, lterms, dterms = [], [], [], []
            for loop in np.flatnonzero(m.signs[:, v]):
                sg, r = float(m.signs[loop, v]), 2 * int(loop)
                fterms.append((r, sg))
                if m.angle_unknown[v] >= 0:
                    aterms.append((r, int(m.angle_unknown[v]), sg * float(self.ratio[v])))
                if m.length_unknown[v] >= 0:
                    lterms.append((r, int(m.length_unknown[v]), sg))
                if m.angle_input[v]:
                    dterms.append((r, sg * float(self.ratio[v])))
            rows.append(
                (
                    int(self.base_index[v]),
                    float(self.ratio[v]),
                    float(self.offset[v]),
                    int(m.length_unknown[v]),
                    float(self.fixed_length[v]),
                    tuple(fterms),
                    tuple(aterms),
                    tuple(lterms),
                    tuple(dterms),
                )
            )
        self.step_tables = tuple(rows)
        self._py_scale = [float(x) for x in self.scale]
        self._py_limit = [float(x) for x in self.step_limit]
        self.step = compile_kernel(self.step_tables, self.n_unknowns)

    # --- geometry of a stack of positions --------------------------------
    def vectors(self, q, theta2):
        """Lengths L (M, nv) [m], angles theta (M, nv) [rad] of a stack of positions."""
        M = q.shape[0]
        X = np.empty((M, self.n_unknowns + 2))
        X[:, :-2] = q
        X[:, -2] = theta2
        X[:, -1] = 0.0
        theta = X[:, self.base_index] * self.ratio + self.offset
        if len(self.vl):
            L = self.fixed_length + q[:, self.length_index] * self.length_mask
        else:
            L = np.broadcast_to(self.fixed_length, theta.shape)
        return L, theta

    def evaluate(self, q, theta2):
        """Residual F (M, 2 nl), Jacobian J (M, 2 nl, nu) and dF/dtheta2 (M, 2 nl).

        Rows come in (real, imaginary) pairs, loop by loop.
        """
        L, theta = self.vectors(q, theta2)
        return self.evaluate_lt(L, np.cos(theta), np.sin(theta))

    def evaluate_lt(self, L, c, s):
        """As :meth:`evaluate`, from lengths and the cosines, sines of the angles."""
        M = c.shape[0]
        nu, nl = self.n_unknowns, self.n_loops
        Y = np.concatenate([L * c, c, L * s, s], axis=1)
        R = rows_times(Y, self.B).reshape(M, nu + 2, 2 * nl)
        return R[:, 0], R[:, 1 : nu + 1].transpose(0, 2, 1), R[:, nu + 1]

    # --- Newton-Raphson -----------------------------------------------------
    def newton(self, q0, theta2, tol=DEFAULT_TOL, max_iterations=MAX_ITERATIONS, slopes=True):
        """Newton-Raphson on a stack of M positions at once.

        Parameters
        ----------
        q0 : array (M, nu)
            Starting values (angles [rad], lengths [m]).
        theta2 : array (M,)
            Input angles [rad].
        tol : float
            A position has converged when its Newton step moves no unknown by
            more than :func:`step_tolerance` (``tol``) (radians, or lengths
            over the length scale); that last step is taken, after which the
            loop residual is of order the step squared, below ``tol`` times
            the length scale. A position whose loop residual is already
            round-off (ROUNDOFF_RESIDUAL, or ``tol`` if smaller, times the
            length scale) has converged too, without a step larger than that:
            at a singular root the step is noise.

        Returns
        -------
        NewtonResult
            q (M, nu) solutions (the last iterate where not converged);
            iterations (M,); residual (M,) [m] (for a converged position,
            before its last step); reason (M,) int8; slope (M, nu)
            dq/dtheta2 (NaN where not converged, and everywhere when
            ``slopes`` is False); orient (M,) (:func:`orientation`; NaN
            where not converged).
        """
        q = np.array(q0, dtype=float, copy=True)
        theta2 = np.asarray(theta2, dtype=float)
        M = q.shape[0]
        iterations = np.zeros(M, dtype=int)
        residual = np.full(M, np.inf)
        reason = np.full(M, NOT_CLOSED, dtype=np.int8)
        slope = np.full_like(q, np.nan)
        orient = np.full(M, np.nan)
        step_tol = step_tolerance(tol)
        floor = min(tol, ROUNDOFF_RESIDUAL) * self.model.length_scale
        active = np.arange(M)
        qa, ta = q, theta2
        for it in range(max_iterations + 1):
            F, J, Ft = self.evaluate(qa, ta)
            res = np.sqrt(np.einsum("ij,ij->i", F, F))
            residual[active] = res
            sol, bad = solve_stack(J, np.stack([F, Ft], axis=-1) if slopes else F[:, :, None])
            dq = -sol[:, :, 0]
            size = np.max(np.abs(dq) / self.scale, axis=1)
            small = size <= step_tol
            done = (small | (res <= floor)) & ~bad
            if done.any():
                idx = active[done]
                q[idx] = qa[done] + np.where(small[done, None], dq[done], 0.0)
                iterations[idx] += small[done]
                reason[idx] = CONVERGED
                orient[idx] = orientation(J[done])
                if slopes:
                    slope[idx] = -sol[done, :, 1]
            if bad.any():
                q[active[bad]] = qa[bad]
                reason[active[bad]] = SINGULAR_STEP
            keep = ~done & ~bad
            if it == max_iterations or not keep.any():
                q[active[keep]] = qa[keep]
                break
            if not keep.all():
                active, qa, ta, dq = active[keep], qa[keep], ta[keep], dq[keep]
            ratio = np.max(np.abs(dq) / self.step_limit, axis=1)
            damped = ratio > 1.0
            if damped.any():  # never leap to another assembly in one step
                dq[damped] /= ratio[damped, None]
            qa = qa + dq
            iterations[active] += 1
        return NewtonResult(q, iterations, residual, reason, slope, orient)

    def newton1(
        self, q0, theta2, tol=DEFAULT_TOL, max_iterations=MAX_ITERATIONS, least_squares=False
    ):
        """Newton-Raphson at one position, in plain Python floats.

        The same iteration, stopping rule and damping as :meth:`newton`, for
        the sequential steps of a sweep, where numpy's per-call overhead on
        a 4 x 4 system would cost more than the arithmetic.

        An iterate where the Jacobian is exactly singular stops the iteration
        (SINGULAR_STEP), unless ``least_squares`` is set: then that step is
        the least-squares step of least norm (it moves only where the
        Jacobian can), which is how a sweep leaves a singular position.

        Returns a :class:`NewtonResult` with q and slope as lists (slope None
        where not converged, or where the Jacobian is exactly singular) and
        orient the orientation at the last evaluation (det J over the product
        of J's column norms; NaN where not converged).
        """
        q = [float(x) for x in q0]
        if not math.isfinite(theta2):
            return NewtonResult(q, 0, math.nan, NOT_CLOSED, None, math.nan)
        kernel = self.step
        scale, limit = self._py_scale, self._py_limit
        step_tol = step_tolerance(tol)
        floor = min(tol, ROUNDOFF_RESIDUAL) * self.model.length_scale
        steps = 0
        while True:
            res, orient, dq, slope = kernel(q, theta2)
            if res != res:
                return NewtonResult(q, steps, res, SINGULAR_STEP, None, math.nan)
            if dq is None and least_squares:
                dq = self._least_squares_step(q, theta2)
            if dq is None:
                return NewtonResult(q, steps, res, SINGULAR_STEP, None, math.nan)
            ratio = size = 0.0
            for a, lim, sc in zip(dq, limit, scale):
                a = abs(a)
                if a > ratio * lim:
                    ratio = a / lim
                if a > size * sc:
                    size = a / sc
            if size <= step_tol:
                return NewtonResult(
                    [x + y for x, y in zip(q, dq)], steps + 1, res, CONVERGED, slope, orient
                )
            if res <= floor:  # round-off already: at a singular root the step is noise
                return NewtonResult(q, steps, res, CONVERGED, slope, orient)
            if steps == max_iterations:
                return NewtonResult(q, steps, res, NOT_CLOSED, None, math.nan)
            if ratio > 1.0:  # never leap to another assembly in one step
                q = [x + y / ratio for x, y in zip(q, dq)]
            else:
                q = [x + y for x, y in zip(q, dq)]
            steps += 1

    def _least_squares_step(self, q, theta2):
        """The least-squares Newton step of least norm at a singular Jacobian,
        in the unknowns scaled by :attr:`scale`, as a list (None if not
        finite)."""
        F, J, _ = self.evaluate(np.array([q], dtype=float), np.array([theta2]))
        dx = np.linalg.lstsq(J[0] * self.scale, -F[0], rcond=1e-10)[0] * self.scale
        if not np.all(np.isfinite(dx)):
            return None
        return [float(v) for v in dx]


def solve_stack(J, rhs):
    """Solve M small systems; a singular one gives NaN and a True in ``bad``."""
    bad = np.zeros(J.shape[0], dtype=bool)
    try:
        sol = np.linalg.solve(J, rhs)
    except np.linalg.LinAlgError:
        sol = np.full(rhs.shape[:1] + (J.shape[2], rhs.shape[2]), np.nan)
        for i in range(J.shape[0]):
            try:
                sol[i] = np.linalg.solve(J[i], rhs[i])
            except np.linalg.LinAlgError:
                bad[i] = True
    nonfinite = ~np.isfinite(sol).all(axis=(1, 2))
    return sol, bad | nonfinite


def no_convergence(theta2, residual, iterations, reason):
    """The NoConvergence error for one position that Newton-Raphson did not close."""
    residual, iterations = float(residual), int(iterations)
    if not math.isfinite(theta2):
        return NoConvergence(
            f"theta2 = {theta2} is not a finite angle: no position to solve",
            residual=residual,
            iterations=iterations,
        )
    if reason == SINGULAR_STEP:
        return NoConvergence(
            f"Newton-Raphson hit a singular Jacobian at theta2 = {np.degrees(theta2):.6g} deg "
            f"(loop residual {residual:.3e} m): the guesses sit at a singular configuration; "
            f"move them.",
            residual=residual,
            iterations=iterations,
        )
    return NoConvergence(
        f"Newton-Raphson did not close the loops at theta2 = {np.degrees(theta2):.6g} deg "
        f"after {iterations} iterations (loop residual {residual:.3e} m): the linkage cannot "
        f"be assembled there, or the guesses are too far from an assembly. Check the lengths, "
        f"or give guesses closer to the intended assembly.",
        residual=residual,
        iterations=iterations,
    )


def orientation(J):
    """det J over the product of J's column norms, for one square matrix or a
    stack: in [-1, 1], 0 where singular (Hadamard's inequality), its sign the
    assembly's orientation (see the module docstring)."""
    J = np.asarray(J, dtype=float)
    norms = np.prod(np.sqrt(np.einsum("...ij,...ij->...j", J, J)), axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(norms > 0, np.linalg.det(J) / np.where(norms > 0, norms, 1.0), 0.0)


def condition(J, model):
    """Dimensionless conditioning of the Jacobian(s): the ratio of the smallest
    to the largest singular value after scaling each column to unit length,
    doubled (0 singular; 2 for orthogonal columns). Works on one matrix or a
    stack.

    The singular values come from the eigenvalues of the (small) Gram matrix,
    which is about twice as fast as an SVD per matrix and as accurate while
    the ratio is above 1e-3; below that the SVD is taken.
    """
    J = np.asarray(J, dtype=float)
    norms = np.sqrt(np.einsum("...ij,...ij->...j", J, J))[..., None, :]
    Jn = J / np.where(norms == 0, 1.0, norms)
    lam = np.linalg.eigvalsh(np.swapaxes(Jn, -1, -2) @ Jn)
    with np.errstate(invalid="ignore", divide="ignore"):
        cond = 2.0 * np.sqrt(np.maximum(lam[..., 0], 0.0) / lam[..., -1])
        low = ~(cond >= 1e-3)
        if np.any(low):
            sv = np.linalg.svd(Jn[low], compute_uv=False)
            cond = np.array(cond)
            cond[low] = 2.0 * sv[..., -1] / sv[..., 0]
    return cond
