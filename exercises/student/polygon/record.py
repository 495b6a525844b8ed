"""A student's construction as data: what the builder saves with the notebook,
and the one reader of it.

The builder keeps the construction as a list of steps, each a small dict
(points are ``[x, y]`` in SI: m/s on the velocity polygon, m/s^2 on the
acceleration polygon; directions in degrees counter-clockwise from +x):

* ``{"op": "vector", "phase": P, "name": N, "tail": [x, y], "tip": [x, y]}``:
  a vector N laid on the polygon of phase P;
* ``{"op": "line", "phase": P, "name": N, "through": [x, y], "angle": deg}``:
  a construction line carrying the direction of the term N;
* ``{"op": "point", "phase": P, "lines": [N1, N2], "at": [x, y]}``: the point
  where the lines of N1 and N2 cross;
* ``{"op": "read", "phase": P, "name": N, "value": v}``: an unknown read off
  the polygon (SI: rad/s, rad/s^2, m/s, m/s^2).

Saved with the notebook (an output of the builder's cell, mimetype
:data:`MIMETYPE`), the record is ``{"format": FORMAT, "version": 1, "student":
..., "problem": k, "family": ..., "steps": [...]}``. A notebook is the
student's file, so :func:`read_record` trusts nothing in it: every field is
checked for type, size and range before it is used, nothing unknown is
descended into, and a record that does not fit is refused with a message that
says what is wrong (and quotes nothing of it).
"""

import math
import re
from dataclasses import dataclass

MIMETYPE = "application/vnd.accelab.polygon+json"
FORMAT = "accelab-polygon"
VERSION = 1
#: most steps a record may hold (both polygons); a construction has about 20
MAX_STEPS = 200
#: largest coordinate or value [SI]: far beyond any polygon the families draw
MAX_VALUE = 1e12
MAX_NAME = 40
MAX_ID = 100
OPS = {
    "vector": {"op", "phase", "name", "tail", "tip"},
    "line": {"op", "phase", "name", "through", "angle"},
    "point": {"op", "phase", "lines", "at"},
    "read": {"op", "phase", "name", "value"},
}
PHASES = ("velocity", "acceleration")
TOP = {"format", "version", "student", "problem", "family", "steps"}
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_^]{0,39}$")


class RecordError(ValueError):
    """A record that cannot be read; the message says why (for the student)."""


@dataclass(frozen=True)
class Drawn:
    """One step as read: points as complex numbers [SI], ``direction`` a unit
    complex number (lines), ``index`` its place in the record."""

    op: str
    phase: str
    name: str
    index: int
    tail: complex = None
    tip: complex = None
    through: complex = None
    direction: complex = None
    lines: tuple = ()
    at: complex = None
    value: float = None

    @property
    def key(self):
        return f"{self.op}:{self.name}"

    @property
    def vector(self):
        return self.tip - self.tail

    def to_dict(self):
        """The step as the record stores it."""
        out = {"op": self.op, "phase": self.phase}
        if self.op == "vector":
            out.update(name=self.name, tail=_xy(self.tail), tip=_xy(self.tip))
        elif self.op == "line":
            out.update(
                name=self.name,
                through=_xy(self.through),
                angle=math.degrees(math.atan2(self.direction.imag, self.direction.real)),
            )
        elif self.op == "point":
            out.update(lines=list(self.lines), at=_xy(self.at))
        else:
            out.update(name=self.name, value=self.value)
        return out


@dataclass(frozen=True)
class Record:
    """A construction as read by :func:`read_record`: who drew it (``student``), which
    problem of the assignment (its number, ``problem``) of which ``family``, and its
    ``steps`` (:class:`Drawn`) in the order they were drawn."""

    student: str
    problem: int
    family: str
    steps: tuple

    def phase(self, name):
        return [s for s in self.steps if s.phase == name]

    def to_dict(self):
        return {
            "format": FORMAT,
            "version": VERSION,
            "student": self.student,
            "problem": self.problem,
            "family": self.family,
            "steps": [s.to_dict() for s in self.steps],
        }


def _xy(z):
    return [z.real, z.imag]


def _number(value, what):
    if type(value) not in (int, float):  # bool is not a number here
        raise RecordError(f"{what} is not a number")
    x = float(value)
    if not math.isfinite(x) or abs(x) > MAX_VALUE:
        raise RecordError(f"{what} is not a finite number of sensible size")
    return x


def _point(value, what):
    if type(value) is not list or len(value) != 2:
        raise RecordError(f"{what} is not a point [x, y]")
    return complex(_number(value[0], what), _number(value[1], what))


def _name(value, what):
    if type(value) is not str or not _NAME.match(value):
        raise RecordError(f"{what} is not the name of a vector or an unknown")
    return value


def _text(value, what, limit=MAX_ID):
    if value is None:
        return ""
    if type(value) is not str or len(value) > limit:
        raise RecordError(f"{what} is not a short text")
    return value


def read_step(step, index):
    """One step of a record as a :class:`Drawn`; raises RecordError."""
    where = f"step {index + 1}"
    if not isinstance(step, dict):  # a dict, or nbformat's NotebookNode
        raise RecordError(f"{where} is not a step")
    op = step.get("op")
    if type(op) is not str or op not in OPS:
        raise RecordError(f"{where} is not a vector, a line, a point or a read value")
    if set(step) != OPS[op]:
        raise RecordError(f"{where} does not have the fields of a {op}")
    phase = step["phase"]
    if type(phase) is not str or phase not in PHASES:
        raise RecordError(f"{where} is on no polygon (velocity or acceleration)")
    if op == "vector":
        return Drawn(
            op,
            phase,
            _name(step["name"], where),
            index,
            tail=_point(step["tail"], where),
            tip=_point(step["tip"], where),
        )
    if op == "line":
        angle = math.radians(_number(step["angle"], where))
        return Drawn(
            op,
            phase,
            _name(step["name"], where),
            index,
            through=_point(step["through"], where),
            direction=complex(math.cos(angle), math.sin(angle)),
        )
    if op == "point":
        lines = step["lines"]
        if type(lines) is not list or len(lines) != 2:
            raise RecordError(f"{where} does not name the two lines that cross")
        return Drawn(
            op,
            phase,
            "X",
            index,
            lines=tuple(_name(n, where) for n in lines),
            at=_point(step["at"], where),
        )
    return Drawn(op, phase, _name(step["name"], where), index, value=_number(step["value"], where))


def read_steps(steps):
    """A list of steps (the builder's own, or a record's) as Drawn; raises RecordError."""
    if type(steps) is not list:
        raise RecordError("its steps are not a list")
    if len(steps) > MAX_STEPS:
        raise RecordError(f"it has more than {MAX_STEPS} steps")
    return tuple(read_step(s, k) for k, s in enumerate(steps))


def read_record(data):
    """The :class:`Record` in ``data`` (a record as saved with the notebook);
    raises RecordError with what is wrong."""
    if not isinstance(data, dict):
        raise RecordError("it is not a construction record")
    if not set(data) <= TOP or data.get("format") != FORMAT:
        raise RecordError("it is not a construction record of this builder")
    if data.get("version") != VERSION:
        raise RecordError("it was saved by another version of the builder")
    problem = data.get("problem", 0)
    if type(problem) is not int or not 0 <= problem <= 1000:
        raise RecordError("its problem number is not a small whole number")
    return Record(
        _text(data.get("student"), "its student id"),
        problem,
        _text(data.get("family"), "its family", MAX_NAME),
        read_steps(data.get("steps", [])),
    )
