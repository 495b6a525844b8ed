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
# # 7. The acceleration of any point
#
# Once every link's $\omega$ and $\alpha$ are known, the acceleration of *any* point of *any* link
# follows from one equation. This notebook uses it for coupler points, whose paths a designer
# shapes, and for centres of gravity, where Newton's second law will act. It follows section 7.5
# of the chapter (Robert L. Norton, *Design of Machinery*, chapter 7, eqs. 7.30 to 7.32).
#
# **You will be able to**
#
# - write the acceleration of a point on a crank, a rocker or a coupler (eqs. 7.30-7.32) from the
#   link's angle, its internal offset angle $\delta$ and its $\omega$, $\alpha$;
# - get it from the solver, for a coupler point (`p`, `delta3`) or for any point of any link
#   (`Result.point`), at one position or over a cycle;
# - see on a coupler curve where a point accelerates hardest;
# - turn the accelerations of the centres of gravity into the forces $m\mathbf{A}_G$ that the
#   dynamic force analysis needs, in lbf and in newtons.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import Normalize

from accelab.course.animation import animate
from accelab.course.kit import COLORS, explore, in_g, stated, use_style, vector
from accelab.course.practice import practice
from accelab.course.renditions import show
from accelab.course.text import num, say, table, vec, xy
from accelab.solver import Q_, FourBar

use_style()

# %% [markdown]
# ## The idea and its equations
#
# Angular acceleration is a *free vector*: a link has one $\alpha$, whatever point you look
# at. So a point fixed on a link accelerates like a point on a rotating radius, measured from
# any other point of the same link whose acceleration is known (eq. 7.4).
#
# **A point S on the crank**, at the distance $s$ from $O_2$ and the constant angle $\delta_2$
# from the line $O_2A$. It turns about a fixed pivot, so
#
# $$ \mathbf{R}_S = s\,e^{j(\theta_2+\delta_2)} \tag{4.25} $$
#
# $$ \begin{aligned} \mathbf{A}_S = {} & s\alpha_2\, je^{j(\theta_2+\delta_2)} \\
#    & - s\omega_2^2\, e^{j(\theta_2+\delta_2)} \end{aligned} \tag{7.30} $$
#
# **A point U on the rocker**, at $u$ from $O_4$ and the angle $\delta_4$ from $O_4B$: the
# same form with link 4's motion,
#
# $$ \begin{aligned} \mathbf{A}_U = {} & u\alpha_4\, je^{j(\theta_4+\delta_4)} \\
#    & - u\omega_4^2\, e^{j(\theta_4+\delta_4)} \end{aligned} \tag{7.31} $$
#
# **A point P on the coupler**, at $p$ from A and the angle $\delta_3$ from the line AB. The
# coupler has no fixed pivot, so start from A, whose acceleration we know, and add the
# acceleration difference of P from A:
#
# $$ \mathbf{A}_P = \mathbf{A}_A + \mathbf{A}_{PA} \tag{7.32a} $$
#
# $$ \begin{aligned} \mathbf{A}_{PA} = {} & p\alpha_3\, je^{j(\theta_3+\delta_3)} \\
#    & - p\omega_3^2\, e^{j(\theta_3+\delta_3)} \end{aligned} \tag{7.32b} $$
#
# Eq. 7.32 is eq. 7.4 again. It works for any point of any rigid link, referred to any other
# point of the same link, once positions and velocities are known.

# %% [markdown]
# ## Worked examples
#
# ### 1. A coupler point and three centres of gravity
#
# The fourbar $a$ = 2 in, $b$ = 6 in, $c$ = 9 in, $d$ = 7 in at $\theta_2 = 30°$,
# $\omega_2$ = 10 rad/s, $\alpha_2$ = -5 rad/s². The coupler is a triangular plate with the
# point P at $p$ = 3 in, $\delta_3$ = 30°: the linkage, input and coupler point of the course's
# Example 7-1 (notebook 2; the chapter's example prints no numbers, **these are the course's
# own numbers**). Its centre of gravity $G_3$ is the centroid of the triangle A, B, P; the
# crank's and rocker's centres of gravity are at their middles.

