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
# equations look the way they do. Here we draw Example 7-1 of the chapter (Robert L. Norton,
# *Design of Machinery*, chapter 7, section 7.2 and its Figure 7-4) by hand, one line at a
# time, with `accelab.solver.graphical`, which performs the construction as geometry (it
# never asks the analytic solver for an answer).
#
# **You will be able to**
#
# - list what must be known before an acceleration polygon can be drawn (positions,
#   velocities, the input's $\alpha_2$) and count the knowns in eq. 7.4;
# - draw the velocity polygon, then the acceleration polygon of a fourbar, steps 1 to 8 of
#   Example 7-1, with the construction lines $pp$ and $qq$;
# - read $\alpha_3$, $\alpha_4$ and their senses off the polygon, then find the acceleration
#   of any coupler point;
# - recognise the positions where the construction breaks down.

# %%
# %matplotlib inline
import math

import matplotlib.pyplot as plt

from accelab.course.kit import explore, stated, use_style
from accelab.course.polygons import classic_mistakes, show_builder
from accelab.course.practice import practice
from accelab.exercises.student.polygon import PolygonBuilder
from accelab.solver import Q_, FourBar, NotAssemblable, Singular
from accelab.solver.graphical import construct, construct_case
from accelab.solver.graphical.byhand import Markdown, by_hand, case_table
from accelab.solver.graphical.draw import draw_polygon
from accelab.solver.graphical.gallery import EXAMPLE_7_1, INVERTED_SLIDER_CRANK

use_style()

# %% [markdown]
# ## The idea and its equations
#
# For any two points $A$ and $B$ of one link (Case 1 of notebook 1), the acceleration
# difference equation with every term split into its components reads
#
# $$ \begin{aligned} \mathbf{A}_B &= \mathbf{A}_A + \mathbf{A}_{BA} \\
#    \mathbf{A}^t_B + \mathbf{A}^n_B &= \left(\mathbf{A}^t_A + \mathbf{A}^n_A\right) \\
#    &\quad + \left(\mathbf{A}^t_{BA} + \mathbf{A}^n_{BA}\right) \end{aligned} \tag{7.4} $$
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
# Ten knowns, two unknown sizes: the polygon closes where lines parallel to $pp$ and $qq$
# cross. The table also shows what has to come first: the link angles (a position analysis)
# and $\omega_3$, $\omega_4$ (a velocity analysis). The graphical method is a freeze-frame:
# one position, one drawing.
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
# The linkage of this notebook is the one the course calls "Example 7-1" throughout. The
# chapter's example prints no numbers; **these are the course's own**:

# %% tags=["remove-input"] jupyter={"source_hidden": true}
case_table(EXAMPLE_7_1)

# %% [markdown]
# ## Worked example: Example 7-1 by hand, step by step
#
# Every figure below adds **one** vector or **one** construction line to the one before,
# on a pale yellow band; the frame and the scale of each diagram stay the same from its first
# figure to its last, and the scale is the bar under it. The tables give every size and
# direction in the drawing's units, so you can draw along on paper.
#
# **To draw along** you need a ruler, a protractor and two set squares (to draw a line
# perpendicular or parallel to another). Scales that fit a letter or A4 sheet: the linkage at
# half size (1 in on paper for 2 in), the velocity polygon at 1 in for 10 in/s and the
# acceleration polygon at 1 in for 50 in/s$^2$. Angles below are measured from $+x$,
# counter-clockwise positive.
#
# The whole construction is made once; `by_hand` cuts it into the strokes a draftsman makes,
# in the chapter's order:

# %%
con = construct_case(EXAMPLE_7_1)  # the construction: geometry only
walk = by_hand(con)  # the same, stroke by stroke
Markdown(f"{len(walk.labels)} strokes, in order: " + ", ".join(walk.labels) + ".")


# %% tags=["remove-input"] jupyter={"source_hidden": true}
def show(label):
    """The figure of one stroke of the walk."""
    walk.draw(label)
    plt.show()


v = walk.values


