"""Example 7-1 done by hand: the fourbar's construction one stroke at a time
(Chapter 7, section 7.2, Figure 7-4), for a page a student can redo on paper.

:func:`by_hand` turns a finished fourbar :class:`~.construction.Construction`
into a :class:`Walk`: the same geometry, laid out as the chapter draws it and
cut into strokes that each add one vector or one construction line:

========  ==============  =====================================================
labels    diagram         what is drawn
========  ==============  =====================================================
P         linkage         the linkage to scale (arcs b about A and c about O4)
V1..V5    velocity        V_A, the two direction lines, V_B, V_BA (eq. 6.5)
2a..5b    linkage         A_A^n, A_A^t at A; pp; A_B^n at B; A_BA^n; qq
6a..6k    acceleration    the polygon of eq. 7.4 from the pole: A_A^t, A_A^n,
                          A_A, A_BA^n, then *minus* A_B^n, the line parallel
                          to qq through its tip and the one parallel to pp
                          through the pole; where they cross, A_BA^t and A_B^t;
                          A_B^n again at the tip of A_B^t, and A_B
7a, 7b    reading         A_B^t and A_BA^t at B with the senses of alpha4,
                          alpha3 (and of omega4, omega3) they give
8a..8e    point, results  A_P = A_A + A_PA (Figure 7-4c), then the answers at
                          their points on the linkage (Figure 7-4d)
========  ==============  =====================================================

Every figure of a walk (:func:`draw_stroke`) keeps the frame and the scale of
its diagram from the first stroke to the last, states its one scale with a
bar, and lays a pale band under the stroke it adds. The acceleration polygon
and the polygon of P share one scale; the vectors drawn on the linkage have
theirs (the crank's own A_A^n drawn three quarters of the crank long). The
step tables (:meth:`Walk.table`) give every vector's size and direction in the
drawing's units, what it is computed from or that it is measured.

The crossings are found again here with the drafting operations of
:mod:`.geometry`; nothing asks the analytic solvers.
"""

import cmath
import math
from dataclasses import dataclass, field

from . import style
from .construction import Arrow, Construction, Line, Step
from .geometry import intersect_lines

__all__ = ["by_hand", "Walk", "Stroke", "draw_stroke", "case_table", "Markdown"]

#: width of a walk's figures [in]: saved "tight" (Jupyter pads 0.1 in all round) at
#: 100 dpi, 500 px, which a phone shows 342 CSS px wide: text of 10 pt is 9.5 CSS px high
FIGURE_WIDTH = 4.8
#: how long the crank's normal component A_A^n is drawn on the linkage, as a
#: fraction of the crank: it lies beside the crank and stops short of O2
CRANK_FRACTION = 0.75

_V = r"\mathbf{V}"
_A = r"\mathbf{A}"


class Markdown(str):
    """Text that Jupyter (and the site's MyST-NB) shows as rendered Markdown."""

    def _repr_markdown_(self):
        return str(self)


@dataclass
class Stroke(Step):
    """One stroke of a walk: a :class:`~.construction.Step` that adds one vector
    or one line to ``diagram``. ``title`` says what in matplotlib mathtext
    (which MyST's math reads as well); ``quantity`` is its row of the step table
    (see :meth:`Walk.table`); ``turns`` are curved arrows ``(point, sense,
    label, kind)`` the reading strokes draw about a point."""

    diagram: str = ""
    title: str = ""
    quantity: dict | None = None
    turns: list = field(default_factory=list)
    tags: dict = field(default_factory=dict)  # line name -> its label (velocity lines)


@dataclass
class Walk(Construction):
    """A construction as the chapter draws it by hand, one :class:`Stroke` per
    step (see the module docstring). ``scale`` is the drawing scale of the
    vectors on the linkage [drawing length per acceleration, in the drawing's
    units]; ``source`` the construction it was made from."""

    source: Construction | None = None
    scale: float | None = None
    angles: dict = field(default_factory=dict)  # theta2 etc. [rad], for the position figure

    @property
    def labels(self):
        """The strokes' labels, in order ("P", "V1", ..., "8e")."""
        return [s.label for s in self.steps]

    def stroke(self, label):
        """The stroke of this label."""
        return self.steps[self.index(label) - 1]

    def draw(self, label, **kw):
        """The figure of the stroke ``label`` (see :func:`draw_stroke`)."""
        return draw_stroke(self, label, **kw)

    def table(self, phase):
        """The step table of ``phase`` (``"velocity"``, ``"acceleration"`` or
        ``"point"``) as Markdown, in the drawing's units: per vector its step,
        size and direction (angle from +x, counter-clockwise), what its size
        is computed from or that it is measured on the drawing; then the
        angular rates the measured ones give."""
        return Markdown(_table(self, phase))


