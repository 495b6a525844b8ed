"""What a student must construct: the velocity and the acceleration polygon of
one position, as the chapter lays them out (section 7.2, Example 7-1, Figure 7-4).

A :class:`Task` is built from a batch case by the package's own geometric
construction (:func:`accelab.solver.graphical.construct_case`), which never asks
the analytic solver. Each polygon (:class:`Phase`) is one vector equation, both
sides laid tip to tail from the pole:

* the **known** terms (magnitude and direction known: ``V_A``, ``A_A^n``,
  ``A_BA^n``, the Coriolis term) first, on their side of the equation;
* the two **unknown** terms (direction known, length not: ``A_B^t``,
  ``A_BA^t``, a slider's ``A_B``) as construction lines through the end of
  the known part of their side (or, the second unknown of a side, through the
  end of the other side);
* the point where the two lines cross closes the polygon: the unknown terms run
  to it and from it, and the unknowns (omega, alpha, slip) are read off.

The phase lists these as :attr:`Phase.steps`, in the order the chapter takes
them; the checking rules (:mod:`accelab.exercises.student.polygon.rules`) judge a
student's drawing step by step against them. Everything is in SI (m/s, m/s^2,
rad/s, rad/s^2); the drawing shows the case's own units (in/s and in/s^2, or
m/s and m/s^2).
"""

import cmath
import math
from dataclasses import dataclass, field

#: the problem families of the polygon builder and the mechanism each constructs
FAMILY_MECHANISM = {
    "polygon_fourbar": "fourbar",
    "polygon_slidercrank": "slidercrank",
    "polygon_coriolis": "invertedslidercrank",
}
#: the two polygons of a position, in the order they are drawn
PHASES = ("velocity", "acceleration")
#: the answer name of each phase's construction (with a ``p<k>_`` prefix in an
#: assignment of several problems)
ANSWER_SUFFIX = {"velocity": "velocity_polygon", "acceleration": "acceleration_polygon"}
#: the polygon's largest vector spans at most this many grid squares
SQUARES = 8.0
#: directions are right within this band [deg]
BAND_DEG = 1.0
#: lengths are right within this fraction of the polygon's largest vector
LENGTH_FRACTION = 0.02

IN = 0.0254  # [m]
UNITS = {
    "US": {
        "length": ("in", 1 / IN),
        "velocity": ("in/s", 1 / IN),
        "acceleration": ("in/s^2", 1 / IN),
    },
    "SI": {"length": ("mm", 1e3), "velocity": ("m/s", 1.0), "acceleration": ("m/s^2", 1.0)},
}


@dataclass(frozen=True)
class Term:
    """One term of a polygon's vector equation.

    ``vector`` is the exact vector [m/s or m/s^2]; ``known`` says whether its
    length is known before the polygon is drawn; ``side`` is ``"L"`` or ``"R"``
    (the left or right side of the equation). ``link`` and ``across`` say how
    its direction is fixed (along or perpendicular to a link); ``rule`` says it
    in the chapter's terms, ``size`` is how its length is found (eq. 7.6).
    """

    name: str
    kind: str
    vector: complex
    known: bool
    side: str
    link: str
    across: bool
    rule: str
    size: str = ""


@dataclass(frozen=True)
class Read:
    """An unknown read off a finished polygon: ``value`` [SI] comes from the
    term ``source``: an angular rate (``about`` the link vector R: value =
    ``(R x V) / |R|^2``, counter-clockwise positive) or a slip or slider rate
    (``along`` a unit vector: value = V . e)."""

    name: str
    label: str
    unit: str
    value: float
    source: str
    about: complex = None
    along: complex = None
    link: str = ""
    rule: str = ""

    def of(self, vector):
        """The value this read takes for ``vector`` (the source term as drawn)."""
        if self.about is not None:
            r = self.about
            return (r.real * vector.imag - r.imag * vector.real) / abs(r) ** 2
        return vector.real * self.along.real + vector.imag * self.along.imag


@dataclass(frozen=True)
class Step:
    """One step of a phase: ``op`` is ``vector``, ``line``, ``point`` or
    ``read``; ``name`` the term (or read) it is about (``X`` for the point)."""

    op: str
    name: str

    @property
    def key(self):
        return f"{self.op}:{self.name}"


