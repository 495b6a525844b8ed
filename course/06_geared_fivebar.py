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
# # 6. The geared fivebar
#
# Five links in one loop have two degrees of freedom. Gear the second crank to the first and
# one input drives them both: the **geared fivebar**. Its gear ratio and the phase at which the
# gears are meshed are two design knobs a fourbar does not have, and they change the coupler's
# accelerations a great deal. This notebook follows section 7.4 of the chapter (Robert L.
# Norton, *Design of Machinery*, chapter 7, eqs. 7.28 and 7.29).
#
# **You will be able to**
#
# - write the acceleration equation of the geared fivebar (eqs. 7.28-7.29) and say where the
#   gear ratio $\lambda$ and the phase $\phi$ enter;
# - solve it at one position with `GearedFiveBar` and check the closed form against the
#   solver;
# - tell how many crank turns one cycle of the linkage takes, for any gear ratio;
# - judge, from curves over a cycle, how $\lambda$ and $\phi$ change the coupler's angular
#   accelerations and the acceleration of the coupler pin B.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
from fractions import Fraction

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import Normalize

from accelab.course.animation import animate
from accelab.course.kit import COLORS, explore, in_g, stated, use_style
from accelab.course.practice import practice
from accelab.course.renditions import legend, panels, show
from accelab.course.text import num, say, table, vec
from accelab.solver import Q_, FourBar, GearedFiveBar
from accelab.solver.graphical import fivebar as fivebar_construction
from accelab.solver.graphical.draw import draw_linkage

use_style()

# %% [markdown]
# ## The idea and its equations
#
# Crank 2 (length $a$) turns about $O_2$, crank 5 (length $d$) about $O_5$, a distance $f$
# away along the ground. Two couplers join them: link 3 ($b$, from A to B) and link 4 ($c$,
# from C to B). The vector loop is
#
# $$ \begin{aligned} & a e^{j\theta_2} + b e^{j\theta_3} - c e^{j\theta_4} \\
#    & - d e^{j\theta_5} - f e^{j\theta_1} = 0 \end{aligned} $$
#
# Without gears, $\theta_2$ and $\theta_5$ would both be inputs. Gears of ratio $\lambda$,
# meshed at the phase $\phi$, tie them together:
#
# $$ \begin{aligned} \theta_5 &= \lambda\theta_2 + \phi, \\ \omega_5 &= \lambda\omega_2,
#    \qquad \alpha_5 = \lambda\alpha_2 \end{aligned} \tag{7.28c} $$
#
# A pair of external gears turns the two cranks in opposite senses, so $\lambda < 0$ (for
# example $\lambda = -2$: gear 5 has half the teeth of gear 2); an idler gear makes
# $\lambda > 0$. Differentiating the loop twice, with $\omega_5$ and $\alpha_5$ known from
# eq. 7.28c:
#
# $$ \begin{aligned}
#    & \left(a\alpha_2 je^{j\theta_2} - a\omega_2^2 e^{j\theta_2}\right) \\
#    & + \left(b\alpha_3 je^{j\theta_3} - b\omega_3^2 e^{j\theta_3}\right) \\
#    & - \left(c\alpha_4 je^{j\theta_4} - c\omega_4^2 e^{j\theta_4}\right) \\
#    & - \left(d\alpha_5 je^{j\theta_5} - d\omega_5^2 e^{j\theta_5}\right) = 0
#    \end{aligned} \tag{7.28a} $$
#
# Only $\alpha_3$ and $\alpha_4$ are unknown: the geared fivebar is a fourbar whose "ground
# pivot" C moves along a known path. The real and imaginary parts solve to
#
# $$ \begin{aligned} & b\sin(\theta_3-\theta_4)\,\alpha_3 = \\
#    & \quad -a\alpha_2\sin(\theta_2-\theta_4) \\
#    & \quad - a\omega_2^2\cos(\theta_2-\theta_4) \\
#    & \quad - b\omega_3^2\cos(\theta_3-\theta_4) \\
#    & \quad + d\omega_5^2\cos(\theta_5-\theta_4) \\
#    & \quad + d\alpha_5\sin(\theta_5-\theta_4) + c\omega_4^2
#    \end{aligned} \tag{7.29a} $$
#
# $$ \begin{aligned} & c\sin(\theta_4-\theta_3)\,\alpha_4 = \\
#    & \quad a\alpha_2\sin(\theta_2-\theta_3) \\
#    & \quad + a\omega_2^2\cos(\theta_2-\theta_3) \\
#    & \quad - c\omega_4^2\cos(\theta_3-\theta_4) \\
#    & \quad - d\omega_5^2\cos(\theta_3-\theta_5) \\
#    & \quad + d\alpha_5\sin(\theta_3-\theta_5) + b\omega_3^2
#    \end{aligned} \tag{7.29b} $$
#
# and the pins accelerate as
#
# $$ \mathbf{A}_A = a\alpha_2 je^{j\theta_2} - a\omega_2^2 e^{j\theta_2} \tag{7.29c} $$
#
# $$ \mathbf{A}_{BA} = b\alpha_3 je^{j\theta_3} - b\omega_3^2 e^{j\theta_3} \tag{7.29d} $$
#
# $$ \mathbf{A}_C = d\alpha_5 je^{j\theta_5} - d\omega_5^2 e^{j\theta_5} \tag{7.29e} $$
#
# $$ \mathbf{A}_B = \mathbf{A}_A + \mathbf{A}_{BA} \tag{7.29f} $$
#
# (The scanned chapter writes $\mathbf{A}_C$ with $c$; C is the pin of crank 5, whose length
# is $d$.) Both denominators vanish where $\sin(\theta_3 - \theta_4) = 0$: the two couplers in
# line, the fivebar's toggle.
#
# **How long is a cycle?** The linkage is back where it started when *both* cranks are: crank
# 2 after a whole number of turns $q$, crank 5 after a whole number $p$, with
# $p/q = |\lambda|$. Write $\lambda$ as a fraction in lowest terms, $\lambda = \pm p/q$: one
# cycle takes $q$ turns of the input. $\lambda = -2$ repeats every turn, $\lambda = -1.5 =
# -3/2$ every two, and an irrational ratio never repeats exactly.