# ---------------------------------------------------------------- the walk
def by_hand(con):
    """The walk of a fourbar construction (see the module docstring).

    Parameters
    ----------
    con : Construction
        A finished fourbar construction (:func:`accelab.solver.graphical.construct_case`).

    Returns
    -------
    Walk
    """
    if con.mechanism != "fourbar":
        raise ValueError(
            f"by_hand draws the fourbar of Example 7-1 step by step; a {con.mechanism} "
            "construction is drawn whole with draw_linkage and draw_polygons"
        )
    from .draw import units_of

    v = con.values
    pts = con.linkage.points
    O2, A, B, O4 = pts["O2"], pts["A"], pts["B"], pts["O4"]
    R_BA, R_BO4 = B - A, B - O4
    walk = Walk(
        "fourbar",
        con.linkage,
        [],
        dict(v),
        con.circuit,
        title=con.title,
        units=con.units,
        source=con,
    )
    a = abs(A - O2)
    walk.angles = {"theta2": cmath.phase(A - O2), "theta1": cmath.phase(O4 - O2)}

    def add(label, phase, diagram, title, item=None, quantity=None, **extra):
        st = Stroke(label, phase, title, diagram=diagram, title=title, quantity=quantity, **extra)
        if isinstance(item, Arrow):
            st.arrows.append(item)
        elif isinstance(item, Line):
            st.lines.append(item)
        walk.steps.append(st)
        return st

    def q(symbol, value, quantity, size, direction, measured=False):
        return dict(
            symbol=symbol,
            value=value,
            kind=quantity,
            size=size,
            direction=direction,
            measured=measured,
        )

    # -- position
    add(
        "P",
        "position",
        "linkage",
        r"The linkage to scale: arcs $b$ about $A$ and $c$ about $O_4$ meet at $B$",
    )

    # -- velocity polygon: V_B = V_A + V_BA (eq. 6.5)
    V_A = v["V_A"]
    add(
        "V1",
        "velocity",
        "velocity",
        rf"${_V}_A = a\omega_2$ from the pole $o_V$, perpendicular to $O_2A$",
        Arrow(rf"{_V}_{{A}}", 0j, V_A, "velocity", "velocity"),
        q(
            rf"${_V}_A$",
            V_A,
            "velocity",
            r"$a\omega_2$",
            r"perpendicular to $O_2A$, sense of $\omega_2$",
        ),
    )
    add(
        "V2",
        "velocity",
        "velocity",
        rf"The direction of ${_V}_B$: a line through the pole perpendicular to $O_4B$",
        Line("", 0j, 1j * R_BO4, "velocity"),
        tags={"": r"$\perp O_4B$"},
    )
    add(
        "V3",
        "velocity",
        "velocity",
        rf"The direction of ${_V}_{{BA}}$: a line through the tip of ${_V}_A$ "
        r"perpendicular to $AB$",
        Line("", V_A, 1j * R_BA, "velocity"),
        tags={"": r"$\perp AB$"},
    )
    V_B, omega4, omega3 = intersect_lines(
        0j, 1j * R_BO4, V_A, 1j * R_BA, "the velocity lines of B (perpendicular to O4B and AB)"
    )
    add(
        "V4",
        "velocity",
        "velocity",
        rf"${_V}_B$: from the pole to where the two lines cross",
        Arrow(rf"{_V}_{{B}}", 0j, V_B, "resultant", "velocity"),
        q(rf"${_V}_B$", V_B, "velocity", "", r"pole to the crossing", True),
    )
    add(
        "V5",
        "velocity",
        "velocity",
        rf"${_V}_{{BA}}$: from the tip of ${_V}_A$ to the crossing",
        Arrow(rf"{_V}_{{BA}}", V_A, V_B - V_A, "velocity", "velocity"),
        q(rf"${_V}_{{BA}}$", V_B - V_A, "velocity", "", rf"tip of ${_V}_A$ to the crossing", True),
    )
    walk.values.update(omega3=omega3, omega4=omega4, V_B=V_B)

    # -- steps 1-5 on the linkage (Figure 7-4a)
    A_A_n, A_A_t = v["A_A_n"], v["A_A_t"]
    A_B_n = -(omega4**2) * R_BO4
    A_BA_n = -(omega3**2) * R_BA
    add(
        "2a",
        "acceleration",
        "linkage",
        rf"${_A}^n_A = a\omega_2^2$ at $A$, toward $O_2$",
        Arrow(rf"{_A}_{{A}}^{{n}}", A, A_A_n, "normal", "linkage"),
        q(rf"${_A}^n_A$", A_A_n, "acceleration", r"$a\omega_2^2$", r"from $A$ toward $O_2$"),
    )
    add(
        "2b",
        "acceleration",
        "linkage",
        rf"${_A}^t_A = a\alpha_2$ at $A$, perpendicular to $O_2A$, in the sense of $\alpha_2$",
        Arrow(rf"{_A}_{{A}}^{{t}}", A, A_A_t, "tangential", "linkage"),
        q(
            rf"${_A}^t_A$",
            A_A_t,
            "acceleration",
            r"$a\lvert\alpha_2\rvert$",
            r"perpendicular to $O_2A$, sense of $\alpha_2$",
        ),
    )
    add(
        "3",
        "acceleration",
        "linkage",
        rf"Line $pp$ through $B$ perpendicular to $O_4B$: the direction of ${_A}^t_B$",
        Line("pp", B, 1j * R_BO4, "linkage"),
    )
    add(
        "4",
        "acceleration",
        "linkage",
        rf"${_A}^n_B = c\omega_4^2$ at $B$, toward $O_4$",
        Arrow(rf"{_A}_{{B}}^{{n}}", B, A_B_n, "normal", "linkage"),
        q(rf"${_A}^n_B$", A_B_n, "acceleration", r"$c\omega_4^2$", r"from $B$ toward $O_4$"),
    )
    add(
        "5a",
        "acceleration",
        "linkage",
        rf"${_A}^n_{{BA}} = b\omega_3^2$ at $B$, toward $A$",
        Arrow(rf"{_A}_{{BA}}^{{n}}", B, A_BA_n, "normal", "linkage"),
        q(rf"${_A}^n_{{BA}}$", A_BA_n, "acceleration", r"$b\omega_3^2$", r"from $B$ toward $A$"),
    )
    add(
        "5b",
        "acceleration",
        "linkage",
        rf"Line $qq$ through $B$ perpendicular to $AB$: the direction of ${_A}^t_{{BA}}$",
        Line("qq", B, 1j * R_BA, "linkage"),
    )

    # -- step 6: the polygon (Figure 7-4b), tip to tail from the pole o_A
    A_A = A_A_t + A_A_n
    T = A_A + A_BA_n - A_B_n  # the tip of -A_B^n
    X, alpha4, alpha3 = intersect_lines(
        0j, 1j * R_BO4, T, 1j * R_BA, "the lines parallel to pp and qq (links 3 and 4 in line)"
    )
    A_B_t, A_BA_t = X, X - T
    A_B = A_B_t + A_B_n
    add(
        "6a",
        "acceleration",
        "acceleration",
        rf"${_A}^t_A$ from the pole $o_A$",
        Arrow(rf"{_A}_{{A}}^{{t}}", 0j, A_A_t, "tangential", "acceleration"),
    )
    add(
        "6b",
        "acceleration",
        "acceleration",
        rf"${_A}^n_A$ at the tip of ${_A}^t_A$",
        Arrow(rf"{_A}_{{A}}^{{n}}", A_A_t, A_A_n, "normal", "acceleration"),
    )
    add(
        "6c",
        "acceleration",
        "acceleration",
        rf"Their sum ${_A}_A$, from the pole",
        Arrow(rf"{_A}_{{A}}", 0j, A_A, "resultant", "acceleration"),
        q(rf"${_A}_A$", A_A, "acceleration", "", rf"pole to the tip of ${_A}^n_A$", True),
    )
    add(
        "6d",
        "acceleration",
        "acceleration",
        rf"${_A}^n_{{BA}}$ at the tip of ${_A}_A$",
        Arrow(rf"{_A}_{{BA}}^{{n}}", A_A, A_BA_n, "normal", "acceleration"),
    )
    add(
        "6e",
        "acceleration",
        "acceleration",
        rf"$-{_A}^n_B$ at the tip of ${_A}^n_{{BA}}$",
        Arrow(rf"-{_A}_{{B}}^{{n}}", A_A + A_BA_n, -A_B_n, "normal", "acceleration"),
    )
    add(
        "6f",
        "acceleration",
        "acceleration",
        rf"A line parallel to $qq$ through the tip of $-{_A}^n_B$",
        Line("qq", T, 1j * R_BA, "acceleration"),
    )
    add(
        "6g",
        "acceleration",
        "acceleration",
        r"A line parallel to $pp$ through the pole",
        Line("pp", 0j, 1j * R_BO4, "acceleration"),
    )
    add(
        "6h",
        "acceleration",
        "acceleration",
        rf"${_A}^t_{{BA}}$: from the tip of $-{_A}^n_B$ to the crossing",
        Arrow(rf"{_A}_{{BA}}^{{t}}", T, A_BA_t, "tangential", "acceleration"),
        q(
            rf"${_A}^t_{{BA}}$",
            A_BA_t,
            "acceleration",
            "",
            rf"along $qq$, tip of $-{_A}^n_B$ to the crossing",
            True,
        ),
    )
    add(
        "6i",
        "acceleration",
        "acceleration",
        rf"${_A}^t_B$: from the pole to the crossing",
        Arrow(rf"{_A}_{{B}}^{{t}}", 0j, A_B_t, "tangential", "acceleration"),
        q(rf"${_A}^t_B$", A_B_t, "acceleration", "", r"along $pp$, pole to the crossing", True),
    )
    add(
        "6j",
        "acceleration",
        "acceleration",
        rf"${_A}^n_B$ again, now at the tip of ${_A}^t_B$",
        Arrow(rf"{_A}_{{B}}^{{n}}", A_B_t, A_B_n, "normal", "acceleration"),
    )
    add(
        "6k",
        "acceleration",
        "acceleration",
        rf"${_A}_B = {_A}^t_B + {_A}^n_B$, from the pole",
        Arrow(rf"{_A}_{{B}}", 0j, A_B, "resultant", "acceleration"),
        q(rf"${_A}_B$", A_B, "acceleration", "", rf"pole to the tip of ${_A}^n_B$", True),
    )
    walk.values.update(alpha3=alpha3, alpha4=alpha4, A_A=A_A, A_B=A_B, A_B_t=A_B_t, A_BA_t=A_BA_t)

    # -- step 7: the senses, read at their points
    add(
        "7a",
        "acceleration",
        "reading",
        rf"${_A}^t_B$ at $B$: $\alpha_4$ {_sense(alpha4)}, "
        + _against(alpha4, omega4, r"\omega_4", "$B$"),
        Arrow(rf"{_A}_{{B}}^{{t}}", B, A_B_t, "tangential", "reading"),
        turns=[
            (O4, R_BO4, omega4, r"$\omega_4$", "velocity"),
            (O4, R_BO4, alpha4, r"$\alpha_4$", "tangential"),
        ],
    )
    add(
        "7b",
        "acceleration",
        "reading",
        rf"${_A}^t_{{BA}}$ at $B$, about $A$: $\alpha_3$ {_sense(alpha3)}, "
        + _against(alpha3, omega3, r"\omega_3", "link 3"),
        Arrow(rf"{_A}_{{BA}}^{{t}}", B, A_BA_t, "tangential", "reading"),
        turns=[
            (A, R_BA, omega3, r"$\omega_3$", "velocity"),
            (A, R_BA, alpha3, r"$\alpha_3$", "tangential"),
        ],
    )

    # -- step 8: a coupler point (Figure 7-4c), and the answers on the linkage (7-4d)
    if "P" in pts:
        P = pts["P"]
        R_PA = P - A
        A_PA_n = -(omega3**2) * R_PA
        A_PA_t = alpha3 * 1j * R_PA
        A_P = A_A + A_PA_n + A_PA_t
        add(
            "8a",
            "acceleration",
            "point",
            rf"${_A}_A$ from the pole, as in step 6",
            Arrow(rf"{_A}_{{A}}", 0j, A_A, "resultant", "point"),
        )
        add(
            "8b",
            "acceleration",
            "point",
            rf"${_A}^n_{{PA}} = p\omega_3^2$ at its tip, along $PA$ toward $A$",
            Arrow(rf"{_A}_{{PA}}^{{n}}", A_A, A_PA_n, "normal", "point"),
            q(
                rf"${_A}^n_{{PA}}$",
                A_PA_n,
                "acceleration",
                r"$p\omega_3^2$",
                r"from $P$ toward $A$",
            ),
        )
        add(
            "8c",
            "acceleration",
            "point",
            rf"${_A}^t_{{PA}} = p\alpha_3$ at its tip, perpendicular to $PA$",
            Arrow(rf"{_A}_{{PA}}^{{t}}", A_A + A_PA_n, A_PA_t, "tangential", "point"),
            q(
                rf"${_A}^t_{{PA}}$",
                A_PA_t,
                "acceleration",
                r"$p\lvert\alpha_3\rvert$",
                r"perpendicular to $PA$, sense of $\alpha_3$",
            ),
        )
        add(
            "8d",
            "acceleration",
            "point",
            rf"${_A}_P$: from the pole to the tip of ${_A}^t_{{PA}}$",
            Arrow(rf"{_A}_{{P}}", 0j, A_P, "resultant", "point"),
            q(
                rf"${_A}_P$",
                A_P,
                "acceleration",
                "",
                rf"pole to the tip of ${_A}^t_{{PA}}$",
                True,
            ),
        )
        walk.values.update(A_P=A_P)
    results = add(
        "8e",
        "acceleration",
        "results",
        rf"The answers at their points: ${_A}_A$, ${_A}_B$"
        + (rf", ${_A}_P$" if "P" in pts else ""),
    )
    results.arrows += [
        Arrow(rf"{_A}_{{A}}", A, A_A, "resultant", "results"),
        Arrow(rf"{_A}_{{B}}", B, A_B, "resultant", "results"),
    ]
    if "P" in pts:
        results.arrows.append(
            Arrow(rf"{_A}_{{P}}", pts["P"], walk.values["A_P"], "resultant", "results")
        )

    u = units_of(con)
    lf, af = u["length"][1], u["acceleration"][1]
    if abs(A_A_n) > 0:
        walk.scale = CRANK_FRACTION * a * lf / (abs(A_A_n) * af)
    return walk


