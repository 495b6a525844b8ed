"""The inverted slider-crank with Quantities in and out
(kernel: accelab.solver.kernels.invertedslidercrank)."""

import numpy as np

from ..errors import InvalidInput
from ..kernels import invertedslidercrank as kernel
from . import pivot
from .base import Mechanism


class InvertedSliderCrank(Mechanism):
    """Inverted slider-crank (Chapter 7, section 7.3, eqs. 7.20-7.27).

    The block (link 3) is pinned to the crank at A and slides along a line
    fixed to link 4 at the angle gamma to O4B. ``b`` is the signed distance
    from B to A along that line; ``open`` is the assembly with the larger b.

    Parameters
    ----------
    a : Quantity or str
        Crank length O2A [length].
    c : Quantity or str
        Length O4B [length], >= 0 (0: the slide line passes through O4).
    d : Quantity or str
        Ground length O2O4 [length].
    gamma : Quantity or str
        Angle from O4B to the slide line [angle], signed.
    theta1 : Quantity or str, optional
        Ground angle [angle], default 0.

    Outputs beyond the fourbar's: b, b_dot, b_ddot, b_dddot; ``A_coriolis``
    (2 b' omega3 j e^{j theta3}, eq. 7.21c), ``A_slip`` (b'' e^{j theta3}),
    ``V_slip``, and ``A_A4``, the acceleration of the point of link 4 under A,
    so that A_A = A_A4 + A_slip + A_coriolis.
    """

    name = "invertedslidercrank"
    # the geometry in SI floats (Mechanism._init sets one attribute per parameter)
    _a: float
    _c: float
    _d: float
    _gamma: float
    _theta1: float
    _pivots = ("O2", "O4")
    _points = {"A": ("O2", "a", "theta2", 0.0), "B": ("O4", "c", "theta4", 0.0)}
    _link_bases = {2: "O2", 3: "A", 4: "O4"}
    _point_outputs = (
        "R_A",
        "R_B",
        "V_A",
        "V_B",
        "A_A",
        "A_B",
        "A_BA",
        "A_coriolis",
        "A_slip",
        "A_A4",
        "J_A",
        "J_B",
    )

    def _validate(self):
        if self._c < 0:
            raise InvalidInput(
                f"c must be >= 0 (got {self._given_text('c')}): it is the length "
                f"O4B; turn the slide line with gamma instead",
                "c",
            )

    def _pivot(self, key):
        return self._d * np.exp(1j * self._theta1) if key == "O4" else 0j

    def _extra(self, result, name):
        if name in ("A_coriolis", "A_slip", "V_slip", "A_A4"):
            si = result.si
            e3 = np.exp(1j * si("theta3"))
            if name == "A_coriolis":
                return 2j * si("b_dot") * si("omega3") * e3
            if name == "A_slip":
                return si("b_ddot") * e3
            if name == "V_slip":
                return si("b_dot") * e3
            return si("A_B") + si("b") * (1j * si("alpha3") - si("omega3") * si("omega3")) * e3
        return None

    def _kernel(self, motion, circuit, order):
        return kernel.solve(
            self._a,
            self._c,
            self._d,
            self._gamma,
            motion["theta2"],
            motion["omega2"],
            motion["alpha2"],
            motion["jerk2"],
            self._theta1,
            circuit,
            order,
        )

    def _not_assemblable_reason(self, motion, inputs):
        t = inputs["theta2"] - self._theta1
        s = float(np.hypot(self._a * np.cos(t) - self._d, self._a * np.sin(t)))
        reach = self._c * abs(np.sin(self._gamma))
        return (
            f"the slide line passes at least c |sin gamma| = {self._show(reach)} from O4, "
            f"but A is only |A - O4| = {self._show(s)} from O4. Choose another theta2, or "
            f"reduce c or |sin gamma|."
        )

    def _near_pivot(self, inputs):
        span = self._a + self._c + self._d
        return pivot.near(self._a, self._d, self._theta1, inputs["theta2"], span)

    def _singular_reason(self, motion, inputs):
        s = self._near_pivot(inputs)
        if s is not None:
            return pivot.reason(self._show(s), "a = d")
        return "the slide line is tangent to the crank pin's reach (b + c cos gamma = 0)"

    def _singular_advice(self, motion, inputs):
        if self._near_pivot(inputs) is not None:
            return pivot.advice(self._a, self._a + self._c + self._d, "a and d")
        return super()._singular_advice(motion, inputs)