@dataclass
class Phase:
    """One polygon: its equation, terms, closing point and reads (see the module
    docstring). ``tol`` is the length tolerance [SI], ``band`` the direction
    band [deg]; ``unit``/``factor`` the display unit and SI-to-display factor;
    ``scale`` the drawing's scale [display unit per grid square]."""

    name: str
    title: str
    equation: str
    terms: list
    reads: list
    unit: str
    factor: float
    resultants: list = field(default_factory=list)  # extra terms: pole -> X
    tol: float = 0.0
    band: float = BAND_DEG
    scale: float = 1.0

    def term(self, name):
        for t in self.terms + self.resultants:
            if t.name == name:
                return t
        raise KeyError(name)

    def side(self, s):
        return [t for t in self.terms if t.side == s]

    @property
    def unknowns(self):
        return [t for t in self.terms if not t.known]

    def known_end(self, s):
        """End of the known part of side ``s`` (the pole plus its known terms)."""
        return sum((t.vector for t in self.side(s) if t.known), 0j)

    def end(self, s):
        return sum((t.vector for t in self.side(s)), 0j)

    @property
    def closing(self):
        """Where the polygon closes: the tip of the sides' sum (both sides end there)."""
        return self.end("L")

    @property
    def X(self):
        """The point where the two construction lines cross."""
        u1 = self.unknowns[0]
        return self.anchor(u1, "tip")

    def anchor(self, term, end):
        """Exact tail or tip (``end``) of a term in the chapter's layout: knowns
        tip to tail from the pole, an unknown from the end of its side's knowns
        to the crossing, a second unknown of one side from the crossing to the
        end of the other side. A resultant runs from the pole to the crossing."""
        if term in self.resultants:
            return 0j if end == "tail" else self.X
        chain = self.side(term.side)
        tail = 0j
        for t in chain:
            if t is term:
                return tail if end == "tail" else tail + t.vector
            tail += t.vector
        raise KeyError(term.name)

    def line_anchor(self, term):
        """The point the construction line of an unknown is drawn through: the
        end of its side's known part, or (a second unknown of one side) the
        end of the other side."""
        chain = self.side(term.side)
        unknown = [t for t in chain if not t.known]
        if term is unknown[0]:
            return self.anchor(term, "tail")
        return self.anchor(term, "tip")

    @property
    def largest(self):
        return max(abs(t.vector) for t in self.terms + self.resultants)

    @property
    def steps(self):
        """The phase's steps in the chapter's order."""
        out = [Step("vector", t.name) for t in self.terms if t.known]
        out += [Step("line", t.name) for t in self.unknowns]
        out.append(Step("point", "X"))
        out += [Step("vector", t.name) for t in self.unknowns]
        out += [Step("vector", t.name) for t in self.resultants]
        out += [Step("read", r.name) for r in self.reads]
        return out


@dataclass
class Task:
    """The construction a student must make for one case: the linkage to scale
    and the two phases. ``units`` is "US" or "SI" (the drawing's units)."""

    mechanism: str
    case: dict
    units: str
    points: dict
    links: list
    ground: list
    slides: list
    directions: dict  # link name -> unit vector (the link from its first point)
    phases: dict

    def phase(self, name):
        if name not in self.phases:
            raise KeyError(f"no phase {name!r}; the phases are {', '.join(self.phases)}")
        return self.phases[name]


