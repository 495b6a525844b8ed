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
# # 1. The acceleration of a rotating point
#
# Every linkage analysis in this course starts from one small fact: how a point on a link that
# turns about a fixed pivot accelerates. This notebook builds that fact, then uses it to
# separate the two situations in which we subtract one acceleration from another. It follows
# section 7.1 of the chapter this course is built on: Robert L. Norton, *Design of Machinery*,
# chapter 7, "Acceleration Analysis" (eqs. 7.1 to 7.6, Figures 7-1 to 7-3, problem 7-1).
#
# **You will be able to**
#
# - write the acceleration of a point on a rotating link as a tangential plus a normal
#   component, in polar (complex exponential) and in cartesian form;
# - say which way each component points from the signs of $\omega$ and $\alpha$, without a
#   formula sheet;
# - tell an *acceleration difference* (two points of one rigid body) from a *relative
#   acceleration* (two points of different bodies), and know what each lets you assume;
# - work problem 7-1 by hand, in inches and in metres, and check it with `accelab.solver`.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import matplotlib.pyplot as plt
import numpy as np

from accelab.course.animation import animate
from accelab.course.kit import explore, in_g, point_label, stated, use_style, vector
from accelab.course.practice import practice
from accelab.course.renditions import legend, panels, show
from accelab.course.text import num, say, table, vec, xy
from accelab.solver import Q_, RotatingPoint
from accelab.solver.graphical import construct_case
from accelab.solver.graphical.draw import draw_linkage

use_style()

# %% [markdown]
# ## The idea and its equations
#
# Acceleration is the rate of change of velocity, angular or linear:
#
# $$ \alpha = \frac{d\omega}{dt}, \qquad \mathbf{A} = \frac{d\mathbf{V}}{dt} \tag{7.1} $$
#
# Put a point $P$ at the fixed distance $p$ from a pivot at the origin, on a link at angle
# $\theta$. In complex notation its position is $\mathbf{R}_P = p e^{j\theta}$ and its velocity
# $\mathbf{V}_P = p\,\omega\, j e^{j\theta}$: the factor $j$ turns the velocity $90^\circ$ ahead of
# the radius. Differentiate once more. Both $\omega$ and $\theta$ change with time, so the
# product rule gives two terms:
#
# $$ \begin{aligned} \mathbf{A}_P &= p\,\alpha\, je^{j\theta} - p\,\omega^2 e^{j\theta} \\
#    &= \mathbf{A}^t_P + \mathbf{A}^n_P \end{aligned} \tag{7.2} $$
#
# * The **tangential** component $p\alpha\,je^{j\theta}$ is perpendicular to the radius. The $j$
#   turns it $90^\circ$ counter-clockwise from $\mathbf{R}_P$ when $\alpha > 0$; a negative
#   $\alpha$ turns it the other way. It follows the sign of $\alpha$ only.
# * The **normal** (centripetal) component $-p\omega^2 e^{j\theta}$ came from $j \cdot j = -1$:
#   it points from $P$ straight back at the pivot, *whatever the sign of $\omega$*, because
#   $\omega$ appears squared.
#
# With Euler's identity $e^{j\theta} = \cos\theta + j\sin\theta$ the same vector in cartesian
# form (real part $x$, imaginary part $y$) is
#
# $$ \begin{aligned} \mathbf{A}_P = {} & p\alpha\,(-\sin\theta + j\cos\theta) \\
#    & - p\omega^2(\cos\theta + j\sin\theta) \end{aligned} \tag{7.3} $$
#
# and the sizes of the two parts, which is all a graphical construction needs, are
#
# $$ A^t = p\,\alpha, \qquad A^n = p\,\omega^2 \tag{7.6} $$
#
# Let us check eq. 7.3 against the solver for a point 4 in from its pivot at
# $\theta = 30^\circ$, turning clockwise ($\omega = -20$ rad/s) while speeding up
# counter-clockwise ($\alpha = 150$ rad/s$^2$). Writing the formula out here is for learning
# only: the assertion makes sure it says what `accelab.solver` computes.

# %%
p, theta, omega, alpha = 4.0 * 0.0254, np.radians(30), -20.0, 150.0  # SI: m, rad, rad/s, rad/s^2
by_hand = p * alpha * (-np.sin(theta) + 1j * np.cos(theta)) - p * omega**2 * (
    np.cos(theta) + 1j * np.sin(theta)
)  # eq. 7.3

point = RotatingPoint(p="4 in")
r = point.solve(theta2="30 deg", omega2="-20 rad/s", alpha2="150 rad/s^2")
assert np.isclose(by_hand, r.A.to("m/s^2").magnitude, rtol=1e-12)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "cartesian", "polar"],
    [
        [rf"${s}$", xy(getattr(r, k), "in/s^2"), vec(getattr(r, k), "in/s^2")]
        for k, s in (("A_t", r"\mathbf{A}^t"), ("A_n", r"\mathbf{A}^n"), ("A", r"\mathbf{A}"))
    ],
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
angle = {k: float(np.angle(getattr(r, k).to("in/s^2").magnitude, deg=True)) for k in ("A_t", "A_n")}
stated(angle["A_n"], "-150")
stated(angle["A_t"], "120")

