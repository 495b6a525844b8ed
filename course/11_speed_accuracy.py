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
# # 11. Speed and accuracy
#
# The course has met several ways of computing the same accelerations: closed forms (notebooks
# 3 to 9), Newton-Raphson on vector loops (notebook 10), the graphical construction (notebook
# 2), and, in the checks of notebook 9, finite differences of the position. This notebook puts
# them side by side on one linkage, measures what each costs and how far from the truth it is,
# and shows where each one fails.
#
# **You will be able to**
#
# - time a computation fairly (a warm-up call, repeats, the median, time per position) and
#   measure its error against a reference far more accurate than the method;
# - compare the closed forms (vectorised, in a Python loop, through the unit-aware API),
#   vector-loop Newton-Raphson at several tolerances, finite differences and the graphical
#   construction, and pick one for a job;
# - explain the V-shaped error of finite differences, truncation against round-off, and choose
#   a step near the best one ($\epsilon^{1/3}$ for a first derivative);
# - explain why accuracy falls as a toggle position nears, and read the solver's refusal there
#   (`Singular`, the `valid` mask, `roundoff`);
# - keep units at the edges of a computation instead of paying for them on every element.

# %%
import math

import matplotlib.pyplot as plt
import numpy as np
from IPython.display import Image, display

from coursekit import explore, use_style
from solver import FourBar, Q_, Singular, VectorLoopLinkage
from benchmarks import accuracy
from benchmarks.cases import all_cases
from benchmarks.charts import STYLE
from benchmarks.methods import methods as bench_methods
from benchmarks.timing import measure_interleaved
from solver.graphical import construct
from solver.kernels import MAX_ROUNDOFF
from solver.kernels import fourbar as closed_form

try:  # the reference needs mpmath (installed with the test extra: pip install -e ".[test]")
    from benchmarks.reference import at_points
    HAVE_MPMATH = True
except ImportError:
    HAVE_MPMATH = False

use_style()
EPS = np.finfo(float).eps                   # 2.2e-16: the spacing of float64 numbers near 1

# %% [markdown]
# ## The idea and its equations
#
# **Two numbers for every method.** *Time per position*: the median wall-clock time of
# repeated calls, after one warm-up call that is not counted (it pays for imports and caches),
# divided by the number of positions the call solved. *Error*: for each output $x$ at each
# position, against a reference value $x_\text{ref}$,
#
# $$ e = \frac{\left|x - x_\text{ref}\right|}{\max\left(\left|x_\text{ref}\right|,\ s\right)} $$
#
# where $s$ is the median of $|x_\text{ref}|$ over the cycle, so that an output passing through
# zero is judged against its usual size rather than against zero (angle differences are taken
# modulo $2\pi$). A method's error is the worst $e$ over its outputs and positions. The
# reference must be far more accurate than anything it judges: here it is the same vector loops
# closed again in `mpmath` at 30 significant digits (60 near a toggle) and rounded to float64
# only at the end. Float64 numbers carry about 16 digits ($\epsilon = 2.2\times10^{-16}$), so an
# error near $10^{-15}$ is as good as a float64 answer gets.
#
# **Finite differences.** If only the position can be computed (a position solver without
# derivatives, a CAD export, a measured path), the derivatives can be estimated from positions
# at nearby crank angles. For $f(\theta_2) = \theta_4$, write $k_n$ for its $n$-th derivative
# $d^n\theta_4/d\theta_2^n$; with a step $h$, the central differences are
#
# $$ k_1 \approx \frac{f(\theta_2+h) - f(\theta_2-h)}{2h}, \qquad
#    k_2 \approx \frac{f(\theta_2+h) - 2f(\theta_2) + f(\theta_2-h)}{h^2} $$
#
# $$ k_3 \approx \frac{f(\theta_2+2h) - 2f(\theta_2+h) + 2f(\theta_2-h) - f(\theta_2-2h)}{2h^3} $$
#
# and the chain rule turns them into time derivatives:
#
# $$ \omega_4 = k_1\omega_2, \qquad \alpha_4 = k_2\omega_2^2 + k_1\alpha_2, \qquad
#    \varphi_4 = k_3\omega_2^3 + 3k_2\omega_2\alpha_2 + k_1\varphi_2 $$
#
# Each estimate of the $n$-th derivative makes two errors. *Truncation*: the Taylor terms the
# formula drops, proportional to $h^2$ for these central differences. *Round-off*: every
# computed $f$ is off by about $\epsilon\left|f\right|$, and the formula divides those errors by
# $h^n$:
#
# $$ E_n(h) \approx C_n h^2 + \frac{\epsilon\left|f\right|}{h^n} $$
#
# Shrinking $h$ cuts the first term and inflates the second. On log-log axes the error is a V,
# lowest where the two terms are equal, at $h^\ast \sim \epsilon^{1/(n+2)}$ with an error of
# about $\epsilon^{2/(n+2)}$: $h^\ast \approx \epsilon^{1/3} \approx 6\times10^{-6}$ rad and an
# error near $10^{-11}$ for velocity, $\epsilon^{1/4} \approx 10^{-4}$ rad and $10^{-8}$ for
# acceleration, $\epsilon^{1/5} \approx 7\times10^{-4}$ rad and $10^{-6}$ for jerk. No step
# gives all three well, and none comes near $10^{-15}$.
#
# **Near a toggle.** The closed forms divide by $bc\sin(\theta_4 - \theta_3)$ (the denominator
# of eq. 7.12), which vanishes when links 3 and 4 fall in line. Every output there is computed
# from one small "gap" $g$: how far $\left|O_4 - A\right|$ is from $b + c$ or
# $\left|b - c\right|$. The gap is the difference of lengths of ordinary size, so it carries an
# absolute round-off of about $\epsilon(a + b + c + d)$, and the outputs, which grow like
# $g^{-1/2}$ (velocity) to $g^{-5/2}$ (jerk), inherit a relative round-off of about
#
# $$ \rho \approx 4\,\epsilon\,\frac{a + b + c + d}{g} $$
#
# (the 4 was calibrated against a 50-digit reference on some 850 random linkages). The solver
# computes this estimate at every position and returns it as `roundoff`; where it exceeds
# `MAX_ROUNDOFF` $= 10^{-6}$ it refuses to answer: NaN, `valid` False and status `'singular'` in
# an array, a `Singular` error for a single position. The gap shrinks in proportion to the
# crank's distance $\delta$ from the toggle, so accuracy falls like $1/\delta$, and the refusal
# starts about $10^{-8}$ rad from the toggle.
#
# **Newton-Raphson's tolerance.** Notebook 10 showed each Newton step roughly squaring the
# error. In a sweep each position starts from the last one moved on by the velocity, already
# close, so about two steps reach round-off. A loose tolerance can save at most one of them:
# it loses accuracy and buys almost no time.
#
# **Units.** pint checks and converts units at every operation, a fixed cost of microseconds
# per operation whatever the array holds. One Quantity wrapping an array of 360 crank angles pays
# it once; 360 Quantities, one per angle, pay it 360 times.

