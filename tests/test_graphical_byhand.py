"""Example 7-1 by hand (accelab.solver.graphical.byhand): one stroke per figure, in the
chapter's layout, at one frame and one scale per diagram, readable on a phone."""

import cmath

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pytest
from matplotlib.colors import to_hex

from accelab.solver.graphical import construct_case, style
from accelab.solver.graphical.byhand import FIGURE_WIDTH, by_hand, case_table, draw_stroke
from accelab.solver.graphical.gallery import EXAMPLE_7_1, construction
from accelab.solver.graphical.labels import layers

#: how wide a 390 px phone shows a figure of the site (measured in headless Chromium) [CSS px]
PHONE_WIDTH = 342
SMALLEST_TEXT = 9.0  # CSS px
PAD = 0.1  # in: what a "tight" save (the notebook's inline backend) adds all round


@pytest.fixture(scope="module")
def walk():
    return by_hand(construct_case(EXAMPLE_7_1))


def _arrows(walk, diagram):
    return {a.name: a for a in walk.items(diagram)[0]}


def test_every_stroke_adds_one_vector_or_one_line(walk):
    assert walk.labels[:6] == ["P", "V1", "V2", "V3", "V4", "V5"]
    assert walk.labels[-1] == "8e"
    for s in walk.steps:
        added = len(s.arrows) + len(s.lines)
        if s.label == "P":
            assert added == 0  # the linkage itself
        elif s.label == "8e":  # the answers drawn back on the linkage (Figure 7-4d)
            assert [a.kind for a in s.arrows] == ["resultant"] * 3 and not s.lines
        else:
            assert added == 1, s.label
        outside_math = s.title.split("$")[::2]  # symbols are typeset, never A_BA^n
        assert s.title and not any(c in "".join(outside_math) for c in "_^\\"), s.label


def test_polygon_is_the_chapters_layout(walk):
    """Step 6: -A_B^n at the tip of A_BA^n; a line parallel to qq through its tip and one
    parallel to pp through the pole; A_BA^t and A_B^t end where they cross; A_B = A_B^t +
    A_B^n from the pole."""
    a = _arrows(walk, "acceleration")
    lines = {ln.name: ln for ln in walk.items("acceleration")[1]}
    A_A, A_BAn, mBn = a[r"\mathbf{A}_{A}"], a[r"\mathbf{A}_{BA}^{n}"], a[r"-\mathbf{A}_{B}^{n}"]
    assert a[r"\mathbf{A}_{A}^{t}"].start == 0 and A_A.start == 0
    assert abs(a[r"\mathbf{A}_{A}^{n}"].tip - A_A.tip) < 1e-12
    assert abs(A_BAn.start - A_A.tip) < 1e-12 and abs(mBn.start - A_BAn.tip) < 1e-12
    assert lines["pp"].point == 0 and abs(lines["qq"].point - mBn.tip) < 1e-12
    crossing = a[r"\mathbf{A}_{B}^{t}"].tip
    assert a[r"\mathbf{A}_{B}^{t}"].start == 0
    assert abs(a[r"\mathbf{A}_{BA}^{t}"].start - mBn.tip) < 1e-12
    assert abs(a[r"\mathbf{A}_{BA}^{t}"].tip - crossing) < 1e-12
    for name, ln in lines.items():  # the crossing lies on both lines
        off = (crossing - ln.point) / ln.direction
        assert abs(off.imag) < 1e-9 * abs(off), name
    A_Bn = a[r"\mathbf{A}_{B}^{n}"]
    assert abs(A_Bn.start - crossing) < 1e-12 and abs(A_Bn.vector + mBn.vector) < 1e-12
    assert a[r"\mathbf{A}_{B}"].start == 0 and abs(a[r"\mathbf{A}_{B}"].tip - A_Bn.tip) < 1e-12


