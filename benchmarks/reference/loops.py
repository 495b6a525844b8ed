"""The reference's core: any linkage's vector loops solved in mpmath.

It reads a linkage's vectors and loops (SI numbers: floats or mpf), closes
the loops by Newton-Raphson at the working precision (continuing along the
crank angles from the guesses: each position starts from a cubic Taylor
prediction from the last), and gets the n-th derivatives from the n-th
derivative of every loop,

    sum_v s_v z_v^(n) = 0,   z_v = L_v e^{j theta_v},

whose unknown part is J q^(n) with the position Jacobian J (eqs. 7.2 and 7.40
for a vector of constant length, 7.19 for one whose length varies). Named points are signed sums of
vectors, differentiated the same way.
"""

import mpmath as mp

from ..cases import MOTION

DPS = 40


class LoopReference:
    """A case's loops in mpmath.

    Parameters
    ----------
    case : :class:`~accelab.benchmarks.cases.Case`, or anything with ``name``,
        ``vectors`` (name -> {"length": number | "unknown", "angle": number |
        "input" | "unknown" | {"follow", "ratio", "offset"}}), ``loops``
        (signed sums of names) and ``outputs`` (name -> (vector, "angle" |
        "length", order)).
    """

    def __init__(self, case):
        self.case = case
        self.names = list(case.vectors)
        self.unknowns = []  # (vector, "angle" | "length")
        for name in self.names:
            v = case.vectors[name]
            if v["angle"] == "unknown":
                self.unknowns.append((name, "angle"))
            if v["length"] == "unknown":
                self.unknowns.append((name, "length"))
        self.index = {u: k for k, u in enumerate(self.unknowns)}
        # every angle as ratio * source + offset, the source "input", an
        # unknown's index, or None (fixed); follow chains resolved here
        self.angle = {name: self._resolve(name) for name in self.names}
        self.length = {}
        for name in self.names:
            L = case.vectors[name]["length"]
            self.length[name] = self.index[(name, "length")] if L == "unknown" else mp.mpf(L)
        self.loops = [self.parse(loop) for loop in case.loops]
        size = max(v["length"] for v in case.vectors.values() if v["length"] != "unknown")
        self.scale = [size if kind == "length" else 1.0 for _, kind in self.unknowns]
        if 2 * len(self.loops) != len(self.unknowns):
            raise ValueError(
                f"{case.name}: {len(self.unknowns)} unknowns for {len(self.loops)} loops"
            )

    def _resolve(self, name):
        angle = self.case.vectors[name]["angle"]
        if angle == "input":
            return "input", 1.0, 0.0
        if angle == "unknown":
            return self.index[(name, "angle")], 1.0, 0.0
        if isinstance(angle, dict):
            src, r, o = self._resolve(angle["follow"])
            k = mp.mpf(angle.get("ratio", 1.0))
            return src, k * r, k * o + mp.mpf(angle.get("offset", 0.0))
        return None, 0.0, mp.mpf(angle)

    @staticmethod
    def parse(text):
        """A signed sum of vector names as [(+1 | -1, name)]."""
        terms, sign = [], 1
        for tok in text.replace("+", " + ").replace("-", " - ").split():
            if tok in "+-":
                sign = 1 if tok == "+" else -1
            else:
                terms.append((sign, tok))
                sign = 1
        return terms

    # --- every vector's state ------------------------------------------------
    def state(self, q, th_in):
        """``{name: (L, th, e)}``: each vector's length and angle with their
        derivatives 0..n-1 (lists) and e^{j theta}. ``q`` is the list of the
        unknowns' derivative vectors (lists of mpf), ``th_in`` the input's."""
        n = len(q)
        zero = mp.mpf(0)
        out = {}
        for name in self.names:
            src, r, o = self.angle[name]
            if src is None:
                th = [mp.mpf(o)] + [zero] * (n - 1)
            else:
                base = th_in if src == "input" else [qk[src] for qk in q]
                th = [r * base[k] for k in range(n)]
                th[0] += o
            spec = self.length[name]
            if isinstance(spec, int):
                L = [qk[spec] for qk in q]
            else:
                L = [spec] + [zero] * (n - 1)
            out[name] = (L, th, mp.expj(th[0]))
        return out

    @staticmethod
    def dz(L, th, e, n):
        """n-th time derivative of z = L e^{j theta} (eqs. 7.2, 7.19, 7.40)."""
        if n == 0:
            return L[0] * e
        w = th[1]
        if n == 1:
            return (L[1] + 1j * L[0] * w) * e
        al = th[2]
        if n == 2:
            return (L[2] - L[0] * w * w + 1j * (L[0] * al + 2 * L[1] * w)) * e
        jk = th[3]
        return (
            L[3]
            - 3 * L[1] * w * w
            - 3 * L[0] * w * al
            + 1j * (3 * L[2] * w + 3 * L[1] * al + L[0] * jk - L[0] * w**3)
        ) * e

    def _loops(self, state, n):
        out = []
        for loop in self.loops:
            s = self.sum(state, loop, n)
            out += [s.real, s.imag]
        return out

    def sum(self, state, terms, n):
        """The n-th time derivative of a signed sum of vectors (a loop or a point)."""
        s = mp.mpc(0)
        for sign, name in terms:
            L, th, e = state[name]
            s += sign * self.dz(L, th, e, n)
        return s

    def _jacobian(self, state):
        """d(loops)/d(unknowns) at a position (real, square)."""
        nu = len(self.unknowns)
        J = mp.matrix(nu, nu)
        for i, loop in enumerate(self.loops):
            for sign, name in loop:
                L, th, e = state[name]
                src, r, _ = self.angle[name]
                if isinstance(src, int):  # dz/dq = j r L e^{j theta}
                    d = sign * r * L[0] * 1j * e
                    J[2 * i, src] += d.real
                    J[2 * i + 1, src] += d.imag
                spec = self.length[name]
                if isinstance(spec, int):  # dz/dL = e^{j theta}
                    J[2 * i, spec] += sign * e.real
                    J[2 * i + 1, spec] += sign * e.imag
        return J

    def _newton(self, q0, theta2, strict):
        """Close the loops from ``q0`` (list of mpf).

        ``strict`` iterates until a step is below the working precision, or
        stops shrinking once below its square root (round-off reached: near
        a toggle the Jacobian's conditioning limits how small a step gets);
        otherwise it stops once a step is below 10^(-dps/2 + 1): quadratic
        convergence then leaves an error near 10^-dps times the curvature,
        far below float64 on a well-conditioned cycle.
        """
        q0 = list(q0)
        half = mp.mpf(10) ** (-(mp.mp.dps // 2 - 1))
        stop = mp.mpf(10) ** (-(mp.mp.dps - 6)) if strict else half
        last = None
        for _ in range(80):
            state = self.state([q0], [theta2])
            F = self._loops(state, 0)
            J = self._jacobian(state)
            dq = mp.lu_solve(J, mp.matrix([-f for f in F]))
            q0 = [q0[k] + dq[k] for k in range(len(q0))]
            size = max(abs(x) for x in dq)
            if size < stop or (last is not None and size < half and size > last / 4):
                return q0
            last = size
        raise ArithmeticError(
            f"{self.case.name}: reference Newton did not converge at theta2 = {float(theta2)!r}"
        )

    def position(self, guess, theta2, strict=True):
        """The unknowns (list of mpf, in the order of :attr:`unknowns`) that
        close the loops at ``theta2``, from ``guess``."""
        return self._newton([mp.mpf(g) for g in guess], mp.mpf(theta2), strict)

    def solve_one(self, guess, theta2, omega2, alpha2, jerk2, strict=False):
        """The unknowns and their first three time derivatives at one crank angle.

        ``guess`` lists the unknowns in the order of :attr:`unknowns`.
        Returns a list of four lists of mpf: q, q', q'', q'''.
        """
        th = [mp.mpf(theta2), mp.mpf(omega2), mp.mpf(alpha2), mp.mpf(jerk2)]
        q = [self._newton([mp.mpf(g) for g in guess], th[0], strict)]
        J = self._jacobian(self.state(q, th[:1]))
        nu = len(self.unknowns)
        for n in (1, 2, 3):
            # the n-th derivative of the loops with the unknowns' n-th derivatives at zero
            state = self.state(q + [[mp.mpf(0)] * nu], th[: n + 1])
            known = self._loops(state, n)
            x = mp.lu_solve(J, mp.matrix([-k for k in known]))
            q.append([x[k] for k in range(nu)])
        return q

    def start(self, guess):
        """The guesses (dict vector -> float) in the order of :attr:`unknowns`."""
        return [guess[name] for name, _ in self.unknowns]

    def sweep(self, theta2, guess, motion=None, dps=None):
        """Continue from ``guess`` (dict vector -> float) along ``theta2``.

        Each position starts from a cubic Taylor prediction from the last
        (its theta2-derivatives follow from the time derivatives by the
        chain rule); where Newton-Raphson fails from it, or lands far from
        it (another assembly), the step is halved, down to 1e-6 rad.
        Returns a dict output name -> list of floats.
        """
        m = dict(MOTION, **(motion or {}))
        out = {k: [] for k in self.case.outputs}
        with mp.workdps(dps or DPS):
            w, al, jk = mp.mpf(m["omega2"]), mp.mpf(m["alpha2"]), mp.mpf(m["jerk2"])
            t = mp.mpf(float(theta2[0]))
            prev = (t, self.solve_one(self.start(guess), t, w, al, jk))
            self.record(out, prev[1], t, m)
            for t in theta2[1:]:
                prev = self._step(prev, mp.mpf(float(t)), w, al, jk)
                self.record(out, prev[1], prev[0], m)
        return {k: [float(x) for x in v] for k, v in out.items()}

    def _step(self, prev, t, w, al, jk, depth=0):
        t0, (q, q1, q2, q3) = prev
        h = t - t0
        nu = len(q)
        d1 = [x / w for x in q1]
        d2 = [(q2[k] - d1[k] * al) / w**2 for k in range(nu)]
        d3 = [(q3[k] - 3 * d2[k] * w * al - d1[k] * jk) / w**3 for k in range(nu)]
        g = [q[k] + h * (d1[k] + h * (d2[k] / 2 + h * d3[k] / 6)) for k in range(nu)]
        try:
            sol = self.solve_one(g, t, w, al, jk)
            if max(abs(sol[0][k] - g[k]) / self.scale[k] for k in range(nu)) < 0.05:
                return t, sol
        except (ArithmeticError, ZeroDivisionError):
            pass
        if depth > 20:
            raise ArithmeticError(
                f"{self.case.name}: the reference cannot follow the "
                f"assembly to theta2 = {float(t)!r}"
            )
        mid = self._step(prev, (t0 + t) / 2, w, al, jk, depth + 1)
        return self._step(mid, t, w, al, jk, depth + 1)

    def record(self, out, q, theta2, motion):
        """Append the case's outputs at one solved position to ``out``."""
        th = [
            mp.mpf(theta2),
            mp.mpf(motion["omega2"]),
            mp.mpf(motion["alpha2"]),
            mp.mpf(motion["jerk2"]),
        ]
        state = self.state(q, th)
        for name, (vec, kind, n) in self.case.outputs.items():
            L, angles, _ = state[vec]
            if kind == "angle":
                value = angles[n]
                if n == 0:  # angles in (-pi, pi], as the kernels report them
                    value = mp.atan2(mp.sin(value), mp.cos(value))
            else:
                value = L[n]
            out[name].append(value)