def _against(alpha, omega, name, what):
    """Whether alpha speeds the turning up or slows it down, in words."""
    if alpha * omega < 0:
        return f"against ${name}$ ({_sense(omega)}): {what} is slowing"
    if alpha * omega > 0:
        return f"with ${name}$ ({_sense(omega)}): {what} is speeding up"
    return f"${name}$ {_sense(omega)}"


def _sense(x):
    return "counter-clockwise" if x > 0 else "clockwise" if x < 0 else "(zero)"


# ---------------------------------------------------------------- tables
def _unit_text(walk, kind):
    from .draw import units_of

    name, factor = units_of(walk)[kind]
    return name.replace("$^2$", "²"), factor


def _angle(z):
    return math.degrees(math.atan2(z.imag, z.real))


def _table(walk, phase):
    diagrams = {
        "velocity": ("velocity",),
        "acceleration": ("linkage", "acceleration"),
        "point": ("point",),
    }
    if phase not in diagrams:
        raise ValueError(f"phase must be one of {', '.join(diagrams)} (got {phase!r})")
    rows = []
    for s in walk.steps:
        if s.diagram in diagrams[phase] and s.quantity:
            qd = s.quantity
            unit, factor = _unit_text(walk, qd["kind"])
            how = "**measured**" if qd["measured"] else qd["size"]
            rows.append(
                f"| {s.label} | {qd['symbol']} | {abs(qd['value']) * factor:.4g} {unit} "
                f"| {_angle(qd['value']):.1f}° | {how} | {qd['direction']} |"
            )
    head = (
        "| step | vector | size | angle from $+x$ | size from | direction |\n"
        "|---|---|---|---|---|---|\n"
    )
    text = head + "\n".join(rows)
    lengths = {k: abs(z) for k, z in _lengths(walk).items()}
    v = walk.values
    if phase == "velocity":
        text += (
            "\n\nMeasured, then divided by the link lengths ($V = r\\omega$): "
            + _rate(
                r"\omega_4", r"V_B", "c", abs(v["V_B"]), lengths["c"], v["omega4"], walk, "rad/s"
            )
            + "; "
            + _rate(
                r"\omega_3",
                r"V_{BA}",
                "b",
                abs(v["V_B"] - v["V_A"]),
                lengths["b"],
                v["omega3"],
                walk,
                "rad/s",
            )
            + "."
        )
    elif phase == "acceleration":
        text += (
            "\n\nMeasured along $pp$ and $qq$, then divided by the link lengths (eq. 7.6): "
            + _rate(
                r"\alpha_4",
                r"A^t_B",
                "c",
                abs(v["A_B_t"]),
                lengths["c"],
                v["alpha4"],
                walk,
                "rad/s²",
            )
            + "; "
            + _rate(
                r"\alpha_3",
                r"A^t_{BA}",
                "b",
                abs(v["A_BA_t"]),
                lengths["b"],
                v["alpha3"],
                walk,
                "rad/s²",
            )
            + ". The signs are the senses read in step 7."
        )
    return text


