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
# # 2. Graphical acceleration analysis of a fourbar
#
# Before computers, accelerations were found by drawing: vectors laid tip to tail at a
# scale, closed by lines whose direction is known but whose length is not. The method is
# still the quickest independent check on a program, and it shows *why* the analytic
# equations look the way they do. Here we build Example 7-1 of the chapter (Robert L. Norton,
# *Design of Machinery*, chapter 7, section 7.2 and its Figure 7-4) one step at a time with
# `accelab.solver.graphical`, which performs the construction as geometry (it never asks the analytic
# solver for an answer).
#
# **You will be able to**
#
# - list what must be known before an acceleration polygon can be drawn (positions,
#   velocities, the input's $\alpha_2$) and count the knowns in eq. 7.4;
# - draw the acceleration polygon of a fourbar, steps 1 to 8 of Example 7-1, with the
#   construction lines $pp$ and $qq$;
# - read $\alpha_3$, $\alpha_4$ and their senses off the polygon, then find the acceleration
#   of any coupler point;
# - recognise the positions where the construction breaks down.

# %%
# %matplotlib inline
import math
import textwrap

import matplotlib.pyplot as plt

from accelab.course.kit import cartesian, explore, polar, stated, use_style
from accelab.exercises.practice import practice
from accelab.solver import Q_, FourBar, NotAssemblable, Singular
from accelab.solver.graphical import construct, construct_case
from accelab.solver.graphical.draw import draw_linkage, draw_polygon
from accelab.solver.graphical.gallery import EXAMPLE_7_1

use_style()

# %% [markdown]
# ## The idea and its equations
#
# For any two points $A$ and $B$ of one link (Case 1 of notebook 1), the acceleration
# difference equation with every term split into its components reads
#
# $$ \mathbf{A}_B = \mathbf{A}_A + \mathbf{A}_{BA}, \qquad
#    \left(\mathbf{A}^t_B + \mathbf{A}^n_B\right) = \left(\mathbf{A}^t_A + \mathbf{A}^n_A\right)
#    + \left(\mathbf{A}^t_{BA} + \mathbf{A}^n_{BA}\right) \tag{7.4} $$
#
# and the size of each component of a point turning at radius $r$ is
#
# $$ A^t = r\,\alpha, \qquad A^n = r\,\omega^2 \tag{7.6} $$
#
# Six vectors, each with a size and a direction: twelve numbers. A vector equation in the
# plane gives two scalar equations, so we must know ten of them. For the fourbar with $A$ on
# the crank and $B$ on the rocker:
#
# | term | size | direction |
# |---|---|---|
# | $\mathbf{A}^t_A$ | $a\,\alpha_2$, known | perpendicular to $O_2A$, known |
# | $\mathbf{A}^n_A$ | $a\,\omega_2^2$, known | from $A$ toward $O_2$, known |
# | $\mathbf{A}^n_B$ | $c\,\omega_4^2$, known once $\omega_4$ is | from $B$ toward $O_4$, known |
# | $\mathbf{A}^n_{BA}$ | $b\,\omega_3^2$, known once $\omega_3$ is | from $B$ toward $A$, known |
# | $\mathbf{A}^t_B$ | **unknown** ($c\,\alpha_4$) | perpendicular to $O_4B$: line $pp$ |
# | $\mathbf{A}^t_{BA}$ | **unknown** ($b\,\alpha_3$) | perpendicular to $AB$: line $qq$ |
#
# Ten knowns, two unknown sizes: the polygon closes where the lines $pp$ and $qq$ cross.
# The table also shows what has to come first: the link angles (a position analysis) and
# $\omega_3$, $\omega_4$ (a velocity analysis). The graphical method is a freeze-frame: one
# position, one drawing.
#
# **Two slips of the chapter's text to read past.** Just before Example 7-1 the chapter says
# the directions of the centripetal and tangential components are "perpendicular to and along
# the radius of rotation, respectively". That is the wrong way round: the centripetal (normal)
# component lies *along* the radius and the tangential one is *perpendicular* to it, as eq. 7.2
# and the example itself draw them. And in the discussion after the example it says we could
# compute $\mathbf{A}^n_B$ "since we knew $\omega_3$ and the link length": $\mathbf{A}^n_B =
# c\,\omega_4^2$ needs $\omega_4$, the rocker's. (The course's [errata page](errata.md) lists
# every misprint it found.)
#
# The linkage of this notebook, used throughout the course as "Example 7-1". The chapter's
# example prints no numbers; **these are the course's own numbers**:

# %%
EXAMPLE_7_1

# %% [markdown]
# ## Worked example: Example 7-1, step by step
#
# `construct_case` records the construction as a list of steps; `draw_linkage` and
# `draw_polygon` draw what the steps up to a given one have added. A small helper puts the
# linkage and one polygon side by side.

# %%
con = construct_case(EXAMPLE_7_1)
for s in con.steps:
    print(
        textwrap.fill(
            s.text, 92, initial_indent=f"{s.label:>3}  {s.phase:<13}", subsequent_indent=" " * 18
        )
    )


def show(step, diagram=None, figsize=(11, 5.2)):
    """The linkage (left) and one polygon (right) as they stand after `step`."""
    if diagram is None:
        fig, ax = plt.subplots(figsize=(7, 5.4))
        draw_linkage(con, step=step, ax=ax)
    else:
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=figsize, width_ratios=[1.15, 1])
        draw_linkage(con, step=step, ax=ax1)
        draw_polygon(con, diagram, step=step, ax=ax2)
    fig.suptitle(f"after step {step}", fontsize=11, color="#555555")
    plt.show()


# %% [markdown]
# **Position and velocity first (P, V1-V3).** The linkage is drawn to scale: $A$ at $a$ from
# $O_2$, then arcs of radius $b$ about $A$ and $c$ about $O_4$ meet at $B$ (the open circuit
# takes the upper intersection). The velocity polygon solves $\mathbf{V}_B = \mathbf{V}_A +
# \mathbf{V}_{BA}$ the same way: $\mathbf{V}_A$ is fully known, $\mathbf{V}_B$ is perpendicular
# to $O_4B$ and $\mathbf{V}_{BA}$ perpendicular to $AB$. Their lengths give $\omega_4 =
# V_B/c$ and $\omega_3 = V_{BA}/b$.

# %% mystnb={"figure": {"caption": "Example 7-1, velocity polygon: V_A, then V_B and V_BA found where their known directions cross."}, "image": {"alt": "Velocity polygon of the fourbar with the vectors V_A, V_B and V_BA drawn from the pole."}}
show("V3", "velocity")
v = con.values
print(f"omega3 = {v['omega3']:.4f} rad/s, omega4 = {v['omega4']:.4f} rad/s (both clockwise)")

# %% [markdown]
# **Steps 1-2: the input point.** $A$ turns about a fixed pivot, so both parts of its
# acceleration are known from eq. 7.6 and drawn at $A$: $A^n_A = a\omega_2^2$ toward $O_2$,
# $A^t_A = a|\alpha_2|$ perpendicular to $O_2A$, clockwise here because $\alpha_2 < 0$.

# %% mystnb={"figure": {"caption": "Example 7-1, first steps of the acceleration polygon: the crank pin's tangential and normal accelerations."}, "image": {"alt": "Linkage and the start of the acceleration polygon with the two components of A_A."}}
a_in = Q_(2, "in")
print(
    "A_A^n:",
    polar(Q_(v["A_A_n"], "m/s^2"), "in/s^2"),
    f"  (a omega2^2 = {(a_in * Q_(10, 'rad/s') ** 2).to('in/s^2'):.4g~P})",
)
print(
    "A_A^t:",
    polar(Q_(v["A_A_t"], "m/s^2"), "in/s^2"),
    f"  (a |alpha2| = {(a_in * Q_(5, 'rad/s^2')).to('in/s^2'):.4g~P})",
)
show("2")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
stated(abs(v["A_A_n"]) / abs(v["A_A_t"]), "20")
# %% [markdown]
# The tangential part is a twentieth of the normal one ($\alpha_2$ is small next to
# $\omega_2^2$), too short to see at the scale of the drawing, so the drawing shows it again
# magnified in an inset (the chapter's Figure 7-4 draws these two components at twice size for
# the same reason).
#
# **Steps 3-5: the directions we know.** $B$ turns about $O_4$, so $\mathbf{A}^t_B$ lies on
# the line $pp$ through $B$ perpendicular to $O_4B$, and $\mathbf{A}^n_B = c\omega_4^2$ points
# at $O_4$. Relative to $A$, $B$ turns with link 3: $\mathbf{A}^n_{BA} = b\omega_3^2$ points
# from $B$ to $A$ and $\mathbf{A}^t_{BA}$ lies on the line $qq$ perpendicular to $AB$.

