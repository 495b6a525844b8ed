"""Drawings of the graphical constructions: produced, step by step, and
compared with a small baseline image."""

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from matplotlib.testing.compare import compare_images  # noqa: E402

from solver.graphical import construct_case  # noqa: E402
from solver.graphical import style  # noqa: E402
from solver.graphical.draw import (diagrams, draw_linkage, draw_polygons, nice,  # noqa: E402
                                   save)
from solver.graphical.gallery import EXAMPLE_7_1, GALLERY, construction  # noqa: E402

BASELINE = os.path.join(os.path.dirname(__file__), "graphical_baseline")


def texts(fig):
    out = []
    for ax in fig.axes:
        out += [t.get_text() for t in ax.texts]
    return out + [t.get_text() for t in fig.texts]


def test_linkage_figure_has_labelled_components_and_scale_bars():
    con = construct_case(EXAMPLE_7_1)
    fig = draw_linkage(con)
    t = texts(fig)
    for label in (r"$\mathbf{A}_{A}^{n}$", r"$\mathbf{A}_{A}^{t}$", r"$\mathbf{A}_{B}^{t}$",
                  r"$\mathbf{A}_{P}$", "$O_2$", "$O_4$", "p", "q"):
        assert label in t, label
    assert any(s.startswith("lengths: ") for s in t)
    assert any(s.startswith("accelerations: ") for s in t)
    ax = fig.axes[0]
    assert ax.get_aspect() == 1.0  # equal aspect: drawn to scale
    legend = [x.get_text() for x in ax.get_legend().get_texts()]
    assert "tangential" in legend and "construction line" in legend
    plt.close(fig)


def test_polygons_figure_panels_and_labels():
    con = construct_case(EXAMPLE_7_1)
    assert diagrams(con) == ["velocity", "acceleration", "point"]
    fig = draw_polygons(con)
    assert [ax.get_title() for ax in fig.axes] == ["Velocity polygon", "Acceleration polygon",
                                                   "Acceleration of P"]
    t = texts(fig)
    for label in (r"$\mathbf{A}_{BA}^{t}$", r"$\mathbf{A}_{B}^{t}$", r"$-\mathbf{A}_{B}^{n}$",
                  r"$\mathbf{A}_{PA}^{n}$", r"$\mathbf{V}_{B}$", "$o_A$", "$o_V$"):
        assert label in t, label
    plt.close(fig)


def test_coriolis_drawn_for_the_inverted_slider_crank():
    con = construction("graphical-invertedslidercrank")
    fig = draw_polygons(con)
    legend = [x.get_text() for x in fig.axes[-1].get_legend().get_texts()]
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


def test_nice_scale_numbers():
    assert [nice(x) for x in (0.045, 1.0, 7.3, 230.0)] == [0.02, 1.0, 5.0, 200.0]


def test_save_writes_png_and_svg(tmp_path):
    paths = save(construct_case(EXAMPLE_7_1), tmp_path, "ex71")
    assert sorted(os.path.basename(p) for p in paths) == [
        "ex71-linkage.png", "ex71-linkage.svg", "ex71-polygons.png", "ex71-polygons.svg"]
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
