# ---
# jupyter:
#   jupytext:
#     text_representation:
#       extension: .py
#       format_name: percent
#       format_version: '1.3'
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # 9. Jerk
#
# Force follows acceleration ($F = ma$), so a quickly changing acceleration is a quickly changing
# force: a jolt. The rate of change of acceleration is called **jerk** (also pulse or shock). This
# notebook computes it for linkages and shows why a designer cares, following section 7.7 of the
# chapter (Robert L. Norton, *Design of Machinery*, chapter 7, eqs. 7.33 to 7.41).
#
# **You will be able to**
#
# - differentiate the fourbar's acceleration loop once more and solve it for the angular jerks
#   $\varphi_3$ and $\varphi_4$ (eqs. 7.33-7.39), and get them from the solver (`jerk3`, `jerk4`);
# - compute the linear jerk of the pins and of any point (eqs. 7.40-7.41);
# - check a jerk against a numerical derivative of the angular acceleration;
# - compare the jerks of the slider-crank, the inverted slider-crank and the geared fivebar, and
#   explain, with a small vibration model, why limiting jerk reduces vibration.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import matplotlib.pyplot as plt
import numpy as np

from accelab.course.kit import COLORS, explore, stated, use_style
from accelab.course.practice import practice
from accelab.course.renditions import panels, show
from accelab.course.text import num, say, sci, table, vec
from accelab.solver import Q_, FourBar, GearedFiveBar, InvertedSliderCrank, SliderCrank

use_style()

# %% [markdown]
# ## The idea and its equations
#
# Angular and linear jerk are the time derivatives of angular and linear acceleration:
#
# $$ \varphi = \frac{d\alpha}{dt} \tag{7.33a} $$
#
# $$ \mathbf{J} = \frac{d\mathbf{A}}{dt} \tag{7.33b} $$
#
# (The chapter's $\varphi_k$ is `jerk_k` in the solver; in notebook 6, $\phi$ was the
# fivebar's phase, a different thing.) Differentiating a rotating vector $L e^{j\theta}$ three
# times gives $L(-\omega^3 j - 3\omega\alpha + \varphi j)e^{j\theta}$. Doing that to every term
# of the fourbar's acceleration loop (eq. 7.7) and collecting:
#
# $$ \begin{aligned}
#    & -a\omega_2^3 je^{j\theta_2} - 3a\omega_2\alpha_2 e^{j\theta_2} \\
#    & \quad + a\varphi_2 je^{j\theta_2} \\
#    & - b\omega_3^3 je^{j\theta_3} - 3b\omega_3\alpha_3 e^{j\theta_3} \\
#    & \quad + b\varphi_3 je^{j\theta_3} \\
#    & + c\omega_4^3 je^{j\theta_4} + 3c\omega_4\alpha_4 e^{j\theta_4} \\
#    & \quad - c\varphi_4 je^{j\theta_4} = 0
#    \end{aligned} \tag{7.34b} $$
#
# Everything is known from the position, velocity and acceleration analyses except
# $\varphi_3$ and $\varphi_4$ (the input's jerk $\varphi_2$ is given; zero at steady speed or
# constant $\alpha_2$). The real and imaginary parts are two linear equations:
#
# $$ \begin{aligned}
#    & a\omega_2^3\sin\theta_2 - 3a\omega_2\alpha_2\cos\theta_2 \\
#    & \quad - a\varphi_2\sin\theta_2 \\
#    & + b\omega_3^3\sin\theta_3 - 3b\omega_3\alpha_3\cos\theta_3 \\
#    & \quad - b\varphi_3\sin\theta_3 \\
#    & - c\omega_4^3\sin\theta_4 + 3c\omega_4\alpha_4\cos\theta_4 \\
#    & \quad + c\varphi_4\sin\theta_4 = 0
#    \end{aligned} \tag{7.35a} $$
#
# $$ \begin{aligned}
#    & -a\omega_2^3\cos\theta_2 - 3a\omega_2\alpha_2\sin\theta_2 \\
#    & \quad + a\varphi_2\cos\theta_2 \\
#    & - b\omega_3^3\cos\theta_3 - 3b\omega_3\alpha_3\sin\theta_3 \\
#    & \quad + b\varphi_3\cos\theta_3 \\
#    & + c\omega_4^3\cos\theta_4 + 3c\omega_4\alpha_4\sin\theta_4 \\
#    & \quad - c\varphi_4\cos\theta_4 = 0
#    \end{aligned} \tag{7.35b} $$
#
# The chapter names the known terms $A \ldots K$ in eq. 7.35a and $L \ldots U$ in eq. 7.35b
# (eqs. 7.36a and 7.37a), e.g. $A = a\omega_2^3\sin\theta_2$, $H = c\sin\theta_4$,
# $K = b\sin\theta_3$, $R = b\cos\theta_3$, $U = c\cos\theta_4$ (the scan prints
# $c\cos\theta_A$, a misread subscript), and eliminates $\varphi_3$:
#
# $$ \begin{aligned} K\varphi_3 = {} & A - B - C + D \\
#    & - E - F + G + H\varphi_4 \end{aligned} \tag{7.36b} $$
#
# $$ \begin{aligned} & (KU - HR)\,\varphi_4 = \\
#    & \quad K(N - L - M - P \\
#    & \qquad - Q + S + T) \\
#    & \quad + R(A - B - C + D \\
#    & \qquad - E - F + G) \end{aligned} \tag{7.39} $$
#
# (The chapter writes the numerator out as fourteen products, $KN - KL - \ldots + KS + KT$;
# above they are gathered by $K$ and $R$, and the cell below evaluates the chapter's form.)
# The denominator $KU - HR = bc\sin(\theta_3 - \theta_4)$ vanishes at the toggle, as the
# acceleration's did. The pins' linear jerks follow from the same rotating-vector derivative:
#
# $$ \begin{aligned}
#    \mathbf{J}_A = {} & -a\omega_2^3 je^{j\theta_2} - 3a\omega_2\alpha_2 e^{j\theta_2} \\
#      & + a\varphi_2 je^{j\theta_2} \\
#    \mathbf{J}_B = {} & -c\omega_4^3 je^{j\theta_4} - 3c\omega_4\alpha_4 e^{j\theta_4} \\
#      & + c\varphi_4 je^{j\theta_4}
#    \end{aligned} \tag{7.40} $$
#
# (the scanned chapter ends the line of $\mathbf{J}_B$ with a stray "= 0"), and any point from
# a point of the same link, as for acceleration:
#
# $$ \mathbf{J}_P = \mathbf{J}_A + \mathbf{J}_{PA} \tag{7.41} $$
#
# (Just before eq. 7.41 the chapter sends the reader to "Section 7.4 (p. 319)" for the
# acceleration of any point; that is section 7.5, the subject of notebook 7. Section 7.4 is the
# geared fivebar.)

