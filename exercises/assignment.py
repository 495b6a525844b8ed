"""An assignment: its spec (the same for every student) and each student's variant.

The spec is a plain dict, stored in the notebook's locked parameter cell and in
``source/<assignment>/accelab.json``::

    {"course": "mech101", "assignment": "A", "units": "US", "tolerance": 0.01,
     "angle_tolerance": 1.0,
     "problems": [{"family": "rotation", "ranges": {}}, {"family": "fourbar"}]}

``tolerance`` is relative (0.01: a number is right within 1% of the exact value);
``angle_tolerance`` is an absolute band for directions [deg] (modulo 360 deg).

A variant is the list of problems that the seed of (course, assignment,
student, problem number) draws. With more than one problem, answer names get
the prefix ``p<k>_`` (``p2_alpha3``), so they stay distinct.
"""

from dataclasses import dataclass

from .families import FAMILIES, generate
from .seeding import seed_for
from .silence import silenced

SPEC_KEYS = {"course", "assignment", "units", "tolerance", "problems"}
#: relative tolerance of numbers, and the band of directions [deg]
DEFAULT_TOLERANCE = 0.01
DEFAULT_ANGLE_TOLERANCE = 1.0


def make_spec(
    course,
    assignment,
    families,
    units="US",
    tolerance=DEFAULT_TOLERANCE,
    ranges=None,
    angle_tolerance=DEFAULT_ANGLE_TOLERANCE,
):
    """A checked spec. ``ranges`` maps family -> its ranges dict."""
    spec = {
        "course": str(course),
        "assignment": str(assignment),
        "units": units,
        "tolerance": float(tolerance),
        "angle_tolerance": float(angle_tolerance),
        "problems": [{"family": f, "ranges": dict((ranges or {}).get(f, {}))} for f in families],
    }
    return check_spec(spec)


def check_spec(spec):
    missing = SPEC_KEYS - set(spec)
    if missing:
        raise ValueError(f"assignment spec lacks {sorted(missing)}")
    if spec["units"] not in ("US", "SI"):
        raise ValueError(f"units must be 'US' or 'SI' (got {spec['units']!r})")
    if not 0 < float(spec["tolerance"]) < 0.5:
        raise ValueError(f"tolerance is relative, e.g. 0.01 for 1% (got {spec['tolerance']!r})")
    if not 0 < float(spec.get("angle_tolerance", DEFAULT_ANGLE_TOLERANCE)) <= 45:
        raise ValueError(
            f"angle_tolerance is a band in degrees, e.g. 1.0 (got {spec['angle_tolerance']!r})"
        )
    if not spec["problems"]:
        raise ValueError("an assignment needs at least one problem")
    for p in spec["problems"]:
        if p.get("family") not in FAMILIES:
            raise ValueError(
                f"unknown problem family {p.get('family')!r}; use one of {', '.join(FAMILIES)}"
            )
    return spec


@dataclass
class Variant:
    """One student's assignment: the assignment's ``spec``, the ``student`` id, and the
    :class:`~accelab.exercises.problem.Problem` of each of the spec's problems, drawn
    from a seed of course, assignment, student and problem (:func:`build_variant`)."""

    spec: dict
    student: str
    problems: list

    @property
    def answers(self):
        return {a.name: a for p in self.problems for a in p.answers}

    @property
    def tolerance(self):
        return float(self.spec["tolerance"])

    @property
    def angle_tolerance(self):
        """Band of directions [deg]."""
        return float(self.spec.get("angle_tolerance", DEFAULT_ANGLE_TOLERANCE))

    def statement(self):
        """What the student's kernel may hold: given values and what is asked."""
        return {
            "course": self.spec["course"],
            "assignment": self.spec["assignment"],
            "student": self.student,
            "units": self.spec["units"],
            "tolerance": self.tolerance,
            "angle_tolerance": self.angle_tolerance,
            "problems": [p.statement_view() for p in self.problems],
        }

    def public(self):
        """The variant as ``accelab variant --json`` prints it: no answers."""
        return {
            "course": self.spec["course"],
            "assignment": self.spec["assignment"],
            "student": self.student,
            "units": self.spec["units"],
            "tolerance": self.tolerance,
            "angle_tolerance": self.angle_tolerance,
            "problems": [dict(p.public(), number=k + 1) for k, p in enumerate(self.problems)],
            "answers": [
                dict(a.public(), problem=k + 1)
                for k, p in enumerate(self.problems)
                for a in p.answers
            ],
        }


def build_variant(spec, student):
    """The variant of ``student`` (deterministic in spec and student id)."""
    check_spec(spec)
    problems = []
    many = len(spec["problems"]) > 1
    for k, p in enumerate(spec["problems"], start=1):
        seed = seed_for(spec["course"], spec["assignment"], student, k, p["family"])
        problem = generate(p["family"], seed, ranges=p.get("ranges") or None, units=spec["units"])
        if many:
            for a in problem.answers:
                a.name = f"p{k}_{a.name}"
        problems.append(problem)
    return Variant(spec, str(student), problems)


def statement_of(spec, student):
    """The statement of ``student`` (:meth:`Variant.statement`)."""
    with silenced():
        return build_variant(spec, student).statement()
