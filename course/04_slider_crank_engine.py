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
# # 4. The slider-crank and the engine
#
# The slider-crank turns rotation into straight-line motion, and its best known member is
# the piston engine. The chapter (Robert L. Norton, *Design of Machinery*, chapter 7) makes a
# striking claim in its section 7.6: the pistons of a small car engine accelerate at about 40 g
# at idle and about 2000 g at 6000 rpm. In this notebook we derive the slider-crank's
# accelerations (section 7.3, eqs. 7.14 to 7.16 and Figure 7-6) and then check that claim
# ourselves, from an engine geometry we make up but could find in a catalogue.
#
# **You will be able to**
#
# - differentiate the slider-crank's vector loop and solve it for $\alpha_3$ and the slider's
#   acceleration $\ddot d$;
# - explain why the slider's acceleration has no normal component, and what the chapter's
#   label $\mathbf{A}_{BA}$ in eq. 7.15 really is;
# - estimate a piston's acceleration from bore, stroke, rod length and speed, in m/s$^2$,
#   ft/s$^2$ and g, and say how it scales with speed and rod length;
# - recognise slider-cranks that cannot be assembled.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import math

import matplotlib.pyplot as plt
import numpy as np

from accelab.course.animation import animate
from accelab.course.kit import COLORS, explore, in_g, stated, use_style
from accelab.course.practice import practice
from accelab.course.renditions import legend, panels, show
from accelab.course.text import num, say, table, vec, xy
from accelab.solver import Q_, NotAssemblable, Singular, SliderCrank
from accelab.solver.graphical import construct_case
from accelab.solver.graphical.draw import draw_linkage, draw_polygon
from accelab.solver.graphical.gallery import SLIDER_CRANK

use_style()

# %% [markdown]
# ## The idea and its equations
#
# With the slide along the $x$ axis ($\theta_1 = 0$), a crank $a$, a connecting rod $b$ and a
# slider offset $c$ (perpendicular to the slide, $\theta_4 = 90^\circ$) close the loop
#
# $$ \begin{aligned} & a e^{j\theta_2} - b e^{j\theta_3} \\
#    & - c e^{j\theta_4} - d e^{j\theta_1} = 0 \end{aligned} \tag{4.14} $$
#
# Here $b e^{j\theta_3}$ points from the slider pin $B$ back to the crank pin $A$, and the
# slider's position $d$ is the one length that changes. Differentiating twice ($a$, $b$, $c$,
# $\theta_1$, $\theta_4$ constant):
#
# $$ \begin{aligned} & \left(a\alpha_2 je^{j\theta_2} - a\omega_2^2 e^{j\theta_2}\right) \\
#  & - \left(b\alpha_3 je^{j\theta_3} - b\omega_3^2 e^{j\theta_3}\right) - \ddot d = 0
#    \end{aligned} \tag{7.14} $$
#
# The first bracket is $\mathbf{A}_A$. The second is the acceleration of $A$ turning about $B$
# with the rod, $\mathbf{A}_{AB}$ (the vector $b e^{j\theta_3}$ points from $B$ to $A$), and the
# last term is the slider's acceleration $\mathbf{A}_B = \ddot d$, which lies along the slide:
# a block in pure translation has no normal component. So eq. 7.14 is eq. 7.4 once more,
#
# $$ \begin{aligned} \mathbf{A}_B &= \mathbf{A}_A + \mathbf{A}_{BA}, \\
#    \mathbf{A}_{BA} &= -\mathbf{A}_{AB} \end{aligned} \tag{7.15} $$
#
# (The chapter labels the second bracket $\mathbf{A}_{BA}$ in eq. 7.15b; by eq. 7.4's own
# definition it is $\mathbf{A}_{AB}$, the same vector reversed. This course follows eq. 7.4.)
#
# Split into real and imaginary parts (the chapter's eqs. 7.16b and 7.16c):
#
# $$ \begin{aligned} & -a\alpha_2\sin\theta_2 - a\omega_2^2\cos\theta_2 \\
#    & + b\alpha_3\sin\theta_3 + b\omega_3^2\cos\theta_3 \\
#    & - \ddot d = 0 \end{aligned} \tag{7.16b} $$
#
# $$ \begin{aligned} & a\alpha_2\cos\theta_2 - a\omega_2^2\sin\theta_2 \\
#    & - b\alpha_3\cos\theta_3 + b\omega_3^2\sin\theta_3 = 0 \end{aligned} \tag{7.16c} $$
#
# (The scanned chapter's eq. 7.16b ends in "$- d = 0$": its two dots are lost in the scan. The
# term is the slider's acceleration $\ddot d$, as eq. 7.14 says; a plain $d$, a position, would
# not even have the right dimension.)
#
# The imaginary part has one unknown, $\alpha_3$; the real part then gives $\ddot d$:
#
# $$ \begin{aligned} \alpha_3 = \frac{1}{b\cos\theta_3} \big( & a\alpha_2\cos\theta_2 \\
#    & - a\omega_2^2\sin\theta_2 \\ & + b\omega_3^2\sin\theta_3 \big) \end{aligned}
#    \tag{7.16d} $$
#
# $$ \begin{aligned} \ddot d = {} & -a\alpha_2\sin\theta_2 - a\omega_2^2\cos\theta_2 \\
#    & + b\alpha_3\sin\theta_3 + b\omega_3^2\cos\theta_3 \end{aligned} \tag{7.16e} $$
#
# The denominator $b\cos\theta_3$ vanishes when the rod stands perpendicular to the slide,
# which only a rod no longer than crank plus offset can reach. Checked against the solver,
# at the slider-crank `accelab.solver.graphical` also draws (40 mm crank, 120 mm rod, 10 mm
# offset):

