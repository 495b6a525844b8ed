"""Sphinx configuration of accelab's documentation site (``make docs``).

Sphinx with MyST-NB reads the course notebooks (jupytext percent ``.py`` files
under ``course/``, linked here as ``docs/course``) and executes them with a
cache; sphinx-book-theme lays the pages out; autodoc with numpydoc writes the
API reference from the docstrings. Nothing on a page is fetched from the
network: MathJax is served from the site itself. ``docs/_ext/accelab_docs.py``
adds what the project needs on top (notebook downloads, figure links, the
tables generated from code).
"""

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path[:0] = [str(ROOT), str(HERE / "_ext"), str(HERE)]

import notebooks  # noqa: E402  (docs/notebooks.py: how the course is executed)

import accelab  # noqa: E402

notebooks.set_kernel_env()

project = "accelab"
author = "the accelab developers"
copyright = "2026, the accelab developers"
release = version = accelab.__version__  # the one place the version is written
# signatures name an object without its module path (the page and its heading say which
# module): accelab.solver.vectorloops.newton.SINGULAR_CONDITION does not fit a phone
add_module_names = False

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "numpydoc_once",
    "data_url_links",
    "readable_defaults",
    "sphinx.ext.mathjax",
    "math_at_build",
    "accelab_docs",
]

root_doc = "index"
exclude_patterns = [
    "_build",
    "*.py",
    "**/__pycache__",
    "**/.ipynb_checkpoints",
    "notebooks.py",
    "conf.py",
    "_ext",
    "course/[!0-9]*.py",
    "course/site",
    "**/*.ipynb",
    "api/generated/*.rst.txt",
]
templates_path = ["_templates"]
suppress_warnings = ["myst.header", "mystnb.unknown_mime_type"]
nitpicky = False
highlight_language = "text"  # literal blocks of the docstrings are formulas, not Python

# ---------------------------------------------------------------- MyST and notebooks
source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".py": "myst-nb"}
nb_custom_formats = {".py": ["jupytext.reads", {"fmt": "py:percent"}]}
myst_enable_extensions = [
    "dollarmath",
    "amsmath",
    "colon_fence",
    "deflist",
    "html_image",
    "attrs_inline",
]
myst_heading_anchors = 3
myst_dmath_double_inline = True
nb_execution_mode = "cache"
nb_execution_cache_path = str(notebooks.cache_path(prune=True))
nb_execution_timeout = notebooks.CELL_TIMEOUT
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_merge_streams = True
# Markdown outputs (a practice problem, its answers) read as the pages do: tables, math
nb_render_markdown_format = "myst"
nb_ipywidgets_js = {}  # never load the widget manager from a CDN
nb_output_stderr = "warn"

# ---------------------------------------------------------------- math, served locally
mathjax_path = "mathjax/tex-chtml.js"
mathjax3_config = {
    "tex": {"tags": "none"},
    "options": {"enableMenu": False},
}

# ---------------------------------------------------------------- API reference
autosummary_generate = True
autosummary_ignore_module_all = False
autodoc_default_options = {"members": True, "show-inheritance": False}
autodoc_member_order = "bysource"
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks = set()

# ---------------------------------------------------------------- HTML
html_theme = "sphinx_book_theme"
html_title = "accelab"
html_static_path = ["_static"]
html_favicon = "_static/favicon.svg"
html_css_files = ["accelab.css"]
html_js_files = ["accelab.js"]
html_last_updated_fmt = None
html_copy_source = False
html_show_sourcelink = False
html_search_scorer = str(HERE / "search_scorer.js")  # prose before API objects
html_theme_options = {
    "footer_content_items": ["copyright.html", "licence-footer.html"],
    "home_page_in_toc": True,
    "show_navbar_depth": 1,
    "use_download_button": False,
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "show_toc_level": 2,
    "navigation_with_keys": False,
}
html_context = {"default_mode": "light"}
