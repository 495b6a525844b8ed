"""The course notebooks, as a student gets them: ``accelab course --out DIR``
writes them (once per session, into ``build/course-notebooks``), and each is
executed with nbclient from another folder (``build/course-run``), with
``MPLBACKEND=Agg`` and ``ACCELAB_STATIC=1`` in the environment and nothing
added to the path: the notebooks must import everything from the installed
packages and set their own inline backend. A test fails on any error or any
output on stderr, and checks that the executed notebook holds its figures,
its animation and its practice problems' verdicts.

Each notebook is executed once per session, one after another (``AT_ONCE`` says
why): :func:`executed` keeps the executed notebook in ``build/course/NN_slug.ipynb``
and in the documentation build's execution cache (``docs/notebooks.py``), so the
site test that runs after it (``tests/test_docs.py``) builds the course pages
without executing the notebooks again.

The fast tests check each notebook's shape against the course conventions
(title cell, section order, folded answers, numbered equations, next link,
citations, practice, the graded families it names).
"""

import argparse
import base64
import json
import re
import time
import warnings
from pathlib import Path

import pytest

import accelab.course
from accelab.course import cli as course_cli
from accelab.exercises.families import REGISTRY
from docs.notebooks import CELL_TIMEOUT, NotebookFailed, notebook_client, store
from docs.notebooks import execute as run_notebook
from docs.notebooks import kernel_env as site_kernel_env

ROOT = Path(__file__).resolve().parents[1]
COURSE = ROOT / "course"
BUILD = ROOT / "build" / "course"  # executed notebooks (the site test reads them)
WRITTEN = ROOT / "build" / "course-notebooks"  # what `accelab course --out` wrote
RUN = ROOT / "build" / "course-run"  # the kernels' working folder: not course/
#: s per notebook: the course's execution budget (a warning), held against the kernel's own
#: CPU time: the tests' wall time is that of a notebook sharing two cores with other workers
BUDGET = 20.0
MAX_ANIMATION = 1.5e6  # bytes of one animation as the page loads it
#: graded exercise families, from their registry
FAMILIES = tuple(REGISTRY)

NOTEBOOKS = accelab.course.notebooks()
#: what the last notebook says, and no other
LAST = "This is the last notebook."
#: one worker executes the notebooks, once, then builds the site from them (tests/test_docs.py)
pytestmark = pytest.mark.xdist_group("course")

_executed = {}  # stem -> (path of the executed notebook, seconds) or the exception


def kernel_env():
    """The environment a student's kernel might have: the Makefile's MPLBACKEND=Agg (the
    notebooks set their inline backend themselves), headless figures for explore(), and
    no path tricks."""
    env = site_kernel_env()
    env["MPLBACKEND"] = "Agg"
    env.pop("PYTHONPATH", None)
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


CHECK_AFTER_RUN_ALL = "from accelab.course.kit import check_explored\ncheck_explored()"
#: after that, the kernel writes the CPU time it has used (user and system, all its threads)
WRITE_KERNEL_CPU = (
    "import os as _os, time as _time\n"
    "with open(_os.environ['ACCELAB_KERNEL_CPU'], 'w') as _f:\n"
    "    _f.write(repr(_time.process_time()))"
)


def kernel_cpu_file(notebook):
    """Where the kernel of ``notebook`` writes the CPU seconds it used (WRITE_KERNEL_CPU)."""
    return BUILD / f"{Path(notebook).stem}.kernel-cpu"


def widgets_log(notebook):
    """Where the kernel of ``notebook`` writes the controls its explore() calls checked."""
    return BUILD / f"{Path(notebook).stem}.widgets.jsonl"