# %%
sc = SliderCrank(a="40 mm", b="120 mm", c="10 mm")
r = sc.solve(theta2="60 deg", omega2="30 rad/s", alpha2="-200 rad/s^2")

a, b = 0.040, 0.120  # m
t2, w2, al2 = math.radians(60), 30.0, -200.0
t3, w3 = r.theta3.to("rad").magnitude, r.omega3.to("rad/s").magnitude
alpha3 = (a * al2 * math.cos(t2) - a * w2**2 * math.sin(t2) + b * w3**2 * math.sin(t3)) / (
    b * math.cos(t3)
)  # eq. 7.16d
d_ddot = (
    -a * al2 * math.sin(t2)
    - a * w2**2 * math.cos(t2)
    + b * alpha3 * math.sin(t3)
    + b * w3**2 * math.cos(t3)
)  # eq. 7.16e
assert math.isclose(alpha3, r.alpha3.to("rad/s^2").magnitude, rel_tol=1e-12)
assert math.isclose(d_ddot, r.d_ddot.to("m/s^2").magnitude, rel_tol=1e-12)

# the chapter's second bracket is A_AB = -A_BA, and A_B = A_A + A_BA (eq. 7.4)
bracket = (b * alpha3 * 1j - b * w3**2) * np.exp(1j * t3)
assert np.isclose(bracket, -r.A_BA.to("m/s^2").magnitude)
assert np.isclose(r.A_B.to("m/s^2").magnitude, (r.A_A + r.A_BA).to("m/s^2").magnitude)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", "value"],
    [
        [r"$\theta_3$", f"{num(r.theta3.m_as('deg'))}°"],
        [r"$\omega_3$", f"{num(r.omega3)} rad/s"],
        [r"$\alpha_3$ (eq. 7.16d)", f"{num(alpha3)} rad/s²"],
        [r"$d$, $\dot d$", f"{num(r.d.m_as('mm'))} mm, {num(r.d_dot.m_as('m/s'))} m/s"],
        [r"$\ddot d$ (eq. 7.16e)", f"{num(d_ddot)} m/s²"],
        [r"$\mathbf{A}_A$", f"{xy(r.A_A, 'm/s^2')} = {vec(r.A_A, 'm/s^2')}"],
        [r"$\mathbf{A}_{BA}$", f"{xy(r.A_BA, 'm/s^2')} = {vec(r.A_BA, 'm/s^2')}"],
        [r"$\mathbf{A}_B$", f"{xy(r.A_B, 'm/s^2')}: along the slide only"],
    ],
)

