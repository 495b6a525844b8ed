"""The course notebooks, as a student gets them: ``accelab course --out DIR``
writes them (once per session, into ``build/course-notebooks``), and each is
executed with nbclient from another folder (``build/course-run``), with
``MPLBACKEND=Agg`` and ``ACCELAB_STATIC=1`` in the environment and nothing
added to the path: the notebooks must import everything from the installed
packages and set their own inline backend. A test fails on any error or any
output on stderr, and checks that the executed notebook holds its figures,
its animation and its practice problems' verdicts.

Each notebook is executed once per session: :func:`executed` keeps the
executed notebook in ``build/course/NN_slug.ipynb`` and in the documentation
build's execution cache (``docs/notebooks.py``), so the site test that runs
after it (``tests/test_docs.py``) builds the course pages without executing
the notebooks again.

The fast tests check each notebook's shape against the course conventions
(title cell, section order, folded answers, numbered equations, next link,
citations, practice, the graded families it names).
"""

import argparse
import base64
import json
import os
import re
import time
import warnings
from pathlib import Path

import pytest

import accelab.course
from accelab.course import cli as course_cli
from accelab.exercises.families import REGISTRY
from docs.notebooks import problems

ROOT = Path(__file__).resolve().parents[1]
COURSE = ROOT / "course"
BUILD = ROOT / "build" / "course"  # executed notebooks (the site test reads them)
WRITTEN = ROOT / "build" / "course-notebooks"  # what `accelab course --out` wrote
RUN = ROOT / "build" / "course-run"  # the kernels' working folder: not course/
BUDGET = 20.0  # s per notebook: the course's execution budget (a warning)
CELL_TIMEOUT = 300  # s
MAX_ANIMATION = 1.5e6  # bytes of one animation as the page loads it
#: graded exercise families, from their registry
FAMILIES = tuple(REGISTRY)

NOTEBOOKS = accelab.course.notebooks()
#: one worker executes the notebooks, once, then builds the site from them (tests/test_docs.py)
pytestmark = pytest.mark.xdist_group("course")

_executed = {}  # stem -> (path of the executed notebook, seconds) or the exception


class NotebookFailed(RuntimeError):
    """A notebook raised in a cell or wrote to stderr; the message lists where."""


def kernel_env():
    """The environment a student's kernel might have: the Makefile's
    MPLBACKEND=Agg (the notebooks set their inline backend themselves), headless
    figures for explore(), and no path tricks."""
    env = dict(os.environ)
    env["ACCELAB_STATIC"] = "1"
    env["MPLBACKEND"] = "Agg"
    env.pop("PYTHONPATH", None)
    env.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    return env


_written = {}


def written_course():
    """The course as ``accelab course --out`` writes it (once per session)."""
    if "dir" not in _written:
        parser = argparse.ArgumentParser(prog="accelab")
        course_cli.register(parser.add_subparsers(dest="command"))
        args = parser.parse_args(["course", "--out", str(WRITTEN), "--force"])
        status = args.func(args)
        assert status == 0, f"accelab course --out {WRITTEN} exited with {status}"
        _written["dir"] = WRITTEN
    return _written["dir"]


