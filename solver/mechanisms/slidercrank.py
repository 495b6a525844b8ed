"""The offset slider-crank with Quantities in and out
(kernel: accelab.solver.kernels.slidercrank)."""

import numpy as np

from ..kernels import slidercrank as kernel
from .base import Mechanism


class SliderCrank(Mechanism):
    """Offset slider-crank (Chapter 7, section 7.3, eqs. 7.14-7.16).

    Parameters
    ----------
    a, b : Quantity or str
        Crank O2A and connecting rod AB lengths [length].
    c : Quantity or str, optional
        Slider offset [length], signed, default 0.
    theta1 : Quantity or str, optional
        Angle of the slide axis [angle], default 0.

    ``circuit='open'`` (of :meth:`solve`) has the slider on the +x side of the
    crank pin (cos theta3 < 0 in the slide-axis frame). Outputs: theta3,
    omega3, alpha3, jerk3, d [length] (the slider's position along the axis),
    d_dot, d_ddot, d_dddot, A_A, A_B, A_BA, J_A, J_B ...

    Examples
    --------
    >>> sc = SliderCrank(a="40 mm", b="120 mm", c="10 mm")
    >>> sc.solve(theta2="60 deg", omega2="3000 rpm").d_ddot
    """

    name = "slidercrank"
    # the geometry in SI floats (Mechanism._init sets one attribute per parameter)
    _a: float
    _b: float
    _c: float
    _theta1: float
    _relative = {"BA": ("b", "theta3", np.pi)}
    _link_bases = {2: "O2", 3: "A"}
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

    def _init(self, si, given, units):
        super()._init(si, given, units)
        self._points = {"A": ("O2", self._a, "theta2", 0.0), "B": (None, self._slider, None, 0.0)}

    def _slider(self, result, order):
        axis = np.exp(1j * self._theta1)
        if order == 0:
            return (result.si("d") + 1j * self._c) * axis
        return result.si(("d_dot", "d_ddot", "d_dddot")[order - 1]) * axis

    def _kernel(self, motion, circuit, order):
        return kernel.solve(
            self._a,
            self._b,
            self._c,
            motion["theta2"],
            motion["omega2"],
            motion["alpha2"],
            motion["jerk2"],
            self._theta1,
            circuit,
            order,
        )

    def _not_assemblable_reason(self, motion, inputs):
        y = self._a * np.sin(inputs["theta2"] - self._theta1) - self._c
        return (
            f"the crank pin is {self._show(abs(y))} from the slide line but the rod is "
            f"only b = {self._given_text('b')} long (need |a sin(theta2) - c| <= b). Choose "
            f"another theta2, a longer rod or a smaller offset."
        )

    def _singular_reason(self, motion, inputs):
        return "the connecting rod is perpendicular to the slide"
