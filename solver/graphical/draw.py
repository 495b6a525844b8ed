"""Drawings of a graphical construction (matplotlib): the linkage to scale with
the acceleration components at their points (Figure 7-4a/d) and the velocity
and acceleration polygons (Figure 7-4b/c).

``step=k`` draws what steps 1..k of the construction have added (see
:class:`~solver.graphical.construction.Construction`), with that step's text
as the caption, so a notebook can walk through the method.
"""

import math
import re
import textwrap

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from . import style

DIAGRAM_UNITS = {"velocity": ("m/s", "Velocity polygon"),
                 "acceleration": (r"m/s$^2$", "Acceleration polygon"),
                 "point": (r"m/s$^2$", "Acceleration of P")}


# ---------------------------------------------------------------- helpers
def nice(x):
    """A round number (1, 2 or 5 times a power of ten) not above x > 0."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    e = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10 ** e <= x:
            return m * 10 ** e
    return 10 ** e


def fmt(x):
    """A scale-bar number without trailing noise."""
    return f"{x:.0f}" if x >= 1 else f"{x:.3g}"


def length_unit(size):
    """(factor, name) to show lengths of a linkage of this size [m]."""
    return (1e3, "mm") if size < 1.0 else (1.0, "m")


class _Labels:
    """Greedy placement of labels away from each other and from the drawing."""

    def __init__(self, ax, extent):
        self.ax = ax
        self.extent = extent
        self.obstacles = []  # complex points to keep away from
        self.placed = []

    def avoid_segment(self, z0, z1):
        n = max(5, min(60, int(40 * abs(z1 - z0) / self.extent) + 2))
        self.obstacles += [z0 + (z1 - z0) * k / (n - 1) for k in range(n)]

    def _score(self, z, rank, offset):
        d_obst = min((abs(z - p) for p in self.obstacles), default=offset)
        d_label = min((abs(z - p) for p in self.placed), default=3 * offset)
        return min(d_obst, offset) + min(d_label, 3 * offset) - 0.02 * offset * rank

    def place(self, text, candidates, offset=None, **kw):
        offset = offset or 0.06 * self.extent
        best = max(enumerate(candidates), key=lambda rc: self._score(rc[1], rc[0], offset))[1]
        self.placed.append(best)
        return self.ax.text(best.real, best.imag, text, ha="center", va="center",
                            fontsize=style.LABEL_SIZE, zorder=10,
                            bbox=dict(boxstyle="round,pad=0.12", fc="white", ec="none",
                                      alpha=0.8), **kw)


def _arrow(ax, start, vector, kind, head):
    """Shaft with the kind's line style and a solid arrowhead of size ``head``."""
    st = style.component(kind)
    length = abs(vector)
    if length == 0.0 or not math.isfinite(length):
        return False
    u = vector / length
    h = min(head, 0.45 * length)
    w = 0.38 * h
    tip = start + vector
    base = tip - h * u
    ax.plot([start.real, base.real], [start.imag, base.imag], color=st["color"],
            linestyle=st["linestyle"], linewidth=st["linewidth"], zorder=6,
            solid_capstyle="butt", dash_capstyle="butt")
    n = 1j * u * w
    tri = [(tip.real, tip.imag), ((base + n).real, (base + n).imag),
           ((base - n).real, (base - n).imag)]
    ax.add_patch(Polygon(tri, closed=True, facecolor=st["color"], edgecolor=st["color"],
                         linewidth=0.5, zorder=7))
    return True


def _label_candidates(start, vector, offset):
    u = vector / abs(vector)
    n = 1j * u
    out = []
    for f in (0.5, 0.35, 0.65, 0.2, 0.8):
        m = start + f * vector
        out += [m + offset * n, m - offset * n]
    out += [start + vector + 1.1 * offset * u]
    return out


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


def _construction_line(ax, labels, line, box):
    u = line.direction / abs(line.direction)
    x0, x1, y0, y1 = box
    inset = 0.03 * max(x1 - x0, y1 - y0)
    seg = _clip(line.point, u, (x0 + inset, x1 - inset, y0 + inset, y1 - inset))
    if seg is None:
        return
    z0, z1 = seg
    ax.plot([z0.real, z1.real], [z0.imag, z1.imag], zorder=3, **style.CONSTRUCTION_LINE)
    labels.avoid_segment(z0, z1)
    if line.name:
        letter = line.name[0]
        for z in (z0, z1):
            ax.text(z.real, z.imag, letter, fontsize=style.FONT_SIZE, style="italic",
                    color="#555555", ha="center", va="center", zorder=9,
                    bbox=dict(boxstyle="circle,pad=0.1", fc="white", ec="none"))
            labels.placed.append(z)


