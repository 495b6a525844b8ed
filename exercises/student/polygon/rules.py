"""The rules a polygon is checked by: the one place they are written.

The builder's instant feedback (practice) and the grader (an assignment) both
call :func:`judge_phase` on a student's steps and a
:class:`~accelab.exercises.student.polygon.task.Phase` (the exact construction,
from :mod:`accelab.solver.graphical`), so a step is judged the same way
wherever it is judged. The browser draws; it judges nothing.

A step is right when, within the phase's tolerances (directions within
``band`` degrees, by default 1 deg; lengths and points within ``tol``, 2% of the
polygon's largest vector):

* a **known vector** (``V_A``, ``A_A^n``, ``A_BA^n``, ``A_cor``) has its
  direction and sense, its length, and starts at the pole or at the tip of
  another known term of its side of the equation (tip to tail);
* a **construction line** carries the direction of its unknown term and passes
  through the end of the known part of that term's side (for the second
  unknown of one side: through the end of the other side);
* the **point** is where the lines of the two unknowns cross;
* an **unknown vector** runs from where its line starts to the crossing (or
  from the crossing to the end of the other side), in its direction and sense;
* a **read value** (omega, alpha, a slip rate) is what the polygon gives,
  with its sign (counter-clockwise positive).

Each judgement that fails says which rule it broke, in the chapter's terms
(``A_A^n points from A toward O2``; ``A_BA^t is perpendicular to BA``; the
inverted slider-crank needs the Coriolis term), and never states the expected
value or draws it. Only :func:`next_step`, which a practising student asks
for, shows a step.

The judgement of a drawing that leans on an earlier step of the student's own
(a line through the tip of their A_BA^n, a vector to their crossing) accepts
the student's own point when it is itself right: one slip costs one step.
"""

import cmath
import math
from dataclasses import dataclass, field

LINK_NAMES = {"slide": "the slide", "O2O4": "the ground link O2O4"}


@dataclass(frozen=True)
class Result:
    """The judgement of one expected step: ``ok``, and ``message`` (the rule
    broken, or what was right). ``index`` is the judged step's place in the
    student's list (None when it is missing)."""

    key: str
    ok: bool
    message: str
    index: int = None

    @property
    def missing(self):
        return self.index is None


@dataclass
class Judgement:
    """A phase judged: one :class:`Result` per expected step, in order."""

    phase: str
    results: list = field(default_factory=list)
    notes: list = field(default_factory=list)

    @property
    def right(self):
        return sum(1 for r in self.results if r.ok)

    @property
    def credit(self):
        """Fraction of the steps that are right, in [0, 1]."""
        return self.right / len(self.results) if self.results else 0.0

    def by_key(self):
        return {r.key: r for r in self.results}


def _link(name):
    return LINK_NAMES.get(name, name)


def _deg(z):
    return math.degrees(cmath.phase(z))


def _wrap(d):
    """An angle difference [deg] in (-180, 180]."""
    d = (d + 180.0) % 360.0 - 180.0
    return 180.0 if d == -180.0 else d


def _near(p, q, tol):
    return p is not None and q is not None and abs(p - q) <= tol


def _distance_to_line(point, through, direction):
    w = point - through
    return abs(w.real * direction.imag - w.imag * direction.real) / abs(direction)


def _crossing(p1, u1, p2, u2):
    den = u1.real * u2.imag - u1.imag * u2.real
    if abs(den) < 1e-9 * abs(u1) * abs(u2):
        return None
    w = p2 - p1
    t = (w.real * u2.imag - w.imag * u2.real) / den
    return p1 + t * u1


def _join(names):
    names = list(names)
    if len(names) <= 1:
        return "".join(names)
    return ", ".join(names[:-1]) + " or " + names[-1]


