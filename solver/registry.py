"""Every closed-form mechanism of the package, registered once.

One entry per mechanism says what it is called, what it takes, which class solves it,
which construction draws it and how its links are labelled. Everything that lists
mechanisms reads this registry instead of keeping its own list: the batch format and
``accelab solve`` (:mod:`accelab.solver.cases`), the unit-aware classes
(:data:`accelab.solver.MECHANISMS`), the graphical constructions and their drawings
(:mod:`accelab.solver.graphical`), the documentation and the tests. Adding a
mechanism (CONTRIBUTING.md, "Add a mechanism") is one :class:`Registered` entry in
:data:`REGISTRY` besides its kernel, its class and its tests.

The classes and constructions are named as ``"module:attribute"`` and imported when
asked for (:func:`mechanism_class`, :func:`construction`), so that this module imports
neither layer: the graphical constructions read it without importing the analytic
solvers, as the layer rule wants (tests/test_layers.py).
"""

import importlib
from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

from .parameters import OPEN_CROSSED, THETA1, Declaration, Parameter, angle, length

__all__ = [
    "Registered",
    "REGISTRY",
    "PARAMETERS",
    "BATCH_MECHANISMS",
    "DRAWABLE",
    "mechanism_class",
    "construction",
    "link_symbols",
]


class Registered(NamedTuple):
    """One mechanism of the package.

    ``name``: its name in the batch format, on the command line and in
    :data:`accelab.solver.MECHANISMS`; ``parameters``: what it takes
    (:class:`accelab.solver.parameters.Declaration`); ``mechanism``: its unit-aware
    class, ``"module:Class"`` in :mod:`accelab.solver.mechanisms`; ``construction``:
    the function in :mod:`accelab.solver.graphical` that draws its polygons,
    ``"module:function"`` taking the case's SI parameters as keywords (None: not
    drawn); ``batch``: whether the batch format and ``accelab solve`` take it;
    ``links``: the chapter's symbol of each link a schematic labels, keyed by the
    link's two pins; ``example``: parameters and motion (text with units, as a case of
    the batch format gives them) of one position it solves, which the tests solve at
    every order and check against finite differences (tests/test_registry.py).
    """

    name: str
    parameters: Declaration
    mechanism: str
    construction: str | None = None
    batch: bool = True
    links: Mapping[tuple[str, str], str] = {}
    example: Mapping[str, Any] = {}