# %% [markdown]
# ## Worked examples
#
# ### 1. The fourbar at one position
#
# The fourbar of notebooks 3 and 7 ($a$ = 2, $b$ = 6, $c$ = 9, $d$ = 7 in) at
# $\theta_2 = 30°$, $\omega_2$ = 10 rad/s, $\alpha_2$ = -5 rad/s² with its coupler point P
# ($p$ = 3 in, $\delta_3$ = 30°): the course's Example 7-1 (the chapter's example prints no
# numbers; **these are the course's own numbers**), here with a driving jerk
# $\varphi_2$ = 20 rad/s³ added.

# %%
fourbar = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
r = fourbar.solve(
    theta2="30 deg",
    omega2="10 rad/s",
    alpha2="-5 rad/s^2",
    jerk2="20 rad/s^3",
    p="3 in",
    delta3="30 deg",
)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "value"],
    [
        [r"$\varphi_3$ (`jerk3`)", f"{num(r.jerk3)} rad/s³"],
        [r"$\varphi_4$ (`jerk4`)", f"{num(r.jerk4)} rad/s³"],
    ]
    + [
        [
            f"$\\mathbf{{J}}_{k[-1]}$",
            f"{vec(getattr(r, k), 'in/s^3')} = {vec(getattr(r, k), 'm/s^3')}",
        ]
        for k in ("J_A", "J_B", "J_P")
    ],
)