def execute(notebook, outdir=BUILD, timeout=CELL_TIMEOUT):
    """Execute the written ``notebook`` from :data:`RUN` (``docs/notebooks.py``'s runner)
    and write the result to ``outdir``, failed or not; returns the executed notebook.
    Raises :class:`NotebookFailed` on an error or stderr output."""
    import nbformat

    RUN.mkdir(parents=True, exist_ok=True)
    outdir.mkdir(parents=True, exist_ok=True)
    target = outdir / Path(notebook).name
    env = kernel_env()
    # every explore() draws each control at its ends and a few steps between (kit.check_ranges)
    checked = widgets_log(notebook)
    checked.unlink(missing_ok=True)
    env["ACCELAB_CHECK_WIDGETS"] = str(checked)
    kernel_cpu_file(notebook).unlink(missing_ok=True)
    env["ACCELAB_KERNEL_CPU"] = str(kernel_cpu_file(notebook))
    after = CHECK_AFTER_RUN_ALL + "\n" + WRITE_KERNEL_CPU
    try:
        # after the last cell, every slider again, as a person moves it after Run All
        nb = run_notebook(notebook, timeout, cwd=RUN, env=env, after=after)
    except NotebookFailed as exc:
        nbformat.write(exc.notebook, target)
        raise
    nbformat.write(nb, target)
    return nb


#: notebooks executed at once, each by a kernel of its own (this process only waits on
#: them). One: with three test workers on two cores the run is CPU-bound, and a second
#: kernel only adds contention (measured: -n 3, a whole run 245 s and 467 busy cpu-s with
#: one, 250-256 s and 475-490 cpu-s with two); the course group (notebooks, then the site)
#: still ends well before the other workers. More than one: the pool runs them in turn.
AT_ONCE = 1
#: the tests that execute notebooks (their ``source``: the notebooks a session needs)
EXECUTING = (
    "test_notebook_executes",
    "test_notebook_shows_no_raw_values",
    "test_notebook_figures_read_on_a_phone",
)
_pool = {}  # "pool": the executor, "wanted": stems, "running": {stem: Future}


@pytest.fixture(scope="module", autouse=True)
def _executions(request):
    """The notebooks the selected tests execute; the pool that executes them, from the
    first test that asks for one (:func:`executed`), in the course's order; what has not
    started when the module's tests end (a run stopped early) is not started."""
    from concurrent.futures import ThreadPoolExecutor

    _pool["wanted"] = {
        item.callspec.params["source"].stem
        for item in request.session.items
        if getattr(item, "originalname", None) in EXECUTING
    }
    _pool["running"] = {}
    _pool["pool"] = ThreadPoolExecutor(max_workers=AT_ONCE, thread_name_prefix="notebook")
    yield
    _pool["pool"].shutdown(wait=True, cancel_futures=True)


def _timed(notebook):
    t0 = time.perf_counter()
    nb = execute(notebook)
    return nb, time.perf_counter() - t0


def _future(key):
    """The execution of the written notebook ``key``; the first call starts every notebook
    the session wants."""
    running = _pool["running"]
    if not running:
        course = written_course()
        for stem in [s.stem for s in NOTEBOOKS if s.stem in _pool["wanted"]]:
            running[stem] = _pool["pool"].submit(_timed, course / f"{stem}.ipynb")
    if key not in running:
        running[key] = _pool["pool"].submit(_timed, written_course() / f"{key}.ipynb")
    return running[key]


def executed(source):
    """The executed notebook of ``source`` (a course/NN_slug.py), executed once per session
    (:func:`_future`). Returns ``(path, seconds)``; re-raises a failure."""
    key = Path(source).stem
    if key not in _executed:
        try:
            nb, seconds = _future(key).result()
            store(source, nb, seconds)  # the site test builds from the cache
            _executed[key] = (BUILD / f"{key}.ipynb", seconds)
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


RENDITION = re.compile(r"\(data:image/png;base64,([A-Za-z0-9+/=]+)\)\{\.accelab-(wide|narrow)\}")