class _Drawing:
    """A student's steps on one phase, with the points their chain defines."""

    def __init__(self, phase, steps):
        self.phase = phase
        self.latest = {}
        for s in steps:
            self.latest[s.key] = s  # a later step of the same key replaces it

    def vector(self, name):
        return self.latest.get(f"vector:{name}")

    def line(self, name):
        return self.latest.get(f"line:{name}")

    def known_end(self, side):
        """The end of the student's known part of ``side``, or None while a
        known term of it is not drawn."""
        end = 0j
        for t in self.phase.side(side):
            if t.known:
                v = self.vector(t.name)
                if v is None:
                    return None
                end += v.vector
        return end

    def crossing(self):
        """Where the student's two lines of the unknowns cross (None without them)."""
        names = [t.name for t in self.phase.unknowns]
        lines = [self.line(n) for n in names]
        if any(ln is None for ln in lines):
            return None
        return _crossing(lines[0].through, lines[0].direction, lines[1].through, lines[1].direction)


def _describe_anchor(phase, term, end):
    """Words for where a term starts or ends (for messages; no numbers)."""
    if term in phase.resultants:
        return "the pole" if end == "tail" else "the point where the lines cross"
    chain = phase.side(term.side)
    unknown = [t for t in chain if not t.known]
    first = term is unknown[0]
    if (end == "tail") == first:
        if end == "tip":
            return "the point where the lines cross"
        knowns = [t.name for t in chain if t.known]
        return f"the tip of {knowns[-1]}" if knowns else "the pole"
    if end == "tail":
        return "the point where the lines cross"
    other = "L" if term.side == "R" else "R"
    names = [t.name for t in phase.side(other)]
    return f"the tip of {names[0]}" if len(names) == 1 else f"the end of {' + '.join(names)}"


def _student_anchor(phase, drawing, term, end, x_student):
    """The student's own version of a term's tail or tip, or None."""
    if term in phase.resultants:
        return 0j if end == "tail" else x_student
    chain = phase.side(term.side)
    unknown = [t for t in chain if not t.known]
    first = term is unknown[0]
    if (end == "tail") == first:
        return drawing.known_end(term.side) if end == "tail" else x_student
    if end == "tail":
        return x_student
    return drawing.known_end("L" if term.side == "R" else "R")


# ---------------------------------------------------------------- the rules
def direction_problem(term, drawn, band, line=False):
    """Why a drawn direction (complex) is not the term's, or None."""
    if abs(drawn) == 0.0:
        return f"{term.name} has no length"
    d = _wrap(_deg(drawn) - _deg(term.vector))
    if line:
        d = _wrap(2.0 * d) / 2.0  # a line has no sense
    if abs(d) <= band:
        return None
    if line:
        what = f"the line of {term.name}"
    else:
        what = term.name
    if not line and abs(180.0 - abs(d)) <= band:
        if term.known:
            return f"{term.name} has the wrong sense: {term.rule}"
        return None  # the caller says where an unknown runs
    if abs(abs(d) - 90.0) <= band:
        if term.across:
            return f"{what} is perpendicular to {_link(term.link)}, not along it: {term.rule}"
        if term.link:
            return f"{what} lies along {_link(term.link)}, not across it: {term.rule}"
    return f"{what} is not in the direction of {term.name}: {term.rule}"


#: factors a slip multiplies a length by, and what to check
FACTORS = (
    (2.0, "check for a doubled or a halved term"),
    (12.0, "check inches against feet"),
    (25.4, "check inches against millimetres"),
    (1000.0, "check millimetres against metres"),
    (2 * math.pi, "check revolutions against radians"),
)


