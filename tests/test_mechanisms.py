"""accelab.solver.mechanisms, the unit-aware layer: conversion at the boundary,
Quantities out, errors that name the parameter, scalar/array agreement, and
lazy outputs."""

import numpy as np
import pytest

from accelab.solver import (
    Q_,
    FourBar,
    GearedFiveBar,
    InvalidInput,
    InvertedSliderCrank,
    NotAssemblable,
    RotatingPoint,
    Singular,
    SliderCrank,
    SlottedLink,
    ureg,
)
from accelab.solver.kernels import fourbar as fourbar_kernel


def test_units_do_not_change_the_answer():
    """The same linkage in inches/degrees and in metres/radians agrees exactly."""
    us = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2"
    )
    si = FourBar(a=Q_(0.0508, "m"), b=Q_(0.1524, "m"), c=Q_(0.2286, "m"), d=Q_(0.1778, "m")).solve(
        theta2=Q_(np.pi / 6, "rad"), omega2=Q_(10, "rad/s"), alpha2=Q_(-5, "rad/s^2")
    )
    for name in ("theta3", "omega4", "alpha3", "jerk4"):
        assert getattr(us, name).m == pytest.approx(getattr(si, name).m, rel=1e-13)
    assert us.A_B.to("m/s^2").m == pytest.approx(si.A_B.m, rel=1e-13)
    assert str(us.A_B.units) == "meter / second ** 2"


