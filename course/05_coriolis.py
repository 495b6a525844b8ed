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
# So far every point we followed was fixed on its link. This notebook lets a point *slide along a
# link that turns*, and a fourth term appears in its acceleration. It follows the chapter's
# treatment of the Coriolis component and of the inverted slider-crank (Robert L. Norton,
# *Design of Machinery*, chapter 7, section 7.3: eqs. 7.17 to 7.27, Figures 7-7 and 7-8).
#
# **You will be able to**
#
# - split the acceleration of a point that slides on a rotating link into its tangential, normal,
#   Coriolis and slip parts (eq. 7.19), with the direction of each;
# - explain, with numbers, what a person walking across a turning roundabout feels;
# - solve the inverted slider-crank (eqs. 7.20-7.27) and read its Coriolis term from the solver;
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
# Differentiating the product gives two velocity terms: the **transmission** part, the speed the
# link would give a point fixed at radius $p$, and the **slip** part along the slot:
#
# $$ \mathbf{V}_P = p\,\omega_2\,j e^{j\theta_2} + \dot p\, e^{j\theta_2} \tag{7.18a} $$
#
# $$ \mathbf{V}_P = \mathbf{V}_{P_{trans}} + \mathbf{V}_{P_{slip}} \tag{7.18b} $$
#
# Differentiate once more. The transmission term holds three functions of time ($p$, $\omega_2$,
# $\theta_2$) and the slip term two ($\dot p$, $\theta_2$), so the chain rule gives five terms:
#
# $$ \mathbf{A}_P = \left(p\alpha_2 j e^{j\theta_2} - p\omega_2^2 e^{j\theta_2}
#    + \dot p\,\omega_2 j e^{j\theta_2}\right) + \left(\dot p\,\omega_2 j e^{j\theta_2}
#    + \ddot p\, e^{j\theta_2}\right) \tag{7.19a} $$
#
# Two of them are the same, $\dot p\,\omega_2 j e^{j\theta_2}$: one because the transmission speed
# $p\omega_2$ grows as the block moves out, the other because the slip velocity turns with the
# link. Together they make the Coriolis term:
#
# $$ \mathbf{A}_P = p\alpha_2 j e^{j\theta_2} - p\omega_2^2 e^{j\theta_2}
#    + 2\dot p\,\omega_2 j e^{j\theta_2} + \ddot p\, e^{j\theta_2} \tag{7.19b} $$
#
# $$ \mathbf{A}_P = \mathbf{A}_{P_{tangential}} + \mathbf{A}_{P_{normal}}
#    + \mathbf{A}_{P_{coriolis}} + \mathbf{A}_{P_{slip}} \tag{7.19c} $$
#
# | part | size | direction |
# |---|---|---|
# | tangential | $p\,\alpha_2$ | perpendicular to the slot, in the sense of $\alpha_2$ |
# | normal | $p\,\omega_2^2$ | along the slot, toward the pivot |
# | **Coriolis** | $2\,\dot p\,\omega_2$ | perpendicular to the slot: $\mathbf{V}_{slip}$ turned 90° in the sense of $\omega_2$ |
# | slip | $\ddot p$ | along the slot |
#
# The Coriolis part needs *both* a slip velocity and a turning slot. A pin joint has no slip; the
# slider of an ordinary slider-crank slips along the ground, which does not turn. So neither has a
# Coriolis term, and the inverted slider-crank, whose block slides on a turning link, does.

# %%
# %matplotlib inline
import matplotlib.pyplot as plt
import numpy as np

from accelab.course.animation import animate
from accelab.course.kit import COLORS, LINESTYLES, explore, in_g, stated, use_style, vector
from accelab.course.practice import practice
from accelab.solver import Q_, InvertedSliderCrank, SlottedLink
from accelab.solver.graphical import Arrow, Construction, Line, Step, invertedslidercrank, slotted
from accelab.solver.graphical.draw import draw_linkage, draw_polygon
from accelab.solver.graphical.geometry import intersect_lines

use_style()


