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
# # 3. The analytic fourbar
#
# A drawing gives one position. To design a linkage we need the accelerations at every crank
# angle, and that calls for the analytic solution: differentiate the vector loop twice and
# solve for the two unknown angular accelerations. This notebook derives it (Robert L. Norton,
# *Design of Machinery*, chapter 7, section 7.3: eqs. 7.7 to 7.13 and Figure 7-5), checks it
# against the graphical answer of notebook 2, then runs a whole cycle on both circuits.
#
# **You will be able to**
#
# - differentiate the fourbar's vector loop into the acceleration equation and recognise in
#   it the acceleration difference equation 7.4;
# - solve it for $\alpha_3$ and $\alpha_4$ and compute $\mathbf{A}_A$, $\mathbf{A}_{BA}$,
#   $\mathbf{A}_B$, in US and SI units;
# - plot $\alpha_3$, $\alpha_4$ and $|\mathbf{A}_B|$ over a cycle and say what changes between
#   the open and crossed circuits;
# - recognise toggle and non-assemblable positions and read the solver's `valid` mask.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import math

import matplotlib.pyplot as plt
import numpy as np

from accelab.course.animation import animate
from accelab.course.kit import CIRCUIT_COLORS, explore, stated, use_style
from accelab.course.practice import practice
from accelab.course.renditions import panels, show
from accelab.course.text import num, say, sci, table, vec, xy
from accelab.solver import Q_, FourBar, NotAssemblable, Singular
from accelab.solver.graphical import construct_case
from accelab.solver.graphical.draw import draw_linkage
from accelab.solver.graphical.gallery import EXAMPLE_7_1

use_style()

