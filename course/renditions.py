"""Figures that read on a laptop and on a phone: one drawing, two renditions.

A figure laid out for a page 760 px wide (panels side by side) shrinks to
less than half its size on a phone, and its labels with it. :func:`show`
therefore asks the drawing for two layouts: ``draw(narrow=False)``, the wide
rendition (at most :data:`WIDE` px across), and ``draw(narrow=True)``, the
narrow one (at most :data:`NARROW` px, panels stacked), and shows

* in a live notebook, the wide rendition only, as an ordinary figure;
* executed headless (the site and the tests set ``ACCELAB_STATIC``), both, as
  one Markdown output of two images marked ``.accelab-wide`` and
  ``.accelab-narrow``: the site's stylesheet shows the one that fits the
  screen (the narrow one below 600 px), and each opens at full size.

>>> def draw(narrow):
...     fig, axes = panels(2, narrow, wide=(7.6, 3.6), tall=(4.4, 6.4))
...     ...
...     return fig
>>> show(draw, alt="What the two panels show")

A figure that is already narrow (one panel, at most :data:`SINGLE` px wide,
text of 10 pt or more) needs no second rendition: ``plt.show()`` it.
"""

import base64
import io

import matplotlib.pyplot as plt

from accelab.course.kit import is_static

__all__ = ["show", "panels", "legend", "png", "Renditions", "WIDE", "NARROW", "SINGLE", "DPI"]

#: resolution of every rendition [px per inch]: 1 in of figure is 100 CSS px at full size
DPI = 100
#: widest wide rendition [px]: the article column of the site at 1366 px
WIDE = 780
#: widest narrow rendition [px]: shown about 358 px wide on a 390 px phone, so that
#: 10 pt text (13.9 px) is still about 11 px there
NARROW = 460
#: widest figure shown in one rendition only [px]: 10 pt text stays near 9 px on a phone
SINGLE = 560


def png(fig, dpi=DPI):
    """The figure as PNG bytes, at ``dpi``; the figure is closed."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, facecolor="white")
    plt.close(fig)
    return buf.getvalue()


def _escape(alt):
    return " ".join(str(alt).replace("[", "(").replace("]", ")").split())


class Renditions:
    """Two PNG renditions of one figure (bytes), shown as a Markdown output."""

    def __init__(self, wide, narrow, alt):
        self.wide = wide
        self.narrow = narrow
        self.alt = _escape(alt)

    def _repr_markdown_(self):
        def image(data, kind):
            b64 = base64.b64encode(data).decode("ascii")
            return f"![{self.alt}](data:image/png;base64,{b64}){{.accelab-{kind}}}"

        return image(self.wide, "wide") + "\n\n" + image(self.narrow, "narrow") + "\n"

    def __repr__(self):
        return f"<figure in two renditions: {self.alt}>"


def show(draw, alt):
    """Show the figure ``draw(narrow)`` makes: its wide rendition in a live
    notebook; both renditions when executed headless (see the module's text).

    Parameters
    ----------
    draw : callable
        ``draw(narrow: bool)`` returns a matplotlib Figure.
    alt : str
        What the figure shows, for a reader who cannot see it.
    """
    from IPython.display import display

    if not is_static():
        fig = draw(False)
        display(fig)
        plt.close(fig)
        return None
    display(Renditions(png(draw(False)), png(draw(True)), alt))
    return None


def panels(n, narrow, wide=(7.6, 3.6), tall=(4.4, 6.4), **kw):
    """``(fig, axes)`` with ``n`` panels: side by side in the wide rendition
    (``wide`` = its size [in]), one above the other in the narrow one (``tall``).
    Keyword arguments go to :func:`matplotlib.pyplot.subplots` (``width_ratios``
    becomes ``height_ratios`` when the panels are stacked)."""
    if narrow:
        if "width_ratios" in kw:
            kw["height_ratios"] = kw.pop("width_ratios")
        kw.pop("sharey", None)
        return plt.subplots(n, 1, figsize=tall, **kw)
    kw.pop("height_ratios", None)
    return plt.subplots(1, n, figsize=wide, **kw)


def legend(where, kinds, lines=False, ncol=1, **kw):
    """A legend of the vector kinds drawn (colours, line styles and names of
    :mod:`accelab.solver.graphical.style`), on an Axes or a Figure: for a
    figure too narrow for the drawer's own legend of three columns."""
    from matplotlib.lines import Line2D

    from accelab.solver.graphical import style

    handles = [
        Line2D(
            [],
            [],
            color=style.component(k)["color"],
            linestyle=style.component(k)["linestyle"],
            linewidth=style.component(k)["linewidth"],
            label=style.component(k)["label"],
        )
        for k in style.COMPONENT
        if k in kinds
    ]
    if lines:
        handles.append(Line2D([], [], label="construction line", **style.CONSTRUCTION_LINE))
    kw.setdefault("frameon", False)
    kw.setdefault("handlelength", 2.6)
    return where.legend(handles=handles, ncol=ncol, **kw)