# %% [markdown]
# ## Worked example 1: one position, drawn and computed
#
# The graphical construction of the same position solves eq. 7.15 with a polygon:
# $\mathbf{A}_A$ is known, $\mathbf{A}^n_{BA} = b\omega_3^2$ is known, $\mathbf{A}^t_{BA}$ has
# a known direction (perpendicular to the rod) and $\mathbf{A}_B$ a known direction (along the
# slide). Two lines, one crossing: the same recipe as the fourbar, with the slide in the place
# of the rocker.

# %%
con = construct_case(SLIDER_CRANK)
assert math.isclose(con.values["alpha3"], r.alpha3.to("rad/s^2").magnitude, rel_tol=1e-9)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"The construction gives $\alpha_3$ = {num(con.values['alpha3'], 7)} rad/s² and "
    rf"$\mathbf{{A}}_B$ = {num(con.values['A_B'].real, 7)} m/s² along $x$: the equations' "
    "answer, to the last digit shown."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The slider-crank's graphical solution: the linkage with its accelerations, and the acceleration polygon, in which the slide takes the rocker's place."}}
def construction(narrow):
    fig, (ax1, ax2) = panels(
        2, narrow, wide=(7.8, 4.0), tall=(4.4, 8.6), width_ratios=[1.2, 1], layout="constrained"
    )
    draw_linkage(con, ax=ax1, legend=False)
    draw_polygon(con, "acceleration", ax=ax2, legend=False)
    legend(
        fig,
        ("normal", "tangential", "resultant"),
        lines=True,
        ncol=2 if narrow else 4,
        loc="outside lower center",
    )
    return fig


show(construction, alt="Slider-crank linkage beside its acceleration polygon.")

# %% [markdown]
# The same slider acceleration in US units, as a drawing in inches ($a = 1.575$ in,
# $b = 4.724$ in) would carry it; pint converts:

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"$\ddot d$ = {num(r.d_ddot.m_as('in/s^2'))} in/s² = {num(r.d_ddot.m_as('ft/s^2'))} "
    f"ft/s² = {num(in_g(r.d_ddot), 3)} g"
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(Q_(40, "mm"), "1.575", "in")
stated(Q_(120, "mm"), "4.724", "in")

# %% [markdown]
# ## Worked example 2: how hard does a piston accelerate?
#
# The chapter: *the piston of a small four-cylinder economy car engine (about 1.5 L) is at
# about 40 g at idle, as much as 700 g at highway speeds, and about 2000 g at its top speed
# of 6000 rpm.* Let us check.
#
# **A plausible engine.** Four cylinders of bore 77 mm and stroke 80 mm give
# $4 \times \frac{\pi}{4}(77\ \text{mm})^2 \times 80\ \text{mm} = 1.49$ L. The crank radius is
# half the stroke, $a = 40$ mm. Connecting rods of such engines are about 3 to 3.5 crank
# radii long; take $b = 130$ mm. No offset ($c = 0$): the cylinder axis passes through the
# crank axis. The crank turns at constant speed ($\alpha_2 = 0$); the piston is at top dead
# centre (TDC, farthest from the crank) when $\theta_2 = 0$.

# %%
bore, stroke, rod = Q_(77, "mm"), Q_(80, "mm"), Q_(130, "mm")
displacement = (4 * math.pi / 4 * bore**2 * stroke).to("L")
engine = SliderCrank(a=stroke / 2, b=rod)