def _extent(points):
    xs = [z.real for z in points]
    ys = [z.imag for z in points]
    return min(xs), max(xs), min(ys), max(ys)


def _set_limits(ax, points, margin, strip=0.0):
    """Frame the points with a margin, plus a strip of ``strip`` times the
    frame's size below it for the scale bars. Returns the drawing's box (without
    the strip) and the strip's top y."""
    x0, x1, y0, y1 = _extent(points)
    box = (x0 - margin, x1 + margin, y0 - margin, y1 + margin)
    h = strip * max(box[1] - box[0], box[3] - box[2])
    ax.set_xlim(box[0], box[1])
    ax.set_ylim(box[2] - h, box[3])
    ax.set_aspect("equal")
    ax.axis("off")
    return box


def _scale_bar(ax, x, y, length_data, text, tick):
    ax.plot([x, x + length_data], [y, y], color="black", linewidth=2.0, zorder=8,
            solid_capstyle="butt")
    for xx in (x, x + length_data):
        ax.plot([xx, xx], [y - tick, y + tick], color="black", linewidth=1.5, zorder=8)
    ax.text(x + length_data / 2, y + 1.5 * tick, text, ha="center", va="bottom",
            fontsize=style.FONT_SIZE - 1, zorder=8)


def _legend(ax, kinds, with_lines, **kw):
    order = [k for k in style.COMPONENT if k in kinds]
    handles = [Line2D([], [], color=style.component(k)["color"],
                      linestyle=style.component(k)["linestyle"],
                      linewidth=style.component(k)["linewidth"],
                      label=style.component(k)["label"]) for k in order]
    if with_lines:
        handles.append(Line2D([], [], label="construction line", **style.CONSTRUCTION_LINE))
    if handles:
        ax.legend(handles=handles, fontsize=style.FONT_SIZE - 1, frameon=False,
                  handlelength=3.2, **kw)


def _caption(fig, con, step):
    if step is None:
        return
    step = con.index(step)
    if step == 0:
        return
    s = con.steps[step - 1]
    head = (f"Step {s.label}" if s.phase == "acceleration" else
            {"position": "Position", "velocity": f"Velocity {s.label}"}[s.phase])
    text = textwrap.fill(f"{head} ({step}/{len(con.steps)}): {s.text}", 100)
    text = _mathtext(text)
    fig.text(0.5, 0.0, text, ha="center", va="top", fontsize=style.FONT_SIZE)


_SYMBOL = re.compile(r"\b([AV])_([A-Za-z0-9]+)(?:\^([a-z]))?"
                     r"|\b(omega|alpha|theta|delta|gamma)(\d?)\b")


def _mathtext(text):
    """Step texts say A_BA^t, omega3 ...: show them as the chapter's symbols."""
    def sub(m):
        if m.group(1):
            sup = f"^{{{m.group(3)}}}" if m.group(3) else ""
            return rf"$\mathbf{{{m.group(1)}}}_{{{m.group(2)}}}{sup}$"
        sym = "\\" + m.group(4)
        return f"${sym}_{{{m.group(5)}}}$" if m.group(5) else f"${sym}$"
    return _SYMBOL.sub(sub, text).replace("^2", "$^2$")


# ---------------------------------------------------------------- linkage
def _pretty(name):
    return {"O2": r"$O_2$", "O4": r"$O_4$", "O5": r"$O_5$"}.get(name, f"${name}$")


def _ground(ax, z, size):
    """A pivot's ground symbol: a hatched triangle under the pin."""
    tri = [(z.real, z.imag), (z.real - 0.6 * size, z.imag - size),
           (z.real + 0.6 * size, z.imag - size)]
    ax.add_patch(Polygon(tri, closed=True, facecolor="white", edgecolor="#222222",
                         hatch=style.GROUND_HATCH, linewidth=1.0, zorder=1))