# %% [markdown]
# The normal part points at $-150^\circ$ (that is, $210^\circ$), exactly opposite the radius
# at $30^\circ$; the tangential part at $120^\circ$, a quarter turn counter-clockwise from the
# radius because $\alpha > 0$, even though the link turns clockwise. The picture, with the
# acceleration vectors drawn at the point they belong to (the chapter's Figure 7-1):


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "A point 4 in from its pivot (the chapter's Figure 7-1): the tangential part $\\mathbf{A}^t$, the normal part $\\mathbf{A}^n$ and the total $\\mathbf{A}_P$ drawn at the point, with scale bars in inches and in/s²."}}
def rotating(p, theta2, omega2, alpha2):
    """The graphical construction of a point on a link turning about a fixed pivot
    (section 7.1), as the solver's drawings take it: inputs as quantity strings."""
    return construct_case(
        {"mechanism": "rotation", "p": p, "theta2": theta2, "omega2": omega2, "alpha2": alpha2}
    )


def figure_7_1(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 4.9) if narrow else (6.4, 4.6))
    draw_linkage(
        rotating("4 in", "30 deg", "-20 rad/s", "150 rad/s^2"),
        ax=ax,
        names={"O2": "O"},
        legend=not narrow,
        title=r"4 in link, $\omega = -20$ rad/s, $\alpha = 150$ rad/s$^2$",
    )
    if narrow:
        legend(fig, ("normal", "tangential", "resultant"), loc="outside lower center")
    return fig


show(
    figure_7_1,
    alt="A link from O to P with three acceleration arrows at P: tangential, normal "
    "(beside the link) and the total.",
)

# %% [markdown]
# The drawing is the solver's (`accelab.solver.graphical`), as every linkage drawing of the
# course: the link to scale, the acceleration components at the point they belong to, and a
# scale bar for each (inches for the link, in/s$^2$ for the arrows). The normal part lies along
# the link, so it is drawn just beside it.

# %% [markdown]
# ### Two cases of one equation
#
# Once the pivot itself moves, the acceleration of $P$ is the pivot's acceleration plus
# that of $P$ as seen from the pivot:
#
# $$ \mathbf{A}_P = \mathbf{A}_A + \mathbf{A}_{PA} \tag{7.4} $$
#
# Read backwards, the same equation defines the difference of two accelerations:
#
# $$ \mathbf{A}_{PA} = \mathbf{A}_P - \mathbf{A}_A \tag{7.5} $$
#
# The algebra is identical; what we may *assume* about $\mathbf{A}_{PA}$ is not.
#
# | | Case 1: acceleration difference | Case 2: relative acceleration |
# |---|---|---|
# | the points | two points of **one** rigid body | points of **two** bodies |
# | $\mathbf{A}_{PA}$ | $p\alpha\,je^{j\theta} - p\omega^2e^{j\theta}$, the body's own $\omega$, $\alpha$ | whatever $\mathbf{A}_P - \mathbf{A}_A$ comes to |
# | its normal part | along $PA$, toward $A$, of size $p\,\omega^2$ | no such rule |
# | its tangential part | perpendicular to $PA$, of size $p\,\alpha$ | no such rule |
#
# Case 1 is what makes graphical and analytic linkage analysis possible: for two pins of one
# link we know the *directions* of both parts of $\mathbf{A}_{PA}$ before we know their sizes.

# %% [markdown]
# ## Worked example 1: problem 7-1
#
# *A point 6.5 in from the centre of a body in pure rotation passes position $A$, at
# $45^\circ$ from the $x$ axis, with $\omega = 100$ rad/s; the body has a constant
# $\alpha = -500$ rad/s$^2$. It reaches position $B$ 0.01 s later. Find $\theta$ and $\omega$
# at $B$; write the acceleration at $A$ and at $B$ in polar and cartesian form; write and
# evaluate the acceleration difference between $B$ and $A$.*
#
# **Step 1: where is B?** With $\alpha$ constant, $\omega_B = \omega_A + \alpha t$ and
# $\theta_B = \theta_A + \omega_A t + \tfrac12 \alpha t^2$ (angles in radians!).

# %%
t = Q_(0.01, "s")
theta_A, omega_A, alpha_7_1 = Q_(45, "deg"), Q_(100, "rad/s"), Q_(-500, "rad/s^2")
omega_B = omega_A + alpha_7_1 * t
theta_B = (theta_A + omega_A * t + 0.5 * alpha_7_1 * t**2).to("deg")
say(rf"At $B$: $\omega_B$ = {num(omega_B)} rad/s and $\theta_B$ = {num(theta_B, 5)}°.")

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
turned = theta_B - theta_A
stated(turned.to("rad"), "0.975", "rad")
stated(turned, "55.86", "deg")
stated(omega_A - omega_B, "5", "rad/s")

