"""Drawings of the graphical constructions: produced, step by step, and
compared with a small baseline image."""

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pytest
from matplotlib.testing.compare import compare_images

from accelab.exercises.families import REGISTRY
from accelab.solver.graphical import (
    construct_case,
    style,
)
from accelab.solver.graphical.draw import (
    diagrams,
    draw_linkage,
    draw_polygon,
    draw_polygons,
    nice,
    save,
)
from accelab.solver.graphical.gallery import EXAMPLE_7_1, GALLERY, construction
from accelab.solver.graphical.labels import label_texts, layers

BASELINE = os.path.join(os.path.dirname(__file__), "graphical_baseline")


def texts(fig):
    out = []
    for ax in fig.axes:
        out += [t.get_text() for t in ax.texts]
    return out + [t.get_text() for t in fig.texts] + label_texts(fig)


def test_linkage_figure_has_labelled_components_and_scale_bars():
    con = construct_case(EXAMPLE_7_1)
    fig = draw_linkage(con)
    t = texts(fig)
    for label in (
        r"$\mathbf{A}_{A}^{n}$",
        r"$\mathbf{A}_{A}^{t}$",
        r"$\mathbf{A}_{B}^{t}$",
        r"$\mathbf{A}_{P}$",
        "$O_{2}$",
        "$O_{4}$",
        "p",
        "q",
    ):
        assert label in t, label
    assert "1 in" in t, "an inch linkage has its scale bars in inches"
    assert any(s.endswith(r"in/s$^2$") for s in t)
    ax = fig.axes[0]
    assert ax.get_aspect() == 1.0  # equal aspect: drawn to scale
    legend = [x.get_text() for x in ax.get_legend().get_texts()]
    assert "tangential" in legend and "construction line" in legend
    plt.close(fig)


def test_polygons_figure_panels_and_labels():
    con = construct_case(EXAMPLE_7_1)
    assert diagrams(con) == ["velocity", "acceleration", "point"]
    fig = draw_polygons(con)
    assert sorted(ax.get_title() for ax in fig.axes) == [
        "Acceleration of P",
        "Acceleration polygon",
        "Velocity polygon",
    ]
    t = texts(fig)
    for label in (
        r"$\mathbf{A}_{BA}^{t}$",
        r"$\mathbf{A}_{B}^{t}$",
        r"$\mathbf{A}_{B}^{n}$",
        r"$\mathbf{A}_{PA}^{n}$",
        r"$\mathbf{V}_{B}$",
        "$o_A$",
        "$o_V$",
    ):
        assert label in t, label
    plt.close(fig)


def test_coriolis_drawn_for_the_inverted_slider_crank():
    con = construction("graphical-invertedslidercrank")
    fig = draw_polygons(con)
    legend = [x.get_text() for x in fig.legends[0].get_texts()]
    assert "Coriolis" in legend and "slip" in legend
    assert r"$\mathbf{A}_{cor}$" in texts(fig)
    plt.close(fig)


def test_styles_differ_in_line_style_not_only_colour():
    kinds = ["normal", "tangential", "coriolis", "slip"]
    styles = {str(style.component(k)["linestyle"]) for k in kinds}
    assert len(styles) == 4  # readable in greyscale
    assert len({style.component(k)["color"] for k in kinds}) == 4


def test_walk_the_construction_step_by_step():
    con = construct_case(EXAMPLE_7_1)
    drawn = []
    for k in range(len(con.steps) + 1):
        fig = draw_linkage(con, step=k)
        lines = sum(len(ax.lines) for ax in fig.axes)
        drawn.append(lines)
        if k:
            caption = fig.texts[-1].get_text()
            assert f"({k}/{len(con.steps)})" in caption
            assert ("Step " + con.steps[k - 1].label) in caption or k <= 4
        plt.close(fig)
    assert drawn == sorted(drawn) and drawn[-1] > drawn[0]
    # the polygon is empty before step 6 and complete after it
    fig = draw_polygons(con, step=4)
    assert r"$\mathbf{A}_{B}^{t}$" not in texts(fig)
    plt.close(fig)
    fig = draw_polygons(con, step="6")  # Example 7-1's step 6 by its label
    assert r"$\mathbf{A}_{B}^{t}$" in texts(fig)
    assert "Step 6 (10/12)" in fig.texts[-1].get_text()
    plt.close(fig)
    with pytest.raises(ValueError, match="no step '9'"):
        draw_polygons(con, step="9")


