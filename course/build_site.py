"""Build the self-study site from the executed course: ``python -m course.build_site``.

Every ``course/NN_slug.py`` (jupytext percent format) is executed headless
(working directory ``course/``, ``ACCELAB_STATIC=1``, so ``coursekit.explore``
draws its static figures) into ``build/course/NN_slug.ipynb``, and each
executed notebook becomes one page of ``build/site/``:

* an index page with the course outline, one line per notebook;
* one page per notebook: previous / contents / next navigation, the markdown
  rendered with its equations typeset at build time as MathML (Chromium,
  Firefox and Safari render it natively; nothing loads from a CDN), display
  equations numbered by their ``\\tag{7.4}``, answers folded in ``<details>``,
  code highlighted (long cells folded), outputs as text, and figures as PNG
  files (widget state is never shown: a notebook executed headless shows its
  static fallback figures).

Options: ``--reuse`` keeps executed notebooks newer than their sources (the
test session's, for example); ``--executed DIR`` and ``--out DIR`` move the
two build folders; ``--readme-figures figures`` also refreshes the course
figures the README shows (``figures/course-*.png``). The exit status is 1 if a notebook failed to execute (its
page is still built, showing the error), 0 otherwise.
"""

import argparse
import base64
import html
import json
import os
import re
import shutil
import string
import struct
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
EXECUTED = ROOT / "build" / "course"
SITE = ROOT / "build" / "site"
CELL_TIMEOUT = 300          # s per cell
FOLD_CODE_LINES = 14        # longer code cells are folded on the page
#: figures the README shows: file name -> (notebook, n-th figure of its executed outputs)
README_FIGURES = {"course-piston-acceleration.png": ("04_slider_crank_engine", 2)}

__all__ = ["sources", "execute", "executed_notebooks", "build", "main", "NotebookFailed"]


# ---------------------------------------------------------------- execution
class NotebookFailed(RuntimeError):
    """A notebook raised in a cell or wrote to stderr; the message lists where."""


def sources(course=HERE):
    """The course notebooks, in order: ``course/NN_*.py``."""
    return sorted(Path(course).glob("[0-9][0-9]_*.py"))


def kernel_env():
    """Environment of the kernel: headless figures, the inline backend, and the
    repository and ``course/`` importable (``solver``, ``coursekit``)."""
    env = dict(os.environ)
    env["ACCELAB_STATIC"] = "1"
    env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), str(HERE)]
                                        + [p for p in [env.get("PYTHONPATH")] if p])
    env.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    return env


def problems(nb):
    """Error outputs and stderr text of an executed notebook, one line each."""
    out = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        for o in cell.get("outputs", []):
            if o.output_type == "error":
                out.append(f"cell {i}: {o.ename}: {o.evalue}")
            elif o.output_type == "stream" and o.name == "stderr":
                out.append(f"cell {i}: stderr: {o.text.strip()[:500]}")
    return out


def execute(source, outdir=EXECUTED, timeout=CELL_TIMEOUT):
    """Convert ``source`` with jupytext, execute it with nbclient in ``course/``
    and write ``outdir/<stem>.ipynb`` (also when it fails, errors included).

    Returns the path; raises :class:`NotebookFailed` on a cell error or on any
    output to stderr."""
    import jupytext
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    source = Path(source)
    nb = jupytext.read(source)
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3", startup_timeout=120,
                            allow_errors=False, resources={"metadata": {"path": str(HERE)}})
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    target = outdir / (source.stem + ".ipynb")
    try:
        client.execute(env=kernel_env())
    except CellExecutionError as exc:
        _write_failed(nb, target)
        raise NotebookFailed(f"{source.name} failed:\n{exc}") from None
    except Exception as exc:  # a timeout, a dead kernel: the same verdict, with its kind
        _write_failed(nb, target)
        raise NotebookFailed(f"{source.name} failed: {type(exc).__name__}: {exc}") from None
    found = problems(nb)
    if found:
        _write_failed(nb, target)
        raise NotebookFailed(f"{source.name} wrote to stderr or failed:\n" + "\n".join(found))
    nbformat.write(nb, target)
    return target


