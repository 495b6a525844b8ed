"""Labels placed where they overlap nothing, decided when the figure is drawn.

A :class:`LabelLayer` is an artist added to one Axes. The drawing tells it
what to keep clear of (link and vector segments, pins, construction lines)
and what to label (a point, a vector); at draw time, when the final size of
the axes and of every text is known, it places each label at the best of a
few candidate spots around its anchor: inside the axes, clear of the other
labels and of the drawing, as near the anchor as possible. A label that
finds no clear spot near its anchor goes a little farther out, joined to it
by a thin leader line.

Placing at draw time makes the result independent of the figure's layout
engine, of the DPI it is saved at and of the format (PNG or SVG).
"""

import math
from typing import Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.lines import Line2D
from matplotlib.text import Text
from matplotlib.transforms import IdentityTransform

from . import style

#: cost of one label spot: what each fault weighs (distances in pixels)
COST_OUTSIDE = 1e5  # any part of the label outside the axes
COST_OVERLAP = 4e3  # per unit of overlapped area (fraction of the label's own area)
COST_TOUCH = 600.0  # per label it overlaps at all
COST_SEGMENT = 900.0  # per link or vector it crosses (times the segment's weight)
COST_PIN = 900.0  # per pin inside it
COST_LEADER = 120.0  # a spot that needs a leader line
COST_DISTANCE = 1.5  # per pixel from the anchor


#: (text, size, style, weight) -> (width, height) [pt]
_SIZES: dict[tuple[Any, ...], tuple[float, float]] = {}


def _segments_hit(seg, halfwidth, boxes):
    """Which segments cross which boxes: ``seg`` an N x 4 array of x0 y0 x1 y1,
    ``boxes`` an M x 4 array of x0 y0 x1 y1 (pixels), each box grown by each
    segment's half width. Returns an M x N boolean array (Liang-Barsky)."""
    boxes = np.atleast_2d(np.asarray(boxes, dtype=float))
    if len(seg) == 0:
        return np.zeros((len(boxes), 0), dtype=bool)
    bx0 = boxes[:, :1] - halfwidth
    by0 = boxes[:, 1:2] - halfwidth
    bx1 = boxes[:, 2:3] + halfwidth
    by1 = boxes[:, 3:4] + halfwidth
    x0, y0, x1, y1 = seg.T
    dx, dy = x1 - x0, y1 - y0
    shape = (len(boxes), len(seg))
    t0 = np.zeros(shape)
    t1 = np.ones(shape)
    ok = np.ones(shape, dtype=bool)
    for p, q in ((-dx, x0 - bx0), (dx, bx1 - x0), (-dy, y0 - by0), (dy, by1 - y0)):
        p = np.broadcast_to(p, shape)
        flat = np.abs(p) < 1e-12
        ok &= ~(flat & (q < 0))
        r = q / np.where(flat, 1.0, p)
        t0 = np.where(~flat & (p < 0), np.maximum(t0, r), t0)
        t1 = np.where(~flat & (p > 0), np.minimum(t1, r), t1)
    return ok & (t0 <= t1)