# %% [markdown]
# ## The idea and its equations
#
# The fourbar closes a vector loop (links $a$, $b$, $c$, ground $d$ at $\theta_1 = 0$):
#
# $$ a e^{j\theta_2} + b e^{j\theta_3} - c e^{j\theta_4} - d e^{j\theta_1} = 0 \tag{4.5} $$
#
# Differentiating once gives the velocity equation (each $e^{j\theta}$ brings down
# $j\omega$):
#
# $$ \begin{aligned} & ja\omega_2 e^{j\theta_2} + jb\omega_3 e^{j\theta_3} \\
#    & - jc\omega_4 e^{j\theta_4} = 0 \end{aligned} \tag{6.14} $$
#
# Differentiating again, every term has two functions of time, $\omega$ and $\theta$, and so
# yields two terms:
#
# $$ \begin{aligned} & \left(a\alpha_2 je^{j\theta_2} - a\omega_2^2 e^{j\theta_2}\right) \\
#  & + \left(b\alpha_3 je^{j\theta_3} - b\omega_3^2 e^{j\theta_3}\right) \\
#  & - \left(c\alpha_4 je^{j\theta_4} - c\omega_4^2 e^{j\theta_4}\right) = 0
#    \end{aligned} \tag{7.7} $$
#
# Each bracket is a rotating point's acceleration (eq. 7.2): the first is $\mathbf{A}_A$, the
# second $\mathbf{A}_{BA}$ (B about A on the coupler), the third $\mathbf{A}_B$ (B about $O_4$).
# Eq. 7.7 is the acceleration difference equation in disguise:
#
# $$ \mathbf{A}_A + \mathbf{A}_{BA} - \mathbf{A}_B = 0 \tag{7.8} $$
#
# **From one vector equation to two scalar ones.** Put Euler's identity
# $e^{j\theta} = \cos\theta + j\sin\theta$ into every term of eq. 7.7 and multiply out the
# $j$ of each tangential term ($j \cdot j = -1$):
#
# $$ \begin{aligned}
#    & a\alpha_2(-\sin\theta_2 + j\cos\theta_2) \\
#    & - a\omega_2^2(\cos\theta_2 + j\sin\theta_2) \\
#    & + b\alpha_3(-\sin\theta_3 + j\cos\theta_3) \\
#    & - b\omega_3^2(\cos\theta_3 + j\sin\theta_3) \\
#    & - c\alpha_4(-\sin\theta_4 + j\cos\theta_4) \\
#    & + c\omega_4^2(\cos\theta_4 + j\sin\theta_4) = 0
#    \end{aligned} \tag{7.10b} $$
#
# A complex number is zero only if its real and its imaginary parts both are. Collecting the
# real terms (the $x$ components) and the imaginary ones (the $y$ components, where the $j$'s
# cancel) gives two equations:
#
# $$ \begin{aligned}
#    & -a\alpha_2\sin\theta_2 - a\omega_2^2\cos\theta_2 \\
#    & - b\alpha_3\sin\theta_3 - b\omega_3^2\cos\theta_3 \\
#    & + c\alpha_4\sin\theta_4 + c\omega_4^2\cos\theta_4 = 0
#    \end{aligned} \tag{7.11a} $$
#
# $$ \begin{aligned}
#    & a\alpha_2\cos\theta_2 - a\omega_2^2\sin\theta_2 \\
#    & + b\alpha_3\cos\theta_3 - b\omega_3^2\sin\theta_3 \\
#    & - c\alpha_4\cos\theta_4 + c\omega_4^2\sin\theta_4 = 0
#    \end{aligned} \tag{7.11b} $$
#
# Everything in them is known from the position and velocity analyses except $\alpha_3$ and
# $\alpha_4$, and both appear to the first power only: two *linear* equations in two
# unknowns. Keep the unknowns on the left and move every known term to the right. With the
# chapter's names for the coefficients,
#
# $$ \begin{aligned} A\alpha_4 - B\alpha_3 &= C, \\ D\alpha_4 - E\alpha_3 &= F \end{aligned} $$
#
# where
#
# $$ \begin{aligned}
#    A &= c\sin\theta_4, \qquad B = b\sin\theta_3, \\
#    D &= c\cos\theta_4, \qquad E = b\cos\theta_3, \\
#    C &= a\alpha_2\sin\theta_2 + a\omega_2^2\cos\theta_2 \\
#      &\quad + b\omega_3^2\cos\theta_3 - c\omega_4^2\cos\theta_4, \\
#    F &= a\alpha_2\cos\theta_2 - a\omega_2^2\sin\theta_2 \\
#      &\quad - b\omega_3^2\sin\theta_3 + c\omega_4^2\sin\theta_4
#    \end{aligned} \tag{7.12c} $$
#
# (eq. 7.11a gives the first, eq. 7.11b the second). Solving the pair (by Cramer's rule, or
# by eliminating one unknown):
#
# $$ \alpha_3 = \frac{CD - AF}{AE - BD} \tag{7.12a} $$
#
# $$ \alpha_4 = \frac{CE - BF}{AE - BD} \tag{7.12b} $$
#
# The denominator is $AE - BD = bc\sin(\theta_4 - \theta_3)$: it vanishes when links 3 and 4
# are in line, the same toggle that made the construction lines parallel in notebook 2. The
# linear accelerations then follow from eq. 7.8's three brackets with Euler's identity put in
# (eqs. 7.13a to 7.13c).
#
# The solver does not use the letters $A$ to $F$ (it projects eq. 7.7 on the directions of
# links 3 and 4, which is the same algebra). Written out for learning, checked against it:

# %%
fb = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
r = fb.solve(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")

a, b, c = 2.0, 6.0, 9.0  # in
t2, w2, al2 = math.radians(30), 10.0, -5.0
t3, t4 = r.theta3.to("rad").magnitude, r.theta4.to("rad").magnitude
w3, w4 = r.omega3.to("rad/s").magnitude, r.omega4.to("rad/s").magnitude
A, B, D, E = c * math.sin(t4), b * math.sin(t3), c * math.cos(t4), b * math.cos(t3)
C = (
    a * al2 * math.sin(t2)
    + a * w2**2 * math.cos(t2)
    + b * w3**2 * math.cos(t3)
    - c * w4**2 * math.cos(t4)
)
F = (
    a * al2 * math.cos(t2)
    - a * w2**2 * math.sin(t2)
    - b * w3**2 * math.sin(t3)
    + c * w4**2 * math.sin(t4)
)
alpha3 = (C * D - A * F) / (A * E - B * D)  # eq. 7.12a
alpha4 = (C * E - B * F) / (A * E - B * D)  # eq. 7.12b
assert math.isclose(alpha3, r.alpha3.to("rad/s^2").magnitude, rel_tol=1e-12)
assert math.isclose(alpha4, r.alpha4.to("rad/s^2").magnitude, rel_tol=1e-12)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"By eq. 7.12: $\alpha_3$ = {num(alpha3, 6)} rad/s² and $\alpha_4$ = {num(alpha4, 6)} "
    "rad/s², what the solver gives to the last digit."
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
assert math.isclose(A * E - B * D, b * c * math.sin(t4 - t3), rel_tol=1e-12)  # the denominator

# %% [markdown]
# ## Worked example 1: Example 7-1 by the equations
#
# The same linkage and input as notebook 2: $a = 2$, $b = 6$, $c = 9$, $d = 7$ in,
# $\theta_2 = 30^\circ$, $\omega_2 = 10$ rad/s, $\alpha_2 = -5$ rad/s$^2$, open circuit (the
# chapter's Example 7-1 prints no numbers; **these are the course's own numbers**). The
# solver returns Quantities; the vectors are complex, as in the chapter's notation.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "value"],
    [
        [r"$\theta_3$, $\theta_4$", f"{num(r.theta3.m_as('deg'))}°, {num(r.theta4.m_as('deg'))}°"],
        [r"$\omega_3$, $\omega_4$", f"{num(r.omega3)}, {num(r.omega4)} rad/s"],
        [r"$\alpha_3$, $\alpha_4$", f"{num(r.alpha3)}, {num(r.alpha4)} rad/s²"],
    ],
)
table(
    ["", "cartesian [in/s²]", "polar", "in SI"],
    [
        [
            f"${s}$",
            xy(getattr(r, k), "in/s^2"),
            vec(getattr(r, k), "in/s^2"),
            vec(getattr(r, k), "m/s^2"),
        ]
        for k, s in (
            ("A_A", r"\mathbf{A}_A"),
            ("A_BA_t", r"\mathbf{A}^t_{BA}"),
            ("A_BA_n", r"\mathbf{A}^n_{BA}"),
            ("A_BA", r"\mathbf{A}_{BA}"),
            ("A_B", r"\mathbf{A}_B"),
        )
    ],
)

# %% [markdown]
# Check them against the graphical construction, which never calls the analytic solver:

# %%
graphical = construct_case(EXAMPLE_7_1).values
rows = []
for name, symbol, unit in (
    ("alpha3", r"$\alpha_3$", "rad/s²"),
    ("alpha4", r"$\alpha_4$", "rad/s²"),
    ("A_A", r"$\lvert\mathbf{A}_A\rvert$", "m/s²"),
    ("A_B", r"$\lvert\mathbf{A}_B\rvert$", "m/s²"),
    ("A_BA", r"$\lvert\mathbf{A}_{BA}\rvert$", "m/s²"),
):
    exact = complex(getattr(r, name).to(unit.replace("²", "^2")).magnitude)
    drawn = complex(graphical[name])
    rel = abs(exact - drawn) / abs(exact)
    assert rel < 1e-9
    rows.append([f"{symbol} [{unit}]", num(abs(exact), 10), num(abs(drawn), 10), sci(rel)])
table(["", "analytic", "graphical", "relative difference"], rows)

# %% [markdown]
# Exact agreement: both methods solve the same vector equation, one with geometry and one
# with algebra. On paper the drawing would be good to two or three figures.

# %% [markdown]
# ## Worked example 2: a whole cycle, open and crossed
#
# The solver takes an array of crank angles and returns arrays, one position per element.
# The same linkage has two assemblies for every crank angle: **open** and **crossed**
# (coupler and rocker reflected about the line $AO_4$).


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The open and the crossed circuit of the Example 7-1 fourbar at $\\theta_2 = 30^\\circ$: the same crank, the coupler and rocker reflected about the line $AO_4$."}}
def circuits(narrow):
    fig, axes = panels(2, narrow, wide=(7.6, 3.6), tall=(4.4, 7.0), layout="constrained")
    for ax, circuit in zip(axes, ("open", "crossed")):
        g = construct_case(dict(EXAMPLE_7_1, circuit=circuit))
        draw_linkage(g, ax=ax, vectors=False)
        ax.set_title(f"{circuit} circuit at $\\theta_2 = 30^\\circ$")
    return fig