def show(name, z):
    """One line: a vector's size in m/s^2 and in/s^2 and its direction (angle from +x)."""
    si = z.to("m/s^2").magnitude
    us = z.to("in/s^2").magnitude
    print(
        f"{name:<11} {abs(si):8.3f} m/s^2 = {abs(us):8.1f} in/s^2  at {np.angle(si, deg=True):7.1f} deg"
    )


def legend_of(ax, kinds, lines=False):
    """A legend naming the vector kinds drawn (colours and line styles of accelab.solver.graphical)."""
    handles = [
        plt.Line2D(
            [],
            [],
            color=COLORS[k],
            linestyle=LINESTYLES[k],
            linewidth=2,
            label={"normal": "normal (centripetal)", "resultant": "resultant"}.get(k, k),
        )
        for k in kinds
    ]
    if lines:
        handles.append(
            plt.Line2D([], [], color="#8c8c8c", ls="--", lw=1, label="construction line")
        )
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.0, 1.0), fontsize=9)


# %% [markdown]
# ## Worked examples
#
# ### 1. A block in a turning slot (Figure 7-7)
#
# As in the chapter's figure, the link turns clockwise but is being slowed down: $\omega_2 < 0$
# and $\alpha_2 > 0$. The block is 250 mm from the pivot and slides outward at 1.5 m/s while the
# slip itself slows at 3 m/s².

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
for name in ("A_t", "A_n", "A_coriolis", "A_slip", "A"):
    show(name, getattr(r, name))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
parts = {k: abs(getattr(r, k)).m_as("m/s^2") for k in ("A_t", "A_n", "A_coriolis", "A_slip")}
stated(parts["A_coriolis"], "12"), stated(parts["A_coriolis"] / parts["A_n"], "3")
assert max(parts, key=parts.get) == "A_coriolis"

# %% [markdown]
# The Coriolis part, 12 m/s², is the largest of the four: three times the centripetal part. A
# turning slot with a fast slip is exactly where a hand analysis must not drop it.
#
# The next cell writes eq. 7.19's Coriolis term out by hand and checks it against the solver, then
# checks that the four parts add up to the total (eq. 7.19c).

# %%
theta, omega = Q_(30, "deg").to("rad").magnitude, -4.0
p_dot = 1.5
by_hand = 2 * p_dot * omega * 1j * np.exp(1j * theta)  # 2 p' omega j e^{j theta}, m/s^2
assert np.isclose(by_hand, r.A_coriolis.to("m/s^2").magnitude, rtol=1e-12)
parts = r.A_t + r.A_n + r.A_coriolis + r.A_slip
assert np.isclose(parts.to("m/s^2").magnitude, r.A.to("m/s^2").magnitude, rtol=1e-12)
# direction: V_slip turned 90 deg in the sense of omega (clockwise here)
turned = np.angle(r.A_coriolis.magnitude / r.V_slip.magnitude, deg=True)
print(f"Coriolis is V_slip turned by {turned:+.0f} deg (omega2 < 0: clockwise)")

# %% [markdown]
# `accelab.solver.graphical` draws the same four parts at the block and adds them tip to tail; the
# resultant closes the polygon (the chapter's Figure 7-7b and c). The block's motion is given
# here, so no construction lines are needed: every part is known in size and direction.

# %% mystnb={"figure": {"caption": "A block sliding in a turning slot (Figure 7-7): the tangential, normal, Coriolis and slip parts of its acceleration."}, "image": {"alt": "Slotted link with the block and four acceleration arrows: tangential, normal, Coriolis and slip."}}
con = slotted.construct(theta2=theta, omega2=omega, alpha2=15.0, p=0.25, p_dot=1.5, p_ddot=-3.0)
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 5.2), gridspec_kw={"width_ratios": [1.2, 1]})
draw_linkage(con, ax=ax1, legend=False)
draw_polygon(con, "acceleration", ax=ax2)
legend_of(ax2, ("tangential", "normal", "coriolis", "slip", "resultant"))
plt.show()

