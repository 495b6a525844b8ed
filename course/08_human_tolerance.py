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
# # 8. Human tolerance of acceleration
#
# Machines that carry people have a limit that machines carrying parts do not: the passenger.
# This notebook puts a linkage's accelerations in the unit people feel them in, the $g$, sets
# them beside accelerations everyone knows, and asks whether a ride driven by a fourbar is
# tolerable, and for how long. It follows section 7.6 of the chapter (Robert L. Norton,
# *Design of Machinery*, chapter 7: Table 7-1, and Figure 7-10, whose tolerance data the
# chapter takes from Sanders and McCormick, *Human Factors in Engineering and Design*).
#
# **You will be able to**
#
# - express any acceleration in $g$ (and back) with pint, without confusing $g$ with the gram;
# - tell the acceleration of a seat from the load its rider *feels*, which includes gravity, and
#   split that load along the rider's body;
# - compare a mechanism's accelerations with the everyday levels of the chapter's Table 7-1, and
#   say how long each level lasts per cycle;
# - say what such a comparison can and cannot establish.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import matplotlib.pyplot as plt
import numpy as np

from accelab.course.kit import COLORS, G0, explore, in_g, stated, use_style
from accelab.course.practice import practice
from accelab.course.renditions import show
from accelab.course.text import num, say, table
from accelab.solver import Q_, FourBar

use_style()

# %% [markdown]
# ## The idea and its equations
#
# We do not feel velocity (a smooth airliner at 500 mph feels like a parked one); the inner
# ear and the body feel **acceleration**. The convenient unit is the acceleration of gravity at
# sea level,
#
# $$ \begin{aligned} 1\,g &\approx 386\ \text{in/s}^2 \\ &\approx 32.2\ \text{ft/s}^2
#    \approx 9.81\ \text{m/s}^2 , \end{aligned} $$
#
# standardised as exactly 9.80665 m/s². (pint calls it `standard_gravity` or `g_0`; its `g`
# is the gram. `accelab.course.kit.G0` is one standard gravity.)
#
# **What a rider feels.** A seat must push its rider with the force $m(\mathbf{A} -
# \mathbf{g})$: $m\mathbf{A}$ to accelerate them and $-m\mathbf{g}$ to hold them up. Divided by
# $m$ this is the load the rider feels, pressed into the seat,
#
# $$ \mathbf{f} = \mathbf{A} - \mathbf{g}, \qquad \mathbf{g} = -g\,\hat{\mathbf{y}} , $$
#
# so a rider at rest feels $1\,g$ upward (their weight), an extra $1\,g$ upward acceleration
# is felt as twice their weight, and a free fall ($\mathbf{A} = \mathbf{g}$) as
# weightlessness. Pilots call $|\mathbf{f}|/g$ the **load factor**: "9 g" in a fighter is a
# felt load, gravity included.
#
# The chapter's Table 7-1 gives approximate levels of acceleration people meet in everyday
# life, as a feel for the numbers a design produces. It does not say which of the two
# quantities each entry is, and its entries are not all the same kind: the automobile and
# takeoff entries are the vehicle's (horizontal) acceleration $|\mathbf{A}|$, while the roller
# coaster's 3.5 g and the fighter's 9 g are what the riders feel, $|\mathbf{f}|$. Compare like
# with like. A felt load of 3.5 g at the bottom of a loop is an acceleration of $|\mathbf{A}|
# = 3.5 - 1 = 2.5$ g (upward); the other way, a car cornering at 0.8 g gives its driver a felt
# load of $\sqrt{1 + 0.8^2} = 1.28$ g (gravity down, the push of the seat sideways).
#
# | activity (Table 7-1) | the chapter's value | $\lvert\mathbf{A}\rvert$ | felt $\lvert\mathbf{f}\rvert$ |
# |---|---|---|---|
# | gentle acceleration in an automobile | 0.1 g | 0.1 g | 1.005 g |
# | jet aircraft on takeoff | 0.3 g | 0.3 g | 1.04 g |
# | hard acceleration in an automobile | 0.5 g | 0.5 g | 1.12 g |
# | panic stop in an automobile | 0.7 g | 0.7 g | 1.22 g |
# | fast cornering in an automobile | 0.8 g | 0.8 g | 1.28 g |
# | roller coaster | 3.5 g | 2.5 g at the bottom of a loop | 3.5 g |
# | F-16 Air Force jet | 9.0 g | 8 g pulling out of a dive | 9 g |
#
# (The first five are horizontal, so $|\mathbf{f}| = \sqrt{1 + (A/g)^2}\,g$; the last two are
# loads along the body at the bottom of a vertical loop, so $|\mathbf{A}| = |\mathbf{f}| - g$.)
#
# Tolerance depends on three things (the chapter's Figure 7-10, from military and NASA tests):
# the **direction** of the load relative to the body (headward loads drain or flood the brain
# of blood and are the least tolerated), its **size**, and its **duration**. Those tests used
# young, fit, trained subjects; children, the elderly and the general public should not be
# expected to tolerate as much.

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
for a_g, felt_g in ((0.1, "1.005"), (0.3, "1.04"), (0.5, "1.12"), (0.7, "1.22"), (0.8, "1.28")):
    stated(abs(a_g + 1j), felt_g)  # horizontal A, gravity down

