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
# # 10. Linkages of N bars
#
# The fourbar, the slider-crank and the geared fivebar each had a closed form. A sixbar in
# general does not: its loop equations must be solved numerically. This notebook writes any
# linkage as vectors and the loops they close, solves the positions by Newton-Raphson, and gets
# velocities, accelerations and jerks from the same matrix with no further iteration: what the
# chapter's section 7.8 sketches in a paragraph (Robert L. Norton, *Design of Machinery*,
# chapter 7, "Linkages of N Bars"), worked out.
#
# **You will be able to**
#
# - describe a linkage of any number of loops as named vectors and loop equations, and count its
#   unknowns;
# - explain one Newton-Raphson step, its Jacobian, and why it converges so fast near a solution;
# - solve a sixbar with `VectorLoopLinkage` at one position and over a whole cycle on one
#   assembly;
# - recognise what goes wrong with a bad initial guess, at a position the linkage cannot reach,
#   and near a limit (toggle) position, and read the solver's answer there.

# %%
# %matplotlib inline
import copy

import matplotlib.pyplot as plt
import numpy as np

from accelab.course.kit import COLORS, explore, stated, use_style, vector
from accelab.solver import Q_, AccelabError, FourBar, VectorLoopLinkage
from accelab.solver.vectorloops.examples import sixbar_slider, watt2_sixbar

use_style()

# %% [markdown]
# ## The idea and its equations
#
# Every link, and every line between joints of the ground, is a vector $L_k e^{j\theta_k}$. Walk
# round any closed chain of links and the vectors add up to zero: a **vector loop**. The fourbar
# has one loop,
#
# $$ \mathbf{R}_2 + \mathbf{R}_3 - \mathbf{R}_4 - \mathbf{R}_1 = 0 , $$
#
# two scalar equations (real and imaginary parts) for its two unknown angles $\theta_3$,
# $\theta_4$. A sixbar has two independent loops, four equations and four unknowns: angles of
# links, or lengths of sliders. Each loop adds two equations and must add two unknowns.
#
# **Position: Newton-Raphson.** Collect the unknowns in $\mathbf{q}$ and the loops' real and
# imaginary parts in $\mathbf{F}(\mathbf{q}) = 0$. From a guess $\mathbf{q}_0$, linearise and solve
# for the correction:
#
# $$ \mathbf{J}\,\Delta\mathbf{q} = -\mathbf{F}(\mathbf{q}_i), \qquad
#    \mathbf{q}_{i+1} = \mathbf{q}_i + \Delta\mathbf{q}, \qquad
#    J_{mn} = \frac{\partial F_m}{\partial q_n} . $$
#
# The Jacobian is easy to write by hand because each vector depends on at most one unknown:
# $\partial(Le^{j\theta})/\partial\theta = jLe^{j\theta}$ for an unknown angle and
# $\partial(Le^{j\theta})/\partial L = e^{j\theta}$ for an unknown length. For the fourbar,
#
# $$ \mathbf{J} = \begin{bmatrix} -b\sin\theta_3 & c\sin\theta_4 \\
#    b\cos\theta_3 & -c\cos\theta_4 \end{bmatrix} . $$
#
# Near a solution each step roughly squares the error (quadratic convergence): 1e-2, 1e-4, 1e-8,
# 1e-16. Far from one, a step can jump anywhere, including to the *other* assembly.
#
# **Velocity, acceleration, jerk: no more iteration.** Differentiate $\mathbf{F}(\mathbf{q},
# \theta_2) = 0$ in time. The unknown rates always appear multiplied by the same Jacobian:
#
# $$ \mathbf{J}\,\dot{\mathbf{q}} = -\frac{\partial\mathbf{F}}{\partial\theta_2}\,\omega_2, \qquad
#    \mathbf{J}\,\ddot{\mathbf{q}} = -(\text{terms in } \omega, \alpha_2, \dot L \text{ already known}) $$
#
# which is what the chapter's closed forms did by hand for one loop (eq. 7.7 is the fourbar's
# second line). Where $\mathbf{J}$ is singular (two links in line: a limit or toggle position),
# the position may exist but its velocities and accelerations are not defined.

