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
# # 5. Coriolis acceleration
#
# So far every point we followed was fixed on its link. This notebook lets a point *slide along
# a link that turns*, and a fourth term appears in its acceleration. It follows the chapter's
# treatment of the Coriolis component and of the inverted slider-crank (Robert L. Norton,
# *Design of Machinery*, chapter 7, section 7.3: eqs. 7.17 to 7.27, Figures 7-7 and 7-8).
#
# **You will be able to**
#
# - split the acceleration of a point that slides on a rotating link into its tangential,
#   normal, Coriolis and slip parts (eq. 7.19), with the direction of each;
# - explain, with numbers, what a person walking across a turning roundabout feels;
# - solve the inverted slider-crank (eqs. 7.20-7.27) and read its Coriolis term from the
#   solver;
# - say how wrong a graphical solution becomes when it forgets the Coriolis component, over a
#   whole cycle.

# %% [markdown]
# ## The idea and its equations
#
# A block P slides in a radial slot of a link that turns about the origin (the chapter's
# Figure 7-7). Both the *length* and the *angle* of its position vector change with time:
#
# $$ \mathbf{R}_P = p\,e^{j\theta_2} \tag{7.17} $$
#
# Differentiating the product gives two velocity terms: the **transmission** part, the speed
# the link would give a point fixed at radius $p$, and the **slip** part along the slot:
#
# $$ \mathbf{V}_P = p\,\omega_2\,j e^{j\theta_2} + \dot p\, e^{j\theta_2} \tag{7.18a} $$
#
# $$ \mathbf{V}_P = \mathbf{V}_{P_{trans}} + \mathbf{V}_{P_{slip}} \tag{7.18b} $$
#
# Differentiate once more. The transmission term holds three functions of time ($p$,
# $\omega_2$, $\theta_2$) and the slip term two ($\dot p$, $\theta_2$), so the chain rule gives
# five terms:
#
# $$ \begin{aligned} \mathbf{A}_P = {} & \left(p\alpha_2 j e^{j\theta_2}
#    - p\omega_2^2 e^{j\theta_2}\right. \\
#    & \left. + \dot p\,\omega_2 j e^{j\theta_2}\right) \\
#    & + \left(\dot p\,\omega_2 j e^{j\theta_2} + \ddot p\, e^{j\theta_2}\right)
#    \end{aligned} \tag{7.19a} $$
#
# Two of them are the same, $\dot p\,\omega_2 j e^{j\theta_2}$: one because the transmission
# speed $p\omega_2$ grows as the block moves out, the other because the slip velocity turns
# with the link. Together they make the Coriolis term:
#
# $$ \begin{aligned} \mathbf{A}_P = {} & p\alpha_2 j e^{j\theta_2} - p\omega_2^2 e^{j\theta_2} \\
#    & + 2\dot p\,\omega_2 j e^{j\theta_2} + \ddot p\, e^{j\theta_2} \end{aligned} \tag{7.19b} $$
#
# $$ \begin{aligned} \mathbf{A}_P = {} & \mathbf{A}_{P_{tangential}} + \mathbf{A}_{P_{normal}} \\
#    & + \mathbf{A}_{P_{coriolis}} + \mathbf{A}_{P_{slip}} \end{aligned} \tag{7.19c} $$
#
# | part | size | direction |
# |---|---|---|
# | tangential | $p\,\alpha_2$ | perpendicular to the slot, in the sense of $\alpha_2$ |
# | normal | $p\,\omega_2^2$ | along the slot, toward the pivot |
# | **Coriolis** | $2\,\dot p\,\omega_2$ | perpendicular to the slot: $\mathbf{V}_{slip}$ turned 90° in the sense of $\omega_2$ |
# | slip | $\ddot p$ | along the slot |
#
# The Coriolis part needs *both* a slip velocity and a turning slot. A pin joint has no slip;
# the slider of an ordinary slider-crank slips along the ground, which does not turn. So
# neither has a Coriolis term, and the inverted slider-crank, whose block slides on a turning
# link, does.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import matplotlib.pyplot as plt
import numpy as np

from accelab.course.animation import animate
from accelab.course.kit import COLORS, LINESTYLES, explore, in_g, stated, use_style, vector
from accelab.course.practice import practice
from accelab.course.renditions import legend, panels, show
from accelab.course.text import num, say, table
from accelab.solver import Q_, InvertedSliderCrank, SlottedLink
from accelab.solver.graphical import Arrow, Construction, Line, Step, invertedslidercrank, slotted
from accelab.solver.graphical.draw import draw_linkage, draw_polygon
from accelab.solver.graphical.geometry import intersect_lines

use_style()

#: how the parts of an acceleration are written in the tables
PARTS = {
    "A_t": r"tangential $\mathbf{A}^t$",
    "A_n": r"normal $\mathbf{A}^n$",
    "A_coriolis": r"Coriolis $\mathbf{A}_{coriolis}$",
    "A_slip": r"slip $\mathbf{A}_{slip}$",
    "A": r"total $\mathbf{A}_P$",
    "A_A": r"$\mathbf{A}_A$",
    "A_B": r"$\mathbf{A}_B$",
}


def sizes(result, names):
    """A table: each vector's size in m/s² and in/s², and its direction."""
    table(
        ["", "size [m/s²]", "size [in/s²]", "direction"],
        [
            [
                PARTS.get(k, k),
                num(abs(getattr(result, k)).m_as("m/s^2")),
                num(abs(getattr(result, k)).m_as("in/s^2")),
                f"{num(np.angle(getattr(result, k).m_as('m/s^2'), deg=True), decimals=1)}°",
            ]
            for k in names
        ],
    )


# %% [markdown]
# ## Worked examples
#
# ### 1. A block in a turning slot (Figure 7-7)
#
# As in the chapter's figure, the link turns clockwise but is being slowed down:
# $\omega_2 < 0$ and $\alpha_2 > 0$. The block is 250 mm from the pivot and slides outward at
# 1.5 m/s while the slip itself slows at 3 m/s².