# %%
fourbar = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
motion = dict(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")
r = fourbar.solve(**motion, p="3 in", delta3="30 deg")

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "value"],
    [
        [r"$\alpha_3$, $\alpha_4$", f"{num(r.alpha3)}, {num(r.alpha4)} rad/s²"],
        [r"$\mathbf{A}_A$", vec(r.A_A, "in/s^2")],
        [r"$\mathbf{A}_P$", f"{vec(r.A_P, 'in/s^2')} = {vec(r.A_P, 'm/s^2')}"],
    ],
)

# %% [markdown]
# Eq. 7.32 written out by hand, checked against the solver:

# %%
p, delta3 = 3.0, np.radians(30)  # in, rad
t3, w3, a3 = r.theta3.magnitude, r.omega3.magnitude, r.alpha3.magnitude
A_PA = p * a3 * 1j * np.exp(1j * (t3 + delta3)) - p * w3**2 * np.exp(
    1j * (t3 + delta3)
)  # eq. 7.32b
A_P = r.A_A.to("in/s^2").magnitude + A_PA  # eq. 7.32a
assert np.isclose(A_P, r.A_P.to("in/s^2").magnitude, rtol=1e-12)
say(rf"By hand, $\mathbf{{A}}_P$ = {xy(A_P, 'in/s^2', sig=6)}: the solver's value.")

# %% [markdown]
# For points that are not the coupler point, `Result.point(link, p, delta)` gives the
# position, velocity, acceleration (and its tangential and normal parts about the link's base
# pin) and jerk of any point of link 2, 3 or 4, with no new solve. The coupler's centroid, in
# the coupler's own frame (A at the origin, B on the x axis), is $(0 + b + p e^{j\delta_3})/3$:

# %%
g3 = (0 + 6 + 3 * np.exp(1j * delta3)) / 3  # in, from A, in link 3's frame
cg = {
    "S = G2": (2, "1 in", "0 deg"),
    "G3": (3, f"{abs(g3)} in", f"{np.degrees(np.angle(g3))} deg"),
    "U = G4": (4, "4.5 in", "0 deg"),
}
points = {name: r.point(*spec) for name, spec in cg.items()}

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"$G_3$ is {num(abs(g3), 5)} in from $A$, at {num(np.degrees(np.angle(g3)), 5)}° from "
    "$AB$. The accelerations of the three centres of gravity:"
)
table(
    ["point", "acceleration", "in g"],
    [
        [
            name.replace("G2", "$G_2$").replace("G3", "$G_3$").replace("G4", "$G_4$"),
            vec(pm.A, "in/s^2"),
            f"{num(in_g(pm.A), 3)} g",
        ]
        for name, pm in points.items()
    ],
)
# the solver's coupler point and Result.point agree
assert np.isclose(r.point(3, "3 in", "30 deg").si("A"), r.si("A_P"))

# %% [markdown]
# The drawing puts each acceleration at its point (one scale for all). Points of one link
# share $\alpha$ and $\omega$ but not their accelerations: the farther from the link's
# instantaneous centre of zero acceleration, the larger.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The accelerations of the pins $A$ and $B$, the coupler point $P$ and the centres of gravity at $\\theta_2 = 30^\\circ$, drawn at their points at one scale."}}
def linkage_points(res, i=None):
    """Pin positions [in] (complex) of a result, at index i of a sweep."""
    pick = (lambda z: z) if i is None else (lambda z: z[i])
    return {k: pick(getattr(res, "R_" + k).to("in").magnitude) for k in ("A", "B", "P")}


def draw_fourbar(ax, pins, colour="#4d4d4d"):
    O2, O4 = 0j, 7 + 0j
    A, B, P = pins["A"], pins["B"], pins["P"]
    ax.fill([A.real, B.real, P.real], [A.imag, B.imag, P.imag], color="#d9d9d9", ec=colour, lw=1.2)
    for z0, z1 in ((O2, A), (B, O4)):
        ax.plot([z0.real, z1.real], [z0.imag, z1.imag], color=colour, lw=4, solid_capstyle="round")
    ax.plot([O2.real, O4.real], [0, 0], "^", color="#222222", ms=10)
    ax.scatter([A.real, B.real], [A.imag, B.imag], s=36, c="white", edgecolors="#222222", zorder=5)