def test_walk_reads_what_the_construction_reads(walk):
    """The crossings found again by the walk are those of the construction (exact
    geometry, to rounding)."""
    v, c = walk.values, walk.source.values
    for key in ("omega3", "omega4", "alpha3", "alpha4", "A_A", "A_B", "A_P", "V_B"):
        assert abs(v[key] - c[key]) <= 1e-14 * abs(c[key]), key
    assert v["omega4"] < 0 < v["alpha4"]  # the rocker slows: the walk says so in step 7
    assert "slowing" in walk.stroke("7a").title


def test_tables_in_the_drawings_units(walk):
    vel = walk.table("velocity")
    acc = walk.table("acceleration")
    assert vel._repr_markdown_() == vel
    assert "| V1 | $\\mathbf{V}_A$ | 20 in/s | 120.0° |" in vel
    assert "**-3.461 rad/s** (clockwise)" in vel
    assert "| 2a | $\\mathbf{A}^n_A$ | 200 in/s² | -150.0° |" in acc
    assert "| 6i | $\\mathbf{A}^t_B$ | 354.8 in/s² |" in acc and "**measured**" in acc
    assert "**+39.43 rad/s²** (counter-clockwise)" in acc
    assert "m/s" not in acc.replace("in/s", "")
    for table in (vel, acc, walk.table("point")):  # a pipe inside math would split a cell
        for row in table.splitlines():
            if row.startswith("| "):
                assert row.count("|") == 7, row
    with pytest.raises(ValueError, match="phase must be one of"):
        walk.table("jerk")
    given = case_table(EXAMPLE_7_1)
    assert "| crank $O_2A$ (link 2) | $a$ | 2 in |" in given and "30°" in given


def test_a_metric_linkage_is_walked_in_its_units():
    si = dict(EXAMPLE_7_1, a="50 mm", b="150 mm", c="225 mm", d="175 mm", p="75 mm")
    walk = by_hand(construct_case(si))
    vel, acc = walk.table("velocity"), walk.table("acceleration")
    assert " m/s |" in vel and "in/s" not in vel and " m/s² |" in acc
    assert "/ 0.225 m = " in vel  # omega4 = V_B / c, in units that divide
    fig = draw_stroke(walk, "6k")
    assert any(t.endswith("m/s$^2$") for t in _texts(fig))
    plt.close(fig)


def test_refuses_what_it_does_not_draw():
    with pytest.raises(ValueError, match="draws the fourbar of Example 7-1"):
        by_hand(construction("graphical-slidercrank"))


def _figures(walk, diagram):
    return [s.label for s in walk.steps if s.diagram == diagram]


def _fonts(fig):
    """Every text size of a figure [pt], the placed labels included."""
    sizes = [t.get_fontsize() for t in fig.texts]
    for ax in fig.axes:
        sizes += [t.get_fontsize() for t in ax.texts]
        for inset in ax.child_axes:
            sizes += [t.get_fontsize() for t in inset.texts]
    for legend in fig.legends:
        sizes += [t.get_fontsize() for t in legend.get_texts()]
    for layer in layers(fig):
        sizes += [lab["kw"].get("fontsize", layer.fontsize) for lab in layer.labels]
    return sizes