# %%
slot = SlottedLink()
inputs = dict(
    theta2="30 deg",
    omega2="-4 rad/s",
    alpha2="15 rad/s^2",
    p="250 mm",
    p_dot="1.5 m/s",
    p_ddot="-3 m/s^2",
)
r = slot.solve(**inputs)
sizes(r, ("A_t", "A_n", "A_coriolis", "A_slip", "A"))

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
parts = {k: abs(getattr(r, k)).m_as("m/s^2") for k in ("A_t", "A_n", "A_coriolis", "A_slip")}
stated(parts["A_coriolis"], "12")
stated(parts["A_coriolis"] / parts["A_n"], "3")
assert max(parts, key=parts.get) == "A_coriolis"

# %% [markdown]
# The Coriolis part, 12 m/s², is the largest of the four: three times the centripetal part. A
# turning slot with a fast slip is exactly where a hand analysis must not drop it.
#
# The next cell writes eq. 7.19's Coriolis term out by hand and checks it against the solver,
# then checks that the four parts add up to the total (eq. 7.19c).

# %%
theta, omega = Q_(30, "deg").to("rad").magnitude, -4.0
p_dot = 1.5
by_hand = 2 * p_dot * omega * 1j * np.exp(1j * theta)  # 2 p' omega j e^{j theta}, m/s^2
assert np.isclose(by_hand, r.A_coriolis.to("m/s^2").magnitude, rtol=1e-12)
parts = r.A_t + r.A_n + r.A_coriolis + r.A_slip
assert np.isclose(parts.to("m/s^2").magnitude, r.A.to("m/s^2").magnitude, rtol=1e-12)
# direction: V_slip turned 90 deg in the sense of omega (clockwise here)
turned = np.angle(r.A_coriolis.magnitude / r.V_slip.magnitude, deg=True)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"The Coriolis part is $\mathbf{{V}}_{{slip}}$ turned by {num(turned, decimals=0)}°: "
    r"clockwise, the sense of $\omega_2 < 0$."
)

# %% [markdown]
# `accelab.solver.graphical` draws the same four parts at the block and adds them tip to
# tail; the resultant closes the polygon (the chapter's Figure 7-7b and c). The block's motion
# is given here, so no construction lines are needed: every part is known in size and
# direction.

# %%
con = slotted.construct(theta2=theta, omega2=omega, alpha2=15.0, p=0.25, p_dot=1.5, p_ddot=-3.0)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "A block sliding in a turning slot (Figure 7-7): the tangential, normal, Coriolis and slip parts of its acceleration at the block, and added tip to tail."}}
def figure_7_7(narrow):
    fig, (ax1, ax2) = panels(
        2, narrow, wide=(7.8, 4.0), tall=(4.4, 8.4), width_ratios=[1.2, 1], layout="constrained"
    )
    draw_linkage(con, ax=ax1, legend=False)
    draw_polygon(con, "acceleration", ax=ax2, legend=False)
    legend(
        fig,
        ("tangential", "normal", "coriolis", "slip", "resultant"),
        ncol=2 if narrow else 5,
        loc="outside lower center",
    )
    return fig


show(
    figure_7_7,
    alt="Slotted link with the block and four acceleration arrows: tangential, normal, "
    "Coriolis and slip, and the same four added tip to tail.",
)

# %% [markdown]
# ### 2. Walking across a turning roundabout
#
# The chapter's everyday Coriolis example: walk straight toward the centre of a turning
# carousel and you are pushed sideways. You are the block of Figure 7-7 and the floor is the
# slotted link.
#
# Take a playground roundabout of radius 1.8 m turning counter-clockwise at 12 rpm, and a
# child who walks from the rim to the centre at a steady 0.6 m/s along a radial line painted
# on the floor. Her distance from the centre is $p(t) = 1.8\ \text{m} - 0.6\ \text{m/s}\cdot t$,
# so $\dot p = -0.6$ m/s and $\ddot p = 0$, while the floor turns with
# $\theta_2 = \omega_2 t$.

# %%
R_rim, v_walk = Q_(1.8, "m"), Q_(0.6, "m/s")
omega_ride = Q_(12, "rpm").to("rad/s")
t = np.linspace(0, (R_rim / v_walk).to("s").magnitude, 61) * Q_(1, "s")
walk = slot.solve(
    theta2=(omega_ride * t).to("rad"),
    omega2=omega_ride,
    alpha2=0,
    p=R_rim - v_walk * t,
    p_dot=-v_walk,
    p_ddot=0,
)
m_child = Q_(30, "kg")

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"The walk lasts {num(t[-1].m_as('s'), 2)} s while the floor turns "
    f"{num((omega_ride * t[-1]).m_as('turn'), 2)} of a turn. The Coriolis part is "
    f"{num(abs(walk.A_coriolis[0]).m_as('m/s^2'), 3)} m/s² "
    f"({num(in_g(walk.A_coriolis[0]), 2)} g) all the way, whatever $p$ is; the centripetal "
    f"part is {num(abs(walk.A_n[0]).m_as('m/s^2'), 3)} m/s² ({num(in_g(walk.A_n[0]), 2)} g) "
    "at the rim and falls to zero at the centre. The floor must push a "
    f"{num(m_child.m_as('kg'), decimals=0)} kg child sideways with "
    f"{num((m_child * abs(walk.A_coriolis[0])).m_as('N'), 2)} N."
)

# %% [markdown]
# Which way is "sideways"? The Coriolis part is the slip velocity (inward) turned 90° in the
# sense of $\omega_2$ (counter-clockwise), so it points *against* the rotation: walking
# inward, her speed around the centre must drop from $R\omega_2$ to zero, and the floor,
# through friction at her feet, has to take it away. What she **feels** is the opposite of what
# the floor does to her: a shove *forward, in the direction the roundabout turns*. Walking
# outward reverses both.
#
# The figure draws her path over the ground (a spiral, although she walks a straight line on
# the floor) with the two parts of her acceleration at a few instants.

