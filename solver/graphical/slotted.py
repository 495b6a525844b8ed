"""A block sliding in a rotating slotted link (Figure 7-7, eq. 7.19), and a
point on a rotating link (section 7.1, the block with no slip).

Every component is known in size and direction, so the polygon is drawn
tip to tail and closed by the resultant (Figure 7-7c):

    A_P = A_t + A_n + A_coriolis + A_slip
"""

import cmath

from .construction import Arrow, Construction, Linkage


def rotating_point(theta2, omega2, alpha2, p):
    """Velocity and acceleration polygons of a point at radius ``p`` [m] on a link
    turning about O2 (section 7.1): :func:`construct` with the block fixed."""
    return construct(theta2, omega2, alpha2, p, mechanism="rotation")


def construct(theta2, omega2, alpha2, p, p_dot=0.0, p_ddot=0.0, mechanism="slotted"):
    """Velocity and acceleration polygons of a block at P on a link turning about O2.

    Parameters
    ----------
    theta2, omega2, alpha2 : float
        Link angle [rad], angular velocity [rad/s] and acceleration [rad/s^2].
    p, p_dot, p_ddot : float
        Distance O2P [m] and its rates [m/s, m/s^2] (slip velocity, slip
        acceleration; both 0 for a point fixed on the link).
    mechanism : str
        ``"slotted"`` or ``"rotation"`` (names the construction).

    Returns
    -------
    Construction
        ``values``: R, V, V_t, V_slip, A, A_t, A_n, A_coriolis, A_slip.
    """
    e = cmath.exp(1j * theta2)
    P = p * e
    slip = p_dot != 0.0 or p_ddot != 0.0
    con = Construction(
        mechanism,
        Linkage(
            {"O2": 0j, "P": P},
            [] if mechanism == "slotted" else [("O2", "P")],
            ["O2"],
            blocks=[("P", e)] if mechanism == "slotted" else [],
            rods=[(0j, e, 0.0, 1.4 * p)] if mechanism == "slotted" else [],
        ),
        [],
        {},
        None,
        title="Slotted link (Figure 7-7)"
        if mechanism == "slotted"
        else "Rotating point (section 7.1)",
    )
    v = con.values
    con.step("P", "position", "Draw the link at theta2 and P at p from O2.")
    V_t = 1j * omega2 * P
    V_slip = p_dot * e
    st = con.step(
        "V1",
        "velocity",
        "V_P = p omega2 perpendicular to O2P" + (" plus the slip p' along it." if slip else "."),
    )
    st.arrows.append(Arrow(r"\mathbf{V}_{t}", 0j, V_t, "velocity", "velocity"))
    if slip:
        st.arrows += [
            Arrow(r"\mathbf{V}_{slip}", V_t, V_slip, "slip", "velocity"),
            Arrow(r"\mathbf{V}_{P}", 0j, V_t + V_slip, "resultant", "velocity"),
        ]
    A_t = alpha2 * 1j * P
    A_n = -(omega2**2) * P
    A_cor = 2.0 * p_dot * omega2 * 1j * e
    A_slip = p_ddot * e
    st = con.step(
        "1",
        "acceleration",
        f"A_t = p alpha2 = {p * alpha2:.4g} m/s^2 perpendicular to O2P, A_n = p "
        f"omega2^2 = {abs(A_n):.4g} m/s^2 toward O2 (eq. 7.6).",
    )
    parts = [(r"\mathbf{A}_{t}", A_t, "tangential"), (r"\mathbf{A}_{n}", A_n, "normal")]
    if slip:
        st = con.step(
            "2",
            "acceleration",
            f"The block slips on the turning link: A_coriolis = 2 p' omega2 = "
            f"{abs(A_cor):.4g} m/s^2, V_slip turned 90 deg in the sense of omega2; "
            f"A_slip = p'' = {p_ddot:.4g} m/s^2 along the slot (eq. 7.19).",
        )
        parts += [(r"\mathbf{A}_{cor}", A_cor, "coriolis"), (r"\mathbf{A}_{slip}", A_slip, "slip")]
    st.arrows += [Arrow(n, P, z, k, "linkage") for n, z, k in parts]
    st = con.step(
        str(len(con.steps) - 1),
        "acceleration",
        "Polygon: the components tip to tail; the resultant A_P closes it (Figure 7-7c).",
    )
    tail = 0j
    for n, z, k in parts:
        st.arrows.append(Arrow(n, tail, z, k, "acceleration"))
        tail += z
    st.arrows += [
        Arrow(r"\mathbf{A}_{P}", 0j, tail, "resultant", "acceleration"),
        Arrow(r"\mathbf{A}_{P}", P, tail, "resultant", "linkage"),
    ]
    v.update(R=P, V=V_t + V_slip, V_t=V_t, V_slip=V_slip, A=tail, A_t=A_t, A_n=A_n)
    if slip or mechanism == "slotted":
        v.update(A_coriolis=A_cor, A_slip=A_slip)
    return con