# %% [markdown]
# ## Worked examples
#
# ### 1. Six methods on one linkage
#
# The fourbar of notebook 3 ($a$ = 2, $b$ = 6, $c$ = 9, $d$ = 7 in, open circuit) over a full
# turn in steps of $1^\circ$ (360 positions), driven at $\omega_2$ = 10 rad/s,
# $\alpha_2$ = -5 rad/s² and a crank jerk $\varphi_2$ = 20 rad/s³ (so that every term of the jerk
# equation counts). Each method solves all 360 positions; the reference is computed at every
# tenth (36 positions), which is enough to find each method's worst.
#
# The unit-free kernels take SI floats, so the geometry is written once in metres for them and
# once as Quantities for the unit-aware classes.

# %%
cases = all_cases()                          # the benchmark's linkages (SI floats)
case = cases["fourbar-open"]                 # the 2-6-9-7 in fourbar, open circuit
IN = 0.0254                                  # m per inch
geometry = dict(a=2 * IN, b=6 * IN, c=9 * IN, d=7 * IN)          # [m]
motion = dict(omega2=10.0, alpha2=-5.0, jerk2=20.0)            # [rad/s, rad/s^2, rad/s^3]
theta2 = np.radians(np.arange(0.0, 360.0))                      # [rad], 360 positions
picked = slice(0, None, 10)                                     # where the reference is computed
OUTPUTS = ["theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4", "jerk3", "jerk4"]
ORDER = {"theta": 0, "omega": 1, "alpha": 2, "jerk": 3}


def reference(case, angles, dps=30, **motion_):
    """Every output of ``case`` at ``angles`` [rad], the loops closed in mpmath at ``dps``
    digits (each position from the closed form's assembly), rounded to float64 at the end."""
    start = case.kernel(angles, order=0)
    guesses = [{"R3": float(start.theta3[i]), "R4": float(start.theta4[i])}
               for i in range(len(angles))]
    return at_points(case, angles, guesses, dps=dps, motion=motion_ or None)


if HAVE_MPMATH:
    ref = reference(case, theta2[picked])
    REFERENCE = "mpmath, 30 digits"
else:  # without mpmath the closed forms stand in: they cannot then be judged themselves
    m = closed_form.solve(**geometry, theta2=theta2[picked], **motion)
    ref = {k: getattr(m, k) for k in OUTPUTS}
    REFERENCE = "the closed forms (install mpmath for a true reference)"
scale = accuracy.scales(ref)
print(f"reference: {REFERENCE}, at {len(ref['alpha4'])} positions")

# %% [markdown]
# The methods, each written as the call a user would make. A method returns what its API
# returns (the `run` part is what is timed); reading the outputs out as SI arrays for the
# comparison is kept apart.

# %%
fourbar = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
loops = VectorLoopLinkage(                                     # the same fourbar as one loop
    vectors={"R1": {"length": "7 in", "angle": "0 deg"},
             "R2": {"length": "2 in", "angle": "input"},
             "R3": {"length": "6 in", "angle": "unknown", "guess": "110 deg"},
             "R4": {"length": "9 in", "angle": "unknown", "guess": "140 deg"}},
    loops=["R2 + R3 - R4 - R1"])
angles = Q_(theta2, "rad")                                      # one Quantity, 360 angles
inputs = dict(omega2=Q_(10.0, "rad/s"), alpha2=Q_(-5.0, "rad/s^2"), jerk2=Q_(20.0, "rad/s^3"))
as_floats = theta2.tolist()
SI = {"theta": "rad", "omega": "rad/s", "alpha": "rad/s^2", "jerk": "rad/s^3"}


def finite_differences(h, angles=theta2, geometry=geometry, omega2=10.0, alpha2=-5.0,
                       jerk2=20.0):
    """theta3, theta4 and their time derivatives from the closed-form *position* alone:
    central differences of step h [rad] in theta2, then the chain rule."""
    stencil = angles + h * np.arange(-2, 3)[:, None]            # 5 rows: theta2 - 2h .. + 2h
    position = closed_form.solve(**geometry, theta2=stencil, omega2=0.0, order=0)
    out = {}
    for k in "34":
        f = getattr(position, "theta" + k)
        f = f[2] + np.angle(np.exp(1j * (f - f[2])))             # no 2 pi jumps in a stencil
        d1 = (f[3] - f[1]) / (2 * h)
        d2 = (f[3] - 2 * f[2] + f[1]) / h**2
        d3 = (f[4] - 2 * f[3] + 2 * f[1] - f[0]) / (2 * h**3)
        out["theta" + k] = np.angle(np.exp(1j * f[2]))
        out["omega" + k] = d1 * omega2
        out["alpha" + k] = d2 * omega2**2 + d1 * alpha2
        out["jerk" + k] = d3 * omega2**3 + 3 * d2 * omega2 * alpha2 + d1 * jerk2
    return out