# %% [markdown]
# ## Worked examples
#
# ### 1. Newton-Raphson by hand, on the fourbar
#
# The fourbar $a$ = 2, $b$ = 6, $c$ = 9, $d$ = 7 in at $\theta_2 = 30°$ (the course's Example
# 7-1 linkage: the chapter's example prints no numbers, **these are the course's own**), from the guess
# $\theta_3 = 90°$, $\theta_4 = 130°$. Ten lines do it; the cell prints the size of the loop's
# residual at each step and checks the result against the closed form of notebook 3.

# %%
a, b, c, d = 2.0, 6.0, 9.0, 7.0  # in
theta2 = np.radians(30)


def loop(q):
    """F(q): real and imaginary parts of R2 + R3 - R4 - R1 [in] for q = (theta3, theta4)."""
    z = a * np.exp(1j * theta2) + b * np.exp(1j * q[0]) - c * np.exp(1j * q[1]) - d
    return np.array([z.real, z.imag])


def jacobian(q):
    return np.array([[-b * np.sin(q[0]), c * np.sin(q[1])], [b * np.cos(q[0]), -c * np.cos(q[1])]])


q = np.radians([90.0, 130.0])
history = [np.linalg.norm(loop(q))]
for _ in range(6):
    q = q + np.linalg.solve(jacobian(q), -loop(q))  # one Newton-Raphson step
    history.append(np.linalg.norm(loop(q)))
for i, res in enumerate(history):
    print(f"step {i}: |F| = {res:.2e} in")
closed = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(theta2="30 deg", omega2="10 rad/s")
assert np.allclose(
    np.exp(1j * q), np.exp(1j * np.array([closed.theta3.magnitude, closed.theta4.magnitude]))
)
print(
    f"theta3 = {np.degrees(q[0]) % 360:.6f} deg, theta4 = {np.degrees(q[1]) % 360:.6f} deg "
    f"(closed form: {closed.theta3.to('deg').magnitude:.6f}, {closed.theta4.to('deg').magnitude:.6f})"
)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
assert history[4] < 1e-12 < history[3] and history[0] > 0.1  # round-off after four steps
assert all(history[k + 1] < 10 * history[k] ** 2 for k in range(3))  # each about squaring

# %% [markdown]
# The residual falls from inches to round-off in four steps, each about squaring the last: that
# is quadratic convergence. Then the same Jacobian gives the velocities in one linear solve,
# $\mathbf{J}\dot{\mathbf{q}} = -ja\omega_2e^{j\theta_2}$ (as real and imaginary parts):

# %%
omega2 = 10.0
rhs = -1j * a * omega2 * np.exp(1j * theta2)
omega34 = np.linalg.solve(jacobian(q), [rhs.real, rhs.imag])
assert np.allclose(omega34, [closed.omega3.magnitude, closed.omega4.magnitude], rtol=1e-12)
print(f"omega3 = {omega34[0]:.6f} rad/s, omega4 = {omega34[1]:.6f} rad/s, as the closed form")

# %% [markdown]
# **Which solution does Newton find?** The fourbar has two assemblies at this crank angle, open
# and crossed. The map runs plain Newton-Raphson (the ten lines above, vectorised) from 40 000
# different guesses and colours each guess by where it ends. The basins are large and mostly
# sensible, but their boundaries are ragged: a guess near a boundary can land anywhere.

# %% mystnb={"figure": {"caption": "Where plain Newton-Raphson ends from each starting guess: the open circuit, the crossed circuit, or no solution."}, "image": {"alt": "Map of starting guesses for the two unknown angles, coloured by the assembly Newton-Raphson converges to."}}
crossed = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
    theta2="30 deg", omega2="10 rad/s", circuit="crossed"
)
g3, g4 = np.meshgrid(
    np.radians(np.linspace(-180, 180, 200)), np.radians(np.linspace(-180, 180, 200))
)
t3, t4 = g3.copy(), g4.copy()
with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
    for _ in range(30):  # Newton on all guesses at once
        z = a * np.exp(1j * theta2) + b * np.exp(1j * t3) - c * np.exp(1j * t4) - d
        j11, j12, j21, j22 = -b * np.sin(t3), c * np.sin(t4), b * np.cos(t3), -c * np.cos(t4)
        det = j11 * j22 - j12 * j21
        t3, t4 = t3 - (j22 * z.real - j12 * z.imag) / det, t4 - (-j21 * z.real + j11 * z.imag) / det
        t3, t4 = np.angle(np.exp(1j * t3)), np.angle(np.exp(1j * t4))  # angles are periodic
