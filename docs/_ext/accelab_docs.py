"""What accelab's site needs on top of Sphinx, MyST-NB and the book theme.

* Course pages: the notebooks' own ``[Next: ...](NN_slug.ipynb)`` links point
  at the next page, and each page gets a line under its title that downloads
  the notebook as ``.ipynb`` (written next to the page at the end of the build, as
  ``accelab course --out`` writes it: without outputs, the same file every build; it
  imports the installed package).
* Every figure is a link to its own image file, so a tap on a phone opens it
  at full size.
* MathJax is served from the site (the copy the ``sphinx-mathjax-offline``
  package ships: MathJax 3 with its fonts), so no equation needs the network; its fonts
  serve the math typeset at build time (``math_at_build.py``), its script the browser
  where the site was built without ``node``.
* Directives that generate tables from code: ``accelab-families`` (the problem
  families with their default ranges), ``accelab-family-notebooks`` (which
  notebook teaches each family).
"""

import base64
import hashlib
import importlib.util
import posixpath
import re
import shutil
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from sphinx import addnodes
from sphinx.util import logging
from sphinx.util.osutil import relative_uri

logger = logging.getLogger(__name__)

COURSE_DOC = re.compile(r"^course/(\d\d_[A-Za-z0-9_]+)$")
NOTEBOOK_LINK = re.compile(r"\[([^\]`]+)\]\((\d\d_[A-Za-z0-9_]+)\.ipynb\)")
#: a link from a notebook to a page beside it (the errata)
PAGE_LINK = re.compile(r"\[([^\]`]+)\]\((errata)\.md\)")


# ---------------------------------------------------------------- course pages
def _course_stem(docname):
    m = COURSE_DOC.match(docname)
    return m.group(1) if m else None


def _download_line(stem):
    return (
        f'<p class="nb-download">'
        f'<a class="nb-download-link" href="{stem}.ipynb" download="{stem}.ipynb" '
        f'type="application/x-ipynb+json">Download this notebook (.ipynb)</a>'
        f'<span class="nb-download-note"> and run it in Jupyter with accelab installed '
        f'(<a href="../install.html">how to install</a>).</span></p>'
    )


def source_read(app, docname, source):
    """Course notebooks: retarget the next-notebook links and add the download line."""
    stem = _course_stem(docname)
    if stem is None:
        return
    # a {doc} role: the notebooks sit behind a symbolic link (docs/course), where
    # MyST's path links would resolve outside the source folder
    text = NOTEBOOK_LINK.sub(lambda m: f"{{doc}}`{m.group(1)} </course/{m.group(2)}>`", source[0])
    text = PAGE_LINK.sub(lambda m: f"{{doc}}`{m.group(1)} </course/{m.group(2)}>`", text)
    lines = text.split("\n")
    for i, line in enumerate(lines):  # the first '# # Title' of a markdown cell
        if re.match(r"^# # \S", line):
            lines[i + 1 : i + 1] = ["#", "# " + _download_line(stem)]
            break
    source[0] = "\n".join(lines)


def write_notebooks(app, exc):
    """Write each course page's notebook (.ipynb, no outputs) next to its page, as
    ``accelab course --out`` writes it (the notebooks import everything from the
    installed package)."""
    if exc is not None or app.builder.format != "html":
        return
    import nbformat

    from accelab.course.cli import to_notebook

    out = Path(app.outdir)
    done = 0
    for docname in app.env.found_docs:
        stem = _course_stem(docname)
        if stem is None:
            continue
        source = Path(app.env.doc2path(docname))
        target = out / "course" / f"{stem}.ipynb"
        target.parent.mkdir(parents=True, exist_ok=True)
        nbformat.write(to_notebook(source), target)  # as `accelab course --out` writes it
        done += 1
    logger.info(f"wrote {done} course notebooks for download")


# ---------------------------------------------------------------- equations
TAG = re.compile(r"\\tag\*?\{([^{}]*)\}")