def _rendition_images(nb):
    """``[(kind, png bytes)]`` of the figures shown in two renditions (Markdown outputs)."""
    return [
        (kind, base64.b64decode(data))
        for md in _outputs(nb, "text/markdown")
        for data, kind in RENDITION.findall(_text(md))
    ]


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

    cpu = float(kernel_cpu_file(path).read_text())
    sys.stderr.write(
        f"\n{source.stem}: executed in {seconds:.1f} s, {cpu:.1f} cpu-s in its kernel\n"
    )
    if cpu > BUDGET:
        warnings.warn(
            f"{source.stem} took {cpu:.1f} cpu-s in its kernel (the course budget is about "
            f"{BUDGET:g} s per notebook)",
            stacklevel=2,
        )
    nb = json.loads(Path(path).read_text())
    assert _outputs(nb, "image/png") or _rendition_images(nb), (
        "no figure: is %matplotlib inline in the first cell?"
    )
    # headless, no widget is shown: none leaves its model's state in the notebook (the site
    # would carry it on the page, for a widget manager it does not load)
    assert not _outputs(nb, "application/vnd.jupyter.widget-view+json")
    assert "widgets" not in nb["metadata"], "a widget's state saved with no view of it"
    text = source.read_text()
    if "animate(" in text:
        players = [p for p in _outputs(nb, "text/html") if "accelab-player" in _text(p)]
        assert players, "the animation was not shown"
        for html in map(_text, players):
            for control in ("accelab-play", "accelab-back", "accelab-next", 'type="range"'):
                assert control in html, f"the player has no {control}"
            for rendition in ("accelab-wide", "accelab-narrow"):
                assert f'class="{rendition}"' in html, f"no {rendition} rendition"
            assert len(html) < MAX_ANIMATION * 2, f"an animation of {len(html) / 1e6:.1f} MB"
    calls = text.count("\nexplore(")
    if calls:  # each control was drawn at its ends and a few steps between, without an error
        log = widgets_log(path).read_text().splitlines() if widgets_log(path).exists() else []
        assert len(log) == 2 * calls, (
            f"{calls} explore() calls, {len(log)} checks of their range (one as each ran, "
            "one after the last cell)"
        )
    if "practice(" in text:
        # the notebook asserts p.check's verdicts; here: each was said, with a reason
        lines = _stdout(nb).splitlines()
        show = (
            ": show one answer checked right and one wrong, as notebook 1's 'What a check "
            "looks like' does"
        )
        assert any(re.match(r"\w+: right \(", s) for s in lines), (
            "no practice answer was accepted" + show
        )
        refused = [s for s in lines if re.match(r"\w+: ", s) and not re.match(r"\w+: right \(", s)]
        assert refused, "no wrong practice answer was refused" + show
        assert all(len(s) > 30 for s in refused), f"a refusal without its reason: {refused}"


#: raw values as Python prints them: np.float64(...), a tuple of them, 15.70999495871365, 6.01e-06
RAW = re.compile(
    r"np\.float64\(|^\([-\d.e]+, [-\d.e]+.*\)$|\d\.\d{12,}|^\s*-?\d\.\d+e-0\d\s*$|Quantity\(",
    re.M,
)
#: the widest figure shown in one rendition [px] (10 pt text stays near 9 CSS px on a phone)
SINGLE = 600
#: the widest renditions [px]: wide ones fit a 900 px page, narrow ones a phone
WIDEST = {"wide": 960, "narrow": 470}


def _png_width(png):
    import struct

    return struct.unpack(">I", png[16:20])[0]


@pytest.mark.slow
@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_shows_no_raw_values(source):
    """What a cell shows is a figure, a table, a sentence or a player, never a bare value
    (np.float64(3.99...), a tuple, 15.70999495871365) and never a value beside a
    figure (which the site would caption a second time)."""
    path, _ = executed(source)
    nb = json.loads(Path(path).read_text())
    bad = []
    for i, cell in enumerate(nb["cells"]):
        if cell["cell_type"] != "code":
            continue
        shown = [o for o in cell.get("outputs", []) if o["output_type"] != "stream"]
        for o in shown:
            kinds = set(o.get("data", {}))
            if kinds <= {"text/plain"}:
                bad.append(
                    f"cell {i} shows a bare value: {_text(o['data'].get('text/plain'))[:80]}"
                )
        figure = "figure" in cell.get("metadata", {}).get("mystnb", {})
        if figure and len(shown) > 1:
            bad.append(f"cell {i} has a caption and {len(shown)} outputs: the caption repeats")
        for o in cell.get("outputs", []):
            if o["output_type"] == "stream" and RAW.search(_text(o.get("text", ""))):
                bad.append(f"cell {i} prints a raw value: {_text(o['text'])[:120]!r}")
    assert not bad, "\n".join(bad)