show(
    circuits,
    alt="Two drawings of the same fourbar assembled two ways, coupler and rocker "
    "reflected about the line A O4.",
)

# %%
theta2 = Q_(np.linspace(0, 360, 721), "deg")
cycle = {
    circuit: fb.solve(
        theta2=theta2, omega2="10 rad/s", alpha2="-5 rad/s^2", circuit=circuit, order=2
    )
    for circuit in ("open", "crossed")
}
deg = theta2.magnitude


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The Example 7-1 linkage over a whole crank cycle, $\\omega_2 = 10$ rad/s, $\\alpha_2 = -5$ rad/s²: the angular accelerations of links 3 and 4 and the size of $\\mathbf{A}_B$ on both circuits ($\\mathbf{A}_A$ dashed)."}}
def over_a_cycle(narrow):
    fig, axes = plt.subplots(
        3, 1, figsize=(4.4, 7.4) if narrow else (7.6, 6.6), sharex=True, layout="constrained"
    )
    for circuit, res in cycle.items():
        col = CIRCUIT_COLORS[circuit]
        axes[0].plot(deg, res.alpha3.to("rad/s^2").magnitude, color=col, label=circuit)
        axes[1].plot(deg, res.alpha4.to("rad/s^2").magnitude, color=col, label=circuit)
        axes[2].plot(deg, abs(res.A_B).to("in/s^2").magnitude, color=col, label=circuit)
    axes[2].plot(
        deg,
        abs(cycle["open"].A_A).to("in/s^2").magnitude,
        color="#777777",
        ls="--",
        label="$|\\mathbf{A}_A|$ (both)",
    )
    axes[0].set_ylabel("$\\alpha_3$ [rad/s$^2$]")
    axes[1].set_ylabel("$\\alpha_4$ [rad/s$^2$]")
    axes[2].set_ylabel("$|\\mathbf{A}_B|$ [in/s$^2$]")
    axes[2].set_xlabel("crank angle $\\theta_2$ [deg]")
    axes[2].set_xticks(range(0, 361, 90 if narrow else 45))
    for ax in axes:
        ax.axvline(30, color="#aaaaaa", lw=0.8)
    fig.legend(
        *axes[2].get_legend_handles_labels(), loc="outside lower center", ncol=3, frameon=False
    )
    return fig


show(
    over_a_cycle,
    alt="Line plots of alpha3, alpha4 and the size of A_B against crank angle from 0 to "
    "360 degrees, open and crossed circuits.",
)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
rows = []
for circuit, res in cycle.items():
    a4 = res.alpha4.to("rad/s^2").magnitude
    ab = abs(res.A_B).to("in/s^2").magnitude
    rows.append(
        [
            circuit,
            f"{num(a4.min(), 3)} to {num(a4.max(), 3)}",
            f"{num(ab.max(), 4)} in/s² ({num(ab.max() * 0.0254, 3)} m/s²)",
            f"{num(deg[ab.argmax()], decimals=1)}°",
        ]
    )