def _block(ax, z, direction, size):
    u = direction / abs(direction)
    n = 1j * u
    corners = [z + sx * 0.9 * size * u + sy * 0.5 * size * n
               for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    ax.add_patch(Polygon([(c.real, c.imag) for c in corners], closed=True,
                         facecolor="#e6e6e6", edgecolor="#222222", linewidth=1.2, zorder=4))


def draw_linkage(con, step=None, ax=None, scale=None):
    """The linkage to scale with the acceleration components at their points.

    Parameters
    ----------
    con : Construction
    step : int or str, optional
        Draw only what steps 1..step add (default: the finished construction);
        a label such as ``"6"`` names a step of Example 7-1.
    ax : matplotlib Axes, optional
    scale : float, optional
        Drawing scale of the acceleration vectors [m of drawing per m/s^2];
        by default the longest vector is drawn half as long as the linkage.

    Returns
    -------
    matplotlib Figure
    """
    own = ax is None
    if own:
        _, ax = plt.subplots(figsize=(8.2, 6.4))
    fig = ax.figure
    lk = con.linkage
    pts = lk.points
    size = max((abs(p - q) for p in pts.values() for q in pts.values()), default=1.0) or 1.0
    arrows_all, _, _ = con.items("linkage")
    arrows, lines, _ = con.items("linkage", step)
    if scale is None:
        big = max((abs(a.vector) for a in arrows_all), default=0.0)
        scale = 0.5 * size / big if big > 0 else 1.0
    # the frame: the linkage and every vector of the finished drawing (steps line up)
    xs = list(pts.values())
    box = _set_limits(ax, xs + [a.start + a.vector * scale for a in arrows_all], 0.14 * size,
                      strip=0.16 if arrows_all else 0.08)
    labels = _Labels(ax, size)
    for link in lk.links:
        zs = [pts[n] for n in link]
        if len(link) == 3:
            ax.add_patch(Polygon([(z.real, z.imag) for z in zs], closed=True,
                                 **style.COUPLER_FILL))
        else:
            ax.plot([z.real for z in zs], [z.imag for z in zs], **style.LINK)
        for z0, z1 in zip(zs, zs[1:] + zs[:1] if len(zs) == 3 else zs[1:]):
            labels.avoid_segment(z0, z1)
    for p0, u in lk.slides:
        u = u / abs(u)
        ts = [((z - p0) * u.conjugate()).real for z in pts.values()]
        t0, t1 = min(ts + [0.0]) - 0.15 * size, max(ts + [0.0]) + 0.15 * size
        za, zb = p0 + t0 * u, p0 + t1 * u
        ax.plot([za.real, zb.real], [za.imag, zb.imag], color="#222222", linewidth=1.0,
                linestyle="-.", zorder=1)
        labels.avoid_segment(za, zb)
    for p0, u, t0, t1 in lk.rods:
        u = u / abs(u)
        za, zb = p0 + t0 * u, p0 + t1 * u
        ax.plot([za.real, zb.real], [za.imag, zb.imag], color="#4d4d4d", linewidth=2.2,
                zorder=2)
        labels.avoid_segment(za, zb)
    for name, u in lk.blocks:
        _block(ax, pts[name], u, 0.06 * size)
    for g in lk.ground:
        _ground(ax, pts[g], 0.05 * size)
    ax.scatter([z.real for z in xs], [z.imag for z in xs], **style.PIN)
    for ln in lines:
        _construction_line(ax, labels, ln, box)
    kinds = set()
    head = 0.04 * size
    for a in arrows:
        v = a.vector * scale
        if _arrow(ax, a.start, v, a.kind, head):
            kinds.add(a.kind)
            labels.avoid_segment(a.start, a.start + v)
    centre = sum(xs) / len(xs)
    for name, z in pts.items():
        away = z - centre
        away = away / abs(away) if abs(away) > 0 else 1j
        labels.place(_pretty(name), [z + 0.07 * size * away * r for r in
                                     (1, complex(0.7, 0.7), complex(0.7, -0.7), 1j, -1j, -1)])
    for a in arrows:
        v = a.vector * scale
        if abs(v) > 0:
            labels.place(f"${a.name}$", _label_candidates(a.start, v, 0.065 * size),
                         0.065 * size,
                         color=_label_colour(a.kind))
    x0, x1, y0, y1 = box
    span = max(x1 - x0, y1 - y0)
    f, unit = length_unit(size)
    L = nice(0.25 * size * f) / f
    _scale_bar(ax, x0 + 0.02 * span, y0 - 0.05 * span, L, f"lengths: {fmt(L * f)} {unit}",
               0.008 * span)
    if arrows_all:
        Aval = nice(0.25 * size / scale)
        _scale_bar(ax, x0 + 0.02 * span, y0 - 0.13 * span, Aval * scale,
                   f"accelerations: {fmt(Aval)} " + r"m/s$^2$", 0.008 * span)
    ax.set_title(con.title + ": linkage to scale,\naccelerations drawn at their points",
                 fontsize=style.TITLE_SIZE)
    _legend(ax, kinds, bool(lines), loc="upper left", bbox_to_anchor=(1.0, 1.0))
    if own:
        _caption(fig, con, step)
    return fig


def _label_colour(kind):
    return "black" if kind == "resultant" else style.component(kind)["color"]


# ---------------------------------------------------------------- polygons
def diagrams(con):
    """The polygon diagrams this construction has, in drawing order."""
    return [d for d in DIAGRAM_UNITS if con.items(d)[0]]


def draw_polygon(con, diagram, step=None, ax=None):
    """One polygon: ``diagram`` is ``"velocity"``, ``"acceleration"`` or
    ``"point"``. Returns ``(figure, kinds drawn, whether lines were drawn)``."""
    own = ax is None
    if own:
        _, ax = plt.subplots(figsize=(6.5, 6.0))
    unit, title = DIAGRAM_UNITS[diagram]
    arrows_all, _, _ = con.items(diagram)
    arrows, lines, _ = con.items(diagram, step)
    ends = [0j] + [a.start for a in arrows_all] + [a.tip for a in arrows_all]
    x0, x1, y0, y1 = _extent(ends)
    size = max(x1 - x0, y1 - y0) or 1.0
    box = _set_limits(ax, ends, 0.16 * size, strip=0.08)
    labels = _Labels(ax, size)
    for ln in lines:
        _construction_line(ax, labels, ln, box)
    kinds = set()
    head = 0.04 * size
    for a in arrows:
        if _arrow(ax, a.start, a.vector, a.kind, head):
            kinds.add(a.kind)
            labels.avoid_segment(a.start, a.tip)
    ax.scatter([0.0], [0.0], s=22, color="black", zorder=9)
    pole = r"$o_V$" if diagram == "velocity" else r"$o_A$"
    labels.place(pole, [0.06 * size * z for z in (-1 - 1j, 1 - 1j, -1 + 1j, 1 + 1j)])
    for a in arrows:
        if abs(a.vector) > 0:
            labels.place(f"${a.name}$", _label_candidates(a.start, a.vector, 0.07 * size),
                         0.07 * size,
                         color=_label_colour(a.kind))
    bx0, bx1, by0, by1 = box
    span = max(bx1 - bx0, by1 - by0)
    L = nice(0.25 * size)
    _scale_bar(ax, bx0 + 0.02 * span, by0 - 0.05 * span, L, f"{fmt(L)} {unit}", 0.008 * span)
    ax.set_title(title, fontsize=style.TITLE_SIZE)
    if own:
        _legend(ax, kinds, bool(lines), loc="upper left", bbox_to_anchor=(1.0, 1.0))
        _caption(ax.figure, con, step)
    return ax.figure, kinds, bool(lines)


def draw_polygons(con, step=None):
    """Every polygon of the construction side by side, one legend."""
    names = diagrams(con)
    widths = {"velocity": 1.0, "acceleration": 1.3, "point": 0.9}
    fig, axes = plt.subplots(1, len(names), figsize=(4.6 * sum(widths[n] for n in names) + 2, 6),
                             gridspec_kw={"width_ratios": [widths[n] for n in names]},
                             squeeze=False)
    kinds, anylines = set(), False
    for name, ax in zip(names, axes[0]):
        _, k, ln = draw_polygon(con, name, step, ax)
        kinds |= k
        anylines |= ln
    _legend(axes[0][-1], kinds, anylines, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.suptitle(con.title, fontsize=style.TITLE_SIZE + 1)
    _caption(fig, con, step)
    return fig


def save(con, outdir, stem, formats=("png", "svg"), step=None):
    """Write ``{stem}-linkage`` and ``{stem}-polygons`` in each format to
    ``outdir``; returns the list of paths written."""
    import os
    os.makedirs(outdir, exist_ok=True)
    paths = []
    for kind, maker in (("linkage", draw_linkage), ("polygons", draw_polygons)):
        fig = maker(con, step=step)
        # the tight frame, measured once for every format (saves a layout pass each)
        bbox = fig.get_tightbbox(fig.canvas.get_renderer()).padded(0.15)
        for ext in formats:
            path = os.path.join(outdir, f"{stem}-{kind}.{ext}")
            fig.savefig(path, dpi=style.DPI, bbox_inches=bbox, metadata=_metadata(ext))
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
