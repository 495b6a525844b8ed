"""The crank's part of every construction: the input link O2A turns about O2
with the given omega2 and alpha2, so V_A and A_A are known outright
(eq. 7.2); their magnitudes are those of eq. 7.6 (A^t = r alpha, A^n = r
omega^2). Every mechanism's polygon starts from them."""

from .construction import Arrow


def velocity(
    con, A, omega2, text="Velocity polygon: V_A = a omega2, perpendicular to O2A, from the pole."
):
    """Step V1: V_A of the crank pin A [m] turning at omega2 [rad/s]; returns
    ``(V_A, step)``."""
    V_A = 1j * omega2 * A
    st = con.step("V1", "velocity", text)
    st.arrows.append(Arrow(r"\mathbf{V}_{A}", 0j, V_A, "velocity", "velocity"))
    return V_A, st


def acceleration(con, A, a, omega2, alpha2):
    """Steps 1 and 2 of Example 7-1: the normal and tangential components of
    A_A, computed and drawn at A. Returns ``(A_A_n, A_A_t)`` [m/s^2]."""
    A_A_n = -(omega2**2) * A
    A_A_t = alpha2 * 1j * A
    con.step(
        "1",
        "acceleration",
        f"A_A^n = a omega2^2 = {abs(A_A_n):.4g} m/s^2, A_A^t = a alpha2 = "
        f"{a * alpha2:.4g} m/s^2 (eq. 7.6).",
    )
    st = con.step(
        "2",
        "acceleration",
        "At A: A_A^n along AO2 toward O2, A_A^t perpendicular to O2A in the sense of alpha2.",
    )
    st.arrows += [
        Arrow(r"\mathbf{A}_{A}^{n}", A, A_A_n, "normal", "linkage"),
        Arrow(r"\mathbf{A}_{A}^{t}", A, A_A_t, "tangential", "linkage"),
    ]
    return A_A_n, A_A_t


def polygon(A_A_n, A_A_t):
    """The polygon's first two arrows: A_A^t from the pole, A_A^n from its tip."""
    return [
        Arrow(r"\mathbf{A}_{A}^{t}", 0j, A_A_t, "tangential", "acceleration"),
        Arrow(r"\mathbf{A}_{A}^{n}", A_A_t, A_A_n, "normal", "acceleration"),
    ]