def _write_failed(nb, target):
    """Keep a failed run to read, dated 1970 so that ``--reuse`` never takes it."""
    import nbformat
    nbformat.write(nb, target)
    os.utime(target, (0, 0))


def executed_notebooks(outdir=EXECUTED, reuse=False, log=print):
    """Execute every course notebook into ``outdir`` (with ``reuse``, keep the
    ones newer than their source and ``coursekit.py``). Returns
    ``({stem: path}, {stem: error message})``; a failed notebook is in both."""
    outdir = Path(outdir)
    kit = (HERE / "coursekit.py").stat().st_mtime
    paths, failed = {}, {}
    for src in sources():
        target = outdir / (src.stem + ".ipynb")
        if reuse and target.exists() and target.stat().st_mtime >= max(src.stat().st_mtime, kit):
            paths[src.stem] = target
            continue
        t0 = time.perf_counter()
        try:
            paths[src.stem] = execute(src, outdir)
            log(f"executed {src.stem} in {time.perf_counter() - t0:.1f} s")
        except NotebookFailed as exc:
            failed[src.stem] = str(exc)
            if target.exists():
                paths[src.stem] = target
            log(f"FAILED {src.stem}: {str(exc)[:300]}")
    return paths, failed


# ---------------------------------------------------------------- math
_DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.S)
_INLINE = re.compile(r"(?<![\\$])\$(?=\S)((?:\\.|[^$\\\n]|\n(?![ \t]*\n))+?)(?<=\S)\$(?!\$)")
_CODE = re.compile(r"(```.*?```|~~~.*?~~~|`[^`\n]+`)", re.S)
_TAG = re.compile(r"\\tag\*?\{([^}]*)\}")
_PLACEHOLDER = "MATHXPH{}XEND"


class _Math:
    """Typesets the LaTeX of one page as MathML, remembering each piece."""

    def __init__(self):
        from latex2mathml.converter import convert
        self._convert = convert
        self.pieces = []
        self.failures = []
        self.equations = 0

    def _mathml(self, tex, display):
        try:
            out = self._convert(tex.strip(), display="block" if display else "inline")
        except Exception as exc:  # shown as code, reported by build()
            self.failures.append(f"{tex.strip()[:80]!r}: {type(exc).__name__}: {exc}")
            return f'<code class="math-fallback">{html.escape(tex.strip())}</code>'
        return out

    def _display(self, m):
        tex = m.group(1)
        tags = _TAG.findall(tex)
        body = self._mathml(_TAG.sub("", tex), True)
        number = f'<span class="eqno">({html.escape(tags[-1])})</span>' if tags else ""
        self.equations += 1
        self.pieces.append(f'<div class="equation">{body}{number}</div>')
        return "\n\n" + _PLACEHOLDER.format(len(self.pieces) - 1) + "\n\n"

    def _inline(self, m):
        self.pieces.append(self._mathml(m.group(1), False))
        return _PLACEHOLDER.format(len(self.pieces) - 1)

    def protect(self, text):
        """Replace math by placeholders (code spans and blocks left alone)."""
        parts = _CODE.split(text)
        for i in range(0, len(parts), 2):
            parts[i] = _INLINE.sub(self._inline, _DISPLAY.sub(self._display, parts[i]))
        return "".join(parts)

    def restore(self, rendered):
        def put(m):
            return self.pieces[int(m.group(1))]
        rendered = re.sub(r"<p>\s*MATHXPH(\d+)XEND\s*</p>", put, rendered)
        return re.sub(r"MATHXPH(\d+)XEND", put, rendered)


# ---------------------------------------------------------------- markdown
def _markdown():
    from markdown_it import MarkdownIt
    return MarkdownIt("commonmark", {"html": True, "typographer": False}).enable("table")


def _slug(text, used):
    base = re.sub(r"[^a-z0-9]+", "-", re.sub(r"<[^>]+>", "", text).lower()).strip("-") or "s"
    slug, k = base, 2
    while slug in used:
        slug, k = f"{base}-{k}", k + 1
    used.add(slug)
    return slug