# %% [markdown]
# The point turned $0.975$ rad ($55.86^\circ$) in those 10 ms and slowed by 5 rad/s.
#
# **Step 2: the acceleration at A and at B.** In polar form eq. 7.2 is already written:
# $\mathbf{A} = p\alpha\,je^{j\theta} - p\omega^2e^{j\theta}$ with the numbers put in.
# At $A$: $p\alpha = 6.5 \times (-500) = -3250$ in/s$^2$ and
# $p\omega^2 = 6.5\times 100^2 = 65\,000$ in/s$^2$, so
#
# $$ \mathbf{A}_A = -3250\,j e^{j45^\circ} - 65\,000\, e^{j45^\circ}\ \text{in/s}^2 $$
#
# The solver gives both points and the cartesian form:

# %%
pt = RotatingPoint(p="6.5 in")
at_A = pt.solve(theta2=theta_A, omega2=omega_A, alpha2=alpha_7_1)
at_B = pt.solve(theta2=theta_B, omega2=omega_B, alpha2=alpha_7_1)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "position $A$", "position $B$"],
    [
        [r"$\mathbf{A}^t$, size $\lvert p\alpha \rvert$"]
        + [vec(res.A_t, "in/s^2") for res in (at_A, at_B)],
        [r"$\mathbf{A}^n$, size $p\omega^2$"] + [vec(res.A_n, "in/s^2") for res in (at_A, at_B)],
        [r"$\mathbf{A}$, polar"] + [vec(res.A, "in/s^2") for res in (at_A, at_B)],
        [r"$\mathbf{A}$, cartesian"] + [xy(res.A, "in/s^2") for res in (at_A, at_B)],
        [r"$\mathbf{A}$ in SI"] + [vec(res.A, "m/s^2") for res in (at_A, at_B)],
        [r"$\lvert\mathbf{A}\rvert$ in $g$"] + [f"{num(in_g(res.A), 3)} g" for res in (at_A, at_B)],
    ],
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(6.5 * -500, "-3250")
stated(6.5 * 100**2, "65000")
stated(np.angle(at_A.A_t.magnitude, deg=True), "-45")
stated(abs(at_A.A_n), "65000", "in/s^2")
stated(abs(at_B.A_n), "58660", "in/s^2", sig=4)
stated(abs(at_A.A), "1650", "m/s^2", sig=2)
stated(in_g(at_A.A), "170", sig=2)

# %% [markdown]
# Each tangential part points $90^\circ$ *clockwise* from its radius
# ($45^\circ - 90^\circ = -45^\circ$ at $A$) because $\alpha < 0$, while the point itself still
# turns counter-clockwise: the body is slowing down. The normal parts, $65\,000$ and
# $58\,660$ in/s$^2$, dwarf the tangential ones; in SI that is about $1650$ m/s$^2$, some
# 170 g.
#
# **Step 3: the difference.** Eq. 7.5 with $B$ and $A$:
# $\mathbf{A}_{BA} = \mathbf{A}_B - \mathbf{A}_A$.

# %%
A_BA = at_B.A - at_A.A

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"$\mathbf{{A}}_{{BA}}$ = {xy(A_BA, 'in/s^2')} = {vec(A_BA, 'in/s^2')}, "
    rf"that is {vec(A_BA, 'm/s^2')}."
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
# the same difference, component by component (eq. 7.4 with both sides split)
parts = (at_B.A_t - at_A.A_t) + (at_B.A_n - at_A.A_n)
assert np.isclose(parts.to("in/s^2").magnitude, A_BA.to("in/s^2").magnitude)