def number_equations(app, doctree):
    """Display equations numbered as the chapter numbers them (``\\tag{7.19a}``)
    get that number beside them, outside the typeset equation, with an anchor
    (``#eq-7-19a``): the equation alone scrolls sideways when it is wider than
    the page, the number stays in view."""
    used = set()
    for node in doctree.findall(nodes.math_block):
        text = node.astext()
        tags = TAG.findall(text)
        if not tags or node.get("nowrap") or node.get("no-wrap"):
            continue
        number = tags[-1].strip()
        body = TAG.sub("", text).rstrip()
        node.children = [nodes.Text(body)]
        node["number"] = number
        anchor = "eq-" + re.sub(r"[^0-9A-Za-z]+", "-", number).strip("-").lower()
        k, unique = 1, anchor
        while unique in used or unique in doctree.ids:
            k += 1
            unique = f"{anchor}-{k}"
        used.add(unique)
        node["ids"].insert(0, unique)
        doctree.ids[unique] = node


# ---------------------------------------------------------------- figures
#: classes of the renditions of one figure (accelab.course.renditions): the page's
#: stylesheet shows the one that fits the screen
RENDITIONS = ("accelab-wide", "accelab-narrow")


def _in_figure(node):
    parent = node.parent
    while parent is not None:
        if isinstance(parent, nodes.figure):
            return True
        parent = parent.parent
    return False


def caption_images(app, doctree):
    """A picture standing alone in its paragraph (``![what it shows](file.png)``
    in Markdown) becomes a figure whose caption is its alt text, unless it is
    inside a figure already (a notebook output with a caption in its cell)."""
    for para in list(doctree.findall(nodes.paragraph)):
        kids = [k for k in para.children if not (isinstance(k, nodes.Text) and not k.strip())]
        if len(kids) != 1 or not isinstance(kids[0], nodes.image):
            continue
        image = kids[0]
        alt = image.get("alt", "").strip()
        if not alt or _in_figure(para):
            continue
        figure = nodes.figure("", image.deepcopy(), nodes.caption(alt, alt))
        figure["classes"] += [c for c in image.get("classes", []) if c in RENDITIONS]
        para.replace_self(figure)
        doctree.set_id(figure)


def _embedded_to_file(app, uri):
    """The file name in ``_images`` of an image embedded as a base64 ``data:``
    URI (a notebook's Markdown output holds its figure so), written out once:
    a browser opens a file at full size, but never navigates to a data URI."""
    head, _, data = uri.partition(",")
    kind = re.fullmatch(r"data:image/(png|jpeg|gif|svg\+xml);base64", head)
    if not kind:
        return None
    raw = base64.b64decode(data)
    name = f"embedded-{hashlib.sha1(raw).hexdigest()[:16]}.{kind.group(1).split('+')[0]}"
    folder = Path(app.builder.outdir) / "_images"
    folder.mkdir(parents=True, exist_ok=True)
    if not (folder / name).exists():
        (folder / name).write_bytes(raw)
    return name


#: widest figure [CSS px] a phone shows shrunk to its screen: a wider chart (the
#: benchmark's, 1300 px and more) would be unreadable at 342 px, so there it keeps
#: its size (1 in of figure = 100 CSS px) and scrolls sideways in its box
SCROLL_CHART = 800


def _chart_width(app, uri):
    """The width [CSS px] of a local image file at 100 px per inch of its DPI, or None."""
    path = (Path(app.srcdir) / uri).resolve()
    if not path.is_file() or path.suffix.lower() != ".png":
        return None
    try:
        from PIL import Image

        with Image.open(path) as im:
            dpi = (im.info.get("dpi") or (100, 100))[0] or 100
            return round(im.size[0] * 100 / dpi)
    except OSError:
        return None