class _Page:
    """Renders the cells of one notebook into HTML."""

    def __init__(self, stem, pages, figdir, md):
        self.stem = stem
        self.pages = pages          # stems that have a page
        self.figdir = figdir
        self.md = md
        self.math = _Math()
        self.figures = []
        self.headings = []          # (level, id, html text)
        self.missing_links = []
        self._ids = set()

    def markdown(self, text, inline=False):
        protected = self.math.protect(text)
        out = self.md.renderInline(protected) if inline else self.md.render(protected)
        out = self.math.restore(out)
        out = self._links(out)
        return out if inline else self._heading_ids(out)

    def _heading_ids(self, out):
        def add(m):
            level, text = m.group(1), m.group(2)
            hid = _slug(text, self._ids)
            self.headings.append((int(level), hid, text))
            return f'<h{level} id="{hid}">{text}</h{level}>'
        return re.sub(r"<h([1-3])>(.*?)</h\1>", add, out, flags=re.S)

    def _links(self, out):
        def fix(m):
            stem, anchor, text = m.group(1), m.group(2) or "", m.group(3)
            if stem in self.pages:
                return f'<a href="{stem}.html{anchor}">{text}</a>'
            self.missing_links.append(stem)
            return f'<span class="missing" title="this notebook is not written yet">{text}</span>'
        return re.sub(r'<a href="(?:\./)?([0-9][0-9]_[A-Za-z0-9_]+)\.(?:ipynb|py|html)(#[^"]*)?">'
                      r"(.*?)</a>", fix, out, flags=re.S)

    def code(self, source):
        from pygments import highlight
        from pygments.formatters import HtmlFormatter
        from pygments.lexers import PythonLexer
        block = highlight(source, PythonLexer(), HtmlFormatter(cssclass="highlight"))
        n = source.count("\n") + 1
        if n > FOLD_CODE_LINES:
            return f'<details class="code"><summary>Code ({n} lines)</summary>{block}</details>'
        return block

    def figure(self, data, ext):
        raw = base64.b64decode(data) if ext == "png" else data.encode()
        name = f"{self.stem}-{len(self.figures) + 1}.{ext}"
        (self.figdir / name).write_bytes(raw)
        size = ""
        if ext == "png" and raw[:8] == b"\x89PNG\r\n\x1a\n":
            w, h = struct.unpack(">II", raw[16:24])
            size = f' width="{w}" height="{h}"'
        self.figures.append(name)
        alt = f"Figure {len(self.figures)} of notebook {self.stem[:2].lstrip('0')}"
        return f'<figure><img src="figures/{name}" alt="{alt}"{size} loading="eager"></figure>'

    def output(self, o):
        kind = o.get("output_type")
        if kind == "stream":
            cls = "output error" if o.get("name") == "stderr" else "output"
            return f'<div class="{cls}"><pre>{html.escape(o.get("text", ""))}</pre></div>'
        if kind == "error":
            tb = _ANSI.sub("", "\n".join(o.get("traceback", [])) or f"{o.ename}: {o.evalue}")
            return f'<div class="output error"><pre>{html.escape(tb)}</pre></div>'
        data = o.get("data", {})
        if "application/vnd.jupyter.widget-view+json" in data and "image/png" not in data:
            return ""                      # live widget state: nothing to show on a page
        if "image/png" in data:
            return self.figure(data["image/png"], "png")
        if "image/svg+xml" in data:
            return self.figure(data["image/svg+xml"], "svg")
        if "text/html" in data:
            return f'<div class="output html">{data["text/html"]}</div>'
        if "text/markdown" in data:
            return f'<div class="output">{self.markdown(data["text/markdown"])}</div>'
        if "text/latex" in data:
            return f'<div class="output">{self.markdown(data["text/latex"])}</div>'
        if "text/plain" in data:
            return f'<div class="output"><pre>{html.escape(data["text/plain"])}</pre></div>'
        return ""

    def cell(self, cell):
        if cell.cell_type == "markdown":
            return f'<section class="text">{self.markdown(cell.source)}</section>'
        if cell.cell_type != "code" or not cell.source.strip():
            return ""
        outs = "".join(self.output(o) for o in cell.get("outputs", []))
        return f'<div class="cell">{self.code(cell.source)}{outs}</div>'