def at_their_points(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 4.8) if narrow else (7.4, 4.8), layout="constrained")
    pins = linkage_points(r)
    draw_fourbar(ax, pins)
    scale = 0.008  # in of drawing per in/s^2
    ends = [0j, 7 + 0j]
    here = {"A": r.A_A, "P": r.A_P, "B": r.A_B, **{k: pm.A for k, pm in points.items()}}
    where = {
        "A": pins["A"],
        "P": pins["P"],
        "B": pins["B"],
        **{k: pm.R.to("in").magnitude for k, pm in points.items()},
    }
    for name, A in here.items():
        z0 = where[name]
        ax.plot(z0.real, z0.imag, "o", color="black", ms=4, zorder=6)
        tip = vector(ax, z0, A.to("in/s^2").magnitude, "resultant", scale=scale)
        ends += [z0, tip]
        label = name.replace("G2", "$G_2$").replace("G3", "$G_3$").replace("G4", "$G_4$")
        ax.annotate(label, (z0.real, z0.imag), textcoords="offset points", xytext=(6, 6))
    ax.set_xlim(min(z.real for z in ends) - 0.5, max(z.real for z in ends) + 0.5)
    ax.set_ylim(min(z.imag for z in ends) - 0.5, max(z.imag for z in ends) + 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x [in]")
    ax.set_ylabel("y [in]")
    ax.set_title(f"1 in of arrow = {1 / scale:.0f} in/s$^2$")
    return fig


show(
    at_their_points,
    alt="Fourbar drawing with acceleration arrows at A, B, the coupler point and the three "
    "centres of gravity.",
)

# %% [markdown]
# ### 2. Coupler curves coloured by acceleration
#
# Over a whole crank turn (steady 10 rad/s) the coupler point traces its coupler curve.
# Colouring the curve by $|\mathbf{A}_P|$ shows *where on its path* a point accelerates
# hardest: usually on the tight bends traversed quickly. Each panel draws the linkage at
# $\theta_2 = 60°$ with the chosen point (star) tied to A by a dashed line; a point outside the
# plate is still a point of link 3, as if the plate were larger. One sweep solves the linkage;
# `Result.point` then gives every other point of the coupler without solving again.

# %%
theta = Q_(np.linspace(0, 2 * np.pi, 361), "rad")
cycle = fourbar.solve(theta2=theta, omega2="10 rad/s", p="3 in", delta3="30 deg")
assert cycle.valid.all()
choices = {
    r"P: $p$ = 3 in, $\delta_3$ = 30°": ("3 in", "30 deg"),
    r"$G_3$, the centroid": (f"{abs(g3)} in", f"{np.degrees(np.angle(g3))} deg"),
    r"$p$ = 8 in, $\delta_3$ = -30°": ("8 in", "-30 deg"),
}


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The coupler curves of three points of the coupler over a cycle at 10 rad/s, coloured by the size of their acceleration; a circle marks each point's largest acceleration, a star the point at $\\theta_2 = 60^\\circ$."}}
def coupler_curves(narrow):
    norm = Normalize(0, 500)
    fig, axes = plt.subplots(
        3 if narrow else 1,
        1 if narrow else 3,
        figsize=(4.4, 10.2) if narrow else (7.8, 3.5),
        sharex=True,
        sharey=True,
        layout="constrained",
    )
    for ax, (label, (pp, dd)) in zip(axes, choices.items()):
        pm = cycle.point(3, pp, dd)
        z = pm.R.to("in").magnitude
        A = np.abs(pm.A.to("in/s^2").magnitude)
        xy_ = np.column_stack([z.real, z.imag])
        lc = LineCollection(np.stack([xy_[:-1], xy_[1:]], axis=1), cmap="viridis", norm=norm, lw=3)
        lc.set_array(A[:-1])
        ax.add_collection(lc)
        k = np.argmax(A)
        ax.plot(z.real[k], z.imag[k], "o", mfc="none", mec="black", ms=10)
        ax.annotate(
            f"max {A[k]:.0f} in/s²",
            (z.real[k], z.imag[k]),
            textcoords="offset points",
            xytext=(8, -20),
            fontsize=10,
        )
        draw_fourbar(ax, linkage_points(cycle, 60))  # the plate A, B, P at theta2 = 60 deg
        A60 = cycle.R_A[60].to("in").magnitude
        ax.plot([A60.real, z[60].real], [A60.imag, z[60].imag], color="#4d4d4d", lw=1, ls="--")
        ax.plot(z[60].real, z[60].imag, "*", color="black", ms=11, zorder=7)
        ax.set_title(label)
        ax.set_aspect("equal")
        ax.set_xlabel("x [in]")
        ax.set_ylabel("y [in]")
    fig.colorbar(
        lc,
        ax=axes,
        label=r"$|\mathbf{A}|$ [in/s$^2$]",
        shrink=0.8,
        orientation="horizontal" if narrow else "vertical",
    )
    return fig


show(
    coupler_curves,
    alt="Three coupler curves of points of the coupler, coloured from low to high "
    "acceleration, with the linkage drawn at one position.",
)

# %% [markdown]
# ### 3. Ready for F = m a
#
# The forces that make the links move are $m\mathbf{A}_G$, one per link, applied at its centre
# of gravity (with a torque $I_G\alpha$ about it, which needs the $\alpha$ we already have).
# Give the links masses: crank 0.2 lb, coupler plate 0.6 lb, rocker 0.8 lb, and run the crank
# at a steady 300 rpm. pint carries the units, including the US trap that a pound of *mass* at
# 1 g needs a pound of *force*: it knows $g_c$ and converts lb·in/s² to lbf.

# %%
masses = {"S = G2": Q_(0.2, "lb"), "G3": Q_(0.6, "lb"), "U = G4": Q_(0.8, "lb")}
fast = fourbar.solve(theta2=theta, omega2="300 rpm", alpha2=0)
assert fast.valid.all()
force = {name: masses[name] * fast.point(*spec).A for name, spec in cg.items()}  # m A_G
size = {name: np.abs(f.m_as("lbf")) for name, f in force.items()}

# %% tags=["hide-input"] jupyter={"source_hidden": true}
rows = []
for name, s in size.items():
    k = np.argmax(s)
    at = (
        rf"$\theta_2$ = {num(np.degrees(theta.magnitude[k]), decimals=0)}°"
        if np.ptp(s) > 1e-9 * s[k]
        else r"every angle ($s\omega_2^2$, constant)"
    )
    label = name.replace("G2", "$G_2$").replace("G3", "$G_3$").replace("G4", "$G_4$")
    rows.append(
        [
            label,
            f"{num(masses[name].m_as('lb'), decimals=1)} lb",
            f"{num(s[k], 3)} lbf",
            f"{num(Q_(s[k], 'lbf').m_as('N'), 3)} N",
            at,
        ]
    )
say(
    f"One pound of mass at 1 g needs {num((Q_(1, 'lb') * Q_(1, 'standard_gravity')).m_as('lbf'), 4)} "
    "lbf. The largest force each link's centre of gravity needs:"
)
table(["", "mass", r"largest $\lvert m\mathbf{A}_G\rvert$", "", "at"], rows)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The force needed to accelerate each link, $|m\\mathbf{A}_G|$ of its centre of gravity, over a cycle at 300 rpm."}}
def forces(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 3.9) if narrow else (7.4, 3.6), layout="constrained")
    colour = {"S = G2": COLORS["normal"], "G3": "black", "U = G4": COLORS["tangential"]}
    for name, s in size.items():
        label = name.replace("G2", "$G_2$").replace("G3", "$G_3$").replace("G4", "$G_4$")
        ax.plot(
            np.degrees(theta.magnitude), s, color=colour[name], label=f"{label}, {masses[name]:~P}"
        )
    ax.set_xlabel(r"crank angle $\theta_2$ [deg]")
    ax.set_ylabel(r"$|m\,\mathbf{A}_G|$ [lbf]")
    ax.set_xticks(range(0, 361, 90 if narrow else 60))
    secondary = ax.secondary_yaxis(
        "right", functions=(lambda f: f * 4.4482216, lambda n: n / 4.4482216)
    )
    secondary.set_ylabel("[N]")
    ax.legend()
    return fig