# %% [markdown]
# The chapter's constants and eqs. 7.36b and 7.39, evaluated by hand and checked against the
# solver; then eq. 7.40 for $\mathbf{J}_B$ and eq. 7.41 for the coupler point.

# %%
a, b, c = 2.0, 6.0, 9.0  # in
t2, w2, al2, ph2 = np.radians(30), 10.0, -5.0, 20.0
t3, t4 = r.theta3.magnitude, r.theta4.magnitude
w3, w4, al3, al4 = (getattr(r, k).magnitude for k in ("omega3", "omega4", "alpha3", "alpha4"))
A, B, C = a * w2**3 * np.sin(t2), 3 * a * w2 * al2 * np.cos(t2), a * ph2 * np.sin(t2)  # eq. 7.36a
D, E, F = b * w3**3 * np.sin(t3), 3 * b * w3 * al3 * np.cos(t3), c * w4**3 * np.sin(t4)
G, H, K = 3 * c * w4 * al4 * np.cos(t4), c * np.sin(t4), b * np.sin(t3)
L, M, N = a * w2**3 * np.cos(t2), 3 * a * w2 * al2 * np.sin(t2), a * ph2 * np.cos(t2)  # eq. 7.37a
P, Q, R = b * w3**3 * np.cos(t3), 3 * b * w3 * al3 * np.sin(t3), b * np.cos(t3)
S, T, U = c * w4**3 * np.cos(t4), 3 * c * w4 * al4 * np.sin(t4), c * np.cos(t4)
phi4 = (
    K * N
    - K * L
    - K * M
    - K * P
    - K * Q
    + A * R
    - B * R
    - C * R
    + D * R
    - E * R
    - F * R
    + G * R
    + K * S
    + K * T
) / (K * U - H * R)  # eq. 7.39
phi3 = (A - B - C + D - E - F + G + H * phi4) / K  # eq. 7.36b
assert np.isclose(K * U - H * R, b * c * np.sin(t3 - t4), rtol=1e-12)  # KU - HR
assert np.isclose(phi3, r.jerk3.magnitude, rtol=1e-12)
assert np.isclose(phi4, r.jerk4.magnitude, rtol=1e-12)
e4 = np.exp(1j * t4)
J_B = -c * w4**3 * 1j * e4 - 3 * c * w4 * al4 * e4 + c * phi4 * 1j * e4  # eq. 7.40
assert np.isclose(J_B, r.J_B.to("in/s^3").magnitude, rtol=1e-12)
J_PA = r.point(3, "3 in", "30 deg").J - r.J_A  # eq. 7.41
assert np.isclose((r.J_A + J_PA - r.J_P).to("in/s^3").magnitude, 0, atol=1e-9)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"Eqs. 7.36b and 7.39 give $\varphi_3$ = {num(phi3, 6)} and $\varphi_4$ = "
    f"{num(phi4, 6)} rad/s³, as the solver does."
)

# %% [markdown]
# ### 2. Checking jerk against a numerical derivative
#
# A closed form is only as good as its derivation. An independent check: at a steady
# $\omega_2$ = 10 rad/s, $\theta_2 = \omega_2 t$, so $\varphi_3 = d\alpha_3/dt =
# \omega_2\, d\alpha_3/d\theta_2$. We take $\alpha_3$ on a grid of crank angles, differentiate
# it numerically (central differences) and lay the result over the solver's `jerk3`.

# %%
h = np.radians(0.5)  # grid step of theta2
grid = np.arange(0, 2 * np.pi + h / 2, h)
cyc = fourbar.solve(theta2=Q_(grid, "rad"), omega2="10 rad/s", alpha2=0)
alpha3 = cyc.alpha3.magnitude
numeric = 10.0 * (np.roll(alpha3, -1) - np.roll(alpha3, 1)) / (2 * h)  # periodic central difference
numeric[[0, -1]] = 10.0 * (alpha3[1] - alpha3[-2]) / (2 * h)  # 0 and 360 deg are one point
jerk3 = cyc.jerk3.magnitude
error = np.abs(numeric - jerk3)
deg = np.degrees(grid)
coarse = cyc.alpha3.magnitude[::2]  # the same check at step 2h
numeric2 = 10.0 * (np.roll(coarse, -1) - np.roll(coarse, 1)) / (4 * h)
numeric2[[0, -1]] = 10.0 * (coarse[1] - coarse[-2]) / (4 * h)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"The largest difference is {sci(error.max() / np.abs(jerk3).max())} of the largest jerk "
    f"(a step of {num(np.degrees(h), decimals=1)}°); doubling the step multiplies it by "
    f"{num(np.abs(numeric2 - jerk3[::2]).max() / error.max(), 2)}, as an error of order $h^2$ "
    "should."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The coupler's angular jerk from the solver and by numerical differentiation of its acceleration; they differ by the finite-difference error."}}