# %% [markdown]
# ### 2. Walking across a turning roundabout
#
# The chapter's everyday Coriolis example: walk straight toward the centre of a turning carousel
# and you are pushed sideways. You are the block of Figure 7-7 and the floor is the slotted link.
#
# Take a playground roundabout of radius 1.8 m turning counter-clockwise at 12 rpm, and a child
# who walks from the rim to the centre at a steady 0.6 m/s along a radial line painted on the
# floor. Her distance from the centre is $p(t) = 1.8\ \text{m} - 0.6\ \text{m/s}\cdot t$, so
# $\dot p = -0.6$ m/s and $\ddot p = 0$, while the floor turns with $\theta_2 = \omega_2 t$.

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
print(f"walk lasts {t[-1]:.1f~P}, the floor turns {(omega_ride * t[-1]).to('turn'):.2f~P}")
print(
    f"Coriolis:     {abs(walk.A_coriolis[0]).to('m/s^2'):.2f~P} = "
    f"{in_g(walk.A_coriolis[0]):.3f} g all the way (it does not depend on p)"
)
print(
    f"centripetal:  {abs(walk.A_n[0]).to('m/s^2'):.2f~P} = "
    f"{in_g(walk.A_n[0]):.3f} g at the rim, falling to 0 at the centre"
)
m_child = Q_(30, "kg")
print(
    f"sideways push the floor must give a {m_child:~P} child: "
    f"{(m_child * abs(walk.A_coriolis[0])).to('N'):.0f~P}"
)

# %% [markdown]
# Which way is "sideways"? The Coriolis part is the slip velocity (inward) turned 90° in the sense
# of $\omega_2$ (counter-clockwise), so it points *against* the rotation: walking inward, her
# speed around the centre must drop from $R\omega_2$ to zero, and the floor, through friction at
# her feet, has to take it away. What she **feels** is the opposite of what the floor does to her:
# a shove *forward, in the direction the roundabout turns*. Walking outward reverses both.
#
# The figure draws her path over the ground (a spiral, although she walks a straight line on
# the floor) with the two parts of her acceleration at a few instants.