def nice_scale(x):
    """A round scale (1, 2, 2.5 or 5 times a power of ten) at least x > 0."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    e = math.floor(math.log10(x))
    for m in (1, 2, 2.5, 5, 10):
        if m * 10**e >= x * (1 - 1e-12):
            return m * 10**e
    return 10 ** (e + 1)


def _unit(z):
    return z / abs(z)


def task_of_case(case):
    """The :class:`Task` of a batch case (fourbar, slidercrank or
    invertedslidercrank). Raises the solver's errors for a case that cannot
    be drawn, and ValueError for another mechanism."""
    from accelab.solver.graphical import construct_case

    mechanism = case.get("mechanism") if isinstance(case, dict) else None
    if mechanism not in ("fourbar", "slidercrank", "invertedslidercrank"):
        raise ValueError(
            f"the polygon builder draws a fourbar, a slidercrank or an invertedslidercrank "
            f"(got {mechanism!r})"
        )
    case = {k: v for k, v in case.items() if k not in ("p", "delta3")}  # no coupler point
    con = construct_case(case)
    units = con.units if con.units in UNITS else "SI"
    v = con.values
    pts = dict(con.linkage.points)
    if mechanism == "fourbar":
        phases, dirs = _fourbar(v, pts)
        slides = []
    elif mechanism == "slidercrank":
        phases, dirs = _slidercrank(v, pts, con)
        slides = [(p, d) for p, d in con.linkage.slides]
    else:
        phases, dirs = _inverted(v, pts, con)
        slides = [(p, d) for p, d, *_ in con.linkage.rods]
    for ph in phases:
        unit, factor = UNITS[units][ph.name]
        ph.unit, ph.factor = unit, factor
        ph.tol = LENGTH_FRACTION * ph.largest
        ph.scale = nice_scale(ph.largest * factor / SQUARES)
    links = [tuple(x for x in link) for link in con.linkage.links]
    return Task(
        mechanism,
        dict(case),
        units,
        pts,
        links,
        list(con.linkage.ground),
        slides,
        dirs,
        {ph.name: ph for ph in phases},
    )


def _crank_and_coupler_velocities(V_A, V_B):
    """The terms of eq. 6.5 up to B that a fourbar and a slider-crank share: V_A (A turns
    about O2) and V_BA (B turns about A, unknown in size)."""
    return [
        Term(
            "V_A",
            "velocity",
            V_A,
            True,
            "R",
            "O2A",
            True,
            "V_A is perpendicular to O2A, in the sense of omega2 (A turns about O2)",
            "a omega2",
        ),
        Term(
            "V_BA",
            "velocity",
            V_B - V_A,
            False,
            "R",
            "AB",
            True,
            "V_BA is perpendicular to AB (B turns about A)",
        ),
    ]


def _crank_accelerations(v, side):
    """A_A's two terms (the crank turns about O2), both known, on ``side`` ("L" or "R") of
    the polygon's vector equation: the fourbar's and the slider-crank's have them on the
    right (A_B = A_A + A_BA), the inverted slider-crank's on the left (eq. 7.21)."""
    return [
        Term(
            "A_A^t",
            "tangential",
            v["A_A_t"],
            True,
            side,
            "O2A",
            True,
            "A_A^t is perpendicular to O2A, in the sense of alpha2",
            "a alpha2",
        ),
        Term(
            "A_A^n",
            "normal",
            v["A_A_n"],
            True,
            side,
            "O2A",
            False,
            "A_A^n points from A toward O2, the centre of A's path",
            "a omega2^2",
        ),
    ]


def _crank_and_coupler_accelerations(v):
    """The terms of eq. 7.4 up to B that a fourbar and a slider-crank share: A_A's two
    (the crank turns about O2) and A_BA's two (B turns about A); only A_BA^t is unknown."""
    return [
        *_crank_accelerations(v, "R"),
        Term(
            "A_BA^n",
            "normal",
            v["A_BA_n"],
            True,
            "R",
            "AB",
            False,
            "A_BA^n points from B toward A (B turns about A)",
            "b omega3^2",
        ),
        Term(
            "A_BA^t",
            "tangential",
            v["A_BA_t"],
            False,
            "R",
            "AB",
            True,
            "A_BA^t is perpendicular to BA",
        ),
    ]


def _fourbar(v, pts):
    A, B, O4 = pts["A"], pts["B"], pts["O4"]
    R_BA, R_BO4 = B - A, B - O4
    dirs = {"O2A": _unit(A), "AB": _unit(R_BA), "O4B": _unit(R_BO4), "O2O4": _unit(O4)}
    V_A, V_B = v["V_A"], v["V_B"]
    vel = Phase(
        "velocity",
        "Velocity polygon",
        "V_B = V_A + V_BA (eq. 6.5)",
        [
            *_crank_and_coupler_velocities(V_A, V_B),
            Term(
                "V_B",
                "resultant",
                V_B,
                False,
                "L",
                "O4B",
                True,
                "V_B is perpendicular to O4B (B turns about O4)",
            ),
        ],
        [
            Read(
                "omega3",
                "omega3",
                "rad/s",
                v["omega3"],
                "V_BA",
                about=R_BA,
                link="AB",
                rule="omega3 = V_BA / b, counter-clockwise positive: the sense in which "
                "V_BA turns B about A",
            ),
            Read(
                "omega4",
                "omega4",
                "rad/s",
                v["omega4"],
                "V_B",
                about=R_BO4,
                link="O4B",
                rule="omega4 = V_B / c, counter-clockwise positive: the sense in which "
                "V_B turns B about O4",
            ),
        ],
        "",
        1.0,
    )
    acc = Phase(
        "acceleration",
        "Acceleration polygon",
        "A_B^n + A_B^t = A_A^t + A_A^n + A_BA^n + A_BA^t (eq. 7.4)",
        [
            *_crank_and_coupler_accelerations(v),
            Term(
                "A_B^n",
                "normal",
                v["A_B_n"],
                True,
                "L",
                "O4B",
                False,
                "A_B^n points from B toward O4, the centre of B's path",
                "c omega4^2",
            ),
            Term(
                "A_B^t",
                "tangential",
                v["A_B_t"],
                False,
                "L",
                "O4B",
                True,
                "A_B^t is perpendicular to O4B (B turns about O4)",
            ),
        ],
        [
            Read(
                "alpha3",
                "alpha3",
                "rad/s^2",
                v["alpha3"],
                "A_BA^t",
                about=R_BA,
                link="AB",
                rule="alpha3 = A_BA^t / b, counter-clockwise positive: the sense in which "
                "A_BA^t turns B about A",
            ),
            Read(
                "alpha4",
                "alpha4",
                "rad/s^2",
                v["alpha4"],
                "A_B^t",
                about=R_BO4,
                link="O4B",
                rule="alpha4 = A_B^t / c, counter-clockwise positive: the sense in which "
                "A_B^t turns B about O4",
            ),
        ],
        "",
        1.0,
        resultants=[
            Term(
                "A_B",
                "resultant",
                v["A_B"],
                False,
                "L",
                "",
                False,
                "A_B = A_B^n + A_B^t runs from the pole to where the lines cross",
            ),
        ],
    )
    return [vel, acc], dirs


