"""Mechanisms that move: the linkage through its cycle with its acceleration
vectors (drawn by the solver's linkage drawer, :func:`accelab.solver.graphical.draw.draw_linkage`),
and beside it a marker running along the curves of the angular accelerations
and of the sizes of the accelerations.

>>> from accelab.course.animation import animate
>>> from accelab.solver.graphical.gallery import EXAMPLE_7_1
>>> animate(EXAMPLE_7_1)            # shown in a notebook as an animated PNG

Made with :class:`matplotlib.animation.FuncAnimation` and written as an
animated PNG (APNG, by Pillow, which matplotlib already needs; one palette of
128 colours for every frame): a notebook shows it as an ordinary ``image/png``
output, so it plays in Jupyter, in the documentation site (where it is a
figure with its caption, like any other) and in any browser, with no
JavaScript and no ffmpeg. The frames are few (36 by default) and small (96
dpi, 710 px wide), so that one animation weighs well under a megabyte and
takes a few seconds to make.

Every frame is the graphical construction of that position (section 7.2), so
the vectors drawn are exact, and the curves come from the same constructions
at every 2 degrees.
"""

import math
import os
import tempfile

import numpy as np

from accelab.solver.graphical import construct_case
from accelab.solver.graphical import style as _style

__all__ = ["animate", "Animation", "DEFAULTS"]