# %% [markdown]
# Drawn to scale, as the problem asks: the two positions on their circle with their
# accelerations, and the vector triangle $\mathbf{A}_B = \mathbf{A}_A + \mathbf{A}_{BA}$.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Problem 7-1: the accelerations at positions $A$ and $B$ on their circle, and the vector triangle $\\mathbf{A}_B = \\mathbf{A}_A + \\mathbf{A}_{BA}$ of eq. 7.4."}}
def problem_7_1(narrow):
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.6, 4.0), tall=(4.4, 8.2), layout="constrained")
    ring = 6.5 * np.exp(1j * np.linspace(0, 2 * np.pi, 200))
    ax1.plot(ring.real, ring.imag, color="#bbbbbb", lw=1)
    scale = 6.5 / 80_000  # in of drawing per in/s^2
    for res, label in ((at_A, "A"), (at_B, "B")):
        z = complex(res.R.to("in").magnitude)
        ax1.plot([0, z.real], [0, z.imag], color="#4d4d4d", lw=3, solid_capstyle="round")
        ax1.scatter([z.real], [z.imag], s=40, facecolor="white", edgecolor="k", zorder=5)
        point_label(ax1, label, z, fontweight="bold")
        vector(ax1, z, complex(res.A_t.to("in/s^2").magnitude), "tangential", None, scale)
        A = complex(res.A.to("in/s^2").magnitude)
        vector(ax1, z, A, "resultant", rf"$\mathbf{{A}}_{label}$", scale)
    arc = 6.5 * np.exp(1j * np.linspace(np.radians(45), theta_B.to("rad").magnitude, 40))
    ax1.plot(1.12 * arc.real, 1.12 * arc.imag, color="#888888", lw=1)
    point_label(ax1, "0.01 s", 1.15 * arc[20], color="#555555", fontsize=10)
    ax1.scatter([0], [0], s=40, facecolor="white", edgecolor="k", zorder=5)
    point_label(ax1, "O", 0j)
    legend(ax1, ("tangential", "resultant"), loc="lower left")
    ax1.set_aspect("equal")
    ax1.set_xlabel("x [in]")
    ax1.set_ylabel("y [in]")
    ax1.set_title(f"arrows: 1 in = {num(1 / scale)} in/s$^2$")
    ax1.set_xlim(-8, 8)
    ax1.set_ylim(-4, 8.5)

    zA = complex(at_A.A.to("in/s^2").magnitude) / 1000
    zB = complex(at_B.A.to("in/s^2").magnitude) / 1000
    vector(ax2, 0j, zA, "resultant", r"$\mathbf{A}_A$")
    vector(ax2, 0j, zB, "known", r"$\mathbf{A}_B$")
    vector(ax2, zA, zB - zA, "tangential", r"$\mathbf{A}_{BA}$")
    ax2.scatter([0], [0], color="k", s=15)
    ax2.set_aspect("equal")
    ax2.set_xlabel("$A_x$ [1000 in/s$^2$]")
    ax2.set_ylabel("$A_y$ [1000 in/s$^2$]")
    ax2.set_title(r"$\mathbf{A}_B = \mathbf{A}_A + \mathbf{A}_{BA}$")
    ax2.set_xlim(-50, 25)
    ax2.set_ylim(-62, 8)
    return fig


show(
    problem_7_1,
    alt="The rotating link at two positions with acceleration arrows, and the triangle "
    "adding A_A and A_BA to give A_B.",
)

# %% [markdown]
# A caution on what we just computed. $A$ and $B$ here are *one particle at two instants*,
# so $\mathbf{A}_{BA}$ is the change of its acceleration over 10 ms, not the acceleration
# difference of two pins of a body at one instant. The subtraction is the same; the meaning
# is not, and none of the Case 1 rules (normal part along $BA$ of size $|BA|\,\omega^2$) apply
# to it. The next example compares the two real cases.

# %% [markdown]
# ## Worked example 2: acceleration difference or relative acceleration?
#
# **Case 1.** A carriage slides along $x$ with $\mathbf{A}_A = 12$ m/s$^2$ (no rotation: its
# acceleration has no normal part). A link $AP$, 0.3 m long, is pinned to it at $A$ and turns
# at $\theta = 60^\circ$ with $\omega = 8$ rad/s, $\alpha = -40$ rad/s$^2$. Seen from $A$, $P$ is
# a rotating point, so `RotatingPoint` gives $\mathbf{A}_{PA}$, and eq. 7.4 adds the carriage.
#
# **Case 2.** Two cars. Car $P$ takes a bend of radius 50 m (centre at the origin) at
# 15 m/s while speeding up at 2 m/s$^2$; car $A$, 20 m away, drives straight along $+x$
# and brakes at 6 m/s$^2$. Each car's own acceleration is known; their relative
# acceleration is eq. 7.5. A car on a circular path is a rotating point with
# $\omega = v/R$ and $\alpha = \dot v/R$.

# %%
# Case 1: one body
A_A1 = Q_(12 + 0j, "m/s^2")
link = RotatingPoint(p="0.3 m").solve(theta2="60 deg", omega2="8 rad/s", alpha2="-40 rad/s^2")
A_PA1 = link.A  # acceleration difference, about A
A_P1 = A_A1 + A_PA1  # eq. 7.4
R_PA1 = complex(link.R.to("m").magnitude)  # P as seen from A

# Case 2: two bodies
bend, v, v_dot = Q_(50, "m"), Q_(15, "m/s"), Q_(2, "m/s^2")
car_P = RotatingPoint(p=bend).solve(theta2="80 deg", omega2=v / bend, alpha2=v_dot / bend)
A_P2 = car_P.A
A_A2 = Q_(-6 + 0j, "m/s^2")
R_P2 = complex(car_P.R.to("m").magnitude)
R_A2 = R_P2 + 20 * np.exp(1j * np.radians(-110))  # car A is 20 m away
A_PA2 = A_P2 - A_A2  # relative acceleration, eq. 7.5


def angle_to_line(a_vec, from_p_to_a):
    """Angle between a vector and the line P->A [deg]."""
    z = complex(a_vec.to("m/s^2").magnitude)
    return np.degrees(np.angle(z / from_p_to_a))


