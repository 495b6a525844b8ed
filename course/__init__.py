"""accelab's course: acceleration analysis of planar linkages, one notebook per topic.

The notebooks are jupytext percent-format scripts (``course/NN_slug.py``, no
outputs in git), shipped with the package: ``accelab course --out DIR``
writes them as ``.ipynb`` notebooks (:mod:`accelab.course.cli`), :func:`notebooks`
lists them, and ``make docs`` publishes them as the course section of the
documentation site (``docs/``). They are clients of the installed packages:
:mod:`accelab.solver` for every number, :mod:`accelab.course.kit` for what they share (the
``explore`` control, number formatting, plot style, :func:`accelab.course.kit.stated`),
:mod:`accelab.course.text` for results written as sentences and tables,
:mod:`accelab.course.renditions` for figures in a wide and a narrow (phone) rendition,
:mod:`accelab.course.animation` and :mod:`accelab.course.player` for the mechanisms that
move (a player with play, pause and step), and ``accelab.exercises.practice`` for
self-study problems with instant feedback. ``benchmark.json`` holds the numbers of the
benchmark run that notebook 11 quotes.
``errata.md`` lists the misprints of the chapter the course found, and
``FAMILIES.md`` (written from the families' registry, :mod:`accelab.course.families`)
which notebook teaches each graded exercise family.
"""

from pathlib import Path

HERE = Path(__file__).resolve().parent

__all__ = ["notebooks", "pages", "HERE"]


def notebooks():
    """The course notebooks' sources, in order: ``course/NN_slug.py``."""
    return sorted(HERE.glob("[0-9][0-9]_*.py"))


def pages():
    """The course's Markdown pages, name -> text: the errata, and the families table
    written from the registry (:func:`accelab.course.families.page`)."""
    from . import families

    out = {p.name: p.read_text() for p in sorted(HERE.glob("*.md"))}
    out[families.NAME] = families.page()
    return out
