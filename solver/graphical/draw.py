"""Drawings of a graphical construction (matplotlib): the linkage to scale with
the acceleration components at their points (Figure 7-4a/d) and the velocity
and acceleration polygons (Figure 7-4b/c).

What makes them read like a textbook figure:

* **the linkage's own units**: an inch linkage is drawn and labelled in in, in/s
  and in/s^2, a metric one in mm, m/s and m/s^2 (``units="US"`` / ``"SI"``,
  by default the units the case was given in);
* **every component visible**: a vector too short to see at the figure's scale
  is shown again in a magnified inset (its factor written in it);
* **vectors beside the link**, not on it: a vector that lies along a link from
  its pin (a centripetal component) is drawn a few points to its side;
* **labels that overlap nothing**: placed when the figure is drawn
  (:mod:`.labels`), clear of each other, of the links and of the vectors;
* **scale bars** for lengths and accelerations, and arrowheads of one size
  in every panel.

``step=k`` draws what steps 1..k of the construction have added (see
:class:`~accelab.solver.graphical.construction.Construction`), with that step's text
as the caption, so a notebook can walk through the method.
"""

import math
import re
import textwrap
from typing import Any

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.markers import MarkerStyle
from matplotlib.patches import FancyArrowPatch, Polygon
from matplotlib.path import Path
from matplotlib.transforms import Affine2D, ScaledTranslation

from ..registry import link_symbols
from . import style
from .labels import LabelLayer, labels_of

IN = 0.0254  # m per inch

#: display units: name -> (length unit, factor from m), velocity, acceleration
UNIT_SYSTEMS = {
    "US": {
        "length": ("in", 1 / IN),
        "velocity": ("in/s", 1 / IN),
        "acceleration": (r"in/s$^2$", 1 / IN),
    },
    "SI": {"length": ("mm", 1e3), "velocity": ("m/s", 1.0), "acceleration": (r"m/s$^2$", 1.0)},
    "SI-m": {"length": ("m", 1.0), "velocity": ("m/s", 1.0), "acceleration": (r"m/s$^2$", 1.0)},
}
DIAGRAMS = {
    "velocity": ("velocity", "Velocity polygon"),
    "acceleration": ("acceleration", "Acceleration polygon"),
    "point": ("acceleration", "Acceleration of P"),
}
#: a vector shorter than this fraction of its diagram's size gets a magnified inset
TINY = 0.06
#: an inset that would magnify less than this is not drawn (the vector is readable as is)
MIN_MAGNIFICATION = 4
#: a vector shorter than this fraction of its diagram is round-off of a zero (a slip
#: velocity of 1e-16 m/s at theta2 = 360 deg): never magnified, which would take an inset
#: of a 1e15 times magnification that no renderer finishes drawing
ROUNDOFF = 1e-9
INSET_WIDTH = 0.34  # of the axes
#: a vector within this angle [deg] of a link from its own pin is drawn beside the link
ALONG = 12.0
BESIDE = 5.5  # how far beside [pt]
HEAD_LENGTH = 9.0  # arrowhead length [pt]
_HEAD = Path(
    [(0, 0), (-1, 0.36), (-0.82, 0), (-1, -0.36), (0, 0)],
    [Path.MOVETO, Path.LINETO, Path.LINETO, Path.LINETO, Path.CLOSEPOLY],
)
__all__ = [
    "draw_linkage",
    "draw_polygon",
    "draw_polygons",
    "save",
    "diagrams",
    "nice",
    "fmt",
    "units_of",
    "arrow",
    "UNIT_SYSTEMS",
]


