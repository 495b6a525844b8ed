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
# # 11. Which method when: speed and accuracy
#
# The course has found accelerations four ways: the chapter's **closed forms** (notebooks 3
# to 9), **Newton-Raphson** on vector loops (notebook 10), the **graphical construction**
# (notebook 2) and, to check jerk in notebook 9, **finite differences**. Where all work they
# agree. This notebook says what each needs and costs, how accurate it is and where it fails,
# so that you can choose one for a job. (The chapter, Robert L. Norton, *Design of Machinery*,
# chapter 7, works by hand and by its closed forms; its section 7.8 leaves linkages of more
# loops to "an equation solver".) Times and errors are quoted from the project's one benchmark
# run, the one the site's *Benchmark* page shows, so that the two pages agree.
#
# **You will be able to**
#
# - pick a method for a design sweep, a check, or a linkage without a closed form;
# - say where each fails: near a toggle, from a bad guess, with the wrong step;
# - choose a finite-difference step for a derivative, and say why smaller is not better.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
# %matplotlib inline
import json
import math

import matplotlib.pyplot as plt
import numpy as np

from accelab.course import HERE
from accelab.course.kit import explore, stated, use_style
from accelab.course.renditions import show
from accelab.course.text import num, say, sci, table
from accelab.solver import FourBar, VectorLoopLinkage
from accelab.solver.graphical import construct
from accelab.solver.kernels import MAX_ROUNDOFF
from accelab.solver.kernels import fourbar as closed_form

use_style()
EPS = np.finfo(float).eps  # 2.2e-16: the spacing of float64 numbers near 1
IN = 0.0254  # m per inch
BENCH = json.loads((HERE / "benchmark.json").read_text())  # the benchmark run the site shows

# %% [markdown]
# ## The idea: four ways to the same accelerations
#
# | method | needs | gives | fails where |
# |---|---|---|---|
# | closed forms (eqs. 7.12, 7.16, 7.26, 7.29, 7.39) | a mechanism that has one | every output to jerk, for a whole array of crank angles at once | a toggle: the denominator vanishes |
# | Newton-Raphson on vector loops | guesses of the unknowns | any linkage of any number of loops, to jerk | a bad guess gives the other assembly; a toggle makes the Jacobian singular |
# | graphical construction | a drawing | the vectors to see, to acceleration | one position at a time; no jerk |
# | finite differences of positions | positions only | estimates of the derivatives | the step: too large truncates, too small amplifies round-off; silent near toggles |
#
# **Finite differences** need the most care. With a step $h$ in $\theta_2$, the central
# differences of $f(\theta_2) = \theta_4$ estimate its first and second derivatives,
#
# $$ k_1 \approx \frac{f(\theta_2+h) - f(\theta_2-h)}{2h} $$
#
# $$ k_2 \approx \frac{f(\theta_2+h) - 2f(\theta_2) + f(\theta_2-h)}{h^2} $$
#
# (and $k_3$ from five points), and the chain rule makes them time derivatives:
# $\omega_4 = k_1\omega_2$, $\alpha_4 = k_2\omega_2^2 + k_1\alpha_2$. Each estimate of the
# $n$-th derivative makes two errors: *truncation*, the Taylor terms left out, which shrinks as
# $h^2$; and *round-off*, the error of about $\epsilon|f|$ in every computed $f$
# ($\epsilon = 2.2\times10^{-16}$ in float64), divided by $h^n$:
#
# $$ E_n(h) \approx C_n h^2 + \frac{\epsilon\,|f|}{h^n} $$
#
# The sum is smallest where the two are equal, near $h^\ast \sim \epsilon^{1/(n+2)}$, with an
# error near $\epsilon^{2/(n+2)}$: about $10^{-11}$ for a velocity, $10^{-8}$ for an
# acceleration and $10^{-6}$ for a jerk. A smaller step is worse, not better.

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
for n, quoted in ((1, 1e-11), (2, 1e-8), (3, 1e-6)):
    assert 0.2 < EPS ** (2 / (n + 2)) / quoted < 5  # the model's best errors, to an order

# %% [markdown]
# ## Worked example 1: one position, four methods
#
# Example 7-1's linkage ($a$ = 2, $b$ = 6, $c$ = 9, $d$ = 7 in, open circuit) at
# $\theta_2 = 30^\circ$, $\omega_2$ = 10 rad/s, $\alpha_2$ = -5 rad/s²: $\alpha_3$ and
# $\alpha_4$ by each method. The finite differences use only positions from the closed form,
# with $h = 10^{-4}$ rad, near the best step for a second derivative.