def from_motion(m):            # a kernel Motion
    return {k: getattr(m, k) for k in OUTPUTS}


def from_list(ms):             # one Motion, or one dict of values, per position
    if isinstance(ms[0], dict):
        return {k: np.array([float(m[k]) for m in ms]) for k in OUTPUTS if k in ms[0]}
    return {k: np.array([getattr(m, k) for m in ms]) for k in OUTPUTS}


def from_result(r):            # a unit-aware Result
    return {k: getattr(r, k).m_as(SI[k[:-1]]) for k in OUTPUTS}


def from_loops(r):             # a VectorLoopLinkage result: the vectors R3 and R4
    out = {}
    for k in "34":
        v = r.vectors["R" + k]
        out["theta" + k] = np.angle(np.exp(1j * v.angle.m_as("rad")))
        for word in ("omega", "alpha", "jerk"):
            out[word + k] = getattr(v, word).m_as(SI[word])
    return out


METHODS = {   # name: (run, read, family in the benchmark's charts)
    "closed forms, vectorised": (
        lambda: closed_form.solve(**geometry, theta2=theta2, **motion), from_motion, "kernels"),
    "closed forms, unit-aware API": (
        lambda: fourbar.solve(theta2=angles, **inputs), from_result, "units"),
    "closed forms, Python loop": (
        lambda: [closed_form.solve(**geometry, theta2=t, **motion) for t in as_floats],
        from_list, "scalar"),
    **{f"vector loops, tol {tol:g}": (
        lambda tol=tol: loops.solve(theta2=angles, **inputs, tol=tol), from_loops, "loops")
       for tol in (1e-4, 1e-8, 1e-13)},
    **{f"finite differences, h = {h:g} rad": (
        lambda h=h: finite_differences(h), dict, "fd") for h in (1e-2, 1e-3, 1e-4, 1e-6)},
    "graphical construction": (
        lambda: [construct("fourbar", "open", **geometry, theta2=t, omega2=10.0,
                           alpha2=-5.0).values for t in as_floats], from_list, "graphical"),
}

# the finite differences above are the benchmark's (benchmarks.methods), written out; the
# two agree to round-off (which, divided by h^3 in the jerk, is about 1e-7 here)
run, read = next(m for m in bench_methods(include_peers=False)
                 if m.key == "fd-h1e-03").prepare(case, theta2)
bench_fd, ours = read(run()), finite_differences(1e-3)
differences = accuracy.relative_errors(ours, bench_fd, accuracy.scales(bench_fd), OUTPUTS)
assert max(np.max(d) for d in differences.values()) < 1e-5

# %% [markdown]
# Now time each one and measure its worst error up to acceleration and up to jerk. The clock
# (`benchmarks.timing`) warms each method up, then times them in turn within each of five
# repeats, so that a busy machine slows them all alike, and reports the median:

# %%
def worst(values, up_to):
    names = [k for k in OUTPUTS if ORDER[k[:-1]] <= up_to and k in values]
    picked_values = {k: np.asarray(values[k])[picked] for k in names}
    errors = accuracy.relative_errors(picked_values, ref, scale, names)
    return float(np.nanmax(accuracy.worst(errors)))


clocks = measure_interleaved([run for run, _, _ in METHODS.values()], repeats=5, min_time=0.01)
table = {}
for (name, (run, read, family)), clock in zip(METHODS.items(), clocks):
    result = run()
    values = read(result)
    table[name] = {"us": clock["median"] / theta2.size * 1e6, "family": family,
                   "acc": worst(values, 2),
                   "jerk": worst(values, 3) if "jerk4" in values else None}
    if name.startswith("vector loops"):
        table[name]["iterations"] = np.mean(result.iterations)

print(f"{'method':36s}{'us/position':>12s}{'worst error':>14s}{'worst error':>14s}")
print(f"{'':36s}{'':>12s}{'to accel.':>14s}{'to jerk':>14s}")
for name, row in table.items():
    jerk = f"{row['jerk']:14.1e}" if row["jerk"] is not None else f"{'(no jerk)':>14s}"
    print(f"{name:36s}{row['us']:12.2f}{row['acc']:14.1e}{jerk}")
closed = table["closed forms, vectorised"]
assert table["finite differences, h = 0.001 rad"]["jerk"] > 1e3 * max(closed["jerk"], 1e-15)
if HAVE_MPMATH:
    assert closed["jerk"] < 1e-13 and table["graphical construction"]["acc"] < 1e-13

# %% mystnb={"figure": {"caption": "Time per position against error for each method on the 2-6-9-7 in fourbar, measured when the page was built."}, "image": {"alt": "Scatter plot on log axes of time per position against relative error, one point per method."}}
LABEL_AT = {"kernels": (-4, -15, "right"), "units": (4, 14, "left"), "scalar": (-4, 14, "right"),
            "graphical": (4, 14, "left")}     # where each label sits [points], so none overlap
fig, ax = plt.subplots(figsize=(9, 5.2))
for name, row in table.items():
    colour, marker = STYLE[row["family"]]
    y = row["jerk"] if row["jerk"] is not None else row["acc"]
    ax.plot(row["us"], max(y, 1e-16), marker, color=colour, ms=10,
            mfc=colour if row["jerk"] is not None else "white", mew=2)
    short = (name.replace("closed forms, ", "").replace("vector loops, ", "")
             .replace("finite differences, ", "").replace(" rad", ""))
    dx, dy, ha = LABEL_AT.get(row["family"], (8, 3, "left"))
    if name.endswith("h = 0.0001 rad"):             # beside its neighbour h = 0.01: go left
        dx, dy, ha = -8, 3, "right"
    ax.annotate(short, (row["us"], max(y, 1e-16)), textcoords="offset points",
                xytext=(dx, dy), ha=ha, va="center", fontsize=9, color=colour)