n1 = link.A_n

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "vector", "angle to the line $P \\to A$"],
    [
        [r"Case 1: $\mathbf{A}_{PA}$", vec(A_PA1, "m/s^2"), ""],
        [
            r"Case 1: $\mathbf{A}^n_{PA}$",
            vec(n1, "m/s^2"),
            f"{num(abs(angle_to_line(n1, -R_PA1)), decimals=1)}°: along it",
        ],
        [r"Case 1: $\mathbf{A}_P$", vec(A_P1, "m/s^2"), ""],
        [r"Case 2: $\mathbf{A}_P$", vec(A_P2, "m/s^2"), ""],
        [r"Case 2: $\mathbf{A}_A$", vec(A_A2, "m/s^2"), ""],
        [
            r"Case 2: $\mathbf{A}_{PA}$",
            vec(A_PA2, "m/s^2"),
            f"{num(angle_to_line(A_PA2, R_A2 - R_P2), 3)}°: nothing special",
        ],
    ],
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Acceleration difference on one body (its normal part lies along $PA$) against relative acceleration of two bodies (no such rule)."}}
def two_cases(narrow):
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.6, 3.6), tall=(4.4, 7.0), layout="constrained")
    # case 1: carriage, link, vectors at P (drawing scale 0.3 m per 40 m/s^2)
    s1 = 0.3 / 40
    P1 = R_PA1
    ax1.add_patch(plt.Rectangle((-0.25, -0.08), 0.5, 0.08, fc="#dddddd", ec="#4d4d4d"))
    ax1.plot([0, P1.real], [0, P1.imag], color="#4d4d4d", lw=4, solid_capstyle="round")
    ax1.scatter([0, P1.real], [0, P1.imag], s=40, facecolor="white", edgecolor="k", zorder=5)
    point_label(ax1, "A", 0j)
    point_label(ax1, "P", P1)
    vector(ax1, 0j, complex(A_A1.magnitude), "known", r"$\mathbf{A}_A$", s1)
    At = complex(link.A_t.to("m/s^2").magnitude)
    vector(ax1, P1, At, "tangential", r"$\mathbf{A}^t_{PA}$", s1)
    An = complex(n1.to("m/s^2").magnitude)
    vector(ax1, P1, An, "normal", r"$\mathbf{A}^n_{PA}$", s1, beside=5)  # drawn beside the link
    vector(ax1, P1, complex(A_P1.to("m/s^2").magnitude), "resultant", r"$\mathbf{A}_P$", s1)
    ax1.plot([P1.real, 0], [P1.imag, 0], ls=":", color="#888888")
    ax1.set_aspect("equal")
    ax1.set_xlim(-0.3, 0.45)
    ax1.set_ylim(-0.15, 0.45)
    ax1.set_xlabel("x [m]")
    ax1.set_ylabel("y [m]")
    ax1.set_title("Case 1: one body.\n$\\mathbf{A}^n_{PA}$ lies along $PA$")
    # case 2: two cars on the road, vectors at the cars (drawing scale 2.5 m per m/s^2)
    s2 = 2.5
    road = 50 * np.exp(1j * np.radians(np.linspace(55, 105, 60)))
    ax2.plot(road.real, road.imag, color="#bbbbbb", lw=6, solid_capstyle="butt")
    ax2.plot([R_A2.real - 15, R_A2.real + 15], [R_A2.imag] * 2, color="#bbbbbb", lw=6)
    for z, name in ((R_P2, "P"), (R_A2, "A")):
        ax2.scatter([z.real], [z.imag], marker="s", s=60, color="#4d4d4d", zorder=5)
        point_label(ax2, f"car {name}", z)
    ax2.plot([R_P2.real, R_A2.real], [R_P2.imag, R_A2.imag], ls=":", color="#888888")
    vector(ax2, R_P2, complex(A_P2.to("m/s^2").magnitude), "resultant", r"$\mathbf{A}_P$", s2)
    vector(ax2, R_A2, complex(A_A2.magnitude), "known", r"$\mathbf{A}_A$", s2)
    A_PA = complex(A_PA2.to("m/s^2").magnitude)
    vector(ax2, R_P2, A_PA, "tangential", r"$\mathbf{A}_{PA}$", s2)
    ax2.set_aspect("equal")
    ax2.set_xlabel("x [m]")
    ax2.set_ylabel("y [m]")
    ax2.set_xlim(-20, 32)
    ax2.set_ylim(24, 54)
    ax2.set_title("Case 2: two bodies.\n$\\mathbf{A}_{PA}$ has no such rule")
    return fig