# %% mystnb={"figure": {"caption": "Example 7-1, the known normal components of A_B and A_BA added, and the construction lines for the unknown tangential ones."}, "image": {"alt": "Acceleration polygon under construction with normal components and dashed construction lines."}}
show("5")

# %% [markdown]
# **Step 6: the polygon.** Eq. 7.4 has two sides, and the drawing lays each from the pole
# $o_A$. The right side, tip to tail in the order the equation adds it: $\mathbf{A}^t_A$,
# $\mathbf{A}^n_A$ (together $\mathbf{A}_A$), then $\mathbf{A}^n_{BA}$, and through its tip a
# line parallel to $qq$ (the direction of the unknown $\mathbf{A}^t_{BA}$). The left side:
# $\mathbf{A}^n_B$, and through its tip a line parallel to $pp$ (the direction of the unknown
# $\mathbf{A}^t_B$). Both sides equal $\mathbf{A}_B$, so the two lines cross at its tip: the
# crossing cuts off $\mathbf{A}^t_{BA}$ and $\mathbf{A}^t_B$, and $\mathbf{A}_B$ runs from the
# pole to it, the sum of either chain.
#
# The chapter's step 6 does the same with $\mathbf{A}^n_B$ moved to the right side: it draws
# $-\mathbf{A}^n_B$ at the end of $\mathbf{A}^n_{BA}$, the line parallel to $qq$ through that
# tip and the one parallel to $pp$ through the pole. The two lines then cross at the tip of
# $\mathbf{A}^t_B$ instead, with the same lengths cut off. Laying both sides from the pole shows
# $\mathbf{A}_B$ as the sum it is.

# %% mystnb={"figure": {"caption": "Example 7-1, the closed acceleration polygon: the tangential components found where the construction lines cross."}, "image": {"alt": "Linkage beside its completed acceleration polygon, with every component labelled."}}
show("6", "acceleration", figsize=(12, 6))

# %% [markdown]
# **Step 7: read the answer.** Measured along $pp$ and $qq$ and divided by the link lengths
# (eq. 7.6), the two tangential parts give the angular accelerations. Their *senses* come
# from the arrows: $\mathbf{A}^t_B$ points the way $B$ is being speeded up about $O_4$.

# %%
print(f"A_B^t  = {abs(v['A_B_t']):.4f} m/s^2  -> alpha4 = A_B^t / c  = {v['alpha4']:+.4f} rad/s^2")
print(f"A_BA^t = {abs(v['A_BA_t']):.4f} m/s^2  -> alpha3 = A_BA^t / b = {v['alpha3']:+.4f} rad/s^2")
print(
    "A_A =", cartesian(Q_(v["A_A"], "m/s^2"), "in/s^2"), "=", polar(Q_(v["A_A"], "m/s^2"), "in/s^2")
)
print(
    "A_B =", cartesian(Q_(v["A_B"], "m/s^2"), "in/s^2"), "=", polar(Q_(v["A_B"], "m/s^2"), "in/s^2")
)
c_len = 9 * 0.0254
assert math.isclose(v["alpha4"], abs(v["A_B_t"]) / c_len, rel_tol=1e-12)  # CCW: positive
assert v["alpha3"] > 0 and v["alpha4"] > 0 and EXAMPLE_7_1["alpha2"].startswith("-")

# %% [markdown]
# Both angular accelerations come out counter-clockwise (positive), although $\alpha_2$ is
# clockwise: the input's acceleration is tiny here, and what accelerates links 3 and 4 is
# mostly the *changing direction* of the crank pin's velocity ($a\omega_2^2$).
#
# **Step 8: any other point.** With $\alpha_3$ and $\omega_3$ known, a coupler point $P$
# ($p = 3$ in from $A$, $30^\circ$ off the line $AB$) follows from the same equation with $A$ as
# reference: $\mathbf{A}_P = \mathbf{A}_A + \mathbf{A}^t_{PA} + \mathbf{A}^n_{PA}$, all three
# fully known now. No construction lines are needed.