def _factor_hint(ratio, phase, others=()):
    """A hint for a length off by a recognisable factor, else ''."""
    if not ratio > 0:
        return ""
    for factor, text in FACTORS:
        for r in (factor, 1.0 / factor):
            if abs(ratio - r) <= 0.03 * r:
                return f"; it is off by a factor of about {factor:g}: {text}"
    scales = [phase.scale] + [p.scale for p in others if p is not phase]
    for s in scales:
        for r in (s, 1.0 / s):
            if r != 1.0 and abs(ratio - r) <= 0.03 * r:
                return (
                    f"; check the polygon's scale (1 square = {phase.scale:g} {phase.unit}) "
                    "and whether the length was typed in squares or in units"
                )
    for a in others:
        if a is not phase:
            r = phase.scale / a.scale
            if abs(ratio - r) <= 0.03 * r or abs(ratio - 1 / r) <= 0.03 / r:
                return "; check the scale: each polygon has its own"
    return ""


#: where the chapter gives the size of a known term
SIZE_EQUATION = {"normal": "eq. 7.6", "tangential": "eq. 7.6", "coriolis": "eq. 7.19"}


def length_problem(term, drawn, phase, others=()):
    """Why a drawn vector's length is not the term's, or None."""
    got, want = abs(drawn), abs(term.vector)
    if abs(got - want) <= phase.tol:
        return None
    how = "too long" if got > want else "too short"
    hint = _factor_hint(got / want if want else 0.0, phase, others)
    if term.known and term.size:
        cite = SIZE_EQUATION.get(term.kind)
        size = f"{term.size} ({cite})" if cite else term.size
        return f"{term.name} is {how}: its length is {size}{hint}"
    return f"{term.name} is {how}{hint}"


def judge_known(phase, drawing, term, step, others=()):
    problems = [
        p
        for p in (
            direction_problem(term, step.vector, phase.band),
            length_problem(term, step.vector, phase, others),
        )
        if p
    ]
    side = phase.side(term.side)
    mates = [t for t in side if t.known and t is not term]
    tips = [drawing.vector(t.name) for t in mates]
    starts = [0j] + [v.tip for v in tips if v is not None]
    if not any(_near(step.tail, z, phase.tol) for z in starts):
        names = [t.name for t in mates]
        problems.append(
            f"{term.name} is laid tip to tail on its side of {phase.equation}: start it at the "
            + ("pole" if not names else f"pole or at the tip of {_join(names)}")
        )
    else:
        shared = [
            t.name
            for t, v in zip(mates, tips)
            if v is not None and v.index < step.index and _near(v.tail, step.tail, phase.tol)
        ]
        if shared:
            problems.append(
                f"{term.name} starts where {shared[0]} starts: lay the terms of a side tip to "
                "tail, each from the tip of the one before"
            )
    return problems


def judge_line(phase, drawing, term, step):
    problems = []
    p = direction_problem(term, step.direction, phase.band, line=True)
    if p:
        problems.append(p)
    true_anchor = phase.line_anchor(term)
    chain = phase.side(term.side)
    first = term is [t for t in chain if not t.known][0]
    side = term.side if first else ("L" if term.side == "R" else "R")
    mine = drawing.known_end(side)
    on = lambda z: z is not None and _distance_to_line(z, step.through, step.direction) <= phase.tol  # noqa: E731
    if not (on(true_anchor) or on(mine)):
        knowns = [t for t in phase.side(side) if t.known]
        missing = [t for t in knowns if drawing.vector(t.name) is None]
        where = (
            "the pole"
            if not knowns and first
            else f"the end of {' + '.join(t.name for t in knowns)}"
        )
        text = f"the line of {term.name} passes through {where}"
        if missing:
            text += f", and {_join(t.name for t in missing)} is not drawn: " + "; ".join(
                t.rule for t in missing
            )
        problems.append(text)
    return problems


def judge_point(phase, drawing, step, line_results):
    names = {t.name for t in phase.unknowns}
    u1, u2 = (t.name for t in phase.unknowns)
    if set(step.lines) != names:
        return [f"the polygon closes where the lines of {u1} and {u2} cross: mark that point"]
    crossing = drawing.crossing()
    at = crossing if crossing is not None else step.at
    if _near(at, phase.X, phase.tol):
        return []
    if crossing is not None and all(line_results) and _near(step.at, crossing, phase.tol):
        return []  # the crossing of two right lines: as right as they are
    return [
        f"the lines of {u1} and {u2} do not cross where the polygon closes: check each line "
        "(its direction, and the point it passes through)"
    ]