# %% [markdown]
# ## Worked examples
#
# ### 1. Accelerations in g
#
# Table 7-1's accelerations $|\mathbf{A}|$ in SI and US units, and the two engine numbers the
# chapter quotes for machinery that carries no one (notebook 4 reproduces them): a small car
# engine's piston sees about 40 g at idle and about 2000 g at 6000 rpm.

# %%
table_7_1 = {  # |A| [g]; the last two from the felt loads 3.5 g and 9 g at the bottom of a loop
    "gentle acceleration, car": 0.1,
    "jet takeoff": 0.3,
    "hard acceleration, car": 0.5,
    "panic stop, car": 0.7,
    "fast cornering, car": 0.8,
    "roller coaster (felt 3.5 g)": 2.5,
    "F-16 fighter jet (felt 9 g)": 8.0,
}
engine = {"piston at idle": 40, "piston at 6000 rpm": 2000}

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["", r"$\lvert\mathbf{A}\rvert$ [g]", "[m/s²]", "[in/s²]"],
    [
        [
            what,
            num(level, 2),
            num((level * G0).m_as("m/s^2"), 3),
            num((level * G0).m_as("in/s^2"), 3),
        ]
        for what, level in {**table_7_1, **engine}.items()
    ],
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
assert np.isclose(in_g(Q_(386.09, "in/s^2")), 1.0, rtol=1e-4)

# %% [markdown]
# ### 2. A ride on a fourbar
#
# A fairground ride carries its car on the coupler of a crank-rocker: crank $a$ = 3 m, coupler
# $b$ = 7 m, rocker $c$ = 6 m, ground $d$ = 8 m; the car is at $p$ = 4 m, $\delta_3$ = 60° on
# the coupler and is bolted to it, so it tilts with the coupler. The motor turns the crank at a
# steady 12 rpm: one cycle every 5 s. The car swoops through a loop 5 m wide and 7 m high.

# %%
ride = FourBar(a="3 m", b="7 m", c="6 m", d="8 m")
car = dict(p="4 m", delta3="60 deg")
N = 721
theta = Q_(np.linspace(0, 2 * np.pi, N), "rad")


def ride_cycle(rpm):
    """Time [s], the car's acceleration and the rider's felt load (in g, complex), the body axes."""
    r = ride.solve(theta2=theta, omega2=Q_(rpm, "rpm"), alpha2=0, **car)
    assert r.valid.all()
    t = (theta / Q_(rpm, "rpm")).to("s").magnitude
    A = r.A_P.to("standard_gravity").magnitude  # complex, in g
    felt = A + 1j  # f = A - g, g pointing down, in g
    t3 = r.theta3.magnitude
    up = 1j * np.exp(1j * (t3 - t3.mean()))  # the car's "up", tilting with link 3
    headward = (felt * np.conj(up)).real  # along the spine, seat to head
    forward = (felt * np.conj(up * -1j)).real  # chest to back (eyeballs in), the rider faces +x
    return t, r, A, felt, headward, forward