@pytest.mark.slow
@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_figures_read_on_a_phone(source):
    """A figure shown once is at most SINGLE px wide; a wide figure comes with a narrow
    rendition no wider than a phone needs; the player's phone rendition likewise."""
    path, _ = executed(source)
    nb = json.loads(Path(path).read_text())
    bad = [
        f"a figure of {_png_width(base64.b64decode(_text(png)))} px in one rendition"
        for png in _outputs(nb, "image/png")
        if _png_width(base64.b64decode(_text(png))) > SINGLE
    ]
    renditions = _rendition_images(nb)
    bad += [
        f"a {kind} rendition of {_png_width(png)} px"
        for kind, png in renditions
        if _png_width(png) > WIDEST[kind]
    ]
    kinds = [kind for kind, _ in renditions]
    assert kinds.count("wide") == kinds.count("narrow"), "every wide rendition has its narrow one"
    for html in (_text(h) for h in _outputs(nb, "text/html") if "accelab-player" in _text(h)):
        widths = dict(re.findall(r'class="accelab-(wide|narrow)"[^>]*width="(\d+)"', html))
        bad += [f"a {k} player of {w} px" for k, w in widths.items() if int(w) > WIDEST[k]]
    assert not bad, "\n".join(bad)


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
    # written again: the same files (cell ids included), nothing to see in a diff
    again = tmp_path / "again"
    twice = parser.parse_args(["course", "--out", str(again)])
    assert twice.func(twice) == 0
    for path in out.iterdir():
        assert (again / path.name).read_bytes() == path.read_bytes(), path.name
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
        assert LAST not in allmd, f"'{LAST}' belongs to the last notebook, {NOTEBOOKS[-1].name}"
    else:  # the last one says so and links back to the contents: every other notebook
        assert LAST in allmd, f"the last notebook ends with '{LAST} Back to the contents: ...'"
        missing = [p.stem for p in NOTEBOOKS[:-1] if f"({p.stem}.ipynb)" not in allmd]
        assert not missing, f"the links back to the contents: add {missing}"
    code = [c.source for c in _cells(source) if c.cell_type == "code"]
    assert code[0].startswith("%matplotlib inline"), "the first code cell sets the inline backend"
    allcode = "\n".join(code)
    assert "from accelab.solver" in allcode or "import accelab.solver" in allcode, (
        "notebooks are clients of accelab.solver"
    )
    assert "coursekit" not in allcode and "sys.path" not in allcode, "no path tricks"
    assert "../" not in allcode, "nothing read from outside the installed package"
    flat = " ".join(allmd.split())  # a title may wrap from one line to the next
    assert "Design of Machinery" in flat and "Norton" in flat, (
        "the book is cited: Norton, *Design of Machinery*"
    )


def _hidden(cell):
    tags = cell.metadata.get("tags", [])
    folded = cell.metadata.get("jupyter", {}).get("source_hidden", False)
    return tags, folded


def _only_asserts(src):
    """True when every statement of the cell is an ``assert``."""
    import ast

    try:
        body = ast.parse(src).body
    except SyntaxError:  # a cell magic
        return False
    return bool(body) and all(isinstance(node, ast.Assert) for node in body)


@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_prose_checks_and_plotting_code_are_folded(source):
    """The apparatus is off the page: a cell that only checks the prose (stated, assert)
    is removed from the site and folded in the notebook; a cell that draws a captioned
    figure shows the figure, its code folded (and hidden on the site)."""
    bad = []
    for i, cell in enumerate(_cells(source)):
        if cell.cell_type != "code":
            continue
        tags, folded = _hidden(cell)
        src = cell.source
        if "stated(" in src and not ({"remove-cell", "remove-input"} & set(tags) and folded):
            bad.append(f"cell {i} checks the prose in view: {src.splitlines()[0][:70]}")
        if _only_asserts(src) and not ({"remove-cell", "remove-input"} & set(tags) and folded):
            bad.append(f"cell {i} only checks, but is on the page: {src.splitlines()[0][:70]}")
        if "figure" in cell.metadata.get("mystnb", {}) and not (
            {"hide-input", "remove-input"} & set(tags) and folded
        ):
            bad.append(f"cell {i} shows its plotting code: {src.splitlines()[0][:70]}")
        if "globals()" in src:
            bad.append(f"cell {i} reads globals()")
    assert not bad, "\n".join(bad)


