"""Figures of a construction drawn with the polygon builder (matplotlib, PNG):

* the student's drawing of a polygon with each wrong step marked (a red
  outline and a numbered badge), for the grader's feedback;
* the finished construction, where the builder cannot run (a page of the
  course site, a notebook executed headless).

The styles are the package's (:mod:`accelab.solver.graphical.style`): the
kinds of vector keep their colours and line styles.
"""

import io
import math
import re

from accelab.solver.graphical import style

from .record import read_steps
from .task import ideal_steps

WRONG = "#c0142b"
FONT = 13


def mathtext(name):
    """The chapter's symbol of a step name in mathtext: ``A_BA^t`` -> A_BA^t bold."""
    m = re.match(r"^([AV])_([A-Za-z0-9]+)(?:\^([a-z]+))?$", name)
    if not m:
        return name
    sub = m.group(2)
    sub = re.sub(r"^([A-Z])(\d)$", r"\1_\2", sub)
    sup = f"^{{{m.group(3)}}}" if m.group(3) else ""
    return rf"$\mathbf{{{m.group(1)}}}_{{{sub}}}{sup}$"


def _dot(u, v):
    return u.real * v.real + u.imag * v.imag


def _kinds(phase):
    return {t.name: t.kind for t in phase.terms + phase.resultants}


def _extent(phase, steps):
    pts = [0j]
    for s in steps:
        pts += [z for z in (s.tail, s.tip, s.through, s.at) if z is not None]
    f = phase.factor
    xs = [z.real * f for z in pts]
    ys = [z.imag * f for z in pts]
    size = max(max(xs) - min(xs), max(ys) - min(ys), 2 * phase.scale)
    m = 0.14 * size
    return min(xs) - m, max(xs) + m, min(ys) - m, max(ys) + m


def _clip_line(p, u, box):
    x0, x1, y0, y1 = box
    ts = []
    for t in (
        (x0 - p.real) / u.real if u.real else None,
        (x1 - p.real) / u.real if u.real else None,
        (y0 - p.imag) / u.imag if u.imag else None,
        (y1 - p.imag) / u.imag if u.imag else None,
    ):
        if t is not None:
            q = p + t * u
            if x0 - 1e-9 <= q.real <= x1 + 1e-9 and y0 - 1e-9 <= q.imag <= y1 + 1e-9:
                ts.append(t)
    if len(ts) < 2:
        return None
    return p + min(ts) * u, p + max(ts) * u


def _label_pole(ax, box, span, taken):
    """Write "pole" beside the pole, on the side farthest from every label and arrow
    (a short vector at the pole has its label there too), inside the frame."""
    import cmath

    x0, x1, y0, y1 = box
    r = 0.07 * span
    spots = [r * cmath.exp(1j * math.radians(45 * k)) for k in range(8)]
    inside = [
        z
        for z in spots
        if x0 + 0.6 * r <= z.real <= x1 - 0.6 * r and y0 + r / 3 <= z.imag <= y1 - r / 3
    ] or spots
    spot = max(inside, key=lambda z: min((abs(z - t) for t in taken), default=span))
    ax.text(
        spot.real,
        spot.imag,
        "pole",
        fontsize=FONT - 2,
        color="#333333",
        ha="center",
        va="center",
        zorder=9,
        bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},
    )