# ---------------------------------------------------------------- helpers
def nice(x):
    """A round number (1, 2 or 5 times a power of ten) not above x > 0."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    e = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10**e <= x * (1 + 1e-12):
            return m * 10**e
    return 10**e


def fmt(x):
    """A scale-bar number without trailing noise."""
    return f"{x:.0f}" if x >= 1 else f"{x:.3g}"


def length_unit(size):
    """(factor, name) to show lengths of a metric linkage of this size [m]."""
    return (1e3, "mm") if size < 1.0 else (1.0, "m")


def units_of(con, units=None):
    """The display units of a drawing: ``units`` ("US", "SI", "SI-m") or the
    construction's own (``con.units``, set from the case by ``construct_case``);
    a metric linkage a metre or more across is drawn in m instead of mm."""
    units = units or getattr(con, "units", None) or "SI"
    if units not in UNIT_SYSTEMS:
        raise ValueError(f"units must be one of {', '.join(UNIT_SYSTEMS)} (got {units!r})")
    if units == "SI":
        pts = list(con.linkage.points.values())
        size = max((abs(p - q) for p in pts for q in pts), default=0.0)
        if size >= 1.0:
            units = "SI-m"
    return UNIT_SYSTEMS[units]


def _pts_per_data(ax):
    """Points of the figure per data unit of ``ax`` as it stands (an estimate:
    a layout engine may still move the axes a little)."""
    ax.apply_aspect()
    bb = ax.get_position()
    w_pts = bb.width * ax.figure.get_figwidth() * 72.0
    x0, x1 = ax.get_xlim()
    return w_pts / abs(x1 - x0)


def _offset(ax, off):
    """ax.transData shifted by ``off`` (complex) points."""
    if off == 0:
        return ax.transData
    return ax.transData + ScaledTranslation(
        off.real / 72.0, off.imag / 72.0, ax.figure.dpi_scale_trans
    )


def _arrow(ax, start, vector, kind, ppd, offset=0j, zorder=6):
    """A vector from ``start`` (data) in the style of its kind: the shaft in its
    line style, a solid head of a fixed size in points (smaller on a vector too
    short for it). ``offset`` [pt] draws it beside where it belongs."""
    st = style.component(kind)
    length = abs(vector)
    if length == 0.0 or not math.isfinite(length):
        return False
    head = min(HEAD_LENGTH * (1.15 if kind == "resultant" else 1.0), 0.55 * length * ppd)
    tip = start + vector
    trans = _offset(ax, offset)
    ax.add_patch(
        FancyArrowPatch(
            (start.real, start.imag),
            (tip.real, tip.imag),
            arrowstyle="-",
            shrinkA=0,
            shrinkB=0.6 * head,
            color=st["color"],
            linewidth=st["linewidth"],
            linestyle=st["linestyle"],
            capstyle="butt",
            joinstyle="miter",
            transform=trans,
            zorder=zorder,
        )
    )
    angle = math.degrees(math.atan2(vector.imag, vector.real))
    ax.plot(
        [tip.real],
        [tip.imag],
        linestyle="none",
        transform=trans,
        zorder=zorder + 1,
        marker=MarkerStyle(_HEAD, transform=Affine2D().rotate_deg(angle)),
        markersize=2 * head,
        color=st["color"],
        markeredgewidth=0.4,
    )
    return True


def arrow(ax, start, vector, kind="resultant", label=None, scale=1.0, beside=0.0):
    """A vector in the style of its kind, for a hand-made figure: drawn from
    ``start`` (complex, data units) as ``scale * vector``, its label placed at
    draw time clear of every line, text and other label of the axes (the
    axes' :class:`~accelab.solver.graphical.labels.LabelLayer`). ``beside`` [pt] draws
    it that far to its left (negative: right), e.g. beside a link it lies on.
    Returns the tip (data units)."""
    start = complex(start)
    v = complex(vector) * scale
    off = 1j * v / abs(v) * beside if beside and v else 0j
    _arrow(ax, start, v, kind, math.inf, off)
    layer = labels_of(ax)
    if v:
        layer.avoid(start, start + v, width=style.component(kind)["linewidth"], offset=off)
        if label:
            layer.add_vector(label, start, v, color=_label_colour(kind), offset=off)
    return start + v


def _clip(point, u, box):
    """End points of the line point + t u inside box = (x0, x1, y0, y1), or None."""
    x0, x1, y0, y1 = box
    lo, hi = -math.inf, math.inf
    for p, d, a, b in ((point.real, u.real, x0, x1), (point.imag, u.imag, y0, y1)):
        if abs(d) < 1e-15:
            if not a <= p <= b:
                return None
            continue
        t0, t1 = sorted(((a - p) / d, (b - p) / d))
        lo, hi = max(lo, t0), min(hi, t1)
    if not lo < hi:
        return None
    return point + lo * u, point + hi * u


def _line_segment(point, direction, box):
    """The part of a construction line that a drawing of frame ``box`` shows."""
    u = direction / abs(direction)
    x0, x1, y0, y1 = box
    inset = 0.04 * max(x1 - x0, y1 - y0)
    return _clip(point, u, (x0 + inset, x1 - inset, y0 + inset, y1 - inset))


def _construction_line(ax, labels, point, direction, name, box, letters=True, halo=False):
    seg = _line_segment(point, direction, box)
    if seg is None:
        return
    z0, z1 = seg
    if halo:
        _halo(ax, z0, z1 - z0)
    ax.plot([z0.real, z1.real], [z0.imag, z1.imag], zorder=3, **style.CONSTRUCTION_LINE)
    labels.avoid(z0, z1, weight=0.12, width=1.0)
    if name and letters:
        for z in (z0, z1):
            labels.add_fixed(name[0], z, color="#555555", style="italic", fontsize=style.FONT_SIZE)


def _halo(ax, start, vector, offset=0j):
    """A broad pale band under a vector or line: what the step being shown adds."""
    tip = start + vector
    ax.plot(
        [start.real, tip.real],
        [start.imag, tip.imag],
        transform=_offset(ax, offset),
        **style.HIGHLIGHT,
    )


def _samples(z0, z1, n):
    """n + 1 points from z0 to z1: what an inset should not cover."""
    return [z0 + (z1 - z0) * k / n for k in range(n + 1)]


def _obstacles(pairs, vectors, lines, box):
    """Points along the links (``pairs`` of ends), the vectors ((start, vector))
    and the construction lines ((point, direction), as clipped to ``box``) of a
    complete diagram: an inset is placed where they are fewest."""
    out = []
    for z0, z1 in pairs:
        out += _samples(z0, z1, 40)
    for point, direction in lines:
        seg = _line_segment(point, direction, box)
        if seg is not None:
            out += _samples(seg[0], seg[1], 30)
    for s, v in vectors:
        out += _samples(s, s + v, 20)
    return out


def _extent(points):
    xs = [z.real for z in points]
    ys = [z.imag for z in points]
    return min(xs), max(xs), min(ys), max(ys)


def _frame(ax, points, margin, strip=0.0, box=None):
    """Frame the points (or the given ``box``) with a margin, plus a strip of
    ``strip`` times the frame's size below it for the scale bars. Returns the
    drawing's box (without the strip)."""
    if box is None:
        x0, x1, y0, y1 = _extent(points)
        box = (x0 - margin, x1 + margin, y0 - margin, y1 + margin)
    h = strip * max(box[1] - box[0], box[3] - box[2])
    ax.set_xlim(box[0], box[1])
    ax.set_ylim(box[2] - h, box[3])
    ax.set_aspect("equal")
    ax.axis("off")
    return box


def _scale_bar(ax, labels, x, y, length_data, text, tick):
    """A bar ``length_data`` long at (x, y) with its value written after it;
    the labels of the drawing keep clear of both."""
    ax.plot(
        [x, x + length_data], [y, y], color="black", linewidth=2.0, zorder=8, solid_capstyle="butt"
    )
    for xx in (x, x + length_data):
        ax.plot([xx, xx], [y - tick, y + tick], color="black", linewidth=1.3, zorder=8)
    labels.avoid(complex(x, y), complex(x + length_data, y), width=6.0)
    labels.add_fixed(
        text,
        complex(x + length_data + 1.5 * tick, y),
        ha="left",
        boxed=False,
        fontsize=style.FONT_SIZE - 1,
    )


def _legend(ax, kinds, with_lines, **kw):
    order = [k for k in style.COMPONENT if k in kinds]
    handles = [
        Line2D(
            [],
            [],
            color=style.component(k)["color"],
            linestyle=style.component(k)["linestyle"],
            linewidth=style.component(k)["linewidth"],
            label=style.component(k)["label"],
        )
        for k in order
    ]
    if with_lines:
        handles.append(Line2D([], [], label="construction line", **style.CONSTRUCTION_LINE))
    if handles:
        kw.setdefault("handlelength", 3.0)
        return ax.legend(handles=handles, fontsize=style.FONT_SIZE - 1, frameon=False, **kw)
    return None


def _caption(fig, con, step):
    if step is None:
        return
    step = con.index(step)
    if step == 0:
        return
    s = con.steps[step - 1]
    head = (
        f"Step {s.label}"
        if s.phase == "acceleration"
        else {"position": "Position", "velocity": f"Velocity {s.label}"}[s.phase]
    )
    width = max(60, int(fig.get_figwidth() * 12))
    text = textwrap.fill(f"{head} ({step}/{len(con.steps)}): {s.text}", width)
    fig.text(0.5, 0.0, _mathtext(text), ha="center", va="top", fontsize=style.FONT_SIZE)


_SYMBOL = re.compile(
    r"\b([AV])_([A-Za-z0-9]+)(?:\^([a-z]))?"
    r"|\b(omega|alpha|theta|delta|gamma)(\d?)\b"
)


def _mathtext(text):
    """Step texts say A_BA^t, omega3 ...: show them as the chapter's symbols."""

    def sub(m):
        if m.group(1):
            sup = f"^{{{m.group(3)}}}" if m.group(3) else ""
            return rf"$\mathbf{{{m.group(1)}}}_{{{m.group(2)}}}{sup}$"
        sym = "\\" + m.group(4)
        return f"${sym}_{{{m.group(5)}}}$" if m.group(5) else f"${sym}$"

    return _SYMBOL.sub(sub, text).replace("^2", "$^2$")


def _added_by(con, step):
    """The arrows and lines that ``step`` itself adds (none for no step)."""
    if step is None:
        return ()
    n = con.index(step)
    if n == 0:
        return ()
    s = con.steps[n - 1]
    return tuple(s.arrows) + tuple(s.lines)


def _among(item, items):
    return any(item is x for x in items)


def _label_colour(kind):
    return "black" if kind == "resultant" else style.component(kind)["color"]


def _pretty(name, names=None):
    name = (names or {}).get(name, name)
    if not name:
        return None
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", name)
    return f"${m.group(1)}_{{{m.group(2)}}}$" if m else f"${name}$"


# ---------------------------------------------------------------- insets
def _tiny(vectors, size, ppd=None):
    """Indices of the vectors (complex, drawn lengths) too short to see: shorter
    than a fraction of the diagram, or than a few arrowheads on paper (``ppd``:
    points per data unit)."""
    short = TINY * size
    if ppd:
        short = max(short, 2.4 * HEAD_LENGTH / ppd)
    return [i for i, v in enumerate(vectors) if ROUNDOFF * size < abs(v) < short]


def _leader(region, rect):
    """The leader from a magnified region to its inset: (start, end) in data
    units, or None when the two touch. ``region`` and ``rect`` are
    (x0, x1, y0, y1)."""
    centre = complex((region[0] + region[1]) / 2, (region[2] + region[3]) / 2)
    half = (region[1] - region[0]) / 2
    inset_centre = complex((rect[0] + rect[1]) / 2, (rect[2] + rect[3]) / 2)
    d = inset_centre - centre
    if abs(d) == 0:
        return None
    a = centre + d / abs(d) * half * 1.05
    hw, hh = (rect[1] - rect[0]) / 2, (rect[3] - rect[2]) / 2
    t = min(hw / abs(d.real) if d.real else math.inf, hh / abs(d.imag) if d.imag else math.inf)
    b = inset_centre - d * min(t, 1.0)
    if abs(b - centre) <= abs(a - centre):
        return None
    return a, b


def _near_segment(z, a, b, tol):
    d = b - a
    t = max(0.0, min(1.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d)) <= tol


def _inset_spot(ax, region, box, obstacles, frac):
    """Where to put an inset of width ``frac`` (axes fraction): of the corners
    and edge middles of the drawing box, the one whose rectangle covers the
    fewest obstacle points, whose leader crosses the fewest, and that does not
    cover the magnified region itself. Returns (bounds in axes fraction, cost:
    about the number of obstacle points covered)."""
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    w = frac
    h = frac * (x1 - x0) / (y1 - y0)  # a square region stays square
    bx0 = (box[0] - x0) / (x1 - x0)
    bx1 = (box[1] - x0) / (x1 - x0)
    by0 = (box[2] - y0) / (y1 - y0)
    by1 = (box[3] - y0) / (y1 - y0)
    xm, ym = (bx0 + bx1 - w) / 2, (by0 + by1 - h) / 2
    tol = 0.012 * (x1 - x0)  # a leader this close to a line reads as crossing it
    best = None
    for cx, cy in (
        (bx1 - w, by1 - h),
        (bx0, by1 - h),
        (bx1 - w, by0),
        (bx0, by0),
        (xm, by1 - h),
        (bx1 - w, ym),
        (bx0, ym),
        (xm, by0),
    ):
        rx0, rx1 = x0 + cx * (x1 - x0), x0 + (cx + w) * (x1 - x0)
        ry0, ry1 = y0 + cy * (y1 - y0), y0 + (cy + h) * (y1 - y0)
        m = 0.05 * (x1 - x0)  # lines running up to its border read as running into it
        inside = sum(
            1.0 if rx0 <= z.real <= rx1 and ry0 <= z.imag <= ry1 else 0.1
            for z in obstacles
            if rx0 - m <= z.real <= rx1 + m and ry0 - m <= z.imag <= ry1 + m
        )
        covers = not (region[1] < rx0 or region[0] > rx1 or region[3] < ry0 or region[2] > ry1)
        crossed = 0.0
        leader = _leader(region, (rx0, rx1, ry0, ry1))
        if leader is not None:
            a, b = leader
            crossed = sum(
                0.5
                for z in obstacles
                if not (region[0] <= z.real <= region[1] and region[2] <= z.imag <= region[3])
                and _near_segment(z, a, b, tol)
            )
        cost = inside + crossed + (10**6 if covers else 0)
        if best is None or cost < best[0]:
            best = (cost, (cx, cy, w, h))
    assert best is not None  # the loop tries at least one spot
    return best[1], best[0]


#: length [pt] a magnified vector is drawn about (within a factor of 2.5: the
#: magnification is a round number), and the room [pt] around it in the inset
INSET_TARGET = 46.0
INSET_MARGIN = 26.0


def _inset_plan(ax, box, starts, vectors, tiny, ppd):
    """(centre, half side, factor, width as a fraction of the axes) of the
    region to magnify around the vectors ``tiny`` (indices), or None when the
    magnification would be too small to be worth an inset. The inset is as
    large as the magnified vectors need, with room for their labels."""
    if not tiny:
        return None
    ends = [starts[i] for i in tiny] + [starts[i] + vectors[i] for i in tiny]
    x0, x1, y0, y1 = _extent(ends)
    centre = complex((x0 + x1) / 2, (y0 + y1) / 2)
    longest = max(abs(vectors[i]) for i in tiny)
    factor = _magnification(INSET_TARGET / (longest * ppd))
    if factor < MIN_MAGNIFICATION:
        return None
    side_pt = max(max(x1 - x0, y1 - y0) * factor * ppd + 2 * INSET_MARGIN, 2.6 * INSET_MARGIN)
    width_pt = ax.get_position().width * ax.figure.get_figwidth() * 72.0
    frac = min(side_pt / width_pt, INSET_WIDTH)
    half = frac * width_pt / ppd / factor / 2
    return centre, half, factor, frac


def _magnification(x):
    """A round magnification (1, 2, 3, 4 or 5 times a power of ten) not above x."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    e = math.floor(math.log10(x))
    for m in (5, 4, 3, 2, 1):
        if m * 10**e <= x * (1 + 1e-12):
            return m * 10**e
    return 10**e


def _inset_layout(ax, box, every, span, ppd, inset, obstacles):
    """The inset of a drawing, decided on its complete diagram (``every``: the
    (start, vector) pairs of all its steps), so that a walk through the steps
    keeps it in one place: ``(plan, spot, tiny)`` with ``tiny`` the indices of
    ``every`` it magnifies, or None. Widens the axes when no spot is free."""
    if not inset:
        return None
    tiny = _tiny([v for _, v in every], span, ppd)
    plan = _inset_plan(ax, box, [s for s, _ in every], [v for _, v in every], tiny, ppd)
    if plan is None:
        return None
    centre, half, _, frac = plan
    region = (centre.real - half, centre.real + half, centre.imag - half, centre.imag + half)
    spot, covered = _inset_spot(ax, region, box, obstacles, frac)
    if covered > 1.5:  # no free corner: make room beside the drawing
        spot, plan = _inset_beside(ax, box, plan, obstacles)
    return plan, spot, tiny


def _inset_beside(ax, box, plan, obstacles):
    """Widen the axes by a strip for the inset, on the side (right or left) and
    at the height (top, middle, bottom) where its leader crosses the fewest
    lines; returns ``(spot, plan)``, the plan's region grown as the drawing
    shrank (the inset magnifies by the same factor)."""
    centre, half, factor, frac = plan
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    grow = frac / (1 - frac) * (x1 - x0)
    half = half / (1 - frac)
    region = (centre.real - half, centre.real + half, centre.imag - half, centre.imag + half)
    h = frac * (x1 - x0 + grow) / (y1 - y0)
    tol = 0.012 * (x1 - x0 + grow)
    top = (box[3] - y0) / (y1 - y0) - h
    bottom = (box[2] - y0) / (y1 - y0)
    best = None
    for side, lims in (("right", (x0, x1 + grow)), ("left", (x0 - grow, x1))):
        fx = 1 - frac if side == "right" else 0.0
        for fy in (top, (top + bottom) / 2, bottom):
            rect = (
                lims[0] + fx * (lims[1] - lims[0]),
                lims[0] + (fx + frac) * (lims[1] - lims[0]),
                y0 + fy * (y1 - y0),
                y0 + (fy + h) * (y1 - y0),
            )
            leader = _leader(region, rect)
            crossed = 0
            if leader is not None:
                crossed = sum(
                    1
                    for z in obstacles
                    if not (region[0] <= z.real <= region[1] and region[2] <= z.imag <= region[3])
                    and _near_segment(z, leader[0], leader[1], tol)
                )
            if best is None or crossed < best[0]:
                best = (crossed, lims, (fx, fy, frac, h))
    assert best is not None  # the loops try at least one spot
    ax.set_xlim(*best[1])
    return best[2], (centre, half, factor, frac)


def _paint_with_inset(ax, box, drawn, span, ppd, inset, paint, obstacles, every=None):
    """Paint the vectors ``drawn`` ((start, vector) pairs) with ``paint``, and
    those too short to see again in a magnified inset. ``every`` holds the
    vectors of the complete diagram (``drawn`` is its first part): the inset
    is placed for it, and shown once a vector it magnifies is drawn.
    ``obstacles``: points of the complete diagram. Returns the label layer."""
    every = drawn if every is None else every
    layout = _inset_layout(ax, box, every, span, ppd, inset, obstacles)
    labels = LabelLayer(ax)
    tiny = [i for i in layout[2] if i < len(drawn)] if layout else []
    paint(ax, labels, None, tiny)
    if tiny:
        _magnifier(ax, layout[0], layout[1], tiny, paint)
    return labels


def _magnifier(ax, plan, spot, tiny, draw):
    """A magnified inset at ``spot`` (axes fraction) of the region ``plan`` (see
    :func:`_inset_plan`) around the vectors ``tiny``. ``draw(inset_ax, labels,
    region, tiny)`` paints the scene into the inset, labelling the tiny vectors."""
    centre, half, factor, _ = plan
    region = (centre.real - half, centre.real + half, centre.imag - half, centre.imag + half)
    inset = ax.inset_axes(spot)
    inset.set_xlim(region[0], region[1])
    inset.set_ylim(region[2], region[3])
    inset.set_aspect("equal", adjustable="box")
    inset.set_xticks([])
    inset.set_yticks([])
    for sp in inset.spines.values():
        sp.set_visible(True)  # all four, whatever the caller's style hides
        sp.set_edgecolor("#777777")
        sp.set_linewidth(0.8)
    inset.patch.set_facecolor("white")
    inset.patch.set_alpha(0.95)
    labels = LabelLayer(inset)
    # the factor's corner (top left): the labels keep off it
    w, h = region[1] - region[0], region[3] - region[2]
    corner = [
        complex(region[0] + fx * w, region[2] + fy * h) for fx, fy in ((0.0, 0.8), (0.3, 1.0))
    ]
    labels.avoid(corner[0], corner[1], width=1.0)
    labels.avoid(complex(corner[0].real, corner[1].imag), complex(corner[1].real, corner[0].imag))
    draw(inset, labels, region, tiny)
    inset.text(
        0.04,
        0.96,
        f"\u00d7{factor:g}",
        transform=inset.transAxes,
        ha="left",
        va="top",
        fontsize=style.FONT_SIZE - 1,
        color="#555555",
    )
    rect = Polygon(
        [
            (region[0], region[2]),
            (region[1], region[2]),
            (region[1], region[3]),
            (region[0], region[3]),
        ],
        closed=True,
        fill=False,
        edgecolor="#777777",
        linewidth=0.8,
        zorder=9,
    )
    ax.add_patch(rect)
    # a leader from the magnified region to the inset
    ix0, iy0, iw, ih = spot
    fx = ax.get_xlim()
    fy = ax.get_ylim()
    leader = _leader(
        region,
        (
            fx[0] + ix0 * (fx[1] - fx[0]),
            fx[0] + (ix0 + iw) * (fx[1] - fx[0]),
            fy[0] + iy0 * (fy[1] - fy[0]),
            fy[0] + (iy0 + ih) * (fy[1] - fy[0]),
        ),
    )
    if leader is not None:
        a, b = leader
        ax.plot([a.real, b.real], [a.imag, b.imag], color="#999999", lw=0.8, zorder=9)
    return True


# ---------------------------------------------------------------- linkage
def _ground(ax, z, size):
    """A pivot's ground symbol: a hatched triangle under the pin."""
    tri = [
        (z.real, z.imag),
        (z.real - 0.6 * size, z.imag - size),
        (z.real + 0.6 * size, z.imag - size),
    ]
    ax.add_patch(
        Polygon(
            tri,
            closed=True,
            facecolor="white",
            edgecolor="#222222",
            hatch=style.GROUND_HATCH,
            linewidth=1.0,
            zorder=1,
        )
    )


def _block(ax, z, direction, size):
    u = direction / abs(direction)
    n = 1j * u
    corners = [
        z + sx * 0.9 * size * u + sy * 0.5 * size * n
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]
    ax.add_patch(
        Polygon(
            [(c.real, c.imag) for c in corners],
            closed=True,
            facecolor="#e6e6e6",
            edgecolor="#222222",
            linewidth=1.2,
            zorder=4,
        )
    )


def _on(z, z0, z1, tol):
    """Whether the point z lies on the segment z0-z1 (within tol)."""
    d = z1 - z0
    if abs(d) == 0:
        return abs(z - z0) <= tol
    t = ((z - z0) * d.conjugate()).real / abs(d) ** 2
    return -1e-9 <= t <= 1 + 1e-9 and abs(z - (z0 + t * d)) <= tol


def _beside(arrows, segments, size):
    """For each linkage vector (start, v), an offset [pt] that moves it beside a
    link (or slide) it would otherwise lie on, and beside another vector along
    the same line from the same point."""
    offsets = []
    taken: dict[Any, Any] = {}
    tol = 1e-9 * size
    for start, v in arrows:
        off = 0j
        if abs(v) > 0:
            u = v / abs(v)
            along = False
            for z0, z1 in segments:
                d = z1 - z0
                if abs(d) == 0 or not _on(start, z0, z1, tol):
                    continue
                sine = abs((u * (d / abs(d)).conjugate()).imag)
                probe = start + 0.01 * size * u  # a little way along the vector
                if sine < math.sin(math.radians(ALONG)) and _on(probe, z0, z1, 0.01 * size):
                    along = True
            key = (round(start.real, 9), round(start.imag, 9))
            same = [
                w
                for w in taken.get(key, [])
                if abs(math.degrees(math.atan2((w * u.conjugate()).imag, (w * u.conjugate()).real)))
                < ALONG
            ]
            if along or same:
                k = len(same) + (1 if along else 0)
                side = 1 if k % 2 else -1
                off = side * 1j * u * BESIDE * ((k + 1) // 2)
            taken.setdefault(key, []).append(u)
        offsets.append(off)
    return offsets


def draw_linkage(
    con,
    step=None,
    ax=None,
    scale=None,
    *,
    units=None,
    box=None,
    legend=True,
    title=None,
    scale_bars=True,
    vectors=True,
    symbols=False,
    names=None,
    inset=True,
    lines=True,
    notes=None,
    colour=None,
    kinds=None,
    highlight=False,
    diagram="linkage",
):
    """The linkage to scale with the acceleration components at their points.

    Parameters
    ----------
    con : Construction
    step : int or str, optional
        Draw only what steps 1..step add (default: the finished construction);
        a label such as ``"6"`` names a step of Example 7-1.
    ax : matplotlib Axes, optional
    scale : float, optional
        Drawing scale of the acceleration vectors [length unit of the drawing
        per acceleration unit of the drawing, e.g. in per in/s^2]; by default
        the longest vector is drawn about half as long as the linkage. Give
        one scale (and one ``box``) to draw several positions alike.
    units : {"US", "SI", "SI-m"}, optional
        Display units (default: the units of the case, see :func:`units_of`).
    box : tuple, optional
        (x0, x1, y0, y1) of the drawing in its length unit: the frame, the
        same for every figure given it (the scale bars go below it).
    legend, title, scale_bars : bool or str
        Parts of the figure to draw (``title`` may be the title's text).
    vectors : bool
        False draws the linkage alone (a schematic, with ``symbols``).
    symbols : bool
        Label the links with the chapter's symbols (a, b, c, d ...).
    names : dict, optional
        New names for points, e.g. ``{"P": "A"}``.
    notes : dict, optional
        Text to write beside a point, e.g. ``{"O2": r"$\\omega_2$"}``.
    colour : str, optional
        Colour of the links (default: the style's grey), to tell a second
        position drawn on the same axes from the first.
    kinds : sequence of str, optional
        Draw only the vectors of these kinds (e.g. ``("resultant",)``).
    inset : bool
        Magnify vectors too short to see in an inset.
    lines : bool
        Draw the construction lines (pp, qq).
    highlight : bool
        Lay a pale band under what ``step`` itself adds (a walk through the
        construction shows each step's stroke this way).
    diagram : str
        The diagram of the construction whose vectors are drawn on the
        linkage (default ``"linkage"``).

    Returns
    -------
    matplotlib Figure
    """
    own = ax is None
    if own:
        _, ax = plt.subplots(figsize=(7.4, 5.6), layout="constrained")
    fig = ax.figure
    u = units_of(con, units)
    lname, lf = u["length"]
    aname, af = u["acceleration"]
    lk = con.linkage
    pts = {k: z * lf for k, z in lk.points.items()}
    size = max((abs(p - q) for p in pts.values() for q in pts.values()), default=1.0) or 1.0
    arrows_all, clines_all, _ = con.items(diagram) if vectors else ([], [], {})
    arrows, clines, _ = con.items(diagram, step) if vectors else ([], [], {})
    if kinds is not None:
        arrows_all = [a for a in arrows_all if a.kind in kinds]
        arrows = [a for a in arrows if a.kind in kinds]
    if not lines:
        clines = clines_all = []
    new = _added_by(con, step) if highlight else ()
    if scale is None:
        big = max((abs(a.vector) * af for a in arrows_all), default=0.0)
        scale = 0.55 * size / big if big > 0 else 1.0
    drawn = [(a.start * lf, a.vector * af * scale) for a in arrows]
    every = [(a.start * lf, a.vector * af * scale) for a in arrows_all]
    # a given frame fixes the scale bars too (the same in every figure drawn in it)
    bar = size if box is None else 0.6 * max(box[1] - box[0], box[3] - box[2])
    box = _frame(
        ax,
        list(pts.values()) + [s + v for s, v in every] + [s for s, _ in every],
        0.13 * size,
        strip=(0.15 if arrows_all else 0.09) if scale_bars else 0.0,
        box=box,
    )
    span = max(box[1] - box[0], box[3] - box[2])
    ppd = _pts_per_data(ax)
    guides = []
    for link in lk.links:
        zs = [pts[n] for n in link]
        guides += list(zip(zs, zs[1:] + zs[:1] if len(zs) == 3 else zs[1:]))
    for p0, d, t0, t1 in lk.rods:  # a slide carried by a link
        d = d / abs(d)
        guides.append((p0 * lf + t0 * lf * d, p0 * lf + t1 * lf * d))
    for p0, d in lk.slides:  # a slide on the ground
        d = d / abs(d)
        guides.append((p0 * lf - 10 * size * d, p0 * lf + 10 * size * d))
    offsets = _beside(drawn, guides, size)
    pairs = []
    for link in lk.links:
        zs = [pts[n] for n in link]
        pairs += list(zip(zs, zs[1:] + zs[:1] if len(zs) == 3 else zs[1:]))
    obstacles = _obstacles(pairs, every, [(ln.point * lf, ln.direction) for ln in clines_all], box)

    def paint(target, labels, region=None, tiny=()):
        """Draw the scene on ``target``; the main axes or a magnifying inset."""
        main = region is None
        ppd_t = ppd if main else _pts_per_data(target)
        for link in lk.links:
            zs = [pts[n] for n in link]
            if len(link) == 3:
                target.add_patch(
                    Polygon([(z.real, z.imag) for z in zs], closed=True, **style.COUPLER_FILL)
                )
                pairs = list(zip(zs, zs[1:] + zs[:1]))
            else:
                target.plot(
                    [z.real for z in zs],
                    [z.imag for z in zs],
                    **dict(style.LINK, **({"color": colour} if colour else {})),
                )
                pairs = list(zip(zs, zs[1:]))
            for z0, z1 in pairs:
                labels.avoid(z0, z1, width=style.LINK["linewidth"] if len(link) == 2 else 1.2)
            if symbols and len(link) == 2:
                table = link_symbols(con.mechanism)  # the registry's
                sym = table.get(tuple(link)) or table.get(tuple(reversed(link)))
                if sym:
                    labels.add_vector(
                        f"${sym}$", zs[0], zs[1] - zs[0], color="#333333", priority=0.5
                    )
        for p0, d in lk.slides:
            d = d / abs(d)
            ts = [((z - p0 * lf) * d.conjugate()).real for z in pts.values()]
            t0, t1 = min(ts + [0.0]) - 0.15 * size, max(ts + [0.0]) + 0.15 * size
            za, zb = p0 * lf + t0 * d, p0 * lf + t1 * d
            target.plot(
                [za.real, zb.real],
                [za.imag, zb.imag],
                color="#222222",
                linewidth=1.0,
                linestyle="-.",
                zorder=1,
            )
            labels.avoid(za, zb, weight=0.5, width=1.0)
        for p0, d, t0, t1 in lk.rods:
            d = d / abs(d)
            za, zb = p0 * lf + t0 * lf * d, p0 * lf + t1 * lf * d
            target.plot(
                [za.real, zb.real], [za.imag, zb.imag], color="#4d4d4d", linewidth=2.2, zorder=2
            )
            labels.avoid(za, zb, width=2.2)
        for name, d in lk.blocks:
            _block(target, pts[name], d, 0.06 * size)
            e = d / abs(d) * 0.06 * size
            corners = [
                pts[name] + sx * 0.9 * e + sy * 0.5j * e
                for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))
            ]
            for k in range(4):
                labels.avoid(corners[k], corners[(k + 1) % 4], width=1.2)
        for g in lk.ground:
            _ground(target, pts[g], 0.05 * size)
            z = pts[g]
            corners = [z, z + complex(-0.6, -1) * 0.05 * size, z + complex(0.6, -1) * 0.05 * size]
            for k in range(3):
                labels.avoid(corners[k], corners[(k + 1) % 3], width=1.0)
        xs = list(pts.values())
        target.scatter([z.real for z in xs], [z.imag for z in xs], **style.PIN)
        for z in xs:
            labels.avoid_pin(z, 4.0)
        for ln in clines:
            _construction_line(
                target,
                labels,
                ln.point * lf,
                ln.direction,
                ln.name,
                box if main else (region[0], region[1], region[2], region[3]),
                letters=main,
                halo=_among(ln, new),
            )
        for i, (a, (s, v)) in enumerate(zip(arrows, drawn)):
            if _among(a, new) and abs(v) > 0:
                _halo(target, s, v, offsets[i])
            if _arrow(target, s, v, a.kind, ppd_t, offsets[i]):
                labels.avoid(
                    s, s + v, width=style.component(a.kind)["linewidth"], offset=offsets[i]
                )
        for name, z in pts.items():
            if _pretty(name, names) and (
                main or (region[0] <= z.real <= region[1] and region[2] <= z.imag <= region[3])
            ):
                labels.add_point(_pretty(name, names), z, priority=0)
        for name, text in (notes or {}).items():
            if main and name in pts:
                labels.add_point(
                    text, pts[name], color="#444444", priority=0.7, fontsize=style.FONT_SIZE - 1
                )
        for i, (a, (s, v)) in enumerate(zip(arrows, drawn)):
            if abs(v) > 0 and (main != (i in tiny)):
                labels.add_vector(
                    f"${a.name}$",
                    s,
                    v,
                    color=_label_colour(a.kind),
                    offset=offsets[i],
                    priority=1 + (0 if a.kind == "resultant" else 0.5),
                )

    labels = _paint_with_inset(ax, box, drawn, span, ppd, inset, paint, obstacles, every)
    kinds = {a.kind for a in arrows}
    if scale_bars:
        x0, x1, y0, y1 = box
        tick = 0.008 * span
        L = nice(0.22 * bar)
        _scale_bar(ax, labels, x0 + 0.02 * span, y0 - 0.045 * span, L, f"{fmt(L)} {lname}", tick)
        if arrows:
            Aval = nice(0.22 * bar / scale)
            _scale_bar(
                ax,
                labels,
                x0 + 0.02 * span,
                y0 - 0.11 * span,
                Aval * scale,
                f"{fmt(Aval)} {aname}",
                tick,
            )
    if title is None or title is True:
        title = (
            con.title + ": linkage to scale,\naccelerations drawn at their points"
            if arrows_all
            else con.title
        )
    if title:
        ax.set_title(title, fontsize=style.TITLE_SIZE)
    if legend and (kinds or clines):
        _legend(
            ax,
            kinds,
            bool(clines),
            loc="upper center",
            bbox_to_anchor=(0.5, 0.0),
            ncol=3,
            borderaxespad=0.2,
        )
    if own:
        _caption(fig, con, step)
    return fig


