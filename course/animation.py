"""Mechanisms that move: the linkage through its cycle with its acceleration
vectors (drawn by the solver's linkage drawer, :func:`accelab.solver.graphical.draw.draw_linkage`),
and beside it a marker running along the curves of the angular accelerations
and of the accelerations of the points.

>>> from accelab.course.animation import animate
>>> from accelab.solver.graphical.gallery import EXAMPLE_7_1
>>> animate(EXAMPLE_7_1)            # shown in a notebook as a player

The result is shown in a **player** (:mod:`accelab.course.player`): play and
pause, step one frame back or on, a slider over the frames with the crank
angle of each, and a speed control, so that a lecturer can stop the linkage
where the curves peak and talk about that position. It is plain HTML and a
short script with the frames inside: it plays in Jupyter, on the
documentation site and in a saved page, with nothing fetched from the
network.

Each animation comes in two renditions of the same frames: ``wide`` (the
linkage beside its curves, 760 px across, for a laptop or a projector) and
``narrow`` (the linkage above its curves, 440 px across, for a phone); the
page shows the one that fits. A live notebook makes the wide one only. The
frames are few (36 by default), drawn at 100 dpi and stored as PNG with one
palette of 128 colours, so that an animation weighs a few hundred kilobytes
and takes a few seconds to make.

Every frame is the graphical construction of that position (section 7.2), so
the vectors drawn are exact, and the curves come from the same constructions
at every 2 degrees.
"""

import io
import math

import numpy as np

from accelab.course.player import player_html
from accelab.solver.graphical import construct_case
from accelab.solver.graphical import style as _style

__all__ = ["animate", "Animation", "DEFAULTS", "LAYOUTS"]

#: what to plot beside each mechanism: (angular curves, vector sizes); a name
#: ``"A_B.x"`` plots the x component of A_B with its sign instead of its size
DEFAULTS = {
    "fourbar": (("alpha3", "alpha4"), ("A_A", "A_B", "A_P")),
    "slidercrank": (("alpha3",), ("A_A", "A_B.x")),
    "invertedslidercrank": (("alpha4",), ("A_A", "A_B", "A_coriolis")),
    "fivebar": (("alpha3", "alpha4"), ("A_A", "A_B", "A_C")),
    "rotation": (("omega2",), ("A_t", "A_n", "A")),
}
#: how each name reads on the plots
SYMBOLS = {
    "alpha3": r"$\alpha_3$",
    "alpha4": r"$\alpha_4$",
    "alpha5": r"$\alpha_5$",
    "omega2": r"$\omega_2$",
    "omega3": r"$\omega_3$",
    "omega4": r"$\omega_4$",
    "A_A": r"$|\mathbf{A}_A|$",
    "A_B": r"$|\mathbf{A}_B|$",
    "A_C": r"$|\mathbf{A}_C|$",
    "A_P": r"$|\mathbf{A}_P|$",
    "A_PA": r"$|\mathbf{A}_{PA}|$",
    "A_coriolis": r"$|\mathbf{A}_{cor}|$",
    "A_t": r"$|\mathbf{A}^t|$",
    "A_n": r"$|\mathbf{A}^n|$",
    "A": r"$|\mathbf{A}|$",
    "A_B.x": r"$A_{B,x}$",
    "A_A.x": r"$A_{A,x}$",
}
#: the colours of the curves, in order (Okabe-Ito, as the drawings)
CURVE_COLOURS = [
    "#000000",
    _style.OKABE_ITO["vermillion"],
    _style.OKABE_ITO["blue"],
    _style.OKABE_ITO["green"],
]
#: curves of a vector component take the colour of its kind in the drawings
KIND_COLOURS = {
    "A_t": _style.COMPONENT["tangential"]["color"],
    "A_n": _style.COMPONENT["normal"]["color"],
    "A_coriolis": _style.COMPONENT["coriolis"]["color"],
    "A_slip": _style.COMPONENT["slip"]["color"],
}
#: the two renditions: figure size [in] at 100 dpi, and the linkage beside or above the curves
LAYOUTS = {
    "wide": {"size": (7.6, 3.7), "beside": True},
    "narrow": {"size": (4.4, 6.3), "beside": False},
}
DPI = 100
#: text sizes of the frames [pt]: at 100 dpi, 10 pt is 13.9 px at full size, and
#: still about 11 px when the narrow rendition fills a phone's 358 px
FONTS = {
    "font.size": 10,
    "axes.titlesize": 10.5,
    "axes.labelsize": 10,
    "legend.fontsize": 10,
    "xtick.labelsize": 10,
    "ytick.labelsize": 10,
    "axes.titley": 1.0,  # titles at a fixed height: matplotlib need not measure the axes again
}