def _placed(fig):
    """Every label box placed when ``fig`` was drawn, per layer, with its axes box."""
    fig.canvas.draw()
    return [(layer.placed, layer.ax.bbox) for layer in layers(fig)]


def _overlap(a, b):
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w > 0.5 and h > 0.5


@pytest.mark.parametrize("name", sorted(GALLERY))
def test_labels_never_overlap_and_stay_inside(name):
    """In every figure of the gallery, no two labels share a pixel and every
    label lies inside its axes, at the size the site shows the figure."""
    con = construction(name)
    for maker in (draw_linkage, draw_polygons):
        fig = maker(con)
        fig.set_dpi(100)
        for boxes, frame in _placed(fig):
            assert boxes
            for i, a in enumerate(boxes):
                assert frame.x0 - 1 <= a[0] and a[2] <= frame.x1 + 1, (name, maker.__name__)
                assert frame.y0 - 1 <= a[1] and a[3] <= frame.y1 + 1, (name, maker.__name__)
                for b in boxes[i + 1 :]:
                    assert not _overlap(a, b), (name, maker.__name__, a, b)
        plt.close(fig)


def test_tiny_component_is_magnified_in_an_inset():
    """Example 7-1's A_A^t is a twentieth of A_A^n: the polygon and the linkage
    show it again in a magnified inset, labelled there."""
    con = construct_case(EXAMPLE_7_1)
    fig, ax = plt.subplots()
    draw_polygon(con, "acceleration", ax=ax)
    assert len(ax.child_axes) == 1
    inset = ax.child_axes[0]
    assert r"$\mathbf{A}_{A}^{t}$" in [
        lab["text"] for layer in layers(fig) if layer.ax is inset for lab in layer.labels
    ]
    assert any(t.get_text().startswith("\u00d7") for t in inset.texts)  # its factor
    plt.close(fig)
    fig = draw_linkage(con)
    assert fig.axes[0].child_axes
    plt.close(fig)


def test_acceleration_polygon_draws_both_sides_of_eq_7_4_from_the_pole():
    """A_B is the sum it is: the chain A_B^n + A_B^t and the chain
    A_A^t + A_A^n + A_BA^n + A_BA^t both end at its tip."""
    con = construct_case(EXAMPLE_7_1)
    arrows = {a.name: a for a in con.items("acceleration")[0]}
    tip = arrows[r"\mathbf{A}_{B}"].tip
    assert arrows[r"\mathbf{A}_{B}^{n}"].start == 0
    assert arrows[r"\mathbf{A}_{B}^{t}"].start == arrows[r"\mathbf{A}_{B}^{n}"].tip
    assert abs(arrows[r"\mathbf{A}_{B}^{t}"].tip - tip) < 1e-12
    assert abs(arrows[r"\mathbf{A}_{BA}^{t}"].tip - tip) < 1e-12
    assert abs(arrows[r"\mathbf{A}_{BA}^{n}"].tip - arrows[r"\mathbf{A}_{BA}^{t}"].start) < 1e-12


def test_vectors_along_a_link_are_drawn_beside_it():
    """A_A^n points from A along the crank: it is drawn a few points beside it."""
    from accelab.solver.graphical.draw import _beside

    con = construct_case(EXAMPLE_7_1)
    pts = con.linkage.points
    arrows = [(a.start, a.vector) for a in con.items("linkage")[0]]
    segs = [(pts[p], pts[q]) for p, q in (("O2", "A"), ("A", "B"), ("O4", "B"))]
    offsets = _beside(arrows, segs, 0.3)
    names = [a.name for a in con.items("linkage")[0]]
    assert abs(offsets[names.index(r"\mathbf{A}_{A}^{n}")]) > 0
    assert offsets[names.index(r"\mathbf{A}_{A}^{t}")] == 0  # perpendicular: stays put


def test_units_follow_the_case():
    si = construct_case(dict(EXAMPLE_7_1, a="50 mm", b="150 mm", c="230 mm", d="180 mm", p="75 mm"))
    assert si.units == "SI" and construct_case(EXAMPLE_7_1).units == "US"
    fig = draw_linkage(si)
    assert any(s.endswith("mm") for s in texts(fig))
    plt.close(fig)


def test_nice_scale_numbers():
    assert [nice(x) for x in (0.045, 1.0, 7.3, 230.0)] == [0.02, 1.0, 5.0, 200.0]