def judge_unknown(phase, drawing, term, step, x_student, point_ok):
    """An unknown term (or a resultant) drawn to close the polygon: right when it
    runs between the student's own right points (follow-through: its direction
    and length are then as right as the drawing), or between the exact points
    with its exact direction and length."""
    if abs(step.vector) == 0.0:
        return [f"{term.name} has no length"]
    mine = {
        end: _student_anchor(phase, drawing, term, end, x_student if point_ok else None)
        for end in ("tail", "tip")
    }
    if point_ok and all(
        _near(z, mine[e], phase.tol) for e, z in (("tail", step.tail), ("tip", step.tip))
    ):
        return []
    ends = {
        e: _near(z, phase.anchor(term, e), phase.tol) or _near(z, mine[e], phase.tol)
        for e, z in (("tail", step.tail), ("tip", step.tip))
    }
    problems = []
    if not (ends["tail"] and ends["tip"]):
        problems.append(
            f"{term.name} runs from {_describe_anchor(phase, term, 'tail')} to "
            f"{_describe_anchor(phase, term, 'tip')}"
        )
    d = _wrap(_deg(step.vector) - _deg(term.vector))
    if abs(180.0 - abs(d)) <= phase.band and not ends["tail"]:
        pass  # drawn backwards: the message above says where it runs
    elif abs(d) > phase.band:
        p = direction_problem(term, step.vector, phase.band)
        if p is None:  # the opposite sense
            p = (
                f"{term.name} has the wrong sense: it runs from "
                f"{_describe_anchor(phase, term, 'tail')} to "
                f"{_describe_anchor(phase, term, 'tip')}"
            )
        problems.append(p)
    if not problems:
        p = length_problem(term, step.vector, phase)
        if p:
            problems.append(p)
    return problems


def read_tolerance(phase, read):
    if read.about is not None:
        return max(0.02 * abs(read.value), phase.tol / abs(read.about))
    return max(0.02 * abs(read.value), phase.tol)


def judge_read(phase, drawing, read, step, source_ok):
    tol = read_tolerance(phase, read)
    v = step.value
    if abs(v - read.value) <= tol:
        return []
    source = drawing.vector(read.source)
    if source is not None and source_ok and abs(v - read.of(source.vector)) <= tol:
        return []
    if abs(v + read.value) <= tol:
        return [f"{read.label} has the wrong sign: {read.rule}"]
    hint = _factor_hint(abs(v / read.value), phase) if read.value else ""
    text = f"{read.label} is not what the polygon gives: {read.rule}{hint}"
    if source is None:
        text += f"; draw {read.source} first, then measure it"
    return [text]


def _ok_text(step):
    return {
        "vector": "right",
        "line": "right",
        "point": "right: the polygon closes here",
        "read": "right",
    }[step.op]