def fd_check(narrow):
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.8, 3.6), tall=(4.4, 7.0), layout="constrained")
    ax1.plot(deg, jerk3, color="black", lw=2, label=r"$\varphi_3$, solver (eq. 7.39)")
    ax1.plot(
        deg[::12],
        numeric[::12],
        "o",
        color=COLORS["tangential"],
        ms=5,
        label=r"$\omega_2\,\Delta\alpha_3/\Delta\theta_2$",
    )
    ax1.set_ylabel(r"$\varphi_3$ [rad/s$^3$]")
    ax1.set_title("Jerk of the coupler at 10 rad/s")
    ax1.legend()
    ax2.semilogy(deg, error / np.abs(jerk3).max(), color=COLORS["normal"])
    ax2.set_ylabel("difference / largest jerk")
    ax2.set_title("They differ by $O(h^2)$")
    for ax in (ax1, ax2):
        ax.set_xlabel(r"$\theta_2$ [deg]")
        ax.set_xticks(range(0, 361, 90))
    return fig


show(
    fd_check,
    alt="Two overlapping curves of jerk against crank angle, and their small difference on a "
    "logarithmic scale.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
assert error.max() < 1e-3 * np.abs(jerk3).max()
stated(np.abs(numeric2 - jerk3[::2]).max() / error.max(), "4", sig=1)

# %% [markdown]
# The check above is at steady speed, where $\varphi_2 = 0$. The next cell checks one instant
# of a general motion: the crank at $\theta_2 = 30°$ with $\omega_2$ = 10 rad/s, $\alpha_2$ =
# -5 rad/s² and $\varphi_2$ = 20 rad/s³. A short time $\Delta t$ earlier and later the crank's
# angle, speed and acceleration follow from a Taylor expansion, so we can solve both instants
# and take $(\alpha_3(\Delta t) - \alpha_3(-\Delta t))/2\Delta t$.


# %%
def crank_at(dt):
    """theta2, omega2, alpha2 at time dt for a motion with constant jerk 20 rad/s^3."""
    return (
        np.radians(30) + 10 * dt - 5 * dt**2 / 2 + 20 * dt**3 / 6,
        10 - 5 * dt + 20 * dt**2 / 2,
        -5 + 20 * dt,
    )


dt = 1e-4
later, earlier = (
    fourbar.solve(
        theta2=Q_(th, "rad"), omega2=Q_(w, "rad/s"), alpha2=Q_(al, "rad/s^2"), jerk2="20 rad/s^3"
    )
    for th, w, al in (crank_at(dt), crank_at(-dt))
)
fd = (later.alpha3 - earlier.alpha3).magnitude / (2 * dt)
fdJ = (later.A_B - earlier.A_B).to("in/s^2").magnitude / (2 * dt)
J_B = r.J_B.to("in/s^3").magnitude
assert abs(fd / r.jerk3.magnitude - 1) < 1e-5 and abs(fdJ - J_B) < 1e-5 * abs(J_B)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "central difference, $\\Delta t = 10^{-4}$ s", "solver", "relative difference"],
    [
        [
            r"$\varphi_3$ [rad/s³]",
            num(fd, 8),
            num(r.jerk3.magnitude, 8),
            sci(abs(fd / r.jerk3.magnitude - 1)),
        ],
        [
            r"$\mathbf{J}_B$ [in/s³]",
            f"{num(abs(fdJ), 7)} at {num(np.angle(fdJ, deg=True), decimals=2)}°",
            f"{num(abs(J_B), 7)} at {num(np.angle(J_B, deg=True), decimals=2)}°",
            sci(abs(fdJ - J_B) / abs(J_B)),
        ],
    ],
)