def deg(z):
    """Angle of a vector from +x [deg]."""
    return math.degrees(math.atan2(z.imag, z.real))


IN = 0.0254  # m per inch: the drawing is in inches

# %% [markdown]
# ### Position
#
# Example 7-1 assumes the position and velocity analyses done; the acceleration polygon needs
# both, so we draw them first. Lay off $O_2O_4 = d$ along $+x$ and the crank $a$ at
# $\theta_2$; then swing an arc of radius $b$ about $A$ and one of radius $c$ about $O_4$.
# They meet at $B$ (the open circuit takes the upper crossing).

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step P, on the linkage."}, "image": {"alt": "The fourbar of Example 7-1 drawn to scale, with the two arcs that locate B and the crank angle theta2."}}
show("P")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
Markdown(
    f"Measured on the drawing: $\\theta_3$ = {math.degrees(v['theta3']):.1f}° and "
    f"$\\theta_4$ = {math.degrees(v['theta4']):.1f}° (angles of $\\vec{{AB}}$ and "
    "$\\vec{O_4B}$ from $+x$)."
)

# %% [markdown]
# ### The velocity polygon
#
# The velocity difference equation of $B$ against $A$ is solved the same way as eq. 7.4 will
# be: $\mathbf{V}_B = \mathbf{V}_A + \mathbf{V}_{BA}$ (eq. 6.5). $\mathbf{V}_A$ is known
# outright, $a\omega_2$ perpendicular to the crank in the sense of $\omega_2$; it is drawn
# from a pole $o_V$, the point of zero velocity.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step V1, on the velocity polygon."}, "image": {"alt": "Velocity polygon with the vector V_A drawn from the pole o_V."}}
show("V1")

# %% [markdown]
# $B$ turns about the fixed $O_4$, so $\mathbf{V}_B$ is perpendicular to $O_4B$: a line
# through the pole. Relative to $A$, $B$ turns with link 3, so $\mathbf{V}_{BA}$ is
# perpendicular to $AB$: a line through the tip of $\mathbf{V}_A$.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step V2, on the velocity polygon."}, "image": {"alt": "Velocity polygon: V_A and a line through the pole perpendicular to O4B."}}
show("V2")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step V3, on the velocity polygon."}, "image": {"alt": "Velocity polygon: V_A and the two direction lines, perpendicular to O4B and to AB."}}
show("V3")

# %% [markdown]
# Where the two lines cross is the tip of $\mathbf{V}_B$: from the pole to the crossing is
# $\mathbf{V}_B$, from the tip of $\mathbf{V}_A$ to the crossing is $\mathbf{V}_{BA}$.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step V4, on the velocity polygon."}, "image": {"alt": "Velocity polygon: V_B drawn from the pole to where the two lines cross."}}
show("V4")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step V5, on the velocity polygon."}, "image": {"alt": "The finished velocity polygon: V_A, V_B and V_BA."}}
show("V5")

# %% [markdown]
# The velocity polygon in numbers. A size measured on the drawing, divided by the link's
# length, is the link's angular velocity; its sense is the way the vector turns the link
# (here $\mathbf{V}_B$ points up and to the right at $B$, which is up and to the left of
# $O_4$: it turns $O_4B$ clockwise).

# %% tags=["remove-input"] jupyter={"source_hidden": true}
walk.table("velocity")

# %% [markdown]
# ### The acceleration polygon: steps 1 to 8 of Example 7-1
#
# **Step 1.** Start where most is known, the crank pin $A$: it turns about a fixed pivot, so
# eq. 7.6 gives both components of its acceleration outright:
# $A^n_A = a\omega_2^2$ = 2 in $\times$ (10 rad/s)$^2$ = 200 in/s$^2$ and
# $A^t_A = a\alpha_2$ = 2 in $\times$ (-5 rad/s$^2$) = -10 in/s$^2$, clockwise like $\alpha_2$.
#
# **Step 2.** Draw them at $A$ on the linkage: $\mathbf{A}^n_A$ along $AO_2$ toward $O_2$,
# $\mathbf{A}^t_A$ perpendicular to $O_2A$ in the sense of $\alpha_2$. The vectors on the
# linkage have their own scale (the lower bar), one for the whole linkage drawing.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 2a, on the linkage (Figure 7-4a)."}, "image": {"alt": "The linkage with the normal acceleration of A drawn at A, toward O2."}}
show("2a")