def execute(notebook, outdir=BUILD, timeout=CELL_TIMEOUT):
    """Execute the written ``notebook`` from :data:`RUN` and write the result to
    ``outdir``; returns the executed notebook. Raises :class:`NotebookFailed` on
    an error or stderr output."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    nb = nbformat.read(notebook, as_version=4)
    RUN.mkdir(parents=True, exist_ok=True)
    outdir.mkdir(parents=True, exist_ok=True)
    target = outdir / Path(notebook).name
    # no timing metadata on the cells: the docs build's cache must match them by content
    client = NotebookClient(
        nb,
        timeout=timeout,
        kernel_name="python3",
        startup_timeout=120,
        allow_errors=False,
        record_timing=False,
        resources={"metadata": {"path": str(RUN)}},
    )
    try:
        client.execute(env=kernel_env())
    except CellExecutionError as exc:
        nbformat.write(nb, target)
        raise NotebookFailed(f"{Path(notebook).name} failed:\n{exc}") from None
    except Exception as exc:  # a timeout, a dead kernel
        nbformat.write(nb, target)
        raise NotebookFailed(f"{Path(notebook).name} failed: {type(exc).__name__}: {exc}") from None
    found = problems(nb)
    nbformat.write(nb, target)
    if found:
        raise NotebookFailed(
            f"{Path(notebook).name} wrote to stderr or failed:\n" + "\n".join(found)
        )
    return nb


def _store(source, nb, seconds):
    """Hand an executed notebook to the documentation build's cache, if the
    repository has one (``docs/notebooks.py``)."""
    import sys

    if str(ROOT) not in sys.path:  # docs/ is not an installed package
        sys.path.append(str(ROOT))
    try:
        from docs.notebooks import store
    except ImportError:
        return
    store(source, nb, seconds)


def executed(source):
    """The executed notebook of ``source`` (a course/NN_slug.py), executing the
    written .ipynb the first time this session asks. Returns ``(path,
    seconds)``; re-raises a failure."""
    key = Path(source).stem
    if key not in _executed:
        notebook = written_course() / f"{key}.ipynb"
        t0 = time.perf_counter()
        try:
            nb = execute(notebook)
            seconds = time.perf_counter() - t0
            _store(source, nb, seconds)
            _executed[key] = (BUILD / notebook.name, seconds)
        except NotebookFailed as exc:  # remembered so that it is not run again
            _executed[key] = exc
    value = _executed[key]
    if isinstance(value, Exception):
        raise value
    return value


def execute_all():
    """Execute every notebook (once per session); ``{stem: path}`` of those that
    ran and ``{stem: message}`` of those that failed."""
    ok, failed = {}, {}
    for source in NOTEBOOKS:
        try:
            ok[source.stem] = executed(source)[0]
        except NotebookFailed as exc:
            failed[source.stem] = str(exc)
    return ok, failed


def _outputs(nb, mime):
    return [
        o["data"][mime]
        for c in nb["cells"]
        if c["cell_type"] == "code"
        for o in c.get("outputs", [])
        if mime in o.get("data", {})
    ]


def _text(value):
    return "".join(value) if isinstance(value, list) else value


def _stdout(nb):
    return "".join(
        _text(o.get("text", ""))
        for c in nb["cells"]
        if c["cell_type"] == "code"
        for o in c.get("outputs", [])
        if o.get("output_type") == "stream" and o.get("name") == "stdout"
    )


# ---------------------------------------------------------------- execution
@pytest.mark.slow
@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_executes(source):
    """Written by `accelab course`, executed from another folder with
    MPLBACKEND=Agg: it runs, holds its figures (the inline backend is its own),
    its animation (small enough to load quickly) and its practice verdicts."""
    path, seconds = executed(source)
    import sys

    sys.stderr.write(f"\n{source.stem}: executed in {seconds:.1f} s\n")
    if seconds > BUDGET:
        warnings.warn(
            f"{source.stem} took {seconds:.1f} s (the course budget is about "
            f"{BUDGET:g} s per notebook)",
            stacklevel=2,
        )
    nb = json.loads(Path(path).read_text())
    assert _outputs(nb, "image/png"), "no figure: is %matplotlib inline in the first cell?"
    text = source.read_text()
    if "animate(" in text:
        pngs = [base64.b64decode(_text(p)) for p in _outputs(nb, "image/png")]
        animated = [p for p in pngs if 0 < p.find(b"acTL") < p.find(b"IDAT")]  # an APNG
        assert animated, "the animation was not shown"
        for png in animated:
            assert len(png) * 4 / 3 < MAX_ANIMATION, f"an animation of {len(png) / 1e6:.1f} MB"
    if "practice(" in text:
        # the notebook asserts p.check's verdicts; here: each was said, with a reason
        lines = _stdout(nb).splitlines()
        assert any(re.match(r"\w+: right \(", s) for s in lines), "no practice answer was accepted"
        refused = [s for s in lines if re.match(r"\w+: ", s) and not re.match(r"\w+: right \(", s)]
        assert refused, "no wrong practice answer was refused"
        assert all(len(s) > 30 for s in refused), f"a refusal without its reason: {refused}"


@pytest.mark.slow
def test_course_command_writes_notebooks_a_student_can_run(tmp_path):
    """`accelab course --out DIR` writes one .ipynb per notebook and the pages;
    it keeps a notebook already there unless --force; and the written notebooks
    are what the execution tests above run (from another folder)."""
    parser = argparse.ArgumentParser(prog="accelab")
    course_cli.register(parser.add_subparsers(dest="command"))
    out = tmp_path / "my course"
    args = parser.parse_args(["course", "--out", str(out)])
    assert args.func(args) == 0
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted([p.stem + ".ipynb" for p in NOTEBOOKS] + list(accelab.course.pages()))
    import nbformat

    nb = nbformat.read(out / NOTEBOOKS[0].with_suffix(".ipynb").name, as_version=4)
    assert nb.metadata["kernelspec"]["name"] == "python3"
    assert nb.cells[1].source.startswith("%matplotlib inline")
    assert not any(c.get("outputs") for c in nb.cells if c.cell_type == "code")
    # a student's edits survive a second run
    mine = out / "01_rotating_point.ipynb"
    mine.write_text(mine.read_text().replace("The acceleration", "My notes: the acceleration"))
    assert args.func(args) == 1
    assert "My notes" in mine.read_text()
    assert "errata.md" in names and "FAMILIES.md" in names


def test_course_command_reports_an_unusable_folder(tmp_path, capsys):
    parser = argparse.ArgumentParser(prog="accelab")
    course_cli.register(parser.add_subparsers(dest="command"))
    blocked = tmp_path / "a file"
    blocked.write_text("not a folder")
    args = parser.parse_args(["course", "--out", str(blocked / "course")])
    assert args.func(args) == 2
    err = capsys.readouterr().err
    assert "cannot write to" in err and "Traceback" not in err


# ---------------------------------------------------------------- conventions
def _cells(source):
    import jupytext

    return jupytext.read(source).cells


def _markdown(source):
    return [c.source for c in _cells(source) if c.cell_type == "markdown"]


@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_follows_the_conventions(source):
    text = source.read_text()
    assert "kernelspec" in text and "python3" in text, "jupytext header with a python3 kernel"
    assert "# %% [markdown]" in text, "jupytext percent format"
    md = _markdown(source)
    number = int(source.name[:2])
    first = md[0].lstrip()
    assert re.match(rf"# {number}\. \S", first), f"first cell must start '# {number}. Title'"
    assert "you will be able to" in first.lower(), "a 'You will be able to' list up front"
    headings = [
        line[3:].strip().lower()
        for cell in md
        for line in cell.splitlines()
        if line.startswith("## ")
    ]
    order = []
    for word in ("idea", "worked example", "explore", "check yourself", "common mistakes"):
        hits = [i for i, h in enumerate(headings) if word in h]
        assert hits, f"no '## ...{word}...' section (headings: {headings})"
        order.append(hits[0])
    assert order == sorted(order), f"sections out of order: {headings}"
    allmd = "\n".join(md)
    assert allmd.count("<details>") == allmd.count("</details>") > 0, "folded answers"
    for block in re.findall(r"\$\$(.+?)\$\$", allmd, flags=re.S):
        tags = re.findall(r"\\tag\{([^}]*)\}", block)
        for tag in tags:
            assert re.fullmatch(r"\d+\.\d+[a-z]?", tag), f"equation tag {tag!r}: use 7.4, 7.12a"
    later = [p for p in NOTEBOOKS if int(p.name[:2]) > number]
    if later:
        nxt = later[0].stem
        assert f"({nxt}.ipynb)" in allmd, f"a closing link [Next: ...]({nxt}.ipynb)"
    code = [c.source for c in _cells(source) if c.cell_type == "code"]
    assert code[0].startswith("%matplotlib inline"), "the first code cell sets the inline backend"
    allcode = "\n".join(code)
    assert "from accelab.solver" in allcode or "import accelab.solver" in allcode, (
        "notebooks are clients of accelab.solver"
    )
    assert "coursekit" not in allcode and "sys.path" not in allcode, "no path tricks"
    assert "../" not in allcode, "nothing read from outside the installed package"
    assert "Design of Machinery" in allmd and "Norton" in allmd, "the book is cited"


@pytest.mark.parametrize(
    "source",
    [p for p in NOTEBOOKS if int(p.name[:2]) <= 9],
    ids=[p.stem for p in NOTEBOOKS if int(p.name[:2]) <= 9],
)
def test_topic_notebooks_practise_and_name_their_families(source):
    """Each notebook of the chapter's topics has a practice section with
    instant feedback and names the graded exercise families that practise it."""
    md = "\n".join(_markdown(source))
    assert "## Practice" in md, "a '## Practice' section"
    named = [f for f in FAMILIES if f"`{f}`" in md]
    assert named, "name the graded exercise families that practise this notebook"
    assert "practice(" in source.read_text()


def test_families_page_maps_every_family_to_a_notebook():
    page = accelab.course.pages()["FAMILIES.md"]
    stems = {p.stem for p in NOTEBOOKS}
    for family in FAMILIES:
        row = next((line for line in page.splitlines() if line.startswith(f"| `{family}`")), None)
        assert row, f"FAMILIES.md has no row for {family}"
        linked = re.findall(r"\]\((\d\d_[a-z_]+)\.ipynb\)", row)
        assert linked and set(linked) <= stems, row
        for stem in linked:  # and that notebook names the family back
            assert f"`{family}`" in (COURSE / f"{stem}.py").read_text(), (
                f"course/{stem}.py teaches {family} (exercises/families/__init__.py): name "
                f"the family `{family}` in its text, where it says which families practise it"
            )


def test_errata_page_lists_corrections_and_checks():
    page = (COURSE / "errata.md").read_text()
    assert page.startswith("# ")
    rows = [line for line in page.splitlines() if line.startswith("| ") and "---" not in line]
    assert len(rows) >= 12, "one row per misprint found"
    for needle in (
        "7.16b",
        "7.24a",
        "7.26b",
        "7.27b",
        "7.29e",
        "7.40",
        "omega_4",
        "perpendicular to and along",
        "Section 7.5",
    ):
        assert needle in page, needle


# ---------------------------------------------------------------- the kit
def test_kit_static_figure(monkeypatch):
    """explore() headless: one figure with a panel per value of the first slider."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from accelab.course import kit

    assert kit.static_values(0, 360, 5, 4) == [0, 90, 180, 270]
    assert kit.static_values(10, 50, 5, 3) == [10, 30, 50]
    calls = []

    def draw(theta2, omega2):
        calls.append((theta2, omega2))
        fig, ax = plt.subplots(figsize=(3, 2))
        ax.plot([0, 1], [0, theta2])
        return fig

    fig = kit.small_multiples(draw, "theta2", [0, 90, 180], {"omega2": 10}, "deg")
    assert calls == [(0, 10), (90, 10), (180, 10)]
    assert len(fig.axes) == 3
    w, h = fig.get_size_inches() * fig.dpi
    assert w == pytest.approx(900) and h > 200
    plt.close("all")
    assert kit._label("rpm", 6, "rpm") == "6 rpm"  # never "rpm = 6 rpm"
    assert kit._label("theta2", 30, "deg") == "theta2 = 30 deg"
    monkeypatch.setenv("ACCELAB_STATIC", "1")
    assert kit.is_static()
    with pytest.raises(ValueError, match="min, max, step, default"):
        kit.explore(draw, theta2=(0, 360))
    z = kit.Q_(3 + 4j, "m/s**2")
    assert kit.polar(z) == "5 m/s² at 53.13 deg"
    assert kit.cartesian(z) == "(3 + j4) m/s²"
    assert kit.in_g(kit.Q_(9.80665, "m/s**2")) == pytest.approx(1.0)