def link_images(app, doctree, docname):
    """Wrap every image that is not already a link in a link to its file."""
    if app.builder.format != "html":
        return
    imgdir = relative_uri(app.builder.get_target_uri(docname), "_images")
    for image in list(doctree.findall(nodes.image)):
        if isinstance(image.parent, nodes.reference):
            continue
        uri = image.get("candidates", {}).get("*", image["uri"])
        embedded = _embedded_to_file(app, uri) if uri.startswith("data:") else None
        if uri in app.env.images:
            refuri = posixpath.join(imgdir, app.env.images[uri][1])
        elif embedded:
            refuri = posixpath.join(imgdir, embedded)
            image["uri"] = refuri
            image["candidates"] = {"*": refuri}
        elif "://" in uri or uri.startswith("data:"):
            continue
        else:
            refuri = uri
        classes = ["image-full-size"] + [c for c in image.get("classes", []) if c in RENDITIONS]
        width = None if "://" in uri or uri.startswith("data:") else _chart_width(app, uri)
        if width and width > SCROLL_CHART and isinstance(image.parent, nodes.figure):
            image.parent["classes"].append("scroll-chart")
            image["width"] = f"{width}px"
        ref = nodes.reference("", "", internal=True, refuri=refuri, classes=classes)
        ref["reftitle"] = "Open the image at full size"
        image.replace_self(ref)
        ref.append(image)


DATA_URI = re.compile(r"data:image/(png|jpeg|gif);base64,([A-Za-z0-9+/=]+)")


def player_frames(app, doctree, docname):
    """The frames of an animation player (raw HTML with ``data:`` URIs, from
    :mod:`accelab.course.player`) written out as image files once each, so that
    the page stays small and a browser loads only the frames it plays."""
    if app.builder.format != "html":
        return
    imgdir = relative_uri(app.builder.get_target_uri(docname), "_images")
    for raw in list(doctree.findall(nodes.raw)):
        text = raw.astext()
        if "accelab-player" not in text or "data:image/" not in text:
            continue

        def out(m):
            name = _embedded_to_file(app, m.group(0))
            return posixpath.join(imgdir, name) if name else m.group(0)

        new = DATA_URI.sub(out, text)
        raw.replace_self(nodes.raw("", new, format="html"))


#: a word with a hyphen inside ("slider-crank", "7-1;")
HYPHENATED = re.compile(r"\S*\w-\w\S*")


def drop_empty_field_lists(app, doctree):
    """An API entry whose value is hidden (``:meta hide-value:``) keeps an empty field
    list, which held the hidden field: it is dropped, so the entry ends with its text
    (spaced as every other entry)."""
    for field_list in list(doctree.findall(nodes.field_list)):
        if not field_list.children:
            field_list.parent.remove(field_list)


def unbreakable_words(app, doctree):
    """In a table cell a line may break between words but never inside one: a
    hyphenated word ("slider-crank", "problem 7-1") is kept on one line (a table
    wider than a phone scrolls in its box instead)."""
    for entry in doctree.findall(nodes.entry):
        for text in list(entry.findall(nodes.Text)):
            parent = text.parent
            if isinstance(parent, (nodes.literal, nodes.math, nodes.raw, nodes.inline)):
                continue
            value = str(text)
            if not HYPHENATED.search(value):
                continue
            pieces, pos = [], 0
            for m in HYPHENATED.finditer(value):
                if m.start() > pos:
                    pieces.append(nodes.Text(value[pos : m.start()]))
                pieces.append(nodes.inline(m.group(0), m.group(0), classes=["nobreak"]))
                pos = m.end()
            if pos < len(value):
                pieces.append(nodes.Text(value[pos:]))
            parent.replace(text, pieces)


#: text touching a formula on either side, up to the nearest space: "(" before it, "):" after it
TOUCHING_BEFORE = re.compile(r"\S+$")
TOUCHING_AFTER = re.compile(r"^\S+")