for family, label in (("kernels", "closed forms"), ("units", "closed forms, unit-aware"),
                      ("scalar", "closed forms, Python loop"), ("loops", "vector loops"),
                      ("fd", "finite differences"), ("graphical", "graphical (hollow: to acc.)")):
    colour, marker = STYLE[family]
    ax.plot([], [], marker, color=colour, ms=8, label=label)
ax.axhline(EPS, color="#888888", ls=":", lw=1)
ax.text(290, EPS * 1.6, "float64 epsilon", color="#666666", fontsize=9, ha="right")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlim(0.3, 300)
ax.set_ylim(1e-16, 1e5)
ax.set_xlabel("time per position [µs] (median, 360 positions per call)")
ax.set_ylabel("worst relative error, to jerk [-]")
ax.set_title("The 2-6-9-7 in fourbar, measured just now (reference: "
             + REFERENCE.split(" (")[0] + ")", fontsize=11)
ax.legend(loc="upper right", fontsize=9, ncol=2)
plt.show()

# %% [markdown]
# What to notice (your times depend on the machine; their order does not):
#
# - **The closed forms are both the fastest and as accurate as float64 allows**, about
#   $10^{-15}$ to jerk. Vectorised over 360 positions they cost well under a microsecond per
#   position. The *same* formulas called one position at a time from a Python loop give
#   identical numbers tens of times slower: the cost is Python's per-call overhead, not the
#   arithmetic.
# - **Units cost little when one Quantity holds the whole array** (the unit-aware API is a
#   fraction slower than the kernels here; example 4 shows when they cost much more).
# - **Newton-Raphson** on the same loop is exact too at its default tolerance, ten or twenty
#   times dearer than the closed forms, and takes two iterations per position. Loosening the
#   tolerance to $10^{-4}$ loses six or seven digits and saves almost nothing.
# - **Finite differences** are cheap (five position solves per point) and never accurate: the
#   best step here gives about $10^{-5}$ in jerk. $h = 10^{-6}$ rad is worse than useless.
# - **The graphical construction**, an independent geometric method, agrees with the
#   reference to round-off, costs as much as the Python loop, and stops at acceleration.

# %%
for name, row in table.items():
    if "iterations" in row:
        print(f"{name[14:]:10s}: {row['iterations']:.2f} iterations per position, "
              f"{row['us']:.1f} us/position, worst error {row['jerk']:.1e}")

# %% [markdown]
# ### 2. Finite differences: truncation against round-off
#
# At one position, $\theta_2 = 30°$, estimate the first three derivatives of $\theta_4$ with
# respect to $\theta_2$ ($k_1$, $k_2$, $k_3$) at steps from $10^{-12}$ to $10^{-1}$ rad. Driving
# the crank at $\omega_2$ = 1 rad/s with $\alpha_2 = \varphi_2 = 0$ makes the time derivatives
# equal the $\theta_2$ derivatives, so the reference is simply $\omega_4$, $\alpha_4$,
# $\varphi_4$ at that input.

# %% mystnb={"figure": {"caption": "Central differences of theta4 at theta2 = 30 deg: the error against the step h, truncation on the right and round-off on the left."}, "image": {"alt": "Log-log plot of finite-difference error against step size, a V shape."}}
at30 = np.radians([30.0])
unit_motion = dict(omega2=1.0, alpha2=0.0, jerk2=0.0)
if HAVE_MPMATH:
    exact = reference(case, at30, **unit_motion)
else:
    exact = from_motion(closed_form.solve(**geometry, theta2=at30, **unit_motion))
steps = np.logspace(-12, -1, 45)
derivative = {1: "omega4", 2: "alpha4", 3: "jerk4"}
errors = {n: [] for n in derivative}
for h in steps:
    fd = finite_differences(h, angles=at30, **unit_motion)
    for n, name in derivative.items():
        errors[n].append(abs(fd[name][0] - exact[name][0]) / abs(exact[name][0]))

fig, ax = plt.subplots(figsize=(8.5, 5))
colours = {1: STYLE["kernels"][0], 2: STYLE["loops"][0], 3: STYLE["fd"][0]}
words = {1: "$k_1 = d\\theta_4/d\\theta_2$", 2: "$k_2 = d^2\\theta_4/d\\theta_2^2$",
         3: "$k_3 = d^3\\theta_4/d\\theta_2^3$"}
for n in derivative:
    e = np.array(errors[n])
    ax.loglog(steps, e, "o-", ms=3.5, color=colours[n], label=words[n])
    best = int(np.argmin(e))
    ax.plot(steps[best], e[best], "o", ms=11, mfc="none", mec=colours[n], mew=2)
    h_star = EPS ** (1 / (n + 2))
    ax.axvline(h_star, color=colours[n], ls=":", lw=1.2)
    ax.text(h_star * 1.15, 1e4 / 10 ** (1.3 * n), f"$\\epsilon^{{1/{n + 2}}}$",
            color=colours[n], fontsize=12)
    print(f"derivative {n}: best step {steps[best]:.1e} rad (eps^(1/{n + 2}) = {h_star:.1e}),"
          f" error {e[best]:.1e}; at h = 1e-8: {np.interp(-8, np.log10(steps), e):.1e}")