# %% mystnb={"figure": {"caption": "Example 7-1, the acceleration of coupler point P found from A_A and the acceleration difference A_PA."}, "image": {"alt": "Acceleration polygon extended to the coupler point P."}}
show("8", "point")
print(
    "A_P =", cartesian(Q_(v["A_P"], "m/s^2"), "in/s^2"), "=", polar(Q_(v["A_P"], "m/s^2"), "in/s^2")
)

# %% [markdown]
# Notebook 3 solves the same linkage from the differentiated vector loop, and the two
# answers agree to better than one part in $10^9$ (it checks this): the drawing is exact
# geometry, only a ruler makes it approximate.
#
# ### When the construction fails
#
# The lines $pp$ and $qq$ must cross. They are perpendicular to $O_4B$ and $AB$, so they are
# parallel exactly when links 3 and 4 lie on one line: a **toggle** position. A non-Grashof
# linkage ($a = 5$, $b = 5$, $c = 5$, $d = 7$ in) reaches one where $|O_4A| = b + c$; just
# beyond it the arcs that locate $B$ no longer meet and the linkage cannot be assembled at
# all.

# %%
a, b, c, d = (x * 0.0254 for x in (5, 5, 5, 7))  # SI, as accelab.solver.graphical takes them
toggle = math.acos((a * a + d * d - (b + c) ** 2) / (2 * a * d))
print(f"toggle at theta2 = {math.degrees(toggle):.4f} deg")
for t2 in (toggle - 0.05, toggle, toggle + 0.05):
    try:
        g = construct("fourbar", a=a, b=b, c=c, d=d, theta2=t2, omega2=10.0, alpha2=0.0)
        print(f"theta2 = {math.degrees(t2):8.4f} deg: alpha4 = {g.values['alpha4']:.5g} rad/s^2")
    except (Singular, NotAssemblable) as exc:
        print(f"theta2 = {math.degrees(t2):8.4f} deg: {type(exc).__name__}: {str(exc)[:110]}...")

# %% [markdown]
# Near the toggle $\alpha_4$ grows without bound: the two construction lines meet at a
# shallower and shallower angle, far from the pole. At the toggle itself the solver refuses
# to return a number rather than return one it cannot vouch for.

# %% [markdown]
# ## Explore: a new drawing for every position
#
# The graphical method's cost is that nothing carries over from one crank angle to the
# next: each position needs its own polygon. Move $\theta_2$ and watch the acceleration
# polygon of Example 7-1 change shape and size: blue normal components, red dashed tangential
# ones, black $\mathbf{A}_A$ and $\mathbf{A}_B$ from the pole $o_A$. The positions are all drawn
# in one frame, at one scale (in a live notebook the frame grows with $\omega_2^2$ when you
# move $\omega_2$, so that the polygon keeps its size on the screen).


# %% mystnb={"figure": {"caption": "The graphical construction at several crank angles, all at the same scale: the polygon changes shape over the cycle."}, "image": {"alt": "Small multiples of the fourbar's acceleration polygon at several crank angles."}}
def draw(theta2, omega2):
    case = dict(EXAMPLE_7_1, theta2=f"{theta2} deg", omega2=f"{omega2} rad/s")
    case.pop("p"), case.pop("delta3")
    g = construct_case(case)
    reach = 380 * (omega2 / 10) ** 2  # in/s^2: the frame grows as omega2^2
    fig, ax = plt.subplots(figsize=(4.4, 4.6))
    draw_polygon(
        g,
        "acceleration",
        ax=ax,
        box=(-reach, reach, -reach, reach),
        inset=False,
        title=f"$\\alpha_3$ = {g.values['alpha3']:.3g}, $\\alpha_4$ = "
        f"{g.values['alpha4']:.3g} rad/s$^2$",
    )
    ax.title.set_fontsize(10)
    return fig


explore(draw, theta2=(0, 360, 5, 30, "deg"), omega2=(1, 20, 1, 10, "rad/s"))

