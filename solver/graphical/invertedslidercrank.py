"""Graphical acceleration analysis of the inverted slider-crank, with its
Coriolis component (Figure 7-8, eqs. 7.19 and 7.21).

Link 4 turns about O4 and carries the slide line through B (O4B = c) at the
fixed angle gamma to O4B; the block 3, pinned to the crank at A, slides on
it. Point A of the block and the point A4 of link 4 that lies under it at
this instant differ by a slip along the slide. A point moving along a
rotating link has, besides the slip acceleration, the Coriolis component
``2 omega4 x V_slip`` (eq. 7.19): it is perpendicular to the slide, turned
from V_slip in the sense of omega4. The polygon is

    A_A = A_A4^n + A_A4^t + A_coriolis + A_slip

with A_A (from the crank), A_A4^n and A_coriolis known; the line of A_slip
(along the slide) and the line of A_A4^t (perpendicular to O4A) close it.
"""

import cmath
import math

from ..errors import NotAssemblable
from . import crank
from .construction import Arrow, Construction, Line, Linkage
from .geometry import intersect_line_circle, intersect_lines

SIGNS = {"open": 1.0, "crossed": -1.0}


def construct(a, c, d, gamma, theta2, omega2, alpha2, theta1=0.0, circuit="open"):
    """Velocity and acceleration polygons of an inverted slider-crank.

    Parameters
    ----------
    a : float
        Crank O2A [m].
    c : float
        O4B [m], >= 0 (0: the slide line passes through O4).
    d : float
        Ground O2O4 [m].
    gamma : float
        Angle from O4->B to the slide line [rad] (theta3 = theta4 + gamma).
    theta2, omega2, alpha2 : float
        Crank angle [rad], angular velocity [rad/s], acceleration [rad/s^2].
    theta1 : float
        Angle of the ground line O2->O4 [rad].
    circuit : {'open', 'crossed'}
        Of the two places where the slide line passes through A, ``open``
        takes the one with the larger signed length b from B to A (as the
        analytic solver does), ``crossed`` the smaller.

    Returns
    -------
    Construction
        ``values``: theta3, theta4, omega3 = omega4, alpha3 = alpha4, b,
        b_dot, b_ddot, and R_A, R_B, V_A, V_B, A_A, A_B, A_BA, A_coriolis,
        A_slip, A_A4 (of the point of link 4 under A) with A_A4_n, A_A4_t.

    Raises
    ------
    NotAssemblable
        The slide line cannot pass through A.
    Singular
        The slide is perpendicular to O4A (the polygon's lines are parallel).
    """
    e1 = cmath.exp(1j * theta1)
    O4 = d * e1
    A = a * cmath.exp(1j * theta2)
    s = abs(A - O4)
    # In link 4's own frame (O4 at 0, B at c on the x axis) the slide line is
    # c + t e^{j gamma}; an arc of radius |O4A| about O4 cuts it where A must be.
    eg = cmath.exp(1j * gamma)
    try:
        Z, b = intersect_line_circle(complex(c), eg, 0j, s, SIGNS[circuit], "the slide")
    except NotAssemblable:
        raise NotAssemblable(
            f"the slide line cannot pass through A at theta2 = {math.degrees(theta2):.6g} deg: "
            f"it stays c |sin gamma| = {abs(c * eg.imag):.6g} m from O4 but A is only "
            f"{s:.6g} m from O4; shorten c, reduce |sin gamma| or change the input angle"
        ) from None
    e4 = (A - O4) / Z  # turn link 4 so that point lands on A (|Z| = s)
    e4 /= abs(e4)
    e3 = e4 * eg
    B = O4 + c * e4
    pts = {"O2": 0j, "A": A, "O4": O4, "B": B}
    links = [("O2", "A"), ("O4", "B")]
    m = 0.3 * max(abs(b), a)  # how far link 4's slide reaches past A and B
    con = Construction(
        "invertedslidercrank",
        Linkage(
            pts,
            links,
            ["O2", "O4"],
            blocks=[("A", e3)],
            rods=[(B, e3, min(0.0, b) - m, max(0.0, b) + m)],
        ),
        [],
        {},
        circuit,
        title=f"Inverted slider-crank ({circuit} circuit)",
    )
    v = con.values
    R_AO4 = A - O4
    con.step(
        "P",
        "position",
        "Draw the linkage to scale: A at a from O2. In link 4's frame the slide line "
        "passes c |sin gamma| from O4; an arc of radius O4A cuts it, fixing theta4 "
        f"and b ({circuit} circuit).",
    )
    theta4 = cmath.phase(e4 / e1) + theta1
    v.update(theta3=theta4 + gamma, theta4=theta4, b=b, R_A=A, R_B=B)

    V_A, st = crank.velocity(
        con,
        A,
        omega2,
        "Velocity polygon: V_A = a omega2 perpendicular to O2A. V_A = V_A4 "
        "+ V_slip: A4 is the point of link 4 under A.",
    )
    st = con.step(
        "V2",
        "velocity",
        "V_A4 is perpendicular to O4A: line through the pole; V_slip is along the "
        "slide: line through the tip of V_A.",
    )
    st.lines += [Line("", 0j, 1j * R_AO4, "velocity"), Line("", V_A, e3, "velocity")]
    V_A4, omega4, t = intersect_lines(
        0j, 1j * R_AO4, V_A, e3, "the velocity lines (perpendicular to O4A, along the slide)"
    )
    b_dot = -t
    V_slip = b_dot * e3
    st = con.step(
        "V3",
        "velocity",
        "They meet at the tip of V_A4: omega4 = V_A4 / O4A, V_slip = b' along the slide.",
    )
    st.arrows += [
        Arrow(r"\mathbf{V}_{A_4}", 0j, V_A4, "velocity", "velocity"),
        Arrow(r"\mathbf{V}_{slip}", V_A4, V_slip, "slip", "velocity"),
    ]
    V_B = 1j * omega4 * (B - O4)
    v.update(omega3=omega4, omega4=omega4, b_dot=b_dot, V_A=V_A, V_B=V_B)

    A_A_n, A_A_t = crank.acceleration(con, A, a, omega2, alpha2)
    A_A = A_A_n + A_A_t
    A_A4_n = -(omega4**2) * R_AO4
    st = con.step(
        "3",
        "acceleration",
        f"A4 turns about O4: A_A4^n = O4A omega4^2 = {abs(A_A4_n):.4g} m/s^2 toward "
        "O4; construction line pp through A perpendicular to O4A: the direction of "
        "A_A4^t.",
    )
    st.arrows.append(Arrow(r"\mathbf{A}_{A_4}^{n}", A, A_A4_n, "normal", "linkage"))
    st.lines.append(Line("pp", A, 1j * R_AO4, "linkage"))
    A_cor = 2.0 * b_dot * omega4 * 1j * e3
    st = con.step(
        "4",
        "acceleration",
        "A_A = A_A4 + A_coriolis + A_slip: A slides on the turning link 4, so the "
        f"Coriolis component 2 omega4 V_slip = {abs(A_cor):.4g} m/s^2 appears, "
        "perpendicular to the slide, V_slip turned 90 deg in the sense of omega4 "
        "(eq. 7.19).",
    )
    st.arrows.append(Arrow(r"\mathbf{A}_{cor}", A, A_cor, "coriolis", "linkage"))
    st = con.step(
        "5", "acceleration", "A_slip lies along the slide: construction line rr through A."
    )
    st.lines.append(Line("rr", A, e3, "linkage"))
    T = A_A4_n + A_cor
    X, b_ddot, t = intersect_lines(
        T, e3, A_A, 1j * R_AO4, "the lines rr and pp (along the slide, perpendicular to O4A)"
    )
    alpha4 = -t
    A_slip = X - T
    A_A4_t = A_A - X
    st = con.step(
        "6",
        "acceleration",
        "Polygon: A_A (A_A^t, A_A^n) from the pole; from the pole also A_A4^n, then "
        "A_coriolis; a line parallel to rr through its tip and one parallel to pp "
        "through the tip of A_A meet: A_slip and A_A4^t close the polygon.",
    )
    st.arrows += crank.polygon(A_A_n, A_A_t) + [
        Arrow(r"\mathbf{A}_{A_4}^{n}", 0j, A_A4_n, "normal", "acceleration"),
        Arrow(r"\mathbf{A}_{cor}", A_A4_n, A_cor, "coriolis", "acceleration"),
    ]
    st.lines += [Line("rr", T, e3, "acceleration"), Line("pp", A_A, 1j * R_AO4, "acceleration")]
    st.arrows += [
        Arrow(r"\mathbf{A}_{slip}", T, A_slip, "slip", "acceleration"),
        Arrow(r"\mathbf{A}_{A_4}^{t}", X, A_A4_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{A}", 0j, A_A, "resultant", "acceleration"),
    ]
    A_B_n = -(omega4**2) * (B - O4)
    A_B_t = alpha4 * 1j * (B - O4)
    A_B = A_B_n + A_B_t
    st = con.step(
        "7",
        "acceleration",
        f"alpha3 = alpha4 = A_A4^t / O4A = {alpha4:.6g} rad/s^2; b'' = {b_ddot:.6g} "
        "m/s^2 (A_slip along the slide, positive from B toward A).",
    )
    st = con.step(
        "8",
        "acceleration",
        "A_B = A_B^n + A_B^t with O4B omega4^2 and O4B alpha4; the results drawn on the linkage.",
    )
    st.arrows += [
        Arrow(r"\mathbf{A}_{A}", A, A_A, "resultant", "linkage"),
        Arrow(r"\mathbf{A}_{slip}", A, A_slip, "slip", "linkage"),
    ]
    if c > 0.0:
        st.arrows.append(Arrow(r"\mathbf{A}_{B}", B, A_B, "resultant", "linkage"))
    v.update(
        alpha3=alpha4,
        alpha4=alpha4,
        b_ddot=b_ddot,
        A_A=A_A,
        A_B=A_B,
        A_BA=A_B - A_A,
        A_coriolis=A_cor,
        A_slip=A_slip,
        A_A4=A_A4_n + A_A4_t,
        A_A4_n=A_A4_n,
        A_A4_t=A_A4_t,
        A_A_n=A_A_n,
        A_A_t=A_A_t,
        A_B_n=A_B_n,
        A_B_t=A_B_t,
    )
    return con