# %%
geometry = dict(a=2 * IN, b=6 * IN, c=9 * IN, d=7 * IN)  # [m]
t30, motion = math.radians(30), dict(omega2="10 rad/s", alpha2="-5 rad/s^2")
exact = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(theta2="30 deg", **motion)
vectors = {"R1": ("7 in", "0 deg"), "R2": ("2 in", "input")}
vectors |= {"R3": ("6 in", "unknown", "90 deg"), "R4": ("9 in", "unknown", "130 deg")}  # sketch
loops = VectorLoopLinkage(
    vectors={k: dict(zip(("length", "angle", "guess"), v)) for k, v in vectors.items()},
    loops=["R2 + R3 - R4 - R1"],
).solve(theta2="30 deg", **motion)
drawn = construct("fourbar", "open", **geometry, theta2=t30, omega2=10.0, alpha2=-5.0).values


def by_differences(h, angles, geometry=geometry, omega2=10.0, alpha2=-5.0):
    """alpha3 and alpha4 from the closed-form *positions* alone: central differences."""
    f = closed_form.solve(**geometry, theta2=np.add.outer([-h, 0, h], angles), omega2=0, order=0)
    out = {}
    for k in "34":
        t = getattr(f, "theta" + k)
        t = t[1] + np.angle(np.exp(1j * (t - t[1])))  # no 2 pi jump inside a stencil
        k1, k2 = (t[2] - t[0]) / (2 * h), (t[2] - 2 * t[1] + t[0]) / h**2
        out["alpha" + k] = k2 * omega2**2 + k1 * alpha2
    return out


ref = {k: getattr(exact, k).m_as("rad/s^2") for k in ("alpha3", "alpha4")}
nr = {k: loops.vectors["R" + k[-1]].alpha.m_as("rad/s^2") for k in ref}
methods = {"closed forms (`FourBar`)": ref, "Newton-Raphson (`VectorLoopLinkage`)": nr}
methods |= {
    "graphical construction": drawn,
    "differences, $h = 10^{-4}$": by_differences(1e-4, t30),
}


def row(name, v):
    worst = max(abs(v[k] / ref[k] - 1) for k in ref)
    return [name, num(v["alpha3"], 10), num(v["alpha4"], 10), sci(worst)]


# %% tags=["hide-input"] jupyter={"source_hidden": true}
table(
    ["method", r"$\alpha_3$ [rad/s²]", r"$\alpha_4$ [rad/s²]", "difference"],
    [row(*i) for i in methods.items()],
)

# %% [markdown]
# The three exact methods agree to the digits float64 holds; the differences, even at a good
# step, to about eight. (On paper a construction is good to two or three figures.)
#
# ## Worked example 2: the finite-difference step
#
# The same position, steps from $10^{-12}$ to $10^{-1}$ rad, the first three derivatives of
# $\theta_4$, against the closed form (its own error, about $10^{-15}$, is off the plot).

# %%
unit = dict(omega2=1.0, alpha2=0.0, jerk2=0.0)  # then time and theta2 derivatives are equal
truth = closed_form.solve(**geometry, theta2=t30, **unit)
true = {1: truth.omega4, 2: truth.alpha4, 3: truth.jerk4}
steps = np.logspace(-12, -1, 45)
errors = {n: [] for n in true}
for h in steps:
    f = closed_form.solve(**geometry, theta2=t30 + h * np.arange(-2, 3), omega2=0, order=0)
    f = f.theta4[2] + np.angle(np.exp(1j * (f.theta4 - f.theta4[2])))
    k = {1: (f[3] - f[1]) / (2 * h), 2: (f[3] - 2 * f[2] + f[1]) / h**2}
    k[3] = (f[4] - 2 * f[3] + 2 * f[1] - f[0]) / (2 * h**3)
    for n in true:
        errors[n].append(abs(k[n] / true[n] - 1))
best = {n: int(np.argmin(errors[n])) for n in true}

