"""Graphical acceleration analysis of the offset slider-crank.

The slider B moves along the slide axis (angle theta1, offset c to its left),
so A_B has a known direction and an unknown length: the polygon of eq. 7.4,
``A_B = A_A + A_BA``, closes where the line along the slide through the pole
meets the line perpendicular to AB through the tip of ``A_A + A_BA^n``
(the method of Example 7-1 with pp along the slide).
"""

import cmath
import math

from ..errors import NotAssemblable
from . import crank
from .construction import Arrow, Construction, Line, Linkage
from .geometry import intersect_line_circle, intersect_lines

SIGNS = {"open": 1.0, "crossed": -1.0}


def construct(a, b, theta2, omega2, alpha2, c=0.0, theta1=0.0, circuit="open"):
    """Velocity and acceleration polygons of a slider-crank.

    Parameters
    ----------
    a, b : float
        Crank O2A and connecting rod AB lengths [m].
    theta2, omega2, alpha2 : float
        Crank angle [rad], angular velocity [rad/s], acceleration [rad/s^2].
    c : float
        Slider offset [m], signed: the slide axis passes at c e^{j(theta1 + 90 deg)}.
    theta1 : float
        Angle of the slide axis [rad].
    circuit : {'open', 'crossed'}
        ``open``: the slider on the +x side (along the slide axis) of the crank
        pin A, as in docs/conventions.md#circuits.

    Returns
    -------
    Construction
        ``values``: theta3 (of R3, from B to A), omega3, alpha3, d (slider
        position along the axis), d_dot, d_ddot, and R_A, R_B, V_A, V_B, A_A,
        A_B, A_BA with the parts A_A_n, A_A_t, A_BA_n, A_BA_t.

    Raises
    ------
    NotAssemblable
        The rod cannot reach the slide axis.
    Singular
        The rod stands perpendicular to the slide (the polygon's lines are parallel).
    """
    e1 = cmath.exp(1j * theta1)
    A = a * cmath.exp(1j * theta2)
    origin_axis = 1j * c * e1
    try:
        B, d = intersect_line_circle(origin_axis, e1, A, b, SIGNS[circuit], "the rod")
    except NotAssemblable:
        h = abs(((A - origin_axis) * e1.conjugate()).imag)
        raise NotAssemblable(
            f"the connecting rod b = {b:.6g} m cannot reach the slide axis at theta2 = "
            f"{math.degrees(theta2):.6g} deg: A is {h:.6g} m from it (need b >= "
            "|a sin(theta2 - theta1) - c|); lengthen b or change the offset c"
        ) from None
    pts = {"O2": 0j, "A": A, "B": B}
    con = Construction(
        "slidercrank",
        Linkage(
            pts, [("O2", "A"), ("A", "B")], ["O2"], slides=[(origin_axis, e1)], blocks=[("B", e1)]
        ),
        [],
        {},
        circuit,
        title=f"Slider-crank ({circuit} circuit)",
    )
    v = con.values
    R_BA = B - A
    con.step(
        "P",
        "position",
        "Draw the linkage to scale: A at a from O2; an arc of radius b about A cuts "
        f"the slide axis at B ({circuit} circuit).",
    )
    v.update(theta3=cmath.phase((A - B) / e1) + theta1, d=d)

    V_A, st = crank.velocity(con, A, omega2)
    st = con.step(
        "V2",
        "velocity",
        "V_B is along the slide: line through the pole; V_BA is perpendicular to "
        "AB: line through the tip of V_A.",
    )
    st.lines += [Line("", 0j, e1, "velocity"), Line("", V_A, 1j * R_BA, "velocity")]
    V_B, d_dot, omega3 = intersect_lines(
        0j, e1, V_A, 1j * R_BA, "the velocity lines of B (along the slide, perpendicular to AB)"
    )
    st = con.step("V3", "velocity", "The lines meet at the tip of V_B: omega3 = V_BA / AB.")
    st.arrows += [
        Arrow(r"\mathbf{V}_{B}", 0j, V_B, "resultant", "velocity"),
        Arrow(r"\mathbf{V}_{BA}", V_A, V_B - V_A, "velocity", "velocity"),
    ]
    v.update(omega3=omega3, d_dot=d_dot, R_A=A, R_B=B, V_A=V_A, V_B=V_B)

    A_A_n, A_A_t = crank.acceleration(con, A, a, omega2, alpha2)
    st = con.step(
        "3",
        "acceleration",
        "The slider translates: A_B lies along the slide axis, construction line pp.",
    )
    st.lines.append(Line("pp", B, e1, "linkage"))
    con.step("4", "acceleration", "A_B = A_A + A_BA (eq. 7.4).")
    A_BA_n = -(omega3**2) * R_BA
    st = con.step(
        "5",
        "acceleration",
        f"A_BA^n = b omega3^2 = {abs(A_BA_n):.4g} m/s^2 along BA toward A; "
        "construction line qq through B perpendicular to BA.",
    )
    st.lines.append(Line("qq", B, 1j * R_BA, "linkage"))
    A_A = A_A_t + A_A_n
    T = A_A + A_BA_n
    A_B, d_ddot, alpha3 = intersect_lines(
        0j, e1, T, 1j * R_BA, "the lines pp and qq (along the slide, perpendicular to BA)"
    )
    A_BA_t = A_B - T
    st = con.step(
        "6",
        "acceleration",
        "Polygon: A_A^t, A_A^n, A_BA^n tip to tail; a line parallel to qq through "
        "the tip and one parallel to pp through the pole meet at the tip of A_B.",
    )
    st.arrows += crank.polygon(A_A_n, A_A_t) + [
        Arrow(r"\mathbf{A}_{BA}^{n}", A_A, A_BA_n, "normal", "acceleration")
    ]
    st.lines += [Line("qq", T, 1j * R_BA, "acceleration"), Line("pp", 0j, e1, "acceleration")]
    st.arrows += [
        Arrow(r"\mathbf{A}_{BA}^{t}", T, A_BA_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{A}", 0j, A_A, "resultant", "acceleration"),
        Arrow(r"\mathbf{A}_{B}", 0j, A_B, "resultant", "acceleration"),
    ]
    st = con.step(
        "7",
        "acceleration",
        f"alpha3 = A_BA^t / BA = {alpha3:.6g} rad/s^2; the slider's acceleration "
        f"d'' = {d_ddot:.6g} m/s^2 along the axis.",
    )
    st.arrows += [
        Arrow(r"\mathbf{A}_{A}", A, A_A, "resultant", "linkage"),
        Arrow(r"\mathbf{A}_{B}", B, A_B, "resultant", "linkage"),
    ]
    v.update(
        alpha3=alpha3,
        d_ddot=d_ddot,
        A_A=A_A,
        A_B=A_B,
        A_BA=A_B - A_A,
        A_A_n=A_A_n,
        A_A_t=A_A_t,
        A_BA_n=A_BA_n,
        A_BA_t=A_BA_t,
    )
    return con