res = np.abs(a * np.exp(1j * theta2) + b * np.exp(1j * t3) - c * np.exp(1j * t4) - d)
res[~np.isfinite(res)] = np.inf
ended = np.full(g3.shape, 2)  # 2: did not converge
for k, sol in enumerate((closed, crossed)):
    near = np.abs(np.exp(1j * t3) - np.exp(1j * sol.theta3.magnitude)) < 1e-6
    ended[(res < 1e-9) & near] = k
fig, ax = plt.subplots(figsize=(6.2, 5))
cmap = plt.matplotlib.colors.ListedColormap([COLORS["normal"], COLORS["tangential"], "#dddddd"])
ax.pcolormesh(np.degrees(g3), np.degrees(g4), ended, cmap=cmap, vmin=-0.5, vmax=2.5, shading="auto")
for sol, name in ((closed, "open"), (crossed, "crossed")):
    ax.plot(
        *np.degrees(np.angle(np.exp(1j * np.array([sol.theta3.magnitude, sol.theta4.magnitude])))),
        "o",
        mec="black",
        mfc="white",
        ms=9,
    )
    ax.annotate(
        name,
        np.degrees(np.angle(np.exp(1j * np.array([sol.theta3.magnitude, sol.theta4.magnitude])))),
        textcoords="offset points",
        xytext=(8, 6),
        fontsize=11,
        fontweight="bold",
    )
ax.plot(90, 130, "k+", ms=12, mew=2)
ax.set_xlabel(r"guess for $\theta_3$ [deg]")
ax.set_ylabel(r"guess for $\theta_4$ [deg]")
ax.set_title("Where plain Newton-Raphson ends:\nopen (blue), crossed (vermillion), nowhere (grey)")
plt.show()
print(
    f"open: {np.mean(ended == 0):.0%} of the guesses, crossed: {np.mean(ended == 1):.0%}, "
    f"neither after 30 steps: {np.mean(ended == 2):.1%}"
)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
assert g3.size == 40_000
stated(np.mean(ended == 2), "0.3", sig=1)

# %% [markdown]
# Near each solution lies a smooth basin; further away the basins interleave in thin,
# ragged bands, and a third of the square (grey) never converges: plain Newton-Raphson falls into
# a cycle, bouncing between two wrong configurations for ever. The next cell shows one such cycle,
# then what the solver does from the same guess. Its Newton-Raphson limits the size of each step
# (so that it creeps instead of leaping) and reports a guess that sits exactly on a singular
# configuration instead of dividing by zero.

# %%
q = np.radians([-73.4, -14.9])
for i in range(4):
    step = np.linalg.solve(jacobian(q), -loop(q))
    print(
        f"plain Newton step {i}: theta3, theta4 = {np.degrees(q[0]):7.2f}, {np.degrees(q[1]):7.2f} deg, "
        f"|F| = {np.linalg.norm(loop(q)):.3f} in"
    )
    q = q + step


def fourbar_loops(guess3, guess4):
    return VectorLoopLinkage(
        vectors={
            "R1": {"length": "7 in", "angle": "0 deg"},
            "R2": {"length": "2 in", "angle": "input"},
            "R3": {"length": "6 in", "angle": "unknown", "guess": guess3},
            "R4": {"length": "9 in", "angle": "unknown", "guess": guess4},
        },
        loops=["R2 + R3 - R4 - R1"],
    )


s = fourbar_loops("-73.4 deg", "-14.9 deg").solve(theta2="30 deg", omega2="10 rad/s")
print(
    f"solver from the same guess: theta3 = {s.vectors['R3'].angle.to('deg'):.4f~P}, "
    f"theta4 = {s.vectors['R4'].angle.to('deg'):.4f~P} after {s.iterations} (damped) iterations"
)
try:
    fourbar_loops("180 deg", "180 deg").solve(theta2="30 deg", omega2="10 rad/s")
except AccelabError as err:
    print(f"solver from theta3 = theta4 = 180 deg: {type(err).__name__}: {err}")