# %% [markdown]
# The polygon turns with the crank and stretches and shrinks: at some angles
# $\mathbf{A}^t_B$ is the longest vector, at others almost nothing. Doubling $\omega_2$ (with
# $\alpha_2$ small) makes every vector four times longer and leaves the shape alone, since
# every term but $\mathbf{A}^t_A$ scales with $\omega_2^2$: with the frame following
# $\omega_2^2$, the picture hardly changes.

# %% [markdown]
# ## Check yourself
#
# **1.** Why must the velocity polygon be drawn before the acceleration polygon?
#
# <details><summary>Answer</summary>
#
# The normal components $b\omega_3^2$ and $c\omega_4^2$ need $\omega_3$ and $\omega_4$. Without
# them there are four unknown sizes in eq. 7.4 and only two equations.
#
# </details>
#
# **2.** In step 6, what goes wrong if you draw $+\mathbf{A}^n_B$ instead of
# $-\mathbf{A}^n_B$?
#
# <details><summary>Answer</summary>
#
# The polygon closes at the wrong point: you have solved $\mathbf{A}^t_B - \mathbf{A}^n_B =
# \mathbf{A}_A + \mathbf{A}_{BA}$, not eq. 7.4. Both $\alpha_3$ and $\alpha_4$ come out wrong,
# usually without any visible sign that something is off. Terms on the left side of the
# equation are subtracted when the polygon is laid from the right side.
#
# </details>
#
# **3.** $\mathbf{A}^t_{BA}$ in the polygon points, roughly, from right to left, and $B$ is above
# $A$. Is $\alpha_3$ clockwise or counter-clockwise?
#
# <details><summary>Answer</summary>
#
# Counter-clockwise. $\mathbf{A}^t_{BA} = b\alpha_3\,je^{j\theta_3}$: with $\theta_3$ near
# $90^\circ$ (B above A), $je^{j\theta_3}$ points to the left, so a leftward
# $\mathbf{A}^t_{BA}$ means $\alpha_3 > 0$. The printed $\alpha_3 = +8.77$ rad/s$^2$ agrees.
#
# </details>
#
# **4.** To find the acceleration of a point on the rocker (link 4), which reference point
# would you use and what do you need?
#
# <details><summary>Answer</summary>
#
# $O_4$, the rocker's fixed pivot: $\mathbf{A}_U = u\alpha_4\,je^{j(\theta_4+\delta_4)} -
# u\omega_4^2 e^{j(\theta_4+\delta_4)}$, since $\mathbf{A}_{O_4} = 0$. You need $\omega_4$ and
# $\alpha_4$, i.e. the finished polygon.
#
# </details>