hh = np.logspace(-12, -1, 2)
ax.loglog(hh, hh**2, color="#888888", ls="--", lw=1)
ax.text(2e-2, 2e-2**2 * 3, "truncation $\\propto h^2$", color="#666666", fontsize=9,
        ha="right")
ax.loglog(hh, EPS / hh, color="#888888", ls="-.", lw=1)
ax.text(2e-11, EPS / 2e-11 * 3, "round-off $\\propto \\epsilon/h$", color="#666666", fontsize=9)
ax.set_ylim(1e-13, 1e10)
ax.set_xlabel("step $h$ [rad]")
ax.set_ylabel("relative error [-]")
ax.set_title("Central differences of $\\theta_4(\\theta_2)$ at $\\theta_2$ = 30°")
ax.legend(loc="lower left", title="derivative")
plt.show()

# %% [markdown]
# Each curve is the V the error model predicts: on the right, truncation falls as $h^2$ (slope
# 2); on the left, round-off grows as $\epsilon/h^n$ (slopes $-1$, $-2$, $-3$), jagged because
# round-off is. Where the points sit at exactly 1 (100 %), the positions in the stencil rounded to
# the same float64 numbers and the difference came out zero. The best steps lie near
# $\epsilon^{1/(n+2)}$, and the best errors near $\epsilon^{2/(n+2)}$: about $10^{-11}$,
# $10^{-8}$ and $10^{-7}$ to $10^{-6}$ (the bottom of each V is itself round-off, so it moves a
# little from one run to the next). Smaller is *not* better: at $h = 10^{-8}$ rad, a step that
# looks careful, the acceleration is pure noise and the jerk is wrong by orders of magnitude.
#
# ### 3. Near a toggle: error against distance, and the refusal
#
# The non-Grashof triple rocker of the benchmark ($a$ = 5, $b$ = 4, $c$ = 6, $d$ = 3.5 in, open)
# has a toggle where links 3 and 4 fold onto each other, $\left|O_4 - A\right| = c - b$, at
# $\theta_2 = \cos^{-1}\left((a^2 + d^2 - (c-b)^2)/2ad\right)$. Solve it at crank angles
# $10^{-13}$ to $10^{-1}$ rad beyond that, and compare with a 60-digit reference.

# %%
rocker = cases["fourbar-nongrashof-open"]
p = rocker.params
toggle = math.acos((p["a"] ** 2 + p["d"] ** 2 - (p["c"] - p["b"]) ** 2) / (2 * p["a"] * p["d"]))
delta = np.logspace(-13, -1, 25)                                # distance from the toggle [rad]
near = toggle + delta
kern = rocker.kernel(near)                                      # omega2 10, alpha2 -5, jerk2 20
fd_near = {h: finite_differences(h, angles=near, geometry=p) for h in (1e-3, 1e-5)}
cycle = rocker.kernel(rocker.theta2(37))                        # the outputs' usual sizes
rocker_scale = accuracy.scales({k: getattr(cycle, k) for k in OUTPUTS})
if HAVE_MPMATH:
    truth = reference(rocker, near, dps=60)
    measured = accuracy.worst(accuracy.relative_errors(from_motion(kern), truth, rocker_scale))
    with np.errstate(invalid="ignore"):  # NaN where the stencil reaches past the toggle
        fd_error = {h: accuracy.worst(accuracy.relative_errors(fd, truth, rocker_scale))
                    for h, fd in fd_near.items()}
refused = kern.status != 0
if not HAVE_MPMATH:
    print("mpmath is not installed: no measured errors below, only the solver's own estimate")
print(f"toggle at theta2 = {math.degrees(toggle):.6f} deg; refused at {refused.sum()} of "
      f"{refused.size} distances, the farthest {delta[refused].max():.1e} rad")
for i in (8, 10, 12, 16, 24):
    got = f"measured error {measured[i]:.1e}" if HAVE_MPMATH and not refused[i] else ""
    print(f"  delta = {delta[i]:.0e} rad: roundoff estimate {kern.roundoff[i]:.1e}, "
          f"{'refused' if refused[i] else 'answered'} {got}")

# %% mystnb={"figure": {"caption": "The triple rocker approaching its toggle: the closed forms' error grows like one over the distance until they refuse."}, "image": {"alt": "Log-log plot of error against distance to the toggle position for several methods."}}
fig, ax = plt.subplots(figsize=(9, 5))
ax.loglog(delta, kern.roundoff, color="#444444", ls="--", lw=1.5,
          label="the solver's estimate, roundoff")
ax.axhline(MAX_ROUNDOFF, color=STYLE["graphical"][0], lw=1.2)
ax.text(2e-13, MAX_ROUNDOFF * 1.8, f"MAX_ROUNDOFF = {MAX_ROUNDOFF:g}",
        color=STYLE["graphical"][0], fontsize=9)
ax.axvspan(1e-14, np.sqrt(delta[refused].max() * delta[~refused].min()), color="#eeeeee")
ax.text(3e-13, 1e-14, "closed forms refuse:\nNaN, valid False,\nor Singular raised",
        fontsize=9, color="#555555")
if HAVE_MPMATH:
    ax.loglog(delta, measured, "o-", color=STYLE["kernels"][0], ms=5,
              label="closed forms: measured error, to jerk")
    for h, style in ((1e-3, "v-"), (1e-5, "v--")):
        ax.loglog(delta, fd_error[h], style, color=STYLE["fd"][0], ms=5,
                  label=f"finite differences, h = {h:.0e} rad (NaN once past the toggle)")
ax.set_xlim(1e-13, 0.2)
ax.set_ylim(1e-16, 1e2)
ax.set_xlabel("distance of $\\theta_2$ from the toggle, $\\delta$ [rad]")
ax.set_ylabel("relative error [-]")
ax.set_title("Triple rocker (5, 4, 6, 3.5 in) approaching its toggle")
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2, fontsize=9)
plt.show()

