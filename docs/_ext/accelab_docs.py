"""What accelab's site needs on top of Sphinx, MyST-NB and the book theme.

* Course pages: the notebooks' own ``[Next: ...](NN_slug.ipynb)`` links point
  at the next page, and each page gets a line under its title that downloads
  the notebook as ``.ipynb`` (written next to the page at the end of the build,
  converted by jupytext, without outputs) and the ``coursekit.py`` it imports.
* Every figure is a link to its own image file, so a tap on a phone opens it
  at full size.
* MathJax is served from the site (the copy the ``sphinx-mathjax-offline``
  package ships: MathJax 3 with its fonts), so no equation needs the network.
* Directives that generate tables from code: ``accelab-families`` (the problem
  families with their default ranges), ``accelab-family-notebooks`` (which
  notebook teaches each family).
"""

import importlib.util
import posixpath
import re
import shutil
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from sphinx.util import logging
from sphinx.util.osutil import relative_uri

logger = logging.getLogger(__name__)

COURSE_DOC = re.compile(r"^course/(\d\d_[A-Za-z0-9_]+)$")
NOTEBOOK_LINK = re.compile(r"\[([^\]`]+)\]\((\d\d_[A-Za-z0-9_]+)\.ipynb\)")


# ---------------------------------------------------------------- course pages
def _course_stem(docname):
    m = COURSE_DOC.match(docname)
    return m.group(1) if m else None


def _download_line(stem):
    return (f'<p class="nb-download">'
            f'<a class="nb-download-link" href="{stem}.ipynb" download="{stem}.ipynb" '
            f'type="application/x-ipynb+json">Download this notebook (.ipynb)</a>'
            f'<span class="nb-download-note"> to run it yourself in Jupyter, with '
            f'<a href="coursekit.py" download="coursekit.py">coursekit.py</a> beside it and '
            f'accelab installed (<code>pip install -e .</code>).</span></p>')


def source_read(app, docname, source):
    """Course notebooks: retarget the next-notebook links and add the download line."""
    stem = _course_stem(docname)
    if stem is None:
        return
    # a {doc} role: the notebooks sit behind a symbolic link (docs/course), where
    # MyST's path links would resolve outside the source folder
    text = NOTEBOOK_LINK.sub(lambda m: f"{{doc}}`{m.group(1)} </course/{m.group(2)}>`",
                             source[0])
    lines = text.split("\n")
    for i, line in enumerate(lines):           # the first '# # Title' of a markdown cell
        if re.match(r"^# # \S", line):
            lines[i + 1:i + 1] = ["#", "# " + _download_line(stem)]
            break
    source[0] = "\n".join(lines)


def write_notebooks(app, exc):
    """Write each course page's notebook (.ipynb, no outputs) and coursekit.py
    next to its page."""
    if exc is not None or app.builder.format != "html":
        return
    import jupytext
    out = Path(app.outdir)
    done = 0
    for docname in app.env.found_docs:
        stem = _course_stem(docname)
        if stem is None:
            continue
        source = Path(app.env.doc2path(docname))
        nb = jupytext.read(source, fmt="py:percent")
        target = out / "course" / f"{stem}.ipynb"
        target.parent.mkdir(parents=True, exist_ok=True)
        jupytext.write(nb, target, fmt="ipynb")
        done += 1
        kit = source.parent / "coursekit.py"
        if kit.exists():
            shutil.copyfile(kit, target.parent / "coursekit.py")
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
def link_images(app, doctree, docname):
    """Wrap every image that is not already a link in a link to its file."""
    if app.builder.format != "html":
        return
    imgdir = relative_uri(app.builder.get_target_uri(docname), "_images")
    for image in list(doctree.findall(nodes.image)):
        if isinstance(image.parent, nodes.reference):
            continue
        uri = image.get("candidates", {}).get("*", image["uri"])
        if uri in app.env.images:
            refuri = posixpath.join(imgdir, app.env.images[uri][1])
        elif "://" in uri or uri.startswith("data:"):
            continue
        else:
            refuri = uri
        ref = nodes.reference("", "", internal=True, refuri=refuri,
                              classes=["image-full-size"])
        ref["reftitle"] = "Open the image at full size"
        image.replace_self(ref)
        ref.append(image)


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
        logger.warning("MathJax is missing: pip install sphinx-mathjax-offline "
                       "(the docs extra installs it)")
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
    """``[(name, title, module, {param: (lo, hi, step, kind)})]`` of every family."""
    import importlib
    from exercises import families
    out = []
    for name, generator in families.FAMILIES.items():
        module = importlib.import_module(generator.__module__)
        defaults = getattr(module, "DEFAULTS", None)
        if defaults is None:   # a family that reuses another's table (FOURBAR_DEFAULTS)
            used = [v for k, v in vars(module).items() if k.endswith("DEFAULTS")
                    and isinstance(v, dict)]
            defaults = used[0] if used else {}
        out.append((name, getattr(module, "TITLE", name), module, defaults))
    return out


def _range_text(lo, hi, step, unit):
    def num(x):
        return f"{x:g}"
    u = f" {unit}" if unit else ""
    return f"{num(lo)} to {num(hi)}{u}, step {num(step)}"


class FamiliesTable(Directive):
    """The problem families and the parameters they draw, with default ranges
    in US and SI units (from ``exercises.families``)."""
    has_content = False
    option_spec = {"class": directives.class_option}

    def run(self):
        try:
            from exercises.families import common
            specs = family_specs()
        except Exception as exc:  # an exercises package being rebuilt: say so on the page
            logger.warning(f"accelab-families: cannot read exercises.families: {exc}")
            return [nodes.paragraph(text=f"(The families could not be read: {exc}.)")]
        result = []
        for name, title, module, defaults in specs:
            section_rows = []
            us = common.ranges_for(defaults, None, "US") if defaults else {}
            si = common.ranges_for(defaults, None, "SI") if defaults else {}
            for param in defaults:
                lo, hi, step, kind = us[param]
                slo, shi, sstep, _ = si[param]
                section_rows.append([
                    _literal(param), kind,
                    _range_text(lo, hi, step, common.display_unit(kind, "US")),
                    _range_text(slo, shi, sstep, common.display_unit(kind, "SI"))])
            head = nodes.paragraph()
            head += nodes.literal(text=name)
            head += nodes.Text(f": {title}. ")
            doc = (module.__doc__ or "").strip().split("\n\n")[0]
            head += nodes.Text(" ".join(doc.split()))
            result.append(head)
            if section_rows:
                result.append(_table(["parameter", "kind", "default range (US)",
                                      "default range (SI)"], section_rows))
        return result


def family_notebooks():
    """``{family: [notebook stems]}``: the notebooks whose text names a family
    as one that practises them (``family `name` ``, or a families line)."""
    from exercises import families
    names = list(families.FAMILIES)
    found = {n: [] for n in names}
    course = Path(__file__).resolve().parents[2] / "course"
    for path in sorted(course.glob("[0-9][0-9]_*.py")):
        text = path.read_text()
        for line in text.splitlines():
            if "famil" not in line.lower():
                continue
            for n in names:
                if re.search(rf"`{n}`", line) and path.stem not in found[n]:
                    found[n].append(path.stem)
    return found


def setup(app):
    app.connect("source-read", source_read)
    app.connect("doctree-read", number_equations)
    app.connect("doctree-resolved", link_images)
    app.connect("build-finished", write_notebooks)
    app.connect("build-finished", copy_mathjax)
    app.add_directive("accelab-families", FamiliesTable)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