# %%
R = walk.R.to("m").magnitude
A_cor = walk.A_coriolis.to("m/s^2").magnitude
A_n = walk.A_n.to("m/s^2").magnitude


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "A walk across a turning roundabout: her path over the ground with the Coriolis and centripetal parts of her acceleration at a few instants, and the size of each part during the walk."}}
def roundabout(narrow):
    fig, (ax1, ax2) = panels(
        2, narrow, wide=(7.8, 3.9), tall=(4.4, 8.4), width_ratios=[1, 1.1], layout="constrained"
    )
    rim = R_rim.magnitude * np.exp(1j * np.linspace(0, 2 * np.pi, 200))
    ax1.plot(rim.real, rim.imag, color="#888888", lw=1)
    ax1.plot(R.real, R.imag, color="black", lw=1.5)
    scale = 0.3  # m of drawing per m/s^2
    for i in range(0, 61, 12):
        vector(ax1, R[i], A_cor[i], "coriolis", scale=scale)
        vector(ax1, R[i], A_n[i], "normal", scale=scale)
        ax1.plot(
            [0, R[i].real * 1.8 / max(abs(R[i]), 1e-9)],
            [0, R[i].imag * 1.8 / max(abs(R[i]), 1e-9)],
            color="#bbbbbb",
            lw=0.8,
            ls=":",
        )
    ax1.annotate(
        "",
        xy=(1.35, 1.35),
        xytext=(1.85, 0.55),
        arrowprops=dict(arrowstyle="->", connectionstyle="arc3,rad=0.3", color="#555555"),
    )
    ax1.text(1.75, 1.15, r"$\omega_2$", fontsize=12, color="#555555")
    ax1.set_aspect("equal")
    ax1.set_xlabel("x [m]")
    ax1.set_ylabel("y [m]")
    ax1.set_title("Top view (1 m of arrow = 3.3 m/s²)")
    fig.legend(
        handles=[
            plt.Line2D([], [], color="black", label="her path (ground)"),
            plt.Line2D([], [], color="#bbbbbb", ls=":", label="her line, then"),
            plt.Line2D(
                [], [], color=COLORS["coriolis"], ls=LINESTYLES["coriolis"], label="Coriolis"
            ),
            plt.Line2D([], [], color=COLORS["normal"], label="normal"),
        ],
        loc="outside lower center",
        ncol=2,
        frameon=False,
    )
    radius = abs(R)
    ax2.plot(
        radius,
        in_g(walk.A_coriolis),
        color=COLORS["coriolis"],
        ls=LINESTYLES["coriolis"],
        lw=2,
        label=r"Coriolis $2\dot p\omega_2$",
    )
    ax2.plot(radius, in_g(walk.A_n), color=COLORS["normal"], lw=2, label=r"normal $p\omega_2^2$")
    ax2.plot(radius, in_g(walk.A), color="black", lw=2.4, label=r"total $|\mathbf{A}_P|$")
    ax2.invert_xaxis()
    ax2.set_xlabel("her distance from the centre $p$ [m]")
    ax2.set_ylabel("acceleration [g]")
    ax2.set_ylim(bottom=0)
    ax2.legend()
    ax2.set_title("Size of each part (she walks left to right)")
    return fig