theta2 = Q_(np.linspace(0, 360, 721), "deg")
speeds = {"idle": Q_(800, "rpm"), "highway": Q_(3500, "rpm"), "top speed": Q_(6000, "rpm")}
peaks = {}
for name, n in speeds.items():
    piston = engine.solve(theta2=theta2, omega2=n, order=2).d_ddot
    peaks[name] = np.max(np.abs(piston))

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"Displacement {num(displacement.m_as('L'), 3)} L, crank radius $a$ = "
    f"{num((stroke / 2).m_as('mm'))} mm, rod to crank ratio $b/a$ = "
    f"{num((rod / (stroke / 2)).m_as(''), 3)}. The largest piston acceleration over a "
    "revolution:"
)
table(
    ["speed", r"largest $\lvert\ddot d\rvert$", "", ""],
    [
        [
            f"{name}, {num(speeds[name].m_as('rpm'), decimals=0)} rpm",
            f"{num(peak.m_as('m/s^2'), 4)} m/s²",
            f"{num(peak.m_as('ft/s^2'), 4)} ft/s²",
            f"{num(in_g(peak), 3)} g",
        ]
        for name, peak in peaks.items()
    ],
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(displacement, "1.49", "L")
stated(in_g(peaks["idle"]), "37")
stated(in_g(peaks["highway"]), "720", sig=2)
stated(in_g(peaks["top speed"]), "2100", sig=2)
w_top = speeds["top speed"].to("rad/s")
stated(speeds["top speed"].to("turn/s"), "100")
stated(w_top, "628", "rad/s")
stated((stroke / 2) * w_top**2, "15800", "m/s^2", sig=3)
stated(in_g((stroke / 2) * w_top**2), "1600", sig=2)

# %% [markdown]
# About 37 g at 800 rpm, 720 g at 3500 rpm, 2100 g at 6000 rpm: the chapter's figures,
# from nothing but the geometry. Why so large? At 6000 rpm the crank turns 100 times a
# second, $\omega_2 = 628$ rad/s, and the crank pin alone already has $a\omega_2^2 =
# 0.04 \times 628^2 \approx 15\,800$ m/s$^2$, some 1600 g.
#
# The peak is at TDC and is *larger* than $a\omega_2^2$: there the rod adds its own
# centripetal term. With no offset, at $\theta_2 = 0$ the exact value is
# $\ddot d = -a\omega_2^2(1 + a/b)$, pointing back toward the crank:

# %%
top = engine.solve(theta2="0 deg", omega2="6000 rpm", order=2)
w = Q_(6000, "rpm").to("rad/s")
by_hand = -(stroke / 2) * w**2 * (1 + (stroke / 2) / rod)
assert math.isclose(top.d_ddot.to("m/s^2").magnitude, by_hand.to("m/s^2").magnitude, rel_tol=1e-12)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    rf"At TDC and 6000 rpm, $\ddot d$ = {num(top.d_ddot.m_as('m/s^2'), 6)} m/s² "
    rf"$= -a\omega_2^2(1 + a/b)$, with $a\omega_2^2$ = "
    f"{num(((stroke / 2) * w**2).m_as('m/s^2'), 6)} m/s²."
)

# %% [markdown]
# Over a revolution, in g at the three speeds. Every curve is the same shape scaled by
# $\omega_2^2$; the second plot divides it out, and sets beside it the $x$ acceleration of
# the crank pin itself, $-a\omega_2^2\cos\theta_2$, the piston's motion if the rod were
# infinitely long.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Piston acceleration $\\ddot d$ of a 1.49 L engine over a crank revolution at idle, highway speed and 6000 rpm, and the same curves divided by $a\\omega_2^2$: one shape at every speed."}}
def piston_curves(narrow):
    fig, (ax1, ax2) = panels(2, narrow, wide=(7.8, 3.6), tall=(4.4, 7.2), layout="constrained")
    colours = ["#56B4E9", "#E69F00", "#D55E00"]
    for (name, n), col, lw in zip(speeds.items(), colours, (4, 2.8, 1.6)):
        piston = engine.solve(theta2=theta2, omega2=n, order=2).d_ddot
        ax1.plot(theta2.magnitude, in_g(piston), color=col, label=f"{name}, {n:.0f~P}")
        w = n.to("rad/s").magnitude
        ax2.plot(theta2.magnitude, piston.to("m/s^2").magnitude / (0.040 * w**2), color=col, lw=lw)
    ax1.set_ylabel("piston $\\ddot d$ [g]")
    ax2.set_ylabel("$\\ddot d \\,/\\, a\\omega_2^2$")
    ax2.plot(
        theta2.magnitude,
        -np.cos(theta2.to("rad").magnitude),
        color="#888888",
        ls=":",
        lw=1.5,
        label="crank pin: $-\\cos\\theta_2$",
    )
    ax2.set_ylim(-1.45, 1.45)
    ax2.legend(loc="upper right", borderaxespad=0.2)
    ax2.set_title("the same curve at every speed")
    ax1.set_title("bore 77, stroke 80, rod 130 mm")
    for ax in (ax1, ax2):
        ax.set_xlabel("crank angle $\\theta_2$ [deg] (0: TDC)")
        ax.set_xticks(range(0, 361, 90))
    ax1.legend(loc="lower center")
    return fig