# %% [markdown]
# ## Worked examples
#
# ### 1. One position
#
# Cranks $a = d = 1.5$ in, couplers $b = c = 4$ in, pivots $f = 4$ in apart, external gears
# with $\lambda = -2$ meshed so that $\phi = 30°$. At $\theta_2 = 60°$ the input turns at 20
# rad/s counter-clockwise and slows at 50 rad/s².

# %%
geometry = dict(a="1.5 in", b="4 in", c="4 in", d="1.5 in", f="4 in")
fivebar = GearedFiveBar(**geometry, lam=-2, phi="30 deg")
r = fivebar.solve(theta2="60 deg", omega2="20 rad/s", alpha2="-50 rad/s^2")

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "value"],
    [
        [
            r"$\theta_5$, $\omega_5$, $\alpha_5$",
            f"{num(r.theta5.m_as('deg'))}°, {num(r.omega5)} rad/s, {num(r.alpha5)} rad/s²",
        ],
        [r"$\theta_3$, $\theta_4$", f"{num(r.theta3.m_as('deg'))}°, {num(r.theta4.m_as('deg'))}°"],
        [r"$\omega_3$, $\omega_4$", f"{num(r.omega3)}, {num(r.omega4)} rad/s"],
        [r"$\alpha_3$, $\alpha_4$", f"{num(r.alpha3)}, {num(r.alpha4)} rad/s²"],
    ]
    + [
        [
            f"$\\mathbf{{A}}_{k[-1]}$",
            f"{vec(getattr(r, k), 'in/s^2')} = {vec(getattr(r, k), 'm/s^2')} "
            f"({num(in_g(getattr(r, k)), 3)} g)",
        ]
        for k in ("A_A", "A_C", "A_B")
    ],
)

# %% [markdown]
# The next cell evaluates eqs. 7.29a and 7.29b as printed, with the angles and velocities
# from the solver, and asserts that they agree with it; then it checks eq. 7.29f.

