"""The polygon builder: an anywidget (one Python class, one ES module, no build
step, nothing fetched from the network) in which a student constructs the
velocity and acceleration polygons of one position.

The browser side (``builder.js``) draws the linkage to scale and a polygon
canvas with its scale, and turns pointer input (mouse, touchpad, touch) or
typed input into steps; it judges nothing. This side reads every step with the
one reader (:mod:`accelab.exercises.student.polygon.record`), checks it with the one
set of rules (:mod:`accelab.exercises.student.polygon.rules`) when the builder is for
practice, and keeps the construction with the notebook: an output of the
builder's own cell (mimetype :data:`~accelab.exercises.student.polygon.record.MIMETYPE`)
that is updated at each step, so that saving the notebook saves it, and
nbgrader's submit and collect carry it. A copy in ``.accelab-polygons.json``
beside the notebook brings it back when the cell is run again in a new session.

Two modes:

* ``practice``: each step is checked as it is made and the builder says which
  rule a wrong step broke; "Show the next step" shows it (dotted);
* ``assignment``: the steps are recorded, not judged (the grader judges them,
  with the same rules, against the submitter's own values).

Inside the grading sandbox, or executed headless (``ACCELAB_STATIC=1``), there is
no browser: an assignment's builder then shows a line of text, and a practice
builder a figure of the finished construction.
"""

import json
import os
import pathlib
import tempfile
import uuid

import traitlets

from .record import MIMETYPE, Record, RecordError, read_record, read_steps
from .rules import judge_phase, next_step, step_feedback
from .task import ANSWER_SUFFIX, BAND_DEG, FAMILY_MECHANISM, LENGTH_FRACTION, task_of_case

try:  # the grading sandbox and a plain Python have no widgets: fall back to a plain class
    import anywidget

    _Base = anywidget.AnyWidget
except ImportError:  # pragma: no cover - anywidget is a dependency of accelab
    anywidget = None
    _Base = traitlets.HasTraits

_HERE = pathlib.Path(__file__).resolve().parent
#: the file beside the notebook that keeps constructions between sessions
STORE = ".accelab-polygons.json"
#: largest store file read back [bytes]
MAX_STORE = 2_000_000

READS_UNITS = {"rad/s": 1.0, "rad/s^2": 1.0}


def live():
    """True in a Jupyter kernel with a browser to draw in; False headless
    (``ACCELAB_STATIC`` set), in the grading sandbox or in plain Python."""
    if os.environ.get("ACCELAB_STATIC", "0") not in ("", "0") or anywidget is None:
        return False
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and hasattr(shell, "kernel")


def _xy(z, f=1.0):
    return [z.real * f, z.imag * f]


def _fmt(x):
    return f"{x:.4g}"