def math_keeps_what_touches_it(app, doctree):
    """Inline math and the text that touches it (an opening parenthesis, closing
    punctuation, a suffix) stay on one line. A browser may break a line on either side of
    MathJax's box, so a ")" or ":" could start a line of its own in a narrow column."""
    for math in list(doctree.findall(nodes.math)):
        parent = math.parent
        if parent is None or "nobreak" in parent.get("classes", []):
            continue
        i = parent.index(math)
        before = parent[i - 1] if i > 0 and isinstance(parent[i - 1], nodes.Text) else None
        after = (
            parent[i + 1] if i + 1 < len(parent) and isinstance(parent[i + 1], nodes.Text) else None
        )
        lead = TOUCHING_BEFORE.search(str(before)) if before is not None else None
        trail = TOUCHING_AFTER.search(str(after)) if after is not None else None
        if not (lead or trail):
            continue
        span = nodes.inline("", "", classes=["nobreak"])
        if lead:
            span += nodes.Text(lead.group(0))
        parent.replace(math, span)
        span += math
        if trail:
            span += nodes.Text(trail.group(0))
            rest = str(after)[trail.end() :]
            if rest:
                parent.replace(after, nodes.Text(rest))
            else:
                parent.remove(after)
        if lead:
            rest = str(before)[: lead.start()]
            if rest:
                parent.replace(before, nodes.Text(rest))
            else:
                parent.remove(before)


# ---------------------------------------------------------------- API pages
#: the packages the API reference documents, every public module of each
API_PACKAGES = ("accelab.solver", "accelab.exercises")


def _modules(package):
    """``[(module name, is a package)]`` of ``package`` and everything below it
    (private modules, whose name starts with ``_``, left out)."""
    import importlib
    import pkgutil

    top = importlib.import_module(package)
    out = [(package, True)]
    for info in pkgutil.walk_packages(top.__path__, package + "."):
        if any(part.startswith("_") for part in info.name.split(".")):
            continue
        out.append((info.name, info.ispkg))
    return out


def _api_package(module_name):
    """The documented package ``module_name`` belongs to, or None."""
    return next(
        (p for p in API_PACKAGES if module_name == p or str(module_name).startswith(p + ".")), None
    )


def _ours(module_name):
    return bool(module_name) and _api_package(module_name) is not None


def _assigned_here(module, attr):
    """True when ``attr`` is assigned at the top level of ``module``'s source
    (``ureg = pint.UnitRegistry()``): an object of another library that this
    module defines for the package."""
    import inspect

    try:
        source = inspect.getsource(module)
    except (OSError, TypeError):
        return False
    return re.search(rf"^{re.escape(attr)}\s*=", source, re.M) is not None


def _exports(name):
    """``(defined, reexported)`` of a module's ``__all__``: the foreign objects
    it defines itself (documented here as data), and ``[(public name,
    canonical target)]`` of what it brings in from the package's other modules
    (documented where they are defined)."""
    import importlib

    mod = importlib.import_module(name)
    defined, out = [], []
    for attr in getattr(mod, "__all__", []):
        obj = getattr(mod, attr, None)
        home = (
            getattr(obj, "__module__", None)
            if not isinstance(obj, (int, float, str, dict, list, tuple))
            else None
        )
        qual = getattr(obj, "__qualname__", None)
        if home == name or home is None:
            continue
        if _ours(home) and qual and not any(p.startswith("_") for p in home.split(".")):
            out.append((attr, f"{home}.{qual}"))
        elif _assigned_here(mod, attr):
            defined.append(attr)
        else:  # a foreign object defined by one of our modules
            owner = _definer(name, attr)
            if owner:
                out.append((attr, f"{owner}.{attr}"))
    return defined, out


def _definer(package, attr):
    import importlib

    for modname, _ in _modules(_api_package(package) or package):
        try:
            mod = importlib.import_module(modname)
        except Exception:  # noqa: BLE001  a module that does not import defines nothing here
            continue
        if modname != package and attr in getattr(mod, "__all__", []) and _assigned_here(mod, attr):
            return modname
    return None