# %% [markdown]
# ### 3. Linear jerk of points, and the other mechanisms
#
# Over a cycle at 10 rad/s, the pins' and the coupler point's jerks (eqs. 7.40-7.41), then the
# other mechanisms of the chapter, each at a steady input speed: the slider-crank's piston
# ($\dddot d$), the inverted slider-crank's link 4 ($\varphi_4$) and the geared fivebar's
# coupler ($\varphi_3$). At steady speed every jerk is proportional to $\omega_2^3$: double the
# speed and the jerk grows eightfold.

# %%
theta = Q_(np.linspace(0, 2 * np.pi, 361), "rad")
deg = np.degrees(theta.magnitude)
cyc = fourbar.solve(theta2=theta, omega2="10 rad/s", alpha2=0, p="3 in", delta3="30 deg")
engine = SliderCrank(a="40 mm", b="130 mm").solve(theta2=theta, omega2="3000 rpm", alpha2=0)
isc = InvertedSliderCrank(a="4 in", c="3 in", d="8 in", gamma="90 deg").solve(
    theta2=theta, omega2="10 rad/s", alpha2=0
)
fivebar = GearedFiveBar(
    a="1.5 in", b="4 in", c="4 in", d="1.5 in", f="4 in", lam=-2, phi="30 deg"
).solve(theta2=theta, omega2="20 rad/s", alpha2=0)
twice = SliderCrank(a="40 mm", b="130 mm").solve(theta2=theta, omega2="6000 rpm", alpha2=0)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"The piston's largest jerk is {num(np.abs(engine.d_dddot.m_as('m/s^3')).max(), 3)} m/s³ "
    f"at 3000 rpm, and {num(np.abs(twice.d_dddot.m_as('m/s^3')).max(), 3)} m/s³ at 6000 rpm: "
    f"{num(np.abs(twice.d_dddot.magnitude).max() / np.abs(engine.d_dddot.magnitude).max(), 3)} "
    "times as much."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Jerk over a cycle: the linear jerk of points $A$, $B$ and $P$ of the fourbar, the slider-crank's piston $\\dddot d$, the inverted slider-crank's $\\varphi_4$ and the geared fivebar's $\\varphi_3$."}}
def four_mechanisms(narrow):
    fig, axes = plt.subplots(
        4 if narrow else 2,
        1 if narrow else 2,
        figsize=(4.4, 11.0) if narrow else (7.8, 5.8),
        layout="constrained",
    )
    axes = axes.ravel()
    ax = axes[0]
    for name, colour in (
        ("J_A", COLORS["normal"]),
        ("J_B", COLORS["tangential"]),
        ("J_P", "black"),
    ):
        ax.plot(
            deg,
            np.abs(getattr(cyc, name).to("in/s^3").magnitude),
            color=colour,
            label=rf"$|\mathbf{{J}}_{name[-1]}|$",
        )
    ax.set_ylabel(r"[in/s$^3$]")
    ax.set_title("Fourbar, 10 rad/s")
    ax.legend(ncol=3, loc="upper center", columnspacing=0.8, handlelength=1.2)
    ax.set_ylim(top=ax.get_ylim()[1] * 1.25)
    ax = axes[1]
    ax.plot(deg, engine.d_dddot.to("m/s^3").magnitude / 1e6, color="black")
    ax.set_ylabel(r"$\dddot d$ [10$^6$ m/s$^3$]")
    ax.set_title("Slider-crank piston, 3000 rpm")
    ax = axes[2]
    ax.plot(deg, isc.jerk4.magnitude, color="black")
    ax.set_ylabel(r"$\varphi_4$ [rad/s$^3$]")
    ax.set_title("Inverted slider-crank, 10 rad/s")
    ax = axes[3]
    ax.plot(deg, fivebar.jerk3.magnitude / 1000, color="black")
    ax.set_ylabel(r"$\varphi_3$ [10$^3$ rad/s$^3$]")
    ax.set_title(r"Geared fivebar, $\lambda$ = -2, 20 rad/s")
    for ax in axes:
        ax.set_xlabel(r"$\theta_2$ [deg]")
        ax.set_xticks(range(0, 361, 90))
    return fig


