"""Graphical acceleration analysis of the fourbar, step by step (Example 7-1, Figure 7-4).

The construction uses only the link lengths and the input motion. The
linkage is first drawn to scale (two arcs locate B), then the velocity
polygon gives omega3 and omega4, then the acceleration polygon of
eq. 7.4, ``A_B = A_A + A_BA``, closed by the construction lines pp and qq,
gives alpha3 and alpha4 (steps 1 to 8 of Example 7-1).

Every construction line is drawn through a known point along a direction
``j R`` (perpendicular to a link R), so the parameter at which two lines
meet is the angular velocity or acceleration of that link: reading the
polygon is measuring along the lines.
"""

import cmath
import math

from ..errors import NotAssemblable
from . import crank
from .construction import Arrow, Construction, Line, Linkage
from .geometry import intersect_circles, intersect_lines

SIDES = {"open": 1.0, "crossed": -1.0}


def construct(a, b, c, d, theta2, omega2, alpha2, theta1=0.0, circuit="open", p=None, delta3=0.0):
    """Velocity and acceleration polygons of a fourbar (Example 7-1).

    Parameters
    ----------
    a, b, c, d : float
        Crank O2A, coupler AB, rocker O4B and ground O2O4 lengths [m].
    theta2 : float
        Crank angle [rad] from the global x axis.
    omega2, alpha2 : float
        Crank angular velocity [rad/s] and acceleration [rad/s^2].
    theta1 : float
        Angle of the ground line O2->O4 [rad].
    circuit : {'open', 'crossed'}
        ``open`` puts B to the left of the line A->O4 (the chapter's
        eq. 4.10b with the minus sign), ``crossed`` to the right.
    p, delta3 : float, optional
        Coupler point P at distance p [m] from A, at angle delta3 [rad]
        from line AB (the chapter's point C of Figure 7-4).

    Returns
    -------
    Construction
        ``values``: theta3, theta4, omega3, omega4, alpha3, alpha4 and the
        vectors R_A, R_B, V_A, V_B, A_A, A_B, A_BA with their normal and
        tangential parts (A_A_n, A_A_t, A_B_n, A_B_t, A_BA_n, A_BA_t), and
        R_P, V_P, A_P, A_PA when p is given.

    Raises
    ------
    NotAssemblable
        The arcs that locate B do not meet.
    Singular
        The construction lines are parallel (links 3 and 4 in line).
    """
    side = SIDES[circuit]
    O2 = 0j
    O4 = d * cmath.exp(1j * theta1)
    A = a * cmath.exp(1j * theta2)
    pts = {"O2": O2, "A": A, "O4": O4}
    links = [("O2", "A"), ("A", "B"), ("O4", "B")]
    con = Construction(
        "fourbar",
        Linkage(pts, links, ["O2", "O4"]),
        [],
        {},
        circuit,
        title=f"Fourbar ({circuit} circuit)",
    )
    v = con.values

    # -- position: swing arc b about A and arc c about O4; they meet at B
    try:
        B = intersect_circles(A, b, O4, c, side, "the coupler and rocker")
    except NotAssemblable:
        s = abs(O4 - A)
        raise NotAssemblable(
            f"the links cannot close at theta2 = {math.degrees(theta2):.6g} deg: the arcs "
            f"b = {b:.6g} m about A and c = {c:.6g} m about O4 do not meet, since A is "
            f"{s:.6g} m from O4 (need |b - c| <= |O4 - A| <= b + c); change the lengths or "
            "the input angle"
        ) from None
    pts["B"] = B
    R_BA, R_BO4 = B - A, B - O4
    st = con.step(
        "P",
        "position",
        "Draw the linkage to scale: A at a from O2; arcs of radius b about A and "
        f"c about O4 meet at B ({circuit} circuit).",
    )
    e1 = cmath.exp(1j * theta1)  # angles from the ground line, plus theta1 (as the solver)
    v["theta3"] = cmath.phase(R_BA / e1) + theta1
    v["theta4"] = cmath.phase(R_BO4 / e1) + theta1
    if p is not None:
        P = A + p * cmath.exp(1j * (v["theta3"] + delta3))
        pts["P"] = P
        con.linkage.links.append(("A", "P", "B"))
        st.text += " P is fixed to link 3 at p from A, delta3 from AB."

    # -- velocity polygon: V_B = V_A + V_BA (eq. 6.5)
    V_A, st = crank.velocity(con, A, omega2)
    st = con.step(
        "V2",
        "velocity",
        "V_B is perpendicular to O4B: line through the pole; V_BA is perpendicular "
        "to AB: line through the tip of V_A.",
    )
    st.lines += [Line("", 0j, 1j * R_BO4, "velocity"), Line("", V_A, 1j * R_BA, "velocity")]
    V_B, omega4, omega3 = intersect_lines(
        0j, 1j * R_BO4, V_A, 1j * R_BA, "the velocity lines of B (perpendicular to O4B and AB)"
    )
    st = con.step(
        "V3",
        "velocity",
        "The lines meet at the tip of V_B: omega4 = V_B / O4B, omega3 = V_BA / AB.",
    )
    st.arrows += [
        Arrow(r"\mathbf{V}_{B}", 0j, V_B, "resultant", "velocity"),
        Arrow(r"\mathbf{V}_{BA}", V_A, V_B - V_A, "velocity", "velocity"),
    ]
    v.update(omega3=omega3, omega4=omega4, R_A=A, R_B=B, V_A=V_A, V_B=V_B)

    # -- acceleration, Example 7-1 steps 1..8
    A_A_n, A_A_t = crank.acceleration(con, A, a, omega2, alpha2)
    st = con.step(
        "3",
        "acceleration",
        "Construction line pp through B perpendicular to BO4: the direction of A_B^t.",
    )
    st.lines.append(Line("pp", B, 1j * R_BO4, "linkage"))
    A_B_n = -(omega4**2) * R_BO4
    st = con.step(
        "4",
        "acceleration",
        f"A_B = A_A + A_BA (eq. 7.4); A_B^n = c omega4^2 = {abs(A_B_n):.4g} m/s^2 "
        "along BO4 toward O4.",
    )
    st.arrows.append(Arrow(r"\mathbf{A}_{B}^{n}", B, A_B_n, "normal", "linkage"))
    A_BA_n = -(omega3**2) * R_BA
    st = con.step(
        "5",
        "acceleration",
        f"A_BA^n = b omega3^2 = {abs(A_BA_n):.4g} m/s^2 along BA toward A; "
        "construction line qq through B perpendicular to BA: the direction of A_BA^t.",
    )
    st.lines.append(Line("qq", B, 1j * R_BA, "linkage"))
    # step 6: the polygon
    T = A_A_t + A_A_n + A_BA_n - A_B_n
    X, alpha4, alpha3 = intersect_lines(
        0j, 1j * R_BO4, T, 1j * R_BA, "the lines pp and qq (perpendicular to BO4 and BA)"
    )
    A_B_t = X
    A_BA_t = X - T
    A_A = A_A_t + A_A_n
    A_B = A_B_t + A_B_n
    st = con.step(
        "6",
        "acceleration",
        "Polygon: from the pole lay the right side of eq. 7.4 tip to tail, A_A^t, "
        "A_A^n, A_BA^n, and a line parallel to qq through its tip; from the pole "
        "also the known part of the left side, A_B^n, and a line parallel to pp "
        "through its tip. The lines cross at the tip of A_B: A_BA^t and A_B^t "
        "close the two chains.",
    )
    st.arrows += crank.polygon(A_A_n, A_A_t) + [
        Arrow(r"\mathbf{A}_{BA}^{n}", A_A, A_BA_n, "normal", "acceleration"),
        Arrow(r"\mathbf{A}_{B}^{n}", 0j, A_B_n, "normal", "acceleration"),
    ]
    st.lines += [
        Line("qq", A_A + A_BA_n, 1j * R_BA, "acceleration"),
        Line("pp", A_B_n, 1j * R_BO4, "acceleration"),
    ]
    st.arrows += [
        Arrow(r"\mathbf{A}_{B}^{t}", A_B_n, A_B_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{BA}^{t}", A_A + A_BA_n, A_BA_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{A}", 0j, A_A, "resultant", "acceleration"),
        Arrow(r"\mathbf{A}_{B}", 0j, A_B, "resultant", "acceleration"),
    ]
    st.marks["acceleration"] = {"pole": 0j}
    con.step(
        "7",
        "acceleration",
        f"alpha4 = A_B^t / BO4 = {alpha4:.6g} rad/s^2, alpha3 = A_BA^t / BA = "
        f"{alpha3:.6g} rad/s^2 (eq. 7.6; sign from the sense of the vectors).",
    )
    v.update(
        alpha3=alpha3,
        alpha4=alpha4,
        A_A=A_A,
        A_B=A_B,
        A_BA=A_B - A_A,
        A_A_n=A_A_n,
        A_A_t=A_A_t,
        A_B_n=A_B_n,
        A_B_t=A_B_t,
        A_BA_n=A_BA_n,
        A_BA_t=A_BA_t,
    )
    st = con.step(
        "8",
        "acceleration",
        "A_P = A_A + A_PA with A_PA^t = p alpha3, A_PA^n = p omega3^2 "
        "(Figure 7-4c); the results drawn on the linkage (Figure 7-4d)."
        if p is not None
        else "The results drawn on the linkage (Figure 7-4d).",
    )
    st.arrows += [
        Arrow(r"\mathbf{A}_{A}", A, A_A, "resultant", "linkage"),
        Arrow(r"\mathbf{A}_{B}^{t}", B, A_B_t, "tangential", "linkage"),
        Arrow(r"\mathbf{A}_{B}", B, A_B, "resultant", "linkage"),
    ]
    if p is not None:
        R_PA = P - A
        A_PA_n = -(omega3**2) * R_PA
        A_PA_t = alpha3 * 1j * R_PA
        A_P = A_A + A_PA_n + A_PA_t
        st.arrows += [
            Arrow(r"\mathbf{A}_{A}", 0j, A_A, "resultant", "point"),
            Arrow(r"\mathbf{A}_{PA}^{n}", A_A, A_PA_n, "normal", "point"),
            Arrow(r"\mathbf{A}_{PA}^{t}", A_A + A_PA_n, A_PA_t, "tangential", "point"),
            Arrow(r"\mathbf{A}_{P}", 0j, A_P, "resultant", "point"),
            Arrow(r"\mathbf{A}_{P}", P, A_P, "resultant", "linkage"),
        ]
        v.update(R_P=P, V_P=V_A + 1j * omega3 * R_PA, A_P=A_P, A_PA=A_P - A_A)
    return con