# %% mystnb={"figure": {"caption": "A walk across a turning roundabout: the path over the floor with the accelerations at a few instants (left) and the size of each part during the walk (right)."}, "image": {"alt": "Left, a curved path seen from above with acceleration arrows; right, line plots of the Coriolis and centripetal parts against time."}}
R = walk.R.to("m").magnitude
A_cor = walk.A_coriolis.to("m/s^2").magnitude
A_n = walk.A_n.to("m/s^2").magnitude
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": [1, 1.15]})
rim = R_rim.magnitude * np.exp(1j * np.linspace(0, 2 * np.pi, 200))
ax1.plot(rim.real, rim.imag, color="#888888", lw=1)
ax1.plot(R.real, R.imag, color="black", lw=1.5, label="her path over the ground")
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
ax1.set_title("Top view: path and accelerations\n(1 m of drawing = 3.3 m/s²)")
ax1.legend(
    handles=[
        plt.Line2D([], [], color="black", label="path over the ground"),
        plt.Line2D([], [], color="#bbbbbb", ls=":", label="her painted line, then"),
        plt.Line2D([], [], color=COLORS["coriolis"], ls=LINESTYLES["coriolis"], label="Coriolis"),
        plt.Line2D([], [], color=COLORS["normal"], label="normal (centripetal)"),
    ],
    loc="lower left",
    fontsize=8,
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
ax2.set_xlabel("distance from the centre p [m] (she walks from left to right)")
ax2.set_ylabel("acceleration [g]")
ax2.set_ylim(bottom=0)
ax2.legend()
ax2.set_title("Size of each part during the walk")
plt.show()

# %% tags=["remove-input"] jupyter={"source_hidden": true}
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
# Link 4 turns about $O_4$ and carries a slide; the block 3, pinned to the crank at A, slides on
# it. The length $b$ from B to A varies, so the vector loop
# $a e^{j\theta_2} - b e^{j\theta_3} - c e^{j\theta_4} - d e^{j\theta_1} = 0$, differentiated twice
# with $a, c, d$ constant and $b$ varying, gives
#
# $$ \begin{split}
#    & a\alpha_2 je^{j\theta_2} - a\omega_2^2 e^{j\theta_2} \\
#    & - \left(b\alpha_3 je^{j\theta_3} - b\omega_3^2 e^{j\theta_3} + 2\dot b\omega_3 je^{j\theta_3}
#    + \ddot b e^{j\theta_3}\right) \\
#    & - \left(c\alpha_4 je^{j\theta_4} - c\omega_4^2 e^{j\theta_4}\right) = 0
#    \end{split} \tag{7.20b} $$
#
# which is the acceleration difference equation between A and B, with the slide's two extra
# parts inside $\mathbf{A}_{AB} = \mathbf{A}_A - \mathbf{A}_B$:
#
# $$ \mathbf{A}_A - \mathbf{A}_{AB} - \mathbf{A}_B = 0, \qquad
#    \mathbf{A}_{AB} = \mathbf{A}_{AB_{tangential}} + \mathbf{A}_{AB_{normal}}
#    + \mathbf{A}_{AB_{coriolis}} + \mathbf{A}_{AB_{slip}} \tag{7.21} $$
#
# with $\mathbf{A}_{AB_{coriolis}} = 2\dot b\,\omega_3\, j e^{j\theta_3}$ and
# $\mathbf{A}_{AB_{slip}} = \ddot b\, e^{j\theta_3}$. The block cannot turn on the slide, so
# $\theta_3 = \theta_4 + \gamma$ and
#
# $$ \omega_3 = \omega_4, \qquad \alpha_3 = \alpha_4 \tag{7.22} $$
#
# That leaves two unknowns, $\alpha_4$ and $\ddot b$, in the two scalar parts of eq. 7.20b.
# Solving them simultaneously:
#
# $$ \alpha_4 = \frac{a\left[\alpha_2\cos(\theta_3-\theta_2) + \omega_2^2\sin(\theta_3-\theta_2)\right]
#    + c\omega_4^2\sin(\theta_4-\theta_3) - 2\dot b\omega_3}{b + c\cos(\theta_3-\theta_4)}
#    \tag{7.26a} $$
#
# $$ \ddot b = -\frac{N}{b + c\cos(\theta_3-\theta_4)}, \qquad \begin{split}
#    N = {} & a\omega_2^2\left[b\cos(\theta_3-\theta_2) + c\cos(\theta_4-\theta_2)\right] \\
#    & + a\alpha_2\left[b\sin(\theta_2-\theta_3) - c\sin(\theta_4-\theta_2)\right] \\
#    & + 2\dot b c\omega_4\sin(\theta_4-\theta_3)
#    - \omega_4^2\left[b^2 + c^2 + 2bc\cos(\theta_4-\theta_3)\right]
#    \end{split} \tag{7.26b} $$
#
# (The scanned chapter prints $\sin(\theta_4 + \theta_2)$ in eq. 7.26b; the sum is a misprint, the
# cell below shows that only the difference agrees with the solver.) The denominator vanishes
# where $b + c\cos\gamma = 0$: the slide is then perpendicular to $O_4A$ and the equations are
# singular, a limit position. Putting $\alpha_4$ and $\ddot b$ back into eqs. 7.21 gives the
# pins' accelerations (the chapter's eqs. 7.27); the solver reports them as `A_A`, `A_B`, `A_BA`,
# and the Coriolis term alone as `A_coriolis`.
#
# (Two more slips of the scan, both lost dots on $b$. The Coriolis term of eq. 7.24a, the
# loop written out with $j(\cos\theta + j\sin\theta)$, prints as $-2b\omega_3 j(\ldots)$: it
# is $-2\dot b\omega_3 j(\ldots)$, as eq. 7.20b above and the next line, eq. 7.24b, have it. And
# eq. 7.27b, $\mathbf{A}_{BA}$ in cartesian form, prints its last two terms as
# $2b\omega_3(\sin\theta_3 - j\cos\theta_3) - b(\cos\theta_3 + j\sin\theta_3)$: they are
# $2\dot b\omega_3(\ldots)$ and $\ddot b(\ldots)$, the Coriolis and slip terms of eq. 7.21 with
# the sign of $\mathbf{A}_{BA} = -\mathbf{A}_{AB}$. Without the dots neither term has the
# dimension of an acceleration. The cell below checks the corrected eq. 7.27b.)
#
# Our linkage: crank $a$ = 4 in, $O_4B$ = $c$ = 3 in, ground $d$ = 8 in, slide at $\gamma$ = 90°
# to $O_4B$. The crank turns clockwise and is being slowed down, as in the chapter's Figure 7-8.

# %%
isc = InvertedSliderCrank(a="4 in", c="3 in", d="8 in", gamma="90 deg")
r = isc.solve(theta2="60 deg", omega2="-10 rad/s", alpha2="25 rad/s^2")
print(
    f"theta3 = {r.theta3.to('deg'):.2f~P}, theta4 = {r.theta4.to('deg'):.2f~P}, "
    f"b = {r.b.to('in'):.3f~P}"
)
print(f"omega3 = omega4 = {r.omega4:.3f~P}, b' = {r.b_dot.to('in/s'):.2f~P}")
print(f"alpha3 = alpha4 = {r.alpha4:.2f~P}, b'' = {r.b_ddot.to('in/s^2'):.2f~P}")
for name in ("A_A", "A_B", "A_coriolis", "A_slip"):
    show(name, getattr(r, name))

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
den = b + c * np.cos(t3 - t4)
alpha4 = (
    a * (al2 * np.cos(t3 - t2) + w2**2 * np.sin(t3 - t2))
    + c * w4**2 * np.sin(t4 - t3)
    - 2 * bd * w3
) / den


def b_ddot(sign):  # sign = -1: eq. 7.26b as corrected; +1: as printed
    return (
        -(
            a * w2**2 * (b * np.cos(t3 - t2) + c * np.cos(t4 - t2))
            + a * al2 * (b * np.sin(t2 - t3) - c * np.sin(t4 + sign * t2))
            + 2 * bd * c * w4 * np.sin(t4 - t3)
            - w4**2 * (b * b + c * c + 2 * b * c * np.cos(t4 - t3))
        )
        / den
    )


solver_bdd = r.b_ddot.to("in/s^2").magnitude
assert np.isclose(alpha4, r.alpha4.magnitude, rtol=1e-12)
assert np.isclose(b_ddot(-1), solver_bdd, rtol=1e-12)
print(
    f"eq. 7.26a: {alpha4:.6f} rad/s^2; eq. 7.26b: {b_ddot(-1):.4f} in/s^2 (solver {solver_bdd:.4f}); "
    f"as printed: {b_ddot(+1):.4f} in/s^2"
)
e3 = np.exp(1j * t3)
bdd = solver_bdd
A_AB = (b * (1j * r.alpha3.magnitude - w3**2) + 2j * bd * w3 + bdd) * e3  # eq. 7.21c, in/s^2
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
# The graphical construction of `accelab.solver.graphical` does the same analysis by geometry alone (it
# never calls the analytic solver). Its polygon has *two* unknown lengths: $\mathbf{A}_{slip}$ along
# the slide (line rr) and the tangential acceleration of the point $A_4$ of link 4 under A,
# perpendicular to $O_4A$ (line pp). The Coriolis vector is known in size and direction from the
# velocity analysis and sits between them.

# %% mystnb={"figure": {"caption": "The inverted slider-crank and its acceleration polygon, with the Coriolis component included."}, "image": {"alt": "Inverted slider-crank linkage beside its acceleration polygon."}}
a_m, c_m, d_m = (Q_(x, "in").to("m").magnitude for x in (4, 3, 8))
con = invertedslidercrank.construct(
    a=a_m, c=c_m, d=d_m, gamma=np.pi / 2, theta2=t2, omega2=w2, alpha2=al2
)
assert np.isclose(con.values["alpha4"], r.alpha4.magnitude, rtol=1e-9)
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5.4), gridspec_kw={"width_ratios": [1.3, 1]})
draw_linkage(con, ax=ax1, units="US", legend=False)  # the linkage was given in inches
draw_polygon(con, "acceleration", ax=ax2, units="US")
legend_of(ax2, ("tangential", "normal", "coriolis", "slip", "resultant"), lines=True)
plt.show()