# %% [markdown]
# The closed forms' error grows like $1/\delta$, as the round-off model says, and stays an order
# of magnitude or more below the solver's own estimate (the dashed line, which also falls like
# $1/\delta$). Where the estimate crosses $10^{-6}$ the solver stops answering: every number it
# does return is good to better than $10^{-7}$, and it refuses only crank angles within about
# $10^{-8}$ rad of the toggle. Finite differences fail differently: they answer, with no
# warning. With $h = 10^{-3}$ rad the jerk is 2 % wrong $10^{-2}$ rad from the toggle and 30 %
# wrong at $3\times10^{-3}$; then the stencil reaches past the toggle and the answer is NaN. A
# smaller step moves the trouble nearer the toggle without removing it, and costs accuracy
# everywhere else (example 2).
#
# What a user sees: one position inside the threshold raises an error that says what to do; an
# array gives a mask, a status per position and the estimate.

# %%
triple = FourBar(a="5 in", b="4 in", c="6 in", d="3.5 in")
try:
    triple.solve(theta2=Q_(toggle + 1e-9, "rad"), omega2="10 rad/s")
except Singular as err:
    print(f"Singular: {err}\n")
sweep = triple.solve(theta2=Q_(toggle + np.array([1e-9, 1e-7, 1e-4]), "rad"),
                     omega2="10 rad/s", alpha2="-5 rad/s^2")
print("valid   ", sweep.valid)
print("status  ", sweep.status)
print("roundoff", np.array2string(sweep.roundoff, precision=1))
print("alpha4  ", np.array2string(sweep.alpha4.m_as("rad/s^2"), precision=3), "rad/s^2")

# %% [markdown]
# Even where the solver answers, look at the size of the answer: $10^{-7}$ rad from the toggle,
# $\alpha_4$ is about $10^{12}$ rad/s². The numbers are right; the mechanism cannot be driven
# there at speed (notebook 3).
#
# **Newton-Raphson near a toggle** refuses at the same place (its Jacobian is the same matrix,
# singular at the toggle). Its other weakness, converging to the other assembly from a poor
# guess, grows there too, because the two assemblies come close together: notebook 10 maps its
# basins, and the benchmark's chart below counts the branch jumps.
#
# ### 4. The cost of units
#
# Adding two arrays of 1000 lengths three ways: plain floats, one Quantity per array, and one
# Quantity per element (a numpy object array of Quantities, which is what a list comprehension
# over `Q_(x, "m")` builds). Then the solver itself, at 100 crank angles: one call with an array
# against 100 calls with one angle each.

# %% mystnb={"figure": {"caption": "Where the units go: one unit conversion per call, or one per position."}, "image": {"alt": "Bar chart of the time spent with and without units, for one call over many angles and many calls with one angle."}}
x, y = np.linspace(0.1, 0.2, 1000), np.linspace(0.3, 0.4, 1000)
qx, qy = Q_(x, "m"), Q_(y, "in")
ex = np.array([Q_(v, "m") for v in x], dtype=object)
ey = np.array([Q_(v, "in") for v in y], dtype=object)
assert np.allclose((ex + ey)[-1].m_as("m"), (qx + qy).m_as("m")[-1])
adds = {"floats (numpy)": lambda: x + y, "one Quantity per array": lambda: qx + qy,
        "one Quantity per element": lambda: ex + ey}
t_add = {k: clock["median"] for k, clock in
         zip(adds, measure_interleaved(list(adds.values()), repeats=5, min_time=0.005))}
for k, t in t_add.items():
    print(f"add 1000 lengths, {k:26s}: {t * 1e6:9.1f} us "
          f"({t / t_add['floats (numpy)']:6.0f} x floats)")

hundred = np.linspace(0.0, 2 * np.pi, 100, endpoint=False)      # 100 crank angles [rad]
calls = {
    "kernel, one array": lambda: closed_form.solve(**geometry, theta2=hundred, **motion),
    "FourBar, one array": lambda: fourbar.solve(theta2=Q_(hundred, "rad"), **inputs),
    "kernel, 100 calls": lambda: [closed_form.solve(**geometry, theta2=t, **motion)
                                  for t in hundred.tolist()],
    "FourBar, 100 calls": lambda: [fourbar.solve(theta2=Q_(t, "rad"), **inputs)
                                   for t in hundred.tolist()],
}
t_call = {k: clock["median"] / hundred.size * 1e6
          for k, clock in zip(calls, measure_interleaved(list(calls.values()), repeats=5,
                                                         min_time=0.01))}

fig, ax = plt.subplots(figsize=(8, 3.2))
names = list(t_call)
bars = ax.barh(names, [t_call[k] for k in names],
               color=[STYLE["kernels"][0], STYLE["units"][0], STYLE["scalar"][0], "#7F7F7F"])
for bar, k in zip(bars, names):
    ax.text(bar.get_width() * 1.1, bar.get_y() + bar.get_height() / 2,
            f"{t_call[k]:.1f} µs", va="center", fontsize=10)
ax.set_xscale("log")
ax.set_xlim(0.1, 2000)
ax.invert_yaxis()
ax.set_xlabel("time per position [µs], fourbar position to jerk, 100 positions")
ax.set_title("Where the units go: once per call, or once per position")
plt.show()
print(f"FourBar: 100 calls cost {t_call['FourBar, 100 calls'] / t_call['FourBar, one array']:.0f}"
      f" times one call with an array; the units add "
      f"{t_call['FourBar, one array'] / t_call['kernel, one array']:.1f}x to an array call")

