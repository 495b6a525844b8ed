"""accelab.solver.units: one registry, and the one rule for reading a quantity."""

import numpy as np
import pytest

from accelab.solver import FourBar, RotatingPoint, ureg
from accelab.solver.units import ureg as units_ureg


def test_one_registry():
    import pint

    assert ureg is units_ureg
    assert pint.get_application_registry().get() is ureg or pint.get_application_registry() is ureg
    assert isinstance(FourBar(a="2 in", b="6 in", c="9 in", d="7 in").a, ureg.Quantity)


def test_rpm_and_degree_inputs():
    r = RotatingPoint(p="1 m").solve(theta2="0 deg", omega2="60 rpm", alpha2="0 rad/s^2")
    assert r.A_n.m == pytest.approx(-((2 * np.pi) ** 2))  # -p omega^2 along +x
    assert r.A.to("ft/s^2").m.real == pytest.approx(-((2 * np.pi) ** 2) / 0.3048)