def _overlap(a, b):
    """Area shared by two boxes (x0, y0, x1, y1)."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w * h if w > 0 and h > 0 else 0.0


class LabelLayer(Artist):
    """Labels of one Axes, placed at draw time (see the module docstring).

    Geometry is given in data coordinates; ``offset`` (a complex number, in
    points) shifts a segment or an anchor as drawn, for vectors drawn beside
    a link rather than on it.
    """

    def __init__(self, ax, fontsize=None, auto=False):
        super().__init__()
        self.ax = ax
        self.auto = auto  # also keep clear of every line and text of the axes
        self.fontsize = fontsize or style.LABEL_SIZE
        self.segments = []  # (z0, z1, weight, halfwidth [pt], offset [pt])
        self.pins = []  # (z, radius [pt])
        self.labels = []  # see add_point / add_vector / add_fixed
        self.placed = []  # pixel boxes of the last draw
        self.set_zorder(20)
        ax.add_artist(self)
        self.set_clip_on(False)

    # ------------------------------------------------------------ geometry
    def avoid(self, z0, z1, weight=1.0, width=2.0, offset=0j):
        """Keep labels off the segment z0-z1 (data); ``width`` is its line width [pt]."""
        self.segments.append((complex(z0), complex(z1), weight, 0.5 * width + 1.5, complex(offset)))

    def avoid_pin(self, z, radius=4.0):
        self.pins.append((complex(z), radius))

    # ------------------------------------------------------------ labels
    def add_point(self, text, z, color="black", priority=0, **kw):
        """A label beside the point z (a pin's name, the pole)."""
        self.labels.append(
            dict(kind="point", text=text, z=complex(z), color=color, priority=priority, kw=kw)
        )

    def add_vector(self, text, start, vector, color="black", priority=1, offset=0j, **kw):
        """A label beside the vector drawn from ``start`` (data) along ``vector``."""
        self.labels.append(
            dict(
                kind="vector",
                text=text,
                z=complex(start),
                v=complex(vector),
                color=color,
                priority=priority,
                offset=complex(offset),
                kw=kw,
            )
        )

    def add_fixed(self, text, z, color="black", boxed=True, **kw):
        """A label exactly at z (the letters at the ends of a construction line,
        a scale bar's value); the others keep clear of it. ``ha``/``va`` as for
        matplotlib's text (default: centred)."""
        self.labels.append(
            dict(
                kind="fixed", text=text, z=complex(z), color=color, priority=-1, boxed=boxed, kw=kw
            )
        )

    # ------------------------------------------------------------ drawing
    def _px(self, z, offset, ppt):
        x, y = self.ax.transData.transform((z.real, z.imag))
        return complex(x, y) + offset * ppt

    def _text(self, lab, renderer):
        kw = dict(lab["kw"])
        kw.setdefault("ha", "center")
        kw.setdefault("va", "center")
        t = Text(
            0.0,
            0.0,
            lab["text"],
            color=lab["color"],
            fontsize=kw.pop("fontsize", self.fontsize),
            transform=IdentityTransform(),
            **kw,
        )
        t.set_figure(self.figure)
        key = (lab["text"], t.get_fontsize(), t.get_fontstyle(), t.get_fontweight())
        ppt = renderer.points_to_pixels(1.0)
        if key not in _SIZES:  # a label's size in points does not depend on the DPI
            bb = t.get_window_extent(renderer)
            _SIZES[key] = (bb.width / ppt, bb.height / ppt)
        w, h = _SIZES[key]
        return t, w * ppt, h * ppt

    def _candidates(self, lab, w, h, ppt):
        """(centre [px], leader) candidates in order of preference."""
        gap = 7.0 * ppt  # clear of a link 4 pt wide, even at 45 degrees
        out = []
        if lab["kind"] == "fixed":
            return [(self._px(lab["z"], 0j, ppt), False)]
        if lab["kind"] == "point":
            c = self._px(lab["z"], 0j, ppt)
            for ring, leader in ((1.0, False), (2.6, True)):
                for k in range(12):
                    d = complex(
                        math.cos(k * math.pi / 6 + math.pi / 4),
                        math.sin(k * math.pi / 6 + math.pi / 4),
                    )
                    reach = abs(d.real) * w / 2 + abs(d.imag) * h / 2
                    out.append((c + d * (ring * (reach + 7.0 * ppt)), leader))
            return out
        p0 = self._px(lab["z"], lab["offset"], ppt)
        p1 = self._px(lab["z"] + lab["v"], lab["offset"], ppt)
        length = abs(p1 - p0)
        u = (p1 - p0) / length if length > 0 else 1 + 0j
        n = 1j * u
        across = abs(n.real) * w / 2 + abs(n.imag) * h / 2
        along = abs(u.real) * w / 2 + abs(u.imag) * h / 2
        for ring, leader in ((1.0, False), (3.0, True)):
            for f in (0.5, 0.35, 0.65, 0.22, 0.78):
                m = p0 + f * (p1 - p0)
                for side in (1, -1):
                    out.append((m + side * n * (ring * gap + across), leader))
            out.append((p1 + u * (ring * gap + along), leader))
            out.append((p0 - u * (ring * gap + along), leader))
        return out

    def draw(self, renderer):
        """Place every label and draw it; matplotlib calls this when it draws the
        figure, with the axes' final size and the renderer's DPI."""
        if not self.get_visible() or not self.labels:
            return
        ppt = renderer.points_to_pixels(1.0)
        seg = np.array(
            [
                [
                    *(lambda a: (a.real, a.imag))(self._px(z0, off, ppt)),
                    *(lambda b: (b.real, b.imag))(self._px(z1, off, ppt)),
                ]
                for z0, z1, _, _, off in self.segments
            ]
        ).reshape(-1, 4)
        weights = np.array([s[2] for s in self.segments])
        halfw = np.array([s[3] * ppt for s in self.segments])
        pins = [(self._px(z, 0j, ppt), r * ppt) for z, r in self.pins]
        frame = self.ax.bbox
        fixed_boxes = []
        if self.auto:  # the figure's own lines and texts (a notebook's hand-made figure)
            more, widths = [], []
            for line in self.ax.lines:
                if not line.get_visible() or line.get_linestyle() in ("None", "", " "):
                    continue
                xy = line.get_transform().transform(line.get_xydata())
                if len(xy) < 2 or not np.isfinite(xy).all():
                    continue
                more += [[*a, *b] for a, b in zip(xy[:-1], xy[1:])]
                widths += [0.5 * line.get_linewidth() * ppt + 1.5 * ppt] * (len(xy) - 1)
            if more:
                seg = np.vstack([seg, np.array(more)])
                halfw = np.concatenate([halfw, widths])
                weights = np.concatenate([weights, np.full(len(more), 0.6)])
            for t in self.ax.texts:
                if t.get_visible() and t.get_text():
                    bb = t.get_window_extent(renderer)
                    fixed_boxes.append((bb.x0, bb.y0, bb.x1, bb.y1))
        inner = (frame.x0 + 2, frame.y0 + 2, frame.x1 - 2, frame.y1 - 2)
        pad = 1.5 * ppt
        self.placed = list(fixed_boxes)
        order = sorted(range(len(self.labels)), key=lambda i: self.labels[i]["priority"])
        for i in order:
            lab = self.labels[i]
            if lab["kind"] == "point":
                z = self._px(lab["z"], 0j, ppt)
                if not (frame.x0 <= z.real <= frame.x1 and frame.y0 <= z.imag <= frame.y1):
                    continue  # a point outside the view (an inset's) has no label here
            text, w, h = self._text(lab, renderer)
            anchor = self._px(lab["z"], lab.get("offset", 0j), ppt)
            if lab["kind"] == "vector":
                anchor = anchor + 0.5 * (
                    self._px(lab["z"] + lab["v"], lab["offset"], ppt)
                    - self._px(lab["z"], lab["offset"], ppt)
                )
            cands = self._candidates(lab, w, h, ppt)
            boxes = np.array(
                [
                    (
                        c.real - w / 2 - pad,
                        c.imag - h / 2 - pad,
                        c.real + w / 2 + pad,
                        c.imag + h / 2 + pad,
                    )
                    for c, _ in cands
                ]
            )
            hits = _segments_hit(seg, halfw, boxes) @ weights if len(seg) else np.zeros(len(boxes))
            best = None
            for rank, ((c, leader), box) in enumerate(zip(cands, boxes)):
                cost = COST_DISTANCE * abs(c - anchor) + 0.5 * rank
                if leader:
                    cost += COST_LEADER
                if lab["kind"] != "fixed":
                    if (
                        box[0] < inner[0]
                        or box[1] < inner[1]
                        or box[2] > inner[2]
                        or box[3] > inner[3]
                    ):
                        cost += COST_OUTSIDE
                    area = (box[2] - box[0]) * (box[3] - box[1])
                    for other in self.placed:
                        shared = _overlap(box, other)
                        if shared:
                            cost += COST_TOUCH + COST_OVERLAP * shared / area
                    cost += COST_SEGMENT * float(hits[rank])
                    for z, r in pins:
                        if box[0] - r < z.real < box[2] + r and box[1] - r < z.imag < box[3] + r:
                            cost += COST_PIN
                if best is None or cost < best[0]:
                    best = (cost, c, tuple(box), leader)
            assert best is not None  # every label has at least one candidate spot
            _, c, box, leader = best
            if lab["kind"] == "fixed":
                text.set_position((c.real, c.imag))
                bb = text.get_window_extent(renderer)
                box = (bb.x0 - pad, bb.y0 - pad, bb.x1 + pad, bb.y1 + pad)
            self.placed.append(box)
            if leader:
                # from the anchor to the nearest point of the label's box
                ex = min(max(anchor.real, box[0]), box[2])
                ey = min(max(anchor.imag, box[1]), box[3])
                line = Line2D(
                    [anchor.real, ex],
                    [anchor.imag, ey],
                    color="#777777",
                    linewidth=0.7,
                    transform=IdentityTransform(),
                )
                line.set_figure(self.figure)
                line.draw(renderer)
            text.set_position((c.real, c.imag))
            if lab["kind"] != "fixed" or lab.get("boxed", True):
                text.set_bbox(dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.85))
            text.draw(renderer)
        self.stale = False


def labels_of(ax, auto=True):
    """The LabelLayer of ``ax`` (made on first use, keeping clear of every line
    and text of the axes when ``auto``)."""
    for a in ax.artists:
        if isinstance(a, LabelLayer):
            return a
    return LabelLayer(ax, auto=auto)


def layers(fig):
    """Every LabelLayer of a figure, in its axes and in their insets."""
    out: list[LabelLayer] = []
    stack = list(fig.axes)
    while stack:
        ax = stack.pop()
        stack.extend(getattr(ax, "child_axes", []))
        out.extend(a for a in ax.artists if isinstance(a, LabelLayer))
    return out


def label_texts(fig):
    """The text of every label the layers of ``fig`` place."""
    return [lab["text"] for layer in layers(fig) for lab in layer.labels]