show(
    four_mechanisms,
    alt="Four line plots of jerk against crank angle: the fourbar's points, the piston, the "
    "inverted slider-crank and the geared fivebar.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(np.abs(twice.d_dddot.magnitude).max() / np.abs(engine.d_dddot.magnitude).max(), "8")

# %% [markdown]
# The curves are smooth wherever the linkage is far from a toggle: a linkage driven at steady speed
# has finite jerk everywhere it can be assembled. The inverted slider-crank's sharp swing near
# $\theta_2 = 0$ is where the crank pin passes closest to $O_4$ and link 4 swings fastest; its
# jerk there is large but finite.
#
# ### 4. Why jerk matters: vibration
#
# Every real part is elastic. Model what a mechanism carries as a mass on a spring, with natural
# period $T_n$, riding on a base whose acceleration changes from 0 to $A_0$. If the change is
# instantaneous (infinite jerk), the mass is left oscillating with an amplitude equal to the whole
# static deflection $A_0/\omega_n^2$. If the change is spread over a time $\tau$ (jerk
# $A_0/\tau$), the leftover vibration is smaller; for this undamped model its amplitude is
#
# $$ \frac{A_0}{\omega_n^2}\left|\frac{\sin(\omega_n\tau/2)}{\omega_n\tau/2}\right| . $$
#
# The cell integrates the model numerically (a convolution with its impulse response) and
# checks the formula.

# %%
wn = 2 * np.pi  # natural period T_n = 1 s
dt = 1e-3
t = np.arange(0, 6, dt)
impulse = np.sin(wn * t) / wn * dt  # response to a unit impulse


def leftover(tau):
    """Amplitude of the vibration left after a base acceleration ramps 0 -> 1 in time tau."""
    A = np.clip(t / tau, 0, 1) if tau > 0 else np.ones_like(t)
    x = -np.convolve(A, impulse)[: len(t)]  # x'' + wn^2 x = -A(t)
    tail = t > tau + 1e-9
    return x, np.abs(x[tail] + 1 / wn**2).max() * wn**2  # in units of A0/wn^2


taus = np.linspace(0, 3, 61)
simulated = np.array([leftover(tau)[1] for tau in taus])
formula = np.abs(np.sinc(taus))  # sin(pi tau)/(pi tau), T_n = 1 s
assert np.allclose(simulated, formula, atol=5e-3)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"The simulation and the formula agree to {num(np.abs(simulated - formula).max(), 1)} "
    r"$A_0/\omega_n^2$ at every ramp time."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "A spring and mass answering a change of acceleration: its response to a sudden change and to a ramp, and the vibration left over against the ramp time. The less jerk, the less vibration (mostly)."}}
def vibration(narrow):
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.8, 3.5), tall=(4.4, 7.0), layout="constrained")
    for tau, colour, label in (
        (0, COLORS["tangential"], "step: infinite jerk"),
        (1.5, COLORS["normal"], r"ramp over $\tau$ = 1.5 $T_n$"),
    ):
        x, _ = leftover(tau)
        ax1.plot(t, -x * wn**2, color=colour, label=label)
    ax1.set_xlabel(r"time [$T_n$]")
    ax1.set_ylabel(r"deflection [$A_0/\omega_n^2$]")
    ax1.set_title("Response to a change of acceleration")
    ax1.legend(loc="lower right")
    ax2.plot(taus, formula, color="black", label="formula")
    ax2.plot(taus[::3], simulated[::3], "o", color=COLORS["tangential"], ms=4, label="simulated")
    ax2.set_xlabel(r"ramp time $\tau$ [$T_n$] (jerk $A_0/\tau$)")
    ax2.set_ylabel(r"leftover [$A_0/\omega_n^2$]")
    ax2.set_title("Less jerk, less vibration (mostly)")
    ax2.legend()
    return fig


show(
    vibration,
    alt="The response of a spring-mass system to a step and to a ramp of acceleration, and the "
    "leftover vibration against the ramp time, simulated and by the formula.",
)