def api_pages():
    """``{page name: reST text}``: one page per (sub)package, each module of it
    with its members, from the docstrings."""
    pages = {}
    for package in API_PACKAGES:
        groups = {}
        depth = package.count(".") + 2  # accelab.solver.kernels: one page per subpackage
        for name, ispkg in _modules(package):
            parts = name.split(".")
            key = ".".join(parts[:depth]) if (len(parts) > depth or ispkg) else package
            groups.setdefault(key, []).append((name, ispkg))
        for key, members in groups.items():
            title = f"``{key}``"
            lines = [title, "=" * len(title), ""]
            for name, ispkg in members:
                import importlib

                try:
                    importlib.import_module(name)
                except Exception as exc:  # noqa: BLE001  reported as a warning, never hidden
                    logger.warning(f"API reference: cannot import {name}: {exc}")
                    continue
                if name != key:
                    sub = f"``{name}``"
                    lines += [sub, "-" * len(sub), ""]
                defined, exported = _exports(name)
                lines += [f".. automodule:: {name}", "   :members:", "   :undoc-members:"]
                skip = [a for a, _ in exported] + defined
                if skip:  # each object is documented once, in its own module
                    lines.append("   :exclude-members: " + ", ".join(skip))
                lines.append("")
                for attr in defined:
                    lines += [f".. autodata:: {name}.{attr}", "   :no-value:", ""]
                if ispkg:
                    if exported:
                        lines += [f"``{name}`` also offers, documented where they are defined:", ""]
                        lines += [
                            f"* :py:obj:`{name}.{attr} <{target}>`" for attr, target in exported
                        ]
                        lines.append("")
            pages[key] = "\n".join(lines)
    return pages


PIPE = re.compile(r"(?<!\\)\|")


def _indent(line):
    return len(line) - len(line.lstrip())


SECTION_RULE = re.compile(r"^\s*-{3,}\s*$")
TABLE_RULE = re.compile(r"^\s*=+(\s+=+)+\s*$")


def _table_ok(lines, start, end):
    """True when every row of the simple table ``lines[start:end]`` keeps its
    text inside the columns its top border marks (the last column may run on)."""
    border = lines[start]
    gaps = [k for k in range(len(border.rstrip())) if border[k] == " "]
    for line in lines[start:end]:
        if TABLE_RULE.match(line):
            continue
        if any(k < len(line) and line[k] != " " for k in gaps):
            return False
    return True


def _table_end(lines, i):
    """Index after the simple table whose top border is line ``i``."""
    j = i + 1
    while j < len(lines):
        if TABLE_RULE.match(lines[j]) and (j + 1 == len(lines) or not lines[j + 1].strip()):
            return j + 1
        j += 1
    return j