table(
    ["circuit", r"$\alpha_4$ [rad/s²]", r"largest $\lvert\mathbf{A}_B\rvert$", r"at $\theta_2$"],
    rows,
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
A_A = abs(cycle["open"].A_A).to("in/s^2").magnitude
assert np.ptp(A_A) < 1e-9 * A_A[0]  # constant size
stated(A_A[0], "200", sig=2)
ab = abs(cycle["open"].A_B).to("in/s^2").magnitude
assert ab.max() > 2 * A_A[0] and ab.min() < 0.3 * A_A[0]  # "more than doubles ..."

# %% [markdown]
# What to notice:
#
# - $\mathbf{A}_A$ is the same for both circuits (it depends on the crank only) and of
#   constant size, $a\sqrt{\omega_2^4 + \alpha_2^2} \approx a\omega_2^2 = 200$ in/s$^2$; the
#   rest of the linkage turns it into an acceleration of $B$ that more than doubles and falls
#   to a fraction of it within a turn.
# - The two circuits are mirror images of each other about the ground line, so their curves
#   are mirror images too, run backwards: the crossed circuit at $\theta_2$ does what the open
#   one does at $-\theta_2$, with the signs of the angular accelerations reversed. The small
#   $\alpha_2$ spoils the symmetry slightly; with $\alpha_2 = 0$ it is exact, as this check
#   confirms:

# %%
flip = fb.solve(theta2=-theta2, omega2="10 rad/s", circuit="open", order=2)
mirror = fb.solve(theta2=theta2, omega2="10 rad/s", circuit="crossed", order=2)
assert np.allclose(mirror.alpha4.magnitude, -flip.alpha4.magnitude, atol=1e-9)
assert np.allclose(mirror.alpha3.magnitude, -flip.alpha3.magnitude, atol=1e-9)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    r"With $\alpha_2 = 0$, $\alpha_3$ and $\alpha_4$ of the crossed circuit at $\theta_2$ are "
    r"those of the open circuit at $-\theta_2$ with their signs turned, at all "
    f"{deg.size} angles."
)

# %% [markdown]
# **The cycle in motion.** The open circuit through one crank turn: the linkage with the
# accelerations of its pins $A$ and $B$ (one arrow scale for the whole turn), and a marker
# running along the curves of $\alpha_3$, $\alpha_4$ and of $|\mathbf{A}_A|$,
# $|\mathbf{A}_B|$. Stop it where $|\mathbf{A}_B|$ peaks and step through the peak: the
# rocker is swinging back, and $\alpha_4$ is near its extreme. (Notebook 7 animates a point
# of the coupler instead.)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Animation: the Example 7-1 fourbar (open circuit) through one crank turn with the accelerations of $A$ and $B$, and a marker on the curves of $\\alpha_3$, $\\alpha_4$, $|\\mathbf{A}_A|$ and $|\\mathbf{A}_B|$. Play, pause, step or drag the slider."}}
pins_only = {k: v for k, v in EXAMPLE_7_1.items() if k not in ("p", "delta3")}
animate(
    pins_only,
    magnitudes=("A_A", "A_B"),
    title="Example 7-1 linkage",
    alt="The fourbar turning through its cycle with acceleration arrows at A and B, beside "
    "plots of alpha3, alpha4 and the sizes of A_A and A_B with a moving marker.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
at30 = {
    c: fb.solve(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2", circuit=c)
    for c in ("open", "crossed")
}
stated(at30["open"].alpha3, "8.77", "rad/s^2")
stated(at30["crossed"].alpha3, "70.3", "rad/s^2")

# %% [markdown]
# So for a *given crank angle* the two assemblies can have very different accelerations
# (at $30^\circ$: $\alpha_3 = 8.77$ versus $70.3$ rad/s$^2$), and a design must say which
# circuit it means. A linkage cannot switch circuits without being taken apart (or passing
# through a toggle), so the solver follows one circuit through the whole sweep.

# %% [markdown]
# ### Where the solution fails: toggles and gaps
#
# Take a non-Grashof linkage, $a = 5$, $b = 5$, $c = 5$, $d = 7$ in. Its crank cannot turn
# round: beyond a certain angle the coupler and rocker cannot reach each other. At the limit
# they lie in line, $\sin(\theta_4 - \theta_3) = 0$, and the denominator of eq. 7.12 vanishes.
# A sweep returns NaN there and a `valid` mask; a single angle raises an error that says
# what is wrong.

# %%
rocker = FourBar(a="5 in", b="5 in", c="5 in", d="7 in")
swing = Q_(np.linspace(-180, 180, 721), "deg")
sweep = rocker.solve(theta2=swing, omega2="10 rad/s", order=2)
why = " or ".join(f"`{s}`" for s in sorted(set(sweep.status[~sweep.valid])))
say(
    f"The sweep is valid at {sweep.valid.sum()} of {sweep.valid.size} angles; the others are {why}."
)
limit = math.degrees(math.acos((5**2 + 7**2 - (5 + 5) ** 2) / (2 * 5 * 7)))
for angle in (limit, 150.0):
    try:
        rocker.solve(theta2=Q_(angle, "deg"), omega2="10 rad/s")
    except (Singular, NotAssemblable) as exc:
        say(rf"At $\theta_2$ = {num(angle, 6)}° the solver raises `{type(exc).__name__}`: {exc}")

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
mu = rocker.solve(theta2="0 deg", omega2="10 rad/s")
mu = math.degrees(abs(math.remainder(mu.theta4.m_as("rad") - mu.theta3.m_as("rad"), math.pi)))
stated(mu, "23")  # the transmission angle at theta2 = 0, quoted below


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "A non-Grashof fourbar (5, 5, 5, 7 in), open circuit, $\\omega_2 = 10$ rad/s: $\\alpha_4$ runs away near the toggles, and beyond them the linkage cannot be assembled."}}
def toggles(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 3.8) if narrow else (7.6, 3.6), layout="constrained")
    a4 = sweep.alpha4.to("rad/s^2").magnitude
    ax.plot(swing.magnitude, a4, color=CIRCUIT_COLORS["open"])
    for lo, hi in ((-180, -limit), (limit, 180)):
        ax.axvspan(lo, hi, color="#eeeeee", label="cannot be assembled" if lo < 0 else None)
    for x in (-limit, limit):
        ax.axvline(x, color="#d55e00", ls=":", lw=1.2)
        ax.text(x, 2e4, " toggle ", color="#d55e00", ha="left" if x < 0 else "right")
    ax.set_yscale("symlog", linthresh=100)
    ax.set_xlabel("crank angle $\\theta_2$ [deg]")
    ax.set_ylabel("$\\alpha_4$ [rad/s$^2$] (symlog)")
    ax.set_xticks(range(-180, 181, 90 if narrow else 45))
    ax.set_xlim(-180, 180)
    ax.legend(loc="lower center")
    return fig