@pytest.mark.parametrize(
    "kwargs, name, words",
    [
        (dict(a="2 s"), "a", "must be a length"),
        (dict(a=2.0), "a", "needs units"),
        (dict(a="-2 in"), "a", "must be positive"),
        (dict(a="0 in"), "a", "must be positive"),
        (dict(a="nan in"), "a", "must be finite"),
        (dict(a="inf in"), "a", "must be finite"),
        (dict(a="two inches"), "a", "could not be read"),
        (dict(theta1="3 in"), "theta1", "must be an angle"),
    ],
)
def test_invalid_geometry_names_the_parameter(kwargs, name, words):
    geometry = dict(a="2 in", b="6 in", c="9 in", d="7 in")
    geometry.update(kwargs)
    with pytest.raises(InvalidInput, match=words) as info:
        FourBar(**geometry)
    assert info.value.parameter == name
    assert name in str(info.value)
    assert info.value.kind == "invalid_input"


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(theta2="30"), "theta2"),  # a bare number could be degrees or radians
        (dict(theta2="30 in"), "theta2"),
        (dict(omega2="10 rad/s^2"), "omega2"),
        (dict(omega2=10), "omega2"),
        (dict(alpha2="5 m/s^2"), "alpha2"),
        (dict(jerk2="1 rad/s^2"), "jerk2"),
        (dict(circuit="closed"), "circuit"),
    ],
)
def test_invalid_motion_names_the_parameter(kwargs, name):
    args = dict(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")
    args.update(kwargs)
    with pytest.raises(InvalidInput) as info:
        FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(**args)
    assert info.value.parameter == name
    assert "Example" in str(info.value) or "one of" in str(info.value)


def test_unknown_geometry_keyword():
    with pytest.raises(InvalidInput, match="has no parameter e"):
        FourBar(a="2 in", b="6 in", c="9 in", d="7 in", e="1 in")
    with pytest.raises(InvalidInput, match="needs d"):
        FourBar(a="2 in", b="6 in", c="9 in")


def test_not_assemblable_scalar_raises_with_a_fix():
    fb = FourBar(a="3 in", b="4 in", c="5 in", d="13 in")
    with pytest.raises(NotAssemblable, match=r"\|b - c\| <= \|A - O4\| <= b \+ c"):
        fb.solve(theta2="45 deg", omega2="100 rpm")


def test_sweep_returns_mask_instead_of_raising():
    # a non-Grashof linkage: the crank cannot turn fully
    fb = FourBar(a="5 in", b="3 in", c="4 in", d="6 in")
    theta2 = Q_(np.linspace(0, 360, 721), "deg")
    r = fb.solve(theta2=theta2, omega2="1 rad/s", alpha2="0 rad/s^2")
    assert r.valid.dtype == bool and r.valid.shape == (721,)
    assert 0 < r.valid.sum() < 721
    assert np.all(np.isnan(r.alpha3.m[~r.valid]))
    assert np.all(np.isfinite(r.alpha3.m[r.valid]))
    assert set(r.status) <= {"ok", "not_assemblable", "singular"}
    assert "not_assemblable" in set(r.status)


def test_scalar_and_array_agree():
    fb = FourBar(a="2 in", b="6 in", c="9 in", d="7 in", theta1="10 deg")
    angles = np.radians([0.0, 33.0, 170.0, 271.0])
    arr = fb.solve(
        theta2=Q_(angles, "rad"),
        omega2="10 rad/s",
        alpha2="-5 rad/s^2",
        jerk2="3 rad/s^3",
        p="3 in",
        delta3="20 deg",
    )
    for i, t in enumerate(angles):
        one = fb.solve(
            theta2=Q_(t, "rad"),
            omega2="10 rad/s",
            alpha2="-5 rad/s^2",
            jerk2="3 rad/s^3",
            p="3 in",
            delta3="20 deg",
        )
        for name in one.outputs():
            assert np.allclose(getattr(one, name).m, getattr(arr, name).m[i], rtol=4e-16, atol=0)


def test_singular_scalar_raises_and_sweep_masks():
    # a = 2, b = 3, c = 4, d = 5: the crank's limit is where b + c = |A - O4|... use a toggle
    # of links 3 and 4 of a crank-rocker-free linkage: s = b + c
    a, b, c, d = 4.0, 3.0, 2.0, 5.0
    # s^2 = a^2 + d^2 - 2 a d cos(t) = (b + c)^2  -> t at the limit
    t_lim = np.arccos((a * a + d * d - (b + c) ** 2) / (2 * a * d))
    fb = FourBar(a=Q_(a, "m"), b=Q_(b, "m"), c=Q_(c, "m"), d=Q_(d, "m"))
    with pytest.raises(Singular) as info:
        fb.solve(theta2=Q_(t_lim - 1e-13, "rad"), omega2="1 rad/s")
    assert info.value.condition < 1e-4
    assert "limit position" in str(info.value)
    r = fb.solve(theta2=Q_(t_lim - 1e-3, "rad"), omega2="1 rad/s")  # far enough: answered
    assert r.valid and 0 < r.condition < 0.1


def test_outputs_are_lazy_and_cached():
    r = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(theta2="30 deg", omega2="10 rad/s")
    assert "A_B" not in r._cache
    first = r.si("A_B")
    assert r._cache["A_B"] is first


def test_acceleration_difference_and_components():
    r = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2", p="3 in", delta3="30 deg"
    )
    # eq. 7.4: A_B = A_A + A_BA, and each splits into tangential + normal parts
    assert np.isclose(r.si("A_B"), r.si("A_A") + r.si("A_BA"), rtol=1e-14)
    assert np.isclose(r.si("A_BA"), r.si("A_BA_t") + r.si("A_BA_n"), rtol=1e-14)
    assert np.isclose(r.si("A_B"), r.si("A_B_t") + r.si("A_B_n"), rtol=1e-14)
    assert np.isclose(r.si("A_P"), r.si("A_A") + r.si("A_PA"), rtol=1e-14)
    # the normal part points from B towards O4, the tangential part is perpendicular
    e4 = np.exp(1j * r.si("theta4"))
    assert abs((r.si("A_B_n") / e4).imag) < 1e-12 * abs(r.si("A_B_n"))
    assert abs((r.si("A_B_t") / e4).real) < 1e-12 * abs(r.si("A_B_t"))
    with pytest.raises(AttributeError, match="no output"):
        r.A_Q


def test_slider_crank_slider_moves_along_the_axis():
    sc = SliderCrank(a="40 mm", b="120 mm", c="10 mm", theta1="20 deg")
    r = sc.solve(theta2="60 deg", omega2="3000 rpm", alpha2="0 rad/s^2")
    axis = np.exp(1j * np.radians(20))
    assert np.isclose(r.si("A_B"), r.si("d_ddot") * axis, rtol=1e-14)
    assert np.isclose(r.si("A_BA"), r.si("A_BA_t") + r.si("A_BA_n"), rtol=1e-13)
    assert r.d.units == ureg.m


def test_inverted_slider_crank_splits_acceleration_of_A():
    isc = InvertedSliderCrank(a="4 in", c="3 in", d="8 in", gamma="90 deg")
    r = isc.solve(theta2="45 deg", omega2="20 rad/s", alpha2="10 rad/s^2")
    # A on the crank = point of link 4 under A + slip + Coriolis (eqs. 7.19, 7.21)
    assert np.isclose(r.si("A_A"), r.si("A_A4") + r.si("A_slip") + r.si("A_coriolis"), rtol=1e-13)
    # Coriolis is perpendicular to the slide line, slip along it
    e3 = np.exp(1j * r.si("theta3"))
    assert abs((r.si("A_coriolis") / e3).real) < 1e-12 * abs(r.si("A_coriolis"))
    assert r.omega3 == r.omega4
    with pytest.raises(InvalidInput, match="c must be >= 0"):
        InvertedSliderCrank(a="4 in", c="-3 in", d="8 in", gamma="90 deg")