# %% [markdown]
# $\mathbf{A}^t_A$ is a twentieth of $\mathbf{A}^n_A$ ($\alpha_2$ is small next to
# $\omega_2^2$): too short to read at the scale of the drawing, so it is shown again
# magnified in the small box, at the factor written in it. (The chapter's Figure 7-4 draws
# these two components at twice size for the same reason.)

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 2b, on the linkage (Figure 7-4a)."}, "image": {"alt": "The linkage with both components of the acceleration of A, the short tangential one also shown magnified."}}
show("2b")

# %% [markdown]
# **Step 3.** $B$ turns about $O_4$, so its tangential acceleration $\mathbf{A}^t_B$ is
# perpendicular to $O_4B$. Its size is unknown; draw its direction, the construction line
# $pp$ through $B$.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 3, on the linkage (Figure 7-4a)."}, "image": {"alt": "The linkage with construction line pp through B, perpendicular to O4B."}}
show("3")

# %% [markdown]
# **Step 4.** Write eq. 7.4 for $B$ against $A$ (the chapter's equation (c)). Of its twelve
# numbers we now know seven: both parts of $\mathbf{A}_A$, the directions of
# $\mathbf{A}^t_B$ ($pp$) and $\mathbf{A}^n_B$ (along $BO_4$), and the size of
# $\mathbf{A}^n_B = c\,\omega_4^2$ from the velocity polygon's $\omega_4$.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 4, on the linkage (Figure 7-4a)."}, "image": {"alt": "The linkage with the normal acceleration of B drawn at B, toward O4."}}
show("4")

# %% [markdown]
# **Step 5.** The acceleration difference $\mathbf{A}_{BA}$ gives the last three:
# $\mathbf{A}^n_{BA} = b\,\omega_3^2$ points from $B$ toward $A$ (the reference point is the
# centre of the relative rotation), and $\mathbf{A}^t_{BA}$ is perpendicular to $AB$: the
# construction line $qq$ through $B$.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 5a, on the linkage (Figure 7-4a)."}, "image": {"alt": "The linkage with the normal acceleration difference of B relative to A drawn at B, toward A."}}
show("5a")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 5b, on the linkage (Figure 7-4a)."}, "image": {"alt": "The linkage with construction line qq through B, perpendicular to AB: Figure 7-4a complete."}}
show("5b")

# %% [markdown]
# **Step 6: the polygon.** Now eq. 7.4 is solved by drawing, from a new pole $o_A$ (the
# point of zero acceleration), at one scale for the whole polygon. First every vector whose
# size and direction are both known, tip to tail, in the order and with the sense the
# equation gives them. The right side starts with $\mathbf{A}_A$: its two components, then
# their sum.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6a, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: the short tangential component of A_A from the pole, also shown magnified."}}
show("6a")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6b, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: the normal component of A_A at the tip of the tangential one."}}
show("6b")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6c, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: A_A from the pole, the sum of its two components."}}
show("6c")

# %% [markdown]
# The equation adds $\mathbf{A}_{BA}$ to $\mathbf{A}_A$: its known part
# $\mathbf{A}^n_{BA}$ goes at the tip of $\mathbf{A}_A$. $\mathbf{A}^n_B$ is known as well,
# but it is on the *left* side of eq. 7.4, so it is subtracted: draw $-\mathbf{A}^n_B$ (the
# opposite sense) at the tip of $\mathbf{A}^n_{BA}$.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6d, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: the normal component of A_BA added at the tip of A_A."}}
show("6d")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6e, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: minus the normal component of A_B added at the tip of the normal component of A_BA."}}
show("6e")