# %% [markdown]
# Spreading the change of acceleration over more than about one natural period (lower jerk) cuts
# the leftover vibration several times over; a sudden change leaves the most. (At exact multiples
# of $T_n$ the ramp happens to cancel its own vibration, a trick used in motion control.) This is
# why jerk matters more for **cams** than for linkages: a cam profile can impose any motion,
# including one whose acceleration jumps, and the next chapter's cam design rules insist that the
# follower's acceleration be continuous so that its jerk stays finite. A linkage at steady speed
# gives finite jerk automatically, as the curves of example 3 show, but the sizes still matter.
#
# ## Explore
#
# Jerk is the slope of the angular acceleration curve (times $\omega_2$). Move the crank and watch
# the tangent: steep stretches of $\alpha_3$ are where the jerk is large.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The angular jerk is the slope of the angular acceleration: $\\alpha_3$ over a cycle with the tangent at several crank angles $\\theta_2$."}}
jerk_cycle = fourbar.solve(theta2=theta, omega2="10 rad/s", alpha2=0)


def draw(theta2=60):
    i = int(round(theta2))
    al = jerk_cycle.alpha3.magnitude
    phi3 = jerk_cycle.jerk3.magnitude[i]
    slope = phi3 / 10.0 * np.pi / 180  # d(alpha3)/d(theta2) per degree
    fig, ax = plt.subplots(figsize=(4.6, 3.6))
    ax.plot(deg, al, color="black", lw=2)
    span = np.array([-25, 25])
    ax.plot(theta2 + span, al[i] + slope * span, color=COLORS["tangential"], lw=2.5)
    ax.plot(theta2, al[i], "o", color=COLORS["tangential"])
    ax.set_xlabel(r"$\theta_2$ [deg]")
    ax.set_ylabel(r"$\alpha_3$ [rad/s$^2$]")
    ax.set_xticks(range(0, 361, 60))
    ax.set_title(
        rf"$\theta_2$ = {theta2}°: $\varphi_3$ = {phi3:.0f} rad/s$^3$ (the slope)", fontsize=11
    )
    return fig


explore(draw, theta2=(0, 360, 5, 60, "deg"), values=(30, 100, 200, 300))