show(
    roundabout,
    alt="A curved path seen from above with acceleration arrows, and line plots of the "
    "Coriolis and centripetal parts against her distance from the centre.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(in_g(walk.A_coriolis[0]), "0.15")
assert np.ptp(in_g(walk.A_coriolis)) < 1e-12  # the same all the way

# %% [markdown]
# At the rim the floor must supply both parts; near the centre only the Coriolis part is left,
# and it is as large there as anywhere. About 0.15 g sideways is well below the 0.5 g of hard
# acceleration in a car (the chapter's Table 7-1, notebook 8), but it arrives *sideways* and
# unexpectedly, which is why children stumble.
#
# ### 3. The inverted slider-crank (eqs. 7.20-7.27)
#
# Link 4 turns about $O_4$ and carries a slide; the block 3, pinned to the crank at A, slides
# on it. The length $b$ from B to A varies, so the vector loop
#
# $$ \begin{aligned} & a e^{j\theta_2} - b e^{j\theta_3} \\
#    & - c e^{j\theta_4} - d e^{j\theta_1} = 0 \end{aligned} $$
#
# differentiated twice with $a, c, d$ constant and $b$ varying, gives
#
# $$ \begin{aligned}
#    & a\alpha_2 je^{j\theta_2} - a\omega_2^2 e^{j\theta_2} \\
#    & - b\alpha_3 je^{j\theta_3} + b\omega_3^2 e^{j\theta_3} \\
#    & - 2\dot b\omega_3 je^{j\theta_3} - \ddot b e^{j\theta_3} \\
#    & - c\alpha_4 je^{j\theta_4} + c\omega_4^2 e^{j\theta_4} = 0
#    \end{aligned} \tag{7.20b} $$
#
# which is the acceleration difference equation between A and B, with the slide's two extra
# parts inside $\mathbf{A}_{AB} = \mathbf{A}_A - \mathbf{A}_B$:
#
# $$ \mathbf{A}_A - \mathbf{A}_{AB} - \mathbf{A}_B = 0 \tag{7.21} $$
#
# $$ \begin{aligned} \mathbf{A}_{AB} = {} & \mathbf{A}_{AB_{tangential}} \\
#    & + \mathbf{A}_{AB_{normal}} \\
#    & + \mathbf{A}_{AB_{coriolis}} \\
#    & + \mathbf{A}_{AB_{slip}} \end{aligned} $$
#
# with $\mathbf{A}_{AB_{coriolis}} = 2\dot b\,\omega_3\, j e^{j\theta_3}$ and
# $\mathbf{A}_{AB_{slip}} = \ddot b\, e^{j\theta_3}$. The block cannot turn on the slide, so
# $\theta_3 = \theta_4 + \gamma$ and
#
# $$ \omega_3 = \omega_4, \qquad \alpha_3 = \alpha_4 \tag{7.22} $$
#
# That leaves two unknowns, $\alpha_4$ and $\ddot b$, in the two scalar parts of eq. 7.20b.
# Solving them simultaneously, with $q = b + c\cos(\theta_3 - \theta_4)$ for the denominator
# they share:
#
# $$ \begin{aligned} q\,\alpha_4 = {} & a\alpha_2\cos(\theta_3-\theta_2) \\
#    & + a\omega_2^2\sin(\theta_3-\theta_2) \\
#    & + c\omega_4^2\sin(\theta_4-\theta_3) \\
#    & - 2\dot b\,\omega_3 \end{aligned} \tag{7.26a} $$
#
# $$ q\,\ddot b = -N \tag{7.26b} $$
#
# $$ \begin{aligned} N = {} & a\omega_2^2\left[b\cos(\theta_3-\theta_2)\right. \\
#    & \qquad \left. + c\cos(\theta_4-\theta_2)\right] \\
#    & + a\alpha_2\left[b\sin(\theta_2-\theta_3)\right. \\
#    & \qquad \left. - c\sin(\theta_4-\theta_2)\right] \\
#    & + 2\dot b\,c\,\omega_4\sin(\theta_4-\theta_3) \\
#    & - \omega_4^2\left[b^2 + c^2\right. \\
#    & \qquad \left. + 2bc\cos(\theta_4-\theta_3)\right] \end{aligned} $$
#
# (The scanned chapter prints $\sin(\theta_4 + \theta_2)$ in eq. 7.26b; the sum is a misprint,
# the cell below shows that only the difference agrees with the solver.) The denominator
# vanishes where $q = 0$: the slide is then perpendicular to $O_4A$ and the equations are
# singular, a limit position. Putting $\alpha_4$ and $\ddot b$ back into eqs. 7.21 gives the
# pins' accelerations (the chapter's eqs. 7.27); the solver reports them as `A_A`, `A_B`,
# `A_BA`, and the Coriolis term alone as `A_coriolis`.
#
# (Two more slips of the scan, both lost dots on $b$. The Coriolis term of eq. 7.24a, the
# loop written out with $j(\cos\theta + j\sin\theta)$, prints as $-2b\omega_3 j(\ldots)$: it
# is $-2\dot b\omega_3 j(\ldots)$, as eq. 7.20b above and the next line, eq. 7.24b, have it.
# And eq. 7.27b, $\mathbf{A}_{BA}$ in cartesian form, prints its last two terms as
# $2b\omega_3(\sin\theta_3 - j\cos\theta_3)$ and $-b(\cos\theta_3 + j\sin\theta_3)$: they are
# $2\dot b\omega_3(\ldots)$ and $\ddot b(\ldots)$, the Coriolis and slip terms of eq. 7.21
# with the sign of $\mathbf{A}_{BA} = -\mathbf{A}_{AB}$. Without the dots neither term has the
# dimension of an acceleration. The cell below checks the corrected eq. 7.27b.)
#
# Our linkage: crank $a$ = 4 in, $O_4B$ = $c$ = 3 in, ground $d$ = 8 in, slide at
# $\gamma$ = 90° to $O_4B$. The crank turns clockwise and is being slowed down, as in the
# chapter's Figure 7-8.

# %%
isc = InvertedSliderCrank(a="4 in", c="3 in", d="8 in", gamma="90 deg")
r = isc.solve(theta2="60 deg", omega2="-10 rad/s", alpha2="25 rad/s^2")

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "value"],
    [
        [r"$\theta_3$, $\theta_4$", f"{num(r.theta3.m_as('deg'))}°, {num(r.theta4.m_as('deg'))}°"],
        [r"$b$, $\dot b$", f"{num(r.b.m_as('in'))} in, {num(r.b_dot.m_as('in/s'))} in/s"],
        [r"$\omega_3 = \omega_4$", f"{num(r.omega4)} rad/s"],
        [r"$\alpha_3 = \alpha_4$", f"{num(r.alpha4)} rad/s²"],
        [r"$\ddot b$", f"{num(r.b_ddot.m_as('in/s^2'))} in/s²"],
    ],
)
sizes(r, ("A_A", "A_B", "A_coriolis", "A_slip"))

# %% [markdown]
# The next cell evaluates eqs. 7.26a and 7.26b as written above, and the chapter's misprinted
# 7.26b, against the solver, then checks eq. 7.21: A minus B is the turning, sliding vector
# $b e^{j\theta_3}$ differentiated twice, Coriolis and slip included.

# %%
a, c = 4.0, 3.0  # in
t2, w2, al2 = np.radians(60), -10.0, 25.0
t3, t4 = r.theta3.magnitude, r.theta4.magnitude
w3 = w4 = r.omega4.magnitude
b, bd = r.b.to("in").magnitude, r.b_dot.to("in/s").magnitude
q = b + c * np.cos(t3 - t4)
alpha4 = (
    a * (al2 * np.cos(t3 - t2) + w2**2 * np.sin(t3 - t2))
    + c * w4**2 * np.sin(t4 - t3)
    - 2 * bd * w3
) / q  # eq. 7.26a


def b_ddot(sign):  # sign = -1: eq. 7.26b as corrected; +1: as printed
    N = (
        a * w2**2 * (b * np.cos(t3 - t2) + c * np.cos(t4 - t2))
        + a * al2 * (b * np.sin(t2 - t3) - c * np.sin(t4 + sign * t2))
        + 2 * bd * c * w4 * np.sin(t4 - t3)
        - w4**2 * (b * b + c * c + 2 * b * c * np.cos(t4 - t3))
    )
    return -N / q


