"""The unit-aware vector-loop linkage."""

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..errors import InvalidInput, NotAssemblable, Singular
from ..parameters import MOTION
from ..results import Kinematics
from ..status import NOT_ASSEMBLABLE, OK
from ..units import QuantityLike, SIValue, quantity, show, to_si
from .newton import DEFAULT_TOL
from .solve import solve, system_from_case


class VectorLoopLinkage:
    """A planar linkage of any number of loops (section 7.8).

    Parameters
    ----------
    vectors : dict
        Named vectors as in docs/conventions.md#vector-loop-format:
        ``{"R2": {"length": "2 in", "angle": "input"}, "R3": {"length": "6 in",
        "angle": "unknown", "guess": "90 deg"}, "S": {"length": "unknown",
        "guess": "7 in", "angle": "0 deg"}, "R5": {"length": "3 in", "angle":
        {"follow": "R3", "offset": "40 deg"}}, ...}``. The guesses choose the assembly.
    loops : list of str
        Each a signed sum of vector names that closes to zero.
    points : dict, optional
        Named points as signed sums of vectors from the origin.

    Examples
    --------
    >>> fourbar = VectorLoopLinkage(
    ...     vectors={"R1": {"length": "7 in", "angle": "0 deg"},
    ...              "R2": {"length": "2 in", "angle": "input"},
    ...              "R3": {"length": "6 in", "angle": "unknown", "guess": "90 deg"},
    ...              "R4": {"length": "9 in", "angle": "unknown", "guess": "130 deg"}},
    ...     loops=["R2 + R3 - R4 - R1"], points={"B": "R2 + R3"})
    >>> r = fourbar.solve(theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2")
    >>> r.vectors["R4"].alpha, r.points["B"].A
    """

    def __init__(
        self,
        vectors: Mapping[str, Any],
        loops: Sequence[str],
        points: Mapping[str, str] | None = None,
    ) -> None:
        self.description = {"vectors": vectors, "loops": loops, "points": points or {}}
        self.system = system_from_case(self.description)

    @classmethod
    def from_case(cls, case: Mapping[str, Any]) -> "VectorLoopLinkage":
        """The linkage of a ``loops`` case (docs/conventions.md#vector-loop-format)."""
        get: Any = case.get  # a part left out is refused by the reader, which says what to give
        return cls(get("vectors"), get("loops"), get("points"))

    def solve(
        self,
        theta2: QuantityLike,
        omega2: QuantityLike,
        alpha2: QuantityLike = 0,
        jerk2: QuantityLike = 0,
        order: int = 3,
        tol: float = DEFAULT_TOL,
    ) -> "LoopResult":
        """Solve at one input angle or along an array of them (one assembly).

        Parameters
        ----------
        theta2 : Quantity or str, scalar or 1-D array
            Input angle(s) [angle]. An array is a sweep: it follows the
            assembly the guesses pick, position after position.
        omega2, alpha2, jerk2 : Quantity or str
            Input angular velocity [rad/s], acceleration [rad/s^2] and jerk
            [rad/s^3] (scalars, or arrays shaped like theta2).
        order : int
            Highest derivative solved: 1 velocity, 2 acceleration, 3 jerk.
        tol : float
            Newton-Raphson's convergence tolerance, dimensionless (default
            1e-13, which converges to round-off). Newton stops at a position
            with a full step that moves no unknown by more than
            ``1e-8 * sqrt(tol / 1e-13)`` (radians, or lengths over the longest
            link), which it takes: the loop residual after it is of order that
            step squared, below ``tol`` times the longest link (it also stops
            where the residual is already round-off, as at a singular
            position). A looser ``tol`` (up to 1e-2) stops sooner; the
            positions are then accurate to about ``tol`` divided by the
            condition measure, and velocity to jerk, solved exactly at the
            positions found, inherit that error.

        A scalar theta2 that cannot be assembled or is singular raises
        NotAssemblable / Singular (a NoConvergence carries the residual);
        an array gives NaN and a ``valid`` mask there, and ``message`` says
        why. A sweep through a change point (a singular position where two
        assemblies meet, e.g. a fourbar with s + l = p + q) stays on the
        assembly with the orientation it followed and says so in ``notes``;
        a sweep that starts on a singular position reports that position
        ``singular`` and continues from the next one.
        """
        t2, w2, a2, j2 = (
            to_si(v, p.name, p.kind) for p, v in zip(MOTION, (theta2, omega2, alpha2, jerk2))
        )
        if isinstance(order, bool) or order not in (1, 2, 3):
            raise InvalidInput(
                f"order must be 1 (velocity), 2 (acceleration) or 3 (jerk), got {show(order)}",
                "order",
            )
        if np.ndim(t2) > 1:
            raise InvalidInput(
                "theta2 must be one angle or a 1-D array of angles (a sweep) "
                f"for a vector-loop linkage (got shape {np.shape(t2)})",
                "theta2",
            )
        N = np.size(t2)
        for name, v in (("omega2", w2), ("alpha2", a2), ("jerk2", j2)):
            if np.ndim(v) and np.shape(v) != (N,):
                raise InvalidInput(
                    f"{name} must be one value or an array shaped like theta2 "
                    f"({N} positions; got shape {np.shape(v)})",
                    name,
                )
        motion = solve(self.system, t2, w2, a2, j2, order, tol=tol)
        scalar = np.ndim(t2) == 0
        if scalar and motion.status[0] != OK:
            err = motion.message
            if not isinstance(err, Exception):
                cls = NotAssemblable if motion.status[0] == NOT_ASSEMBLABLE else Singular
                err = cls(str(err))
            raise err
        return LoopResult(self.system, motion, scalar)