# every mechanism, in the order the batch format, the command line and the docs list them
# (a comment, not a doc comment: the API pages would print the whole dict)
REGISTRY: dict[str, Registered] = {
    entry.name: entry
    for entry in (
        Registered(
            "fourbar",
            Declaration(
                (
                    length("a", "crank O2A"),
                    length("b", "coupler AB"),
                    length("c", "rocker O4B"),
                    length("d", "ground O2O4"),
                    THETA1,
                ),
                (
                    length("p", "coupler point P: distance from A", required=False),
                    angle(
                        "delta3", "coupler point P: angle from line AB", required=False, default=0.0
                    ),
                ),
                OPEN_CROSSED,
            ),
            mechanism="fourbar:FourBar",
            construction="fourbar:construct",
            links={
                ("O2", "A"): "a",
                ("A", "B"): "b",
                ("O4", "B"): "c",
                ("O2", "O4"): "d",
                ("A", "P"): "p",
            },
            example={
                "a": "2 in",
                "b": "6 in",
                "c": "9 in",
                "d": "7 in",
                "p": "3 in",
                "delta3": "20 deg",
                "theta2": "30 deg",
                "omega2": "10 rad/s",
                "alpha2": "-5 rad/s^2",
            },
        ),
        Registered(
            "slidercrank",
            Declaration(
                (
                    length("a", "crank O2A"),
                    length("b", "connecting rod AB"),
                    length(
                        "c", "slider offset (signed)", positive=False, required=False, default=0.0
                    ),
                    THETA1,
                ),
                (),
                OPEN_CROSSED,
            ),
            mechanism="slidercrank:SliderCrank",
            construction="slidercrank:construct",
            links={("O2", "A"): "a", ("A", "B"): "b"},
            example={
                "a": "40 mm",
                "b": "120 mm",
                "c": "10 mm",
                "theta2": "60 deg",
                "omega2": "3000 rpm",
            },
        ),
        Registered(
            "invertedslidercrank",
            Declaration(
                (
                    length("a", "crank O2A"),
                    length("c", "O4B, >= 0 (0: slide line through O4)", positive=False),
                    length("d", "ground O2O4"),
                    angle("gamma", "angle from O4B to the slide line"),
                    THETA1,
                ),
                (),
                OPEN_CROSSED,
            ),
            mechanism="invertedslidercrank:InvertedSliderCrank",
            construction="invertedslidercrank:construct",
            links={("O2", "A"): "a", ("O4", "B"): "c", ("O2", "O4"): "d"},
            example={
                "a": "40 mm",
                "c": "50 mm",
                "d": "100 mm",
                "gamma": "30 deg",
                "theta2": "60 deg",
                "omega2": "30 rad/s",
                "alpha2": "-40 rad/s^2",
            },
        ),
        Registered(
            "fivebar",
            Declaration(
                (
                    length("a", "crank O2A"),
                    length("b", "coupler AB"),
                    length("c", "coupler CB"),
                    length("d", "crank O5C"),
                    length("f", "ground O2O5"),
                    Parameter(
                        "lam",
                        "dimensionless",
                        True,
                        False,
                        None,
                        "gear ratio theta5/theta2 (signed, a plain number)",
                    ),
                    angle("phi", "phase of link 5: theta5 = lam theta2 + phi"),
                    THETA1,
                ),
                (),
                OPEN_CROSSED,
            ),
            mechanism="fivebar:GearedFiveBar",
            construction="fivebar:construct",
            links={
                ("O2", "A"): "a",
                ("A", "B"): "b",
                ("C", "B"): "c",
                ("O5", "C"): "d",
                ("O2", "O5"): "f",
            },
            example={
                "a": "2 in",
                "b": "6 in",
                "c": "7 in",
                "d": "3 in",
                "f": "5 in",
                "lam": -1,
                "phi": "30 deg",
                "theta2": "60 deg",
                "omega2": "10 rad/s",
                "alpha2": "5 rad/s^2",
            },
        ),
        Registered(
            "rotation",
            Declaration((length("p", "radius of the point"),), (), ()),
            mechanism="rotation:RotatingPoint",
            construction="slotted:rotating_point",
            links={("O2", "P"): "p"},
            example={
                "p": "4 in",
                "theta2": "30 deg",
                "omega2": "-20 rad/s",
                "alpha2": "15 rad/s^2",
            },
        ),
        Registered(
            "slotted",
            Declaration(
                (),
                (
                    length("p", "distance of the block from the pivot", positive=False),
                    Parameter("p_dot", "velocity", True, False, None, "slip velocity"),
                    Parameter("p_ddot", "acceleration", False, False, 0.0, "slip acceleration"),
                    Parameter("p_dddot", "jerk", False, False, 0.0, "slip jerk"),
                ),
                (),
            ),
            mechanism="rotation:SlottedLink",
            construction="slotted:construct",
            batch=False,  # the block's rates are a second input motion: the Python API only
            example={
                "theta2": "40 deg",
                "omega2": "10 rad/s",
                "alpha2": "-50 rad/s^2",
                "p": "80 mm",
                "p_dot": "0.5 m/s",
                "p_ddot": "3 m/s^2",
            },
        ),
    )
}

# what each mechanism takes (name -> Declaration)
PARAMETERS: dict[str, Declaration] = {name: e.parameters for name, e in REGISTRY.items()}
#: the mechanisms of the batch format (docs/conventions.md#batch-format), besides "loops"
BATCH_MECHANISMS: tuple[str, ...] = tuple(n for n, e in REGISTRY.items() if e.batch)
#: the batch mechanisms that have a graphical construction
DRAWABLE: tuple[str, ...] = tuple(
    n for n, e in REGISTRY.items() if e.batch and e.construction is not None
)


def _load(package: str, spec: str) -> Any:
    module, _, attribute = spec.partition(":")
    return getattr(importlib.import_module(f"{package}.{module}"), attribute)


def mechanism_class(name: str) -> type:
    """The unit-aware class of the mechanism ``name`` (``FourBar`` for "fourbar")."""
    return _load("accelab.solver.mechanisms", REGISTRY[name].mechanism)


def construction(name: str) -> Callable[..., Any] | None:
    """The graphical construction of the mechanism ``name`` (a function of its SI
    parameters as keywords that returns a Construction), or None."""
    spec = REGISTRY[name].construction if name in REGISTRY else None
    return None if spec is None else _load("accelab.solver.graphical", spec)


def link_symbols(name: str) -> Mapping[tuple[str, str], str]:
    """The chapter's symbol of each link of ``name`` (pins -> symbol), {} if none."""
    entry = REGISTRY.get(name)
    return entry.links if entry is not None else {}