# %% [markdown]
# Even so, no method can read your mind: **the guesses choose the assembly**. Give them from a
# sketch of the linkage you mean.
#
# ### 2. A sixbar driving a slider
#
# A crank-rocker fourbar (the one above) has its rocker extended past $O_4$ to C; a rod CD pushes
# a slider D along a line 3 in below $O_4$. Two loops:
#
# $$ \mathbf{R}_2 + \mathbf{R}_3 - \mathbf{R}_4 - \mathbf{R}_1 = 0, \qquad
#    \mathbf{R}_{4C} + \mathbf{R}_5 - \mathbf{H} - \mathbf{S} = 0 $$
#
# with four unknowns: $\theta_3$, $\theta_4$ (which also turns $\mathbf{R}_{4C}$, rigidly
# attached at 180°), $\theta_5$ and the slider's length $S$. The description is the one shipped
# in `accelab.solver.vectorloops.examples`:

# %%
slider_six = sixbar_slider()
for name, spec in slider_six["vectors"].items():
    print(f"{name:4} {spec}")
print("loops: ", slider_six["loops"])
print("points:", slider_six["points"])
linkage = VectorLoopLinkage(**slider_six)
r = linkage.solve(theta2="57 deg", omega2="12 rad/s", alpha2="-30 rad/s^2")
S = r.vectors["S"]
print(f"\nNewton-Raphson: {r.iterations} iterations from the guesses")
print(
    f"theta5 = {r.vectors['R5'].angle.to('deg'):.3f~P}; slider S = {S.length.to('in'):.4f~P}, "
    f"S' = {S.length_dot.to('in/s'):.3f~P}, S'' = {S.length_ddot.to('in/s^2'):.2f~P}"
)
print(f"A_D = {r.points['D'].A.to('in/s^2'):.2f~P}")
# the first loop is the fourbar: it must agree with the closed form
fb = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
    theta2="57 deg", omega2="12 rad/s", alpha2="-30 rad/s^2"
)
assert np.isclose(r.vectors["R4"].alpha.magnitude, fb.alpha4.magnitude, rtol=1e-9)

# %% [markdown]
# Drawing the vectors makes the loops visible: each loop is a closed chain of arrows (the
# signs say which way round each arrow is walked). The second loop starts at $O_4$.


# %% mystnb={"figure": {"caption": "The sixbar with a slider at theta2 = 57 deg, drawn as its two vector loops."}, "image": {"alt": "Drawing of a sixbar linkage with the vectors of loop 1 in blue and loop 2 in vermillion."}}
def draw_loops(ax, description, result, starts, i=None, show_names=True):
    """Draw each loop's vectors tip to tail from its start point [in]; i picks a sweep position.
    Returns the complex vectors drawn [in]."""
    pick = (lambda x: x) if i is None else (lambda x: x[i] if np.ndim(x) else x)
    z = {}
    for name, spec in description["vectors"].items():
        v = result.vectors[name]
        L = (v.length if spec["length"] == "unknown" else Q_(spec["length"])).to("in").magnitude
        z[name] = pick(L) * np.exp(1j * pick(v.angle.to("rad").magnitude))
    colours = [COLORS["normal"], COLORS["tangential"]]
    drawn, ends = set(), []
    for k, (text, start) in enumerate(zip(description["loops"], starts)):
        here = start
        for term in (t.strip() for t in text.replace("-", "+ -").split("+") if t.strip()):
            name = term.lstrip("- ").strip()
            if term.startswith("-"):  # walked backwards: the arrow ends here
                tail = here = here - z[name]
            else:
                tail, here = here, here + z[name]
            if name in drawn:
                continue
            drawn.add(name)
            tip = tail + z[name]
            ends += [tail, tip]
            ax.annotate(
                "",
                xy=(tip.real, tip.imag),
                xytext=(tail.real, tail.imag),
                arrowprops=dict(arrowstyle="-|>", color=colours[k], lw=2.2, shrinkA=0, shrinkB=0),
            )
            if show_names:
                mid = tail + 0.5 * z[name] + 0.6 * 1j * z[name] / max(abs(z[name]), 1e-9)
                ax.text(
                    mid.real,
                    mid.imag,
                    name,
                    color=colours[k],
                    fontsize=10,
                    ha="center",
                    va="center",
                )
    ends = np.array(ends)
    ax.set_xlim(ends.real.min() - 1.5, ends.real.max() + 1.5)
    ax.set_ylim(ends.imag.min() - 1.5, ends.imag.max() + 1.5)
    ax.set_aspect("equal")
    return z