def judge_phase(phase, steps, others=()):
    """The :class:`Judgement` of a student's ``steps`` (Drawn, of this phase)
    against ``phase``. ``others`` are the task's other phases (for the scale hint)."""
    drawing = _Drawing(phase, [s for s in steps if s.phase == phase.name])
    judgement = Judgement(phase.name)
    results = {}
    line_ok = {}

    def put(key, step, problems, what):
        if step is None:
            results[key] = Result(key, False, what, None)
        elif problems:
            results[key] = Result(key, False, "; ".join(problems), step.index)
        else:
            results[key] = Result(key, True, f"{what}: {_ok_text(step)}", step.index)

    for term in phase.terms:
        if term.known:
            step = drawing.vector(term.name)
            key = f"vector:{term.name}"
            if step is None:
                put(key, None, [], f"{term.name} is not drawn: {term.rule}")
            else:
                put(key, step, judge_known(phase, drawing, term, step, others), term.name)
    for term in phase.unknowns:
        step = drawing.line(term.name)
        key = f"line:{term.name}"
        if step is None:
            put(key, None, [], f"the line of {term.name} is not drawn")
        else:
            put(key, step, judge_line(phase, drawing, term, step), f"the line of {term.name}")
        line_ok[term.name] = results[key].ok
    point = drawing.latest.get("point:X")
    u1, u2 = (t.name for t in phase.unknowns)
    if point is None:
        put("point:X", None, [], f"the point where the lines of {u1} and {u2} cross is not marked")
    else:
        put(
            "point:X",
            point,
            judge_point(phase, drawing, point, list(line_ok.values())),
            "the point where the lines cross",
        )
    point_ok = results["point:X"].ok
    x_student = drawing.crossing() if point is not None else None
    if x_student is None and point is not None:
        x_student = point.at
    for term in phase.unknowns + phase.resultants:
        step = drawing.vector(term.name)
        key = f"vector:{term.name}"
        if step is None:
            put(key, None, [], f"{term.name} is not drawn")
        else:
            put(
                key, step, judge_unknown(phase, drawing, term, step, x_student, point_ok), term.name
            )
    for read in phase.reads:
        step = drawing.latest.get(f"read:{read.name}")
        key = f"read:{read.name}"
        source_ok = results.get(f"vector:{read.source}", Result("", False, "")).ok
        if step is None:
            put(key, None, [], f"{read.label} is not read off yet")
        else:
            put(key, step, judge_read(phase, drawing, read, step, source_ok), read.label)
    judgement.results = [results[s.key] for s in phase.steps]
    for s in drawing.latest.values():
        if s.key not in results:
            judgement.notes.append(_stray(phase, s))
    return judgement


def _stray(phase, step):
    """What to say of a step that is no step of this phase."""
    names = {t.name for t in phase.terms + phase.resultants}
    if step.op == "line" and step.name in names:
        return (
            f"{step.name} is known in size and direction: lay it as a vector (construction "
            "lines are for the terms whose length is unknown)"
        )
    if step.op == "read":
        return f"{step.name} is not an unknown read off the {phase.title.lower()}"
    return f"{step.name} is not a term of {phase.equation}"


def step_feedback(task, steps):
    """Instant feedback on a student's steps (Drawn, both phases): one dict per
    step, ``{"ok": bool or None, "message": str}``, in the order of ``steps``.
    A step that a later one of the same key replaced gets ``ok = None``."""
    out = [None] * len(steps)
    latest = {}
    for s in steps:
        latest[(s.phase, s.key)] = s.index
    phases = list(task.phases.values())
    judged = {}
    for phase in phases:
        mine = [s for s in steps if s.phase == phase.name]
        if mine:
            judged[phase.name] = judge_phase(phase, mine, phases)
    for k, s in enumerate(steps):
        if latest[(s.phase, s.key)] != s.index:
            out[k] = {"ok": None, "message": "replaced by a later step"}
            continue
        j = judged[s.phase].by_key().get(s.key)
        if j is None:
            out[k] = {"ok": False, "message": _stray(task.phase(s.phase), s)}
        else:
            out[k] = {"ok": j.ok, "message": j.message}
    return out


# ---------------------------------------------------------------- the next step
def _fmt(x):
    return f"{x:.4g}"


