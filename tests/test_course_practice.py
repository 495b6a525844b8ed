"""The practice block of the course notebooks (``accelab.course.practice``): the answers
cell checks the problem its notebook shows above it, after Run All and whatever cells ran
since; and ``kit.explore``'s controls are drawn over their whole range."""

import ast
import io
import itertools
import re
from contextlib import redirect_stdout

import jupytext
import matplotlib.pyplot as plt
import pytest

import accelab.course
from accelab.course.kit import check_ranges, range_values
from accelab.course.practice import practice

TOPICS = [p for p in accelab.course.notebooks() if int(p.name[:2]) <= 9]


def practice_cells(source):
    """(import cells, practice section's code cells) of a notebook."""
    cells = jupytext.read(source).cells
    start = next(
        i for i, c in enumerate(cells) if c.cell_type == "markdown" and "## Practice" in c.source
    )
    end = next(
        i
        for i, c in enumerate(cells)
        if i > start and c.cell_type == "markdown" and c.source.lstrip().startswith("## ")
    )
    imports = [  # the notebook's import statements before its practice section
        ast.unparse(n)
        for c in cells[:start]
        if c.cell_type == "code"
        for n in parse(c.source).body
        if isinstance(n, (ast.Import, ast.ImportFrom))
    ]
    return imports, [c.source for c in cells[start:end] if c.cell_type == "code"]


def parse(code):
    """The cell's code without IPython's magics and shell lines."""
    kept = [line for line in code.splitlines() if not line.lstrip().startswith(("%", "!"))]
    return ast.parse("\n".join(kept))


def assigned(code, name):
    return any(
        isinstance(n, ast.Assign)
        and any(isinstance(t, ast.Name) and t.id == name for t in n.targets)
        for n in ast.walk(parse(code))
    )


def test_a_shown_problem_says_how_to_check_it():
    mine = practice("fourbar", show=False)
    text = mine._repr_markdown_()
    assert f"seed {mine.seed}; not graded" in text and "mine.check('alpha3'" in text
    assert f"practice('fourbar', seed={mine.seed})" in text  # how to come back to it
    example = practice("fourbar", seed=5, show=False)
    assert "example.check('alpha3'" in example._repr_markdown_()


def test_a_shown_construction_problem_says_how_to_build_it(monkeypatch):
    """A polygon family's answers are constructions: the problem says to build them in its
    builder (no check to type), and its answers are the finished polygons as one figure
    in two renditions under the table (a picture in a table cell has no caption)."""
    monkeypatch.setenv("ACCELAB_STATIC", "1")
    mine = practice("polygon_coriolis", show=False)
    text = mine._repr_markdown_()
    assert f"practice('polygon_coriolis', seed={mine.seed}).builder()" in text
    assert ".check(" not in text and "1 deg" in text and "2%" in text
    example = practice("polygon_slidercrank", seed=3, show=False)
    assert "practice('polygon_slidercrank', seed=3).builder()" in example._repr_markdown_()
    answers = example.answers()._repr_markdown_()
    assert "**Answers** (seed 3)" in answers and "| `velocity_polygon` |" in answers
    assert answers.count("{.accelab-wide}") == answers.count("{.accelab-narrow}") == 1
    assert not re.search(r"\|[^\n]*data:image", answers), "no picture inside the table"
    plt.close("all")


@pytest.mark.parametrize("source", TOPICS, ids=[p.stem for p in TOPICS])
def test_only_the_cell_that_shows_the_fresh_problem_binds_mine(source):
    """``mine`` is assigned by one cell, the one that draws and shows a fresh problem; the
    answers cell right after it checks ``mine``; no cell of the notebook rebinds it (nor
    uses the old shared name ``p`` for a practice problem)."""
    cells = [c.source for c in jupytext.read(source).cells if c.cell_type == "code"]
    binding = [c for c in cells if assigned(c, "mine")]
    assert len(binding) == 1, f"{len(binding)} cells assign mine"
    assert re.fullmatch(r'mine = practice\("\w+"\)(  #.*)?', binding[0].strip()), binding[0]
    after = cells[cells.index(binding[0]) + 1]
    assert "mine.check(" in after, after
    assert not any(re.search(r"^p = practice\(", c, flags=re.M) for c in cells)
    assert "from accelab.course.practice import practice" in "\n".join(cells)


@pytest.mark.parametrize("source", TOPICS, ids=[p.stem for p in TOPICS])
def test_the_answers_cell_checks_the_problem_shown_in_any_order(source, monkeypatch):
    """Run All, then the practice cells again in every order: each time, the problem the
    answers cell checks is the one the fresh-problem cell showed last."""
    monkeypatch.setenv("MPLBACKEND", "Agg")
    imports, section = practice_cells(source)
    fresh = next(c for c in section if assigned(c, "mine"))
    namespace = {}
    shown = []

    def run(code):
        out = io.StringIO()
        with redirect_stdout(out):
            exec(compile(code, source.name, "exec"), namespace)
        if code is fresh:  # outside a notebook the problem is shown as its repr
            shown.append(int(re.search(r"seed=(\d+)\)", out.getvalue()).group(1)))

    for code in imports:
        exec(compile(code, source.name, "exec"), namespace)
    others = [c for c in section if c is not fresh]
    for code in section:  # Run All
        run(code)
    assert namespace["mine"].seed == shown[-1]
    for order in itertools.islice(itertools.permutations(section), 0, None, 5):
        for code in order:
            run(code)
            assert namespace["mine"].seed == shown[-1]
    assert others, "a practice section with its page's problem too"
    plt.close("all")


def test_range_values_reach_every_end_as_a_slider_gives_them():
    values = range_values(theta2=(0, 360, 5, 60, "deg"))
    got = [v["theta2"] for v in values]
    assert got == [0, 5, 10, 180, 350, 355, 360] and all(isinstance(x, int) for x in got)
    two = range_values(c=(4.5, 12, 0.1, 9, "in"), omega2=(2, 20, 1, 10))
    cs = [v["c"] for v in two if v["omega2"] == 10]
    assert min(cs) == 4.5 and max(cs) == pytest.approx(12) and isinstance(cs[0], float)
    assert {"c": 4.5, "omega2": 2} in two and {"c": pytest.approx(12), "omega2": 20} in two


def test_check_ranges_names_the_values_where_draw_fails():
    data = list(range(360))  # one short of the slider's 0..360

    def draw(theta2):
        fig, ax = plt.subplots()
        ax.plot([0, 1], [0, data[theta2]])
        return fig

    with pytest.raises(AssertionError, match=r"\{'theta2': 360\}: IndexError"):
        check_ranges(draw, theta2=(0, 360, 5, 60, "deg"))
    data.append(0)
    assert check_ranges(draw, theta2=(0, 360, 5, 60, "deg")) == 7


def test_check_ranges_without_pixels_still_lays_out_text():
    """The second pass (``render=False``) skips the pixels, not the layout: a label whose
    math cannot be parsed at one value fails there, as when rendered."""

    def draw(theta2):
        fig, ax = plt.subplots()
        ax.set_title(r"$\omega_2$" if theta2 < 360 else r"$\omega_{2$")
        return fig

    for render in (True, False):
        with pytest.raises(AssertionError, match=r"\{'theta2': 360\}: ValueError"):
            check_ranges(draw, render=render, theta2=(0, 360, 5, 60, "deg"))