solver_bdd = r.b_ddot.to("in/s^2").magnitude
assert np.isclose(alpha4, r.alpha4.magnitude, rtol=1e-12)
assert np.isclose(b_ddot(-1), solver_bdd, rtol=1e-12)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"Eq. 7.26a gives $\alpha_4$ = {num(alpha4, 7)} rad/s²; eq. 7.26b gives $\ddot b$ = "
    f"{num(b_ddot(-1), 7)} in/s², as the solver does ({num(solver_bdd, 7)}). The misprinted "
    f"eq. 7.26b would give {num(b_ddot(+1), 7)} in/s²."
)
e3 = np.exp(1j * t3)
bdd = solver_bdd
A_AB = (b * (1j * r.alpha3.magnitude - w3**2) + 2j * bd * w3 + bdd) * e3  # eq. 7.21, in/s^2
assert np.isclose(A_AB, (r.A_A - r.A_B).to("in/s^2").magnitude, rtol=1e-12)
# the solver also splits A_A into the point of link 4 under A, the slip and the Coriolis parts
assert np.isclose((r.A_A4 + r.A_slip + r.A_coriolis - r.A_A).to("in/s^2").magnitude, 0, atol=1e-9)
# eq. 7.27b with its dots restored: A_BA in cartesian form
s3, c3 = np.sin(t3), np.cos(t3)
A_BA_727b = (
    b * r.alpha3.magnitude * (s3 - 1j * c3)
    + b * w3**2 * (c3 + 1j * s3)
    + 2 * bd * w3 * (s3 - 1j * c3)
    - bdd * (c3 + 1j * s3)
)
assert np.isclose(A_BA_727b, r.A_BA.to("in/s^2").magnitude, rtol=1e-12)

# %% [markdown]
# The graphical construction of `accelab.solver.graphical` does the same analysis by geometry
# alone (it never calls the analytic solver). Its polygon has *two* unknown lengths:
# $\mathbf{A}_{slip}$ along the slide (line rr) and the tangential acceleration of the point
# $A_4$ of link 4 under A, perpendicular to $O_4A$ (line pp). The Coriolis vector is known in
# size and direction from the velocity analysis and sits between them.

# %%
a_m, c_m, d_m = (Q_(x, "in").to("m").magnitude for x in (4, 3, 8))
con = invertedslidercrank.construct(
    a=a_m, c=c_m, d=d_m, gamma=np.pi / 2, theta2=t2, omega2=w2, alpha2=al2
)
assert np.isclose(con.values["alpha4"], r.alpha4.magnitude, rtol=1e-9)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The inverted slider-crank and its acceleration polygon, with the Coriolis component included (inches and in/s²)."}}
def figure_7_8(narrow):
    fig, (ax1, ax2) = panels(
        2, narrow, wide=(7.8, 4.2), tall=(4.4, 8.8), width_ratios=[1.3, 1], layout="constrained"
    )
    draw_linkage(con, ax=ax1, units="US", legend=False)  # the linkage was given in inches
    draw_polygon(con, "acceleration", ax=ax2, units="US", legend=False)
    legend(
        fig,
        ("tangential", "normal", "coriolis", "slip", "resultant"),
        lines=True,
        ncol=2 if narrow else 3,
        loc="outside lower center",
    )
    return fig


show(figure_7_8, alt="Inverted slider-crank linkage beside its acceleration polygon.")

# %% [markdown]
# ### 4. What a graphical solution gets wrong without the Coriolis component
#
# Suppose a student draws the polygon above but forgets the Coriolis vector. The polygon
# still closes: lines rr and pp still cross somewhere, and a plausible-looking $\alpha_4$ and
# $\ddot b$ come out. Nothing on the drawing warns that they are wrong.
#
# The cell below redoes the last step of the construction with the same drafting operation
# (`intersect_lines`), but with rr drawn through the tip of $\mathbf{A}^n_{A_4}$ instead of
# the tip of $\mathbf{A}^n_{A_4} + \mathbf{A}_{coriolis}$. This is the wrong method on
# purpose; the solver never does it.


# %%
def forgetful(con):
    """(alpha4, b_ddot, X) from the construction's polygon closed WITHOUT the Coriolis vector."""
    v = con.values
    e3 = np.exp(1j * v["theta3"])
    radius = v["R_A"] - d_m  # O4 -> A (theta1 = 0)
    X, b_dd, t = intersect_lines(v["A_A4_n"], e3, v["A_A"], 1j * radius)
    return -t, b_dd, X


wrong_alpha4, wrong_bdd, X = forgetful(con)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "right", "Coriolis forgotten"],
    [
        [r"$\alpha_4$ [rad/s²]", num(con.values["alpha4"]), num(wrong_alpha4)],
        [r"$\ddot b$ [m/s²]", num(con.values["b_ddot"]), num(wrong_bdd)],
    ],
)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
v = con.values
wrong = Construction(
    "invertedslidercrank",
    con.linkage,
    [],
    {},
    "open",
    title="Polygon closed without the Coriolis vector",
)
step = Step("6", "acceleration", "the same polygon without A_coriolis")
e3 = np.exp(1j * v["theta3"])
pp = 1j * (v["R_A"] - d_m)
step.arrows += [
    Arrow(r"\mathbf{A}_{A}^{t}", 0j, v["A_A_t"], "tangential", "acceleration"),
    Arrow(r"\mathbf{A}_{A}^{n}", v["A_A_t"], v["A_A_n"], "normal", "acceleration"),
    Arrow(r"\mathbf{A}_{A_4}^{n}", 0j, v["A_A4_n"], "normal", "acceleration"),
    Arrow(r"\mathbf{A}_{slip}?", v["A_A4_n"], X - v["A_A4_n"], "slip", "acceleration"),
    Arrow(r"\mathbf{A}_{A_4}^{t}?", X, v["A_A"] - X, "tangential", "acceleration"),
    Arrow(r"\mathbf{A}_{A}", 0j, v["A_A"], "resultant", "acceleration"),
]
step.lines += [
    Line("rr", v["A_A4_n"], e3, "acceleration"),
    Line("pp", v["A_A"], pp, "acceleration"),
]
wrong.steps.append(step)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The acceleration polygon with the Coriolis vector (right) and without it (wrong), at one scale: the wrong polygon still closes."}}
def both_polygons(narrow):
    fig, axes = panels(2, narrow, wide=(7.8, 4.0), tall=(4.4, 8.4), layout="constrained")
    # one frame, so one scale, for both polygons [in/s^2]
    ends = [0j] + [
        z / 0.0254
        for c in (con, wrong)
        for a in c.items("acceleration")[0]
        for z in (a.start, a.start + a.vector)
    ]
    pad = 0.08 * max(np.ptp([z.real for z in ends]), np.ptp([z.imag for z in ends]))
    box = (
        min(z.real for z in ends) - pad,
        max(z.real for z in ends) + pad,
        min(z.imag for z in ends) - pad,
        max(z.imag for z in ends) + pad,
    )
    draw_polygon(con, "acceleration", ax=axes[0], units="US", legend=False, box=box)
    axes[0].set_title("Right: with the Coriolis vector")
    draw_polygon(wrong, "acceleration", ax=axes[1], units="US", legend=False, box=box)
    axes[1].set_title("Wrong: Coriolis forgotten\n(the polygon still closes)")
    legend(
        fig,
        ("tangential", "normal", "coriolis", "slip", "resultant"),
        lines=True,
        ncol=2 if narrow else 3,
        loc="outside lower center",
    )
    return fig