# %%
a, b, c, d = 1.5, 4.0, 4.0, 1.5  # in
t2, w2, al2 = np.radians(60), 20.0, -50.0
t3, t4, t5 = (getattr(r, k).to("rad").magnitude for k in ("theta3", "theta4", "theta5"))
w3, w4, w5 = (getattr(r, k).magnitude for k in ("omega3", "omega4", "omega5"))
al5 = -2 * al2  # eq. 7.28c
alpha3 = (
    -a * al2 * np.sin(t2 - t4)
    - a * w2**2 * np.cos(t2 - t4)
    - b * w3**2 * np.cos(t3 - t4)
    + d * w5**2 * np.cos(t5 - t4)
    + d * al5 * np.sin(t5 - t4)
    + c * w4**2
) / (b * np.sin(t3 - t4))
alpha4 = (
    a * al2 * np.sin(t2 - t3)
    + a * w2**2 * np.cos(t2 - t3)
    - c * w4**2 * np.cos(t3 - t4)
    - d * w5**2 * np.cos(t3 - t5)
    + d * al5 * np.sin(t3 - t5)
    + b * w3**2
) / (c * np.sin(t4 - t3))
assert np.isclose(alpha3, r.alpha3.magnitude, rtol=1e-12)
assert np.isclose(alpha4, r.alpha4.magnitude, rtol=1e-12)
assert np.isclose((r.A_A + r.A_BA - r.A_B).to("in/s^2").magnitude, 0, atol=1e-9)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"Eq. 7.29a gives $\alpha_3$ = {num(alpha3, 7)} rad/s² and eq. 7.29b $\alpha_4$ = "
    f"{num(alpha4, 7)} rad/s²: both what the solver gives."
)

# %% [markdown]
# The graphical construction (section 7.2's method, with two moving "pivots" A and C) draws
# the same position to scale with its accelerations at their points. The dotted circles are
# the gears' pitch circles: with external gears of ratio $-2$ on centres 4 in apart, gear 2
# has a pitch radius of 8/3 in and gear 5 of 4/3 in.

# %%
pitch2, pitch5 = 4 * 2 / 3, 4 * 1 / 3  # in: r2 + r5 = 4 in and r2 / r5 = |lambda| = 2
m = Q_(1, "in").to("m").magnitude
con = fivebar_construction.construct(
    a * m, b * m, c * m, d * m, 4 * m, -2, np.radians(30), t2, w2, al2
)
assert np.isclose(con.values["alpha3"], r.alpha3.magnitude, rtol=1e-9)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(pitch2, "2.667")
stated(pitch5, "1.333")


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The geared fivebar of example 1 drawn to scale (inches) with the accelerations at $A$, $B$ and $C$ and the gears' pitch circles (dotted)."}}
def fivebar_drawing(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 5.0) if narrow else (7.4, 5.2), layout="constrained")
    draw_linkage(con, ax=ax, units="US", legend=not narrow)  # the linkage was given in inches
    for centre, radius in ((0, pitch2), (4, pitch5)):  # drawn in inches
        ax.add_patch(plt.Circle((centre, 0), radius, fill=False, color="#999999", ls=":", lw=1.2))
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    ax.set_xlim(min(x0, -pitch2 - 0.3), max(x1, 4 + pitch5 + 0.3))  # room for the pitch circles
    ax.set_ylim(min(y0, -pitch2 - 0.3), y1)
    if narrow:
        legend(fig, ("normal", "tangential", "resultant"), ncol=2, loc="outside lower center")
    return fig


show(
    fivebar_drawing,
    alt="Geared fivebar linkage in inches with acceleration arrows at its pins and two "
    "dotted pitch circles.",
)

# %% [markdown]
# ### 2. A gear ratio of zero is a fourbar
#
# With $\lambda = 0$, crank 5 never turns: C is a fixed pivot at $O_5 + d e^{j\phi}$, and the
# linkage is a fourbar with ground link from $O_2$ to C. The `FourBar` solver must then give
# the same coupler accelerations, which is a useful check on both.