# %% [markdown]
# ## Check yourself
#
# 1. A crank turns at a steady speed. Is the jerk of its pin A zero?
#
# <details><summary>Answer</summary>
#
# No. With $\alpha_2 = \varphi_2 = 0$ eq. 7.40 leaves $\mathbf{J}_A = -a\omega_2^3 je^{j\theta_2}$:
# the centripetal acceleration keeps its size but turns with the crank, and a turning vector is a
# changing one. It points opposite to the velocity.
#
# </details>
#
# 2. The engine above runs twice as fast. What happens to the piston's largest acceleration and
#    largest jerk?
#
# <details><summary>Answer</summary>
#
# At steady speed acceleration scales with $\omega_2^2$ (four times) and jerk with $\omega_2^3$
# (eight times).
#
# </details>
#
# 3. How can you check a jerk computed by a closed form without deriving it again?
#
# <details><summary>Answer</summary>
#
# Differentiate the angular (or linear) acceleration numerically in time: solve at a few nearby
# instants and take central differences, as example 2 does. The two must agree to the
# finite-difference error, which falls as the step squared.
#
# </details>
#
# 4. Why does the chapter say jerk control matters more for cams than for linkages?
#
# <details><summary>Answer</summary>
#
# A linkage driven smoothly has smooth, finite jerk. A cam's profile is designed point by point
# and can easily give a follower motion whose acceleration jumps (infinite jerk), which excites
# vibration, as example 4 shows.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
steady = fourbar.solve(theta2="30 deg", omega2="10 rad/s", alpha2=0)
J_A = steady.J_A.to("in/s^3").magnitude
assert np.isclose(J_A, -2 * 10**3 * 1j * np.exp(1j * np.radians(30)))  # -a omega2^3 j e^{j theta2}
assert np.isclose(
    np.angle(J_A / steady.V_A.magnitude, deg=True) % 360, 180
)  # opposite the velocity
e2 = SliderCrank(a="40 mm", b="130 mm").solve(theta2=theta, omega2="6000 rpm", alpha2=0)
stated(
    np.abs(e2.d_ddot.magnitude).max()
    / np.abs(
        SliderCrank(a="40 mm", b="130 mm")
        .solve(theta2=theta, omega2="3000 rpm", alpha2=0)
        .d_ddot.magnitude
    ).max(),
    "4",
)

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set; solve them with eqs. 7.35 to 7.40, then check
# with `FourBar`. The answers are folded.
#
# **Problem 9.1.** The Example 7-1 fourbar (the course's numbers) runs at a steady 10 rad/s.
# At $\theta_2 = 120^\circ$ find $\varphi_3$, $\varphi_4$ and $\mathbf{J}_B$.
#
# <details><summary>Answer</summary>
#
# With $\alpha_2 = \varphi_2 = 0$: $\varphi_3 = -103.4$ rad/s$^3$, $\varphi_4 = -269.1$
# rad/s$^3$, and $\mathbf{J}_B$ = 2592 in/s$^3$ at $22.0^\circ$.
#
# </details>
#
# **Problem 9.2.** The 40 mm crank, 130 mm rod engine of example 3 at a steady 3000 rpm: what
# is the piston's jerk at top dead centre, and where in the cycle is it largest?
#
# <details><summary>Answer</summary>
#
# Zero at top dead centre: by symmetry the piston's acceleration is at its extreme there, so its
# rate of change passes through zero. It is largest, about $1.8 \times 10^6$ m/s$^3$, near
# $\theta_2 = 59^\circ$ (and $301^\circ$), where the acceleration climbs fastest from its peak
# at TDC toward its zero near $74^\circ$ (notebook 4).
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
r91 = fourbar.solve(theta2="120 deg", omega2="10 rad/s", alpha2=0)
stated(r91.jerk3, "-103.4", "rad/s^3")
stated(r91.jerk4, "-269.1", "rad/s^3")
stated(abs(r91.J_B), "2592", "in/s^3")
stated(np.angle(r91.J_B.magnitude, deg=True), "22.0")
tdc = SliderCrank(a="40 mm", b="130 mm").solve(theta2="0 deg", omega2="3000 rpm", alpha2=0)
assert abs(tdc.d_dddot.m_as("m/s^3")) < 1e-6
stated(np.abs(engine.d_dddot.m_as("m/s^3")).max(), "1.8e6")
where = np.degrees(theta.magnitude[np.argmax(np.abs(engine.d_dddot.m_as("m/s^3")))])
stated(min(where, 360 - where), "59")

# %% [markdown]
# ## Practice
#
# Jerk problems with instant feedback, for self-study (not graded, and never one of a graded
# assignment's). Each run of the next cell draws a fresh fourbar, or give a seed to come back to
# one; hand each answer to `mine.check`, which says at once whether it is right and, if not, what to
# look at (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `jerk`.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("jerk")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("jerk4", Q_(-2.1e4, "rad/s^3"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("jerk", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5, modelled with `FourBar` (the input's
# jerk $\varphi_2$ is zero unless the problem gives one):

# %%
example = practice("jerk", seed=5, show=False)
g = example.given
res = FourBar(a=g["a"], b=g["b"], c=g["c"], d=g["d"]).solve(
    theta2=g["theta2"], omega2=g["omega2"], alpha2=g["alpha2"], circuit=g["circuit"]
)
assert example.check("jerk4", res.jerk4)  # right
assert not example.check("jerk4", res.alpha4)  # an angular acceleration, not a jerk
assert example.check("J_B_mag", abs(res.J_B))  # right

# %% [markdown]
# ## Common mistakes
#
# - **Differentiating $\omega^2$ as $2\omega$.** The derivative of $-L\omega^2 e^{j\theta}$ is
#   $-2L\omega\alpha e^{j\theta} - L\omega^3 je^{j\theta}$; together with the tangential term's
#   derivative it gives the $3\omega\alpha$ of eq. 7.34b.
# - **Forgetting $\varphi_2$** when the input's acceleration changes (a motor starting up).
# - **Copying eq. 7.40 with its stray "= 0"**, or any printed formula, without a check; a
#   numerical derivative is the cheap independent check.
# - **Numerical derivatives across a toggle or a branch change**: there the finite difference
#   measures the jump, not a jerk.
# - **Confusing $\varphi$ (jerk) with $\phi$ (the fivebar's phase).**
#
# [Next: 10. Linkages of N bars](10_nbar_linkages.ipynb)
