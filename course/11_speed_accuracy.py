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
# and shows where each one fails. (The chapter, Robert L. Norton, *Design of Machinery*,
# chapter 7, solves by hand and by its closed forms; its section 7.8 leaves N-bar linkages to
# "an equation solver": this notebook asks what each way of computing costs.)
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
# %matplotlib inline
import math

import matplotlib.pyplot as plt
import numpy as np
from IPython.display import Markdown, display

from accelab.course.kit import explore, measure, stated, use_style
from accelab.solver import Q_, FourBar, Singular, VectorLoopLinkage
from accelab.solver.graphical import construct
from accelab.solver.kernels import MAX_ROUNDOFF
from accelab.solver.kernels import fourbar as closed_form

try:  # the reference needs mpmath (installed with the test extra: pip install -e ".[test]")
    import mpmath

    HAVE_MPMATH = True
except ImportError:
    HAVE_MPMATH = False

use_style()
EPS = np.finfo(float).eps  # 2.2e-16: the spacing of float64 numbers near 1
#: colour and marker of each family of methods on the charts
STYLE = {
    "kernels": ("#0072B2", "o"),
    "units": ("#56B4E9", "s"),
    "scalar": ("#009E73", "D"),
    "loops": ("#E69F00", "^"),
    "fd": ("#D55E00", "v"),
    "graphical": ("#CC79A7", "P"),
}
stated(EPS, "2.2e-16")
for n, (step, err) in {1: ("6e-6", "1e-11"), 2: ("1e-4", "1e-8"), 3: ("7e-4", "1e-6")}.items():
    stated(EPS ** (1 / (n + 2)), step, sig=1)  # h*, quoted below
    assert 0.1 < EPS ** (2 / (n + 2)) / float(err) < 10  # its error, to an order

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
# (a constant the solver calibrates against high-precision references; example 3 puts the
# estimate beside a 60-digit reference). The solver computes this estimate at every position and returns it as `roundoff`; where it exceeds
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
# The fourbar of notebook 3 ($a$ = 2, $b$ = 6, $c$ = 9, $d$ = 7 in, open circuit: the course's
# Example 7-1 linkage; **these are the course's own numbers**, the chapter's example prints
# none) over a full turn in steps of $1^\circ$ (360 positions), driven at $\omega_2$ = 10
# rad/s, $\alpha_2$ = -5 rad/s² and a crank jerk $\varphi_2$ = 20 rad/s³ (so that every term of
# the jerk equation counts). Each method solves all 360 positions; the reference is computed at
# every tenth (36 positions), which is enough to find each method's worst.
#
# **The reference.** The loop closed by geometry (two circles meeting at B) and then
# differentiated order by order, all in `mpmath` at 30 significant digits, rounded to float64
# only at the end. Differentiating $L e^{j\theta}$ gives $j\dot\theta$, then $j\ddot\theta -
# \dot\theta^2$, then $j\dddot\theta - 3\dot\theta\ddot\theta - j\dot\theta^3$ (times $L
# e^{j\theta}$); at each order the loop's derivative is linear in the two unknowns of that
# order, a 2 by 2 solve. Writing it here keeps it apart from the solver's own code.

# %%
IN = 0.0254  # m per inch
geometry = dict(a=2 * IN, b=6 * IN, c=9 * IN, d=7 * IN)  # [m]
motion = dict(omega2=10.0, alpha2=-5.0, jerk2=20.0)  # [rad/s, rad/s^2, rad/s^3]
theta2 = np.radians(np.arange(0.0, 360.0))  # [rad], 360 positions
picked = slice(0, None, 10)  # where the reference is computed
OUTPUTS = ["theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4", "jerk3", "jerk4"]
ORDER = {"theta": 0, "omega": 1, "alpha": 2, "jerk": 3}


def _rates(n, q):
    """d^n/dt^n (e^{j theta}) / e^{j theta} for q = [theta, theta', theta'', theta''']."""
    return (1j * q[1], 1j * q[2] - q[1] ** 2, 1j * q[3] - 3 * q[1] * q[2] - 1j * q[1] ** 3)[n - 1]


