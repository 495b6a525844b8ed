"""The course notebooks: every ``course/NN_*.py`` is converted with jupytext and
executed with nbclient (working directory ``course/``, ``ACCELAB_STATIC=1``),
one test per notebook, failing on any error or any output on stderr.

Each notebook is executed once per test session (``docs/notebooks.py`` says
how): :func:`executed` keeps the executed notebook in ``build/course/NN_slug.ipynb``
and in the documentation build's execution cache, so the site test that runs
after it (``tests/test_docs.py``) builds the course pages without executing the
notebooks again.

The fast tests check each notebook's shape against the course conventions
(title cell, section order, folded answers, numbered equations, next link).
"""

import re
import sys
import time
import warnings
from pathlib import Path

import pytest


ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:  # the course package lives at the top of the repository
    sys.path.insert(0, str(ROOT))

from docs.notebooks import NotebookFailed, execute, sources, store  # noqa: E402

COURSE = ROOT / "course"
BUILD = ROOT / "build" / "course"
BUDGET = 12.0           # s per notebook: the course's execution budget (a warning)

NOTEBOOKS = sources(COURSE)

_executed = {}   # stem -> (path of the executed notebook, seconds) or the exception


def executed(source):
    """The executed notebook of ``source``, executing it the first time this
    session asks. Returns ``(path, seconds)``; re-raises a failure."""
    import nbformat
    key = Path(source).stem
    if key not in _executed:
        t0 = time.perf_counter()
        BUILD.mkdir(parents=True, exist_ok=True)
        path = BUILD / f"{key}.ipynb"
        try:
            nb = execute(Path(source))
            seconds = time.perf_counter() - t0
            nbformat.write(nb, path)
            store(source, nb, seconds)      # the docs build takes it from the cache
            _executed[key] = (path, seconds)
        except NotebookFailed as exc:  # remembered so that it is not run again
            nbformat.write(exc.notebook, path)
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


# ---------------------------------------------------------------- execution
@pytest.mark.slow
@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_executes(source):
    path, seconds = executed(source)
    assert path.exists()
    sys.stderr.write(f"\n{source.stem}: executed in {seconds:.1f} s\n")
    if seconds > BUDGET:
        warnings.warn(f"{source.stem} took {seconds:.1f} s (the course budget is about "
                      f"{BUDGET:g} s per notebook)")


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
    headings = [line[3:].strip().lower() for cell in md for line in cell.splitlines()
                if line.startswith("## ")]
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
    code = "\n".join(c.source for c in _cells(source) if c.cell_type == "code")
    assert "import solver" in code or "from solver" in code, "notebooks are clients of solver"


def test_coursekit_static_figure(monkeypatch):
    """explore() headless: one figure with a panel per value of the first slider."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    sys.path.insert(0, str(COURSE))
    try:
        import coursekit
    finally:
        sys.path.remove(str(COURSE))
    assert coursekit.static_values(0, 360, 5, 4) == [0, 90, 180, 270]
    assert coursekit.static_values(10, 50, 5, 3) == [10, 30, 50]
    calls = []

    def draw(theta2, omega2):
        calls.append((theta2, omega2))
        fig, ax = plt.subplots(figsize=(3, 2))
        ax.plot([0, 1], [0, theta2])
        return fig

    fig = coursekit.small_multiples(draw, "theta2", [0, 90, 180], {"omega2": 10}, "deg")
    assert calls == [(0, 10), (90, 10), (180, 10)]
    assert len(fig.axes) == 3
    w, h = fig.get_size_inches() * fig.dpi
    assert w == pytest.approx(900) and h > 200
    plt.close("all")
    monkeypatch.setenv("ACCELAB_STATIC", "1")
    assert coursekit.is_static()
    with pytest.raises(ValueError, match="min, max, step, default"):
        coursekit.explore(draw, theta2=(0, 360))
    z = coursekit.Q_(3 + 4j, "m/s**2")
    assert coursekit.polar(z) == "5 m/s² at 53.13 deg"
    assert coursekit.cartesian(z) == "(3 + j4) m/s²"
    assert coursekit.in_g(coursekit.Q_(9.80665, "m/s**2")) == pytest.approx(1.0)


@pytest.mark.slow
def test_explore_shows_sliders_in_a_live_kernel(tmp_path):
    """Without ACCELAB_STATIC, inside a kernel, explore() builds ipywidgets sliders
    (one per keyword, with their ranges) and draws through them."""
    import nbformat
    from nbclient import NotebookClient
    from docs.notebooks import kernel_env

    code = '''
import matplotlib.pyplot as plt
from coursekit import explore
import coursekit, ipywidgets
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
print(coursekit.is_static(), type(s["theta2"]).__name__, s["theta2"].max, s["theta2"].value,
      type(s["omega2"]).__name__, s["omega2"].step, shown)
'''
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(code)])
    env = kernel_env()
    env["ACCELAB_STATIC"] = "0"
    NotebookClient(nb, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(COURSE)}}).execute(env=env)
    outputs = nb.cells[0].outputs
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert text.split() == ["False", "IntSlider", "360", "30", "FloatSlider", "0.5",
                            "[(30,", "10.0)]"], text
    assert any("application/vnd.jupyter.widget-view+json" in o.get("data", {}) for o in outputs)