t, r, A, felt, head, fore = ride_cycle(12)
heavy = np.abs(felt) > 1.5

# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["at 12 rpm", "over a cycle"],
    [
        [r"largest $\lvert\mathbf{A}_P\rvert$", f"{num(np.abs(A).max(), 2)} g"],
        [
            r"felt load $\lvert\mathbf{f}\rvert$",
            f"{num(np.abs(felt).min(), 2)} g to {num(np.abs(felt).max(), 2)} g",
        ],
        [
            "felt, along the spine (1 g: sitting still)",
            f"{num(head.min(), 2)} g to {num(head.max(), 2)} g",
        ],
        ["felt, chest to back", f"{num(fore.min(), 2)} g to {num(fore.max(), 2)} g"],
        [
            "felt above 1.5 g",
            f"{num(heavy.mean() * t[-1], 2)} s of each {num(t[-1], decimals=0)} s cycle",
        ],
    ],
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
loop = r.R_P.to("m").magnitude
stated(np.ptp(loop.real), "5", sig=1)
stated(np.ptp(loop.imag), "7", sig=1)
stated(t[-1], "5")

# %% [markdown]
# The drawing shows the car's path with the felt load at a few instants (the arrow is the
# push of the seat on the rider, per unit mass), and, over one cycle, the size of
# $\mathbf{A}_P$ beside Table 7-1's automobile accelerations, and the two body components of
# $\mathbf{f}$, the felt load, beside the roller coaster's felt 3.5 g.

# %%
R = r.R_P.to("m").magnitude


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "A fairground ride at 12 rpm: the car's path with the load the rider feels, and against time the car's acceleration $|\\mathbf{A}_P|$ (with Table 7-1's automobile accelerations) and the two components of the felt load $\\mathbf{f}$ (with the roller coaster's felt load)."}}
def the_ride(narrow):
    fig = plt.figure(figsize=(4.4, 9.6) if narrow else (7.8, 6.4), layout="constrained")
    if narrow:
        ax1, ax2, ax3 = fig.subplots(3, 1, height_ratios=[1.2, 1, 1])
    else:
        grid = fig.add_gridspec(2, 2, width_ratios=[1, 1.25])
        ax1 = fig.add_subplot(grid[:, 0])
        ax2, ax3 = fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, 1])
    ax1.plot(R.real, R.imag, color="#555555", lw=1.5)
    for i in range(0, N - 1, 60):
        z, f = R[i], felt[i]
        ax1.annotate(
            "",
            xy=(z.real + f.real, z.imag + f.imag),
            xytext=(z.real, z.imag),
            arrowprops=dict(arrowstyle="-|>", color=COLORS["resultant"], lw=1.8),
        )
        ax1.plot(z.real, z.imag, "o", color="black", ms=3)
    i = 90
    pins = [0, r.R_A[i].to("m").magnitude, r.R_B[i].to("m").magnitude, 8]
    ax1.plot(
        [z.real for z in pins],
        [z.imag for z in pins],
        "-o",
        color="#9a9a9a",
        lw=3,
        ms=5,
        mfc="white",
        zorder=0,
    )
    ax1.fill(
        [pins[1].real, pins[2].real, R[i].real],
        [pins[1].imag, pins[2].imag, R[i].imag],
        color="#e0e0e0",
        zorder=0,
    )
    ax1.set_aspect("equal")
    ax1.set_xlabel("x [m]")
    ax1.set_ylabel("y [m]")
    ax1.set_title("Path; arrows: felt load $\\mathbf{f}$\n(1 m of arrow = 1 g); linkage at 45°")
    ax2.plot(t, np.abs(A), color="black", lw=2, label=r"$|\mathbf{A}_P|$")
    for what in ("gentle acceleration, car", "fast cornering, car"):
        ax2.axhline(table_7_1[what], color="#999999", lw=0.8, ls=":")
        ax2.text(
            0.1,
            table_7_1[what],
            what.replace(", car", " (car)"),
            va="bottom",
            fontsize=10,
            color="#555555",
        )
    ax2.set_ylabel("acceleration [g]")
    ax2.set_ylim(0, 1.1)
    ax2.set_title("The car's acceleration")
    ax3.plot(t, head, color=COLORS["normal"], lw=2, label="along the spine")
    ax3.plot(t, fore, color=COLORS["tangential"], lw=2, ls="--", label="chest to back")
    ax3.axhline(1, color="#999999", lw=0.8, ls=":")
    ax3.set_ylabel("felt load [g]")
    ax3.set_ylim(-1.0, 2.2)
    ax3.set_title("What the rider feels (roller coaster: 3.5 g)")
    ax3.legend(loc="upper right", ncol=2, fontsize=10)
    for ax in (ax2, ax3):
        ax.set_xlabel("time [s] (one crank turn)")
    return fig