def test_geared_fivebar_link5_follows_the_gears():
    fb5 = GearedFiveBar(a="1 in", b="4 in", c="4 in", d="1 in", f="3 in", lam=-2, phi="30 deg")
    r = fb5.solve(theta2="40 deg", omega2="10 rad/s", alpha2="5 rad/s^2", jerk2="7 rad/s^3")
    assert r.theta5.to("deg").m == pytest.approx(-80 + 30)
    assert r.omega5.m == -20 and r.alpha5.m == -10 and r.jerk5.m == -14
    assert np.isclose(r.si("A_B"), r.si("A_C") + r.si("A_BC_t") + r.si("A_BC_n"), rtol=1e-12)


def test_slotted_link_components():
    r = SlottedLink().solve(
        theta2="90 deg",
        omega2="2 rad/s",
        alpha2="3 rad/s^2",
        p="0.5 m",
        p_dot="1 m/s",
        p_ddot="4 m/s^2",
    )
    # link along +y: normal points to -y, tangential and Coriolis along -x, slip along +y
    assert np.allclose([r.A_n.m.real, r.A_n.m.imag], [0, -2.0], atol=1e-15)
    assert np.allclose([r.A_t.m.real, r.A_t.m.imag], [-1.5, 0], atol=1e-15)
    assert np.allclose([r.A_coriolis.m.real, r.A_coriolis.m.imag], [-4.0, 0], atol=1e-15)
    assert np.allclose([r.A_slip.m.real, r.A_slip.m.imag], [0, 4.0], atol=1e-15)
    assert r.A.m == pytest.approx(r.A_n.m + r.A_t.m + r.A_coriolis.m + r.A_slip.m)


def test_problem_7_1_rotating_point():
    """Problem 7-1 style: a point at radius 4 in at 30 deg turning at -20 rad/s (CW)
    and +15 rad/s^2: A_n = -p w^2 e^{j theta}, A_t = p alpha j e^{j theta}."""
    r = RotatingPoint(p="4 in").solve(theta2="30 deg", omega2="-20 rad/s", alpha2="15 rad/s^2")
    a_n = -4 * 400 * np.exp(1j * np.pi / 6)
    a_t = 4 * 15 * 1j * np.exp(1j * np.pi / 6)
    assert r.A_n.to("in/s^2").m == pytest.approx(a_n)
    assert r.A_t.to("in/s^2").m == pytest.approx(a_t)
    assert abs(r.A.to("in/s^2").m) == pytest.approx(np.hypot(1600, 60))


def test_kernel_has_no_pint():
    import ast
    import pathlib

    for path in pathlib.Path(fourbar_kernel.__file__).parent.glob("*.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                names = [a.name for a in node.names] + [getattr(node, "module", "") or ""]
                assert not any(n.split(".")[0] == "pint" for n in names), path
                assert not any("units" in n for n in names if n), path


def test_any_point_on_any_link():
    """eqs. 7.30-7.32: a point on link 3 given by (p, delta) from A equals the coupler
    point; the mid-point of the rocker has half of B's acceleration."""
    fb = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
    r = fb.solve(
        theta2="30 deg",
        omega2="10 rad/s",
        alpha2="-5 rad/s^2",
        jerk2="2 rad/s^3",
        p="3 in",
        delta3="30 deg",
    )
    pt = r.point(3, "3 in", "30 deg")
    for name in ("R", "V", "A", "J"):
        assert np.isclose(pt.si(name), r.si(name + "_P"), rtol=1e-14)
    cg4 = r.point(4, "4.5 in")
    assert np.isclose(cg4.si("A"), r.si("A_B") / 2, rtol=1e-14)
    assert np.isclose(cg4.si("J"), r.si("J_B") / 2, rtol=1e-14)
    assert np.isclose(cg4.si("A_t") + cg4.si("A_n"), cg4.si("A"), rtol=1e-14)
    with pytest.raises(InvalidInput, match="no rotating link 7"):
        r.point(7, "1 in")
    sweep = fb.solve(theta2=Q_([10, 20, 30], "deg"), omega2="10 rad/s")
    assert sweep.point(4, "1 in").A.shape == (3,)