def reference(geometry, angles, motion, circuit="open", dps=30):
    """Every output at ``angles`` [rad]: the fourbar's loop a e^{j t2} + b e^{j t3} - c e^{j t4}
    - d = 0 closed and differentiated in mpmath at ``dps`` digits, rounded to float64."""
    out = {k: [] for k in OUTPUTS}
    with mpmath.workdps(dps):
        a, b, c, d = (mpmath.mpf(geometry[k]) for k in "abcd")
        side = 1 if circuit == "open" else -1
        for t2 in angles:
            q2 = [mpmath.mpf(float(t2))] + [
                mpmath.mpf(motion[k]) for k in ("omega2", "alpha2", "jerk2")
            ]
            A = a * mpmath.expj(q2[0])
            s = d - A  # from A to O4
            L = abs(s)
            x = (L**2 + b**2 - c**2) / (2 * L)
            B = A + (x + 1j * side * mpmath.sqrt(b**2 - x**2)) * s / L
            q3, q4 = [mpmath.arg(B - A)], [mpmath.arg(B - d)]
            e2, e3, e4 = mpmath.expj(q2[0]), mpmath.expj(q3[0]), mpmath.expj(q4[0])
            k3, k4 = 1j * b * e3, -1j * c * e4  # what multiplies the unknowns
            for n in (1, 2, 3):
                rest = (
                    a * e2 * _rates(n, q2)
                    + b * e3 * _rates(n, q3 + [0] * (4 - len(q3)))
                    - c * e4 * _rates(n, q4 + [0] * (4 - len(q4)))
                )
                det = k3.real * k4.imag - k3.imag * k4.real
                q3.append((-rest.real * k4.imag + rest.imag * k4.real) / det)
                q4.append((-k3.real * rest.imag + k3.imag * rest.real) / det)
            for k, q in (("3", q3), ("4", q4)):
                for word, value in zip(("theta", "omega", "alpha", "jerk"), q):
                    out[word + k].append(float(value))
    return {k: np.array(v) for k, v in out.items()}


def scales(values):
    """s of the error formula: the median size of each output over the positions given."""
    return {k: float(np.median(np.abs(v))) for k, v in values.items()}


def relative_errors(values, ref, scale, names=OUTPUTS):
    """e for each output at each position (angles compared modulo 2 pi)."""
    out = {}
    for k in names:
        x, r = np.asarray(values[k], dtype=float), np.asarray(ref[k], dtype=float)
        diff = np.angle(np.exp(1j * (x - r))) if k.startswith("theta") else x - r
        out[k] = np.abs(diff) / np.maximum(np.abs(r), scale[k])
    return out


def worst_per_position(errors):
    return np.max(np.vstack(list(errors.values())), axis=0)


if HAVE_MPMATH:
    ref = reference(geometry, theta2[picked], motion)
    REFERENCE = "mpmath, 30 digits"
else:  # without mpmath the closed forms stand in: they cannot then be judged themselves
    m = closed_form.solve(**geometry, theta2=theta2[picked], **motion)
    ref = {k: getattr(m, k) for k in OUTPUTS}
    REFERENCE = "the closed forms (install mpmath for a true reference)"
scale = scales(ref)
print(f"reference: {REFERENCE}, at {len(ref['alpha4'])} positions")

# %% [markdown]
# The methods, each written as the call a user would make. A method returns what its API
# returns (the `run` part is what is timed); reading the outputs out as SI arrays for the
# comparison is kept apart.

# %%
fourbar = FourBar(a="2 in", b="6 in", c="9 in", d="7 in")
loops = VectorLoopLinkage(  # the same fourbar as one loop
    vectors={
        "R1": {"length": "7 in", "angle": "0 deg"},
        "R2": {"length": "2 in", "angle": "input"},
        "R3": {"length": "6 in", "angle": "unknown", "guess": "110 deg"},
        "R4": {"length": "9 in", "angle": "unknown", "guess": "140 deg"},
    },
    loops=["R2 + R3 - R4 - R1"],
)
angles = Q_(theta2, "rad")  # one Quantity, 360 angles
inputs = dict(omega2=Q_(10.0, "rad/s"), alpha2=Q_(-5.0, "rad/s^2"), jerk2=Q_(20.0, "rad/s^3"))
as_floats = theta2.tolist()
SI = {"theta": "rad", "omega": "rad/s", "alpha": "rad/s^2", "jerk": "rad/s^3"}


def finite_differences(h, angles=theta2, geometry=geometry, omega2=10.0, alpha2=-5.0, jerk2=20.0):
    """theta3, theta4 and their time derivatives from the closed-form *position* alone:
    central differences of step h [rad] in theta2, then the chain rule."""
    stencil = angles + h * np.arange(-2, 3)[:, None]  # 5 rows: theta2 - 2h .. + 2h
    position = closed_form.solve(**geometry, theta2=stencil, omega2=0.0, order=0)
    out = {}
    for k in "34":
        f = getattr(position, "theta" + k)
        f = f[2] + np.angle(np.exp(1j * (f - f[2])))  # no 2 pi jumps in a stencil
        d1 = (f[3] - f[1]) / (2 * h)
        d2 = (f[3] - 2 * f[2] + f[1]) / h**2
        d3 = (f[4] - 2 * f[3] + 2 * f[1] - f[0]) / (2 * h**3)
        out["theta" + k] = np.angle(np.exp(1j * f[2]))
        out["omega" + k] = d1 * omega2
        out["alpha" + k] = d2 * omega2**2 + d1 * alpha2
        out["jerk" + k] = d3 * omega2**3 + 3 * d2 * omega2 * alpha2 + d1 * jerk2
    return out