# %%
phi = np.radians(30)
C = 4 + d * np.exp(1j * phi)  # fixed pivot, in
still = GearedFiveBar(**geometry, lam=0, phi="30 deg")
as_fourbar = FourBar(
    a="1.5 in", b="4 in", c="4 in", d=f"{abs(C)} in", theta1=f"{np.degrees(np.angle(C))} deg"
)
theta = Q_(np.linspace(0, 2 * np.pi, 73), "rad")
g = still.solve(theta2=theta, omega2="20 rad/s", alpha2="-50 rad/s^2")
f4 = as_fourbar.solve(theta2=theta, omega2="20 rad/s", alpha2="-50 rad/s^2")
both = g.valid & f4.valid
assert both.sum() > 60
assert np.allclose(g.alpha3.magnitude[both], f4.alpha3.magnitude[both], rtol=1e-9)
assert np.allclose(
    g.A_B.to("in/s^2").magnitude[both], f4.A_B.to("in/s^2").magnitude[both], rtol=1e-9
)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"With $\lambda = 0$, $\alpha_3$ and $\mathbf{{A}}_B$ agree with the fourbar's at all "
    f"{both.sum()} positions both can reach."
)

# %% [markdown]
# ### 3. Curves over a cycle: the gear ratio
#
# A steady 20 rad/s input ($\alpha_2 = 0$), the same phase $\phi = 30°$, three gear ratios.
# Each curve is one solver call on an array of crank angles.


# %%
def cycle_turns(lam):
    """Crank turns in one cycle: the denominator of lam as a fraction in lowest terms."""
    return Fraction(lam).limit_denominator(100).denominator


def sweep(lam, phi_deg, points_per_turn=360, omega2="20 rad/s"):
    turns = cycle_turns(lam)
    theta = np.linspace(0, 2 * np.pi * turns, points_per_turn * turns + 1)
    linkage = GearedFiveBar(**geometry, lam=lam, phi=f"{phi_deg} deg")
    return np.degrees(theta), linkage.solve(theta2=Q_(theta, "rad"), omega2=omega2, alpha2=0)


ratios = {lam: sweep(lam, 30) for lam in (-1, -2, 2)}
assert all(s.valid.all() for _, s in ratios.values())


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Over a cycle for three gear ratios $\\lambda$ (phase $\\phi = 30^\\circ$, $\\omega_2 = 20$ rad/s): the coupler's angular acceleration $\\alpha_3$ and the acceleration of pin $B$."}}
def gear_ratios(narrow):
    colours = {-1: COLORS["normal"], -2: COLORS["tangential"], 2: COLORS["coriolis"]}
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.8, 3.6), tall=(4.4, 7.0), layout="constrained")
    for lam, (deg, s) in ratios.items():
        label = rf"$\lambda$ = {lam:+d}"
        ax1.plot(deg, s.alpha3.magnitude / 1000, color=colours[lam], label=label)
        ax2.plot(deg, in_g(s.A_B), color=colours[lam], label=label)
    ax1.set_ylabel(r"$\alpha_3$ [1000 rad/s$^2$]")
    ax2.set_ylabel(r"$|\mathbf{A}_B|$ [g]")
    for ax in (ax1, ax2):
        ax.set_xlabel(r"crank angle $\theta_2$ [deg]")
        ax.set_xticks(range(0, 361, 90))
    ax2.legend()
    ax1.set_title("Coupler 3's angular acceleration")
    ax2.set_title("Acceleration of the coupler pin $B$")
    return fig


show(gear_ratios, alt="Two line plots against crank angle, one curve per gear ratio.")

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
peak_of = {lam: np.nanmax(in_g(s.A_B)) for lam, (_, s) in ratios.items()}
stated(peak_of[-2] / peak_of[-1], "3.4")
stated(peak_of[2] / peak_of[-1], "4.3")
# "mirror each other" holds for phi = 180 deg only: then B stays on the line x = f / 2
mirrored = sweep(-1, 180)[1]
assert np.allclose(mirrored.R_B.m_as("in").real, 2.0, atol=1e-9)
assert np.ptp(ratios[-1][1].R_B.m_as("in").real) > 0.5  # with phi = 30 deg it does not