def _slidercrank(v, pts, con):
    A, B = pts["A"], pts["B"]
    e1 = _unit(con.linkage.slides[0][1])
    R_BA = B - A
    dirs = {"O2A": _unit(A), "AB": _unit(R_BA), "slide": e1}
    V_A, V_B = v["V_A"], v["V_B"]
    vel = Phase(
        "velocity",
        "Velocity polygon",
        "V_B = V_A + V_BA (eq. 6.5)",
        [
            *_crank_and_coupler_velocities(V_A, V_B),
            Term(
                "V_B",
                "resultant",
                V_B,
                False,
                "L",
                "slide",
                False,
                "V_B lies along the slide: the slider translates",
            ),
        ],
        [
            Read(
                "omega3",
                "omega3",
                "rad/s",
                v["omega3"],
                "V_BA",
                about=R_BA,
                link="AB",
                rule="omega3 = V_BA / b, counter-clockwise positive: the sense in which "
                "V_BA turns B about A",
            ),
            Read(
                "d_dot",
                "V_B",
                "",
                v["d_dot"],
                "V_B",
                along=e1,
                link="slide",
                rule="the slider's velocity is V_B along the slide, positive toward +x",
            ),
        ],
        "",
        1.0,
    )
    acc = Phase(
        "acceleration",
        "Acceleration polygon",
        "A_B = A_A^t + A_A^n + A_BA^n + A_BA^t (eq. 7.4)",
        [
            *_crank_and_coupler_accelerations(v),
            Term(
                "A_B",
                "resultant",
                v["A_B"],
                False,
                "L",
                "slide",
                False,
                "A_B lies along the slide: the slider translates",
            ),
        ],
        [
            Read(
                "alpha3",
                "alpha3",
                "rad/s^2",
                v["alpha3"],
                "A_BA^t",
                about=R_BA,
                link="AB",
                rule="alpha3 = A_BA^t / b, counter-clockwise positive: the sense in which "
                "A_BA^t turns B about A",
            ),
            Read(
                "d_ddot",
                "A_B",
                "",
                v["d_ddot"],
                "A_B",
                along=e1,
                link="slide",
                rule="the slider's acceleration is A_B along the slide, positive toward +x",
            ),
        ],
        "",
        1.0,
    )
    return [vel, acc], dirs