def from_motion(m):  # a kernel Motion
    return {k: getattr(m, k) for k in OUTPUTS}


def from_list(ms):  # one Motion, or one dict of values, per position
    if isinstance(ms[0], dict):
        return {k: np.array([float(m[k]) for m in ms]) for k in OUTPUTS if k in ms[0]}
    return {k: np.array([getattr(m, k) for m in ms]) for k in OUTPUTS}


def from_result(r):  # a unit-aware Result
    return {k: getattr(r, k).m_as(SI[k[:-1]]) for k in OUTPUTS}


def from_loops(r):  # a VectorLoopLinkage result: the vectors R3 and R4
    out = {}
    for k in "34":
        v = r.vectors["R" + k]
        out["theta" + k] = np.angle(np.exp(1j * v.angle.m_as("rad")))
        for word in ("omega", "alpha", "jerk"):
            out[word + k] = getattr(v, word).m_as(SI[word])
    return out


METHODS = {  # name: (run, read, family of the charts)
    "closed forms, vectorised": (
        lambda: closed_form.solve(**geometry, theta2=theta2, **motion),
        from_motion,
        "kernels",
    ),
    "closed forms, unit-aware API": (
        lambda: fourbar.solve(theta2=angles, **inputs),
        from_result,
        "units",
    ),
    "closed forms, Python loop": (
        lambda: [closed_form.solve(**geometry, theta2=t, **motion) for t in as_floats],
        from_list,
        "scalar",
    ),
    **{
        f"vector loops, tol {tol:g}": (
            lambda tol=tol: loops.solve(theta2=angles, **inputs, tol=tol),
            from_loops,
            "loops",
        )
        for tol in (1e-4, 1e-8, 1e-13)
    },
    **{
        f"finite differences, h = {h:g} rad": (lambda h=h: finite_differences(h), dict, "fd")
        for h in (1e-2, 1e-3, 1e-4, 1e-6)
    },
    "graphical construction": (
        lambda: [
            construct("fourbar", "open", **geometry, theta2=t, omega2=10.0, alpha2=-5.0).values
            for t in as_floats
        ],
        from_list,
        "graphical",
    ),
}

# %% [markdown]
# Now time each one and measure its worst error up to acceleration and up to jerk. The clock
# (`accelab.course.kit.measure`) warms each method up, then times them in turn within each of five
# repeats, so that a busy machine slows them all alike, and reports the median:


# %%
def worst(values, up_to):
    names = [k for k in OUTPUTS if ORDER[k[:-1]] <= up_to and k in values]
    picked_values = {k: np.asarray(values[k])[picked] for k in names}
    return float(np.nanmax(worst_per_position(relative_errors(picked_values, ref, scale, names))))


seconds = measure([run for run, _, _ in METHODS.values()], repeats=5, min_time=0.01)
table = {}
for (name, (run, read, family)), median in zip(METHODS.items(), seconds):
    result = run()
    values = read(result)
    table[name] = {
        "us": median / theta2.size * 1e6,
        "family": family,
        "acc": worst(values, 2),
        "jerk": worst(values, 3) if "jerk4" in values else None,
    }
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
LABEL_AT = {
    "kernels": (-4, -15, "right"),
    "units": (4, 14, "left"),
    "scalar": (-4, 14, "right"),
    "graphical": (4, 14, "left"),
}  # where each label sits [points], so none overlap
fig, ax = plt.subplots(figsize=(9, 5.2))
for name, row in table.items():
    colour, marker = STYLE[row["family"]]
    y = row["jerk"] if row["jerk"] is not None else row["acc"]
    ax.plot(
        row["us"],
        max(y, 1e-16),
        marker,
        color=colour,
        ms=10,
        mfc=colour if row["jerk"] is not None else "white",
        mew=2,
    )
    short = (
        name.replace("closed forms, ", "")
        .replace("vector loops, ", "")
        .replace("finite differences, ", "")
        .replace(" rad", "")
    )
    dx, dy, ha = LABEL_AT.get(row["family"], (8, 3, "left"))
    if name.endswith("h = 0.0001 rad"):  # beside its neighbour h = 0.01: go left
        dx, dy, ha = -8, 3, "right"
    ax.annotate(
        short,
        (row["us"], max(y, 1e-16)),
        textcoords="offset points",
        xytext=(dx, dy),
        ha=ha,
        va="center",
        fontsize=9,
        color=colour,
    )
for family, label in (
    ("kernels", "closed forms"),
    ("units", "closed forms, unit-aware"),
    ("scalar", "closed forms, Python loop"),
    ("loops", "vector loops"),
    ("fd", "finite differences"),
    ("graphical", "graphical (hollow: to acc.)"),
):
    colour, marker = STYLE[family]
    ax.plot([], [], marker, color=colour, ms=8, label=label)