def next_step(phase, steps, numbers=True):
    """The first step of ``phase`` not yet right, as ``{"key", "text", "ghost"}``
    (``ghost``: the step drawn right, SI, for the builder to show dotted), or
    None when the polygon is done. ``numbers=False`` (an assignment) says what
    to do next in words only, with no value and no ghost."""
    mine = [s for s in steps if s.phase == phase.name]
    judgement = judge_phase(phase, mine)
    drawing = _Drawing(phase, mine)
    for expected, result in zip(phase.steps, judgement.results):
        if result.ok:
            continue
        if not numbers:
            done = set(drawing.latest)
            if expected.key in done:
                continue
            return {
                "key": expected.key,
                "text": _what_next(phase, expected, drawing),
                "ghost": None,
            }
        return {
            "key": expected.key,
            "text": _what_next(phase, expected, drawing, True),
            "ghost": _ghost(phase, expected, drawing),
        }
    return None


def _what_next(phase, expected, drawing=None, numbers=False):
    f, unit = phase.factor, phase.unit
    if expected.op == "vector":
        t = phase.term(expected.name)
        if t.known:
            drawn = [
                m.name
                for m in phase.side(t.side)
                if m.known and m is not t and drawing is not None and drawing.vector(m.name)
            ]
            where = f"from the tip of {drawn[-1]}" if drawn else "from the pole"
            size = f" = {t.size}" if t.size else ""
            if numbers:
                size += (
                    f" = {_fmt(abs(t.vector) * f)} {unit} "
                    f"({_fmt(abs(t.vector) * f / phase.scale)} squares), "
                    f"at {_fmt(_deg(t.vector) % 360)} deg"
                )
            return f"Lay {t.name}{size} {where}: {t.rule}."
        return (
            f"Draw {t.name} from {_describe_anchor(phase, t, 'tail')} to "
            f"{_describe_anchor(phase, t, 'tip')}."
        )
    if expected.op == "line":
        t = phase.term(expected.name)
        first = t is [u for u in phase.side(t.side) if not u.known][0]
        side = t.side if first else ("L" if t.side == "R" else "R")
        knowns = [k.name for k in phase.side(side) if k.known]
        where = f"the end of {' + '.join(knowns)}" if knowns else "the pole"
        return f"Draw the line of {t.name} through {where}: {t.rule}."
    if expected.op == "point":
        u1, u2 = (t.name for t in phase.unknowns)
        return f"Mark the point where the lines of {u1} and {u2} cross: the polygon closes there."
    read = next(r for r in phase.reads if r.name == expected.name)
    text = f"Read {read.label} off the polygon: {read.rule}."
    if numbers:
        text += f" It is {_fmt(read.value)} {read.unit or unit}."
    return text


def _ghost(phase, expected, drawing):
    x = drawing.crossing()
    if expected.op == "vector":
        t = phase.term(expected.name)
        if t.known:
            mates = [drawing.vector(m.name) for m in phase.side(t.side) if m.known and m is not t]
            used = {round(v.tail.real, 12) + 1j * round(v.tail.imag, 12) for v in mates if v}
            tips = [v.tip for v in mates if v is not None]
            free = [z for z in [0j] + tips if not any(_near(z, u, phase.tol) for u in used)]
            tail = free[-1] if free else phase.anchor(t, "tail")
            return {"op": "vector", "tail": _xy(tail), "tip": _xy(tail + t.vector)}
        tail = _student_anchor(phase, drawing, t, "tail", x)
        tip = _student_anchor(phase, drawing, t, "tip", x)
        tail = phase.anchor(t, "tail") if tail is None else tail
        tip = phase.anchor(t, "tip") if tip is None else tip
        return {"op": "vector", "tail": _xy(tail), "tip": _xy(tip)}
    if expected.op == "line":
        t = phase.term(expected.name)
        first = t is [u for u in phase.side(t.side) if not u.known][0]
        side = t.side if first else ("L" if t.side == "R" else "R")
        through = drawing.known_end(side)
        through = phase.line_anchor(t) if through is None else through
        return {"op": "line", "through": _xy(through), "angle": _deg(t.vector)}
    if expected.op == "point":
        return {"op": "point", "at": _xy(x if x is not None else phase.X)}
    return None


def _xy(z):
    return [z.real, z.imag]