def _lengths(walk):
    p = walk.linkage.points
    return {"a": p["A"] - p["O2"], "b": p["B"] - p["A"], "c": p["B"] - p["O4"]}


def _rate(symbol, of, link, size, length, value, walk, unit):
    kind = "velocity" if "omega" in symbol else "acceleration"
    uname, uf = _unit_text(walk, kind)
    lname = uname.split("/")[0]  # the length of the quantity's own unit: in/s / in, m/s / m
    return (
        f"${symbol} = {of}/{link}$ = {size * uf:.4g} {uname} / {length * uf:.4g} {lname} "
        f"= **{value:+.4g} {unit}** ({_sense(value)})"
    )


def case_table(case):
    """The data of a batch case (e.g. ``EXAMPLE_7_1``) as a Markdown table in
    the chapter's symbols, as a page shows it instead of the raw dictionary."""
    names = {
        "a": ("$a$", "crank $O_2A$ (link 2)"),
        "b": ("$b$", "coupler $AB$ (link 3)"),
        "c": ("$c$", "rocker $O_4B$ (link 4)"),
        "d": ("$d$", "ground $O_2O_4$ (link 1)"),
        "theta2": (r"$\theta_2$", "crank angle, from $+x$"),
        "omega2": (r"$\omega_2$", "crank angular velocity (+ counter-clockwise)"),
        "alpha2": (r"$\alpha_2$", "crank angular acceleration (+ counter-clockwise)"),
        "p": ("$p$", "coupler point $P$: distance from $A$"),
        "delta3": (r"$\delta_3$", "coupler point $P$: angle from line $AB$"),
        "circuit": ("", "circuit (branch)"),
    }
    rows = []
    for key, (sym, what) in names.items():
        if key in case:
            value = str(case[key])
            value = value.replace(" deg", "°").replace("^2", "²")
            rows.append(f"| {what} | {sym} | {value} |")
    return Markdown("| quantity | symbol | value |\n|---|---|---|\n" + "\n".join(rows))


