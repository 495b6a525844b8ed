"""The site's math typeset at build time (``docs/_ext/math_at_build.py``): the TeX a display
formula becomes, the choice between build and browser, and MathJax run under node on a few
formulas (a TeX error is reported, not shown in red to a reader). The whole site built and
read this way: tests/test_docs.py."""

import shutil
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest
from docutils import nodes

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "docs" / "_ext"))
import math_at_build  # docs/_ext is not a package: its folder is put on the path


def block(text, **attrs):
    node = nodes.math_block(text, text)
    node.update_all_atts(attrs)
    return node


def test_display_tex_aligns_parts_and_splits_lines():
    assert math_at_build.display_tex(block("a = b")) == "a = b"
    assert math_at_build.display_tex(block("a = b \\\\ c = d")) == (
        "\\begin{split}a = b \\\\ c = d\\end{split}"
    )
    assert math_at_build.display_tex(block("a = b\n\nc = d")) == (
        "\\begin{align}\\begin{aligned}a = b\\\\c = d\\end{aligned}\\end{align}"
    )
    env = "\\begin{align} a &= b \\\\ c &= d \\end{align}"
    assert math_at_build.display_tex(block(env, nowrap=True)) == env


def _node_that_runs(folder):
    path = folder / "node"
    path.write_text("#!/bin/sh\necho v20.0.0\n")
    path.chmod(0o755)
    return str(path)


def _chosen(monkeypatch, environ=None, node=None):
    monkeypatch.setattr(math_at_build, "_node", lambda: node)
    if environ is None:
        monkeypatch.delenv(math_at_build.CHOICE, raising=False)
    else:
        monkeypatch.setenv(math_at_build.CHOICE, environ)
    config = SimpleNamespace(html_math_renderer=None)
    math_at_build.choose_renderer(None, config)
    return config.html_math_renderer


def test_the_math_is_typeset_at_build_unless_node_is_missing_or_the_browser_is_asked(
    monkeypatch, tmp_path
):
    pytest.importorskip("sphinx")
    if math_at_build._mathjax_dir() is None:
        pytest.skip("sphinx-mathjax-offline is not installed (the docs extra)")
    node = _node_that_runs(tmp_path)
    assert _chosen(monkeypatch, node=node) == math_at_build.RENDERER
    assert _chosen(monkeypatch, "build", node=node) == math_at_build.RENDERER
    assert _chosen(monkeypatch, "browser", node=node) == "mathjax"
    assert _chosen(monkeypatch, node=None) == "mathjax"


def test_node_typesets_and_names_a_tex_error():
    if math_at_build._node() is None:
        pytest.skip("node is not on PATH: the site typesets its math in the browser")
    if math_at_build._mathjax_dir() is None:
        pytest.skip("sphinx-mathjax-offline is not installed (the docs extra)")
    html, css, errors = math_at_build._typeset(
        [["\\ddot{\\theta}_3", False], ["\\frac{1}{", True], ["A_{BA}^t", True]]
    )
    assert len(html) == 3 and all(h.startswith("<mjx-container") for h in html)
    assert 'display="true"' in html[2] and 'display="true"' not in html[0]
    assert [index for index, _ in errors] == [1], errors
    assert (
        "mjx-c.mjx-c1D703.TEX-I" in css
    )  # theta: the stylesheet has the characters the formulas use
    assert f'url("{math_at_build.FONT_URL}/MathJax_Zero.woff")' in css
    assert shutil.which("node") or shutil.which("nodejs")


def test_a_node_that_does_not_run_leaves_the_math_to_the_browser_and_says_so(monkeypatch, tmp_path):
    pytest.importorskip("sphinx")
    if math_at_build._mathjax_dir() is None:
        pytest.skip("sphinx-mathjax-offline is not installed (the docs extra)")
    broken = tmp_path / "node"
    broken.write_text("#!/bin/sh\necho 'node: cannot load libnode' >&2\nexit 3\n")
    broken.chmod(0o755)
    said = []
    monkeypatch.setattr(math_at_build.logger, "warning", lambda text, **kw: said.append(text))
    assert _chosen(monkeypatch, node=str(broken)) == "mathjax"
    assert len(said) == 1 and "exit 3: node: cannot load libnode" in said[0], said
    assert "ACCELAB_DOCS_MATH=browser" in said[0]