# %% [markdown]
# With $\lambda = -1$ crank 5 turns as fast as crank 2, the other way, and the coupler moves
# gently. (The two cranks mirror each other about the perpendicular bisector of $O_2O_5$ only
# when $\theta_5 = 180^\circ - \theta_2$, that is with $\phi = 180^\circ$; at the phase used
# here, $30^\circ$, they do not, and $B$ wanders off that line.) At $\lambda = \pm 2$ crank 5
# turns twice per input turn and the couplers are whipped round twice as often: the peaks of
# $|\mathbf{A}_B|$ are 3.4 ($\lambda = -2$) and 4.3 ($\lambda = +2$) times higher. Positive
# and negative ratios of the same size give quite different motions, because the cranks then
# turn the same way or opposite ways.
#
# ### 4. The phase
#
# The phase angle costs nothing to change (mesh the gears one tooth further round), yet it
# changes the linkage: at a given $\theta_2$ crank 5 points somewhere else, so the couplers
# take different shapes. The chart shows the largest $|\mathbf{A}_B|$ over a cycle against
# $\phi$, for four gear ratios.

# %%
phis = np.arange(0, 361, 10)
gear_colour = {
    -1: COLORS["normal"],
    -1.5: COLORS["slip"],
    -2: COLORS["tangential"],
    2: COLORS["coriolis"],
}
peaks = {
    lam: [np.nanmax(in_g(sweep(lam, p, points_per_turn=180)[1].A_B)) for p in phis]
    for lam in gear_colour
}
spread = {lam: max(peak) / min(peak) for lam, peak in peaks.items()}


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The largest acceleration of $B$ in a cycle at $\\omega_2 = 20$ rad/s against the phase angle $\\phi$, for four gear ratios: the phase matters."}}
def phases(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 4.2) if narrow else (7.4, 3.8), layout="constrained")
    for lam, peak in peaks.items():
        ax.plot(phis, peak, "o-", ms=3, color=gear_colour[lam], label=rf"$\lambda$ = {lam:+g}")
    ax.set_xlabel(r"phase $\phi$ [deg]")
    ax.set_ylabel(r"largest $|\mathbf{A}_B|$ [g]")
    ax.set_xticks(range(0, 361, 90 if narrow else 45))
    ax.set_yscale("log")
    ax.legend(
        ncol=2 if narrow else 4, loc="upper center", bbox_to_anchor=(0.5, -0.2 if narrow else -0.16)
    )
    return fig


show(
    phases,
    alt="Line plot of peak acceleration against phase angle from 0 to 360 degrees, one curve "
    "per gear ratio.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(spread[2], "6", sig=1)
stated(spread[-2], "1.7")

# %% [markdown]
# For $\lambda = +2$ the worst phase gives six times the peak acceleration of the best one;
# for $\lambda = -2$ about 1.7 times. A designer who picks the gear ratio for the coupler
# curve's shape still has the phase to tune, and should look at accelerations while doing so.
#
# ### 5. A gear ratio that is not a whole number
#
# With $\lambda = -1.5$, crank 5 makes one and a half turns per input turn, so after one
# input turn it is half a turn away from where it started and the coupler pin B is on a
# different part of its path. One cycle needs two input turns (and three turns of crank 5).

# %%
deg, s = sweep(-1.5, 30)
B = s.R_B.to("in").magnitude
half = len(deg) // 2

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"$\lambda = -1.5 = {Fraction(-1.5)}$: one cycle is {cycle_turns(-1.5)} turns of the "
    "input."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "With $\\lambda = -1.5$ the path of $B$ takes two input turns to close: the path, and the acceleration of $B$ over one full cycle."}}