class Animation:
    """An animation a notebook shows as a player (``_repr_html_``).

    Attributes
    ----------
    renditions : dict
        ``{"wide": [png bytes, ...], "narrow": [...]}``: the frames of each
        rendition made (a live notebook makes the wide one only).
    labels : list of str
        The input angle of each frame, as the player shows it.
    sizes : dict
        ``{rendition: (width, height)}`` of its frames [px].
    alt : str
        What it shows, in words.
    """

    def __init__(self, renditions, labels, sizes, alt, fps=10):
        self.renditions = renditions
        self.labels = labels
        self.sizes = sizes
        self.alt = alt
        self.fps = fps

    @property
    def frames(self):
        return len(self.labels)

    def __len__(self):
        return sum(len(f) for frames in self.renditions.values() for f in frames)

    def html(self):
        """The player (HTML, self-contained)."""
        return player_html(self.renditions, self.labels, self.alt, self.sizes, self.fps)

    def _repr_html_(self):
        return self.html()

    def save(self, path, rendition="wide"):
        """Write one rendition as an animated PNG (for slides): ``path``."""
        from PIL import Image

        frames = [Image.open(io.BytesIO(f)) for f in self.renditions[rendition]]
        frames[0].save(
            path,
            format="PNG",
            save_all=True,
            append_images=frames[1:],
            duration=int(1000 / self.fps),
            loop=0,
        )
        return path

    def __repr__(self):
        kinds = ", ".join(f"{r} {w}x{h} px" for r, (w, h) in self.sizes.items())
        return f"<Animation: {self.frames} frames ({kinds}), {len(self) / 1024:.0f} KiB>"