# %% tags=["remove-input"] jupyter={"source_hidden": true}
stated(v["alpha3"], "8.77")
assert 60 < math.degrees(v["theta3"]) < 120 and v["A_BA_t"].real < 0  # B above A, leftward

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set: draw the polygons yourself (on paper or with
# `construct_case` and `draw_polygon`), then compare. The answers are folded.
#
# **Problem 2.1.** The Example 7-1 linkage (the course's numbers: $a$ = 2, $b$ = 6, $c$ = 9,
# $d$ = 7 in, open circuit) at $\theta_2 = 120^\circ$, $\omega_2$ = 10 rad/s, $\alpha_2$ = -5
# rad/s$^2$. Find $\omega_3$ and $\omega_4$ from the velocity polygon, then $\alpha_3$,
# $\alpha_4$ and $\mathbf{A}_B$ from the acceleration polygon.
#
# <details><summary>Answer</summary>
#
# $\omega_3 = -0.475$ rad/s, $\omega_4 = 2.058$ rad/s. The normal part $A^n_A = a\omega_2^2
# = 200$ in/s$^2$ is again twenty times $A^t_A$; the polygon closes at $\alpha_3 = 30.50$ and
# $\alpha_4 = 11.25$ rad/s$^2$ (both counter-clockwise), and $\mathbf{A}_B$ is 108.2 in/s$^2$ at
# $-122.1^\circ$.
#
# </details>
#
# **Problem 2.2.** Same linkage and input as Example 7-1, but on the *crossed* circuit. Which
# of the vectors of the polygon are the same as on the open circuit, and what is $\alpha_4$?
#
# <details><summary>Answer</summary>
#
# Only $\mathbf{A}^t_A$ and $\mathbf{A}^n_A$ (and their sum $\mathbf{A}_A$): they depend on the
# crank alone. Everything else changes with the position of B. On the crossed circuit
# $\alpha_3 = 70.3$ and $\alpha_4 = 39.61$ rad/s$^2$, against 8.77 and 39.43 on the open one:
# at this angle the two rockers happen to accelerate alike, the couplers do not.
#
# </details>

# %% tags=["remove-input"] jupyter={"source_hidden": true}
g120 = construct_case(dict(EXAMPLE_7_1, theta2="120 deg")).values
stated(g120["omega3"], "-0.475"), stated(g120["omega4"], "2.058")
stated(abs(g120["A_A_n"]) / 0.0254, "200"), stated(abs(g120["A_A_n"] / g120["A_A_t"]), "20")
stated(g120["alpha3"], "30.50"), stated(g120["alpha4"], "11.25")
(
    stated(abs(g120["A_B"]) / 0.0254, "108.2"),
    stated(math.degrees(math.atan2(g120["A_B"].imag, g120["A_B"].real)), "-122.1"),
)
crossed = construct_case(dict(EXAMPLE_7_1, circuit="crossed")).values
assert crossed["A_A"] == v["A_A"] and crossed["A_B"] != v["A_B"]
stated(crossed["alpha3"], "70.3"), stated(crossed["alpha4"], "39.61")
stated(v["alpha3"], "8.77"), stated(v["alpha4"], "39.43")
# the analytic solver agrees (notebook 3 derives it)
r120 = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
    theta2="120 deg", omega2="10 rad/s", alpha2="-5 rad/s^2"
)
assert math.isclose(r120.alpha4.magnitude, g120["alpha4"], rel_tol=1e-9)
# %% [markdown]
# ## Your turn: the polygon builder
#
# Reading a construction is not doing one. The **polygon builder** below is a drawing board
# for Example 7-1: the linkage drawn to scale beside a polygon canvas whose scale is stated
# on it. Build the velocity polygon first, then the acceleration polygon, as the steps above
# did:
#
# - **Vector**: lay a known vector from the pole or from the tip of the last one. Drag from
#   the point to its tip (the direction snaps to a link, or across it, within 2.5°, and the
#   length and angle show as you drag), or type its length (in the polygon's units or in
#   squares) and its direction: parallel or perpendicular to a link, and which way.
# - **Line**: a construction line of known direction (the chapter's $pp$ and $qq$) through a
#   point: drag from the point along the direction, or type it.
# - **Crossing**: tap where two lines cross: the polygon closes there. Then draw the unknown
#   vectors to it, and measure them with **Measure**.
# - **Read off**: type $\omega_3$, $\omega_4$ (then $\alpha_3$, $\alpha_4$), counter-clockwise
#   positive.
# - **Undo**, **Clear**, and zoom: +, −, fit, Ctrl and the mouse wheel, or a pinch on a
#   touchpad or a touch screen.
#
# Each step is checked as you make it: a direction is right within 1°, a length within 2% of
# the polygon's largest vector. A wrong step turns red with a number, and the builder says
# which rule it broke, in the chapter's terms; it never draws the answer unless you ask with
# **Show the next step**. (On this web page the builder cannot run, so the figure shows the
# finished construction. Download the notebook, or write the course with
# `accelab course --out DIR`, to build it yourself.)

# %% mystnb={"figure": {"caption": "Example 7-1 in the polygon builder: the finished velocity and acceleration polygons, one scale each. In a live notebook this cell is the builder itself, empty, and each step is checked as it is drawn."}, "image": {"alt": "The velocity and acceleration polygons of Example 7-1 as the polygon builder draws a finished construction."}}
from accelab.exercises.student.polygon import PolygonBuilder
from accelab.solver.graphical.gallery import EXAMPLE_7_1, INVERTED_SLIDER_CRANK

PolygonBuilder.from_case(EXAMPLE_7_1, title="Example 7-1: your construction").show()

# %% [markdown]
# **What the builder says** when a step breaks a rule: the classic mistakes, made on
# Example 7-1, and the builder's own words for each.

# %%
from accelab.course.polygons import classic_mistakes

classic_mistakes(EXAMPLE_7_1)