# %% tags=["hide-input"] jupyter={"source_hidden": true}
say(
    "The best errors here, for the first, second and third derivative: "
    + ", ".join(f"{sci(errors[n][best[n]])} at $h$ = {sci(steps[best[n]], 1)} rad" for n in true)
    + "."
)


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Central differences of $\\theta_4(\\theta_2)$ at $\\theta_2 = 30^\\circ$: the relative error against the step $h$, truncation on the right, round-off on the left; circles mark each derivative's best step, dotted lines $\\epsilon^{1/(n+2)}$."}}
def v_curves(narrow):
    colours = {1: "#0072B2", 2: "#E69F00", 3: "#D55E00"}  # first, second, third derivative
    fig, ax = plt.subplots(figsize=(4.4, 4.2) if narrow else (7.2, 4.2), layout="constrained")
    for n, name in ((1, "first, $k_1$"), (2, "second, $k_2$"), (3, "third, $k_3$")):
        e = np.maximum(errors[n], 1e-16)
        ax.loglog(steps, e, "o-", ms=3, color=colours[n], label=name)
        ax.plot(steps[best[n]], e[best[n]], "o", ms=11, mfc="none", mec=colours[n], mew=2)
        ax.axvline(EPS ** (1 / (n + 2)), color=colours[n], ls=":", lw=1.2)
    ax.set(ylim=(1e-13, 1e10), xlabel="step $h$ [rad]", ylabel="relative error")
    ax.legend(
        loc="lower left" if narrow else "upper center", title="derivative", ncol=1 if narrow else 3
    )
    return fig


show(v_curves, alt="Log-log plot of finite-difference error against step size: three V shapes.")

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
for n in true:  # each V's bottom within a factor 30 of the model's error, near its step
    assert EPS ** (2 / (n + 2)) / 30 < errors[n][best[n]] < EPS ** (2 / (n + 2)) * 30
    assert EPS ** (1 / (n + 2)) / 30 < steps[best[n]] < EPS ** (1 / (n + 2)) * 30
assert np.interp(-8, np.log10(steps), errors[3]) > 0.5  # "pure noise"

# %% [markdown]
# Each curve is the V of the error model: truncation falls as $h^2$ on the right, round-off
# grows as $\epsilon/h^n$ on the left, jagged because round-off is. The bottoms lie near
# $\epsilon^{1/(n+2)}$, within a factor of thirty of the model's $10^{-11}$, $10^{-8}$ and
# $10^{-6}$ (the bottom of a V is round-off itself: it moves a little from one machine to
# the next). At $h = 10^{-8}$ rad, a step that looks careful, the jerk is pure noise. Over
# the whole cycle and every output to jerk, the benchmark finds finite differences never
# better than $1.4\times10^{-5}$ (at $h = 10^{-3}$ rad), and $3.5\times10^{3}$ times wrong at
# $h = 10^{-6}$ rad.

# %% [markdown]
# ## Worked example 3: near a toggle
#
# A non-Grashof triple rocker ($a$ = 5, $b$ = 4, $c$ = 6, $d$ = 3.5 in) has a toggle where
# links 3 and 4 fold onto each other. Every output there is computed from a small gap that
# carries round-off, so the closed forms lose accuracy as $1/\delta$, $\delta$ being the
# crank's distance from the toggle. The solver estimates that loss at every position (its
# `roundoff`) and refuses to answer where the estimate passes `MAX_ROUNDOFF` $= 10^{-6}$.
# Finite differences never refuse: their stencil simply reaches across.

# %%
p = dict(a=5 * IN, b=4 * IN, c=6 * IN, d=3.5 * IN)
toggle = math.acos((p["a"] ** 2 + p["d"] ** 2 - (p["c"] - p["b"]) ** 2) / (2 * p["a"] * p["d"]))
delta = np.array([1e-9, 1e-7, 2e-3, 1e-2])  # distance from the toggle [rad]
near = closed_form.solve(**p, theta2=toggle + delta, omega2=10.0, alpha2=-5.0)
with np.errstate(invalid="ignore"):
    fd_error = np.abs(by_differences(1e-3, toggle + delta, geometry=p)["alpha4"] / near.alpha4 - 1)