show(
    both_polygons,
    alt="Two acceleration polygons of the same position, one including the Coriolis vector "
    "and one leaving it out.",
)

# %% [markdown]
# One position can be a coincidence. Over a whole crank turn at a steady 10 rad/s we compare
# the right $\alpha_4$ (from the solver, a vectorized call) with the forgetful construction at
# every 2°.

# %%
theta_cycle = np.radians(np.arange(0, 360, 2.0))
cycle = isc.solve(theta2=Q_(theta_cycle, "rad"), omega2="10 rad/s", alpha2=0)
assert cycle.valid.all()
forgot = np.array(
    [
        forgetful(invertedslidercrank.construct(a_m, c_m, d_m, np.pi / 2, th, 10.0, 0.0))[:2]
        for th in theta_cycle
    ]
)
right_a4 = cycle.alpha4.magnitude
err = forgot[:, 0] - right_a4
deg = np.degrees(theta_cycle)
worst = np.argmax(np.abs(err))

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"The largest error in $\alpha_4$ is {num(err[worst], 3)} rad/s² at "
    rf"$\theta_2$ = {num(deg[worst], decimals=0)}°, "
    f"{num(100 * abs(err[worst]) / np.abs(right_a4).max(), 2)} % of the largest "
    rf"$|\alpha_4|$ of the cycle. The Coriolis term reaches "
    f"{num(np.abs(cycle.A_coriolis.m_as('m/s^2')).max(), 3)} m/s², while "
    rf"$|\mathbf{{A}}_A|$ is {num(abs(cycle.A_A[0].m_as('m/s^2')), 3)} m/s² all the time."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Over a whole cycle at 10 rad/s: the angular acceleration of link 4 with and without the Coriolis term, and the forgotten term beside the error it makes in the slip acceleration $\\ddot b$."}}
def over_the_cycle(narrow):
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.8, 3.6), tall=(4.4, 7.2), layout="constrained")
    ax1.plot(deg, right_a4, color="black", lw=2, label="right (solver)")
    ax1.plot(
        deg, forgot[:, 0], color=COLORS["tangential"], lw=2, ls="--", label="Coriolis forgotten"
    )
    ax1.set_ylabel(r"$\alpha_4$ [rad/s$^2$]")
    ax1.set_title(r"Angular acceleration of link 4")
    ax1.legend()
    ax2.plot(
        deg,
        np.abs(cycle.A_coriolis.to("m/s^2").magnitude),
        color=COLORS["coriolis"],
        lw=2,
        ls=LINESTYLES["coriolis"],
        label=r"$|\mathbf{A}_{coriolis}|$, forgotten",
    )
    ax2.plot(
        deg,
        np.abs(forgot[:, 1] - cycle.b_ddot.to("m/s^2").magnitude),
        color=COLORS["slip"],
        lw=2,
        ls=LINESTYLES["slip"],
        label=r"error in $\ddot b$",
    )
    ax2.set_ylabel(r"acceleration [m/s$^2$]")
    ax2.set_title("The forgotten term and its error")
    ax2.legend()
    for ax in (ax1, ax2):
        ax.set_xlabel(r"crank angle $\theta_2$ [deg]")
        ax.set_xticks(range(0, 361, 90))
    return fig


