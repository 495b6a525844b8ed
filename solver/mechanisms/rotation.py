"""A point on a rotating link and a block on a slotted link, with Quantities."""

import numpy as np

from ..kernels import Motion, OK
from ..kernels import rotation as kernel
from ..units import to_si
from .base import Mechanism


class RotatingPoint(Mechanism):
    """A point at radius p on a link in pure rotation (section 7.1, eq. 7.2).

    Outputs: R [length], V, A = A_t + A_n (tangential and normal/centripetal
    components), J.

    Examples
    --------
    >>> RotatingPoint(p="4 in").solve(theta2="30 deg", omega2="-20 rad/s",
    ...                               alpha2="15 rad/s^2").A_n
    """

    _geometry = {"p": ("length", True, None)}
    _outputs = ("R", "V", "A", "A_t", "A_n", "J")

    def solve(self, theta2, omega2, alpha2=0, jerk2=0):
        inputs = self._motion_inputs(theta2, omega2, alpha2, jerk2)
        m = kernel.rotating_point(self._p, inputs["theta2"], inputs["omega2"],
                                  inputs["alpha2"], inputs["jerk2"])
        shape = np.shape(m.A)
        m.status = np.zeros(shape, dtype=np.int8) if shape else np.int8(OK)
        m.condition = np.ones(shape) if shape else 1.0
        m.circuit = None
        return self._finish(m, inputs)


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

    _geometry = {}
    _outputs = ("R", "V", "V_t", "V_slip", "A", "A_t", "A_n", "A_coriolis", "A_slip", "J")

    def solve(self, theta2, omega2, alpha2, p, p_dot, p_ddot=0, p_dddot=0,
              jerk2=0):
        inputs = self._motion_inputs(theta2, omega2, alpha2, jerk2)
        inputs.update(p=to_si(p, "p", "length"), p_dot=to_si(p_dot, "p_dot", "velocity"),
                      p_ddot=to_si(p_ddot, "p_ddot", "acceleration"),
                      p_dddot=to_si(p_dddot, "p_dddot", "jerk"))
        m = kernel.slotted_link(inputs["theta2"], inputs["omega2"], inputs["alpha2"],
                                inputs["p"], inputs["p_dot"], inputs["p_ddot"],
                                inputs["p_dddot"], inputs["jerk2"])
        shape = np.shape(m.A)
        m.status = np.zeros(shape, dtype=np.int8) if shape else np.int8(OK)
        m.condition = np.ones(shape) if shape else 1.0
        m.circuit = None
        return self._finish(m, inputs)