ax.axhline(EPS, color="#888888", ls=":", lw=1)
ax.text(
    0.98,
    EPS * 1.6,
    "float64 epsilon",
    color="#666666",
    fontsize=9,
    ha="right",
    transform=ax.get_yaxis_transform(),
)
ax.set_xscale("log")
ax.set_yscale("log")
low = min(row["us"] for row in table.values())
high = max(row["us"] for row in table.values())
ax.set_xlim(low / 3, high * 3)
ax.set_ylim(1e-16, 1e5)
ax.set_xlabel("time per position [µs] (median, 360 positions per call)")
ax.set_ylabel("worst relative error, to jerk [-]")
ax.set_title(
    "The 2-6-9-7 in fourbar, measured just now (reference: " + REFERENCE.split(" (")[0] + ")",
    fontsize=11,
)
ax.legend(loc="upper right", fontsize=9, ncol=2)
plt.show()

# %% [markdown]
# What to notice (your times depend on the machine; their order does not), with the numbers
# just measured:

# %%
loop, units_ = table["closed forms, Python loop"], table["closed forms, unit-aware API"]
nr = {tol: table[f"vector loops, tol {tol:g}"] for tol in (1e-4, 1e-8, 1e-13)}
fd_best = min((row["jerk"], name) for name, row in table.items() if row["family"] == "fd")
saving = (
    "saves little time"
    if nr[1e-4]["us"] < nr[1e-13]["us"]
    else "saves no time at all (here it even took longer: noise, or the extra checks of a loose stop)"
)
graphical = table["graphical construction"]
display(
    Markdown(f"""
- **The closed forms are both the fastest and as accurate as float64 allows**: a worst error of
  {closed["jerk"]:.0e} to jerk, at {closed["us"]:.2f} µs per position vectorised over 360
  positions. The *same* formulas called one position at a time from a Python loop give
  identical numbers {loop["us"] / closed["us"]:.0f} times slower: the cost is Python's
  per-call overhead, not the arithmetic.
- **Units cost little when one Quantity holds the whole array**: the unit-aware API takes
  {units_["us"]:.2f} µs per position, {units_["us"] / closed["us"]:.1f} times the kernels
  (example 4 shows when they cost much more).
- **Newton-Raphson** on the same loop is as exact at its default tolerance ({nr[1e-13]["jerk"]:.0e}),
  {nr[1e-13]["us"] / closed["us"]:.0f} times dearer than the closed forms, with
  {nr[1e-13]["iterations"]:.2f} iterations per position. Loosening the tolerance to $10^{{-4}}$
  costs accuracy ({nr[1e-4]["jerk"]:.0e}) and {saving}
  ({nr[1e-4]["us"]:.1f} against {nr[1e-13]["us"]:.1f} µs per position).
- **Finite differences** are cheap (five position solves per point) and never accurate: the best
  step here, {fd_best[1].split("= ")[1]}, gives {fd_best[0]:.0e} in jerk;
  $h = 10^{{-6}}$ rad gives {table["finite differences, h = 1e-06 rad"]["jerk"]:.0e}.
- **The graphical construction**, an independent geometric method, agrees with the reference to
  {graphical["acc"]:.0e} (to acceleration: it has no jerk polygon) and costs
  {graphical["us"]:.0f} µs per position, built one position at a time in Python.
""")
)
assert loop["us"] > 5 * closed["us"] and graphical["us"] > 5 * closed["us"]
assert nr[1e-4]["jerk"] > 1e3 * nr[1e-13]["jerk"]

# %%
for name, row in table.items():
    if "iterations" in row:
        print(
            f"{name[14:]:10s}: {row['iterations']:.2f} iterations per position, "
            f"{row['us']:.1f} us/position, worst error {row['jerk']:.1e}"
        )

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
    exact = reference(geometry, at30, unit_motion)
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
words = {
    1: "$k_1 = d\\theta_4/d\\theta_2$",
    2: "$k_2 = d^2\\theta_4/d\\theta_2^2$",
    3: "$k_3 = d^3\\theta_4/d\\theta_2^3$",
}
for n in derivative:
    e = np.array(errors[n])
    ax.loglog(steps, e, "o-", ms=3.5, color=colours[n], label=words[n])
    best = int(np.argmin(e))
    ax.plot(steps[best], e[best], "o", ms=11, mfc="none", mec=colours[n], mew=2)
    h_star = EPS ** (1 / (n + 2))
    ax.axvline(h_star, color=colours[n], ls=":", lw=1.2)
    ax.text(
        h_star * 1.15,
        1e4 / 10 ** (1.3 * n),
        f"$\\epsilon^{{1/{n + 2}}}$",
        color=colours[n],
        fontsize=12,
    )
    print(
        f"derivative {n}: best step {steps[best]:.1e} rad (eps^(1/{n + 2}) = {h_star:.1e}),"
        f" error {e[best]:.1e}; at h = 1e-8: {np.interp(-8, np.log10(steps), e):.1e}"
    )