# %% tags=["hide-input"] jupyter={"source_hidden": true}
rows = [
    [sci(d, 1), ("answered", "", "refused")[s], sci(r, 1), sci(a4) if s == 0 else "NaN", sci(e)]
    for d, s, r, a4, e in zip(delta, near.status, near.roundoff, near.alpha4, fd_error)
]
table(
    ["$\\delta$ [rad]", "closed forms", "`roundoff`", r"$\alpha_4$ [rad/s²]", "differences' error"],
    rows,
)

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
assert list(near.status) == [2, 0, 0, 0] and np.all(near.roundoff[1:] <= MAX_ROUNDOFF)
stated(abs(near.alpha4[1]), "1e12", sig=1)
stated(100 * fd_error[3], "0.3", sig=1)
stated(100 * fd_error[2], "9", sig=1)
assert np.isnan(fd_error[1])  # the stencil crosses the toggle

# %% [markdown]
# $10^{-9}$ rad from the toggle the closed forms refuse (NaN, `valid` False; a single position
# raises `Singular`): their own round-off estimate there passes $10^{-6}$. Finite differences
# with $h = 10^{-3}$ rad answer without a warning, 0.3 % wrong $10^{-2}$ rad from the toggle
# and 9 % at $2\times10^{-3}$; nearer, their stencil crosses the toggle and gives NaN.
#
# The numbers the closed forms do return are right; the benchmark compared them with a
# 60-digit reference: $1.2\times10^{-3}$ rad from the toggle they still meet $10^{-13}$, and
# the nearest position they answer, $7.8\times10^{-9}$ rad away, is $2.1\times10^{-8}$ wrong.
# But look at their size: $10^{12}$ rad/s² is a
# mechanism that cannot be driven there at speed (notebook 3). Newton-Raphson refuses at the
# same place (its Jacobian is the same matrix); its other weakness, landing on the other
# assembly from a poor guess, grows there too, because the two assemblies come close: at
# $30^\circ$ on the Grashof fourbar the benchmark finds it reaching the guessed assembly from
# any guess within 0.37 rad, and far less near a toggle.
#
# ## Which method when
#
# The benchmark's measurements on the same fourbar over a whole turn (360 positions, from
# position to jerk, on two cores of an AMD EPYC), worst relative error over every output
# and position:
#
# | method | µs per position | worst error | use it for | fails at |
# |---|--:|--:|---|---|
# | closed forms, vectorised | 0.481 | $3.7\times10^{-15}$ | whole cycles, design sweeps, optimisation | toggles (it refuses) |
# | closed forms, unit-aware API | 0.598 | $3.7\times10^{-15}$ | one position with units; teaching; checking | many calls of one position each |
# | closed forms, Python loop | 29.2 | $3.7\times10^{-15}$ | nothing an array cannot do | speed |
# | vector loops, Newton-Raphson | 7.82 | $4.3\times10^{-15}$ | linkages without a closed form | bad guesses; toggles |
# | finite differences, $h = 10^{-3}$ rad | 1.24 | $1.4\times10^{-5}$ | a check when only positions exist | accuracy; silent near toggles |
# | graphical construction | 41.1 | $1.8\times10^{-15}$ | seeing the vectors; an independent check | one position at a time; no jerk |
#
# - **The closed forms are both the fastest and as accurate as float64 allows**: called
#   from a Python loop, one position at a time, the same formulas give the same numbers 60
#   times slower. Pass the solver arrays.
# - **Units cost little when one Quantity holds the whole array**: over 360 positions the
#   unit-aware call took 1.68 times the unit-free one when the two were timed in turn (138
#   against 82 µs per call; the table's separate medians say 1.24), while every call pays a
#   fixed cost: 33 µs for one position, against 0.11 µs per position in calls of $10^4$ to
#   $10^5$.
# - **Newton-Raphson** is as exact, at about fifteen times the cost: a sweep starts each
#   position from the last one, so about two iterations reach round-off, and a looser
#   tolerance only loses digits.
# - **Finite differences** are cheap and never accurate: use them only to check, with a step
#   chosen for the derivative you need.

