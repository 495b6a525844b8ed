"""How a mechanism declares what it takes: :class:`Parameter`, :class:`Declaration`.

Every parameter is declared once, in the mechanism's entry of the registry
(:mod:`accelab.solver.registry`), with its kind of quantity (a key of
:data:`accelab.solver.units.KINDS`), whether it must be given, whether it must be
positive, its default and what it means. The unit-aware classes
(:mod:`accelab.solver.mechanisms`), the batch format and the command line
(:mod:`accelab.solver.cases`) read these declarations, and so can the exercise
generators: a parameter added there is taken, checked and listed everywhere.

Defaults, one policy for the Python API, the batch and the command line: a
parameter with a default may be left out and then means that default (SI):

* ``alpha2`` and ``jerk2``: 0 (the crank turns at a steady speed);
* ``theta1``: 0 (the ground line, or slide axis, along +x);
* the slider-crank's offset ``c``: 0; the coupler point's angle ``delta3``:
  0 (P on the line AB).

Everything else (the link lengths, ``theta2``, ``omega2``, the inverted
slider-crank's ``gamma``, the fivebar's ``lam`` and ``phi``) must be given.
"""

from typing import Any, NamedTuple

__all__ = ["Parameter", "Declaration", "MOTION", "THETA1", "OPEN_CROSSED", "length", "angle"]


class Parameter(NamedTuple):
    """One parameter: ``kind`` of quantity, ``required``, ``positive`` (a link
    length, > 0), ``default`` in SI (None: no default), and its ``meaning``."""

    name: str
    kind: str
    required: bool
    positive: bool
    default: Any
    meaning: str


class Declaration(NamedTuple):
    """A mechanism's parameters: ``geometry`` (the constructor's), ``point``
    (extra arguments of ``solve``: the coupler point, or the slotted link's
    block) and its ``circuits`` (empty: it has one assembly)."""

    geometry: tuple[Parameter, ...]
    point: tuple[Parameter, ...]
    circuits: tuple[str, ...]

    def every(self) -> tuple[Parameter, ...]:
        """Geometry, point and motion parameters, in that order."""
        return self.geometry + self.point + MOTION

    def names(self) -> list[str]:
        """The names of :meth:`every` parameter."""
        return [p.name for p in self.every()]


def length(
    name: str,
    meaning: str,
    positive: bool = True,
    required: bool = True,
    default: float | None = None,
) -> Parameter:
    """A length parameter [m]: positive (a link's length) and required unless told."""
    return Parameter(name, "length", required, positive, default, meaning)


def angle(
    name: str, meaning: str, required: bool = True, default: float | None = None
) -> Parameter:
    """An angle parameter [rad], required unless told."""
    return Parameter(name, "angle", required, False, default, meaning)


THETA1 = angle(
    "theta1", "angle of the ground line O2->O4 (slide axis) [angle]", required=False, default=0.0
)

#: the input motion every mechanism takes (theta2 from the global x axis)
MOTION = (
    angle("theta2", "input (crank) angle from the x axis [angle]"),
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
