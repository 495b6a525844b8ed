"""Math typeset once, when the site is built, instead of on every reader's screen.

With MathJax in the page, every page load typesets its formulas again in the reader's
browser: about a second of a phone's CPU on a course page, and the text reflows when the
math appears. Where ``node`` is on PATH, this extension runs the MathJax the site serves
(``sphinx-mathjax-offline``'s, the same TeX input and CHTML output) once over every formula
of the site (``math_at_build.js``) and writes the result into the pages: a page carries its
typeset math and a stylesheet (``_static/math-chtml.css``), and no script.

Without ``node`` (or with ``ACCELAB_DOCS_MATH=browser``), ``sphinx.ext.mathjax`` renders
the math as before: MathJax typesets it in the browser, from the site's own copy. A ``node``
on PATH that does not run does the same, with a warning that says so.

A formula MathJax cannot read is a build warning naming its page (``make docs`` fails on
it), where the browser would have shown it in red to the reader.
"""

import hashlib
import json
import os
import shutil
import subprocess
from pathlib import Path

from docutils import nodes
from sphinx.errors import ExtensionError
from sphinx.locale import _
from sphinx.util import logging
from sphinx.util.math import get_node_equation_number

logger = logging.getLogger(__name__)

RENDERER = "accelab_chtml"
#: ``browser``: leave the math to MathJax in the reader's browser
CHOICE = "ACCELAB_DOCS_MATH"
STYLESHEET = "math-chtml.css"
SCRIPT = Path(__file__).with_suffix(".js")
#: the stylesheet's fonts, from ``_static/`` (accelab_docs.copy_mathjax copies them there)
FONT_URL = "mathjax/output/chtml/fonts/woff-v2"
#: MathJax sizes its math so that its x-height matches the text's, as MathJax in the browser
#: does on each formula: 123.7 % of the theme's body font, measured by MathJax in Chromium on
#: a phone (390 px, 3 device pixels per px). A laptop's screen measures the x-height in whole
#: pixels (9 of 16) and gets 127.3 %; the phone's is the closer measure, and the one whose
#: narrow column the equations are written to fit
SCALE = "123.7%"
#: the whole site's formulas, typeset (a cache in the doctree folder, keyed by their hash)
CACHE = "math-chtml.json"


def _mathjax_dir():
    from accelab_docs import _mathjax_dir as find

    return find()


def _node():
    return shutil.which("node") or shutil.which("nodejs")


def choose_renderer(app, config):
    """Typeset at build time where ``node`` and MathJax's node build are there; otherwise
    (or when ``ACCELAB_DOCS_MATH=browser``) in the browser."""
    mathjax = _mathjax_dir()
    wanted = os.environ.get(CHOICE, "build")
    if wanted not in ("build", "browser"):
        logger.warning(
            f"{CHOICE}={wanted!r}: use 'build' or 'browser'; the math is typeset at build"
        )
    if wanted == "browser" or _node() is None or mathjax is None:
        config.html_math_renderer = "mathjax"
        if wanted != "browser":
            logger.info("math: no node on PATH, MathJax typesets it in the browser")
        return
    if not (mathjax / "node-main.js").is_file():
        config.html_math_renderer = "mathjax"
        return
    broken = _node_fails()
    if broken:
        config.html_math_renderer = "mathjax"
        logger.warning(
            f"math: {_node()} does not run ({broken}): MathJax typesets the math in the "
            f"browser; mend node, or set {CHOICE}=browser to say that this is meant"
        )
        return
    config.html_math_renderer = RENDERER


def _node_fails():
    """Why ``node`` cannot run (a sentence), or None when it runs."""
    try:
        done = subprocess.run([_node(), "--version"], capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired) as exc:
        return str(exc)
    if done.returncode != 0:
        return f"exit {done.returncode}: {done.stderr.strip()[-200:]}"
    return None


def display_tex(node):
    """The TeX of a display formula as one formula: its parts (separated by a blank line)
    aligned one under another, a part of several lines (``\\\\``) as a ``split``."""
    text = node.astext()
    if node.get("no-wrap", node.get("nowrap", False)):
        return text
    parts = [p for p in text.split("\n\n") if p.strip()]
    parts = [rf"\begin{{split}}{p}\end{{split}}" if r"\\" in p else p for p in parts]
    if len(parts) > 1:
        return r"\begin{align}\begin{aligned}" + r"\\".join(parts) + r"\end{aligned}\end{align}"
    return parts[0] if parts else ""


