"""The polygon builder: the graphical method of section 7.2 done by the student,
step by step, in a notebook (practice with instant feedback, or graded).

* :mod:`accelab.exercises.student.polygon.task` -- the construction a student must
  make (from the package's own geometric construction, :mod:`accelab.solver.graphical`);
* :mod:`accelab.exercises.student.polygon.record` -- a construction as data, and the one
  reader of it;
* :mod:`accelab.exercises.student.polygon.rules` -- the rules each step is checked by,
  used by the builder's instant feedback and by the grader alike;
* :mod:`accelab.exercises.student.polygon.widget` -- :class:`PolygonBuilder`, the
  anywidget (``builder.js``);
* :mod:`accelab.exercises.student.polygon.figure` -- a construction drawn with matplotlib
  (feedback, static pages).

It is student-side code (the grading sandbox shows it): a graded notebook's
builder cell runs there too, headless, where it only shows a line of text. The
grader reads the construction from the submitted notebook, outside the sandbox,
and judges it with :mod:`accelab.exercises.student.polygon.rules` against the submitter's own key.

>>> from accelab.exercises.student.polygon import PolygonBuilder
>>> from accelab.solver.graphical.gallery import EXAMPLE_7_1
>>> PolygonBuilder.from_case(EXAMPLE_7_1)   # in JupyterLab: draw Example 7-1's polygons
"""

from typing import Any

from .record import MIMETYPE, RecordError, read_record
from .task import FAMILY_MECHANISM, task_of_case

#: imported when first asked for: the widget needs anywidget and ipywidgets (IPython),
#: a third of a second that the grader and the command line never use
_FROM_WIDGET = ("PolygonBuilder", "check_construction")

__all__ = [
    "PolygonBuilder",
    "check_construction",
    "task_of_case",
    "read_record",
    "RecordError",
    "MIMETYPE",
    "FAMILY_MECHANISM",
]


def __getattr__(name: str) -> Any:
    if name in _FROM_WIDGET:
        from . import widget

        return getattr(widget, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
