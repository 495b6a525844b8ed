"""Graphical acceleration analysis of the geared fivebar (section 7.4).

The gears fix link 5 to the input: theta5 = lam theta2 + phi (from the
ground line), omega5 = lam omega2, alpha5 = lam alpha2. So A (on crank 2)
and C (on crank 5) are both points in pure rotation whose accelerations are
known, and B is found from both of them, as in Example 7-1 but with two
moving "pivots":

    A_B = A_A + A_BA^n + A_BA^t = A_C + A_BC^n + A_BC^t

The line of A_BA^t (perpendicular to AB) through the tip of A_A + A_BA^n and
the line of A_BC^t (perpendicular to CB) through the tip of A_C + A_BC^n
meet at the tip of A_B.
"""

import cmath
import math

from ..errors import NotAssemblable
from . import crank
from .construction import Arrow, Construction, Line, Linkage
from .geometry import intersect_circles, intersect_lines

SIDES = {"open": 1.0, "crossed": -1.0}


def construct(a, b, c, d, f, lam, phi, theta2, omega2, alpha2, theta1=0.0, circuit="open"):
    """Velocity and acceleration polygons of a geared fivebar.

    Parameters
    ----------
    a, b, c, d : float
        Crank 2 (O2A), coupler 3 (AB), coupler 4 (CB), crank 5 (O5C) [m].
    f : float
        Ground O2O5 [m].
    lam : float
        Gear ratio theta5 / theta2 [-] (negative for external gears).
    phi : float
        Phase angle of link 5 [rad].
    theta2, omega2, alpha2 : float
        Input angle [rad], angular velocity [rad/s], acceleration [rad/s^2].
    theta1 : float
        Angle of the ground line O2->O5 [rad].
    circuit : {'open', 'crossed'}
        ``open`` puts B to the left of the line A->C (as the fourbar's open
        circuit does with A->O4, and as the analytic solver defines it).

    Returns
    -------
    Construction
        ``values``: theta3, theta4, theta5, omega3..5, alpha3..5, and R_A,
        R_B, R_C, V_A, V_B, V_C, A_A, A_B, A_C, A_BA, A_BC with their parts.

    Raises
    ------
    NotAssemblable
        The arcs b about A and c about C do not meet.
    Singular
        Links 3 and 4 in line (the polygon's lines are parallel).
    """
    e1 = cmath.exp(1j * theta1)
    theta5 = lam * (theta2 - theta1) + phi + theta1
    omega5, alpha5 = lam * omega2, lam * alpha2
    O5 = f * e1
    A = a * cmath.exp(1j * theta2)
    R_CO5 = d * cmath.exp(1j * theta5)
    C = O5 + R_CO5
    try:
        B = intersect_circles(A, b, C, c, SIDES[circuit], "couplers 3 and 4")
    except NotAssemblable:
        raise NotAssemblable(
            f"the links cannot close at theta2 = {math.degrees(theta2):.6g} deg: arcs b = "
            f"{b:.6g} m about A and c = {c:.6g} m about C (at theta5 = "
            f"{math.degrees(theta5):.6g} deg) do not meet, A and C being {abs(C - A):.6g} m "
            "apart (need |b - c| <= |C - A| <= b + c); change the lengths, lam, phi or the "
            "input angle"
        ) from None
    pts = {"O2": 0j, "A": A, "B": B, "C": C, "O5": O5}
    con = Construction(
        "fivebar",
        Linkage(pts, [("O2", "A"), ("A", "B"), ("C", "B"), ("O5", "C")], ["O2", "O5"]),
        [],
        {},
        circuit,
        title=f"Geared fivebar ({circuit} circuit)",
    )
    v = con.values
    R_BA, R_BC = B - A, B - C
    con.step(
        "P",
        "position",
        "Draw the linkage to scale: A at a from O2; the gears put C at d from O5 at "
        "theta5 = lam theta2 + phi; arcs b about A and c about C meet at B "
        f"({circuit} circuit).",
    )
    v.update(
        theta3=cmath.phase(R_BA / e1) + theta1,
        theta4=cmath.phase(R_BC / e1) + theta1,
        theta5=theta5,
        R_A=A,
        R_B=B,
        R_C=C,
    )

    V_A = 1j * omega2 * A
    V_C = 1j * omega5 * R_CO5
    st = con.step(
        "V1",
        "velocity",
        "Velocity polygon: V_A = a omega2 perpendicular to O2A and V_C = d omega5 "
        "(omega5 = lam omega2) perpendicular to O5C, from the pole.",
    )
    st.arrows += [
        Arrow(r"\mathbf{V}_{A}", 0j, V_A, "velocity", "velocity"),
        Arrow(r"\mathbf{V}_{C}", 0j, V_C, "velocity", "velocity"),
    ]
    st = con.step(
        "V2",
        "velocity",
        "V_BA is perpendicular to AB: line through the tip of V_A; V_BC is "
        "perpendicular to CB: line through the tip of V_C.",
    )
    st.lines += [Line("", V_A, 1j * R_BA, "velocity"), Line("", V_C, 1j * R_BC, "velocity")]
    V_B, omega3, omega4 = intersect_lines(
        V_A, 1j * R_BA, V_C, 1j * R_BC, "the velocity lines of B (perpendicular to AB and CB)"
    )
    st = con.step(
        "V3",
        "velocity",
        "The lines meet at the tip of V_B: omega3 = V_BA / AB, omega4 = V_BC / CB.",
    )
    st.arrows += [
        Arrow(r"\mathbf{V}_{B}", 0j, V_B, "resultant", "velocity"),
        Arrow(r"\mathbf{V}_{BA}", V_A, V_B - V_A, "velocity", "velocity"),
        Arrow(r"\mathbf{V}_{BC}", V_C, V_B - V_C, "velocity", "velocity"),
    ]
    v.update(omega3=omega3, omega4=omega4, omega5=omega5, V_A=V_A, V_B=V_B, V_C=V_C)

    A_A_n, A_A_t = -(omega2**2) * A, alpha2 * 1j * A
    A_C_n, A_C_t = -(omega5**2) * R_CO5, alpha5 * 1j * R_CO5
    A_A, A_C = A_A_n + A_A_t, A_C_n + A_C_t
    con.step(
        "1",
        "acceleration",
        f"A_A^n = a omega2^2 = {abs(A_A_n):.4g} m/s^2, A_A^t = a alpha2; A_C^n = d omega5^2 "
        f"= {abs(A_C_n):.4g} m/s^2, A_C^t = d alpha5 with alpha5 = lam alpha2 (eq. 7.6).",
    )
    st = con.step(
        "2",
        "acceleration",
        "At A and C: the normal components toward O2 and O5, the tangential ones "
        "perpendicular to the cranks.",
    )
    st.arrows += [
        Arrow(r"\mathbf{A}_{A}^{n}", A, A_A_n, "normal", "linkage"),
        Arrow(r"\mathbf{A}_{A}^{t}", A, A_A_t, "tangential", "linkage"),
        Arrow(r"\mathbf{A}_{C}^{n}", C, A_C_n, "normal", "linkage"),
        Arrow(r"\mathbf{A}_{C}^{t}", C, A_C_t, "tangential", "linkage"),
    ]
    A_BA_n, A_BC_n = -(omega3**2) * R_BA, -(omega4**2) * R_BC
    st = con.step(
        "3",
        "acceleration",
        "A_B = A_A + A_BA = A_C + A_BC (eq. 7.4). Construction lines through B: qq "
        "perpendicular to BA (A_BA^t) and pp perpendicular to BC (A_BC^t).",
    )
    st.lines += [Line("qq", B, 1j * R_BA, "linkage"), Line("pp", B, 1j * R_BC, "linkage")]
    TA, TC = A_A + A_BA_n, A_C + A_BC_n
    X, alpha3, alpha4 = intersect_lines(
        TA, 1j * R_BA, TC, 1j * R_BC, "the lines qq and pp (perpendicular to BA and BC)"
    )
    A_BA_t, A_BC_t = X - TA, X - TC
    st = con.step(
        "4",
        "acceleration",
        "Polygon: A_A^t, A_A^n, then A_BA^n and a line parallel to qq; from the pole "
        "also A_C^t, A_C^n, then A_BC^n and a line parallel to pp; they meet at the "
        "tip of A_B.",
    )
    st.arrows += crank.polygon(A_A_n, A_A_t) + [
        Arrow(r"\mathbf{A}_{BA}^{n}", A_A, A_BA_n, "normal", "acceleration"),
        Arrow(r"\mathbf{A}_{C}^{t}", 0j, A_C_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{C}^{n}", A_C_t, A_C_n, "normal", "acceleration"),
        Arrow(r"\mathbf{A}_{BC}^{n}", A_C, A_BC_n, "normal", "acceleration"),
    ]
    st.lines += [
        Line("qq", TA, 1j * R_BA, "acceleration"),
        Line("pp", TC, 1j * R_BC, "acceleration"),
    ]
    st.arrows += [
        Arrow(r"\mathbf{A}_{BA}^{t}", TA, A_BA_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{BC}^{t}", TC, A_BC_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{B}", 0j, X, "resultant", "acceleration"),
    ]
    st = con.step(
        "5",
        "acceleration",
        f"alpha3 = A_BA^t / BA = {alpha3:.6g} rad/s^2, alpha4 = A_BC^t / BC = "
        f"{alpha4:.6g} rad/s^2; the results drawn on the linkage.",
    )
    st.arrows += [
        Arrow(r"\mathbf{A}_{A}", A, A_A, "resultant", "linkage"),
        Arrow(r"\mathbf{A}_{C}", C, A_C, "resultant", "linkage"),
        Arrow(r"\mathbf{A}_{B}", B, X, "resultant", "linkage"),
    ]
    v.update(
        alpha3=alpha3,
        alpha4=alpha4,
        alpha5=alpha5,
        A_A=A_A,
        A_B=X,
        A_C=A_C,
        A_BA=X - A_A,
        A_BC=X - A_C,
        A_A_n=A_A_n,
        A_A_t=A_A_t,
        A_C_n=A_C_n,
        A_C_t=A_C_t,
        A_BA_n=A_BA_n,
        A_BA_t=A_BA_t,
        A_BC_n=A_BC_n,
        A_BC_t=A_BC_t,
    )
    return con