def _inverted(v, pts, con):
    A, O4 = pts["A"], pts["O4"]
    e3 = _unit(con.linkage.rods[0][1])
    R_AO4 = A - O4
    dirs = {"O2A": _unit(A), "O4A": _unit(R_AO4), "slide": e3, "O2O4": _unit(O4)}
    if "B" in pts and abs(pts["B"] - O4) > 0:
        dirs["O4B"] = _unit(pts["B"] - O4)
    V_A, V_A4 = v["V_A"], v["V_A"] - v["b_dot"] * e3
    w4 = v["omega4"]
    vel = Phase(
        "velocity",
        "Velocity polygon",
        "V_A = V_A4 + V_slip (A4: the point of link 4 under A)",
        [
            Term(
                "V_A",
                "velocity",
                V_A,
                True,
                "L",
                "O2A",
                True,
                "V_A is perpendicular to O2A, in the sense of omega2 (A turns about O2)",
                "a omega2",
            ),
            Term(
                "V_A4",
                "velocity",
                V_A4,
                False,
                "R",
                "O4A",
                True,
                "V_A4 is perpendicular to O4A (A4 turns about O4 with link 4)",
            ),
            Term(
                "V_slip",
                "slip",
                v["b_dot"] * e3,
                False,
                "R",
                "slide",
                False,
                "V_slip lies along the slide",
            ),
        ],
        [
            Read(
                "omega4",
                "omega4",
                "rad/s",
                w4,
                "V_A4",
                about=R_AO4,
                link="O4A",
                rule="omega4 = V_A4 / O4A, counter-clockwise positive: the sense in which "
                "V_A4 turns A4 about O4",
            ),
            Read(
                "b_dot",
                "V_slip",
                "",
                v["b_dot"],
                "V_slip",
                along=e3,
                link="slide",
                rule="the slip velocity is V_slip along the slide, positive from B toward A "
                "(as b grows)",
            ),
        ],
        "",
        1.0,
    )
    acc = Phase(
        "acceleration",
        "Acceleration polygon",
        "A_A^t + A_A^n = A_A4^n + A_cor + A_slip + A_A4^t (eqs. 7.19, 7.21)",
        [
            *_crank_accelerations(v, "L"),
            Term(
                "A_A4^n",
                "normal",
                v["A_A4_n"],
                True,
                "R",
                "O4A",
                False,
                "A_A4^n points from A toward O4 (A4 turns about O4)",
                "O4A omega4^2",
            ),
            Term(
                "A_cor",
                "coriolis",
                v["A_coriolis"],
                True,
                "R",
                "slide",
                True,
                "the inverted slider-crank needs the Coriolis term A_cor = 2 omega4 V_slip, "
                "perpendicular to the slide: V_slip turned 90 deg in the sense of omega4 "
                "(eq. 7.19)",
                "2 omega4 V_slip",
            ),
            Term(
                "A_slip",
                "slip",
                v["A_slip"],
                False,
                "R",
                "slide",
                False,
                "A_slip lies along the slide",
            ),
            Term(
                "A_A4^t",
                "tangential",
                v["A_A4_t"],
                False,
                "R",
                "O4A",
                True,
                "A_A4^t is perpendicular to O4A (A4 turns about O4)",
            ),
        ],
        [
            Read(
                "alpha4",
                "alpha4",
                "rad/s^2",
                v["alpha4"],
                "A_A4^t",
                about=R_AO4,
                link="O4A",
                rule="alpha4 = A_A4^t / O4A, counter-clockwise positive: the sense in which "
                "A_A4^t turns A4 about O4",
            ),
            Read(
                "b_ddot",
                "A_slip",
                "",
                v["b_ddot"],
                "A_slip",
                along=e3,
                link="slide",
                rule="the slip acceleration is A_slip along the slide, positive from B toward A",
            ),
        ],
        "",
        1.0,
    )
    return [vel, acc], dirs


def angle_deg(z):
    """Direction of z [deg], counter-clockwise from +x, in [0, 360)."""
    return math.degrees(cmath.phase(z)) % 360.0


def ideal_steps(phase):
    """The finished construction of ``phase`` as the builder records it (a list
    of step dicts, SI): what a right drawing holds, in the chapter's order."""
    out = []
    xy = lambda z: [z.real, z.imag]  # noqa: E731
    for step in phase.steps:
        if step.op == "vector":
            t = phase.term(step.name)
            out.append(
                {
                    "op": "vector",
                    "phase": phase.name,
                    "name": t.name,
                    "tail": xy(phase.anchor(t, "tail")),
                    "tip": xy(phase.anchor(t, "tip")),
                }
            )
        elif step.op == "line":
            t = phase.term(step.name)
            out.append(
                {
                    "op": "line",
                    "phase": phase.name,
                    "name": t.name,
                    "through": xy(phase.line_anchor(t)),
                    "angle": math.degrees(cmath.phase(t.vector)),
                }
            )
        elif step.op == "point":
            out.append(
                {
                    "op": "point",
                    "phase": phase.name,
                    "lines": [t.name for t in phase.unknowns],
                    "at": xy(phase.X),
                }
            )
        else:
            r = next(r for r in phase.reads if r.name == step.name)
            out.append({"op": "read", "phase": phase.name, "name": r.name, "value": r.value})
    return out