def _encode(images, colours=128):
    """PNG bytes of each RGB image (H x W x 3 uint8 arrays), on one shared palette
    of ``colours`` (median cut over a few frames), each pixel mapped to its nearest
    entry exactly (Pillow's own mapping is approximate and greys the white paper).
    A colour's entry is looked up once per animation (the frames share most colours)."""
    from PIL import Image

    h, w = images[0].shape[:2]
    picks = images[:: max(1, len(images) // 4)][:4]
    montage = Image.fromarray(np.concatenate(picks, axis=0), mode="RGB")
    quantized = montage.quantize(colors=colours, method=Image.Quantize.MEDIANCUT)
    entries = np.array(quantized.getpalette()[: 3 * colours], dtype=np.int32).reshape(-1, 3)
    entries[np.argmax(entries.sum(axis=1))] = 255  # the paper stays white
    flat = entries.astype(np.uint8).ravel().tolist()
    unseen = 255  # no entry has this index (colours < 255)
    lookup = np.full(1 << 24, unseen, dtype=np.uint8)  # 0xRRGGBB -> palette index
    out = []
    for im in images:
        rgb = im.reshape(-1, 3).astype(np.int32)
        key = (rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2]
        index = lookup[key]
        new = index == unseen
        if new.any():  # colours not met in the frames before: their nearest entries
            unique = np.unique(key[new])
            colour = np.stack([unique >> 16, (unique >> 8) & 255, unique & 255], axis=1)
            lookup[unique] = np.argmin(
                ((colour[:, None, :] - entries[None, :, :]) ** 2).sum(axis=2), axis=1
            )
            index = lookup[key]
        frame = Image.fromarray(index.reshape(h, w), mode="P")
        frame.putpalette(flat)
        buf = io.BytesIO()
        frame.save(buf, "PNG", compress_level=6)  # 9: 2.5x the time for 8 % less
        out.append(buf.getvalue())
    return out


def _wipe(ax):
    """Take every drawn thing off ``ax`` for the next frame, keeping the axes themselves:
    ``ax.clear()`` also rebuilds both axes' ticks (a fifth of a frame's time), and the
    linkage drawer sets the limits, aspect, axis and title again on every frame."""
    for group in (ax.lines, ax.patches, ax.collections, ax.texts, ax.artists, ax.images):
        for artist in list(group):
            artist.remove()


def _cycle(case, angles, motion):
    """The construction of ``case`` at each angle [deg] of ``angles``."""
    out = []
    for deg in angles:
        c = dict(case, theta2=f"{float(deg)!r} deg")
        if motion is not None:
            c.update(motion(deg))
        out.append(construct_case(c))
    return out


def _value(con, name, motion_values):
    if name in con.values:
        return con.values[name]
    return motion_values[name]


def animate(
    case,
    *,
    frames=36,
    angles=None,
    motion=None,
    curves=None,
    magnitudes=None,
    kinds=("resultant",),
    title=None,
    names=None,
    trace=(),
    extra=None,
    symbols=None,
    alt=None,
    layouts=None,
    fps=10,
    dpi=DPI,
):
    """Animate ``case`` (a batch case, as docs/conventions.md describes) through its cycle.

    Parameters
    ----------
    case : dict
        The mechanism and its input; ``theta2`` is replaced by each angle.
    frames : int
        Frames of the animation (spread evenly over ``angles``).
    angles : (start, stop), optional
        The input angles of the cycle [deg] (default 0 to 360; a geared
        fivebar whose ratio is not a whole number needs more).
    motion : callable, optional
        ``motion(theta2_deg) -> dict`` of case entries that change with the
        angle (e.g. ``{"omega2": "12 rad/s"}`` for a crank speeding up); the
        values it returns are plotted when named in ``curves``.
    curves, magnitudes : sequence of str, optional
        Construction values to plot beside the linkage: angular ones
        (``alpha3`` ...) on top, vectors below: by their size (``A_B``), or
        one component with its sign (``A_B.x``, ``A_B.y``). Defaults per
        mechanism in :data:`DEFAULTS`.
    kinds : sequence of str
        Which vectors to draw on the linkage (``"resultant"``, ``"normal"``,
        ``"tangential"``, ``"coriolis"``, ``"slip"``).
    title : str, optional
    names : dict, optional
        New names for the linkage's points, e.g. ``{"O2": "O"}``.
    trace : sequence of str
        Points whose paths over the cycle are drawn (e.g. ``("P",)``: a coupler curve).
    extra : callable, optional
        ``extra(construction) -> [(start, vector, kind, label), ...]``: more
        arrows to draw on each frame, at the frame's scale (e.g. the triangle
        of an acceleration difference); ``vector`` [m/s^2] is complex, and
        ``start`` a point [m] (complex) or ``(point, offset)``, the point
        moved by the acceleration ``offset`` [m/s^2] drawn at the frame's
        scale (the tip of an arrow drawn from that point).
    symbols : dict, optional
        How the curves' names read on the plots (mathtext), beside :data:`SYMBOLS`.
    alt : str, optional
        What the animation shows, for a reader who cannot see it.
    layouts : sequence of str, optional
        Renditions to make (:data:`LAYOUTS`); default both when executed
        headless (the site), the wide one in a live notebook.
    fps, dpi :
        Frames per second at normal speed, and resolution [px per in].

    Returns
    -------
    Animation
    """
    import matplotlib
    import matplotlib.pyplot as plt

    from accelab.course.kit import is_static
    from accelab.course.mathtext_cache import install

    install()  # the frames share their labels and titles: typeset each once
    from accelab.solver.graphical.draw import arrow as draw_arrow
    from accelab.solver.graphical.draw import draw_linkage, units_of

    if layouts is None:
        layouts = tuple(LAYOUTS) if is_static() else ("wide",)
    names_of = dict(SYMBOLS, **(symbols or {}))
    start, stop = angles or (0.0, 360.0)
    fine = np.linspace(start, stop, int(round(abs(stop - start) / 2.0)) + 1)
    motion_values = [dict(motion(d)) if motion else {} for d in fine]
    cons = _cycle(case, fine, motion)
    mech = cons[0].mechanism
    default_curves, default_mags = DEFAULTS.get(mech, ((), ()))
    curves = list(curves if curves is not None else default_curves)
    magnitudes = [
        m
        for m in (magnitudes if magnitudes is not None else default_mags)
        if m.split(".")[0] in cons[0].values
    ]
    units = units_of(cons[0])
    lname, lf = units["length"]
    aname, af = units["acceleration"]

    def series(name):
        vals = []
        for con, mv in zip(cons, motion_values):
            v = _value(con, name, mv)
            if isinstance(v, str):
                from accelab.solver.units import Q_

                v = Q_(v).to_base_units().magnitude
            vals.append(v)
        return np.array(vals)

    def vector_series(name):
        base, _, part = name.partition(".")
        z = series(base) * af
        return {"x": z.real, "y": z.imag}[part] if part else np.abs(z)

    curve_data = {n: series(n) for n in curves}
    mag_data = {n: vector_series(n) for n in magnitudes}
    extras = [list(extra(con)) if extra else [] for con in cons]

    # one frame and one vector scale for every position
    vecs = [
        (a.start * lf, a.vector * af)
        for con in cons
        for a in con.items("linkage")[0]
        if a.kind in kinds
    ]
    big = max([abs(v) for _, v in vecs] + [abs(v) * af for m in extras for _, v, _, _ in m] or [0])
    pts = [z * lf for con in cons for z in con.linkage.points.values()]
    size_l = max(
        max(z.real for z in pts) - min(z.real for z in pts),
        max(z.imag for z in pts) - min(z.imag for z in pts),
    )
    scale = 0.45 * size_l / big if big > 0 else 1.0

    def origin(start):  # where an extra arrow starts, in drawing units
        if isinstance(start, tuple):
            return start[0] * lf + start[1] * af * scale
        return start * lf

    vecs += [(origin(s), v * af) for more in extras for s, v, _, _ in more]
    paths = {n: np.array([con.linkage.points[n] * lf for con in cons]) for n in trace}
    ends = pts + [s + v * scale for s, v in vecs]
    m = 0.06 * size_l
    box = (
        min(z.real for z in ends) - m,
        max(z.real for z in ends) + m,
        min(z.imag for z in ends) - m,
        max(z.imag for z in ends) + m,
    )
    picks = (
        np.linspace(0, len(fine) - 1, frames + 1)[:-1].round().astype(int)
        if math.isclose((stop - start) % 360, 0)
        else np.linspace(0, len(fine) - 1, frames).round().astype(int)
    )
    heading = title or cons[0].title
    labels = [f"\u03b8\u2082 = {fine[i]:.0f}\u00b0" for i in picks]
    first = next(iter(curve_data), "")
    renditions, sizes = {}, {}

    for layout in layouts:
        spec = LAYOUTS[layout]
        with matplotlib.rc_context(dict(FONTS, **{"figure.dpi": dpi})):
            fig = plt.figure(figsize=spec["size"], dpi=dpi, layout="constrained")
            if spec["beside"]:
                grid = fig.add_gridspec(2, 2, width_ratios=[1.25, 1])
                ax_l = fig.add_subplot(grid[:, 0])
                ax_c = fig.add_subplot(grid[0, 1])
                ax_m = fig.add_subplot(grid[1, 1], sharex=ax_c)
            else:
                grid = fig.add_gridspec(3, 1, height_ratios=[2.1, 1, 1])
                ax_l = fig.add_subplot(grid[0])
                ax_c = fig.add_subplot(grid[1])
                ax_m = fig.add_subplot(grid[2], sharex=ax_c)
            markers = []
            for ax, data in ((ax_c, curve_data), (ax_m, mag_data)):
                used = [KIND_COLOURS.get(n) for n in data]
                free = iter(c for c in CURVE_COLOURS if c not in used)
                for name, y in data.items():
                    colour = KIND_COLOURS.get(name) or next(free)
                    ax.plot(fine, y, color=colour, lw=1.6, label=names_of.get(name, name))
                    markers.append((ax.plot([], [], "o", color=colour, ms=6, zorder=5)[0], y))
                if data:
                    ax.legend(
                        loc="upper right",
                        ncol=len(data),
                        frameon=False,
                        borderaxespad=0.1,
                        handlelength=1.2,
                        columnspacing=0.7,
                        handletextpad=0.4,
                    )
                    lo = min(np.nanmin(y) for y in data.values())
                    hi = max(np.nanmax(y) for y in data.values())
                    pad = 0.5 * (hi - lo or 1.0)
                    ax.set_ylim(lo - 0.08 * pad, hi + pad)
                    if lo < 0 < hi:
                        ax.axhline(0, color="#999999", lw=0.7)
                ax.grid(alpha=0.3)
                ax.spines[["top", "right"]].set_visible(False)
            ax_c.set_ylabel("rad/s" if first.startswith("omega") else r"rad/s$^2$")
            ax_m.set_ylabel(aname)
            ax_m.set_xlabel(r"$\theta_2$ [deg]")
            ax_m.set_xlim(start, stop)
            step = 90 if abs(stop - start) <= 360 else 180
            ax_m.set_xticks(np.arange(start, stop + 1, step))
            plt.setp(ax_c.get_xticklabels(), visible=False)
            cursors = [ax.axvline(start, color="#999999", lw=0.8) for ax in (ax_c, ax_m)]

            def frame(k, ax_l=ax_l, markers=markers, cursors=cursors):
                i = picks[k]
                _wipe(ax_l)
                draw_linkage(
                    cons[i],
                    ax=ax_l,
                    scale=scale,
                    box=box,
                    kinds=kinds,
                    lines=False,
                    names=names,
                    inset=False,
                    legend=False,
                    scale_bars=True,
                    title=rf"{heading}, $\theta_2$ = {fine[i]:.0f}$^\circ$",
                )
                for s, v, kind, label in extras[i]:
                    draw_arrow(ax_l, origin(s), v * af, kind, label, scale)
                for path in paths.values():
                    ax_l.plot(
                        path.real, path.imag, color="#9a9a9a", lw=1.0, ls=(0, (4, 2)), zorder=0
                    )
                for mk, y in markers:
                    mk.set_data([fine[i]], [y[i]])
                for c in cursors:
                    c.set_xdata([fine[i], fine[i]])

            frame(0)
            fig.canvas.draw()  # lay the figure out once ...
            fig.set_layout_engine("none")  # ... and keep it for every frame
            # what moves is drawn on a copy of what does not (the curves, their axes)
            moving = [ax_l] + [mk for mk, _ in markers] + cursors
            for artist in moving:
                artist.set_animated(True)
            fig.canvas.draw()
            still = fig.canvas.copy_from_bbox(fig.bbox)
            images = []
            for k in range(len(picks)):
                frame(k)
                fig.canvas.restore_region(still)
                for artist in moving:
                    fig.draw_artist(artist)
                images.append(np.asarray(fig.canvas.buffer_rgba())[:, :, :3].copy())
            plt.close(fig)
        renditions[layout] = _encode(images)
        sizes[layout] = (images[0].shape[1], images[0].shape[0])
    return Animation(
        renditions,
        labels,
        sizes,
        alt or f"{heading} through its cycle, with its accelerations",
        fps,
    )
