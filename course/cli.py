"""``accelab course --out DIR``: write the course as Jupyter notebooks.

For a student who installed the package: every notebook of the course
(``course/NN_slug.py``, jupytext percent format, shipped with the package)
is written as ``DIR/NN_slug.ipynb``, with the course's pages (the errata and
the table of exercise families) beside them. The notebooks import what they
need from the installed packages, so they run from any folder:

  accelab course --out my-course
  cd my-course && jupyter lab

An existing notebook in DIR is never overwritten (it may hold the student's
work) unless --force is given. Exit status 0 when everything was written, 1
when some notebook was kept, 2 when DIR cannot be written.

The ``accelab`` command calls :func:`register` to add the subcommand.
"""

import argparse
import sys
from pathlib import Path

EPILOG = """example:
  accelab course --out my-course          # then: cd my-course && jupyter lab
  accelab course --out my-course --force  # refresh, overwriting the notebooks there"""


def register(subparsers):
    """Add ``course`` to the ``accelab`` command's subparsers."""
    p = subparsers.add_parser(
        "course",
        help="write the course notebooks (.ipynb) to a folder",
        description="Write the course, one Jupyter notebook per topic, to a folder of your choice.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--out", metavar="DIR", required=True, help="folder for the notebooks (created if needed)"
    )
    p.add_argument(
        "--force", action="store_true", help="overwrite notebooks that are already there"
    )
    p.set_defaults(func=run)
    return p


def to_notebook(source):
    """The notebook (nbformat node) of a percent-format source, with a python3
    kernel and the course's metadata, outputs empty. Its cells' ids are the notebook's
    name and the cell's number (``05_coriolis-07``), so that writing it again gives the
    same file (the site's download is this notebook too)."""
    import jupytext

    nb = jupytext.read(source, fmt="py:percent")
    stem = Path(source).stem
    for number, cell in enumerate(nb.cells):
        cell.id = f"{stem}-{number:02d}"
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nb.metadata.setdefault("language_info", {"name": "python"})
    nb.metadata.pop("jupytext", None)
    return nb


def write(out, force=False, log=print):
    """Write every notebook and page to ``out``; returns ``(written, kept)``
    lists of paths (``kept``: notebooks already there, left alone)."""
    import nbformat

    from . import notebooks, pages

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written, kept = [], []
    for src in notebooks():
        target = out / (src.stem + ".ipynb")
        if target.exists() and not force:
            kept.append(target)
            log(f"kept {target} (it exists; --force overwrites it)")
            continue
        nbformat.write(to_notebook(src), target)
        written.append(target)
        log(str(target))
    for name, text in pages().items():
        target = out / name
        if target.exists() and not force:
            kept.append(target)
            continue
        target.write_text(text)
        written.append(target)
        log(str(target))
    return written, kept


def run(args):
    try:
        _, kept = write(args.out, args.force)
    except OSError as exc:
        print(
            f"accelab course: cannot write to {args.out}: {exc.strerror or exc}; choose "
            "another folder with --out",
            file=sys.stderr,
        )
        return 2
    return 1 if kept else 0


def main(argv=None):
    """``python -m accelab.course.cli --out DIR`` (the same as ``accelab course``)."""
    parser = argparse.ArgumentParser(prog="accelab")
    sub = parser.add_subparsers(dest="command")
    register(sub)
    args = parser.parse_args(["course"] + list(argv if argv is not None else sys.argv[1:]))
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