# %% [markdown]
# pint's cost is per operation, not per number. Wrapped around a whole array it is paid once (a
# few tens of microseconds, here including the conversion from inches); spread over the elements
# it is paid a thousand times, and the same addition takes tens of milliseconds.
# The solver is built the same way: its kernels are plain numpy on SI floats and the classes
# convert at the edges, once per call. So pass the solver arrays, not loops of scalars, and if you
# must call it position by position (an interactive tool, say), know that each call carries a
# fixed cost of tens of microseconds.

# %% [markdown]
# ### 5. The same questions at scale: the benchmark
#
# `make bench` (`accelab bench`) asks these questions of every linkage in `benchmarks/cases.py`
# over full cycles, adds three packages from other authors for comparison, and publishes its
# charts in `figures/` (the README's *Speed and accuracy* section lists the numbers). First,
# time against error for every method and setting on the fourbar of example 1, to jerk:

# %% mystnb={"figure": {"caption": "Benchmark chart 1: time per position against worst relative error, per method and setting."}, "image": {"alt": "Scatter plot on log axes of time per position against worst relative error for every method."}}
display(Image(filename="../figures/bench-speed-accuracy.png"))

# %% [markdown]
# The dashed line joins the methods that nothing beats on both counts at once (the Pareto
# front): the vectorised closed forms, then the Python loop and the graphical construction,
# which are slower and no more accurate in any useful sense. Every finite-difference step lies
# far above it, and the general solver's loose tolerances lie above its default one. Next, the
# toggle (left, the study of example 3 with more methods) and Newton-Raphson's starting guess
# (right):

# %% mystnb={"figure": {"caption": "Benchmark chart 2: error against distance to a toggle position, and Newton-Raphson's outcomes against its starting guess."}, "image": {"alt": "Two panels: error against distance to a toggle, and converged assembly against the error of the starting guess."}}
display(Image(filename="../figures/bench-stability.png"))

# %% [markdown]
# On the left, every method that refuses (the grey band) refuses at the same place, and the
# one peer that never refuses returns numbers more than 10 % wrong there. On the right, a guess
# off by up to a third of a radian still finds the intended assembly of the Grashof fourbar;
# $10^{-4}$ rad from a toggle, where the two assemblies are close, guesses more than about
# 0.005 rad off start to land on the other one, and at 0.1 rad off nearly half of them do. Last,
# how the cost per position falls with the work done in one call:

# %% mystnb={"figure": {"caption": "Benchmark chart 3: time per position against the number of positions and of loops."}, "image": {"alt": "Log-log plot of time per position against the number of positions for several methods."}}
display(Image(filename="../figures/bench-scaling.png"))

# %% [markdown]
# On the left, one call has a fixed cost of tens of microseconds; spread over more positions it
# fades until, from about $10^4$ positions on, the closed forms cost 0.15 to 0.25 µs per
# position, while the Python loop stays where it started. On the right, the general solver's cost
# grows with the number of loops, about 5 µs per position for each loop added.
#
# ## Which method when
#
# | method | cost per position | error | use it for | where it fails |
# |---|---|---|---|---|
# | closed forms, vectorised (`solver.kernels`, or a class with an array of `theta2`) | 0.2-1 µs | $10^{-15}$, to jerk | whole cycles, design sweeps, optimisation | only the mechanisms that have one; refuses within about $10^{-8}$ rad of a toggle, loses accuracy like $1/\delta$ before it |
# | closed forms, unit-aware (`FourBar(...).solve`) | + tens of µs per call | the same | reading one position with units, teaching, checking | many calls of one position each: the per-call cost of pint |
# | closed forms in a Python loop | 30-40 µs | the same | nothing an array cannot do | speed |
# | vector loops, Newton-Raphson (`VectorLoopLinkage`) | 10-20 µs, more with each loop | $10^{-14}$ at the default tolerance | any linkage without a closed form (notebook 10) | needs guesses that pick the assembly; can land on the other assembly from a poor guess; singular at toggles |
# | finite differences of the position | 1-2 µs | $10^{-11}$ velocity, $10^{-8}$ acceleration, $10^{-5}$ jerk at best | a check when only positions exist | the step: too large truncates, too small amplifies round-off; silently wrong near toggles |
# | graphical construction (`solver.graphical`) | about 40 µs | $10^{-15}$, to acceleration | seeing the vectors; an independent check | one position at a time; no jerk |
#
# In one sentence: use a closed form on arrays whenever the mechanism has one, Newton-Raphson on
# arrays when it does not, the graphical construction to see and to check, and finite
# differences only to check, with a step chosen for the derivative you need.

# %% [markdown]
# ## Explore: the finite-difference step
#
# Move the step $h$ (as its power of ten) and watch the error of $\omega_4$, $\alpha_4$ and
# $\varphi_4$ over the whole cycle of example 1, measured against the closed forms (whose error,
# $10^{-15}$, is far below anything on this plot). Find the step where the jerk is best, and see
# what it does to the velocity.

# %% mystnb={"figure": {"caption": "Finite-difference velocities at several steps h against the exact curve."}, "image": {"alt": "Small multiples of velocity against crank angle for several finite-difference steps."}}
exact_cycle = from_motion(closed_form.solve(**geometry, theta2=theta2, **motion))
cycle_scale = accuracy.scales(exact_cycle)
degrees = np.degrees(theta2)


def draw(log10_h):
    h = 10.0 ** log10_h
    e = accuracy.relative_errors(finite_differences(h), exact_cycle, cycle_scale,
                                 ["omega4", "alpha4", "jerk4"])
    fig, ax = plt.subplots(figsize=(5.4, 3.6))
    for name, colour, label in (("omega4", colours[1], "$\\omega_4$"),
                                ("alpha4", colours[2], "$\\alpha_4$"),
                                ("jerk4", colours[3], "$\\varphi_4$")):
        ax.semilogy(degrees, np.maximum(e[name], 1e-16), color=colour, lw=1.2,
                    label=f"{label}: worst {np.max(e[name]):.0e}")
    ax.set_ylim(1e-14, 1e6)
    ax.set_xticks(range(0, 361, 90))
    ax.set_xlabel("$\\theta_2$ [deg]")
    ax.set_ylabel("relative error [-]")
    ax.set_title(f"h = {h:.0e} rad", fontsize=10)
    ax.legend(loc="lower right", fontsize=8, ncol=1)
    return fig