def draw_phase(ax, phase, steps, wrong=None, title=None):
    """Draw a student's ``steps`` (Drawn) of ``phase`` on ``ax``; ``wrong`` maps
    a step's index to the badge number it gets (drawn in red)."""
    from matplotlib.patches import Circle, FancyArrowPatch

    wrong = wrong or {}
    f = phase.factor
    kinds = _kinds(phase)
    box = _extent(phase, steps)
    x0, x1, y0, y1 = box
    span = max(x1 - x0, y1 - y0)
    ax.set_aspect("equal")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    s = phase.scale
    gx = [s * k for k in range(math.floor(x0 / s), math.ceil(x1 / s) + 1)]
    gy = [s * k for k in range(math.floor(y0 / s), math.ceil(y1 / s) + 1)]
    if len(gx) + len(gy) < 400:
        for x in gx:
            ax.axvline(x, color="#e3e3e3", lw=0.6, zorder=0)
        for y in gy:
            ax.axhline(y, color="#e3e3e3", lw=0.6, zorder=0)
    ax.set_xticks([])
    ax.set_yticks([])
    for side in ax.spines.values():
        side.set_color("#bbbbbb")
    ax.plot([0], [0], "o", ms=7, mfc="white", mec="black", zorder=8)
    badges = []
    taken = []  # points the pole's label keeps clear of: labels, and points along the arrows
    drawn = [z * f for st in steps for z in (st.tail, st.tip, st.at) if z is not None]
    centre = sum(drawn, 0j) / len(drawn) if drawn else 0j
    for st in steps:
        bad = st.index in wrong
        colour = WRONG if bad else None
        if st.op == "line":
            seg = _clip_line(st.through * f, st.direction, box)
            if seg:
                ax.plot(
                    [seg[0].real, seg[1].real],
                    [seg[0].imag, seg[1].imag],
                    color=colour or style.CONSTRUCTION_LINE["color"],
                    ls=(0, (8, 4)),
                    lw=1.6 if bad else 1.0,
                    zorder=2,
                )
                mid = st.through * f
                badges.append((st.index, mid))
        elif st.op == "vector":
            kind = kinds.get(st.name, "known")
            spec = style.component(kind if kind in style.COMPONENT else "known")
            a, b = st.tail * f, st.tip * f
            if abs(b - a) > 0:
                ax.add_patch(
                    FancyArrowPatch(
                        (a.real, a.imag),
                        (b.real, b.imag),
                        arrowstyle="-|>",
                        mutation_scale=16,
                        color=colour or spec["color"],
                        lw=spec["linewidth"] + (0.6 if bad else 0),
                        linestyle=spec["linestyle"],
                        shrinkA=0,
                        shrinkB=0,
                        zorder=6,
                    )
                )
                mid = (a + b) / 2
                n = 1j * (b - a) / abs(b - a)
                if _dot(n, mid - centre) < 0:  # the label outside the polygon
                    n = -n
                lab = mid + n * 0.045 * span
                taken.append(lab)
                taken += [a + (b - a) * k / 8 for k in range(9)]
                ax.text(
                    lab.real,
                    lab.imag,
                    mathtext(st.name),
                    fontsize=FONT,
                    color=colour or "#111111",
                    ha="center",
                    va="center",
                    zorder=9,
                    bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},
                )
                badges.append((st.index, mid - n * 0.04 * span))
        elif st.op == "point":
            ax.plot(
                [st.at.real * f],
                [st.at.imag * f],
                "o",
                ms=8,
                mfc="none",
                mec=colour or "black",
                mew=1.6,
                zorder=7,
            )
            badges.append((st.index, st.at * f))
    _label_pole(ax, box, span, taken)
    for index, z in badges:
        if index in wrong:
            r = 0.03 * span
            ax.add_patch(Circle((z.real, z.imag), r, color=WRONG, zorder=10))
            ax.text(
                z.real,
                z.imag,
                str(wrong[index]),
                color="white",
                fontsize=FONT - 2,
                ha="center",
                va="center",
                weight="bold",
                zorder=11,
            )
    unit = phase.unit.replace("^2", "$^2$")
    ax.set_title(f"{title or phase.title}\n1 square = {phase.scale:g} {unit}", fontsize=FONT)


def construction_png(task, steps=None, phase=None, title=None, wrong=None, dpi=100):
    """PNG bytes of ``steps`` (Drawn; None: the finished construction) of
    ``phase`` (a name; None: both polygons, one above the other)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = [phase] if phase else list(task.phases)
    fig, axes = plt.subplots(
        len(names), 1, figsize=(5.6, 4.6 * len(names)), dpi=dpi, layout="constrained", squeeze=False
    )
    for ax, name in zip(axes[:, 0], names):
        ph = task.phase(name)
        drawn = (
            read_steps(ideal_steps(ph)) if steps is None else [s for s in steps if s.phase == name]
        )
        what = "finished construction" if steps is None else "your construction"
        draw_phase(ax, ph, drawn, wrong, f"{ph.title} ({what})")
    if title:
        fig.suptitle(title, fontsize=FONT)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", facecolor="white")
    plt.close(fig)
    return buf.getvalue()
