"""The record of a graphical construction: what is drawn, on which diagram, at which step.

A construction is a list of :class:`Step` objects. Each step adds vectors
(:class:`Arrow`) and construction lines (:class:`Line`) to one of three
diagrams:

``linkage``
    the linkage drawn to scale [m]; its arrows are accelerations [m/s^2]
    placed at the point they act on and drawn at a scale chosen by the
    drawing (Figure 7-4a/d).
``velocity``
    the velocity polygon [m/s], drawn from its pole (the origin).
``acceleration``
    the acceleration polygon [m/s^2], drawn from its pole (Figure 7-4b).
``point``
    the polygon of a further point of a link once its alpha is known
    (A_P = A_A + A_PA, Figure 7-4c) [m/s^2].

Drawing "up to step k" shows everything added by steps 1..k, so a notebook
can walk through the method. ``values`` holds what is read off the finished
construction, in SI units (complex numbers for vectors).
"""

from dataclasses import dataclass, field

#: the kinds of vector the style distinguishes (see :mod:`.style`)
KINDS = ("normal", "tangential", "coriolis", "slip", "resultant", "velocity", "known")


@dataclass
class Arrow:
    """A vector drawn from ``start`` with components ``vector``.

    ``name`` is the chapter's symbol in matplotlib mathtext (e.g.
    ``r"\\mathbf{A}_{BA}^{t}"``); ``kind`` one of :data:`KINDS`.
    """

    name: str
    start: complex
    vector: complex
    kind: str
    diagram: str

    @property
    def tip(self):
        return self.start + self.vector


@dataclass
class Line:
    """A construction line (direction known, length unknown) through ``point``
    along ``direction``; ``name`` is its label in the chapter (pp, qq)."""

    name: str
    point: complex
    direction: complex
    diagram: str


@dataclass
class Step:
    """One step of the method. ``label`` is the chapter's step ("1".."8" as in
    Example 7-1) or a letter for the position ("P") and velocity ("V1"..)
    stages that the example assumes done; ``text`` says what is done."""

    label: str
    phase: str
    text: str
    arrows: list = field(default_factory=list)
    lines: list = field(default_factory=list)
    marks: dict = field(default_factory=dict)  # named points found: {diagram: {name: z}}


@dataclass
class Linkage:
    """The linkage drawn to scale: named points [m], the links as point-name
    sequences, ground pivots, and optional slide lines (point, direction)."""

    points: dict
    links: list
    ground: list
    slides: list = field(default_factory=list)
    blocks: list = field(default_factory=list)  # (point name, direction of its slide)
    rods: list = field(default_factory=list)  # (point, direction, t0, t1): a slide on a link


@dataclass
class Construction:
    """A finished graphical construction (see the module docstring)."""

    mechanism: str
    linkage: Linkage
    steps: list
    values: dict
    circuit: str | None = None
    title: str = ""
    units: str | None = None  # "US" or "SI": how the case gave its lengths (the drawings follow)

    def step(self, label, phase, text):
        s = Step(label, phase, text)
        self.steps.append(s)
        return s

    def index(self, step):
        """The number (1..N) of a step given as a number or as its label
        (``"6"`` is step 6 of Example 7-1, ``"V2"`` a velocity step)."""
        if isinstance(step, str):
            labels = [s.label for s in self.steps]
            if step not in labels:
                raise ValueError(f"no step {step!r}; the steps are {', '.join(labels)}")
            return labels.index(step) + 1
        return int(step)

    def items(self, diagram, upto=None):
        """Arrows and lines of ``diagram`` added by steps 1..``upto`` (a number,
        or a step label such as ``"6"``; all by default); returns
        ``(arrows, lines, marks)``."""
        n = len(self.steps) if upto is None else self.index(upto)
        if not 0 <= n <= len(self.steps):
            raise ValueError(f"step must be between 0 and {len(self.steps)} (got {upto})")
        arrows, lines, marks = [], [], {}
        for s in self.steps[:n]:
            arrows += [a for a in s.arrows if a.diagram == diagram]
            lines += [ln for ln in s.lines if ln.diagram == diagram]
            marks.update(s.marks.get(diagram, {}))
        return arrows, lines, marks

    def to_dict(self):
        """Values read off the construction, SI, vectors as [x, y]."""
        out = {}
        for k, v in self.values.items():
            out[k] = [v.real, v.imag] if isinstance(v, complex) else float(v)
        return out