# %% [markdown]
# That uses up every fully known vector. The two unknowns have known directions: draw a line
# parallel to $qq$ (the direction of $\mathbf{A}^t_{BA}$) through the tip of
# $-\mathbf{A}^n_B$, and a line parallel to $pp$ (the direction of $\mathbf{A}^t_B$) through
# the pole, since the left side, $\mathbf{A}_B$, must start where the polygon started.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6f, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: a line parallel to qq through the tip of minus A_B normal."}}
show("6f")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6g, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: a line parallel to pp through the pole; the two lines cross."}}
show("6g")

# %% [markdown]
# **Where the two chains close.** The crossing fixes both unknown sizes at once. The right
# side of eq. 7.4 runs from the pole tip to tail, $\mathbf{A}^t_A$, $\mathbf{A}^n_A$,
# $\mathbf{A}^n_{BA}$, $-\mathbf{A}^n_B$, and is closed by $\mathbf{A}^t_{BA}$, from the tip of
# $-\mathbf{A}^n_B$ to the crossing. The left side is $\mathbf{A}^t_B$ alone (its
# $\mathbf{A}^n_B$ was moved across), from the pole to the same crossing: both chains end
# there, which is eq. 7.4 drawn.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6h, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: the tangential component of A_BA, from the tip of minus A_B normal to the crossing."}}
show("6h")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6i, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: the tangential component of A_B, from the pole to the crossing."}}
show("6i")

# %% [markdown]
# $\mathbf{A}_B$ itself is the left side put back together, $\mathbf{A}^t_B +
# \mathbf{A}^n_B$: draw $\mathbf{A}^n_B$ once more, now at the tip of $\mathbf{A}^t_B$, and
# close with $\mathbf{A}_B$ from the pole. (The two copies of $\mathbf{A}^n_B$ and
# $-\mathbf{A}^n_B$ are parallel and equal: a parallelogram, a check on the drawing.)

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6j, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "Acceleration polygon: the normal component of A_B drawn again at the tip of the tangential one."}}
show("6j")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 6k, on the acceleration polygon (Figure 7-4b)."}, "image": {"alt": "The finished acceleration polygon, Figure 7-4b: A_B from the pole closes it."}}
show("6k")

# %% [markdown]
# **Step 7: read the answer.** The sizes measured along $pp$ and $qq$, divided by the link
# lengths (eq. 7.6, the chapter's equation (d)), give the angular accelerations; their
# *senses* come from the arrows, placed back at their points.
# $\mathbf{A}^t_B = c\,\alpha_4\,je^{j\theta_4}$: it points the way $\alpha_4$ turns $O_4B$
# about $O_4$. It does **not** say whether $B$ is being speeded up or slowed down; that
# depends on $\omega_4$ too. Here $\mathbf{A}^t_B$ turns the rocker counter-clockwise,
# $\alpha_4 > 0$, while $\omega_4 < 0$ (clockwise): $B$ is slowing down.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 7a, on the linkage, reading the senses."}, "image": {"alt": "The linkage with the tangential acceleration of B at B, and curved arrows for the senses of alpha4 and omega4 about O4."}}
show("7a")

# %% [markdown]
# The same for the coupler. $\mathbf{A}^t_{BA}$, which is $b\,\alpha_3\,je^{j\theta_3}$, is
# the tangential acceleration of $B$ turning about $A$; placed at $B$ it points the way
# $\alpha_3$ turns $AB$ about $A$. Link 3's $\alpha_3$ is a free vector: the same at every
# point of the link.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 7b, on the linkage, reading the senses."}, "image": {"alt": "The linkage with the tangential acceleration difference of B relative to A, and curved arrows for the senses of alpha3 and omega3."}}
show("7b")

# %% [markdown]
# Steps 1 to 7 in numbers:

# %% tags=["remove-input"] jupyter={"source_hidden": true}
walk.table("acceleration")