_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")


def _title(nb, stem):
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            m = re.search(r"^#\s+(.+)$", cell.source, flags=re.M)
            if m:
                return m.group(1).strip()
    return stem


def _summary(nb):
    """The first sentence of the first paragraph after the title."""
    for cell in nb.cells:
        if cell.cell_type != "markdown":
            continue
        paras = [p.strip() for p in re.split(r"\n\s*\n", cell.source) if p.strip()]
        for p in paras:
            if p.startswith("#"):
                continue
            flat = " ".join(p.split())
            m = re.search(r"^(.{30,}?[.!?])(\s|$)", flat)
            return m.group(1) if m else flat
        break
    return ""


# ---------------------------------------------------------------- pages
def _pager(prev, nxt, titles, bottom=False):
    def link(stem, cls, arrow_left):
        if stem is None:
            return f'<span class="{cls} empty"></span>'
        text = html.escape(titles[stem])
        label = f"&larr; {text}" if arrow_left else f"{text} &rarr;"
        rel = "prev" if arrow_left else "next"
        return f'<a class="{cls}" rel="{rel}" href="{stem}.html">{label}</a>'
    cls = "pager bottom" if bottom else "pager"
    return (f'<nav class="{cls}">{link(prev, "prev", True)}'
            f'<a class="contents" href="index.html">Contents</a>{link(nxt, "next", False)}</nav>')


def _template():
    return string.Template((HERE / "site" / "page.html").read_text())


def _stylesheet():
    from pygments.formatters import HtmlFormatter
    css = (HERE / "site" / "style.css").read_text()
    return css + "\n/* code highlighting (pygments) */\n" + \
        HtmlFormatter(style="friendly").get_style_defs(".highlight")


def build(notebooks, out=SITE, log=print):
    """Write the site for ``notebooks`` (``{stem: executed .ipynb path}`` or a
    list of paths) into ``out``; returns the manifest (also written to
    ``out/manifest.json``): per page its title, equations, figures and links,
    plus the warnings (math that could not be typeset, links to notebooks
    that do not exist yet)."""
    import nbformat

    if not isinstance(notebooks, dict):
        notebooks = {Path(p).stem: Path(p) for p in notebooks}
    stems = sorted(notebooks)
    out = Path(out)
    if out.exists():
        shutil.rmtree(out)
    figdir = out / "figures"
    figdir.mkdir(parents=True)
    (out / "style.css").write_text(_stylesheet())
    md = _markdown()
    page_tpl = _template()
    nbs = {s: nbformat.read(notebooks[s], as_version=4) for s in stems}
    titles = {s: _title(nbs[s], s) for s in stems}
    manifest = {"pages": {}, "warnings": []}
    for i, stem in enumerate(stems):
        page = _Page(stem, set(stems), figdir, md)
        body = "".join(page.cell(c) for c in nbs[stem].cells)
        sections = [h for h in page.headings if h[0] == 2]
        if sections:
            items = "".join(f'<li><a href="#{hid}">{text}</a></li>' for _, hid, text in sections)
            toc = f'<nav class="toc"><strong>On this page</strong><ol>{items}</ol></nav>'
            body = body.replace("</h1>", "</h1>" + toc, 1)
        prev = stems[i - 1] if i > 0 else None
        nxt = stems[i + 1] if i + 1 < len(stems) else None
        text = page_tpl.substitute(
            title=html.escape(titles[stem]), body=body,
            where=f"notebook {i + 1} of {len(stems)}",
            pager=_pager(prev, nxt, titles), pager_bottom=_pager(prev, nxt, titles, True))
        (out / f"{stem}.html").write_text(text)
        manifest["pages"][f"{stem}.html"] = {
            "title": titles[stem], "equations": page.math.equations,
            "math": len(page.math.pieces), "figures": page.figures,
            "prev": f"{prev}.html" if prev else None, "next": f"{nxt}.html" if nxt else None}
        manifest["warnings"] += [f"{stem}: math not typeset: {w}" for w in page.math.failures]
        manifest["warnings"] += [f"{stem}: link to {m}, which has no page (shown as text)"
                                 for m in sorted(set(page.missing_links))]
    _index(out, stems, nbs, titles, md, page_tpl, manifest)
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1))
    for w in manifest["warnings"]:
        log(f"warning: {w}")
    return manifest


