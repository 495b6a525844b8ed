"""The fourbar with Quantities in and out (kernel: accelab.solver.kernels.fourbar)."""

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..kernels import fourbar as kernel
from ..units import QuantityLike, to_si
from . import pivot
from .base import Mechanism, Result, check_order


class FourBar(Mechanism):
    """Pin-jointed fourbar linkage (Chapter 7, section 7.3).

    Parameters
    ----------
    a, b, c, d : Quantity or str
        Crank O2A, coupler AB, rocker O4B and ground O2O4 lengths [length].
    theta1 : Quantity or str, optional
        Angle of the ground link O2->O4 [angle], default 0.

    Examples
    --------
    >>> fb = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
    >>> r = fb.solve(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")
    >>> r.alpha3, r.A_B
    """

    name = "fourbar"
    # the geometry in SI floats (Mechanism._init sets one attribute per parameter)
    _a: float
    _b: float
    _c: float
    _d: float
    _theta1: float
    _pivots = ("O2", "O4")
    _points = {"A": ("O2", "a", "theta2", 0.0), "B": ("O4", "c", "theta4", 0.0)}
    _relative = {"BA": ("b", "theta3", 0.0)}
    _link_bases = {2: "O2", 3: "A", 4: "O4"}
    _point_outputs = (
        "R_A",
        "R_B",
        "V_A",
        "V_B",
        "A_A",
        "A_B",
        "A_BA",
        "J_A",
        "J_B",
    )
    _coupler_outputs = ("R_P", "V_P", "A_P", "A_PA", "J_P")

    def _pivot(self, key):
        return self._d * np.exp(1j * self._theta1) if key == "O4" else 0j

    # the coupler point (p, delta3) comes before order, as it has since 0.1: an override
    # with more parameters than Mechanism.solve's, in the middle
    def solve(  # type: ignore[override]
        self,
        theta2: QuantityLike,
        omega2: QuantityLike,
        alpha2: QuantityLike = 0,
        jerk2: QuantityLike = 0,
        circuit: str | None = "open",
        p: QuantityLike | None = None,
        delta3: QuantityLike = 0,
        order: int = 3,
    ) -> Result:
        """Solve the fourbar at one or many crank angles.

        Parameters
        ----------
        theta2 : Quantity or str, scalar or array
            Crank angle from the global x axis [angle].
        omega2, alpha2, jerk2 : Quantity or str
            Crank angular velocity [1/time], acceleration [1/time^2] and
            jerk [1/time^3]; scalars or arrays broadcast with theta2.
        circuit : {'open', 'crossed'}
            Branch: 'open' is the chapter's eq. 4.10b with the minus sign.
        p, delta3 : Quantity or str, optional
            A coupler point P at distance p from A, at angle delta3 from line
            AB (eqs. 4.27, 7.32): adds R_P, V_P, A_P, A_PA, J_P.
        order : int
            Highest derivative to compute (0 position .. 3 jerk).

        Returns
        -------
        Result
            Lazy Quantities theta3 ... jerk4, A_A, A_B, A_BA, J_A, J_B, ...

        Raises
        ------
        NotAssemblable, Singular
            For a scalar theta2 that cannot be assembled or is at a toggle
            position. Arrays get a ``valid`` mask instead.
        """
        circuit = self._circuit(circuit)
        inputs = self._motion_inputs(theta2, omega2, alpha2, jerk2)
        point: dict[str, Any] = {}
        if p is not None:
            point = {
                "p": to_si(p, "p", "length", positive=True),
                "delta3": to_si(delta3, "delta3", "angle"),
            }
        return self.solve_si(inputs, circuit, order, **point)

    def solve_si(
        self,
        motion: Mapping[str, Any],
        circuit: str | None = "open",
        order: int = 3,
        p: float | None = None,
        delta3: float = 0.0,
    ) -> Result:
        """:meth:`solve` from SI floats: ``motion`` holds theta2, omega2, alpha2
        and jerk2 [rad, rad/s, ...], ``p`` [m] and ``delta3`` [rad] the coupler point."""
        circuit = self._circuit(circuit)
        order = check_order(order)
        inputs = dict(motion)
        pts = None
        if p is not None:
            inputs.update(p=p, delta3=delta3)
            pts = dict(self._points, P=("A", p, "theta3", delta3))
        m = kernel.solve(
            self._a,
            self._b,
            self._c,
            self._d,
            inputs["theta2"],
            inputs["omega2"],
            inputs["alpha2"],
            inputs["jerk2"],
            self._theta1,
            circuit,
            order,
        )
        return self._finish(m, inputs, pts=pts)

    def outputs(self, result: Result) -> tuple[str, ...]:
        """The fourbar's outputs, with those of the coupler point P (``R_P``,
        ``V_P``, ``A_P``, ``A_PA``, ``J_P``) when the mechanism has one."""
        coupler = self._coupler_outputs if result.has_point("P") else ()
        return super().outputs(result) + coupler

    def _not_assemblable_reason(self, motion, inputs):
        t = inputs["theta2"] - self._theta1
        s = float(np.hypot(self._d - self._a * np.cos(t), self._a * np.sin(t)))
        need = (
            f"the coupler (b = {self._given_text('b')}) and rocker (c = "
            f"{self._given_text('c')}) must span the distance |A - O4| = {self._show(s)}, "
            f"which needs |b - c| <= |A - O4| <= b + c"
        )
        return need + ". " + self._crank_range_text()

    def _crank_range_text(self):
        """Where the crank can sit: |b - c| <= |A - O4| <= b + c as a range of theta2."""
        a, b, c, d = self._a, self._b, self._c, self._d
        lower = (a * a + d * d - (b + c) ** 2) / (2 * a * d)  # cos(theta2) >= lower
        upper = (a * a + d * d - (b - c) ** 2) / (2 * a * d)  # cos(theta2) <= upper
        if lower > 1 or upper < -1:
            return "These lengths never close the loop: change the link lengths."
        lo = np.degrees(np.arccos(min(1.0, upper)))
        hi = np.degrees(np.arccos(max(-1.0, lower)))
        return (
            f"With these lengths theta2 - theta1 must lie within +/-({lo:.4g} to {hi:.4g}) "
            f"deg; choose theta2 there or change the link lengths."
        )

    def _near_pivot(self, inputs):
        span = self._a + self._b + self._c + self._d
        return pivot.near(self._a, self._d, self._theta1, inputs["theta2"], span)

    def _singular_reason(self, motion, inputs):
        s = self._near_pivot(inputs)
        if s is not None:
            return pivot.reason(self._show(s), "a = d and b = c: a kite")
        return "the coupler and rocker (links 3 and 4) are collinear (a toggle position)"

    def _singular_advice(self, motion, inputs):
        if self._near_pivot(inputs) is not None:
            span = self._a + self._b + self._c + self._d
            return pivot.advice(self._a, span, "a and d, or b and c,")
        return super()._singular_advice(motion, inputs)
