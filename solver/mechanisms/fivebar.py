"""The geared fivebar with Quantities in and out (kernel: accelab.solver.kernels.fivebar)."""

import numpy as np

from ..kernels import fivebar as kernel
from . import pivot
from .base import Mechanism


class GearedFiveBar(Mechanism):
    """Geared fivebar linkage (Chapter 7, section 7.4, eqs. 7.28-7.29).

    Parameters
    ----------
    a, b, c, d : Quantity or str
        Crank O2A, coupler AB, coupler CB and crank O5C lengths [length].
    f : Quantity or str
        Ground length O2O5 [length].
    lam : float
        Gear ratio theta5/theta2 (signed; -1 for equal external gears) [-].
    phi : Quantity or str
        Phase angle of link 5: theta5 = lam theta2 + phi [angle], angles from
        the ground line.
    theta1 : Quantity or str, optional
        Ground angle [angle], default 0.

    ``open`` puts B on the same side of the line A->C as the fourbar's open
    circuit puts B relative to A->O4; ``crossed`` the mirror assembly.
    """

    name = "fivebar"
    # the geometry in SI floats (Mechanism._init sets one attribute per parameter)
    _a: float
    _b: float
    _c: float
    _d: float
    _f: float
    _lam: float
    _phi: float
    _theta1: float
    _pivots = ("O2", "O5")
    _points = {
        "A": ("O2", "a", "theta2", 0.0),
        "C": ("O5", "d", "theta5", 0.0),
        "B": ("A", "b", "theta3", 0.0),
    }
    _relative = {"BA": ("b", "theta3", 0.0), "BC": ("c", "theta4", 0.0)}
    _link_bases = {2: "O2", 3: "A", 4: "C", 5: "O5"}
    _point_outputs = (
        "R_A",
        "R_B",
        "R_C",
        "V_A",
        "V_B",
        "V_C",
        "A_A",
        "A_B",
        "A_C",
        "A_BA",
        "J_A",
        "J_B",
        "J_C",
    )

    def _pivot(self, key):
        return self._f * np.exp(1j * self._theta1) if key == "O5" else 0j

    def _kernel(self, motion, circuit, order):
        return kernel.solve(
            self._a,
            self._b,
            self._c,
            self._d,
            self._f,
            self._lam,
            self._phi,
            motion["theta2"],
            motion["omega2"],
            motion["alpha2"],
            motion["jerk2"],
            self._theta1,
            circuit,
            order,
        )

    def _not_assemblable_reason(self, motion, inputs):
        return (
            f"the couplers b = {self._given_text('b')} and c = {self._given_text('c')} "
            f"cannot span the "
            f"distance between the crank pins A and C there (need |b - c| <= |C - A| <= "
            f"b + c). Choose another theta2, phase phi or link lengths."
        )

    def _pins_apart(self, inputs):
        """|C - A| [m] where the crank pins nearly meet (see :mod:`.pivot`), else None."""
        t2 = inputs["theta2"] - self._theta1
        t5 = self._lam * t2 + self._phi
        r = self._f + self._d * np.exp(1j * t5) - self._a * np.exp(1j * t2)
        span = self._a + self._b + self._c + self._d + self._f
        return abs(r) if abs(r) < span * pivot.FRACTION else None

    def _singular_reason(self, motion, inputs):
        s = self._pins_apart(inputs)
        if s is not None:
            return (
                f"the crank pins A and C come within {self._show(s)} of each other (b = c), "
                f"where the couplers' directions are undefined and each derivative divides "
                f"by |C - A| again"
            )
        return "the two couplers (links 3 and 4) are collinear"

    def _singular_advice(self, motion, inputs):
        if self._pins_apart(inputs) is not None:
            span = self._a + self._b + self._c + self._d + self._f
            return (
                f"Move theta2 until A and C are at least about "
                f"{self._show(span * pivot.FRACTION)} apart, or make b and c differ by more "
                f"than that"
            )
        return super()._singular_advice(motion, inputs)
