"""What each mechanism takes, declared once.

Every parameter is declared here with its kind of quantity (a key of
:data:`accelab.solver.units.KINDS`), whether it must be given, whether it must be
positive, its default and what it means. The unit-aware classes
(:mod:`accelab.solver.mechanisms`), the batch format and the command line
(:mod:`accelab.solver.cases`) read these declarations, and so can the exercise
generators: a parameter added here is taken, checked and listed everywhere.

Defaults, one policy for the Python API, the batch and the command line: a
parameter with a default may be left out and then means that default (SI):

* ``alpha2`` and ``jerk2``: 0 (the crank turns at a steady speed);
* ``theta1``: 0 (the ground line, or slide axis, along +x);
* the slider-crank's offset ``c``: 0; the coupler point's angle ``delta3``:
  0 (P on the line AB).

Everything else (the link lengths, ``theta2``, ``omega2``, the inverted
slider-crank's ``gamma``, the fivebar's ``lam`` and ``phi``) must be given.
"""

from typing import NamedTuple

__all__ = ["Parameter", "Declaration", "MOTION", "PARAMETERS", "BATCH_MECHANISMS"]


class Parameter(NamedTuple):
    """One parameter: ``kind`` of quantity, ``required``, ``positive`` (a link
    length, > 0), ``default`` in SI (None: no default), and its ``meaning``."""

    name: str
    kind: str
    required: bool
    positive: bool
    default: object
    meaning: str


class Declaration(NamedTuple):
    """A mechanism's parameters: ``geometry`` (the constructor's), ``point``
    (extra arguments of ``solve``: the coupler point, or the slotted link's
    block) and its ``circuits`` (empty: it has one assembly)."""

    geometry: tuple
    point: tuple
    circuits: tuple

    def every(self):
        """Geometry, point and motion parameters, in that order."""
        return self.geometry + self.point + MOTION

    def names(self):
        return [p.name for p in self.every()]


def _length(name, meaning, positive=True, required=True, default=None):
    return Parameter(name, "length", required, positive, default, meaning)


def _angle(name, meaning, required=True, default=None):
    return Parameter(name, "angle", required, False, default, meaning)


THETA1 = _angle(
    "theta1", "angle of the ground line O2->O4 (slide axis) [angle]", required=False, default=0.0
)

#: the input motion every mechanism takes (theta2 from the global x axis)
MOTION = (
    _angle("theta2", "input (crank) angle from the x axis [angle]"),
    Parameter("omega2", "angular_velocity", True, False, None, "input angular velocity"),
    Parameter(
        "alpha2",
        "angular_acceleration",
        False,
        False,
        0.0,
        "input angular acceleration (default 0)",
    ),
    Parameter("jerk2", "angular_jerk", False, False, 0.0, "input angular jerk (default 0)"),
)

OPEN_CROSSED = ("open", "crossed")

PARAMETERS = {
    "fourbar": Declaration(
        (
            _length("a", "crank O2A"),
            _length("b", "coupler AB"),
            _length("c", "rocker O4B"),
            _length("d", "ground O2O4"),
            THETA1,
        ),
        (
            _length("p", "coupler point P: distance from A", required=False),
            _angle("delta3", "coupler point P: angle from line AB", required=False, default=0.0),
        ),
        OPEN_CROSSED,
    ),
    "slidercrank": Declaration(
        (
            _length("a", "crank O2A"),
            _length("b", "connecting rod AB"),
            _length("c", "slider offset (signed)", positive=False, required=False, default=0.0),
            THETA1,
        ),
        (),
        OPEN_CROSSED,
    ),
    "invertedslidercrank": Declaration(
        (
            _length("a", "crank O2A"),
            _length("c", "O4B, >= 0 (0: slide line through O4)", positive=False),
            _length("d", "ground O2O4"),
            _angle("gamma", "angle from O4B to the slide line"),
            THETA1,
        ),
        (),
        OPEN_CROSSED,
    ),
    "fivebar": Declaration(
        (
            _length("a", "crank O2A"),
            _length("b", "coupler AB"),
            _length("c", "coupler CB"),
            _length("d", "crank O5C"),
            _length("f", "ground O2O5"),
            Parameter(
                "lam",
                "dimensionless",
                True,
                False,
                None,
                "gear ratio theta5/theta2 (signed, a plain number)",
            ),
            _angle("phi", "phase of link 5: theta5 = lam theta2 + phi"),
            THETA1,
        ),
        (),
        OPEN_CROSSED,
    ),
    "rotation": Declaration((_length("p", "radius of the point"),), (), ()),
    "slotted": Declaration(
        (),
        (
            _length("p", "distance of the block from the pivot", positive=False),
            Parameter("p_dot", "velocity", True, False, None, "slip velocity"),
            Parameter("p_ddot", "acceleration", False, False, 0.0, "slip acceleration"),
            Parameter("p_dddot", "jerk", False, False, 0.0, "slip jerk"),
        ),
        (),
    ),
}

#: the mechanisms of the batch format (docs/conventions.md#batch-format), besides "loops"
BATCH_MECHANISMS = ("fourbar", "slidercrank", "invertedslidercrank", "fivebar", "rotation")