# %% [markdown]
# And on an inverted slider-crank, whose polygon needs the Coriolis component
# $2\omega_4 V_{slip}$ of notebook 5:

# %%
classic_mistakes(INVERTED_SLIDER_CRANK)

# %% [markdown]
# ### One of each kind, to practise
#
# Fresh problems of the three graded exercise families whose answer is a construction:
# `polygon_fourbar`, `polygon_slidercrank` and `polygon_coriolis` (the inverted slider-crank,
# with its Coriolis component). Each run draws a new position, never one of a graded
# assignment's, and its builder checks each step. In a graded assignment the same builder
# records your construction without checking it; the construction is saved with the notebook
# and judged step by step when the assignment is graded, with partial credit.

# %% tags=["remove-output"]
practice("polygon_fourbar").builder().show()

# %% tags=["remove-output"]
practice("polygon_slidercrank").builder().show()

# %% tags=["remove-output"]
practice("polygon_coriolis").builder().show()

# %% [markdown]
# **On this page**, the problems of seed 3 of the slider-crank and the inverted
# slider-crank: draw them on paper (or in the notebook, with
# `practice("polygon_slidercrank", seed=3).builder()`), then unfold the finished
# constructions.

# %%
p = practice("polygon_slidercrank", seed=3)
p

# %% tags=["hide-output"]
p.answers()

# %%
p = practice("polygon_coriolis", seed=3)
p

# %% tags=["hide-output"]
p.answers()

# %% [markdown]
# ## Practice
#
# Fourbar problems with instant feedback, for self-study (not graded, and never one of a graded
# assignment's): each run of the next cell draws a fresh linkage and input (or give a seed to
# come back to one). Solve it graphically, with `construct_case` and the polygon, or by the
# equations of notebook 3, then hand each answer to `p.check`, which says at once whether it is
# right and, if not, what to look at (the unit, the sign, the size).
#
# The graded exercise family that practises this notebook is `fourbar` (with `coupler` for
# step 8).
#
# (The web page of this notebook leaves the freshly drawn problem out, since there is
# nothing to type into there: download the notebook, or write the course with
# `accelab course --out DIR`, and run it. The problem of seed 3 below is the same on
# every run, so the page shows it, with its answers folded.)

# %% tags=["remove-output"]
p = practice("fourbar")
p

# %%
# your answers, e.g.:  p.check("alpha3", Q_(12.5, "rad/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 3: work it out on paper (or with the
# solver), then unfold the answers.

# %%
p = practice("fourbar", seed=3)
p

# %% tags=["hide-output"]
p.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 3, solved by the graphical construction:

# %%
p = practice("fourbar", seed=3)
g = dict(p.problem.given, mechanism="fourbar")
drawn = construct_case(g).values
assert p.check("alpha4", Q_(drawn["alpha4"], "rad/s^2"))  # right
assert not p.check("alpha4", Q_(-drawn["alpha4"], "rad/s^2"))  # the sense read the wrong way
assert not p.check("alpha4", Q_(drawn["alpha4"], "rad/s"))  # not an angular acceleration

# %% [markdown]
# ## Common mistakes
#
# - **Skipping the velocity analysis.** No $\omega_3$, $\omega_4$, no normal components, no
#   polygon.
# - **Normal components pointing outward.** A normal component always points from the moving
#   point toward its centre of rotation relative to the reference: $\mathbf{A}^n_{BA}$ from $B$
#   toward $A$, not from $A$ toward $B$.
# - **Adding a term from the left side of eq. 7.4.** $\mathbf{A}^n_B$ is subtracted in the
#   polygon; $\mathbf{A}_B$ is the vector from the pole to the closing point.
# - **Taking a reference point on another link.** For the coupler point $P$, use $A$ or $B$
#   (on link 3), never $O_2$: the Case 1 rules hold only within one rigid body.
# - **Two scales on one drawing.** Lengths and accelerations each need one scale, written on
#   the drawing, and the polygon must use a single acceleration scale throughout.
# - **Reading the sense of $\alpha$ from the shape of the polygon.** Read it from the
#   direction of the tangential vector relative to its radius ($je^{j\theta}$).
#
# [Next: 3. The analytic fourbar](03_analytic_fourbar.ipynb)