def _formulas(env):
    """``{(tex, display): first docname}`` of every formula of the site."""
    found = {}
    for docname in sorted(env.found_docs):
        try:
            doctree = env.get_doctree(docname)
        except FileNotFoundError:  # excluded or failed to read: no page of its own
            continue
        for node in doctree.findall(nodes.math):
            found.setdefault((node.astext(), False), docname)
        for node in doctree.findall(nodes.math_block):
            found.setdefault((display_tex(node), True), docname)
    return found


def _typeset(formulas):
    """Run MathJax over ``formulas`` ([(tex, display)]): (html list, css, errors)."""
    done = subprocess.run(
        [_node(), str(SCRIPT), str(_mathjax_dir()), FONT_URL],
        input=json.dumps(formulas),
        capture_output=True,
        text=True,
        timeout=600,
    )
    if done.returncode != 0:
        raise ExtensionError(
            f"node {SCRIPT.name} failed (exit {done.returncode}): {done.stderr.strip()[-500:]}; "
            f"{CHOICE}=browser builds the site with MathJax in the browser"
        )
    out = json.loads(done.stdout)
    return out["html"], out["css"], out["errors"]


def typeset_site(app, env):
    """Typeset every formula of the site once (or read them from the cache of the last
    build, when the site's formulas are the same)."""
    if app.builder.format != "html" or app.builder.math_renderer_name != RENDERER:
        return
    found = _formulas(env)
    formulas = sorted(found)
    made_by = [SCRIPT.read_text(), str(_mathjax_dir()), FONT_URL]  # another MathJax: again
    key = hashlib.sha256(json.dumps([made_by, formulas]).encode()).hexdigest()
    cache = Path(app.doctreedir) / CACHE
    try:
        saved = json.loads(cache.read_text())
    except (OSError, ValueError):
        saved = {}
    if saved.get("key") == key:
        html, css, errors = saved["html"], saved["css"], saved["errors"]
    else:
        html, css, errors = _typeset(formulas)
        cache.write_text(json.dumps({"key": key, "html": html, "css": css, "errors": errors}))
    for index, message in errors:
        tex, _display = formulas[index]
        logger.warning(f"math: TeX error in {tex!r}: {message}", location=found[formulas[index]])
    app.accelab_math = dict(zip(formulas, html))
    app.accelab_math_css = css


def _typeset_html(translator, tex, display):
    html = getattr(translator.builder.app, "accelab_math", {}).get((tex, display))
    if html is None:
        logger.warning(f"math: {tex!r} was not typeset with the site", location=translator.document)
        return translator.encode(tex)
    return html


def visit_math(self, node):
    self.body.append(self.starttag(node, "span", "", CLASS="math notranslate nohighlight"))
    self.body.append(_typeset_html(self, node.astext(), False) + "</span>")
    raise nodes.SkipNode


def visit_displaymath(self, node):
    self.body.append(self.starttag(node, "div", CLASS="math notranslate nohighlight"))
    nowrap = node.get("no-wrap", node.get("nowrap", False))
    if node["number"] and not nowrap:
        self.body.append(f'<span class="eqno">({get_node_equation_number(self, node)})')
        self.add_permalink_ref(node, _("Link to this equation"))
        self.body.append("</span>")
    self.body.append(_typeset_html(self, display_tex(node), True) + "</div>\n")
    raise nodes.SkipNode


def add_stylesheet(app):
    if app.builder.format == "html" and app.builder.math_renderer_name == RENDERER:
        app.add_css_file(STYLESHEET)


def write_stylesheet(app, exc):
    css = getattr(app, "accelab_math_css", None)
    if exc is not None or css is None:
        return
    path = Path(app.outdir) / "_static" / STYLESHEET
    path.parent.mkdir(parents=True, exist_ok=True)
    text = f'mjx-container[jax="CHTML"] {{\n  font-size: {SCALE};\n}}\n\n{css}'
    if not path.is_file() or path.read_text() != text:
        path.write_text(text)


def setup(app):
    app.add_html_math_renderer(RENDERER, (visit_math, None), (visit_displaymath, None))
    app.connect("config-inited", choose_renderer)
    app.connect("builder-inited", add_stylesheet)
    app.connect("env-updated", typeset_site)
    app.connect("build-finished", write_stylesheet)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