#: text smaller than this [pt] is too small on a phone (figures are drawn at 100 dpi)
SMALLEST_FONT = 10


@pytest.mark.parametrize(
    "source",
    NOTEBOOKS + [COURSE / f"{m}.py" for m in ("kit", "animation", "renditions", "player")],
    ids=[p.stem for p in NOTEBOOKS] + ["kit", "animation", "renditions", "player"],
)
def test_no_text_too_small_for_a_phone(source):
    sizes = re.findall(
        r"(?:fontsize=|set_fontsize\(|\"font\.size\": |labelsize\": )(\d+(?:\.\d+)?)",
        source.read_text(),
    )
    small = [s for s in sizes if float(s) < SMALLEST_FONT]
    assert not small, f"font sizes below {SMALLEST_FONT} pt: {small}"


@pytest.mark.parametrize(
    "source",
    NOTEBOOKS,
    ids=[p.stem for p in NOTEBOOKS],
)
def test_captions_typeset_their_math(source):
    """Figure captions write symbols as math ($\\alpha_3$), not as code names (alpha3)."""
    plain = re.compile(r"(?<![\\$\w])(alpha|omega|theta|delta|lambda|phi)\d?(?![\w$])|in/s\^2")
    bad = []
    for cell in _cells(source):
        caption = cell.metadata.get("mystnb", {}).get("figure", {}).get("caption", "")
        text = re.sub(r"\$[^$]*\$", "", caption)  # math is fine
        if plain.search(text):
            bad.append(caption[:100])
    assert not bad, "captions with symbols as plain text:\n" + "\n".join(bad)


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


#: where a notebook says which graded families practise it
PRACTISED_BY = re.compile(
    r"The graded exercise famil(?:y|ies) that practises? this notebook (.+?)(?:\n\n|$)", re.S
)