class _Named:
    def __init__(self, values, kinds, scalar):
        self._values, self._kinds, self._scalar = values, kinds, scalar

    def __getattr__(self, name):
        if name.startswith("_") or name not in self._values:
            raise AttributeError(name)
        v = self._values[name]
        return quantity(v[0] if self._scalar else v, self._kinds[name])

    def __dir__(self):
        return list(self._values)

    def __repr__(self):
        return "<" + ", ".join(f"{k}={getattr(self, k):.5g~P}" for k in self._values) + ">"


_VECTOR_KINDS = {
    "angle": "angle",
    "omega": "angular_velocity",
    "alpha": "angular_acceleration",
    "jerk": "angular_jerk",
    "length": "length",
    "length_dot": "velocity",
    "length_ddot": "acceleration",
    "length_dddot": "jerk",
}
_POINT_KINDS = {"R": "length", "V": "velocity", "A": "acceleration", "J": "jerk"}


class LoopResult(Kinematics):
    """Solved vector-loop linkage: ``vectors[NAME]`` (angle, omega, alpha, jerk
    and, for sliders, length, length_dot, length_ddot, length_dddot) and
    ``points[NAME]`` (R, V, A, J as complex Quantities), with ``valid``,
    ``status``, ``condition`` and Newton ``iterations`` per position; for a
    sweep also ``message`` (why the first position that failed did, or what
    the sweep decided on its way) and ``notes`` (position index -> what the
    sweep decided there: where it passed a change point on its own assembly,
    or left a singular first position).

    In the common style of :mod:`accelab.solver.results`, ``r["R3.alpha"]`` is
    ``r.vectors["R3"].alpha`` and ``r["B.A"]`` is ``r.points["B"].A``.
    """

    def __init__(self, system: Any, motion: Any, scalar: bool) -> None:
        self._motion, self._scalar = motion, scalar
        self._status, self._condition = motion.status, motion.condition
        model = system.model
        m = motion
        order = len(m.dth)
        self._values = {}
        self.vectors = {}
        for v, name in enumerate(model.names):
            values = {"angle": m.theta[:, v]}
            for n, key in enumerate(("omega", "alpha", "jerk")[:order]):
                values[key] = m.dth[n][:, v]
            if model.length_unknown[v] >= 0:
                values["length"] = m.L[:, v]
                for n, key in enumerate(("length_dot", "length_ddot", "length_dddot")[:order]):
                    values[key] = m.dL[n][:, v]
            self.vectors[name] = _Named(values, _VECTOR_KINDS, scalar)
            self._values.update({f"{name}.{k}": (x, _VECTOR_KINDS[k]) for k, x in values.items()})
        self.points = {}
        for p, name in enumerate(model.point_names):
            values = {k: m.points[n][:, p] for n, k in enumerate("RVAJ"[: order + 1])}
            self.points[name] = _Named(values, _POINT_KINDS, scalar)
            self._values.update({f"{name}.{k}": (x, _POINT_KINDS[k]) for k, x in values.items()})

    def si(self, name: str) -> SIValue:
        if name not in self._values:
            raise KeyError(
                f"this linkage has no output {name!r}; its outputs are {', '.join(self._values)}"
            )
        v = self._values[name][0]
        return v[0] if self._scalar else v

    def kind(self, name: str) -> str:
        self.si(name)
        return self._values[name][1]

    def outputs(self) -> list[str]:
        """``VECTOR.angle`` ... and ``POINT.A`` ... for every vector and point."""
        return list(self._values)

    @property
    def iterations(self) -> Any:
        """Newton-Raphson's iterations at each position (an int, or an int array)."""
        return self._one(self._motion.iterations)

    @property
    def message(self) -> str | None:
        """Text: the first failed position's reason, else the sweep's notes,
        else the first singular position's (None when all is well)."""
        m = self._motion.message
        return None if m is None else str(m)

    @property
    def notes(self) -> dict[int, str]:
        """dict: position index -> what the sweep decided there."""
        return dict(self._motion.notes)