#: what to plot beside each mechanism: (angular curves, vector magnitudes)
DEFAULTS = {
    "fourbar": (("alpha3", "alpha4"), ("A_A", "A_B", "A_P")),
    "slidercrank": (("alpha3",), ("A_A", "A_B")),
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
    "A_coriolis": r"$|\mathbf{A}_{cor}|$",
    "A_t": r"$|\mathbf{A}^t|$",
    "A_n": r"$|\mathbf{A}^n|$",
    "A": r"$|\mathbf{A}|$",
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


class Animation:
    """An animated PNG that a notebook shows inline (``_repr_png_``).

    Attributes
    ----------
    png : bytes
        The animation (APNG).
    frames : int
    width, height : int
        Its size [px].
    """

    def __init__(self, png, frames, width, height, alt):
        self.png = png
        self.frames = frames
        self.width = width
        self.height = height
        self.alt = alt

    def __len__(self):
        return len(self.png)

    def save(self, path):
        """Write the animated PNG to ``path``."""
        with open(path, "wb") as fh:
            fh.write(self.png)
        return path

    def _repr_png_(self):
        return self.png

    def __repr__(self):
        return (
            f"<Animation: {self.frames} frames, {self.width}x{self.height} px, "
            f"{len(self.png) / 1024:.0f} KiB animated PNG>"
        )


def _writer(fps, colours=128):
    """matplotlib's PillowWriter, taking each frame from the canvas that the
    animation has just drawn (instead of drawing the figure once more), and
    writing an animated PNG whose frames share one palette of ``colours``."""
    from matplotlib.animation import PillowWriter
    from PIL import Image

    class CanvasPngWriter(PillowWriter):
        def grab_frame(self, **savefig_kwargs):
            canvas = self.fig.canvas
            w, h = canvas.get_width_height(physical=True)
            self._frames.append(
                Image.frombuffer(
                    "RGBA", (w, h), bytes(canvas.buffer_rgba()), "raw", "RGBA", 0, 1
                ).convert("RGB")
            )

        def finish(self):
            frames = self._frames
            w, h = frames[0].size
            picks = frames[:: max(1, len(frames) // 4)][:4]
            montage = Image.new("RGB", (w, h * len(picks)), "white")
            for k, f in enumerate(picks):
                montage.paste(f, (0, h * k))
            palette = montage.quantize(colors=colours, method=Image.Quantize.MEDIANCUT)
            frames = [f.quantize(palette=palette, dither=Image.Dither.NONE) for f in frames]
            frames[0].save(
                self.outfile,
                format="PNG",
                save_all=True,
                append_images=frames[1:],
                duration=int(1000 / self.fps),
                loop=0,
                optimize=True,
            )

    return CanvasPngWriter(fps=fps)


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
    fps=10,
    dpi=96,
    size=(7.4, 3.5),
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
        (``alpha3`` ...) on top, vectors by their size (``A_B`` ...) below.
        Defaults per mechanism in :data:`DEFAULTS`.
    kinds : sequence of str
        Which vectors to draw on the linkage (``"resultant"``, ``"normal"``,
        ``"tangential"``, ``"coriolis"``, ``"slip"``).
    title : str, optional
    names : dict, optional
        New names for the linkage's points, e.g. ``{"O2": "O"}``.
    trace : sequence of str
        Points whose paths over the cycle are drawn (e.g. ``("P",)``: a coupler curve).
    fps, dpi, size :
        Frames per second, resolution and figure size [in].

    Returns
    -------
    Animation
    """
    import matplotlib
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation

    from accelab.solver.graphical.draw import draw_linkage, units_of

    start, stop = angles or (0.0, 360.0)
    fine = np.linspace(start, stop, int(round(abs(stop - start) / 2.0)) + 1)
    motion_values = [dict(motion(d)) if motion else {} for d in fine]
    cons = _cycle(case, fine, motion)
    mech = cons[0].mechanism
    default_curves, default_mags = DEFAULTS.get(mech, ((), ()))
    curves = list(curves if curves is not None else default_curves)
    magnitudes = [
        m for m in (magnitudes if magnitudes is not None else default_mags) if m in cons[0].values
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

    curve_data = {n: series(n) for n in curves}
    mag_data = {n: np.abs(series(n)) * af for n in magnitudes}

    # one frame and one vector scale for every position
    vecs = [
        (a.start * lf, a.vector * af)
        for con in cons
        for a in con.items("linkage")[0]
        if a.kind in kinds
    ]
    big = max((abs(v) for _, v in vecs), default=0.0)
    pts = [z * lf for con in cons for z in con.linkage.points.values()]
    size_l = max(
        max(z.real for z in pts) - min(z.real for z in pts),
        max(z.imag for z in pts) - min(z.imag for z in pts),
    )
    scale = 0.45 * size_l / big if big > 0 else 1.0
    paths = {n: np.array([con.linkage.points[n] * lf for con in cons]) for n in trace}
    ends = pts + [s + v * scale for s, v in vecs]
    m = 0.06 * size_l
    box = (
        min(z.real for z in ends) - m,
        max(z.real for z in ends) + m,
        min(z.imag for z in ends) - m,
        max(z.imag for z in ends) + m,
    )

    with matplotlib.rc_context(
        {
            "figure.dpi": dpi,
            "font.size": 9,
            "axes.titlesize": 10,
            "axes.labelsize": 9,
            "legend.fontsize": 8,
            "xtick.labelsize": 8,
            "ytick.labelsize": 8,
        }
    ):
        fig = plt.figure(figsize=size, dpi=dpi, layout="constrained")
        grid = fig.add_gridspec(2, 2, width_ratios=[1.3, 1])
        ax_l = fig.add_subplot(grid[:, 0])
        ax_c = fig.add_subplot(grid[0, 1])
        ax_m = fig.add_subplot(grid[1, 1], sharex=ax_c)
        markers = []
        for ax, data in ((ax_c, curve_data), (ax_m, mag_data)):
            free = iter(c for c in CURVE_COLOURS if c not in [KIND_COLOURS.get(n) for n in data])
            for name, y in data.items():
                colour = KIND_COLOURS.get(name) or next(free)
                ax.plot(fine, y, color=colour, lw=1.5, label=SYMBOLS.get(name, name))
                markers.append((ax.plot([], [], "o", color=colour, ms=6, zorder=5)[0], y))
            if data:
                ax.legend(
                    loc="upper right",
                    ncol=len(data),
                    frameon=False,
                    borderaxespad=0.1,
                    handlelength=1.4,
                    columnspacing=0.8,
                )
                lo = min(np.nanmin(y) for y in data.values())
                hi = max(np.nanmax(y) for y in data.values())
                pad = 0.3 * (hi - lo or 1.0)
                ax.set_ylim(lo - 0.08 * pad, hi + pad)
            ax.grid(alpha=0.3)
            ax.spines[["top", "right"]].set_visible(False)
        first = next(iter(curve_data), "")
        ax_c.set_ylabel("rad/s" if first.startswith("omega") else r"rad/s$^2$")
        ax_m.set_ylabel(aname)
        ax_m.set_xlabel(r"$\theta_2$ [deg]")
        ax_m.set_xlim(start, stop)
        step = 90 if abs(stop - start) <= 360 else 180
        ax_m.set_xticks(np.arange(start, stop + 1, step))
        plt.setp(ax_c.get_xticklabels(), visible=False)
        cursors = [ax.axvline(start, color="#999999", lw=0.8) for ax in (ax_c, ax_m)]
        picks = (
            np.linspace(0, len(fine) - 1, frames + 1)[:-1].round().astype(int)
            if math.isclose((stop - start) % 360, 0)
            else np.linspace(0, len(fine) - 1, frames).round().astype(int)
        )
        heading = title or cons[0].title

        def frame(k):
            i = picks[k]
            ax_l.clear()
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
            for path in paths.values():
                ax_l.plot(path.real, path.imag, color="#9a9a9a", lw=1.0, ls=(0, (4, 2)), zorder=0)
            for mk, y in markers:
                mk.set_data([fine[i]], [y[i]])
            for c in cursors:
                c.set_xdata([fine[i], fine[i]])
            return []

        frame(0)
        fig.canvas.draw()  # lay the figure out once ...
        fig.set_layout_engine("none")  # ... and keep it for every frame
        anim = FuncAnimation(fig, frame, frames=frames, interval=1000 / fps, blit=False)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "animation.png")
            anim.save(path, writer=_writer(fps), dpi="figure")
            with open(path, "rb") as fh:
                png = fh.read()
        width, height = (int(round(x)) for x in fig.get_size_inches() * dpi)
        plt.close(fig)
    return Animation(
        png, frames, width, height, alt=f"{heading} through its cycle, with its accelerations"
    )