# %% [markdown]
# ### 4. What a graphical solution gets wrong without the Coriolis component
#
# Suppose a student draws the polygon above but forgets the Coriolis vector. The polygon still
# closes: lines rr and pp still cross somewhere, and a plausible-looking $\alpha_4$ and
# $\ddot b$ come out. Nothing on the drawing warns that they are wrong.
#
# The cell below redoes the last step of the construction with the same drafting operation
# (`intersect_lines`), but with rr drawn through the tip of $\mathbf{A}^n_{A_4}$ instead of the
# tip of $\mathbf{A}^n_{A_4} + \mathbf{A}_{coriolis}$. This is the wrong method on purpose; the
# solver never does it.


# %%
def forgetful(con):
    """(alpha4, b_ddot, X) from the construction's polygon closed WITHOUT the Coriolis vector."""
    v = con.values
    e3 = np.exp(1j * v["theta3"])
    radius = v["R_A"] - d_m  # O4 -> A (theta1 = 0)
    X, b_dd, t = intersect_lines(v["A_A4_n"], e3, v["A_A"], 1j * radius)
    return -t, b_dd, X


wrong_alpha4, wrong_bdd, X = forgetful(con)
print(
    f"alpha4: right {con.values['alpha4']:8.2f} rad/s^2, without Coriolis {wrong_alpha4:8.2f} rad/s^2"
)
print(f"b'':    right {con.values['b_ddot']:8.3f} m/s^2,   without Coriolis {wrong_bdd:8.3f} m/s^2")