def test_stated_ties_the_prose_to_the_numbers():
    from accelab.course.kit import Q_, stated

    assert stated(36.96, "37") == 36.96
    stated(-23.466, "-23.47")
    stated(2093.0, "2100", sig=2)
    stated(Q_(2.0, "m/s^2"), "78.74", unit="in/s^2")
    stated(1.46e-6, "1.5e-6")
    with pytest.raises(AssertionError, match="the prose says 2100 but"):
        stated(2160.0, "2100", sig=2)
    with pytest.raises(AssertionError):
        stated(36.4, "37")


def test_measure_times_functions_in_turn():
    from accelab.course.kit import measure

    fast, slow = measure([lambda: None, lambda: sum(range(20000))], repeats=3, min_time=0.002)
    assert 0 < fast < slow


def test_animation_is_a_small_apng_drawn_by_the_linkage_drawer(monkeypatch):
    """accelab.course.animation: FuncAnimation frames drawn by draw_linkage, an animated
    PNG shown as an image/png output; a few frames here to keep the test fast."""
    from accelab.course.animation import animate
    from accelab.solver.graphical import draw as drawing
    from accelab.solver.graphical.gallery import EXAMPLE_7_1

    calls = []
    real = drawing.draw_linkage
    monkeypatch.setattr(
        drawing, "draw_linkage", lambda *a, **kw: calls.append(kw) or real(*a, **kw)
    )
    anim = animate(dict(EXAMPLE_7_1, alpha2="0 rad/s^2"), frames=4)
    assert anim._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n" and anim.frames == 4
    assert len(calls) >= 4 and all(kw["box"] == calls[0]["box"] for kw in calls)
    assert all(kw["scale"] == calls[0]["scale"] for kw in calls), "one vector scale"
    assert not hasattr(anim, "_repr_html_"), "an image/png output: the site captions it"
    import io

    from PIL import Image

    im = Image.open(io.BytesIO(anim.png))
    assert im.n_frames == 4 and im.size == (anim.width, anim.height)