class PolygonBuilder(_Base):
    """The builder of one problem's polygons (see the module docstring).

    Make one with :meth:`from_case` (any fourbar, slider-crank or inverted
    slider-crank batch case), :meth:`for_assignment` (problem ``k`` of a graded
    notebook) or :meth:`accelab.exercises.practice.Practice.builder`.
    """

    _esm = _HERE / "builder.js"
    _css = _HERE / "builder.css"

    problem = traitlets.Dict().tag(sync=True)
    steps = traitlets.List().tag(sync=True)
    verdicts = traitlets.List().tag(sync=True)
    summary = traitlets.Dict().tag(sync=True)
    hint = traitlets.Dict().tag(sync=True)
    status = traitlets.Unicode("").tag(sync=True)
    #: how many times the steps were judged (the browser waits for the next one)
    judged = traitlets.Int(0).tag(sync=True)

    def __init__(
        self,
        task,
        mode="practice",
        title="",
        student="",
        number=0,
        family="",
        answers=None,
        given=None,
        store_key=None,
    ):
        if mode not in ("practice", "assignment"):
            raise ValueError(f"mode must be 'practice' or 'assignment' (got {mode!r})")
        self.task, self.mode = task, mode
        self.student, self.number, self.family = str(student), int(number), str(family)
        self.answers = dict(answers or {p: ANSWER_SUFFIX[p] for p in task.phases})
        self.store_key = store_key
        self._drawn = ()
        self._display_id = f"accelab-polygon-{uuid.uuid4().hex}"
        self._shown = False
        self._reverting = False
        super().__init__()
        self.problem = self._problem(title, given or {})
        if live():
            self._restore()
            if hasattr(self, "on_msg"):
                self.on_msg(self._on_msg)
        self._update()

    def open(self):
        """Open the widget's channel to a browser only where there is one (:func:`live`).

        Headless no view is ever made of it, and a model with no view would only weigh on
        what is saved: nbclient keeps every opened model's state in the notebook, and the
        site's page of notebook 02 carried its four builders' state (220 kB of its 373)
        for a widget manager it does not load."""
        if live():
            super().open()

    # ------------------------------------------------------------ makers
    @classmethod
    def from_case(cls, case, mode="practice", title=None, store_key=None):
        """A builder for a batch case (``{"mechanism": "fourbar", "a": "2 in", ...}``)."""
        task = task_of_case(case)
        given = {k: v for k, v in case.items() if k not in ("mechanism", "p", "delta3")}
        title = title or f"Polygon builder: {task.mechanism}"
        key = store_key or "case:" + json.dumps(case, sort_keys=True)
        return cls(task, mode, title, given=given, store_key=key)

    @classmethod
    def for_assignment(cls, variant, number):
        """The builder of problem ``number`` (1-based) of a graded notebook's
        variant (:func:`accelab.exercises.student.runtime.load_variant`)."""
        p = variant.problems[int(number) - 1]
        family = p["family"]
        if family not in FAMILY_MECHANISM:
            raise ValueError(f"problem {number} ({family}) is not drawn with the polygon builder")
        case = {"mechanism": FAMILY_MECHANISM[family], **p["given"]}
        task = task_of_case(case)
        answers = {}
        for a in p["asked"]:
            for phase, suffix in ANSWER_SUFFIX.items():
                if a["kind"] == "construction" and a["name"].endswith(suffix):
                    answers[phase] = a["name"]
        statement = variant.statement
        key = (
            f"assignment:{statement.get('course')}/{statement.get('assignment')}/"
            f"{variant.student}/{number}"
        )
        builder = cls(
            task,
            "assignment",
            f"Problem {number}: {p['title']}",
            variant.student,
            number,
            family,
            answers,
            p["given"],
            key,
        )
        _BUILDERS.update({name: builder for name in answers.values()})
        return builder

    # ------------------------------------------------------------ what the browser gets
    def _problem(self, title, given):
        t = self.task
        from .task import UNITS

        lunit, lf = UNITS[t.units]["length"]
        labels = {"slide": "the slide"}
        phases = []
        for ph in t.phases.values():
            names = [x.name for x in ph.terms + ph.resultants]
            kinds = {x.name: x.kind for x in ph.terms + ph.resultants}
            phases.append(
                {
                    "id": ph.name,
                    "title": ph.title,
                    "unit": ph.unit,
                    "factor": ph.factor,
                    "scale": ph.scale,
                    "equation": ph.equation,
                    "vectors": [{"name": n, "kind": kinds[n]} for n in names],
                    "lines": [x.name for x in ph.terms],
                    "reads": [
                        {
                            "name": r.name,
                            "label": r.label,
                            "unit": r.unit or ph.unit,
                            "factor": READS_UNITS.get(r.unit, ph.factor),
                        }
                        for r in ph.reads
                    ],
                }
            )
        return {
            "title": title,
            "mode": self.mode,
            "student": self.student,
            "band": BAND_DEG,
            "tol_pct": 100 * LENGTH_FRACTION,
            "linkage": {
                "unit": lunit,
                "points": {k: _xy(z, lf) for k, z in t.points.items()},
                "links": [list(link) for link in t.links],
                "ground": list(t.ground),
                "slides": [[_xy(p, lf), _xy(d)] for p, d in t.slides],
            },
            "given": [[k, str(v)] for k, v in given.items()],
            "directions": [
                {"id": k, "label": labels.get(k, k), "angle": _angle(d)}
                for k, d in t.directions.items()
            ],
            "phases": phases,
        }

    # ------------------------------------------------------------ steps in, feedback out
    @traitlets.observe("steps")
    def _steps_changed(self, change):
        if self._reverting:
            return
        try:
            read_steps(change["new"])
        except RecordError as exc:
            self._reverting = True
            try:
                self.steps = list(change["old"])
            finally:
                self._reverting = False
            self.status = f"That step was not taken: {exc}."
            return
        self.status = ""
        self._update()
        self._save()

    def _update(self):
        if hasattr(self, "hold_sync"):
            with self.hold_sync():
                self._judge_all()
        else:
            self._judge_all()
        if self._shown:
            self._show_record(update=True)

    def _judge_all(self):
        self._drawn = read_steps(self.steps)
        if self.mode == "practice":
            self.verdicts = step_feedback(self.task, self._drawn) if self._drawn else []
            self.summary = {
                ph: {"right": j.right, "total": len(j.results)}
                for ph, j in ((p, self.judge(p)) for p in self.task.phases)
            }
        else:
            note = "recorded: judged when the assignment is graded"
            self.verdicts = [{"ok": None, "message": note} for _ in self._drawn]
            self.summary = {
                ph: {"drawn": len({s.key for s in self._drawn if s.phase == ph})}
                for ph in self.task.phases
            }
        self.judged += 1

    def _on_msg(self, widget, content, buffers):
        if not isinstance(content, dict):
            return
        if content.get("type") == "next" and content.get("phase") in self.task.phases:
            phase = self.task.phase(content["phase"])
            found = next_step(phase, self._drawn, numbers=self.mode == "practice")
            if found is None:
                found = {
                    "key": "",
                    "text": f"The {phase.title.lower()} is complete.",
                    "ghost": None,
                }
            self.hint = dict(found, phase=phase.name, serial=self.hint.get("serial", 0) + 1)

    # ------------------------------------------------------------ Python API
    def judge(self, phase):
        """The :class:`~accelab.exercises.student.polygon.rules.Judgement` of the drawing's
        ``phase`` (practice only: an assignment's construction is judged when it is
        graded)."""
        if self.mode != "practice":
            raise RuntimeError("an assignment's construction is judged when it is graded")
        others = list(self.task.phases.values())
        return judge_phase(self.task.phase(phase), self._drawn, others)

    def record(self):
        """The construction as it is saved with the notebook (a dict)."""
        return Record(self.student, self.number, self.family, self._drawn).to_dict()

    def load(self, steps):
        """Put a list of steps (record format) into the builder, e.g. a saved
        construction's ``record()["steps"]``."""
        read_steps(steps)
        self.steps = list(steps)

    def figure(self, phase=None, finished=False):
        """PNG bytes of the drawing (``finished=True``: of the finished
        construction) of ``phase`` (default: both, one above the other)."""
        from .figure import construction_png

        steps = None if finished else self._drawn
        return construction_png(self.task, steps, phase, title=self.problem.get("title"))

    # ------------------------------------------------------------ display
    def _record_bundle(self):
        counts = ", ".join(
            f"{self.task.phase(p).title.lower()}: {n} step{'s' if n != 1 else ''}"
            for p, n in (
                (p, len({s.key for s in self._drawn if s.phase == p})) for p in self.task.phases
            )
        )
        if self.mode == "assignment":
            text = (
                f"*Your construction ({counts}) is saved with the notebook when you save it, "
                "and judged when the assignment is graded.*"
            )
        else:
            right = "; ".join(
                f"{self.task.phase(p).title.lower()}: {s['right']} of {s['total']} steps right"
                for p, s in self.summary.items()
            )
            text = f"*Practice construction: {right}.*"
        return {"text/markdown": text, MIMETYPE: self.record()}

    def _show_record(self, update=False):
        from IPython.display import display, update_display

        if update:
            update_display(self._record_bundle(), raw=True, display_id=self._display_id)
        else:
            display(self._record_bundle(), raw=True, display_id=self._display_id)

    def _ipython_display_(self):
        from IPython.display import Image, display

        if live():
            data = self._repr_mimebundle_()
            bundle = data[0] if isinstance(data, tuple) else data
            display(bundle, raw=True)
            self._shown = True
            self._show_record()
            return
        if self.mode == "assignment":
            text = (
                f"{self.problem.get('title', 'Polygon builder')}: the polygon builder draws in "
                "a live notebook (JupyterLab or Jupyter Notebook)."
            )
            display({"text/plain": text, "text/markdown": f"*{text}*"}, raw=True)
            return
        display(Image(self.figure(finished=not self._drawn)))

    def show(self):
        """Display the builder (a notebook cell can end with ``builder.show()``)."""
        from IPython.display import display

        display(self)

    def __repr__(self):
        n = len(self._drawn)
        return f"<PolygonBuilder {self.task.mechanism} ({self.mode}): {n} step(s)>"

    # ------------------------------------------------------------ kept between sessions
    def _restore(self):
        if not self.store_key:
            return
        data = _read_store().get(self.store_key)
        if data is None:
            return
        try:
            record = read_record(data)
        except RecordError:
            self.status = "A construction kept from an earlier session could not be read."
            return
        self._reverting = True
        try:
            self.steps = [s.to_dict() for s in record.steps]
        finally:
            self._reverting = False

    def _save(self):
        if not self.store_key or not live():
            return
        store = _read_store()
        store[self.store_key] = self.record()
        try:
            folder = os.path.abspath(".")
            fd, tmp = tempfile.mkstemp(prefix=".accelab-polygons-", dir=folder)
            with os.fdopen(fd, "w") as fh:
                json.dump(store, fh)
            os.replace(tmp, os.path.join(folder, STORE))
        except OSError:
            self.status = "The construction could not be kept beside the notebook (save it)."


def _angle(z):
    import cmath
    import math

    return math.degrees(cmath.phase(z))


def _read_store():
    try:
        if os.path.getsize(STORE) > MAX_STORE:
            return {}
        with open(STORE) as fh:
            data = json.load(fh)
    except (OSError, ValueError, RecursionError):
        return {}
    return data if isinstance(data, dict) else {}


#: the builders of this session by answer name (the visible checks find them)
_BUILDERS = {}


def check_construction(name):
    """Visible test of a construction answer: the builder of its problem has
    run and holds a drawing of that polygon. It says nothing of whether the
    drawing is right: that is judged when the assignment is graded."""
    builder = _BUILDERS.get(name)
    if builder is None:
        raise AssertionError(
            "the polygon builder of this problem has not run: run its cell (above) first"
        )
    phase = next((p for p, n in builder.answers.items() if n == name), None)
    drawn = len({s.key for s in builder._drawn if s.phase == phase})
    if not drawn:
        raise AssertionError(
            f"nothing is drawn on the {phase} polygon yet: construct it in the builder above"
        )
    print(
        f"{name}: {drawn} step{'s' if drawn != 1 else ''} drawn (the construction is judged "
        "when the assignment is graded; save the notebook before you submit)"
    )