# %% mystnb={"figure": {"caption": "The acceleration polygon with the Coriolis vector (right) and without it (wrong): the wrong polygon still closes."}, "image": {"alt": "Two acceleration polygons of the same position, one including the Coriolis vector and one leaving it out."}}
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
fig, axes = plt.subplots(1, 2, figsize=(11, 5))
draw_polygon(con, "acceleration", ax=axes[0], units="US")
axes[0].set_title("Right: with the Coriolis vector")
draw_polygon(wrong, "acceleration", ax=axes[1], units="US")
axes[1].set_title("Wrong: Coriolis forgotten\n(the polygon still closes)")
plt.show()

# %% [markdown]
# One position can be a coincidence. Over a whole crank turn at a steady 10 rad/s we compare the
# right $\alpha_4$ (from the solver, a vectorized call) with the forgetful construction at every
# 2°.

# %% mystnb={"figure": {"caption": "Over a whole cycle: the angular acceleration of link 4 with and without the Coriolis term, and the error the omission makes."}, "image": {"alt": "Line plots of alpha4 against crank angle for the right and the wrong construction, and of their difference."}}
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
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
ax1.plot(deg, right_a4, color="black", lw=2, label="right (solver)")
ax1.plot(deg, forgot[:, 0], color=COLORS["tangential"], lw=2, ls="--", label="Coriolis forgotten")
ax1.set_ylabel(r"$\alpha_4$ [rad/s$^2$]")
ax1.set_title(r"Angular acceleration of link 4, $\omega_2$ = 10 rad/s")
ax1.legend()
ax2.plot(
    deg,
    np.abs(cycle.A_coriolis.to("m/s^2").magnitude),
    color=COLORS["coriolis"],
    lw=2,
    ls=LINESTYLES["coriolis"],
    label=r"$|\mathbf{A}_{coriolis}|$, the term forgotten",
)
ax2.plot(
    deg,
    np.abs(forgot[:, 1] - cycle.b_ddot.to("m/s^2").magnitude),
    color=COLORS["slip"],
    lw=2,
    ls=LINESTYLES["slip"],
    label=r"error in the slip acceleration $\ddot b$",
)
ax2.set_ylabel(r"acceleration [m/s$^2$]")
ax2.set_title("The forgotten term and the error it makes")
ax2.legend(fontsize=9)
for ax in (ax1, ax2):
    ax.set_xlabel(r"crank angle $\theta_2$ [deg]")
    ax.set_xticks(range(0, 361, 60))