def plain_docstring(app, what, name, obj, options, lines):
    """The docstrings are written to read as plain text too; make that text
    valid reStructuredText before numpydoc parses it:

    * ``|x|`` means an absolute value there, not a substitution: such bars are
      escaped (not in grid tables or line blocks, whose lines start ``| `` or
      ``+``);
    * in the prose before the numpydoc sections, an indented block under a line
      (a formula, the loop equation) is shown as it is written, as a literal
      block, with or without a colon or a blank line before it.
    """
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        if "|" in line and not stripped.startswith(("| ", "+")) and stripped != "|":
            lines[i] = PIPE.sub(r"\\|", line)
    i = 0
    while i < len(lines) - 1:
        if SECTION_RULE.match(lines[i + 1]) and lines[i].strip():
            break  # numpydoc sections from here on
        if TABLE_RULE.match(lines[i]):
            end = _table_end(lines, i)
            if not _table_ok(lines, i, end):  # show it as written, in a literal block
                lines[i:end] = ["::", ""] + ["    " + line for line in lines[i:end]] + [""]
                end += 3
            i = end
            continue
        head = lines[i].rstrip()
        j = i + 1
        while j < len(lines) and not lines[j].strip():
            j += 1
        if (
            head.strip()
            and j < len(lines)
            and _indent(lines[j]) > _indent(head)
            and not head.lstrip().startswith((":", "..", ">>>"))
            and not head.endswith("::")
            and _indent(head) == 0
        ):
            end = j
            while end < len(lines) and (
                not lines[end].strip() or _indent(lines[end]) > _indent(head)
            ):
                end += 1
            while end > j and not lines[end - 1].strip():
                end -= 1
            block = lines[j:end]
            if (
                head.lstrip().startswith(("``", "*", "-"))  # a list or a definition term
                or re.match(r"\d+[.)] ", head.lstrip())
            ):
                if end < len(lines) and lines[end].strip():
                    lines.insert(end, "")  # it must end with a blank line
                i = end
                continue
            lines[i] = head + (":" if head.endswith(":") else " ::")
            tail = [""] if end < len(lines) and lines[end].strip() else []
            lines[i + 1 : end] = [""] + block + tail
            i = i + 1 + len(block) + len(tail)
        i += 1


def write_api_pages(app):
    out = Path(app.srcdir) / "api" / "generated"
    out.mkdir(parents=True, exist_ok=True)
    pages = api_pages()
    for old in out.glob("*.rst"):
        if old.stem not in pages:
            old.unlink()
    for key, text in pages.items():
        path = out / f"{key}.rst"
        if not path.exists() or path.read_text() != text:
            path.write_text(text)


# ---------------------------------------------------------------- MathJax, served locally
def _mathjax_dir():
    spec = importlib.util.find_spec("sphinx-mathjax-offline")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(list(spec.submodule_search_locations)[0]) / "static" / "mathjax"
    return path if path.is_dir() else None


#: what tex-chtml.js needs at run time: itself, its fonts, and the TeX extensions
MATHJAX_PARTS = ["tex-chtml.js", "output/chtml/fonts/woff-v2", "input/tex/extensions"]


def copy_mathjax(app, exc):
    if exc is not None or app.builder.format != "html":
        return
    src = _mathjax_dir()
    if src is None:
        logger.warning(
            "MathJax is missing: pip install sphinx-mathjax-offline (the docs extra installs it)"
        )
        return
    dst = Path(app.outdir) / "_static" / "mathjax"
    for part in MATHJAX_PARTS:
        s, d = src / part, dst / part
        if s.is_dir():
            shutil.copytree(s, d, dirs_exist_ok=True)
        elif s.exists():
            d.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(s, d)


# ---------------------------------------------------------------- tables from code
def _table(header, rows, classes=("accelab-table",)):
    table = nodes.table(classes=list(classes))
    group = nodes.tgroup(cols=len(header))
    table += group
    for _ in header:
        group += nodes.colspec(colwidth=1)
    head = nodes.thead()
    group += head
    body = nodes.tbody()
    group += body
    for target, cells in ((head, [header]), (body, rows)):
        for cells_row in cells:
            row = nodes.row()
            for cell in cells_row:
                entry = nodes.entry()
                entry += cell if isinstance(cell, nodes.Node) else nodes.paragraph(text=str(cell))
                row += entry
            target += row
    return table


def _literal(text):
    para = nodes.paragraph()
    para += nodes.literal(text=text)
    return para


def family_specs():
    """``[(name, title, module, {param: (lo, hi, step, kind)})]`` of every family
    (accelab.exercises.families.REGISTRY)."""
    from accelab.exercises.families import REGISTRY

    return [(f.name, f.title, f.load(), f.defaults) for f in REGISTRY.values()]


def _range_text(lo, hi, step, unit):
    def num(x):
        return f"{x:g}"

    u = f" {unit}" if unit else ""
    return f"{num(lo)} to {num(hi)}{u}, step {num(step)}"