# %% tags=["remove-cell"] jupyter={"source_hidden": true}
# the prose quotes the benchmark run (course/benchmark.json, checked against the README)
m = BENCH["methods"]
table_quoted = ["0.481 3.7e-15", "0.598 3.7e-15", "29.2 3.7e-15", "7.82 4.3e-15", "1.24 1.4e-05"]
assert [f"{v['us']} {v['error']}" for v in m.values()] == table_quoted + ["41.1 1.8e-15"]
quoted = {"fd_h_1e-6_error": "3.5e+03", "toggle_still_1e-13": "1.2e-03", "newton_guess": "within"}
quoted |= {"toggle_nearest": "7.8e-09", "toggle_nearest_error": "2.1e-08", "units_ratio": "1.68"}
quoted |= {"scalar_loop_slower": "60x", "units_call_us": "138 against 82", "machine": "AMD EPYC"}
quoted |= {"one_position_us": "33 ", "many_positions_us": "0.11 "}
assert (
    all(BENCH[k].startswith(v) for k, v in quoted.items()) and "0.37 rad" in BENCH["newton_guess"]
)
us = {name: float(v["us"]) for name, v in m.items()}
stated(us["closed forms, unit-aware API"] / us["closed forms, vectorised"], "1.24")
stated(us["vector loops, Newton-Raphson"] / us["closed forms, vectorised"], "15", sig=1)
assert min(us, key=us.get) == "closed forms, vectorised"

# %% [markdown]
# ## Explore: the finite-difference step
#
# Move the step $h$ (as its power of ten) and watch the error of $\alpha_4$ over the whole
# cycle of example 1, against the closed form. Round-off is ragged from one position to the
# next; truncation is smooth.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The error of $\\alpha_4$ from central differences over a cycle, at several steps $h$."}}
cycle = np.radians(np.arange(0.0, 360.0))
exact_cycle = closed_form.solve(**geometry, theta2=cycle, omega2=10.0, alpha2=-5.0).alpha4


def draw(log10_h):
    e = np.abs(by_differences(10.0**log10_h, cycle)["alpha4"] / exact_cycle - 1)
    fig, ax = plt.subplots(figsize=(4.6, 3.4))
    ax.semilogy(np.degrees(cycle), np.maximum(e, 1e-16), color="#E69F00", lw=1.2)
    ax.set(ylim=(1e-14, 1e6), xticks=range(0, 361, 90), xlabel=r"$\theta_2$ [deg]")
    ax.set(
        ylabel=r"error of $\alpha_4$", title=f"$h = 10^{{{log10_h:g}}}$ rad: worst {e.max():.0e}"
    )
    return fig


explore(draw, log10_h=(-9, -1, 0.5, -4), values=[-8, -5, -3, -1])

# %% [markdown]
# ## Check yourself
#
# **1.** `FourBar(...).solve(theta2=...)` raises `Singular` $10^{-9}$ rad from a toggle. Is
# the position wrong? What should you do?
#
# <details><summary>Answer</summary>
#
# The position exists; its derivatives are what the solver will not vouch for (its round-off
# estimate passes $10^{-6}$). Move away a little, or pass an array and read `valid`,
# `status` and `roundoff`; and ask whether the machine should run there at all.
#
# </details>
#
# **2.** An optimisation needs $\alpha_4$ of a fourbar at a million crank angles, thousands of
# times. Which method, and how do you call it?
#
# <details><summary>Answer</summary>
#
# The closed-form kernel, `accelab.solver.kernels.fourbar.solve`, with one array of all the
# angles in SI floats and `order=2` (only what is needed); units converted once, outside the
# loop.
#
# </details>

# %% [markdown]
# ## Common mistakes
#
# - **"A smaller step is more accurate."** Not below $\epsilon^{1/(n+2)}$: round-off then
#   grows faster than truncation falls, and the higher the derivative, the sooner.
# - **Units inside the inner loop.** One Quantity per number, or one solver call per position,
#   multiplies the cost; wrap arrays and convert at the edges.
# - **Trusting numbers next to a toggle because they came out.** A method that does not say
#   where it cannot be trusted (finite differences, a home-made formula) is silently wrong
#   there. Use `valid` and `roundoff`.
#
# This is the last notebook. Back to the contents: [1. Rotating point](01_rotating_point.ipynb)
# · [2. Graphical fourbar](02_graphical_fourbar.ipynb) · [3. Analytic
# fourbar](03_analytic_fourbar.ipynb) · [4. Slider-crank and engine](04_slider_crank_engine.ipynb)
# · [5. Coriolis](05_coriolis.ipynb) · [6. Geared fivebar](06_geared_fivebar.ipynb) · [7. Any
# point](07_any_point.ipynb) · [8. Human tolerance](08_human_tolerance.ipynb) ·
# [9. Jerk](09_jerk.ipynb) · [10. N-bar linkages](10_nbar_linkages.ipynb)