hh = np.logspace(-12, -1, 2)
ax.loglog(hh, hh**2, color="#888888", ls="--", lw=1)
ax.text(2e-2, 2e-2**2 * 3, "truncation $\\propto h^2$", color="#666666", fontsize=9, ha="right")
ax.loglog(hh, EPS / hh, color="#888888", ls="-.", lw=1)
ax.text(2e-11, EPS / 2e-11 * 3, "round-off $\\propto \\epsilon/h$", color="#666666", fontsize=9)
ax.set_ylim(1e-13, 1e10)
ax.set_xlabel("step $h$ [rad]")
ax.set_ylabel("relative error [-]")
ax.set_title("Central differences of $\\theta_4(\\theta_2)$ at $\\theta_2$ = 30°")
ax.legend(loc="lower left", title="derivative")
plt.show()

# %% tags=["remove-input"] jupyter={"source_hidden": true}
best = {n: min(errors[n]) for n in derivative}
for n, quoted in ((1, 1e-11), (2, 1e-8), (3, 1e-7)):
    assert quoted / 30 < best[n] < quoted * 30, (n, best[n])
at_1e8 = {n: np.interp(-8, np.log10(steps), errors[n]) for n in derivative}
assert at_1e8[2] >= 0.5 and at_1e8[3] >= 0.5  # noise: 100 % wrong or worse

# %% [markdown]
# Each curve is the V the error model predicts: on the right, truncation falls as $h^2$ (slope
# 2); on the left, round-off grows as $\epsilon/h^n$ (slopes $-1$, $-2$, $-3$), jagged because
# round-off is. Where the points sit at exactly 1 (100 %), the positions in the stencil rounded to
# the same float64 numbers and the difference came out zero. The best steps lie near
# $\epsilon^{1/(n+2)}$, and the best errors near $\epsilon^{2/(n+2)}$: about $10^{-11}$,
# $10^{-8}$ and $10^{-7}$, to within an order of magnitude (the bottom of each V is itself
# round-off, so it moves a little from one run to the next). Smaller is *not* better: at
# $h = 10^{-8}$ rad, a step that looks careful, the acceleration and the jerk are pure noise,
# wrong by 100 % or more.
#
# ### 3. Near a toggle: error against distance, and the refusal
#
# A non-Grashof triple rocker ($a$ = 5, $b$ = 4, $c$ = 6, $d$ = 3.5 in, open)
# has a toggle where links 3 and 4 fold onto each other, $\left|O_4 - A\right| = c - b$, at
# $\theta_2 = \cos^{-1}\left((a^2 + d^2 - (c-b)^2)/2ad\right)$. Solve it at crank angles
# $10^{-13}$ to $10^{-1}$ rad beyond that, and compare with a 60-digit reference.

# %%
p = dict(a=5 * IN, b=4 * IN, c=6 * IN, d=3.5 * IN)  # [m], open circuit
toggle = math.acos((p["a"] ** 2 + p["d"] ** 2 - (p["c"] - p["b"]) ** 2) / (2 * p["a"] * p["d"]))
delta = np.logspace(-13, -1, 25)  # distance from the toggle [rad]
near = toggle + delta
kern = closed_form.solve(**p, theta2=near, **motion)
fd_near = {h: finite_differences(h, angles=near, geometry=p) for h in (1e-3, 1e-5)}
# the outputs' usual sizes: 37 positions across the range the rocker can reach
usual = closed_form.solve(
    **p, theta2=np.linspace(toggle + 0.05, 2 * np.pi - toggle - 0.05, 37), **motion
)
rocker_scale = scales(from_motion(usual))
if HAVE_MPMATH:
    truth = reference(p, near, motion, dps=60)
    measured = worst_per_position(relative_errors(from_motion(kern), truth, rocker_scale))
    with np.errstate(invalid="ignore"):  # NaN where the stencil reaches past the toggle
        fd_error = {
            h: worst_per_position(relative_errors(fd, truth, rocker_scale))
            for h, fd in fd_near.items()
        }
refused = kern.status != 0
if not HAVE_MPMATH:
    print("mpmath is not installed: no measured errors below, only the solver's own estimate")
print(
    f"toggle at theta2 = {math.degrees(toggle):.6f} deg; refused at {refused.sum()} of "
    f"{refused.size} distances, the farthest {delta[refused].max():.1e} rad"
)
for i in (8, 10, 12, 16, 24):
    got = f"measured error {measured[i]:.1e}" if HAVE_MPMATH and not refused[i] else ""
    print(
        f"  delta = {delta[i]:.0e} rad: roundoff estimate {kern.roundoff[i]:.1e}, "
        f"{'refused' if refused[i] else 'answered'} {got}"
    )