show(
    over_the_cycle,
    alt="Line plots of alpha4 against crank angle for the right and the wrong construction, "
    "and of the forgotten term and the error it makes.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
cor_max = np.abs(cycle.A_coriolis.to("m/s^2").magnitude).max()
pin = abs(cycle.A_A[0].to("m/s^2").magnitude)
stated(cor_max, "21")
stated(pin, "10")
stated(cor_max / pin, "2")
assert np.abs(err).max() >= 0.9 * np.abs(right_a4).max()  # "as much as its own largest value"

# %% [markdown]
# The forgotten Coriolis term is not a small correction: for this linkage it reaches twice the
# crank pin's own acceleration (21 against 10 m/s²), and the angular acceleration of link 4
# comes out wrong by as much as its own largest value. The error vanishes only where the
# Coriolis term does: where the block momentarily stops sliding ($\dot b = 0$, at the ends of
# its travel) or link 4 momentarily stops turning ($\omega_4 = 0$, at its extreme angles).
#
# **In motion.** The linkage through one crank turn at a steady 10 rad/s, with the
# accelerations of A and B and the Coriolis component at A (one arrow scale for the whole
# turn), and a marker on the curves of $\alpha_4$ and of the three sizes: watch the green
# Coriolis arrow vanish twice as the block stops on the slide, and twice as link 4 stops.
# Step through those four positions with the player's buttons.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Animation: the inverted slider-crank through one turn at 10 rad/s with the accelerations of $A$ and $B$ and the Coriolis component at $A$, and a marker on $\\alpha_4$ and the three sizes. Play, pause, step or drag the slider."}}
animate(
    {
        "mechanism": "invertedslidercrank",
        "a": "4 in",
        "c": "3 in",
        "d": "8 in",
        "gamma": "90 deg",
        "theta2": "0 deg",
        "omega2": "10 rad/s",
        "alpha2": "0 rad/s^2",
    },
    kinds=("resultant", "coriolis"),
    title="Inverted slider-crank",
    alt="The inverted slider-crank turning, with acceleration arrows at A and B and a green "
    "Coriolis arrow, beside plots of alpha4 and the sizes with a moving marker.",
)

# %% [markdown]
# ## Explore
#
# Move the crank and watch the acceleration of A with its Coriolis and slip parts (the other
# parts are left out, to keep the drawing clear). The Coriolis vector (green,
# dash-dot) is always perpendicular to the slide; it shrinks to nearly nothing where the block
# reverses along the slide ($\dot b = 0$) or link 4 reverses ($\omega_4 = 0$), as at 85°, and it
# grows with the square of the crank speed, like the other parts. Every position is drawn in
# one frame at one scale (in/s$^2$, set for 10 rad/s).

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The inverted slider-crank at four crank angles $\\theta_2$, in one frame and at one scale: the Coriolis component at $A$ nearly vanishes at $85^\\circ$."}}
frames = [
    invertedslidercrank.construct(a_m, c_m, d_m, np.pi / 2, t, 10.0, 0.0)
    for t in np.radians(np.arange(0, 360, 10))
]
KINDS = ("resultant", "coriolis", "slip")
shown = [a for f in frames for a in f.items("linkage")[0] if a.kind in KINDS]
big = max(abs(a.vector) for a in shown) / 0.0254  # in/s^2
SCALE = 4.0 / big  # the longest arrow at 10 rad/s: 4 in
ends = [z / 0.0254 for f in frames for z in f.linkage.points.values()]
ends += [a.start / 0.0254 + SCALE * a.vector / 0.0254 for a in shown]
BOX = (
    min(z.real for z in ends) - 0.5,
    max(z.real for z in ends) + 0.5,
    min(z.imag for z in ends) - 0.5,
    max(z.imag for z in ends) + 0.5,
)
at85 = invertedslidercrank.construct(a_m, c_m, d_m, np.pi / 2, np.radians(85), 10.0, 0.0)
assert abs(at85.values["A_coriolis"]) < 0.02 * cor_max  # "nearly nothing" at 85 deg


def draw(theta2=60, omega2=10):
    con = invertedslidercrank.construct(a_m, c_m, d_m, np.pi / 2, np.radians(theta2), omega2, 0.0)
    v = con.values
    fig, ax = plt.subplots(figsize=(4.4, 4.6))
    draw_linkage(
        con,
        ax=ax,
        units="US",
        scale=SCALE,
        box=BOX,
        legend=False,
        lines=False,
        kinds=KINDS,
        title=rf"$|\mathbf{{A}}_{{cor}}|$ = {abs(v['A_coriolis']) / 0.0254:.0f} in/s$^2$"
        f"\n($\\dot b$ = {v['b_dot'] / 0.0254:.1f} in/s, "
        f"$\\omega_4$ = {v['omega4']:.2f} rad/s)",
    )
    ax.title.set_fontsize(10)
    return fig


explore(
    draw, theta2=(0, 360, 5, 60, "deg"), omega2=(1, 20, 1, 10, "rad/s"), values=(25, 85, 150, 280)
)

# %% [markdown]
# ## Check yourself
#
# 1. A block slides outward at 2 m/s along a slot that turns clockwise at 30 rpm. How large is its
#    Coriolis acceleration, and which way does it point?
#
# <details><summary>Answer</summary>
#
# $2\dot p\,\omega = 2 \times 2 \times \pi = 12.6$ m/s² (30 rpm is $\pi$ rad/s). It is the slip
# velocity (outward) turned 90° clockwise, the sense of $\omega$: if the slot points along +x,
# the Coriolis part points along -y.
#
# </details>
#
# 2. Does a pin-jointed fourbar have a Coriolis term? Does the ordinary slider-crank?
#
# <details><summary>Answer</summary>
#
# No and no. A pin joint has no slip velocity. The slider of a slider-crank slips, but along the
# ground, whose angular velocity is zero, so $2\dot d\,\omega_1 = 0$. A Coriolis term needs a
# slip *on a turning link*, as in the inverted slider-crank.
#
# </details>
#
# 3. Two children walk on the same roundabout at the same speed, one toward the centre and one
#    toward the rim. Compare their Coriolis accelerations.
#
# <details><summary>Answer</summary>
#
# Same size $2v\omega_2$, independent of where they are; opposite directions, because their slip
# velocities are opposite. The one walking inward is shoved forward in the direction of rotation,
# the one walking outward backward.
#
# </details>
#
# 4. In the cycle plot above, the forgotten-Coriolis error in $\alpha_4$ passes through zero at
#    four crank angles. Why four?
#
# <details><summary>Answer</summary>
#
# The error is zero where $2\dot b\,\omega_3 = 0$. The slip $\dot b$ vanishes twice per turn (the
# block reverses at the two ends of its travel on the slide) and $\omega_4$ vanishes twice (link 4
# reverses at its two extreme angles).
#
# </details>
#
# 5. Why is the Coriolis term *twice* $\dot p\,\omega$?
#
# <details><summary>Answer</summary>
#
# Eq. 7.19a has two equal terms. One comes from the transmission speed $p\omega$ changing because
# $p$ changes; the other from the slip velocity $\dot p\,e^{j\theta}$ changing direction because
# the slot turns.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
q1 = slot.solve(theta2="0 deg", omega2="-30 rpm", alpha2=0, p="200 mm", p_dot="2 m/s", p_ddot=0)
stated(abs(q1.A_coriolis), "12.6", "m/s^2")
stated(Q_(30, "rpm"), "3.1416", "rad/s")
assert np.isclose(np.angle(q1.A_coriolis.magnitude, deg=True), -90)  # along -y

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set (its Figure 7-7 is the model); work them with eq.
# 7.19, then check with `SlottedLink` or `InvertedSliderCrank`. The answers are folded.
#
# **Problem 5.1.** A slotted arm lies along $+x$ and turns counter-clockwise at a steady 60 rpm.
# A block in its slot is 200 mm from the pivot, sliding *inward* at 2 m/s, and its inward slip
# is speeding up at 5 m/s$^2$. Find each part of the block's acceleration and the total.
#
# <details><summary>Answer</summary>
#
# $\omega_2 = 2\pi$ rad/s, $\dot p = -2$ m/s, $\ddot p = -5$ m/s$^2$, $\alpha_2 = 0$. Tangential:
# 0. Normal: $p\omega_2^2 = 7.896$ m/s$^2$ toward the pivot ($-x$). Coriolis: $2\dot p\omega_2 =
# 25.13$ m/s$^2$, the inward slip velocity turned 90° counter-clockwise: along $-y$. Slip: 5
# m/s$^2$ along $-x$. Total: $(-12.90 - 25.13j)$ m/s$^2$, 28.25 m/s$^2$ at $-117.2^\circ$: the
# Coriolis part is the largest.
#
# </details>
#
# **Problem 5.2.** For the inverted slider-crank of example 3 (4, 3, 8 in, $\gamma = 90^\circ$)
# at a steady 10 rad/s, at which crank angles is the Coriolis term zero, and why there?
#
# <details><summary>Answer</summary>
#
# Where $2\dot b\,\omega_3 = 0$: where the block stops on the slide, $\dot b = 0$, at
# $\theta_2 = 0^\circ$ and $180^\circ$ (the crank pin on the ground line, where $b$ is longest and
# shortest), and where link 4 stops turning, $\omega_4 = 0$, at its two extreme angles,
# $\theta_2 = 82.8^\circ$ and $331.0^\circ$.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
f1 = slot.solve(
    theta2="0 deg", omega2="60 rpm", alpha2=0, p="200 mm", p_dot="-2 m/s", p_ddot="-5 m/s^2"
)
parts = {
    k: complex(getattr(f1, k).m_as("m/s^2")) for k in ("A_t", "A_n", "A_coriolis", "A_slip", "A")
}
assert abs(parts["A_t"]) < 1e-12
stated(-parts["A_n"].real, "7.896")
stated(-parts["A_coriolis"].imag, "25.13")
stated(-parts["A_slip"].real, "5")
stated(parts["A"].real, "-12.90")
stated(parts["A"].imag, "-25.13")
stated(abs(parts["A"]), "28.25")
stated(np.angle(parts["A"], deg=True), "-117.2")

fine = Q_(np.linspace(0, 2 * np.pi, 7201), "rad")
turn = isc.solve(theta2=fine, omega2="10 rad/s", alpha2=0)
stops = {}
for name, rate in (("b_dot", turn.b_dot.magnitude), ("omega4", turn.omega4.magnitude)):
    stops[name] = np.degrees(fine.magnitude[np.flatnonzero(np.diff(np.sign(rate)))])
stated(stops["b_dot"][0], "0")
stated(stops["b_dot"][1], "180")
stated(stops["omega4"][0], "82.8")
stated(stops["omega4"][1], "331.0")
# %% [markdown]
# ## Practice
#
# Inverted slider-crank problems with their Coriolis term, with instant feedback, for self-study
# (not graded, and never one of a graded assignment's). Each run of the next cell draws a fresh
# linkage, or give a seed to come back to one; hand each answer to `mine.check`, which says at once
# whether it is right and, if not, what to look at (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `coriolis`.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("coriolis")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("A_cor_mag", Q_(850, "in/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("coriolis", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5, modelled with `InvertedSliderCrank`:

# %%
example = practice("coriolis", seed=5, show=False)
g = example.given
model = InvertedSliderCrank(a=g["a"], c=g["c"], d=g["d"], gamma=g["gamma"])
res = model.solve(theta2=g["theta2"], omega2=g["omega2"], alpha2=g["alpha2"], circuit=g["circuit"])
assert example.check("A_cor_mag", abs(res.A_coriolis))  # right
# the factor 2 of eq. 7.19b forgotten:
assert not example.check("A_cor_mag", abs(res.A_coriolis) / 2)
assert example.check("alpha4", res.alpha4)  # right

# %% [markdown]
# ## Common mistakes
#
# - **Leaving the Coriolis vector out of a graphical polygon.** The polygon still closes and gives a
#   confident, wrong answer, as the comparison above shows. The analytic solution cannot forget it:
#   it comes out of differentiating $b\,e^{j\theta_3}$.
# - **Turning the slip velocity the wrong way.** Turn $\mathbf{V}_{slip}$ by 90° in the sense of
#   the slot's $\omega$, not of $\alpha$ and not toward the pivot.
# - **Using the wrong link's $\omega$.** It is the angular velocity of the link that carries the
#   slide (link 4 here; $\omega_3 = \omega_4$ because the block cannot turn on it).
# - **Copying eq. 7.26b from the scanned chapter.** It prints $\sin(\theta_4 + \theta_2)$ where
#   $\sin(\theta_4 - \theta_2)$ is right; check any printed formula against the solver.
# - **Calling the Coriolis term a force.** In the ground frame it is part of the block's true
#   acceleration; the slot's side walls (or the roundabout's floor) must push to produce it. The
#   sideways "shove" the child feels is her own inertia resisting that push.
#
# [Next: 6. The geared fivebar](06_geared_fivebar.ipynb)