fig, ax = plt.subplots(figsize=(9, 4.6))
draw_loops(ax, slider_six, r, starts=[0j, 7 + 0j])
ax.plot([0, 7], [0, 0], "^", color="#222222", ms=10)
ax.axhline(-3, color="#888888", lw=1, ls="-.")
ax.text(0, -3.4, "slide line", color="#666666", fontsize=9)
D = r.points["D"].R.to("in").magnitude
ax.plot(D.real, D.imag, "s", ms=12, mfc="#dddddd", mec="#333333", zorder=0)
ax.set_aspect("equal")
ax.set_xlabel("x [in]")
ax.set_ylabel("y [in]")
ax.set_title(r"Sixbar with slider at $\theta_2$ = 57°: loop 1 (blue), loop 2 (vermillion)")
plt.show()

# %% [markdown]
# **A whole cycle on one assembly.** Passing an array of crank angles makes the solver sweep:
# each position starts from the previous solution moved on by the velocity (a predictor), so
# Newton-Raphson needs only a step or two, and it refuses to jump to another assembly. The same
# call gives the slider's motion, the iterations each position took, and a condition number of
# the Jacobian (a scaled ratio of its smallest to largest singular value: 0 means singular, larger
# is better).

# %% mystnb={"figure": {"caption": "The sixbar over a cycle: slider position, slider acceleration at 12 rad/s, and Newton-Raphson iterations per position."}, "image": {"alt": "Three line plots against crank angle."}}
theta = Q_(np.linspace(0, 2 * np.pi, 361), "rad")
deg = np.degrees(theta.magnitude)
cycle = linkage.solve(theta2=theta, omega2="12 rad/s", alpha2=0)
assert cycle.valid.all()
S = cycle.vectors["S"]
fig, axes = plt.subplots(2, 2, figsize=(11, 6.5), sharex=True)
axes[0, 0].plot(deg, S.length.to("in").magnitude, color="black")
axes[0, 0].set_ylabel("S [in]")
axes[0, 0].set_title("Slider position")
axes[0, 1].plot(deg, S.length_ddot.to("in/s^2").magnitude, color="black")
axes[0, 1].set_ylabel(r"$\ddot S$ [in/s$^2$]")
axes[0, 1].set_title(r"Slider acceleration at $\omega_2$ = 12 rad/s")
axes[1, 0].step(deg, cycle.iterations, where="mid", color=COLORS["normal"])
axes[1, 0].set_ylabel("iterations")
axes[1, 0].set_title("Newton-Raphson iterations per position")
axes[1, 1].plot(deg, cycle.condition, color=COLORS["tangential"])
axes[1, 1].set_ylim(0, 1.1 * np.nanmax(cycle.condition))
axes[1, 1].set_ylabel("condition (0: singular)")
axes[1, 1].set_title("How far from a singular position")
for ax in axes[1]:
    ax.set_xlabel(r"$\theta_2$ [deg]")
    ax.set_xticks(range(0, 361, 60))
plt.show()
its = np.asarray(cycle.iterations)
print(
    f"{its.sum()} iterations for {its.size} positions (mean {its.mean():.2f}, most {its.max()}); "
    f"S from {S.length.to('in').magnitude.min():.3f} to {S.length.to('in').magnitude.max():.3f} in"
)

# %% [markdown]
# ### 3. A Watt II sixbar
#
# The same language describes a Watt II sixbar: the fourbar's rocker, extended to C, drives a
# second fourbar $O_4$-C-D-$O_6$. Both loops close on rotating links, so all four unknowns are
# angles.

# %% mystnb={"figure": {"caption": "The Watt II sixbar at theta2 = 57 deg, and the angular accelerations of its two rockers over a cycle."}, "image": {"alt": "Left, the Watt II sixbar drawing; right, line plots of two angular accelerations against crank angle."}}
watt = watt2_sixbar()
print("loops:", watt["loops"])
w_linkage = VectorLoopLinkage(**watt)
w = w_linkage.solve(theta2=theta, omega2="12 rad/s", alpha2=0)
assert w.valid.all()
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.4), gridspec_kw={"width_ratios": [1.1, 1]})
draw_loops(ax1, watt, w, starts=[0j, 7 + 0j], i=57)
O6 = 7 + 9 * np.exp(1j * np.radians(10))
ax1.plot([0, 7, O6.real], [0, 0, O6.imag], "^", color="#222222", ms=10)
ax1.set_aspect("equal")
ax1.set_xlabel("x [in]")
ax1.set_ylabel("y [in]")
ax1.set_title(r"Watt II at $\theta_2$ = 57°")
for name, colour in (("R4", COLORS["normal"]), ("R6", COLORS["tangential"])):
    ax2.plot(
        deg,
        w.vectors[name].alpha.magnitude,
        color=colour,
        label=rf"$\alpha$ of {name} (link {name[1]})",
    )