def two_turns(narrow):
    fig, (ax1, ax2) = panels(
        2, narrow, wide=(7.8, 3.6), tall=(4.4, 7.4), width_ratios=[1, 1.3], layout="constrained"
    )
    ax1.plot(
        B.real[: half + 1],
        B.imag[: half + 1],
        color=COLORS["tangential"],
        lw=2.2,
        label="first input turn",
    )
    ax1.plot(
        B.real[half:],
        B.imag[half:],
        color=COLORS["normal"],
        lw=2.2,
        ls="--",
        label="second input turn",
    )
    ax1.plot(B.real[0], B.imag[0], "ko", ms=6)
    ax1.annotate(
        r"start, $\theta_2$ = 0",
        (B.real[0], B.imag[0]),
        textcoords="offset points",
        xytext=(8, -14),
        fontsize=10,
    )
    ax1.plot(B.real[half], B.imag[half], "s", color="black", ms=6)
    ax1.annotate(
        "after one turn",
        (B.real[half], B.imag[half]),
        textcoords="offset points",
        xytext=(8, 6),
        fontsize=10,
    )
    ax1.set_aspect("equal")
    ax1.set_xlabel("x [in]")
    ax1.set_ylabel("y [in]")
    ax1.set_title(r"Path of $B$, $\lambda$ = -1.5")
    ax1.legend(loc="lower left")
    ax2.plot(deg, in_g(s.A_B), color="black")
    ax2.axvline(360, color="#888888", ls=":")
    ax2.set_xlabel(r"crank angle $\theta_2$ [deg]")
    ax2.set_ylabel(r"$|\mathbf{A}_B|$ [g]")
    ax2.set_xticks(range(0, 721, 180))
    ax2.set_title("Two input turns make one cycle")
    return fig


show(
    two_turns,
    alt="The closed coupler path of B, and the acceleration of B against crank angle over "
    "two turns.",
)

# %% [markdown]
# ## Explore
#
# Turn the phase (and, live, the gear ratio). The path of B is coloured by the size of its
# acceleration on one fixed colour scale, so a hot path is a fast-changing one; the title gives
# the peaks over the whole cycle, however many input turns it takes.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The path of coupler pin $B$ at four phase angles $\\phi$ ($\\lambda = -2$), coloured by the size of its acceleration in g: the peak changes with the phase."}}
NORM = Normalize(vmin=0, vmax=30)  # g