# %% [markdown]
# Both angular accelerations are counter-clockwise (positive), although $\alpha_2$ is
# clockwise: the input's acceleration is tiny here, and what accelerates links 3 and 4 is
# mostly the *changing direction* of the crank pin's velocity ($a\omega_2^2$).
#
# **Step 8: any other point.** With $\alpha_3$ and $\omega_3$ known, a coupler point $P$ (the
# chapter's $C$; here $p$ = 3 in from $A$, 30° off the line $AB$) follows from eq. 7.4 with
# $A$ as reference: $\mathbf{A}_P = \mathbf{A}_A + \mathbf{A}^n_{PA} + \mathbf{A}^t_{PA}$,
# with $A^n_{PA} = p\,\omega_3^2$ toward $A$ and $A^t_{PA} = p\,\alpha_3$ perpendicular to
# $PA$ (the chapter's equations (e) to (g)). All three are fully known: no construction lines,
# and the same scale as the polygon of step 6.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 8a, on the polygon of P (Figure 7-4c)."}, "image": {"alt": "Polygon of P: A_A from the pole."}}
show("8a")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 8b, on the polygon of P (Figure 7-4c)."}, "image": {"alt": "Polygon of P: the normal acceleration difference of P relative to A at the tip of A_A."}}
show("8b")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 8c, on the polygon of P (Figure 7-4c)."}, "image": {"alt": "Polygon of P: the tangential acceleration difference of P relative to A added."}}
show("8c")

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 8d, on the polygon of P (Figure 7-4c)."}, "image": {"alt": "The polygon of P, Figure 7-4c: A_P from the pole closes it."}}
show("8d")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
walk.table("point")

# %% [markdown]
# Last, the chapter's Figure 7-4d: the answers drawn back at their points on the linkage,
# at the linkage's scale.

# %% tags=["remove-input", "step-figure"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Step 8e, on the linkage (Figure 7-4d)."}, "image": {"alt": "The linkage with the accelerations of A, B and P drawn at their points: Figure 7-4d."}}
show("8e")

# %% [markdown]
# ### The drawing against the analytic answer
#
# Read off the finished drawing, the construction's answers agree with the closed forms
# that notebook 3 derives (`FourBar.solve`) to the last digits a computer carries: the
# drawing is exact geometry; only a ruler makes it approximate.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
exact = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
    theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2", p="3 in", delta3="30 deg"
)
compare = [
    (r"$\omega_3$", v["omega3"], exact.omega3.to("rad/s").magnitude, " rad/s"),
    (r"$\omega_4$", v["omega4"], exact.omega4.to("rad/s").magnitude, " rad/s"),
    (r"$\alpha_3$", v["alpha3"], exact.alpha3.to("rad/s^2").magnitude, " rad/s²"),
    (r"$\alpha_4$", v["alpha4"], exact.alpha4.to("rad/s^2").magnitude, " rad/s²"),
]
for name, key, q in (
    (r"\mathbf{A}_A", "A_A", exact.A_A),
    (r"\mathbf{A}_B", "A_B", exact.A_B),
    (r"\mathbf{A}_P", "A_P", exact.A_P),
):
    z = complex(q.to("in/s^2").magnitude)
    compare += [
        (f"$\\lvert {name}\\rvert$", abs(v[key]) / IN, abs(z), " in/s²"),
        (f"angle of ${name}$", deg(v[key]), deg(z), "°"),
    ]


def relative(d, e):
    """A relative difference as a power of ten, in words when it is none."""
    r = abs(d - e) / abs(e)
    if r == 0:
        return "none"
    m, x = f"{r:.0e}".split("e")
    return f"${m} \\times 10^{{{int(x)}}}$"


rows = [f"| {name} | {d:.6g}{u} | {e:.6g}{u} | {relative(d, e)} |" for name, d, e, u in compare]
Markdown(
    "| quantity | read off the drawing | analytic (notebook 3) | relative difference |\n"
    "|---|---|---|---|\n" + "\n".join(rows)
)