show(
    piston_curves,
    alt="Two line plots of piston acceleration against crank angle, in g, for three engine "
    "speeds; in the second the three curves coincide.",
)

# %% [markdown]
# The acceleration is most negative at TDC (the piston is being pulled back toward the crank
# as it reverses) and positive, but smaller and flatter, around bottom dead centre. The
# asymmetry is the rod's doing: a very long rod would make the piston move like the shadow
# of the crank pin, $\ddot d = -a\omega_2^2\cos\theta_2$, symmetric about BDC.
#
# **How sure is "about 2000 g"?** The answer depends on the stroke and rod we assumed. A
# sweep over plausible 1.5 L geometries, the piston's largest acceleration (at TDC):

# %% tags=["hide-input"] jupyter={"source_hidden": true}
rows = []
for stroke_mm in (72, 80, 88):
    bore_mm = math.sqrt(1.5e6 / 4 / (math.pi / 4) / stroke_mm)  # keep 1.5 L
    for ratio in (3.0, 3.5):
        rod_mm = ratio * stroke_mm / 2
        eng = SliderCrank(a=Q_(stroke_mm / 2, "mm"), b=Q_(rod_mm, "mm"))
        g_idle = in_g(eng.solve(theta2="0 deg", omega2="800 rpm", order=2).d_ddot)
        g_top = in_g(eng.solve(theta2="0 deg", omega2="6000 rpm", order=2).d_ddot)
        rows.append(
            [
                f"{stroke_mm} mm",
                f"{num(bore_mm, 3)} mm",
                f"{num(rod_mm, 3)} mm",
                num(ratio, 2),
                f"{num(abs(g_idle), 2)} g",
                f"{num(abs(g_top), 3)} g",
            ]
        )
table(["stroke", "bore", "rod", "$b/a$", "800 rpm", "6000 rpm"], rows)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
sweep_g = {
    (s_, k): [
        abs(
            in_g(
                SliderCrank(a=Q_(s_ / 2, "mm"), b=Q_(k * s_ / 2, "mm"))
                .solve(theta2="0 deg", omega2=n, order=2)
                .d_ddot
            )
        )
        for n in ("800 rpm", "6000 rpm")
    ]
    for s_ in (72, 80, 88)
    for k in (3.0, 3.5)
}
lo, hi = (
    (min(v[i] for v in sweep_g.values()) for i in (0, 1)),
    (max(v[i] for v in sweep_g.values()) for i in (0, 1)),
)
(idle_lo, top_lo), (idle_hi, top_hi) = lo, hi
stated(top_lo, "1860", sig=3)
stated(top_hi, "2360", sig=3)
stated(idle_lo, "33")
stated(idle_hi, "42")
stated(peaks["top speed"], "20650", "m/s^2", sig=4)
stated(Q_(0.3, "kg") * peaks["top speed"], "6", "kN")