def draw(phi=30, lam=-2.0):
    deg, s = sweep(lam, phi, points_per_turn=240)
    fig, ax = plt.subplots(figsize=(4.6, 4.2))
    ok = s.valid
    if ok.any():
        B = s.R_B.to("in").magnitude
        pts = np.column_stack([B.real, B.imag])
        seg = np.stack([pts[:-1], pts[1:]], axis=1)
        g = in_g(s.A_B)
        lines = LineCollection(seg[ok[:-1] & ok[1:]], cmap="viridis", norm=NORM, lw=2.5)
        lines.set_array(g[:-1][ok[:-1] & ok[1:]])
        ax.add_collection(lines)
        fig.colorbar(lines, ax=ax, label=r"$|\mathbf{A}_B|$ [g]", extend="max")
        title = (
            rf"$\lambda$ = {lam:+g}: cycle of {cycle_turns(lam)} turn(s),"
            "\n"
            rf"peak $|\mathbf{{A}}_B|$ {np.nanmax(g):.0f} g, "
            rf"$|\alpha_3|$ {np.nanmax(np.abs(s.alpha3.magnitude)):.0f} rad/s$^2$"
        )
    else:
        title = rf"$\lambda$ = {lam:+g}, $\phi$ = {phi}°: cannot be assembled"
    if not ok.all():
        title += f"\n({(~ok).sum()} of {ok.size} positions cannot be assembled)"
    if ok[0]:  # the linkage at theta2 = 0, for scale
        z = [0] + [getattr(s, k)[0].to("in").magnitude for k in ("R_A", "R_B", "R_C")] + [4]
        ax.plot(
            [p.real for p in z],
            [p.imag for p in z],
            "-o",
            color="#9a9a9a",
            lw=2,
            ms=4,
            mfc="white",
            zorder=1,
            label=r"linkage at $\theta_2$ = 0",
        )
        ax.legend(loc="lower left", fontsize=10)
    for centre in (0, 4):
        ax.plot(centre, 0, "^", color="#333333", ms=9)
    ax.set_title(title, fontsize=11)
    ax.set_xlim(-3, 7)
    ax.set_ylim(-2, 6.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x [in]")
    ax.set_ylabel("y [in]")
    return fig


explore(draw, phi=(0, 360, 15, 30, "deg"), lam=(-3, 3, 0.5, -2.0))

# %% [markdown]
# ## Check yourself
#
# 1. With $\lambda = -2.5$, how many input turns make one cycle, and how many turns does crank 5
#    make meanwhile?
#
# <details><summary>Answer</summary>
#
# $-2.5 = -5/2$: two input turns, during which crank 5 makes five turns (the other way).
#
# </details>
#
# 2. The input runs at a steady $\omega_2$. What is $\alpha_5$? And if the input is speeding up at
#    $\alpha_2 = 10$ rad/s² with $\lambda = -2$?
#
# <details><summary>Answer</summary>
#
# Zero at steady speed, since $\alpha_5 = \lambda\alpha_2$ (eq. 7.28c). With $\alpha_2 = 10$
# rad/s², $\alpha_5 = -20$ rad/s²: crank 5 speeds up too, in its own (opposite) sense.
#
# </details>
#
# 3. At a steady input speed you double $\omega_2$. What happens to $\alpha_3$ and to
#    $|\mathbf{A}_B|$ at each crank angle?
#
# <details><summary>Answer</summary>
#
# Both are multiplied by four. With $\alpha_2 = 0$ every term of eqs. 7.28-7.29 holds a product of
# two angular velocities, each proportional to $\omega_2$; the positions do not change.
#
# </details>
#
# 4. Why can the phase $\phi$ change the peak acceleration by a factor of six, when it only
#    changes how the gears were meshed?
#
# <details><summary>Answer</summary>
#
# Because it changes the linkage itself: at every input angle crank 5 points elsewhere, so C, the
# couplers' angles and their angular velocities are different. It is a different mechanism with
# the same parts, not the same motion shifted in time.
#
# </details>
#
# 5. What does $\lambda = 0$ turn the geared fivebar into?
#
# <details><summary>Answer</summary>
#
# A fourbar: crank 5 stays at $\phi$, so C is a fixed pivot (worked example 2 checks this).
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
assert Fraction(-2.5) == Fraction(-5, 2) and cycle_turns(-2.5) == 2
steady, doubled = (
    fivebar.solve(theta2="60 deg", omega2=w, alpha2=0) for w in ("20 rad/s", "40 rad/s")
)
stated(doubled.alpha3 / steady.alpha3, "4")
stated(abs(doubled.A_B) / abs(steady.A_B), "4")
stated(
    GearedFiveBar(**geometry, lam=-2, phi="30 deg")
    .solve(theta2="60 deg", omega2="20 rad/s", alpha2="10 rad/s^2")
    .alpha5,
    "-20",
    "rad/s^2",
)
# %% [markdown]
# **In motion.** Example 1's linkage ($\lambda = -2$, $\phi = 30^\circ$) through one input turn
# at a steady 20 rad/s: crank 5 turns twice, the other way, and the coupler pin B is whipped
# round twice. The arrows (one scale for the whole turn) are the accelerations of A, B and C;
# the marker runs along the curves of $\alpha_3$, $\alpha_4$ and the three sizes.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Animation: the geared fivebar ($\\lambda = -2$, $\\phi = 30^\\circ$) through one input turn at 20 rad/s with the accelerations of $A$, $B$ and $C$, and a marker on $\\alpha_3$, $\\alpha_4$ and the three sizes. Play, pause, step or drag the slider."}}
animate(
    {
        "mechanism": "fivebar",
        **geometry,
        "lam": -2,
        "phi": "30 deg",
        "theta2": "0 deg",
        "omega2": "20 rad/s",
        "alpha2": "0 rad/s^2",
    },
    title="Geared fivebar, $\\lambda$ = -2",
    alt="The geared fivebar turning, crank 5 twice as fast the other way, with acceleration "
    "arrows at A, B and C, beside plots of alpha3, alpha4 and the three sizes with a moving "
    "marker.",
)

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set; solve them with eqs. 7.28 and 7.29, then check
# with `GearedFiveBar`. The answers are folded.
#
# **Problem 6.1.** The linkage of example 1 ($a = d = 1.5$ in, $b = c = 4$ in, $f = 4$ in) with
# external gears of ratio $\lambda = -3$ meshed at $\phi = 0$. At $\theta_2 = 0$ the input
# turns at 15 rad/s and speeds up at 40 rad/s$^2$. Find $\theta_5$, $\alpha_5$, $\alpha_3$,
# $\alpha_4$ and $\mathbf{A}_B$.
#
# <details><summary>Answer</summary>
#
# $\theta_5 = \lambda\theta_2 + \phi = 0$, $\alpha_5 = \lambda\alpha_2 = -120$ rad/s$^2$;
# $\alpha_3 = 37.43$ and $\alpha_4 = -157.43$ rad/s$^2$; $\mathbf{A}_B$ = 2193 in/s$^2$ at
# $-132.4^\circ$.
#
# </details>
#
# **Problem 6.2.** How many input turns make one cycle for $\lambda = -2/3$, and how many
# turns does crank 5 make in it?
#
# <details><summary>Answer</summary>
#
# $-2/3$ in lowest terms: three input turns, during which crank 5 makes two (the other way).
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
r61 = GearedFiveBar(**geometry, lam=-3, phi="0 deg").solve(
    theta2="0 deg", omega2="15 rad/s", alpha2="40 rad/s^2"
)
stated(r61.theta5, "0", "deg")
stated(r61.alpha5, "-120", "rad/s^2")
stated(r61.alpha3, "37.43", "rad/s^2")
stated(r61.alpha4, "-157.43", "rad/s^2")
stated(abs(r61.A_B), "2193", "in/s^2")
stated(np.angle(r61.A_B.magnitude, deg=True), "-132.4")
assert cycle_turns(-2 / 3) == 3

# %% [markdown]
# ## Practice
#
# Geared fivebar problems with instant feedback, for self-study (not graded, and never one of
# a graded assignment's). Each run of the next cell draws a fresh linkage, or give a seed to
# come back to one; hand each answer to `mine.check`, which says at once whether it is right and,
# if not, what to look at (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `fivebar`.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("fivebar")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("alpha3", Q_(-410, "rad/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("fivebar", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5, modelled with `GearedFiveBar`:

# %%
example = practice("fivebar", seed=5, show=False)
g = example.given
model = GearedFiveBar(a=g["a"], b=g["b"], c=g["c"], d=g["d"], f=g["f"], lam=g["lam"], phi=g["phi"])
res = model.solve(theta2=g["theta2"], omega2=g["omega2"], alpha2=g["alpha2"], circuit=g["circuit"])
assert example.check("alpha3", res.alpha3)  # right
assert not example.check("alpha4", res.alpha3)  # link 3's, not link 4's
assert example.check("alpha4", res.alpha4)  # right

# %% [markdown]
# ## Common mistakes
#
# - **Plotting one input turn when $\lambda$ is not an integer.** The curve does not close and
#   the peaks of the other turns are missed; take $q$ turns for $\lambda = \pm p/q$.
# - **Forgetting $\alpha_5$.** When the input accelerates, crank 5 does too, $\lambda$ times as
#   much; dropping $d\alpha_5$ from eq. 7.28a is easy because it vanishes at steady speed.
# - **The sign of $\lambda$.** Two external gears turn opposite ways: $\lambda < 0$.
# - **Copying eq. 7.29e from the scan.** $\mathbf{A}_C$ uses crank 5's length $d$, not $c$.
# - **Assuming every phase assembles.** With other lengths some phases cannot close the loop at
#   some angles; the solver then marks those positions in `valid` (and a single position raises
#   `NotAssemblable`). Check `valid` before reading peaks.
#
# [Next: 7. The acceleration of any point](07_any_point.ipynb)