show(
    forces,
    alt="Line plots of force against crank angle for the crank, coupler and rocker.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
accel = {name: np.abs(fast.point(*spec).A.m_as("in/s^2")) for name, spec in cg.items()}
stated(size["S = G2"].max(), "0.5", sig=1)
stated(np.ptp(size["S = G2"]), "0")
stated(size["G3"].max() / size["S = G2"].max(), "10", sig=1)
stated(size["U = G4"].max() / size["S = G2"].max(), "9", sig=1)
for name in ("G3", "U = G4"):
    stated(np.degrees(theta.magnitude[np.argmax(size[name])]), "50", sig=1)
assert accel["U = G4"].max() < accel["G3"].max() and masses["U = G4"] > masses["G3"]
# "where the rocker's angular acceleration alpha4 is largest": within 3 degrees of both peaks
peak_alpha4 = np.degrees(theta.magnitude[np.argmax(np.abs(fast.alpha4.magnitude))])
for name in ("G3", "U = G4"):
    assert abs(np.degrees(theta.magnitude[np.argmax(size[name])]) - peak_alpha4) <= 3

# %% [markdown]
# At 300 rpm the crank's centre of gravity needs half a pound-force all the time; the coupler
# and the rocker need nine to ten times as much, both near $\theta_2 \approx 50°$, where the
# rocker's angular acceleration $\alpha_4$ is at its largest. The rocker's centre of gravity
# accelerates less than the coupler's, but it is heavier: force is mass times acceleration,
# and both matter. These curves are the inputs the dynamic force analysis (a later chapter)
# starts from.
#
# **The coupler point in motion**: the linkage through one turn at a steady 10 rad/s, the
# coupler curve of P dashed, and at P the triangle of eq. 7.32a drawn at every position: the
# acceleration of the pin, $\mathbf{A}_A$ (grey, copied to P), plus the acceleration
# difference $\mathbf{A}_{PA}$ (grey, from its tip), closed by $\mathbf{A}_P$ (black). The
# marker runs along $\alpha_3$ and the sizes of the three vectors. Step through the turn and
# watch $\mathbf{A}_{PA}$, which turns with the coupler, swing $\mathbf{A}_P$ away from
# $\mathbf{A}_A$.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Animation: the coupler point $P$ of Example 7-1 tracing its coupler curve (dashed) at 10 rad/s, with eq. 7.32a drawn at $P$, $\\mathbf{A}_P = \\mathbf{A}_A + \\mathbf{A}_{PA}$, and a marker on $\\alpha_3$ and the three sizes. Play, pause, step or drag the slider."}}
def triangle_at_P(con):
    """Eq. 7.32a at P: A_A copied to P, then A_PA from its tip (start [m], or
    (point [m], offset [m/s^2]) for the tip of the arrow before; vector [m/s^2])."""
    v = con.values
    P = con.linkage.points["P"]
    return [
        (P, v["A_A"], "known", r"$\mathbf{A}_A$"),
        ((P, v["A_A"]), v["A_PA"], "known", r"$\mathbf{A}_{PA}$"),
    ]


animate(
    {
        "mechanism": "fourbar",
        "a": "2 in",
        "b": "6 in",
        "c": "9 in",
        "d": "7 in",
        "p": "3 in",
        "delta3": "30 deg",
        "theta2": "0 deg",
        "omega2": "10 rad/s",
        "alpha2": "0 rad/s^2",
    },
    curves=("alpha3",),
    magnitudes=("A_A", "A_PA", "A_P"),
    trace=("P",),
    extra=triangle_at_P,
    title="Coupler point P",
    alt="The fourbar turning with its coupler curve dashed; at P the acceleration of A, the "
    "acceleration difference of P from A and their sum A_P, beside plots of alpha3 and the "
    "three sizes with a moving marker.",
)

# %% [markdown]
# ## Explore
#
# Move the coupler point around the coupler: the angle $\delta_3$ from AB turns it about A (and,
# live, $p$ moves it away from A). Watch the shape of the coupler curve and where its hottest
# stretch is.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Coupler points at several angles $\\delta_3$ on the coupler ($p$ = 3 in): their paths coloured by the size of their acceleration."}}
NORM = Normalize(0, 600)


def draw(delta3=30, p=3.0):
    res = fourbar.solve(theta2=theta, omega2="10 rad/s", p=f"{p} in", delta3=f"{delta3} deg")
    z = res.R_P.to("in").magnitude
    A = np.abs(res.A_P.to("in/s^2").magnitude)
    fig, ax = plt.subplots(figsize=(4.6, 4.4))
    xy = np.column_stack([z.real, z.imag])
    lc = LineCollection(np.stack([xy[:-1], xy[1:]], axis=1), cmap="viridis", norm=NORM, lw=3)
    lc.set_array(A[:-1])
    ax.add_collection(lc)
    fig.colorbar(lc, ax=ax, label=r"$|\mathbf{A}_P|$ [in/s$^2$]", extend="max")
    draw_fourbar(ax, linkage_points(res, 60))
    ax.set_xlim(
        min(-6, z.real.min() - 1), max(10, z.real.max() + 1)
    )  # one frame unless P leaves it
    ax.set_ylim(min(-6, z.imag.min() - 1), max(10, z.imag.max() + 1))
    ax.set_aspect("equal")
    ax.set_xlabel("x [in]")
    ax.set_ylabel("y [in]")
    ax.set_title(
        rf"$p$ = {p:g} in, $\delta_3$ = {delta3}°: largest $|\mathbf{{A}}_P|$ {A.max():.0f} in/s²",
        fontsize=11,
    )
    return fig


explore(draw, delta3=(0, 360, 10, 30, "deg"), p=(0.5, 10, 0.5, 3.0, "in"))

# %% [markdown]
# ## Check yourself
#
# 1. Two points of the same coupler: do they have the same angular acceleration? The same linear
#    acceleration?
#
# <details><summary>Answer</summary>
#
# Same $\alpha_3$ (and $\omega_3$): angular acceleration is a free vector, a property of the link.
# Different linear accelerations: $\mathbf{A}_{PA}$ depends on where P is ($p$, $\delta_3$).
#
# </details>
#
# 2. Why does eq. 7.32 start from A and not from $O_2$?
#
# <details><summary>Answer</summary>
#
# Eq. 7.4 relates two points *of the same rigid body*. P is on the coupler; $O_2$ is not. A is a
# point of the coupler (the pin it shares with the crank) whose acceleration we already know.
# Starting from B works as well, with the angle measured from BA.
#
# </details>
#
# 3. A point on the coupler at $p = 0$: what is its acceleration?
#
# <details><summary>Answer</summary>
#
# $\mathbf{A}_A$: it *is* A. Eq. 7.32b gives $\mathbf{A}_{PA} = 0$.
#
# </details>
#
# 4. A 0.6 lb coupler's centre of gravity accelerates at 2 g. What force must act on it, in lbf
#    and in N?
#
# <details><summary>Answer</summary>
#
# 1.2 lbf, about 5.3 N: a pound of mass at 1 g needs a pound of force
# ($m a = 0.6\ \text{lb} \times 2 \times 386\ \text{in/s}^2 = 463\ \text{lb·in/s}^2$, and
# $1\ \text{lbf} = 386\ \text{lb·in/s}^2$).
#
# </details>
#
# 5. The crank runs at a steady speed. Does its centre of gravity have a tangential acceleration?
#
# <details><summary>Answer</summary>
#
# No: $\alpha_2 = 0$, so eq. 7.30 leaves only the normal part $s\omega_2^2$ toward $O_2$. The
# coupler's and rocker's centres of gravity still have both parts, because $\alpha_3$ and
# $\alpha_4$ are not zero.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
f4 = Q_(0.6, "lb") * Q_(2, "standard_gravity")
stated(f4, "1.2", "lbf")
stated(f4, "5.3", "N")
stated(f4, "463", "lb*in/s^2")
stated(Q_(1, "lbf"), "386", "lb*in/s^2")
stated(Q_(1, "lbf"), "386.09", "lb*in/s^2")
assert np.isclose(r.point(3, "0 in", "0 deg").si("A"), r.si("A_A"))  # p = 0 is A
crank_cg = fast.point(2, "1 in", "0 deg")
assert np.allclose(np.abs(crank_cg.A_t.magnitude), 0, atol=1e-9)  # steady crank

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set; solve them with eqs. 7.30 to 7.32 on paper, then
# check with `FourBar` and `Result.point`. The answers are folded.
#
# **Problem 7.1.** In the Example 7-1 linkage at its position (the course's numbers: $\theta_2 =
# 30^\circ$, $\omega_2$ = 10 rad/s, $\alpha_2$ = -5 rad/s$^2$), a point U of the rocker lies
# 6 in from $O_4$, at $\delta_4 = 20^\circ$ from the line $O_4B$. Find $\mathbf{A}_U$.
#
# <details><summary>Answer</summary>
#
# Eq. 7.31 with $u$ = 6 in and link 4's $\omega_4 = -3.461$ rad/s and $\alpha_4 = 39.43$
# rad/s$^2$: $\mathbf{A}_U$ = 247.2 in/s$^2$ at $-104.0^\circ$.
#
# </details>
#
# **Problem 7.2.** Same linkage and input. Of the points of the coupler on the line AB
# ($\delta_3 = 0$, $0 \le p \le 6$ in), which accelerates least, and how much?
#
# <details><summary>Answer</summary>
#
# Along AB, $\mathbf{A}_P = \mathbf{A}_A + p\,(\alpha_3 j - \omega_3^2)e^{j\theta_3}$ is linear in
# $p$, so $|\mathbf{A}_P|$ is least at the foot of the perpendicular dropped on that line from
# the pole of the acceleration plane. That foot is at $p = -4.12$ in, beyond A, off the
# coupler: on AB the size only grows from A to B, and A itself accelerates least, 200.2
# in/s$^2$ (B: 370.8 in/s$^2$).
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
U = r.point(4, "6 in", "20 deg")
stated(r.omega4, "-3.461", "rad/s")
stated(r.alpha4, "39.43", "rad/s^2")
stated(abs(U.A), "247.2", "in/s^2")
stated(np.angle(U.A.magnitude, deg=True), "-104.0")
A0 = complex(r.A_A.m_as("in/s^2"))
k = (r.alpha3.magnitude * 1j - r.omega3.magnitude**2) * np.exp(1j * r.theta3.magnitude)
p_min = -((A0 * np.conj(k)).real) / abs(k) ** 2  # in
stated(p_min, "-4.12")
stated(abs(r.A_A), "200.2", "in/s^2")
stated(abs(r.A_B), "370.8", "in/s^2")
along = np.abs(A0 + np.linspace(0, 6, 61) * k)
assert np.all(np.diff(along) > 0)  # grows from A to B

# %% [markdown]
# ## Practice
#
# Coupler-point problems with instant feedback, for self-study (not graded, and never one of a
# graded assignment's). Each run of the next cell draws a fresh linkage and point, or give a seed
# to come back to one; hand each answer to `mine.check`, which says at once whether it is right and,
# if not, what to look at (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `coupler` (with `fourbar` for
# the pins).
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("coupler")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("A_P_mag", Q_(730, "in/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("coupler", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5, modelled with `FourBar`:

# %%
example = practice("coupler", seed=5, show=False)
g = example.given
res = FourBar(a=g["a"], b=g["b"], c=g["c"], d=g["d"]).solve(
    theta2=g["theta2"],
    omega2=g["omega2"],
    alpha2=g["alpha2"],
    circuit=g["circuit"],
    p=g["p"],
    delta3=g["delta3"],
)
assert example.check("A_P_mag", abs(res.A_P))  # right
assert not example.check("A_P_mag", abs(res.A_A))  # the pin's acceleration, not the point's
# right, a bare number in deg:
assert example.check("A_P_ang", np.angle(res.A_P.magnitude, deg=True))

# %% [markdown]
# ## Common mistakes
#
# - **Measuring $\delta_3$ from the wrong line.** It is the angle from line AB (the direction of
#   $\theta_3$), counter-clockwise, fixed in the link; not from the x axis.
# - **Adding $\mathbf{A}_{PA}$ to a point of another link**, e.g. to $\mathbf{A}_B$ with the
#   offset measured from A. Refer P to a point of the coupler, with $p$ and $\delta$ measured from
#   that point.
# - **Using the pin's acceleration for the link's centre of gravity.** The force $m\mathbf{A}_G$
#   needs the acceleration of G itself.
# - **Mixing pound-mass and pound-force.** $m a$ with $m$ in lb and $a$ in in/s² is *not* in lbf
#   until divided by $g_c = 386.09$ lb·in/(lbf·s²); let pint do it, or use blobs or slugs.
#
# [Next: 8. Human tolerance of acceleration](08_human_tolerance.ipynb)