# ---------------------------------------------------------------- polygons
def diagrams(con):
    """The polygon diagrams this construction has, in drawing order."""
    return [d for d in DIAGRAMS if con.items(d)[0]]


def draw_polygon(
    con,
    diagram,
    step=None,
    ax=None,
    *,
    units=None,
    inset=True,
    legend=None,
    title=True,
    scale_bar=True,
    box=None,
    pole=True,
    highlight=False,
):
    """One polygon: ``diagram`` is ``"velocity"``, ``"acceleration"`` or
    ``"point"``. ``box`` (x0, x1, y0, y1 in the drawing's unit) fixes the frame,
    so that several polygons are drawn at one scale. ``highlight`` lays a pale
    band under what ``step`` itself adds. Returns ``(figure, kinds drawn,
    whether construction lines were drawn)``."""
    own = ax is None
    if own:
        _, ax = plt.subplots(figsize=(6.4, 5.6), layout="constrained")
    quantity, default_title = DIAGRAMS[diagram]
    uname, uf = units_of(con, units)[quantity]
    arrows_all, clines_all, _ = con.items(diagram)
    arrows, clines, _ = con.items(diagram, step)
    new = _added_by(con, step) if highlight else ()
    drawn = [(a.start * uf, a.vector * uf) for a in arrows]
    every = [(a.start * uf, a.vector * uf) for a in arrows_all]
    ends = [0j] + [s for s, _ in every] + [s + v for s, v in every]
    x0, x1, y0, y1 = _extent(ends)
    size = max(x1 - x0, y1 - y0) or 1.0
    if box is not None:  # a given frame fixes the scale bar too
        size = 0.7 * max(box[1] - box[0], box[3] - box[2])
    box = _frame(ax, ends, 0.14 * size, strip=0.12 if scale_bar else 0.0, box=box)
    span = max(box[1] - box[0], box[3] - box[2])
    ppd = _pts_per_data(ax)
    obstacles = _obstacles([], every, [(ln.point * uf, ln.direction) for ln in clines_all], box)

    def paint(target, labels, region=None, tiny=()):
        main = region is None
        ppd_t = ppd if main else _pts_per_data(target)
        frame = box if main else region
        for ln in clines:
            _construction_line(
                target,
                labels,
                ln.point * uf,
                ln.direction,
                ln.name,
                frame,
                letters=main,
                halo=_among(ln, new),
            )
        for a, (s, v) in zip(arrows, drawn):
            if _among(a, new) and abs(v) > 0:
                _halo(target, s, v)
            if _arrow(target, s, v, a.kind, ppd_t):
                labels.avoid(s, s + v, width=style.component(a.kind)["linewidth"])
        if pole:
            target.scatter([0.0], [0.0], s=22, color="black", zorder=9)
            labels.avoid_pin(0j, 3.0)
            if main or (region[0] <= 0 <= region[1] and region[2] <= 0 <= region[3]):
                labels.add_point(r"$o_V$" if diagram == "velocity" else r"$o_A$", 0j, priority=0)
        for i, (a, (s, v)) in enumerate(zip(arrows, drawn)):
            if abs(v) > 0 and (main != (i in tiny)):
                labels.add_vector(
                    f"${a.name}$",
                    s,
                    v,
                    color=_label_colour(a.kind),
                    priority=1 + (0 if a.kind == "resultant" else 0.5),
                )

    labels = _paint_with_inset(ax, box, drawn, span, ppd, inset, paint, obstacles, every)
    kinds = {a.kind for a in arrows}
    if scale_bar:
        L = nice(0.22 * size)
        _scale_bar(
            ax,
            labels,
            box[0] + 0.02 * span,
            box[2] - 0.07 * span,
            L,
            f"{fmt(L)} {uname}",
            0.008 * span,
        )
    if title:
        ax.set_title(default_title if title is True else title, fontsize=style.TITLE_SIZE)
    if legend or (legend is None and own):
        _legend(ax, kinds, bool(clines), loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=2)
    if own:
        _caption(ax.figure, con, step)
    return ax.figure, kinds, bool(clines)