def _index(out, stems, nbs, titles, md, page_tpl, manifest):
    items = []
    for stem in stems:
        page = _Page(stem, set(stems), out / "figures", md)
        summary = page.markdown(_summary(nbs[stem]), inline=True)
        num, _, name = titles[stem].partition(". ")
        if not name:
            num, name = stem[:2].lstrip("0"), titles[stem]
        items.append(f'<li><span class="num">{html.escape(num)}.</span>'
                     f'<a href="{stem}.html">{html.escape(name)}</a><p>{summary}</p></li>')
    body = (
        "<h1>Acceleration analysis of planar linkages</h1>"
        "<p>A self-study course in notebooks: the acceleration of a rotating point, graphical "
        "and analytic solutions of the fourbar and the slider-crank, Coriolis acceleration, "
        "the geared fivebar, any point of a linkage, human tolerance of acceleration, jerk, "
        "linkages of any number of bars, and the speed and accuracy of the methods. Each "
        "notebook says what you will be able to do, "
        "develops the idea with the chapter's numbered equations, works examples with units, "
        "and ends with questions (answers folded) and the mistakes to avoid.</p>"
        "<p>Every computation on these pages was made by the tested <code>solver</code> package "
        "when the site was built. To move the sliders yourself, open the notebooks in "
        "<code>course/</code> with Jupyter (they are jupytext scripts: "
        "<code>jupytext --to notebook course/01_rotating_point.py</code>).</p>"
        f'<h2 id="contents">Contents</h2><ol class="outline">{"".join(items)}</ol>')
    text = page_tpl.substitute(title="Contents", body=body, where="course outline",
                               pager="", pager_bottom="")
    (out / "index.html").write_text(text)
    manifest["pages"]["index.html"] = {"title": "Contents", "equations": 0,
                                       "math": body.count("<math"), "figures": [],
                                       "prev": None, "next": None}


def readme_figures(notebooks, outdir):
    """Copy the course figures the README shows (:data:`README_FIGURES`) from
    the executed notebooks into ``outdir``; returns the paths written."""
    import nbformat
    written = []
    for name, (stem, k) in README_FIGURES.items():
        if stem not in notebooks:
            continue
        nb = nbformat.read(notebooks[stem], as_version=4)
        pngs = [o["data"]["image/png"] for c in nb.cells if c.cell_type == "code"
                for o in c.get("outputs", []) if "image/png" in o.get("data", {})]
        target = Path(outdir) / name
        target.write_bytes(base64.b64decode(pngs[k - 1]))
        written.append(target)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m course.build_site",
                                     description="Build the course's self-study site.")
    parser.add_argument("--out", type=Path, default=SITE, help="site folder (build/site)")
    parser.add_argument("--executed", type=Path, default=EXECUTED,
                        help="executed notebooks (build/course)")
    parser.add_argument("--reuse", action="store_true",
                        help="keep executed notebooks newer than their sources")
    parser.add_argument("--readme-figures", type=Path, metavar="DIR",
                        help="also write the course figures the README shows into DIR "
                             "(figures/)")
    args = parser.parse_args(argv)
    os.environ.setdefault("MPLBACKEND", "Agg")
    paths, failed = executed_notebooks(args.executed, reuse=args.reuse)
    manifest = build(paths, args.out)
    if args.readme_figures:
        for path in readme_figures(paths, args.readme_figures):
            print(f"wrote {path}")
    pages = len(manifest["pages"])
    figs = sum(len(p["figures"]) for p in manifest["pages"].values())
    eqs = sum(p["equations"] for p in manifest["pages"].values())
    print(f"site: {args.out}/index.html ({pages} pages, {eqs} display equations, "
          f"{figs} figures)")
    if failed:
        print(f"{len(failed)} notebook(s) failed: {', '.join(sorted(failed))}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