ax2.set_xlabel(r"$\theta_2$ [deg]")
ax2.set_ylabel(r"$\alpha$ [rad/s$^2$]")
ax2.set_xticks(range(0, 361, 60))
ax2.set_title("Angular accelerations of the two rockers, 12 rad/s")
ax2.legend()
plt.show()

# %% [markdown]
# ### 4. When things go wrong
#
# **A bad guess.** Guess the fourbar's angles on the wrong side and Newton-Raphson converges,
# correctly, to the crossed assembly: a legitimate solution of the loops, but not the machine
# you built. Guess the rod pointing left and the slider closes on the other side of C. Nothing
# is "wrong" numerically, which is why the result must be looked at.


# %%
def with_guesses(description, **guesses):
    new = copy.deepcopy(description)
    for name, guess in guesses.items():
        new["vectors"][name]["guess"] = guess
    return new


for label, desc in (
    ("as designed", slider_six),
    ("fourbar guessed crossed", with_guesses(slider_six, R3="-60 deg", R4="-120 deg")),
    ("rod guessed pointing left", with_guesses(slider_six, R5="170 deg")),
):
    s = VectorLoopLinkage(**desc).solve(theta2="57 deg", omega2="12 rad/s")
    print(
        f"{label:26} theta3 = {s.vectors['R3'].angle.to('deg').magnitude % 360:7.2f} deg, "
        f"theta5 = {s.vectors['R5'].angle.to('deg').magnitude % 360:7.2f} deg, "
        f"S = {s.vectors['S'].length.to('in').magnitude:7.3f} in"
    )

# %% [markdown]
# **A position the linkage cannot reach, and the limit before it.** Move the slide line up, to
# 1 in *above* $O_4$, and shorten the rod to 4 in. Now C, swinging between 1.7 and 3.4 in below
# the ground line, is sometimes more than 4 in from the slide: the rod cannot reach, and the
# linkage cannot run a full cycle. Geometry alone says where: the rod reaches while
# $|y_{slide} - y_C| \le 4$ in, and C's path does not depend on the second loop. The sweep marks
# positions it cannot close as invalid instead of inventing numbers; the condition number falls
# toward zero as the rod comes perpendicular to the slide at the edge of the reachable range, and
# the slider's acceleration there grows without bound.

# %% mystnb={"figure": {"caption": "Near a limit position: the condition of the Jacobian falls to zero and the slider's acceleration grows without bound."}, "image": {"alt": "Two line plots against crank angle approaching a limit position."}}
short = copy.deepcopy(slider_six)
short["vectors"]["H"] = {"length": "1 in", "angle": "90 deg"}
short["vectors"]["R5"] = {"length": "4 in", "angle": "unknown", "guess": "50 deg"}
short["vectors"]["S"] = {"length": "unknown", "guess": "5 in", "angle": "0 deg"}
reach = VectorLoopLinkage(**short)
fine = Q_(np.linspace(0, 2 * np.pi, 721), "rad")
fdeg = np.degrees(fine.magnitude)
sw = reach.solve(theta2=fine, omega2="12 rad/s", alpha2=0)
ok = sw.valid
C_y = linkage.solve(theta2=fine, omega2="12 rad/s").points["C"].R.to("in").magnitude.imag
can = np.abs(1.0 - C_y) <= 4.0  # the geometric check
stated(-C_y.max(), "1.7"), stated(-C_y.min(), "3.4")  # C below the ground line
limits = fdeg[np.flatnonzero(np.diff(can.astype(int)))]
print(f"geometry: the rod reaches the slide except between {limits[0]:.1f} and {limits[1]:.1f} deg")
print(
    f"sweep:    valid at {ok.sum()} of {ok.size} positions, status names {sorted(set(sw.status))}"
)
missed = int(np.sum(can & ~ok))
print(
    f"          positions the sweep does not return although geometry allows them: {missed}"
    + (" (it picks the linkage up again where geometry allows)" if missed == 0 else "")
)
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 3.8), sharex=True)
ax1.plot(fdeg, sw.condition, color=COLORS["tangential"])
top = 1.1 * np.nanmax(sw.condition)
ax1.fill_between(fdeg, 0, top, where=~ok, color="#dddddd", label="sweep: not valid")
ax1.set_ylabel("condition")
ax1.set_ylim(0, top)
ax2.plot(fdeg, np.abs(sw.vectors["S"].length_ddot.to("in/s^2").magnitude), color="black")
ax2.fill_between(fdeg, 1, 1e7, where=~ok, color="#dddddd")
ax2.set_yscale("log")
ax2.set_ylim(10, 1e7)
ax2.set_ylabel(r"$|\ddot S|$ [in/s$^2$]")
for ax in (ax1, ax2):
    for x in limits:
        ax.axvline(x, color="black", ls="--", lw=1)
    ax.set_xlabel(r"$\theta_2$ [deg]")
    ax.set_xticks(range(0, 361, 60))