show(
    toggles,
    alt="Plot of alpha4 against crank angle on a symmetric log scale, with the unreachable "
    "angles shaded and the toggles marked.",
)

# %% [markdown]
# $\alpha_4$ runs away as the crank nears a toggle (the plot's vertical scale is logarithmic
# beyond $\pm 100$ rad/s$^2$): the crank cannot be driven through it at speed, and a real
# mechanism stops and reverses there (and, being non-Grashof, comes back on the other
# circuit). Beyond the toggles the linkage does not exist, and the solver says so instead of
# inventing numbers. The fast swing of $\alpha_4$ near $\theta_2 = 0$ is a warning of another
# kind: there coupler and rocker meet at only about $23^\circ$ (a poor transmission angle),
# and small motions of the crank swing the rocker hard.

# %% [markdown]
# ## Explore: the rocker's length and the Grashof condition
#
# Change the rocker $c$ of Example 7-1 and watch $\alpha_4$ over a cycle (open circuit,
# $\omega_2 = 10$ rad/s). With $a = 2$, $b = 6$, $d = 7$ the linkage is a Grashof crank-rocker
# while $a + c \le b + d$, that is $c \le 11$ in; at $c = 11$ it can fold flat (a change point)
# and beyond that the crank can no longer turn round.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "$\\alpha_4$ over a cycle for several rocker lengths $c$: Grashof or not, and how far the crank can turn."}}
def draw(c, omega2):
    link = FourBar(a="2 in", b="6 in", c=Q_(c, "in"), d="7 in")
    res = link.solve(theta2=theta2, omega2=Q_(omega2, "rad/s"), order=2)
    fig, ax = plt.subplots(figsize=(4.5, 3.4))
    ax.plot(deg, res.alpha4.to("rad/s^2").magnitude, color=CIRCUIT_COLORS["open"])
    bad = ~res.valid
    if bad.any():
        ax.fill_between(deg, -400, 400, where=bad, color="#eeeeee", label="not assemblable")
        ax.legend(loc="lower right", fontsize=10)
    ax.set_ylim(-400, 400)
    ax.set_xticks(range(0, 361, 90))
    ax.set_xlabel("$\\theta_2$ [deg]")
    ax.set_ylabel("$\\alpha_4$ [rad/s$^2$]")
    grashof = "Grashof" if 2 + max(c, 7) <= 6 + min(c, 7) else "non-Grashof"
    ax.set_title(f"c = {c:g} in ({grashof})", fontsize=11)
    return fig