def test_save_writes_png_and_svg(tmp_path):
    paths = save(construct_case(EXAMPLE_7_1), tmp_path, "ex71")
    assert sorted(os.path.basename(p) for p in paths) == [
        "ex71-linkage.png",
        "ex71-linkage.svg",
        "ex71-polygons.png",
        "ex71-polygons.svg",
    ]
    for p in paths:
        assert os.path.getsize(p) > 5000
    assert open(paths[0], "rb").read(8) == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("name", ["fourbar-polygons", "invertedslidercrank-linkage"])
def test_matches_baseline_image(tmp_path, name):
    """Compare a low-resolution rendering with the committed baseline (RMS tolerance).
    Regenerate with: python tests/test_graphical_draw.py"""
    actual = render_baseline(name, tmp_path)
    expected = os.path.join(BASELINE, f"{name}.png")
    result = compare_images(expected, actual, tol=12)
    assert result is None, result


def render_baseline(name, outdir):
    mech, kind = name.rsplit("-", 1)
    con = construction(f"graphical-{mech}")
    fig = draw_linkage(con) if kind == "linkage" else draw_polygons(con)
    path = os.path.join(str(outdir), f"{name}.png")
    fig.savefig(path, dpi=40)
    plt.close(fig)
    return path


if __name__ == "__main__":  # regenerate the baselines
    os.makedirs(BASELINE, exist_ok=True)
    for n in ("fourbar-polygons", "invertedslidercrank-linkage"):
        print(render_baseline(n, BASELINE))


@pytest.mark.parametrize(
    "family",
    list(REGISTRY),
)
def test_exercise_figures_come_from_the_one_linkage_drawer(family, monkeypatch):
    """accelab.exercises.figure.statement_figure(problem) -> PNG bytes, drawn by draw_linkage (the
    project's one linkage drawer) as a schematic with the chapter's symbols."""
    from accelab.exercises import figure
    from accelab.exercises.families import generate
    from accelab.solver.graphical import draw as drawing

    calls = []
    real = drawing.draw_linkage

    def spy(con, *args, **kw):
        calls.append(kw)
        return real(con, *args, **kw)

    monkeypatch.setattr(drawing, "draw_linkage", spy)
    png = figure.statement_figure(generate(family, 7))
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 3000
    assert calls and all(kw.get("vectors") is False for kw in calls)
    assert calls[0].get("symbols") is True


@pytest.mark.parametrize("family", list(REGISTRY))
def test_an_exercise_figure_shows_its_whole_title(family, monkeypatch):
    """A family's title and "(schematic: your values differ)" fit the figure's width (the
    inverted slider-crank's polygons' title ran off both sides): a long one is written on
    two lines."""
    from matplotlib.figure import Figure

    from accelab.exercises import figure
    from accelab.exercises.families import generate

    seen = []
    real = Figure.savefig

    def spy(fig, *args, **kw):
        renderer = fig.canvas.get_renderer()
        for ax in fig.axes:
            if ax.get_title():
                bb = ax.title.get_window_extent(renderer)
                seen.append((ax.get_title(), bb.x0, bb.x1, fig.bbox.width))
        return real(fig, *args, **kw)

    monkeypatch.setattr(Figure, "savefig", spy)
    problem = generate(family, 7)
    for shared in (True, False):
        figure.statement_figure(problem, shared=shared)
    assert len(seen) == 2 and problem.title in seen[0][0].replace("\n", " ")
    for title, x0, x1, width in seen:
        assert 0 <= x0 and x1 <= width, (
            f"{family}: {title!r} spans {x0:.0f}..{x1:.0f} of {width:.0f} px"
        )


def test_a_round_off_zero_is_never_magnified():
    """At theta2 = 360 deg the inverted slider-crank's slip velocity is 1e-16 m/s, not 0:
    magnifying it would ask for a 1e15 times inset, which the renderer never finishes.
    Round-off is not a short vector; a short vector still is."""
    import math
    import time

    import matplotlib.pyplot as plt

    from accelab.solver.graphical import invertedslidercrank
    from accelab.solver.graphical.draw import _tiny, draw_linkage

    assert _tiny([7.5e-16, 0.01, 0.5], 1.0) == [1]
    con = invertedslidercrank.construct(0.1016, 0.0762, 0.2032, math.pi / 2, 2 * math.pi, 10.0, 0.0)
    t0 = time.perf_counter()
    fig, ax = plt.subplots()
    draw_linkage(con, ax=ax, units="US", legend=False, lines=False)
    fig.canvas.draw()
    plt.close(fig)
    assert time.perf_counter() - t0 < 20