ax1.plot([], [], "k--", lw=1, label="geometric reach limits")
ax1.legend(fontsize=8, loc="center")
ax1.set_title("Condition of the Jacobian")
ax2.set_title("Slider acceleration near the limit")
plt.show()

# %% [markdown]
# Where the linkage runs *into* the limit (the first dashed line) the sweep stops exactly there.
# Coming *out* of the gap is harder: the sweep has no previous solution to continue from, so it
# must search for the linkage again from its last known state, on either side of the gap. The
# cell above counts the positions that geometry allows but the sweep did not return (compare the
# end of the grey band with the second dashed line): a search can come up empty where a linkage
# exists, so the count is worth printing, and the cell says so when it is zero. In the same way,
# a `not_assemblable` from a sweep means that Newton-Raphson found no closure from its guesses,
# not a proof that none exists; the geometric check is what proves it.
#
# Asked about a single position, the solver raises an error that says what is wrong instead of
# returning numbers. Inside the gap Newton-Raphson cannot close the loops; just inside an edge it
# still can, but the velocities and accelerations there are enormous and only as good as the
# condition number allows; and just after the gap a fresh guess (the rod leaning right, as
# designed) finds the linkage whatever the sweep said.

# %%
after = limits[1] + 10
for angle, guess in ((limits[0] - 0.5, None), (100.0, None), (after, "60 deg")):
    solver_ = reach if guess is None else VectorLoopLinkage(**with_guesses(short, R5=guess))
    try:
        s = solver_.solve(theta2=f"{angle} deg", omega2="12 rad/s")
        print(
            f"{angle:6.1f} deg: ok, condition {s.condition:.3f}, theta5 = "
            f"{s.vectors['R5'].angle.to('deg'):.1f~P}, S'' = {s.vectors['S'].length_ddot.to('in/s^2'):.4g~P}"
        )
    except AccelabError as err:
        print(f"{angle:6.1f} deg: {type(err).__name__}: {str(err)[:150]}...")
k = int(np.argmin(np.abs(fdeg - after)))
print(f"(the sweep said {sw.status[k]!r} at {fdeg[k]:.1f} deg)")

# %% [markdown]
# ## Explore
#
# Turn the crank of the sixbar and watch the two loops close; the arrow at D is the slider's
# acceleration (1 in of arrow = 50 in/s²).


# %% mystnb={"figure": {"caption": "The sixbar with a slider at several crank angles, with the slider's acceleration."}, "image": {"alt": "Small multiples of the sixbar drawing with acceleration arrows."}}
def draw(theta2=57):
    i = int(round(theta2))
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    draw_loops(ax, slider_six, cycle, starts=[0j, 7 + 0j], i=i, show_names=False)
    D = cycle.points["D"].R.to("in").magnitude[i]
    A_D = cycle.points["D"].A.to("in/s^2").magnitude[i]
    vector(ax, D, A_D, "slip", scale=1 / 50)
    ax.plot([0, 7], [0, 0], "^", color="#222222", ms=9)
    ax.axhline(-3, color="#888888", lw=1, ls="-.")
    ax.set_xlim(-3, 25)
    ax.set_ylim(-5, 9)
    ax.set_aspect("equal")
    ax.set_xlabel("x [in]")
    ax.set_title(
        rf"$\theta_2$ = {theta2}°: S'' = {A_D.real:.0f} in/s², "
        f"{cycle.iterations[i]} Newton steps",
        fontsize=10,
    )
    return fig


explore(draw, theta2=(0, 360, 5, 57, "deg"))