# %% mystnb={"figure": {"caption": "The triple rocker approaching its toggle: the closed forms' error grows like one over the distance until they refuse."}, "image": {"alt": "Log-log plot of error against distance to the toggle position for several methods."}}
fig, ax = plt.subplots(figsize=(9, 5))
ax.loglog(
    delta, kern.roundoff, color="#444444", ls="--", lw=1.5, label="the solver's estimate, roundoff"
)
ax.axhline(MAX_ROUNDOFF, color=STYLE["graphical"][0], lw=1.2)
ax.text(
    2e-13,
    MAX_ROUNDOFF * 1.8,
    f"MAX_ROUNDOFF = {MAX_ROUNDOFF:g}",
    color=STYLE["graphical"][0],
    fontsize=9,
)
ax.axvspan(1e-14, np.sqrt(delta[refused].max() * delta[~refused].min()), color="#eeeeee")
ax.text(
    3e-13,
    1e-14,
    "closed forms refuse:\nNaN, valid False,\nor Singular raised",
    fontsize=9,
    color="#555555",
)
if HAVE_MPMATH:
    ax.loglog(
        delta,
        measured,
        "o-",
        color=STYLE["kernels"][0],
        ms=5,
        label="closed forms: measured error, to jerk",
    )
    for h, style in ((1e-3, "v-"), (1e-5, "v--")):
        ax.loglog(
            delta,
            fd_error[h],
            style,
            color=STYLE["fd"][0],
            ms=5,
            label=f"finite differences, h = {h:.0e} rad (NaN once past the toggle)",
        )
ax.set_xlim(1e-13, 0.2)
ax.set_ylim(1e-16, 1e2)
ax.set_xlabel("distance of $\\theta_2$ from the toggle, $\\delta$ [rad]")
ax.set_ylabel("relative error [-]")
ax.set_title("Triple rocker (5, 4, 6, 3.5 in) approaching its toggle")
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2, fontsize=9)
plt.show()

# %% tags=["remove-input"] jupyter={"source_hidden": true}
answered = ~refused
boundary = math.sqrt(delta[refused].max() * delta[answered].min())
assert 1e-9 < boundary < 1e-7  # "about 1e-8 rad", to an order
assert np.all(kern.roundoff[answered] <= MAX_ROUNDOFF)
if HAVE_MPMATH:
    assert np.all(measured[answered] < 1e-7)  # every answer good to 1e-7
    assert np.all(measured[answered] < kern.roundoff[answered])  # below the estimate
    slope = np.polyfit(np.log10(delta[answered]), np.log10(measured[answered]), 1)[0]
    assert -1.4 < slope < -0.6  # grows like 1/delta
    jerk_fd = {
        d_: float(fd_error[1e-3][np.argmin(np.abs(np.log10(delta / d_)))]) for d_ in (1e-2, 3e-3)
    }  # the grid's nearest distances
    print({k: f"{v:.2g}" for k, v in jerk_fd.items()})
    stated(jerk_fd[1e-2], "0.02", sig=1), stated(jerk_fd[3e-3], "0.3", sig=1)

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
sweep = triple.solve(
    theta2=Q_(toggle + np.array([1e-9, 1e-7, 1e-4]), "rad"), omega2="10 rad/s", alpha2="-5 rad/s^2"
)
print("valid   ", sweep.valid)
print("status  ", sweep.status)
print("roundoff", np.array2string(sweep.roundoff, precision=1))
print("alpha4  ", np.array2string(sweep.alpha4.m_as("rad/s^2"), precision=3), "rad/s^2")
stated(abs(sweep.alpha4.m_as("rad/s^2")[1]), "1e12", sig=1)
stated(closed_form.solve(**p, theta2=toggle + 1e-9, **motion).roundoff, "6e-6", sig=1)

# %% [markdown]
# Even where the solver answers, look at the size of the answer: $10^{-7}$ rad from the toggle,
# $\alpha_4$ is about $10^{12}$ rad/s². The numbers are right; the mechanism cannot be driven
# there at speed (notebook 3).
#
# **Newton-Raphson near a toggle** refuses at the same place (its Jacobian is the same matrix,
# singular at the toggle). Its other weakness, converging to the other assembly from a poor
# guess, grows there too, because the two assemblies come close together: notebook 10 maps its
# basins, and the project's benchmark (`accelab bench`) counts the branch jumps.
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
adds = {
    "floats (numpy)": lambda: x + y,
    "one Quantity per array": lambda: qx + qy,
    "one Quantity per element": lambda: ex + ey,
}
t_add = dict(zip(adds, measure(list(adds.values()), repeats=5, min_time=0.005)))
for k, t in t_add.items():
    print(
        f"add 1000 lengths, {k:26s}: {t * 1e6:9.1f} us "
        f"({t / t_add['floats (numpy)']:6.0f} x floats)"
    )