# %% [markdown]
# On paper the ruler sets the accuracy. At the suggested 1 in for 50 in/s$^2$, a length read
# to half a millimetre is about 1 in/s$^2$ out; divided by the link lengths that is
# 0.11 rad/s$^2$ on $\alpha_4$ (0.3 %) but 0.16 rad/s$^2$ on $\alpha_3$ (1.9 %), because
# $\mathbf{A}^t_{BA}$ is short. A short vector in a polygon is where a drawing loses its
# precision: draw those parts at a larger scale, as the chapter does for $\mathbf{A}_A$.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
err = 0.5 / 25.4 * 50  # in/s^2: half a millimetre at 1 in for 50 in/s^2
stated(err, "1", sig=1), stated(err / 9, "0.11"), stated(err / 6, "0.16")
stated(100 * err / 9 / v["alpha4"], "0.3"), stated(100 * err / 6 / v["alpha3"], "1.9")
assert all(abs(d - e) <= 1e-9 * max(abs(e), 1.0) for _, d, e, _ in compare)
stated(abs(v["A_A_n"]) / IN, "200"), stated(abs(v["A_A_t"]) / IN, "10")
stated(abs(v["A_A_n"] / v["A_A_t"]), "20")
assert v["alpha3"] > 0 and v["alpha4"] > 0 and v["omega4"] < 0 and EXAMPLE_7_1["alpha2"][0] == "-"

# %% [markdown]
# ### When the construction fails
#
# The lines parallel to $pp$ and $qq$ must cross. They are perpendicular to $O_4B$ and $AB$,
# so they are parallel exactly when links 3 and 4 lie on one line: a **toggle** position. A
# non-Grashof linkage ($a$ = 5, $b$ = 5, $c$ = 5, $d$ = 7 in) reaches one where $|O_4A| =
# b + c$; just beyond it the arcs that locate $B$ no longer meet and the linkage cannot be
# assembled at all.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
a, b, c, d = (x * IN for x in (5, 5, 5, 7))  # SI, as accelab.solver.graphical takes them
toggle = math.acos((a * a + d * d - (b + c) ** 2) / (2 * a * d))
lines = []
for t2 in (toggle - 0.05, toggle, toggle + 0.05):
    try:
        g = construct("fourbar", a=a, b=b, c=c, d=d, theta2=t2, omega2=10.0, alpha2=0.0)
        said = f"$\\alpha_4$ = {g.values['alpha4']:.5g} rad/s²"
    except (Singular, NotAssemblable) as exc:
        said = f"refused (`{type(exc).__name__}`): {str(exc).split(':')[0]}"
    lines.append(f"| {math.degrees(t2):.4f}° | {said} |")
Markdown(
    f"The toggle is at $\\theta_2$ = {math.degrees(toggle):.4f}°. With $\\omega_2$ = 10 rad/s "
    "and $\\alpha_2 = 0$:\n\n| $\\theta_2$ | the construction |\n|---|---|\n" + "\n".join(lines)
)

# %% [markdown]
# Near the toggle $\alpha_4$ grows without bound: the two construction lines meet at a
# shallower and shallower angle, far from the pole. At the toggle itself the construction
# refuses to return a number rather than return one it cannot vouch for.

# %% [markdown]
# ## Explore: a new drawing for every position
#
# The graphical method's cost is that nothing carries over from one crank angle to the
# next: each position needs its own polygon. Move $\theta_2$ and watch the acceleration
# polygon of Example 7-1 change shape and size: blue normal components, red dashed tangential
# ones, black $\mathbf{A}_A$ and $\mathbf{A}_B$ from the pole $o_A$. The positions are all drawn
# in one frame, at one scale (in a live notebook the frame grows with $\omega_2^2$ when you
# move $\omega_2$, so that the polygon keeps its size on the screen).


# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "The graphical construction at several crank angles, all at the same scale: the polygon changes shape over the cycle."}, "image": {"alt": "Small multiples of the fourbar's acceleration polygon at several crank angles."}}
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
# usually without any visible sign that something is off. A term moved from the left side of
# the equation to the right changes its sense.
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
# $\mathbf{A}^t_{BA}$ means $\alpha_3 > 0$. The table of step 7 says $\alpha_3 = +8.769$
# rad/s$^2$.
#
# </details>
#
# **4.** $\alpha_4$ is positive here. Is $B$ speeding up?
#
# <details><summary>Answer</summary>
#
# No. $\omega_4 = -3.461$ rad/s is clockwise and $\alpha_4 = +39.43$ rad/s$^2$
# counter-clockwise: the rocker's angular acceleration opposes its angular velocity, so $B$ is
# slowing down. A point speeds up when $\alpha$ and $\omega$ have the same sign.
#
# </details>
#
# **5.** To find the acceleration of a point on the rocker (link 4), which reference point
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
stated(v["alpha3"], "8.769"), stated(v["omega4"], "-3.461"), stated(v["alpha4"], "39.43")
assert 60 < math.degrees(v["theta3"]) < 120 and v["A_BA_t"].real < 0  # B above A, leftward

# %% [markdown]
# ## Further problems
#
# In the style of the chapter's problem set: draw the polygons yourself (on paper or with
# `construct_case` and `by_hand`), then compare. The answers are folded.
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
# Reading a construction is not doing one. The **polygon builder** is a drawing board for the
# construction above: the linkage drawn to scale beside a polygon canvas whose scale is stated
# on it. Build the velocity polygon first, then the acceleration polygon:
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
# **Show the next step**.
#
# **One difference from step 6.** The builder lays each side of eq. 7.4 from the pole as it
# stands, without moving $\mathbf{A}^n_B$ across: on the right, $\mathbf{A}^t_A$,
# $\mathbf{A}^n_A$ and $\mathbf{A}^n_{BA}$ tip to tail, then the line of
# $\mathbf{A}^t_{BA}$ ($qq$) through the end; on the left, $\mathbf{A}^n_B$ from the pole,
# then the line of $\mathbf{A}^t_B$ ($pp$) through its tip. The lines cross at the tip of
# $\mathbf{A}_B$ itself, not of $\mathbf{A}^t_B$: it is the other corner of step 6j's
# parallelogram, and every value read off is the same.
#
# The cell below (its code folded) is the builder of Example 7-1, made by
# `PolygonBuilder.from_case(EXAMPLE_7_1)`: `from_case` makes one for any fourbar, slider-crank
# or inverted slider-crank case. On this web page the builder cannot run, so the figure shows
# the finished construction; download the notebook, or write the course with
# `accelab course --out DIR`, to build it yourself.

# %% tags=["hide-input"] jupyter={"source_hidden": true} mystnb={"figure": {"caption": "Example 7-1 in the polygon builder: the finished velocity and acceleration polygons, one scale each, both sides of eq. 7.4 laid from the pole. In a live notebook this cell is the builder itself, empty, and each step is checked as it is drawn."}}
board = PolygonBuilder.from_case(EXAMPLE_7_1, title="Example 7-1: your construction")
show_builder(
    board,
    alt="The velocity and acceleration polygons of Example 7-1 as the polygon builder draws "
    "a finished construction, each on a grid with its scale.",
)

# %% [markdown]
# **What the builder says** when a step breaks a rule: the classic mistakes, made on
# Example 7-1, and the builder's own words for each.

# %% tags=["hide-input"] jupyter={"source_hidden": true}
classic_mistakes(EXAMPLE_7_1)

# %% [markdown]
# And on an inverted slider-crank, whose polygon needs the Coriolis component
# $2\omega_4 V_{slip}$ of notebook 5:

# %% tags=["hide-input"] jupyter={"source_hidden": true}
classic_mistakes(INVERTED_SLIDER_CRANK)

