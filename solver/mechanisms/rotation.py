"""A point on a rotating link and a block on a slotted link, with Quantities."""

from collections.abc import Mapping
from typing import Any

from ..kernels import rotation as kernel
from ..units import QuantityLike, to_si
from .base import Mechanism, Result


class RotatingPoint(Mechanism):
    """A point at radius p on a link in pure rotation (section 7.1, eq. 7.2).

    Outputs: R [length], V, A = A_t + A_n (tangential and normal/centripetal
    components), J.

    Examples
    --------
    >>> RotatingPoint(p="4 in").solve(theta2="30 deg", omega2="-20 rad/s",
    ...                               alpha2="15 rad/s^2").A_n
    """

    name = "rotation"
    # the geometry in SI floats (Mechanism._init sets one attribute per parameter)
    _p: float

    def _kernel(self, motion, circuit, order):
        return kernel.rotating_point(
            self._p, motion["theta2"], motion["omega2"], motion["alpha2"], motion["jerk2"]
        )


class SlottedLink(Mechanism):
    """A block sliding along a rotating link (Figure 7-7, eq. 7.19).

    Its acceleration has four parts: tangential (p alpha), normal
    (-p omega^2), Coriolis (2 p' omega, perpendicular to the link) and slip
    (p'' along the link).

    Examples
    --------
    >>> r = SlottedLink().solve(theta2="30 deg", omega2="5 rad/s", alpha2="0 rad/s^2",
    ...                         p="0.2 m", p_dot="1 m/s", p_ddot="0 m/s^2")
    >>> r.A_coriolis
    """

    name = "slotted"

    # the block's own motion (p and its rates) is a second input: not Mechanism.solve's signature
    def solve(  # type: ignore[override]
        self,
        theta2: QuantityLike,
        omega2: QuantityLike,
        alpha2: QuantityLike,
        p: QuantityLike,
        p_dot: QuantityLike,
        p_ddot: QuantityLike = 0,
        p_dddot: QuantityLike = 0,
        jerk2: QuantityLike = 0,
    ) -> Result:
        """Solve the block at one or many link angles: the link's angle and rates
        [angle, 1/time, 1/time^2, 1/time^3] and the block's distance from the pivot
        and its rates [length, velocity, acceleration, jerk]."""
        inputs = self._motion_inputs(theta2, omega2, alpha2, jerk2)
        values = {"p": p, "p_dot": p_dot, "p_ddot": p_ddot, "p_dddot": p_dddot}
        block = {q.name: to_si(values[q.name], q.name, q.kind) for q in self.declaration().point}
        return self.solve_si(inputs, **block)

    def solve_si(  # type: ignore[override]
        self,
        motion: Mapping[str, Any],
        p: Any,
        p_dot: Any,
        p_ddot: Any = 0.0,
        p_dddot: Any = 0.0,
    ) -> Result:
        """:meth:`solve` from SI floats: the motion [rad, rad/s, ...] and the
        block's distance and rates [m, m/s, m/s^2, m/s^3]."""
        inputs = dict(motion, p=p, p_dot=p_dot, p_ddot=p_ddot, p_dddot=p_dddot)
        m = kernel.slotted_link(
            motion["theta2"],
            motion["omega2"],
            motion["alpha2"],
            p,
            p_dot,
            p_ddot,
            p_dddot,
            motion["jerk2"],
        )
        return self._finish(m, inputs)