# %% [markdown]
# From about 1860 to 2360 g at 6000 rpm, and 33 to 42 g at 800 rpm: the claim holds for any
# reasonable small engine. Newton's law then says what it costs: a 0.3 kg piston at 2100 g
# needs $F = m\,\ddot d \approx 0.3 \times 20\,650 \approx 6$ kN from its rod, reversing 100
# times a second. That is why pistons are made of aluminium alloys and rods are forged.
#
# **The engine in motion**, at 6000 rpm: the crank pin's acceleration turns with the crank at
# a constant size while the piston's acceleration $\ddot d$ swings along the cylinder, with
# its sign: toward the crank (negative) through top dead centre, away from it around bottom
# dead centre. One arrow scale for the whole turn; millimetres and m/s$^2$. Step through
# $\theta_2 = 0$ and $180^\circ$ to see the two peaks of different size, and stop where
# $\ddot d$ crosses zero (near $74^\circ$): the piston is at its fastest there.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Animation: the 1.5 L engine's slider-crank at 6000 rpm through one turn, with the accelerations of the crank pin and the piston, and a marker on $\\alpha_3$, $|\\mathbf{A}_A|$ and the piston's $\\ddot d$ with its sign. Play, pause, step or drag the slider."}}
animate(
    {
        "mechanism": "slidercrank",
        "a": "40 mm",
        "b": "130 mm",
        "c": "0 mm",
        "theta2": "0 deg",
        "omega2": "6000 rpm",
        "alpha2": "0 rad/s^2",
    },
    magnitudes=("A_A", "A_B.x"),
    symbols={"A_B.x": r"piston $\ddot d$"},
    title="1.5 L engine, 6000 rpm",
    alt="The engine's slider-crank turning, with acceleration arrows at the crank pin and the "
    "piston, beside plots of alpha3, the crank pin's acceleration and the piston's signed "
    "acceleration with a moving marker.",
)

# %% [markdown]
# ### A slider-crank that cannot be assembled
#
# If the rod is shorter than the crank ($b < a$), the rod cannot reach the slide line at
# crank angles where the crank pin is more than $b$ away from it: $|a\sin\theta_2 - c| \le b$
# is needed. At the edge, the rod stands perpendicular to the slide and eq. 7.16d divides by
# $\cos\theta_3 = 0$.

# %%
short = SliderCrank(a="50 mm", b="40 mm")
sweep = short.solve(theta2=theta2, omega2="10 rad/s", order=2)
say(
    f"The 50 mm crank with a 40 mm rod assembles at {sweep.valid.sum()} of {sweep.valid.size} crank angles."
)
try:
    short.solve(theta2="90 deg", omega2="10 rad/s")
except (NotAssemblable, Singular) as exc:
    say(rf"At $\theta_2 = 90^\circ$ the solver raises `{type(exc).__name__}`: {exc}")

# %% [markdown]
# ## Explore: the rod length
#
# The rod/crank ratio shapes the piston's motion. Move the rod length (crank radius 40 mm,
# 6000 rpm): a short rod raises the TDC peak toward $a\omega_2^2(1 + a/b)$ and flattens and
# splits the positive lobe at BDC; a long rod brings the curve toward the pure cosine of the
# crank pin (dotted).


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Piston acceleration over a revolution for several connecting-rod lengths $b$ (crank 40 mm, 6000 rpm): a shorter rod gives a higher peak at TDC."}}
def draw(rod_mm, rpm):
    eng = SliderCrank(a="40 mm", b=Q_(rod_mm, "mm"))
    res = eng.solve(theta2=theta2, omega2=Q_(rpm, "rpm"), order=2)
    w = Q_(rpm, "rpm").to("rad/s").magnitude
    fig, ax = plt.subplots(figsize=(4.5, 3.5))
    ax.plot(theta2.magnitude, in_g(res.d_ddot), color=COLORS["resultant"], lw=2)
    ax.plot(
        theta2.magnitude,
        -0.040 * w**2 * np.cos(theta2.to("rad").magnitude) / 9.80665,
        color="#888888",
        ls=":",
        label="crank pin's shadow",
    )
    ax.set_ylim(-3000, 1800)
    ax.set_xticks(range(0, 361, 90))
    ax.set_xlabel("$\\theta_2$ [deg]")
    ax.set_ylabel("piston [g]")
    peak = abs(in_g(res.d_ddot)).max()
    ax.set_title(f"$b/a$ = {rod_mm / 40:.2f}: peak {peak:.0f} g at {rpm:g} rpm", fontsize=11)
    ax.legend(loc="lower center", fontsize=10)
    return fig