# %% [markdown]
# ### One of each kind, to practise
#
# Fresh problems of the three graded exercise families whose answer is a construction:
# `polygon_fourbar`, `polygon_slidercrank` and `polygon_coriolis` (the inverted slider-crank,
# with its Coriolis component). Each run of a cell below draws a new position, never one of a
# graded assignment's, and shows it with its builder, which checks each step. In a graded
# assignment the same builder records your construction without checking it; the construction
# is saved with the notebook and judged step by step when the assignment is graded, with
# partial credit.
#
# (The web page leaves these fresh problems out: there is nothing to draw in there. It shows
# the problems of seed 3 of the slider-crank and the inverted slider-crank instead, below.)

# %% tags=["remove-output"]
practice("polygon_fourbar").builder().show()

# %% tags=["remove-output"]
practice("polygon_slidercrank").builder().show()

# %% tags=["remove-output"]
practice("polygon_coriolis").builder().show()

# %% [markdown]
# **Two constructions to try on this page**, the slider-crank and the inverted slider-crank
# of seed 3: draw them on paper (or in the notebook, in
# `practice("polygon_slidercrank", seed=3).builder()`), then unfold the finished
# constructions.

# %%
example = practice("polygon_slidercrank", seed=3)

# %% tags=["hide-output"]
example.answers()

# %%
example = practice("polygon_coriolis", seed=3)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# ## Practice
#
# Fourbar problems with instant feedback, for self-study (not graded, and never one of a graded
# assignment's): each run of the next cell draws a fresh linkage and input (or give a seed to
# come back to one). Solve it graphically, with `construct_case` and the polygon, or by the
# equations of notebook 3, then hand each answer to `mine.check`, which says at once whether it is
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
mine = practice("fourbar")  # a fresh problem, shown by this cell

# %%
# your answers to the problem above, e.g.:  mine.check("alpha3", Q_(12.5, "rad/s^2"))

# %% [markdown]
# **A problem to try on this page**, seed 3: work it out on paper (or with the
# solver), then unfold the answers.

# %%
example = practice("fourbar", seed=3)

# %% tags=["hide-output"]
example.answers()

# %% [markdown]
# **What a check looks like**, on the problem of seed 3, solved by the graphical construction:

# %%
example = practice("fourbar", seed=3, show=False)
g = dict(example.problem.given, mechanism="fourbar")
drawn = construct_case(g).values
assert example.check("alpha4", Q_(drawn["alpha4"], "rad/s^2"))  # right
assert not example.check("alpha4", Q_(-drawn["alpha4"], "rad/s^2"))  # the sense read the wrong way
assert not example.check("alpha4", Q_(drawn["alpha4"], "rad/s"))  # not an angular acceleration

# %% [markdown]
# ## Common mistakes
#
# - **Skipping the velocity analysis.** No $\omega_3$, $\omega_4$, no normal components, no
#   polygon.
# - **Normal components pointing outward.** A normal component always points from the moving
#   point toward its centre of rotation relative to the reference: $\mathbf{A}^n_{BA}$ from $B$
#   toward $A$, not from $A$ toward $B$.
# - **Adding a term from the left side of eq. 7.4.** $\mathbf{A}^n_B$ is subtracted in the
#   polygon (step 6e draws $-\mathbf{A}^n_B$); $\mathbf{A}_B$ is $\mathbf{A}^t_B +
#   \mathbf{A}^n_B$, from the pole.
# - **Taking a reference point on another link.** For the coupler point $P$, use $A$ or $B$
#   (on link 3), never $O_2$: the Case 1 rules hold only within one rigid body.
# - **Two scales on one drawing.** Lengths and accelerations each need one scale, written on
#   the drawing, and the polygon must use a single acceleration scale throughout.
# - **Reading the sense of $\alpha$ from the shape of the polygon.** Read it from the
#   direction of the tangential vector relative to its radius ($je^{j\theta}$).
# - **Reading "speeding up" from the sign of $\alpha$.** $\alpha > 0$ means counter-clockwise,
#   not faster: a link speeds up only when $\alpha$ and $\omega$ have the same sense (the
#   rocker of Example 7-1 is slowing, with $\alpha_4 > 0$ and $\omega_4 < 0$).
#
# [Next: 3. The analytic fourbar](03_analytic_fourbar.ipynb)