explore(draw, c=(4.5, 12, 0.1, 9, "in"), omega2=(2, 20, 1, 10, "rad/s"), values=[5, 9, 10.8, 11.5])


# %% tags=["remove-cell"] jupyter={"source_hidden": true}
def rocker_cycle(c):
    res = FourBar(a="2 in", b="6 in", c=f"{c} in", d="7 in").solve(
        theta2=theta2, omega2="10 rad/s", order=2
    )
    return (
        np.degrees(np.ptp(np.unwrap(res.theta4.m_as("rad")))),
        np.nanmax(np.abs(res.alpha4.m_as("rad/s^2"))),
    )


swing, peak = zip(*(rocker_cycle(c) for c in (5, 9, 10.8, 10.95)))
stated(swing[0], "48")
stated(swing[1], "33")
stated(peak[0], "66")
stated(peak[1], "49")
stated(peak[2], "140")
stated(peak[3], "289")
assert 2 + 11 == 6 + 7  # the change point at c = 11 in

# %% [markdown]
# ## Check yourself
#
# **1.** In eq. 7.7, which bracket is $\mathbf{A}_{BA}$, and why does it carry $\omega_3$ and
# $\alpha_3$ rather than $\omega_2$, $\alpha_2$?
#
# <details><summary>Answer</summary>
#
# The second, $b\alpha_3 je^{j\theta_3} - b\omega_3^2e^{j\theta_3}$. $A$ and $B$ are both on the
# coupler (link 3), so $B$ turns about $A$ with the coupler's own $\omega_3$ and $\alpha_3$
# (Case 1 of notebook 1).
#
# </details>
#
# **2.** With $\alpha_2 = 0$, does $\mathbf{A}_A$ vanish? Do $\alpha_3$ and $\alpha_4$?
#
# <details><summary>Answer</summary>
#
# No and no. $\mathbf{A}_A$ keeps its normal part $-a\omega_2^2e^{j\theta_2}$, and the terms in
# $\omega^2$ in $C$ and $F$ keep $\alpha_3$ and $\alpha_4$ non-zero at almost every angle. A
# crank turning at constant speed still makes the rest of the linkage accelerate.
#
# </details>
#
# **3.** If $\omega_2$ doubles (with $\alpha_2 = 0$), what happens to $\alpha_3$, $\alpha_4$ and
# $\mathbf{A}_B$ at a given $\theta_2$?
#
# <details><summary>Answer</summary>
#
# All are multiplied by four. $\omega_3$ and $\omega_4$ are proportional to $\omega_2$, so every
# term in $C$ and $F$ scales as $\omega_2^2$. Check it: `fb.solve(theta2="30 deg",
# omega2="20 rad/s").alpha4` is four times the value at 10 rad/s.
#
# </details>
#
# **4.** A sweep returns `valid` False at a few angles. Give two different reasons, and how
# to tell them apart.
#
# <details><summary>Answer</summary>
#
# The linkage cannot be assembled there ($|O_4A|$ outside $|b - c| \dots b + c$), or it is at a
# toggle (links 3 and 4 in line, eq. 7.12's denominator zero). `result.status` says
# `'not_assemblable'` or `'singular'` for each angle.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
slow, fast = (
    fb.solve(theta2="30 deg", omega2=w, alpha2="0 rad/s^2") for w in ("10 rad/s", "20 rad/s")
)
stated(fast.alpha4 / slow.alpha4, "4")
stated(fast.alpha3 / slow.alpha3, "4")
stated(abs(fast.A_B) / abs(slow.A_B), "4")
# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set; solve them with eq. 7.12 on paper (a calculator
# for the trigonometry), then check with `FourBar`. The answers are folded.
#
# **Problem 3.1.** A fourbar has $a$ = 3, $b$ = 8, $c$ = 7 and $d$ = 9 in. At $\theta_2 =
# 45^\circ$ the crank turns clockwise at 20 rad/s and accelerates counter-clockwise at 100
# rad/s$^2$ ($\omega_2 = -20$ rad/s, $\alpha_2 = 100$ rad/s$^2$). Find $\alpha_3$, $\alpha_4$
# and $\mathbf{A}_B$ on the open circuit.
#
# <details><summary>Answer</summary>
#
# $\alpha_3 = 111.0$ rad/s$^2$ and $\alpha_4 = 271.3$ rad/s$^2$ (both counter-clockwise);
# $\mathbf{A}_B$ = 1899 in/s$^2$ at $-175.3^\circ$, nearly along $-x$.
#
# </details>
#
# **Problem 3.2.** The same linkage and input on the crossed circuit.
#
# <details><summary>Answer</summary>
#
# $\alpha_3 = 259.6$ rad/s$^2$, $\alpha_4 = 99.3$ rad/s$^2$, $\mathbf{A}_B$ = 909 in/s$^2$ at
# $1.5^\circ$: the same crank, a different linkage.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
link = FourBar(a="3 in", b="8 in", c="7 in", d="9 in")
for circuit, (a3, a4, ab, ang) in (
    ("open", ("111.0", "271.3", "1899", "-175.3")),
    ("crossed", ("259.6", "99.3", "909", "1.5")),
):
    res = link.solve(theta2="45 deg", omega2="-20 rad/s", alpha2="100 rad/s^2", circuit=circuit)
    stated(res.alpha3, a3, "rad/s^2"), stated(res.alpha4, a4, "rad/s^2")
    stated(abs(res.A_B), ab, "in/s^2"), stated(np.angle(res.A_B.magnitude, deg=True), ang)