explore(draw, log10_h=(-9, -1, 0.5, -3), values=[-8, -5, -3, -1])

# %% [markdown]
# At $h = 10^{-8}$ rad round-off rules: the velocity is still usable, the acceleration and the
# jerk are noise. At $10^{-5}$ the velocity is near its best and the jerk still useless. At
# $10^{-3}$ the jerk is at its best (about $10^{-5}$), bought with a velocity a thousand times
# worse than it could be. At $10^{-1}$ truncation rules all three. The two kinds of error also
# look different round the cycle: round-off is ragged from one position to the next, truncation
# is smooth (its sharp dips are where the error changes sign).

# %% [markdown]
# ## Check yourself
#
# **1.** You estimate an acceleration (a second derivative) by central differences with
# $h = 10^{-8}$ rad. Roughly how large is the round-off error, relative to the value?
#
# <details><summary>Answer</summary>
#
# About $\epsilon/h^2 = 2\times10^{-16}/10^{-16} \approx 2$: the estimate is pure noise. The best
# step for a second derivative is near $\epsilon^{1/4} \approx 10^{-4}$ rad, where the error is
# about $10^{-8}$.
#
# </details>
#
# **2.** Why does loosening Newton-Raphson's tolerance from $10^{-13}$ to $10^{-4}$ save almost no
# time in a sweep, yet cost six or seven digits?
#
# <details><summary>Answer</summary>
#
# Each position starts from a prediction that is already close, and Newton-Raphson converges
# quadratically, so about two steps reach round-off anyway; the loose tolerance saves at most the
# last step. Stopping earlier leaves an error near the tolerance (divided by the condition
# measure), and velocity to jerk, solved exactly at that slightly wrong position, inherit it.
#
# </details>
#
# **3.** `FourBar(...).solve(theta2=...)` raises `Singular` at a crank angle $10^{-9}$ rad from a
# toggle. Is the position wrong? What should you do?
#
# <details><summary>Answer</summary>
#
# The position exists; what the solver will not vouch for are its derivatives: its round-off
# estimate there (about $6\times10^{-6}$ for the triple rocker) exceeds $10^{-6}$. Move $\theta_2$
# away from the toggle (about $10^{-6}$ rad is plenty), or pass an array and read `valid`,
# `status` and `roundoff`. And ask whether the machine should run there at all: the accelerations
# a hair from a toggle are enormous.
#
# </details>
#
# **4.** An optimisation needs $\alpha_4$ of a fourbar at $10^6$ crank angles, thousands of
# times. Which method, and how would you call it?
#
# <details><summary>Answer</summary>
#
# The closed-form kernel, `solver.kernels.fourbar.solve`, with one array of all the angles in SI
# floats and `order=2` (compute only what is needed): a fraction of a microsecond per position,
# so a fraction of a second per evaluation. Units at the edges only: convert the design
# variables once, not inside the loop.
#
# </details>
#
# **5.** The graphical construction agrees with the reference to $10^{-15}$. Why not always use
# it?
#
# <details><summary>Answer</summary>
#
# It builds the construction one position at a time in Python (tens of microseconds each, dozens
# of times the cost of the vectorised closed forms), and it stops at acceleration: there is no jerk
# polygon. Its strength is that it is independent, and that it shows the vectors.
#
# </details>

# %% [markdown]
# ## Common mistakes
#
# - **Timing one call, or the first call.** The first call pays for imports and caches, and a
#   single run is at the mercy of whatever else the machine is doing. Warm up, repeat, take the
#   median, and divide by the positions solved. Compare methods timed in the same session.
# - **Checking a method against one no better than itself.** Two finite-difference estimates
#   that agree prove nothing. The reference must be orders of magnitude more accurate than what
#   it judges (here, 30 to 60 digits).
# - **"A smaller step is more accurate."** Not below $\epsilon^{1/(n+2)}$: round-off then grows
#   faster than truncation falls, and the higher the derivative, the sooner.
# - **Units inside the inner loop.** One Quantity per number, or one solver call per position,
#   multiplies the cost by tens to thousands. Wrap arrays, call once, convert at the edges.
# - **Loosening a tolerance to go faster.** With quadratic convergence and a good predictor it
#   saves nothing and loses digits.
# - **Trusting numbers next to a toggle because they came out.** A method that does not say
#   where it cannot be trusted (finite differences, a home-made formula) gives wrong numbers
#   silently there. Use the `valid` mask and `roundoff`, and keep NaN out of maxima and means.
# - **Comparing angles without wrapping.** $359.9°$ and $-0.1°$ are the same angle; take
#   differences modulo $2\pi$.
#
# This is the last notebook. Back to the contents:
# [1. Rotating point](01_rotating_point.ipynb) ·
# [2. Graphical fourbar](02_graphical_fourbar.ipynb) ·
# [3. Analytic fourbar](03_analytic_fourbar.ipynb) ·
# [4. Slider-crank and engine](04_slider_crank_engine.ipynb) ·
# [5. Coriolis](05_coriolis.ipynb) ·
# [6. Geared fivebar](06_geared_fivebar.ipynb) ·
# [7. Any point](07_any_point.ipynb) ·
# [8. Human tolerance](08_human_tolerance.ipynb) ·
# [9. Jerk](09_jerk.ipynb) ·
# [10. N-bar linkages](10_nbar_linkages.ipynb)