class FamiliesTable(Directive):
    """The problem families and the parameters they draw, with default ranges
    in US and SI units (from ``accelab.exercises.families``)."""

    has_content = False
    option_spec = {"class": directives.class_option}

    def run(self):
        try:
            from accelab.exercises.families import common

            specs = family_specs()
        except Exception as exc:  # noqa: BLE001  an exercises package being rebuilt: say so
            logger.warning(f"accelab-families: cannot read accelab.exercises.families: {exc}")
            return [nodes.paragraph(text=f"(The families could not be read: {exc}.)")]
        result = []
        for name, title, module, defaults in specs:
            section_rows = []
            us = common.ranges_for(defaults, None, "US") if defaults else {}
            si = common.ranges_for(defaults, None, "SI") if defaults else {}
            for param in defaults:
                lo, hi, step, kind = us[param]
                slo, shi, sstep, _ = si[param]
                section_rows.append(
                    [
                        _literal(param),
                        kind,
                        _range_text(lo, hi, step, common.display_unit(kind, "US")),
                        _range_text(slo, shi, sstep, common.display_unit(kind, "SI")),
                    ]
                )
            head = nodes.paragraph()
            head += nodes.literal(text=name)
            head += nodes.Text(f": {title}. ")
            doc = (module.__doc__ or "").strip().split("\n\n")[0]
            head += nodes.Text(" ".join(doc.split()))
            result.append(head)
            if section_rows:
                result.append(
                    _table(
                        ["parameter", "kind", "default range (US)", "default range (SI)"],
                        section_rows,
                    )
                )
        return result


def family_notebooks(course):
    """``{family: [notebook stems]}``: the notebooks that teach each family, as the
    registry says (accelab.exercises.families.REGISTRY), those the course has."""
    from accelab.exercises.families import REGISTRY

    return {
        f.name: [s for s in f.notebooks if (Path(course) / f"{s}.py").exists()]
        for f in REGISTRY.values()
    }


class FamilyNotebooks(Directive):
    """Which course notebook teaches each problem family."""

    has_content = False

    def run(self):
        env = self.state.document.settings.env
        course = Path(env.srcdir) / "course"
        try:
            from accelab.exercises.families import REGISTRY

            mapping = family_notebooks(course)
        except Exception as exc:  # noqa: BLE001  said on the page and in a warning
            logger.warning(f"accelab-family-notebooks: {exc}")
            return [nodes.paragraph(text=f"(The families could not be read: {exc}.)")]
        rows = []
        for name, family in REGISTRY.items():
            cell = nodes.paragraph()
            for k, stem in enumerate(mapping.get(name, [])):
                if k:
                    cell += nodes.Text(", ")
                ref = addnodes.pending_xref(
                    "",
                    refdomain="std",
                    reftype="doc",
                    reftarget=f"/course/{stem}",
                    refexplicit=False,
                    refdoc=env.docname,
                )
                ref += nodes.inline(text=stem)
                cell += ref
            if not mapping.get(name):
                cell += nodes.Text("(none yet)")
            rows.append([_literal(name), family.title, cell])
        return [_table(["family", "what the student solves", "taught in"], rows)]


def setup(app):
    app.connect("builder-inited", write_api_pages)
    app.connect("autodoc-process-docstring", plain_docstring, priority=400)  # before numpydoc
    app.connect("source-read", source_read)
    app.connect("doctree-read", number_equations)
    app.connect("doctree-read", caption_images)
    app.connect("doctree-read", unbreakable_words)
    app.connect("doctree-read", math_keeps_what_touches_it)
    app.connect("doctree-read", drop_empty_field_lists)
    app.connect("doctree-resolved", link_images)
    app.connect("doctree-resolved", player_frames)
    app.connect("build-finished", write_notebooks)
    app.connect("build-finished", copy_mathjax)
    app.add_directive("accelab-families", FamiliesTable)
    app.add_directive("accelab-family-notebooks", FamilyNotebooks)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