show(
    the_ride,
    alt="The car's path with arrows of felt load; the car's acceleration against time with "
    "two automobile levels; the two components of the felt load against time.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(np.abs(A).max(), "0.8")
stated(np.abs(felt).min(), "0.5")
stated(np.abs(felt).max(), "1.7")
stated(heavy.mean() * t[-1], "1")
assert np.abs(A).max() < 2.5 and np.abs(felt).max() < 3.5  # below a roller coaster either way
assert head.mean() > np.abs(fore).mean()  # mostly along the spine

# %% [markdown]
# **Is it tolerable?** At 12 rpm the car's acceleration peaks at about 0.8 g, the level of
# fast cornering in a car (the same kind of number: an acceleration $|\mathbf{A}|$). With
# gravity the rider feels between about half and 1.7 times their weight, mostly along the
# spine, pressed into the seat at the bottom of the loop and light at the top; a roller
# coaster's riders feel up to 3.5 g. Each load lasts about a second per cycle. That is well
# inside the everyday experience of Table 7-1, so for healthy adults it is plausibly
# tolerable; whether it is *fun* or *safe for everyone* is another matter, below.
#
# **Speed matters quadratically.** At a steady crank speed every acceleration scales with
# $\omega_2^2$, while each cycle gets shorter. The next cell runs the same ride from 6 to 24
# rpm.

# %%
speeds = np.arange(6, 25, 2)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
rows = []
for rpm in speeds:
    t_, _, A_, felt_, head_, _ = ride_cycle(rpm)
    dt = t_[-1] / (N - 1)
    rows.append(
        (np.abs(A_).max(), np.abs(felt_).max(), head_.min(), (np.abs(felt_) > 2).sum() * dt)
    )
rows = np.array(rows)
table(
    [
        "crank speed",
        r"largest $\lvert\mathbf{A}\rvert$",
        "largest felt",
        "least felt along the spine",
        "felt above 2 g",
    ],
    [
        [
            f"{rpm} rpm",
            f"{num(peak, 3)} g",
            f"{num(fmax, 3)} g",
            f"{num(hmin, 2)} g",
            f"{num(above, 2)} s per cycle",
        ]
        for rpm, (peak, fmax, hmin, above) in zip(speeds, rows)
        if rpm in (12, 16, 20, 24)
    ],
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The same ride from 6 to 24 rpm: the peak acceleration and the peak felt load grow with the square of the speed, and the least load along the spine falls below zero."}}
def faster(narrow):
    fig, ax = plt.subplots(figsize=(4.4, 4.0) if narrow else (7.2, 3.8), layout="constrained")
    ax.plot(speeds, rows[:, 0], "o-", color="black", label=r"peak $|\mathbf{A}_P|$")
    ax.plot(speeds, rows[:, 1], "s-", color=COLORS["normal"], label="peak felt load")
    ax.plot(speeds, rows[:, 2], "v-", color=COLORS["tangential"], label="least felt load, spine")
    ax.axhline(3.5, color="#999999", ls=":")
    ax.text(6, 3.55, "roller coaster, felt (Table 7-1)", fontsize=10, color="#555555", va="bottom")
    ax.axhline(0, color="#999999", lw=0.8)
    ax.set_ylim(-0.6, 4.3)
    ax.set_xlabel("crank speed [rpm]")
    ax.set_ylabel("[g]")
    ax.legend(loc="upper left", bbox_to_anchor=(0, 0.9))
    return fig


show(
    faster,
    alt="Line plots of the peak acceleration, the peak felt load and the least load along "
    "the spine against ride speed from 6 to 24 rpm.",
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
peak_of = dict(zip(speeds, rows[:, 0]))
felt_of = dict(zip(speeds, rows[:, 1]))
stated(peak_of[24] / peak_of[12], "4")
stated(peak_of[24], "3.2")
stated(felt_of[24], "3.8")


def least_spine(rpm):
    return ride_cycle(rpm)[4].min()


lo, hi = 12.0, 24.0  # the speed where the spine load reaches 0
for _ in range(30):
    mid = 0.5 * (lo + hi)
    lo, hi = (mid, hi) if least_spine(mid) > 0 else (lo, mid)
floating = 0.5 * (lo + hi)
stated(floating, "16", sig=2)

# %% [markdown]
# Doubling the speed from 12 to 24 rpm multiplies the peak acceleration by four, to about
# 3.2 g, and the rider then feels up to 3.8 g: more than the 3.5 g a roller coaster's riders
# feel. Already near 16 rpm the load along the spine falls to zero at the top of the loop,
# and beyond it turns *negative*: the rider would be lifted out of the seat and must be held
# by a restraint. That, more than the peak, is what a designer of this ride would watch.
#
# ### 3. A seat mechanism: a motorised baby swing
#
# A swing seat hangs 600 mm below the pivot of the rocker of a small crank-rocker ($a$ = 30
# mm, $b$ = 200 mm, $c$ = 100 mm, $d$ = 200 mm); the seat arm is fixed to the rocker at
# $\delta_4 = 165°$ so that it hangs straight down mid-swing. The motor turns at 30 rpm: one
# swing every 2 s, through 36°. `Result.point` gives the seat's acceleration directly.

# %%
swing = FourBar(a="30 mm", b="200 mm", c="100 mm", d="200 mm")
s = swing.solve(theta2=theta, omega2="30 rpm", alpha2=0)
seat = s.point(4, "600 mm", "165 deg")

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    f"The seat swings through {num(np.degrees(np.ptp(s.theta4.magnitude)), 2)}° and "
    f"accelerates at up to {num(in_g(seat.A).max(), 2)} g (its tangential part up to "
    f"{num(in_g(seat.A_t).max(), 2)} g, its normal part up to {num(in_g(seat.A_n).max(), 2)} g)."
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(np.degrees(np.ptp(s.theta4.magnitude)), "36")
stated(in_g(seat.A).max(), "0.25", sig=1)

# %% [markdown]
# Up to about a quarter of a $g$: between gentle and hard acceleration in a car. By Table 7-1 this
# is an everyday level for an adult. But the rider is an infant, exactly the population the
# chapter warns that the tolerance data do not describe. The calculation tells the designer how
# large the accelerations are and how they scale (halve the speed and they quarter); it cannot
# say they are acceptable for a baby. That needs the product's own safety standard and medical
# advice, not Figure 7-10.
#
# **What tolerance data can and cannot say.**
#
# - *Can*: give orders of magnitude (a mechanism at 0.3 g is in a different world from one at
#   9 g); show that direction and duration matter as much as size; flag loads near the limits
#   measured on trained volunteers as certainly unacceptable for the public.
# - *Cannot*: certify a design. The subjects were young and fit; the loads were mostly sustained
#   and steady, not the repeated cycles of a ride or the sudden jolts of a mechanism (jerk,
#   notebook 9); comfort, nausea and fatigue are not in them. Real rides are designed to published
#   standards (for example ASTM F2291 for amusement rides) that set limits by direction and duration,
#   and are then measured on the built ride.
#
# ## Explore
#
# Run the ride faster or slower (10 s of riding, the cycle repeated). Watch the peaks grow with
# the square of the speed while the cycles come faster, and watch for the moment the spine load
# crosses zero.


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The ride at four crank speeds: the size of the car's acceleration $|\\mathbf{A}_P|$ and the two components of the felt load over 10 s (dotted: the roller coaster's felt 3.5 g)."}}
def draw(speed=12):
    rpm = speed
    t, _, A, felt, head, fore = ride_cycle(rpm)
    turns = int(np.ceil(10 / t[-1]))  # repeat the cycle to fill 10 s
    T = np.concatenate([t[:-1] + k * t[-1] for k in range(turns)])
    rep = lambda x: np.tile(x[:-1], turns)  # noqa: E731
    fig, ax = plt.subplots(figsize=(4.6, 3.8))
    ax.plot(T, rep(np.abs(A)), color="black", lw=2, label=r"$|\mathbf{A}_P|$")
    ax.plot(T, rep(head), color=COLORS["normal"], lw=2, label="felt, along the spine")
    ax.plot(T, rep(fore), color=COLORS["tangential"], lw=2, ls="--", label="felt, chest to back")
    ax.axhline(3.5, color="#999999", lw=0.8, ls=":")
    ax.axhline(0, color="#999999", lw=0.8)
    ax.set_ylim(-3, 4.5)
    ax.set_xlim(0, 10)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("[g]")
    ax.set_title(
        f"{rpm} rpm: a cycle every {60 / rpm:.1f} s,\npeak $|\\mathbf{{A}}_P|$ {np.abs(A).max():.2f} g",
        fontsize=11,
    )
    ax.legend(fontsize=10, loc="lower left", ncol=1)
    return fig


explore(draw, speed=(6, 24, 1, 12, "rpm"))

# %% [markdown]
# ## Check yourself
#
# 1. The chapter says a small engine's piston reaches about 2000 g at 6000 rpm. What is that in
#    m/s² and in in/s²?
#
# <details><summary>Answer</summary>
#
# About 19 600 m/s² and 772 000 in/s² (`(2000 * G0).to("m/s^2")`).
#
# </details>
#
# 2. A lift (elevator) accelerates upward at 0.1 g. What does its passenger feel? And a lift whose
#    cable has snapped?
#
# <details><summary>Answer</summary>
#
# $\mathbf{f} = \mathbf{A} - \mathbf{g}$: 1.1 g, 10 % heavier than usual. In free fall
# $\mathbf{A} = \mathbf{g}$, so $\mathbf{f} = 0$: weightless, although the acceleration is 1 g.
#
# </details>
#
# 3. The ride's crank speed goes from 12 to 18 rpm. By how much do the peak accelerations grow,
#    and how long is a cycle now?
#
# <details><summary>Answer</summary>
#
# By $(18/12)^2 = 2.25$ (at steady speed every acceleration is proportional to $\omega_2^2$). A
# cycle takes 60/18 = 3.3 s instead of 5 s. The felt load does not simply scale, because gravity
# is added unchanged.
#
# </details>
#
# 4. Why can Table 7-1 not tell you whether 3 g for 10 s is safe?
#
# <details><summary>Answer</summary>
#
# It lists typical values of everyday accelerations, not limits, and gives neither duration nor
# direction. A roller coaster's riders feel 3.5 g for a moment, not for 10 s. Limits come from
# tolerance data such as Figure 7-10 (for the population they were measured on) and from design
# standards.
#
# </details>
#
# 5. On the ride at 20 rpm, the spine load becomes negative at the top of the loop. What does the
#    rider experience, and what must the design provide?
#
# <details><summary>Answer</summary>
#
# The car accelerates downward faster than gravity would, so the seat would have to *pull* the
# rider down: they lift off the seat. A restraint (lap bar, harness) must hold them.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
stated(2000 * G0, "19600", "m/s^2", sig=3)
stated(2000 * G0, "772000", "in/s^2", sig=3)
stated(1 + 0.1, "1.1")
stated((18 / 12) ** 2, "2.25")
stated(60 / 18, "3.3")
assert least_spine(20) < 0

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set; the answers are folded.
#
# **Problem 8.1.** A Ferris wheel of radius 20 m turns at a steady 2 rpm. What does a rider feel
# at the top and at the bottom of the wheel, in g? Does the wheel belong in Table 7-1's company?
#
# <details><summary>Answer</summary>
#
# The seat accelerates toward the hub at $R\omega^2 = 20 \times (2\pi/30)^2 = 0.877$ m/s$^2$,
# 0.0895 g. At the top that acceleration points down, so the rider feels $1 - 0.0895 = 0.911$ g;
# at the bottom $1.089$ g. Less than the gentlest entry of Table 7-1 (0.1 g): a Ferris wheel is a
# slow ride.
#
# </details>
#
# **Problem 8.2.** At what crank speed would the fourbar ride of example 2 first lift its
# riders off their seats?
#
# <details><summary>Answer</summary>
#
# Where the least load along the spine reaches zero: the cell above example 3 finds it by
# bisection, at 15.7 rpm. Below that the seat always pushes; above it the top of the loop needs a
# restraint.
#
# </details>

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
wheel = (Q_(20, "m") * Q_(2, "rpm").to("rad/s") ** 2 / Q_(1, "rad") ** 2).to("m/s^2")
stated(wheel, "0.877", "m/s^2")
stated(in_g(wheel), "0.0895")
stated(1 - in_g(wheel), "0.911")
stated(1 + in_g(wheel), "1.089")
assert in_g(wheel) < 0.1
stated(floating, "15.7")

# %% [markdown]
# ## Practice
#
# Amusement-ride problems with instant feedback, for self-study (not graded, and never one of
# a graded assignment's). Each run of the next cell draws a fresh ride, or give a seed to come
# back to one; hand each answer to `mine.check`, which says at once whether it is right and, if not,
# what to look at (the unit, the size).
#
# The graded exercise family that practises this notebook is `tolerance`.
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 5 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
mine = practice("tolerance")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("A_g", Q_(1.2, "standard_gravity"))

# %% [markdown]
# **A problem to try on this page**, seed 5: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("tolerance", seed=5)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 5: the passenger is a point on an arm
# turning about a fixed axis, as in notebook 1:

# %%
from accelab.solver import RotatingPoint

example = practice("tolerance", seed=5, show=False)
g = example.given
A = RotatingPoint(p=g["R"]).solve(theta2="0 deg", omega2=g["omega"], alpha2=g["alpha"]).A
assert example.check("A_g", abs(A).to("standard_gravity"))  # right
assert not example.check("A_g", abs(A).to("m/s^2").magnitude)  # m/s^2 handed in where g was asked

# %% [markdown]
# ## Common mistakes
#
# - **Writing `Q_(3, "g")`.** That is three grams. Use `standard_gravity`, `g_0` or `accelab.course.kit.G0`.
# - **Forgetting gravity.** The rider feels $\mathbf{A} - \mathbf{g}$, not $\mathbf{A}$; at rest
#   $\mathbf{A} = 0$ and they still feel 1 g.
# - **Quoting only the peak.** Tolerance depends on direction (along the spine is worst) and
#   duration; say both.
# - **Stretching the data.** Results on trained military volunteers are an upper bound, not a
#   design limit for children, the elderly or the public.
# - **Judging a slow mechanism by acceleration alone.** At 0.2 g the question is rarely tolerance;
#   smoothness (jerk, next notebook) and comfort decide.
#
# [Next: 9. Jerk](09_jerk.ipynb)