def draw_polygons(con, step=None, units=None):
    """Every polygon of the construction in one figure, one legend: the
    acceleration polygon large, the velocity polygon (and that of the coupler
    point, if any) beside it."""
    names = diagrams(con)
    others = [n for n in names if n != "acceleration"]
    fig = plt.figure(figsize=(8.2, 6.0), layout="constrained")
    if "acceleration" in names and others:
        grid = fig.add_gridspec(len(others), 2, width_ratios=[1.75, 1])
        axes = {"acceleration": fig.add_subplot(grid[:, 0])}
        for k, n in enumerate(others):
            axes[n] = fig.add_subplot(grid[k, 1])
    else:
        grid = fig.add_gridspec(1, len(names))
        axes = {n: fig.add_subplot(grid[0, k]) for k, n in enumerate(names)}
    kinds, anylines = set(), False
    for name in names:
        _, k, ln = draw_polygon(con, name, step, axes[name], units=units)
        kinds |= k
        anylines |= ln
    _legend(fig, kinds, anylines, loc="outside lower center", ncol=3)
    fig.suptitle(con.title, fontsize=style.TITLE_SIZE + 1)
    _caption(fig, con, step)
    return fig


def save(con, outdir, stem, formats=("png", "svg"), step=None, units=None):
    """Write ``{stem}-linkage`` and ``{stem}-polygons`` in each format to
    ``outdir``; returns the list of paths written."""
    import os

    os.makedirs(outdir, exist_ok=True)
    paths = []
    for kind, maker in (("linkage", draw_linkage), ("polygons", draw_polygons)):
        fig = maker(con, step=step, units=units)
        for ext in formats:
            path = os.path.join(outdir, f"{stem}-{kind}.{ext}")
            fig.savefig(
                path, dpi=style.DPI, bbox_inches="tight", pad_inches=0.12, metadata=_metadata(ext)
            )
            paths.append(path)
        plt.close(fig)
    return paths


def _metadata(ext):
    """Reproducible files: no creation date or software version stamped in."""
    if ext == "svg":
        return {"Date": None, "Creator": None}
    if ext == "png":
        return {"Software": None}
    return None