# ---------------------------------------------------------------- figures
def _diagram_box(walk, diagram, uf):
    """(x0, x1, y0, y1) of a polygon diagram [drawing units], the same size for
    the acceleration polygon and that of P (one scale for both)."""
    from .draw import _extent

    def extent(name):
        arrows = walk.items(name)[0]
        ends = [0j] + [a.start * uf for a in arrows] + [a.tip * uf for a in arrows]
        return _extent(ends)

    names = ["acceleration", "point"] if diagram in ("acceleration", "point") else [diagram]
    names = [n for n in names if walk.items(n)[0]]
    boxes = {n: extent(n) for n in names}
    w = max(b[1] - b[0] for b in boxes.values())
    h = max(b[3] - b[2] for b in boxes.values())
    x0, x1, y0, y1 = boxes[diagram]
    m = 0.14 * max(w, h)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    return (cx - w / 2 - m, cx + w / 2 + m, cy - h / 2 - m, cy + h / 2 + m)


def _kinds(walk, diagram):
    arrows, lines, _ = walk.items(diagram)
    turns = {k for s in walk.steps if s.diagram == diagram for *_, k in s.turns}
    return {a.kind for a in arrows} | turns, bool(lines)


def draw_stroke(walk, label, width=FIGURE_WIDTH):
    """The figure of one stroke of a walk: its diagram as it stands after the
    stroke, the stroke on a pale band, the step's title above, one scale bar
    per quantity, and a legend of every kind the diagram will hold (so that
    the figures of one diagram have one frame, one scale and one size).

    Parameters
    ----------
    walk : Walk
    label : str
        The stroke ("P", "V1", ..., "6e", ..., "8e"); see ``walk.labels``.
    width : float
        Figure width [in].

    Returns
    -------
    matplotlib Figure
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from .draw import _legend, draw_linkage, draw_polygon, units_of

    st = walk.stroke(label)
    fig = plt.figure(figsize=(width, 2 * width), layout="none")
    left, right = 0.02, 0.02
    ax = fig.add_axes((left, 0.1, 1 - left - right, 0.8))
    u = units_of(walk)
    if st.diagram in ("linkage", "reading", "results"):
        draw_linkage(
            walk,
            step=label,
            ax=ax,
            scale=walk.scale,
            legend=False,
            title=False,
            diagram=st.diagram,
            lines=st.diagram == "linkage",
            symbols=st.label == "P",
            highlight=True,
        )
        if st.label == "P":
            _position_marks(ax, walk, u["length"][1])
        for centre, along, rate, text, kind in st.turns:
            _turn(ax, centre * u["length"][1], along, rate, text, kind, walk)
    else:
        quantity = "velocity" if st.diagram == "velocity" else "acceleration"
        uf = u[quantity][1]
        box = _diagram_box(walk, st.diagram, uf)
        draw_polygon(
            walk, st.diagram, step=label, ax=ax, legend=False, title=False, box=box, highlight=True
        )
        _tags(ax, walk, label, uf, box)
    # the figure's height follows the drawing's aspect; the axes keep their width
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    ax_w = (1 - left - right) * width
    ax_h = ax_w * (y1 - y0) / (x1 - x0)
    title = f"{st.label}. {st.title}"
    top = 0.62  # [in] two lines of title
    kinds, lines = _kinds(walk, st.diagram)
    n_legend = len(kinds) + (1 if lines else 0) if st.label != "P" else 0
    # below the legend, room for the site's "full size" badge (bottom right) to cover nothing
    badge = 0.3
    bottom = badge + 0.04 + 0.2 * math.ceil(n_legend / 2) if n_legend else badge
    height = ax_h + top + bottom
    fig.set_size_inches(width, height)
    ax.set_position((left, bottom / height, 1 - left - right, ax_h / height))
    fig.text(
        0.02,
        1 - 0.08 / height,
        _wrap(title, width),
        ha="left",
        va="top",
        fontsize=style.TITLE_SIZE,
    )
    # an invisible frame: a "tight" save (Jupyter's) keeps the figure's own size, badge room too
    fig.add_artist(Rectangle((0, 0), 1, 1, transform=fig.transFigure, fill=False, edgecolor="none"))
    if n_legend:
        _legend(
            fig,
            kinds,
            lines,
            loc="lower left",
            bbox_to_anchor=(0.02, badge / height),
            ncol=2,
            handlelength=2.4,
            columnspacing=1.2,
            borderaxespad=0.0,
        )
    return fig


def _wrap(text, width):
    """Wrap a mathtext title to the figure's width (a rough measure: math
    counts by the letters it shows)."""
    import re

    shown = lambda s: len(re.sub(r"\\[a-z]+|[{}$^_]", "", s))  # noqa: E731
    limit = int(width * 72 / (0.52 * style.TITLE_SIZE))
    words, lines, cur = text.split(" "), [], ""
    for w in words:
        if cur and shown(cur + " " + w) > limit:
            lines.append(cur)
            cur = w
        else:
            cur = f"{cur} {w}" if cur else w
    lines.append(cur)
    return "\n".join(lines)


def _tags(ax, walk, label, uf, box):
    """Labels of the direction lines that have no letters (the velocity polygon's)."""
    from .draw import _line_segment
    from .labels import labels_of

    n = walk.index(label)
    diagram = walk.steps[n - 1].diagram
    crossing = walk.values["V_B"] * uf  # the lines' own crossing: keep the tags off it
    for s in walk.steps[:n]:
        for ln in s.lines:
            text = s.tags.get(ln.name)
            if text and ln.diagram == diagram:
                seg = _line_segment(ln.point * uf, ln.direction, box)
                if seg is None:
                    continue
                z0, z1 = seg
                end = z1 if abs(z1 - crossing) > abs(z0 - crossing) else z0
                labels_of(ax).add_point(
                    text, end + 0.12 * ((ln.point * uf) - end), color="#555555", priority=0.8
                )


def _position_marks(ax, walk, lf):
    """The position step's drafting: the arcs that meet at B, the ground line
    and the crank angle theta2."""
    from .labels import labels_of

    pts = {k: z * lf for k, z in walk.linkage.points.items()}
    O2, A, B, O4 = pts["O2"], pts["A"], pts["B"], pts["O4"]
    grey = {"color": "#8c8c8c", "linewidth": 1.0, "zorder": 1.5}
    layer = labels_of(ax)
    for centre in (A, O4):
        r = abs(B - centre)
        mid = cmath.phase(B - centre)
        t = [mid + math.radians(x) for x in range(-14, 15)]
        zs = [centre + r * cmath.exp(1j * x) for x in t]
        ax.plot([z.real for z in zs], [z.imag for z in zs], **grey)
        for z0, z1 in zip(zs[::4], zs[4::4]):
            layer.avoid(z0, z1, width=1.0)
    ax.plot([O2.real, O4.real], [O2.imag, O4.imag], linestyle=(0, (6, 3, 1, 3)), **grey)
    layer.avoid(O2, O4, width=1.0)
    theta2 = walk.angles["theta2"]
    theta1 = walk.angles["theta1"]
    r = 0.45 * abs(A - O2)
    n = max(2, int(abs(math.degrees(theta2 - theta1)) / 3))
    zs = [O2 + r * cmath.exp(1j * (theta1 + (theta2 - theta1) * k / n)) for k in range(n + 1)]
    ax.plot([z.real for z in zs], [z.imag for z in zs], color="#333333", linewidth=1.0, zorder=4)
    for z0, z1 in zip(zs, zs[1:]):
        layer.avoid(z0, z1, width=1.0)
    # in the wedge between the ground line and the crank, just beyond the arc
    mid = O2 + 1.55 * r * cmath.exp(1j * (theta1 + theta2) / 2)
    layer.add_fixed(r"$\theta_2$", mid, color="#333333", fontsize=style.LABEL_SIZE)


def _turn(ax, centre, along, rate, text, kind, walk):
    """A curved arrow about ``centre`` (drawing units) across the link that
    leaves it along ``along``, in the sense of ``rate``, labelled ``text``
    at its head: the sense of an omega or alpha that a step reads."""
    from matplotlib.patches import FancyArrowPatch
    from matplotlib.path import Path

    from .draw import units_of
    from .labels import labels_of

    if rate == 0:
        return
    pts = list(walk.linkage.points.values())
    size = max(abs(p - q) for p in pts for q in pts) * units_of(walk)["length"][1]
    r = (0.07 if kind == "velocity" else 0.11) * size
    sense = 1 if rate > 0 else -1
    mid = cmath.phase(along)
    half = math.radians(50)
    t = [mid - sense * half + sense * 2 * half * k / 24 for k in range(25)]
    zs = [centre + r * cmath.exp(1j * x) for x in t]
    spec = style.component(kind)
    ax.add_patch(
        FancyArrowPatch(
            path=Path([(z.real, z.imag) for z in zs]),
            arrowstyle="-|>,head_length=6,head_width=3",
            color=spec["color"],
            linewidth=1.6,
            zorder=7,
        )
    )
    layer = labels_of(ax)
    for z0, z1 in zip(zs[::4], zs[4::4]):
        layer.avoid(z0, z1, width=1.6)
    layer.add_point(text, zs[-1], color=spec["color"], priority=0.4)