@pytest.mark.parametrize("diagram", ["velocity", "linkage", "acceleration", "point", "reading"])
def test_one_frame_one_scale_and_readable_on_a_phone(walk, diagram):
    """The figures of one diagram share their size, frame and scale bars (a walk never
    rescales); each states one scale per quantity; the stroke it adds lies on the pale
    band; labels never overlap and stay inside; the smallest text is at least 9 CSS px on
    a phone."""
    shapes, frames, bars = set(), set(), set()
    for label in _figures(walk, diagram):
        fig = draw_stroke(walk, label)
        fig.set_dpi(100)
        fig.canvas.draw()
        ax = fig.axes[0]
        if label != "P":  # the linkage alone has no legend
            shapes.add(tuple(round(x, 6) for x in fig.get_size_inches()))
        frames.add(tuple(round(x, 9) for x in (*ax.get_xlim(), *ax.get_ylim())))
        scale = [t for t in _texts(fig) if t.endswith(("in/s$^2$", "in/s"))]
        bars.add(tuple(scale))
        assert len(scale) <= 1, (label, scale)  # one scale per polygon
        halo = [ln for ln in ax.lines if to_hex(ln.get_color()) == style.HIGHLIGHT["color"].lower()]
        stroke = walk.stroke(label)
        if stroke.arrows or stroke.lines:
            assert halo or ax.child_axes, f"{label}: the stroke it adds is not marked"
        for layer in layers(fig):
            boxes, frame = layer.placed, layer.ax.bbox
            for i, a in enumerate(boxes):
                assert frame.x0 - 1 <= a[0] and a[2] <= frame.x1 + 1, label
                assert frame.y0 - 1 <= a[1] and a[3] <= frame.y1 + 1, label
                for b in boxes[i + 1 :]:
                    w = min(a[2], b[2]) - max(a[0], b[0])
                    h = min(a[3], b[3]) - max(a[1], b[1])
                    assert not (w > 0.5 and h > 0.5), (label, a, b)
        # saved as Jupyter saves it ("tight", 0.1 in of padding), shown 342 px wide
        shown = PHONE_WIDTH / ((fig.get_figwidth() + 2 * PAD) * 72)  # CSS px per pt
        assert min(_fonts(fig)) * shown >= SMALLEST_TEXT, (label, min(_fonts(fig)))
        assert fig.get_figwidth() == FIGURE_WIDTH
        plt.close(fig)
    assert len(shapes) == 1 and len(frames) == 1, (diagram, shapes, frames)
    assert len({b for b in bars if b}) <= 1, bars


def _texts(fig):
    out = [t.get_text() for t in fig.texts]
    for ax in fig.axes:
        out += [t.get_text() for t in ax.texts]
    return out + [lab["text"] for layer in layers(fig) for lab in layer.labels]


def test_a_tight_save_keeps_the_figures_size(walk):
    """Jupyter saves figures "tight": the badge room under the legend must survive it."""
    import io

    from PIL import Image

    for label in ("P", "6g", "8e"):
        fig = draw_stroke(walk, label)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=100, bbox_inches="tight", pad_inches=PAD)
        w, h = Image.open(buf).size
        assert (w, h) == (
            round((fig.get_figwidth() + 2 * PAD) * 100),
            round((fig.get_figheight() + 2 * PAD) * 100),
        )
        plt.close(fig)


def test_polygons_of_b_and_p_share_one_scale(walk):
    """Figure 7-4b and 7-4c at one scale: the same data span in the same axes width."""
    spans = []
    for label in ("6k", "8d"):
        fig = draw_stroke(walk, label)
        ax = fig.axes[0]
        x0, x1 = ax.get_xlim()
        spans.append((x1 - x0) / ax.get_position().width)
        plt.close(fig)
    assert spans[0] == pytest.approx(spans[1], rel=1e-9)


def test_inset_only_where_a_vector_is_too_short(walk):
    """A_A^t (a twentieth of A_A^n) is magnified from the stroke that draws it on; no
    other figure has an inset."""
    with_inset = set()
    for label in walk.labels:
        fig = draw_stroke(walk, label)
        if fig.axes[0].child_axes:
            with_inset.add(label)
        plt.close(fig)
    expected = {"2b", "3", "4", "5a", "5b"} | {f"6{k}" for k in "abcdefghijk"}
    assert with_inset == expected


def test_position_figure_draws_the_arcs_that_locate_b(walk):
    fig = draw_stroke(walk, "P")
    ax = fig.axes[0]
    pts = walk.linkage.points
    B = pts["B"] / 0.0254
    arcs = 0
    for ln in ax.lines:
        xy = ln.get_xydata()
        if len(xy) > 10:
            zs = [complex(x, y) for x, y in xy]
            for centre in (pts["A"] / 0.0254, pts["O4"] / 0.0254):
                r = [abs(z - centre) for z in zs]
                if max(r) - min(r) < 1e-9 and abs(r[0] - abs(B - centre)) < 1e-9:
                    arcs += 1
    assert arcs == 2
    assert any("theta_2" in t for t in _texts(fig))
    assert cmath.phase(pts["A"]) == pytest.approx(cmath.pi / 6)
    plt.close(fig)