# %% [markdown]
# ## Check yourself
#
# 1. A linkage has three independent loops. How many unknowns must its description have?
#
# <details><summary>Answer</summary>
#
# Six: each loop gives two scalar equations (real and imaginary parts), and the system must be
# square for Newton-Raphson.
#
# </details>
#
# 2. Why does the velocity analysis of an N-bar need no iteration once the positions are known?
#
# <details><summary>Answer</summary>
#
# The differentiated loop equations are *linear* in the unknown rates, with the same Jacobian
# as the position step: one linear solve $\mathbf{J}\dot{\mathbf{q}} = \ldots$ each for velocity,
# acceleration and jerk.
#
# </details>
#
# 3. The residual of a Newton-Raphson run goes 3e-1, 2e-2, 1e-4, 4e-9, 5e-16. Is this what you
#    expect?
#
# <details><summary>Answer</summary>
#
# Yes: each residual is roughly the square of the previous one (times a constant), the mark of
# quadratic convergence near a simple root. The last value is round-off.
#
# </details>
#
# 4. In example 4 the solver converged with a "bad" guess. How would you notice?
#
# <details><summary>Answer</summary>
#
# Draw it, or compare with what you expect: the crossed fourbar has $\theta_3$ below the ground
# line, and a slider on the wrong side of C has $S$ far from the design value. A sweep from a bad
# guess follows the wrong assembly consistently, so a single look at one position is enough.
#
# </details>
#
# 5. What does a condition number near zero tell you, and why do the accelerations blow up there?
#
# <details><summary>Answer</summary>
#
# The Jacobian is nearly singular: two links are nearly in line (here the rod is nearly
# perpendicular to the slide). Solving $\mathbf{J}\ddot{\mathbf{q}} = \ldots$ divides by a
# nearly zero quantity, so finite crank motion demands unbounded rates: a limit position.
#
# </details>

# %% tags=["remove-input"] jupyter={"source_hidden": true}
assert len(watt["loops"]) == 2 and len(slider_six["loops"]) == 2

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set, for a linkage with no closed form; set it up as
# vectors and loops, then solve with `VectorLoopLinkage`. The answers are folded.
#
# **Problem 10.1.** The sixbar with a slider of example 2 runs at a steady 12 rad/s. At
# $\theta_2 = 120^\circ$, where is the slider, how fast is it moving and how hard is it
# accelerating?
#
# <details><summary>Answer</summary>
#
# $S$ = 12.42 in, $\dot S$ = 7.97 in/s and $\ddot S$ = 39.1 in/s$^2$; the rod CD then lies
# almost along the slide ($\theta_5 = 1.05^\circ$).
#
# </details>
#
# **Problem 10.2.** How many unknowns does a linkage of three independent loops need, and how
# many rows has its Jacobian?
#
# <details><summary>Answer</summary>
#
# Six unknowns (two per loop) and a square 6 by 6 Jacobian: each loop gives the real and the
# imaginary part of one vector equation.
#
# </details>

# %% tags=["remove-input"] jupyter={"source_hidden": true}
r101 = linkage.solve(theta2="120 deg", omega2="12 rad/s", alpha2="0 rad/s^2")
S101 = r101.vectors["S"]
stated(S101.length, "12.42", "in"), stated(S101.length_dot, "7.97", "in/s")
stated(S101.length_ddot, "39.1", "in/s^2"), stated(r101.vectors["R5"].angle, "1.05", "deg")

# %% [markdown]
# ## Common mistakes
#
# - **Unknowns and equations that do not match** (two per loop). The solver refuses such a
#   description with `InvalidInput` naming the count.
# - **Careless guesses.** They choose the assembly; a sketch of the intended linkage gives good
#   ones.
# - **Treating a converged answer as the right one.** Newton-Raphson finds *a* solution; check it
#   is the linkage you meant.
# - **Reading numbers near a singular position.** Use the `valid` mask and the condition number;
#   the solver reports `Singular` or `NotAssemblable` (or `NoConvergence`) rather than guessing.
# - **Iterating for velocities.** Only positions need Newton-Raphson.
#
# This is the last notebook on the chapter's analysis. The next one compares the methods the
# course has used, closed forms, Newton-Raphson, finite differences and the graphical
# construction, for speed and accuracy.
#
# [Next: 11. Speed and accuracy](11_speed_accuracy.ipynb)