@pytest.mark.slow
def test_explore_shows_sliders_in_a_live_kernel():
    """Without ACCELAB_STATIC, inside a kernel, explore() builds ipywidgets sliders
    (one per keyword, with their ranges) and draws through them."""
    import nbformat
    from nbclient import NotebookClient

    code = """
import matplotlib.pyplot as plt
from accelab.course.kit import explore
from accelab.course import kit
import ipywidgets
shown = []
def draw(theta2, omega2):
    shown.append((theta2, omega2))
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, theta2 * omega2])
    return fig
made = []
real = ipywidgets.interactive
ipywidgets.interactive = lambda f, **kw: made.append(kw) or real(f, **kw)
explore(draw, theta2=(0, 360, 5, 30, "deg"), omega2=(0.5, 20, 0.5, 10))
ipywidgets.interactive = real
s = made[0]
print(kit.is_static(), type(s["theta2"]).__name__, s["theta2"].max, s["theta2"].value,
      type(s["omega2"]).__name__, s["omega2"].step, shown)
"""
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(code)])
    env = kernel_env()
    env["ACCELAB_STATIC"] = "0"
    RUN.mkdir(parents=True, exist_ok=True)
    NotebookClient(
        nb, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(RUN)}}
    ).execute(env=env)
    outputs = nb.cells[0].outputs
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert text.split() == [
        "False",
        "IntSlider",
        "360",
        "30",
        "FloatSlider",
        "0.5",
        "[(30,",
        "10.0)]",
    ], text
    assert any("application/vnd.jupyter.widget-view+json" in o.get("data", {}) for o in outputs)