hundred = np.linspace(0.0, 2 * np.pi, 100, endpoint=False)  # 100 crank angles [rad]
calls = {
    "kernel, one array": lambda: closed_form.solve(**geometry, theta2=hundred, **motion),
    "FourBar, one array": lambda: fourbar.solve(theta2=Q_(hundred, "rad"), **inputs),
    "kernel, 100 calls": lambda: [
        closed_form.solve(**geometry, theta2=t, **motion) for t in hundred.tolist()
    ],
    "FourBar, 100 calls": lambda: [
        fourbar.solve(theta2=Q_(t, "rad"), **inputs) for t in hundred.tolist()
    ],
}
t_call = {
    k: t / hundred.size * 1e6
    for k, t in zip(calls, measure(list(calls.values()), repeats=5, min_time=0.01))
}

fig, ax = plt.subplots(figsize=(8, 3.2))
names = list(t_call)
bars = ax.barh(
    names,
    [t_call[k] for k in names],
    color=[STYLE["kernels"][0], STYLE["units"][0], STYLE["scalar"][0], "#7F7F7F"],
)
for bar, k in zip(bars, names):
    ax.text(
        bar.get_width() * 1.1,
        bar.get_y() + bar.get_height() / 2,
        f"{t_call[k]:.1f} µs",
        va="center",
        fontsize=10,
    )
ax.set_xscale("log")
ax.set_xlim(0.1, 2000)
ax.invert_yaxis()
ax.set_xlabel("time per position [µs], fourbar position to jerk, 100 positions")
ax.set_title("Where the units go: once per call, or once per position")
plt.show()
print(
    f"FourBar: 100 calls cost {t_call['FourBar, 100 calls'] / t_call['FourBar, one array']:.0f}"
    f" times one call with an array; the units add "
    f"{t_call['FourBar, one array'] / t_call['kernel, one array']:.1f}x to an array call"
)

# %%
display(
    Markdown(f"""
pint's cost is per operation, not per number. Wrapped around a whole array it is paid once
({(t_add["one Quantity per array"] - t_add["floats (numpy)"]) * 1e6:.0f} µs more than plain floats
here, including the conversion from inches); spread over the elements it is paid a thousand times,
and the same addition takes {t_add["one Quantity per element"] * 1e3:.1f} ms. The solver is built
the same way: its kernels are plain numpy on SI floats and the classes convert at the edges, once
per call. So pass the solver arrays, not loops of scalars; if you must call it position by position
(an interactive tool, say), each call carries a fixed cost, here
{t_call["FourBar, 100 calls"] - t_call["kernel, 100 calls"]:.0f} µs for the units alone.
""")
)
assert t_add["one Quantity per element"] > 30 * t_add["one Quantity per array"]
assert t_call["FourBar, 100 calls"] > 5 * t_call["FourBar, one array"]

# %% [markdown]
# ### 5. The same questions at scale
#
# The project's benchmark (`make bench`, or `accelab bench`) asks these questions of every
# linkage the solver handles, over full cycles and many sizes of call, and sets three packages
# from other authors beside it; the README's *Speed and accuracy* section shows its charts and
# numbers. What this notebook measured on one linkage is what it finds across all of them: the
# closed forms on arrays are fastest and exact to round-off, a call's fixed cost fades as it
# carries more positions, and the general solver pays for each loop it adds.
#
# ## Which method when
#
# The table below is built from the measurements of this run (example 1 for the costs and
# errors, example 2 for the best finite-difference errors): your machine may give other times,
# not another order.

# %%
kern, unit_api, pyloop = (
    table[k]
    for k in (
        "closed forms, vectorised",
        "closed forms, unit-aware API",
        "closed forms, Python loop",
    )
)
nr_default = table["vector loops, tol 1e-13"]
fds = [row for row in table.values() if row["family"] == "fd"]
graph = table["graphical construction"]
fd_errors = ", ".join(f"{min(errors[n]):.0e}" for n in derivative)
rows = [
    (
        "closed forms, vectorised (`accelab.solver.kernels`, or a class with an array of `theta2`)",
        f"{kern['us']:.2f} µs",
        f"{kern['jerk']:.0e}, to jerk",
        "whole cycles, design sweeps, optimisation",
        "only the mechanisms that have one; refuses near a toggle (example 3)",
    ),
    (
        "closed forms, unit-aware (`FourBar(...).solve`)",
        f"{unit_api['us']:.2f} µs (one call, 360 positions)",
        f"{unit_api['jerk']:.0e}",
        "reading one position with units, teaching, checking",
        "many calls of one position each: the per-call cost of pint (example 4)",
    ),
    (
        "closed forms in a Python loop",
        f"{pyloop['us']:.1f} µs",
        f"{pyloop['jerk']:.0e}",
        "nothing an array cannot do",
        "speed",
    ),
    (
        "vector loops, Newton-Raphson (`VectorLoopLinkage`)",
        f"{nr_default['us']:.1f} µs",
        f"{nr_default['jerk']:.0e} at the default tolerance",
        "any linkage without a closed form (notebook 10)",
        "needs guesses that pick the assembly; singular at toggles",
    ),
    (
        "finite differences of the position",
        f"{min(r['us'] for r in fds):.1f} to {max(r['us'] for r in fds):.1f} µs",
        f"at best {fd_errors} (velocity, acceleration, jerk)",
        "a check when only positions exist",
        "the step: too large truncates, too small amplifies round-off; silently wrong near toggles",
    ),
    (
        "graphical construction (`accelab.solver.graphical`)",
        f"{graph['us']:.0f} µs",
        f"{graph['acc']:.0e}, to acceleration",
        "seeing the vectors; an independent check",
        "one position at a time; no jerk",
    ),
]
display(
    Markdown(
        "| method | cost per position | error | use it for | where it fails |\n"
        "|---|---|---|---|---|\n" + "\n".join("| " + " | ".join(r) + " |" for r in rows)
    )
)