# %% [markdown]
# ## Practice
#
# Fourbar problems with instant feedback, for self-study (not graded, and never one of a graded
# assignment's): each run of the next cell draws a fresh linkage and input, or give a seed to
# come back to one. Solve it with eq. 7.12 (or `FourBar`, to check your hand work), then hand
# each answer to `mine.check`: it says at once whether it is right and, if not, what to look at
# (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `fourbar`.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("fourbar")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("alpha4", Q_(-31.4, "rad/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("fourbar", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5, modelled with `FourBar`:

# %%
example = practice("fourbar", seed=5, show=False)
g = example.given
model = FourBar(a=g["a"], b=g["b"], c=g["c"], d=g["d"])
res = model.solve(theta2=g["theta2"], omega2=g["omega2"], alpha2=g["alpha2"], circuit=g["circuit"])
assert example.check("alpha3", res.alpha3)  # right
assert not example.check("alpha3", res.alpha4)  # the rocker's, not the coupler's
assert example.check("A_B_mag", abs(res.A_B).to("m/s^2"))  # right, in other units

# %% [markdown]
# ## Common mistakes
#
# - **Solving acceleration before position and velocity.** Eq. 7.12 needs $\theta_3$,
#   $\theta_4$, $\omega_3$, $\omega_4$ at the same crank angle and on the same circuit.
# - **Mixing circuits.** Taking $\theta_3$, $\theta_4$ of the open circuit with $\omega$'s from a
#   crossed-circuit formula gives numbers that belong to no linkage.
# - **Degrees in the trigonometry.** `math.sin(30)` is the sine of 30 radians. Let the
#   solver take Quantities such as `"30 deg"`.
# - **Copying eq. 7.12 from a scan.** Printed equations can carry typos; derive them from the
#   loop (as above) or check them against an independent method before trusting them.
# - **Ignoring the `valid` mask.** NaN propagates silently into maxima and means; use
#   `np.nanmax` or select `result.valid` first, and ask why the gaps are there.
#
# [Next: 4. The slider-crank and the engine](04_slider_crank_engine.ipynb)