explore(
    draw,
    rod_mm=(80, 400, 10, 130, "mm"),
    rpm=(600, 7000, 100, 6000, "rpm"),
    values=[80, 130, 200, 400],
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
for rod_mm, above in ((80, "50"), (400, "10")):
    res = SliderCrank(a="40 mm", b=Q_(rod_mm, "mm")).solve(
        theta2=theta2, omega2="6000 rpm", order=2
    )
    ratio = np.max(np.abs(res.d_ddot.m_as("m/s^2"))) / (0.040 * w_top.magnitude**2)
    stated(100 * (ratio - 1), above)

# %% [markdown]
# With $b = 80$ mm ($b/a = 2$) the peak is 50 % above the crank pin's; with 400 mm it is
# only 10 % above. Engines use $b/a$ around 3 to 3.5: a longer rod would make a taller,
# heavier engine for little gain.

# %% [markdown]
# ## Check yourself
#
# **1.** The engine's speed drops from 6000 to 3000 rpm. What happens to the peak piston
# acceleration?
#
# <details><summary>Answer</summary>
#
# It falls to a quarter, about 530 g: at constant speed every term of eq. 7.16e is
# proportional to $\omega_2^2$.
#
# </details>
#
# **2.** Why has $\mathbf{A}_B$ no normal component, while $\mathbf{A}_A$ has one?
#
# <details><summary>Answer</summary>
#
# The slider translates along a straight line: its path has no curvature, so there is no
# centripetal acceleration, only acceleration along the path ($\ddot d$). The crank pin moves
# on a circle and always has $a\omega_2^2$ toward $O_2$.
#
# </details>
#
# **3.** Convert 2100 g to ft/s$^2$ and to in/s$^2$.
#
# <details><summary>Answer</summary>
#
# $2100 \times 32.17 \approx 67\,600$ ft/s$^2$ $\approx 811\,000$ in/s$^2$ (with $g = 32.17$
# ft/s$^2$ $= 386.1$ in/s$^2$). In code: `Q_(2100, "standard_gravity").to("ft/s^2")`.
#
# </details>
#
# **4.** At TDC, what is the direction of the piston's acceleration, and what is
# $\alpha_3$ there (no offset, constant $\omega_2$)?
#
# <details><summary>Answer</summary>
#
# Toward the crank ($-x$): $\ddot d = -a\omega_2^2(1 + a/b)$. And $\alpha_3 = 0$: by eq. 7.16d
# with $\theta_2 = 0$, $\theta_3 = 180^\circ$ and $\alpha_2 = 0$ every term of the numerator
# vanishes. The rod has its largest angular *velocity* there instead.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
half = np.max(np.abs(engine.solve(theta2=theta2, omega2="3000 rpm", order=2).d_ddot))
stated(in_g(half), "530", sig=2)
stated(half / peaks["top speed"], "0.25")
stated(Q_(2100, "standard_gravity"), "67600", "ft/s^2", sig=3)
stated(Q_(2100, "standard_gravity"), "811000", "in/s^2", sig=3)
stated(Q_(1, "standard_gravity"), "32.17", "ft/s^2")
stated(Q_(1, "standard_gravity"), "386.1", "in/s^2")
tdc = engine.solve(theta2="0 deg", omega2="6000 rpm", order=2)
assert abs(tdc.alpha3.m_as("rad/s^2")) < 1e-9 and tdc.d_ddot.magnitude < 0

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set; solve by eqs. 7.16d and 7.16e, then check with
# `SliderCrank`. The answers are folded.
#
# **Problem 4.1.** An offset slider-crank has crank $a$ = 1.5 in, rod $b$ = 5 in and offset
# $c$ = 0.5 in. At $\theta_2 = 120^\circ$ the crank turns at 50 rad/s counter-clockwise and is
# slowing at 400 rad/s$^2$. Find $\theta_3$, $\alpha_3$ and the slider's acceleration.
#
# <details><summary>Answer</summary>
#
# $\theta_3 = 170.8^\circ$ (the rod, from the slider back to the crank pin), $\alpha_3 = 587.8$
# rad/s$^2$, and $\ddot d = 2579$ in/s$^2$ (215.0 ft/s$^2$, 6.68 g) along $+x$.
#
# </details>
#
# **Problem 4.2.** In the 1.5 L engine above (no offset, steady speed), at which crank angles
# is the piston's acceleration zero? Is its velocity then largest?
#
# <details><summary>Answer</summary>
#
# Near $74^\circ$ and $286^\circ$ from top dead centre, not at $90^\circ$ and $270^\circ$: the
# rod's angle shifts them. There $\ddot d = 0$, so the piston's speed $|\dot d|$ is at its
# largest (the speed of a smooth motion peaks where its acceleration passes through zero).
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
res = SliderCrank(a="1.5 in", b="5 in", c="0.5 in").solve(
    theta2="120 deg", omega2="50 rad/s", alpha2="-400 rad/s^2"
)
stated(res.theta3, "170.8", "deg")
stated(res.alpha3, "587.8", "rad/s^2")
stated(res.d_ddot, "2579", "in/s^2")
stated(res.d_ddot, "215.0", "ft/s^2")
stated(in_g(res.d_ddot), "6.68")
fine = Q_(np.linspace(0, 360, 7201), "deg")
e_fine = engine.solve(theta2=fine, omega2="6000 rpm", order=2)
zero = fine.magnitude[np.flatnonzero(np.diff(np.sign(e_fine.d_ddot.magnitude)))]
stated(zero[0], "74")
stated(zero[1], "286")
speed = np.abs(e_fine.d_dot.magnitude)
assert abs(fine.magnitude[np.argmax(speed[:3600])] - zero[0]) < 0.2

# %% [markdown]
# ## Practice
#
# Slider-crank problems with instant feedback, for self-study (not graded, and never one of a
# graded assignment's). Each run of the next cell draws a fresh linkage, or give a seed to come
# back to one; then hand each answer to `mine.check`, which says at once whether it is right and,
# if not, what to look at (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `slidercrank`.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("slidercrank")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("A_slider", Q_(-1200, "in/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("slidercrank", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5, modelled with `SliderCrank`:

# %%
example = practice("slidercrank", seed=5, show=False)
g = example.given
res = SliderCrank(a=g["a"], b=g["b"], c=g["c"]).solve(
    theta2=g["theta2"], omega2=g["omega2"], alpha2=g["alpha2"]
)
assert example.check("A_slider", res.d_ddot)  # right
assert not example.check("A_slider", abs(res.A_A))  # the crank pin's, not the slider's
assert not example.check("alpha3", -res.alpha3)  # the sign of alpha3 turned

# %% [markdown]
# ## Common mistakes
#
# - **rpm used as rad/s.** $6000$ rpm is $6000 \times 2\pi/60 = 628$ rad/s; forgetting the
#   factor $2\pi/60$ is an error of almost ten in $\omega$ and a hundred in acceleration. Let
#   pint convert: `Q_(6000, "rpm").to("rad/s")`.
# - **Stroke taken for the crank radius.** The stroke is the piston's travel, twice the crank
#   radius: $a = \text{stroke}/2$.
# - **"g" in pint.** `"g"` is the gram; standard gravity is `"standard_gravity"` (or `"g_0"`).
# - **Trusting eq. 7.15b's label.** The bracket $b\alpha_3je^{j\theta_3} - b\omega_3^2e^{j\theta_3}$
#   is $\mathbf{A}_{AB}$ because $\mathbf{R}_3$ points from $B$ to $A$; eq. 7.4 needs
#   $\mathbf{A}_{BA} = -\mathbf{A}_{AB}$.
# - **Looking for the peak at BDC.** Without offset the largest magnitude is at TDC, where
#   crank and rod terms add; at BDC they partly cancel.
#
# [Next: 5. Coriolis acceleration](05_coriolis.ipynb)