@pytest.mark.parametrize("source", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_a_family_a_notebook_names_lists_it(source):
    """The other way round from the families page: a family the notebook names where it
    says which families practise it has the notebook among its notebooks (else FAMILIES.md
    leaves the notebook out of the family's row)."""
    md = "\n\n".join(_markdown(source))
    for sentence in PRACTISED_BY.findall(md):
        for family in re.findall(r"`(\w+)`", sentence):
            if family not in REGISTRY:
                continue
            assert source.stem in REGISTRY[family].notebooks, (
                f"{source.name} names `{family}` as a family that practises it: add "
                f"{source.stem!r} to its notebooks in exercises/families/__init__.py"
            )


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
        "6.24",
        "\\theta_A",
        "slin",
        "sense of 0)",
        "felt",
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
    assert w == pytest.approx(900) and h > 200  # three panels of 300 px
    narrow = kit.small_multiples(
        draw, "theta2", [0, 90, 180], {"omega2": 10}, "deg", width=kit.NARROW_WIDTH
    )
    w, h = narrow.get_size_inches() * narrow.dpi
    assert w == pytest.approx(300) and h > 3 * 200, "one column on a phone"
    plt.close("all")
    assert kit._label("rpm", 6, "rpm") == "6 rpm"  # never "rpm = 6 rpm"
    assert kit._label("theta2", 30, "deg") == "$\\theta_2$ = 30\u00b0"
    assert kit._label("alpha2", -500, "rad/s^2") == "$\\alpha_2$ = \u2212500 rad/s\u00b2"
    assert kit._description("rpm", "rpm") == "rpm"  # a slider never reads "rpm [rpm]"
    assert kit._description("theta2", "deg") == "$\\theta_2$ [\u00b0]"
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

    assert stated(36.96, "37") is None  # a cell of checks shows nothing
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


def test_animation_is_a_player_drawn_by_the_linkage_drawer(monkeypatch):
    """accelab.course.animation: frames drawn by draw_linkage at one scale in one frame,
    in two renditions (wide, narrow), shown as an HTML player with play, pause, step and a
    frame slider; a few frames here to keep the test fast."""
    import io

    from PIL import Image

    from accelab.course.animation import animate
    from accelab.solver.graphical import draw as drawing
    from accelab.solver.graphical.gallery import EXAMPLE_7_1

    calls = []
    real = drawing.draw_linkage
    monkeypatch.setattr(
        drawing, "draw_linkage", lambda *a, **kw: calls.append(kw) or real(*a, **kw)
    )
    anim = animate(dict(EXAMPLE_7_1, alpha2="0 rad/s^2"), frames=4, layouts=("wide", "narrow"))
    assert anim.frames == 4 and set(anim.renditions) == {"wide", "narrow"}
    assert len(calls) >= 8 and all(kw["box"] == calls[0]["box"] for kw in calls)
    assert all(kw["scale"] == calls[0]["scale"] for kw in calls), "one vector scale"
    for kind, frames in anim.renditions.items():
        sizes = {Image.open(io.BytesIO(f)).size for f in frames}
        assert sizes == {anim.sizes[kind]} and len(frames) == 4
        assert Image.open(io.BytesIO(frames[0])).convert("RGB").getpixel((2, 2)) == (255, 255, 255)
    assert anim.sizes["wide"][0] <= 780 and anim.sizes["narrow"][0] <= 460
    html = anim._repr_html_()
    for part in ("accelab-play", "accelab-back", "accelab-next", "accelab-first", 'type="range"'):
        assert part in html, part
    assert "http" not in html, "nothing fetched from the network"
    assert html.isascii(), "the player reads the same whatever the page's encoding"
    assert not hasattr(anim, "_repr_png_"), "one output: the player"
    # a component with its sign: the slider's acceleration along the slide
    from accelab.solver.graphical.gallery import SLIDER_CRANK

    signed = animate(SLIDER_CRANK, frames=2, layouts=("narrow",), magnitudes=("A_B.x",))
    assert signed.frames == 2 and list(signed.renditions) == ["narrow"]


def test_renditions_show_both_headless(monkeypatch):
    """accelab.course.renditions.show: headless, one Markdown output holding the wide and
    the narrow rendition; live, the wide figure alone."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from accelab.course import renditions

    shown = []
    monkeypatch.setattr("IPython.display.display", shown.append)

    def draw(narrow):
        fig, axes = renditions.panels(2, narrow)
        return fig

    monkeypatch.setenv("ACCELAB_STATIC", "1")
    renditions.show(draw, alt="two panels")
    (out,) = shown
    md = out._repr_markdown_()
    assert md.count("data:image/png;base64,") == 2
    assert "{.accelab-wide}" in md and "{.accelab-narrow}" in md and "![two panels]" in md
    monkeypatch.setattr(renditions, "is_static", lambda: False)  # a live kernel
    shown.clear()
    renditions.show(draw, alt="two panels")
    assert len(shown) == 1 and hasattr(shown[0], "savefig")
    plt.close("all")


def test_math_is_typeset_once_for_every_figure():
    """accelab.course.mathtext_cache: the math parsers of two figures (renderers) share
    their results; a change of font, DPI or mathtext setting typesets again."""
    import matplotlib
    from matplotlib.font_manager import FontProperties
    from matplotlib.mathtext import MathTextParser

    from accelab.course.mathtext_cache import install

    install()
    install()  # once per process
    prop = FontProperties(size=10)
    one, two = MathTextParser("agg"), MathTextParser("agg")
    first = one.parse(r"$\mathbf{A}_{B}$", 100, prop)
    assert two.parse(r"$\mathbf{A}_{B}$", 100, prop) is first, "typeset once"
    assert two.parse(r"$\mathbf{A}_{B}$", 200, prop) is not first
    assert two.parse(r"$\mathbf{A}_{B}$", 100, FontProperties(size=12)) is not first
    italic = two.parse("$x$", 100, prop)
    with matplotlib.rc_context({"mathtext.default": "rm"}):  # upright letters
        upright = two.parse("$x$", 100, prop)
    assert upright is not italic and upright.image.tobytes() != italic.image.tobytes()
    assert MathTextParser("path").parse(r"$\mathbf{A}_{B}$", 100, prop) is not first


def test_results_read_as_text():
    """accelab.course.text: numbers with the digits they deserve, a true minus sign,
    units kept with their number."""
    from accelab.course.text import num, sci, table, vec

    assert num(-65000.4) == "\u221265\u202f000"
    assert num(2093.4, 2) == "2100" and num(3.9912, 3) == "3.99"
    assert sci(4.0e-8) == "$4.0\\times10^{-8}$" and sci(float("nan")) == "\u2014"
    assert vec(3 + 4j, "m/s^2") == "5.000\u00a0m/s\u00b2 at 53.1\u00b0"
    md = table(["", "$x$"], [["a", 1.5]], show=False).markdown
    assert md.splitlines()[1] == "|:--|--:|" and "| a | 1.500 |" in md


@pytest.mark.slow
def test_explore_shows_sliders_in_a_live_kernel():
    """Without ACCELAB_STATIC, inside a kernel, explore() builds ipywidgets sliders
    (one per keyword, with their ranges) and draws through them."""
    import nbformat

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
    notebook_client(
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


def test_notebook_11_quotes_the_benchmark_the_site_shows():
    """Notebook 11 quotes one benchmark run (course/benchmark.json); every number of it is
    the README's (whose benchmark section the site's Benchmark page includes), each time
    and error in the row of the case it names."""
    data = json.loads((COURSE / "benchmark.json").read_text())
    readme = (ROOT / "README.md").read_text()
    section = readme[
        readme.index("<!-- benchmark:start -->") : readme.index("<!-- benchmark:end -->")
    ]
    row = next(line for line in section.splitlines() if line.startswith(f"| {data['case']} |"))
    for name, v in data["methods"].items():
        assert f"{v['us']} µs / {v['error']}" in row, (name, v)
    for key, value in data.items():
        if isinstance(value, str) and key not in ("what", "case"):
            assert value in section, (key, value)
    assert "benchmark.json" in (COURSE / "11_speed_accuracy.py").read_text()


def test_notebook_11_is_short():
    """Rewritten for a kinematics student: about a third of its former length (1057 lines)."""
    assert len((COURSE / "11_speed_accuracy.py").read_text().splitlines()) <= 380


def test_the_count_of_notebooks_is_written_once():
    """'eleven notebooks' is written on the syllabus only, and says the truth."""
    words = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"]
    words += ["eleven", "twelve", "thirteen"]
    count = words[len(NOTEBOOKS)]
    places = [ROOT / "README.md", COURSE / "__init__.py"] + sorted((ROOT / "docs").rglob("*.md"))
    said = [p for p in places if re.search(rf"\b{count} notebooks", p.read_text(), re.I)]
    assert [p.name for p in said] == ["syllabus.md"], (
        f"docs/syllabus.md: write '{count} notebooks' (the course has {len(NOTEBOOKS)}), "
        f"there and nowhere else; it is written in: {[str(p.relative_to(ROOT)) for p in said]}"
    )


def test_the_syllabus_has_a_row_and_a_time_per_notebook_and_their_sum():
    """docs/syllabus.md's table has one row per notebook, in order, each with its time in
    hours, and the total below it ('About 17½ hours in all') is their sum."""
    text = (ROOT / "docs" / "syllabus.md").read_text()
    rows = re.findall(r"^\| \{doc\}`[^<]*<course/(\d\d_\w+)>` \|.*\| ([\d.]+) h \|$", text, re.M)
    assert [stem for stem, _ in rows] == [p.stem for p in NOTEBOOKS], (
        "docs/syllabus.md, 'The notebooks': one row per notebook, in order, ending '| N h |'"
    )
    hours = sum(float(h) for _, h in rows)
    said = re.search(r"About (\d+)(½?) hours in all", text)
    assert said, "docs/syllabus.md: say the total below the table, 'About N hours in all'"
    total = int(said.group(1)) + (0.5 if said.group(2) else 0.0)
    assert total == hours, f"docs/syllabus.md: the rows add up to {hours:g} hours, not {total:g}"