# %% [markdown]
# In one sentence: use a closed form on arrays whenever the mechanism has one, Newton-Raphson on
# arrays when it does not, the graphical construction to see and to check, and finite
# differences only to check, with a step chosen for the derivative you need.

# ## Explore: the finite-difference step
#
# Move the step $h$ (as its power of ten) and watch the error of $\omega_4$, $\alpha_4$ and
# $\varphi_4$ over the whole cycle of example 1, measured against the closed forms (whose error,
# $10^{-15}$, is far below anything on this plot). Find the step where the jerk is best, and see
# what it does to the velocity.

# %% mystnb={"figure": {"caption": "Finite-difference velocities at several steps h against the exact curve."}, "image": {"alt": "Small multiples of velocity against crank angle for several finite-difference steps."}}
exact_cycle = from_motion(closed_form.solve(**geometry, theta2=theta2, **motion))
cycle_scale = scales(exact_cycle)
degrees = np.degrees(theta2)


def draw(log10_h):
    h = 10.0**log10_h
    e = relative_errors(
        finite_differences(h), exact_cycle, cycle_scale, ["omega4", "alpha4", "jerk4"]
    )
    fig, ax = plt.subplots(figsize=(5.4, 3.6))
    for name, colour, label in (
        ("omega4", colours[1], "$\\omega_4$"),
        ("alpha4", colours[2], "$\\alpha_4$"),
        ("jerk4", colours[3], "$\\varphi_4$"),
    ):
        ax.semilogy(
            degrees,
            np.maximum(e[name], 1e-16),
            color=colour,
            lw=1.2,
            label=f"{label}: worst {np.max(e[name]):.0e}",
        )
    ax.set_ylim(1e-14, 1e6)
    ax.set_xticks(range(0, 361, 90))
    ax.set_xlabel("$\\theta_2$ [deg]")
    ax.set_ylabel("relative error [-]")
    ax.set_title(f"h = {h:.0e} rad", fontsize=10)
    ax.legend(loc="lower right", fontsize=8, ncol=1)
    return fig


explore(draw, log10_h=(-9, -1, 0.5, -3), values=[-8, -5, -3, -1])


# %% tags=["remove-input"] jupyter={"source_hidden": true}
def fd_worst(h):
    e = relative_errors(
        finite_differences(h), exact_cycle, cycle_scale, ["omega4", "alpha4", "jerk4"]
    )
    return {k: float(np.max(v)) for k, v in e.items()}


at = {x: fd_worst(10.0**x) for x in (-8, -5, -3, -1)}
assert at[-8]["omega4"] < 1e-4 and at[-8]["alpha4"] > 1e-2 and at[-8]["jerk4"] > 1  # noise
assert at[-5]["omega4"] < 1e-8 and at[-5]["jerk4"] > 1e-1
stated(at[-3]["jerk4"], "1e-5", sig=1)
assert at[-3]["omega4"] > 100 * at[-5]["omega4"]  # "a thousand times worse"
assert all(v > 1e-3 for v in at[-1].values())  # truncation rules

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
# The closed-form kernel, `accelab.solver.kernels.fourbar.solve`, with one array of all the angles in SI
# floats and `order=2` (compute only what is needed): the cheapest per position of all the
# methods example 1 measured, so a million positions cost about a million times that. Units at
# the edges only: convert the design variables once, not inside the loop.
#
# </details>
#
# **5.** The graphical construction agrees with the reference to round-off. Why not always use
# it?
#
# <details><summary>Answer</summary>
#
# It builds the construction one position at a time in Python (example 1 measured it many times
# dearer than the vectorised closed forms), and it stops at acceleration: there is no jerk
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