plt.show()
worst = np.argmax(np.abs(err))
print(
    f"largest error in alpha4: {err[worst]:+.1f} rad/s^2 at theta2 = {deg[worst]:.0f} deg, "
    f"{abs(err[worst]) / np.abs(right_a4).max():.0%} of the largest |alpha4| in the cycle"
)
print(
    f"Coriolis term: up to {np.abs(cycle.A_coriolis.to('m/s^2').magnitude).max():.1f} m/s^2; "
    f"|A_A| is {abs(cycle.A_A[0].to('m/s^2').magnitude):.1f} m/s^2 all the time"
)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
cor_max = np.abs(cycle.A_coriolis.to("m/s^2").magnitude).max()
pin = abs(cycle.A_A[0].to("m/s^2").magnitude)
stated(cor_max, "21"), stated(pin, "10"), stated(cor_max / pin, "2")
assert np.abs(err).max() >= 0.9 * np.abs(right_a4).max()  # "as much as its own largest value"

# %% [markdown]
# The forgotten Coriolis term is not a small correction: for this linkage it reaches twice the
# crank pin's own acceleration (21 against 10 m/s²), and the angular acceleration of link 4 comes out wrong
# by as much as its own largest value. The error vanishes only where the Coriolis term does:
# where the block momentarily stops sliding ($\dot b = 0$, at the ends of its travel) or link 4
# momentarily stops turning ($\omega_4 = 0$, at its extreme angles).
#
# **In motion.** The linkage through one crank turn at a steady 10 rad/s, with the
# accelerations of A and B and the Coriolis component at A (one arrow scale for the whole
# turn), and a marker on the curves of $\alpha_4$ and of the three sizes: watch the green
# Coriolis arrow vanish twice as the block stops on the slide, and twice as link 4 stops.

# %% mystnb={"figure": {"caption": "Animation: the inverted slider-crank through one turn at 10 rad/s with the accelerations of A and B and the Coriolis component at A, and a marker on alpha4 and the three sizes."}, "image": {"alt": "Animated inverted slider-crank with acceleration arrows and a green Coriolis arrow, beside plots with a moving marker."}}
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

# %% mystnb={"figure": {"caption": "The inverted slider-crank at four crank angles, in one frame and at one scale: the Coriolis component at A nearly vanishes at 85 deg."}, "image": {"alt": "Four drawings of the inverted slider-crank with the acceleration of A, its Coriolis and slip parts, and the acceleration of B."}}
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

# %% tags=["remove-input"] jupyter={"source_hidden": true}
q1 = slot.solve(theta2="0 deg", omega2="-30 rpm", alpha2=0, p="200 mm", p_dot="2 m/s", p_ddot=0)
stated(abs(q1.A_coriolis), "12.6", "m/s^2"), stated(Q_(30, "rpm"), "3.1416", "rad/s")
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

# %% tags=["remove-input"] jupyter={"source_hidden": true}
f1 = slot.solve(
    theta2="0 deg", omega2="60 rpm", alpha2=0, p="200 mm", p_dot="-2 m/s", p_ddot="-5 m/s^2"
)
parts = {
    k: complex(getattr(f1, k).m_as("m/s^2")) for k in ("A_t", "A_n", "A_coriolis", "A_slip", "A")
}
assert abs(parts["A_t"]) < 1e-12
(
    stated(-parts["A_n"].real, "7.896"),
    stated(-parts["A_coriolis"].imag, "25.13"),
    stated(-parts["A_slip"].real, "5"),
)
(
    stated(parts["A"].real, "-12.90"),
    stated(parts["A"].imag, "-25.13"),
    stated(abs(parts["A"]), "28.25"),
)
stated(np.angle(parts["A"], deg=True), "-117.2")

fine = Q_(np.linspace(0, 2 * np.pi, 7201), "rad")
turn = isc.solve(theta2=fine, omega2="10 rad/s", alpha2=0)
stops = {}
for name, rate in (("b_dot", turn.b_dot.magnitude), ("omega4", turn.omega4.magnitude)):
    stops[name] = np.degrees(fine.magnitude[np.flatnonzero(np.diff(np.sign(rate)))])
stated(stops["b_dot"][0], "0"), stated(stops["b_dot"][1], "180")
stated(stops["omega4"][0], "82.8"), stated(stops["omega4"][1], "331.0")
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
