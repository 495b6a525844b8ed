"""A schematic figure of a problem's linkage (PNG bytes), drawn by the solver's
linkage drawer (:func:`accelab.solver.graphical.draw.draw_linkage`) from the positions
of the instructor's preview variant. Every student's geometry differs, so the
figure is titled as a schematic and shows the chapter's symbols, not numbers."""

import io

from accelab.solver.batch import read_case

#: the input's symbols, written beside the driven pivot
INPUT = r"$\theta_2, \omega_2, \alpha_2$"


def _box(cons):
    """A frame [display length unit] that holds every construction's points."""
    from accelab.solver.graphical.draw import units_of

    pts = [z * units_of(c)["length"][1] for c in cons for z in c.linkage.points.values()]
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    size = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    m = 0.16 * size
    return min(xs) - m, max(xs) + m, min(ys) - m, max(ys) + m


def _fit_title(fig, ax, head, tail, margin=6.0):
    """Write the title ``head tail`` on one line if it fits the figure's width (less
    ``margin`` [px] each side), else ``tail`` (the parenthesis) on a line of its own, and
    ``head`` in as many lines as it needs: a family's long title is never cut off."""
    import textwrap

    room = fig.bbox.width - 2 * margin
    renderer = fig.canvas.get_renderer()

    def fits(text):
        ax.title.set_text(text)
        return ax.title.get_window_extent(renderer).width <= room

    if fits(f"{head} {tail}"):
        return
    for width in range(len(head), 10, -4):
        lines = textwrap.wrap(head, width) + [tail]
        if fits("\n".join(lines)):
            return
    ax.title.set_text("\n".join(textwrap.wrap(head, 10) + [tail]))


def statement_figure(problem, dpi=90, shared=True):
    """PNG bytes of the problem's figure, drawn to scale from its values.

    ``shared``: the figure stands in an assignment's notebook that every student
    receives, drawn from one variant, so its title says the reader's values
    differ; a practice problem's own figure (``shared=False``) says it is this
    problem's."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from accelab.solver.graphical import construct_case
    from accelab.solver.graphical.draw import draw_linkage, units_of

    spec = problem.figure
    con = construct_case(spec["case"])
    fig, ax = plt.subplots(figsize=(5.0, 3.6), dpi=dpi, layout="constrained")
    title = f"{problem.title} " + (
        "(schematic: your values differ)" if shared else "(this problem, to scale)"
    )
    if spec["mechanism"] == "rotation":
        # problem 7-1 style: the point at A and, later, at B on the same circle
        second = construct_case(spec["case_B"]) if "case_B" in spec else None
        box = _box([con] + ([second] if second else []))
        if second:  # the path from A to B, inside the frame too
            import numpy as np

            f = units_of(con)["length"][1]
            t = np.linspace(
                read_case(spec["case"]).params["theta2"],
                read_case(spec["case_B"]).params["theta2"],
                40,
            )
            r = abs(con.linkage.points["P"]) * f
            arc_x, arc_y = r * np.cos(t), r * np.sin(t)
            pad = 0.08 * r
            box = (
                min(box[0], arc_x.min() - pad),
                max(box[1], arc_x.max() + pad),
                min(box[2], arc_y.min() - pad),
                max(box[3], arc_y.max() + pad),
            )
        draw_linkage(
            con,
            ax=ax,
            vectors=False,
            symbols=True,
            names={"O2": "O", "P": "A"},
            notes={"O2": r"$\omega, \alpha$"},
            title=title,
            legend=False,
            scale_bars=False,
            box=box,
        )
        if second:
            ax.plot(arc_x, arc_y, "--", color="0.55", lw=1.0, zorder=0)
            draw_linkage(
                second,
                ax=ax,
                vectors=False,
                names={"O2": None, "P": "B"},
                title=title,
                legend=False,
                scale_bars=False,
                box=box,
                colour="#9a9a9a",
            )
    else:
        draw_linkage(
            con,
            ax=ax,
            vectors=False,
            symbols=True,
            notes={"O2": INPUT},
            title=title,
            legend=False,
            scale_bars=False,
        )
    ax.title.set_fontsize(9)
    _fit_title(fig, ax, problem.title, title[len(problem.title) + 1 :])
    buf = io.BytesIO()
    # cropped to what is drawn: a flat linkage at its true shape leaves bands of white
    fig.savefig(buf, format="png", bbox_inches="tight", pad_inches=0.08)
    plt.close(fig)
    return buf.getvalue()