show(
    two_cases,
    alt="Two panels comparing a point pair on one rotating body with a point on each of "
    "two bodies, with their acceleration vectors.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(abs(n1), "19.2", "m/s^2")
stated(abs(angle_to_line(n1, -R_PA1)), "0")

# %% [markdown]
# In Case 1 the normal part of $\mathbf{A}_{PA}$ lies exactly on the line from $P$ to $A$
# ($0^\circ$) and has the size $|PA|\,\omega^2 = 0.3 \times 8^2 = 19.2$ m/s$^2$: we could
# have drawn its direction before computing anything. In Case 2 the relative acceleration
# makes an arbitrary angle with the line joining the cars; there is no link, no shared
# $\omega$, and no component with a direction known in advance.

# %% [markdown]
# ## Explore: how $\alpha$ and $\omega$ steer the acceleration
#
# The point keeps its radius (6.5 in) and angle ($45^\circ$); move $\alpha$ and $\omega$.
# Watch the angle $\varphi$ between $\mathbf{A}$ and the inward radius: $\tan\varphi =
# \alpha/\omega^2$. The tangential part swaps sides when $\alpha$ changes sign; flipping the
# sign of $\omega$ changes nothing at all.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The rotating point at four values of $\\alpha$ ($\\omega = 20$ rad/s), all in one frame at one arrow scale: only the tangential part changes."}}
BOX = (-3.0, 10.5, -3.5, 10.5)  # one frame [in] ...
SCALE = 6.5 / 12_000  # ... and one arrow scale [in per in/s^2] for every panel


def draw(alpha2, omega2):
    con = rotating("6.5 in", "45 deg", f"{omega2} rad/s", f"{alpha2} rad/s^2")
    A = abs(con.values["A"]) / 0.0254  # in/s^2
    phi = np.degrees(np.arctan2(alpha2, omega2**2))
    fig, ax = plt.subplots(figsize=(4.2, 4.4))
    ring = 6.5 * np.exp(1j * np.linspace(0, 2 * np.pi, 200))
    ax.plot(ring.real, ring.imag, color="#dddddd", lw=1)
    draw_linkage(
        con,
        ax=ax,
        scale=SCALE,
        box=BOX,
        names={"O2": "O"},
        legend=False,
        title=f"$\\omega$ = {omega2:g} rad/s: |A| = {A:,.0f} in/s$^2$, "
        f"$\\varphi$ = {phi:.0f}$^\\circ$",
    )
    ax.title.set_fontsize(10)
    return fig


explore(draw, alpha2=(-1500, 1500, 50, -500, "rad/s^2"), omega2=(-40, 40, 1, 20, "rad/s"))

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(6.5 * 20**2, "2600")
stated((100 / 20) ** 2, "25")
assert abs(np.degrees(np.arctan2(500, 100**2))) < 3  # "only a few degrees"

# %% [markdown]
# At $\omega = 20$ rad/s the normal part is $6.5 \times 400 = 2600$ in/s$^2$ whatever
# $\alpha$ is; only the tangential part grows, shrinks and swaps sides with $\alpha$. At
# $\omega = 100$ rad/s (problem 7-1) the normal part would be 25 times larger and $\varphi$ only
# a few degrees: at high speed the acceleration of a point on a crank points almost straight at
# the pivot.
#
# ### The point in motion
#
# Let the point start slowly ($\omega_0$ = 2 rad/s) and speed up at a constant
# $\alpha$ = 10 rad/s$^2$ through one turn: then $\omega^2 = \omega_0^2 + 2\alpha\theta$. The
# tangential part keeps its size, $p\alpha$; the normal part grows with $\omega^2$ and soon
# dominates, and the total acceleration swings round toward the pivot. The arrows are drawn at
# one scale; the marker runs along the curves of $\omega$ and of the sizes of the three vectors.
# Pause the player where the two parts are equal ($\omega^2 = \alpha$, early in the turn) and
# step on from there.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Animation: a point 6.5 in from its pivot speeding up from 2 rad/s at 10 rad/s² through one turn, with $\\omega$ and the sizes of its acceleration components. Play, pause, step or drag the slider."}}
def speeding_up(theta2_deg, omega0=2.0, alpha=10.0):
    """omega at the angle theta2 [deg] for a start at omega0 [rad/s], constant alpha."""
    return {"omega2": f"{np.sqrt(omega0**2 + 2 * alpha * np.radians(theta2_deg)):.6f} rad/s"}


animate(
    {
        "mechanism": "rotation",
        "p": "6.5 in",
        "theta2": "0 deg",
        "omega2": "2 rad/s",
        "alpha2": "10 rad/s^2",
    },
    motion=speeding_up,
    kinds=("tangential", "normal", "resultant"),
    title="6.5 in link speeding up",
    names={"O2": "O"},
    alt="A turning link whose acceleration arrows grow as it speeds up, beside plots of "
    "omega and of the acceleration sizes with a moving marker.",
)

# %% [markdown]
# ## Check yourself
#
# **1.** A point is 0.2 m from its pivot at $\theta = 90^\circ$ (straight up), with
# $\omega = 5$ rad/s and $\alpha = 0$. Which way does its acceleration point, and how big is it?
#
# <details><summary>Answer</summary>
#
# Straight down, toward the pivot: only the normal part exists, $p\omega^2 = 0.2 \times 25 =
# 5$ m/s$^2$, so $\mathbf{A} = -5j$ m/s$^2$ $= 5\,e^{j270^\circ}$ m/s$^2$.
#
# </details>
#
# **2.** Same point, now with $\omega = -5$ rad/s and $\alpha = -30$ rad/s$^2$. Give
# $\mathbf{A}$ in cartesian form.
#
# <details><summary>Answer</summary>
#
# The normal part is unchanged, $-5j$ m/s$^2$. The tangential part is
# $p\alpha\,je^{j90^\circ} = 0.2(-30)(j\cdot j) = +6$ m/s$^2$, i.e. along $+x$ (clockwise from
# straight up). So $\mathbf{A} = 6 - 5j$ m/s$^2$, $7.81$ m/s$^2$ at $-39.8^\circ$.
#
# </details>
#
# **3.** Two pins $A$ and $B$ of one link are 0.1 m apart and the link has $\omega = 10$ rad/s.
# What do you know about $\mathbf{A}_{BA}$ before knowing $\alpha$?
#
# <details><summary>Answer</summary>
#
# Its normal part: 10 m/s$^2$ ($0.1 \times 10^2$), along the line from $B$ toward $A$. And the
# direction of its tangential part: perpendicular to $AB$. Only the size (and sense) of the
# tangential part waits for $\alpha$. That is Case 1, and it is exactly what the graphical
# method of the next notebook uses.
#
# </details>
#
# **4.** In problem 7-1, why is $|\mathbf{A}_B| < |\mathbf{A}_A|$?
#
# <details><summary>Answer</summary>
#
# The normal part dominates and grows with $\omega^2$; $\omega$ fell from 100 to 95 rad/s, so
# $p\omega^2$ fell by about 10 % (from 65 000 to 58 660 in/s$^2$). The tangential part
# $|p\alpha| = 3250$ in/s$^2$ is the same at both positions.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
# the answers above, checked against the solver
q = RotatingPoint(p="0.2 m")
a1 = q.solve(theta2="90 deg", omega2="5 rad/s", alpha2="0 rad/s^2").A.to("m/s^2").magnitude
assert np.isclose(a1, -5j)
a2 = q.solve(theta2="90 deg", omega2="-5 rad/s", alpha2="-30 rad/s^2").A.to("m/s^2").magnitude
assert np.isclose(a2, 6 - 5j)
stated(abs(a2), "7.81")
stated(np.angle(a2, deg=True), "-39.8")
stated(0.1 * 10**2, "10")
stated(100 * (1 - (abs(at_B.A_n) / abs(at_A.A_n)).magnitude), "10", sig=1)
stated(abs(at_A.A_t), "3250", "in/s^2")
stated(abs(at_B.A_t), "3250", "in/s^2")

# %% [markdown]
# ## Further problems
#
# Problems in the style of the chapter's problem set (its problem 7-1 is worked above). Try
# them on paper first; the answers are folded.
#
# **Problem 1.1.** A point of a flywheel 150 mm from its centre is at $\theta = 210^\circ$. The
# flywheel turns clockwise at 30 rad/s and is being slowed at 400 rad/s$^2$ (so
# $\omega = -30$ rad/s, $\alpha = +400$ rad/s$^2$). (a) Find the tangential and normal
# components of the point's acceleration and the total, in polar and cartesian form. (b) What
# angle does the acceleration make with the line from the point to the centre? (c) At what
# speed $|\omega|$, with the same $\alpha$, would the two components be equal?
#
# <details><summary>Answer</summary>
#
# (a) $A^t = p\alpha = 0.15 \times 400 = 60$ m/s$^2$, perpendicular to the radius and turned
# counter-clockwise from it ($\alpha > 0$): at $300^\circ$, $(30 - 51.96j)$ m/s$^2$.
# $A^n = p\omega^2 = 0.15 \times 900 = 135$ m/s$^2$ toward the centre, at $30^\circ$:
# $(116.91 + 67.5j)$ m/s$^2$. The total is $(146.91 + 15.54j)$ m/s$^2$ $= 147.7$ m/s$^2$ at
# $6.04^\circ$.
#
# (b) $\tan\varphi = \alpha/\omega^2 = 400/900$, $\varphi = 23.96^\circ$ from the inward
# radius, on the side of $\alpha$.
#
# (c) $p\alpha = p\omega^2$ when $\omega^2 = \alpha$: $|\omega| = 20$ rad/s.
#
# </details>
#
# **Problem 1.2.** Two pins $A$ and $B$ of one rigid link are 120 mm apart, $B$ at $60^\circ$
# from $A$. The link turns at $\omega = 6$ rad/s and $\alpha = -25$ rad/s$^2$, and pin $A$
# accelerates at $\mathbf{A}_A = (2 - 4j)$ m/s$^2$. Find $\mathbf{A}_B$ (eq. 7.4).
#
# <details><summary>Answer</summary>
#
# $B$ turns about $A$ with the link (Case 1): $\mathbf{A}_{BA} = p\alpha\,je^{j60^\circ} -
# p\omega^2e^{j60^\circ}$ with $p = 0.12$ m: $A^t_{BA} = 3$ m/s$^2$ at $-30^\circ$, $A^n_{BA}
# = 4.32$ m/s$^2$ at $240^\circ$, so $\mathbf{A}_{BA} = (0.438 - 5.241j)$ m/s$^2$ and
# $\mathbf{A}_B = \mathbf{A}_A + \mathbf{A}_{BA} = (2.438 - 9.241j)$ m/s$^2$, 9.557 m/s$^2$ at
# $-75.22^\circ$.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
# the folded answers, computed
f = RotatingPoint(p="150 mm").solve(theta2="210 deg", omega2="-30 rad/s", alpha2="400 rad/s^2")
At, An, A = (complex(getattr(f, k).to("m/s^2").magnitude) for k in ("A_t", "A_n", "A"))
stated(abs(At), "60")
stated(np.angle(At, deg=True) % 360, "300")
stated(At.real, "30")
stated(At.imag, "-51.96")
stated(abs(An), "135")
stated(np.angle(An, deg=True), "30")
stated(An.real, "116.91")
stated(An.imag, "67.5")
stated(A.real, "146.91")
stated(A.imag, "15.54")
stated(abs(A), "147.7")
stated(np.angle(A, deg=True), "6.04")
stated(np.degrees(np.arctan2(400, 900)), "23.96")
stated(np.sqrt(400), "20")
BA = RotatingPoint(p="120 mm").solve(theta2="60 deg", omega2="6 rad/s", alpha2="-25 rad/s^2")
A_BA = complex(BA.A.to("m/s^2").magnitude)
stated(abs(BA.A_t), "3", "m/s^2")
stated(np.angle(BA.A_t.magnitude, deg=True), "-30")
stated(abs(BA.A_n), "4.32", "m/s^2")
stated(np.angle(BA.A_n.magnitude, deg=True) % 360, "240")
stated(A_BA.real, "0.438")
stated(A_BA.imag, "-5.241")
A_B = 2 - 4j + A_BA
stated(A_B.real, "2.438")
stated(A_B.imag, "-9.241")
stated(abs(A_B), "9.557")
stated(np.angle(A_B, deg=True), "-75.22")
# %% [markdown]
# ## Practice
#
# Problems like problem 7-1 with instant feedback, for self-study: not graded, and never one
# of a graded assignment's. Each run of the next cell draws a fresh problem (or give it a
# seed, e.g. `practice("rotation", seed=12)`, to come back to one; `mine.seed` tells you the
# seed of the one you have). Work it out, then hand each answer to `mine.check`: it says at once
# whether it is right and, if not, what to look at (the unit, the sign, the size). A bare number
# is read in the unit the problem asks for; a Quantity may be in any unit of the right kind.
#
# The graded exercise family that practises this notebook is `rotation` (problem 7-1 style);
# the instructor's guide lists every family with the notebooks that teach it.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 2 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("rotation")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("A_A_x", Q_(-48500, "in/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 2: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("rotation", seed=2)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like.** The problem of seed 2, solved with the solver (`RotatingPoint`,
# as in the worked example) and checked; then the same answer with its sign flipped, and in the
# wrong kind of unit:

# %%
example = practice("rotation", seed=2, show=False)
g = example.given
point = RotatingPoint(p=g["p"])
at_A = point.solve(theta2=g["theta_A"], omega2=g["omega"], alpha2=g["alpha"])
assert example.check("A_A_x", at_A.A.real.to("in/s^2"))  # right
assert not example.check("A_A_x", -at_A.A.real.to("in/s^2"))  # a sign error
assert not example.check("A_A_x", Q_(at_A.A.real.to("in/s^2").magnitude, "in/s"))  # a velocity unit

# %% [markdown]
# ## Common mistakes
#
# - **Degrees in $\omega t$.** $\theta_B = \theta_A + \omega t + \tfrac12\alpha t^2$ holds in
#   radians; adding $0.975$ to $45$ "degrees" puts $B$ in the wrong place. Let pint carry the
#   units, as above.
# - **Letting $\omega$'s sign steer the normal part.** $\omega^2$ is never negative: the normal
#   part always points at the centre of rotation.
# - **Letting $\omega$'s sign steer the tangential part.** It follows $\alpha$, and $\alpha$ may
#   oppose $\omega$ (a slowing body, as in problem 7-1).
# - **Treating a relative acceleration like an acceleration difference.** The normal part
#   "along the line joining the points" belongs to two points of *one* rigid body only.
# - **Mixing in/s$^2$ and ft/s$^2$**, or dividing by $g = 9.81$ with accelerations in in/s$^2$
#   ($g = 386$ in/s$^2$). Convert with units, not by memory.
#
# [Next: 2. Graphical acceleration analysis of a fourbar](02_graphical_fourbar.ipynb)
