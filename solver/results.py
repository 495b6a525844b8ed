"""What every result of the package offers: one protocol, two result types.

:class:`~accelab.solver.mechanisms.Result` (the closed-form mechanisms) and
:class:`~accelab.solver.vectorloops.LoopResult` (any linkage as vector loops) share
this protocol (:class:`Kinematics`):

* ``result[name]`` -- an output as a pint Quantity (SI units of the
  package's registry); ``result.si(name)`` -- the same as plain SI floats;
* ``result.outputs()`` -- the names it can give;
* ``result.valid``, ``result.status``, ``result.condition`` -- per position
  (a bool / str / float for one position, arrays for a sweep);
* ``result.to_dict()`` -- every output as plain Python (vectors as [x, y]).

Each type also has its own reading style, as the chapter names things: the
mechanisms' outputs as attributes (``r.alpha3``, ``r.A_BA``), the vector
loops' per vector and point (``r.vectors["R3"].alpha``, ``r.points["B"].A``;
``r["R3.alpha"]``, ``r["B.A"]`` in the common style).
"""

import math
from collections.abc import Iterable
from typing import Any, cast

import numpy as np
import pint

from .errors import InvalidInput, error_object
from .status import OK, STATUS_NAMES
from .units import SIValue, quantity

__all__ = ["Kinematics", "as_plain", "finite_or_refused"]


class Kinematics:
    """The common protocol of results (see the module docstring).

    Subclasses set ``_status`` (int8 per position), ``_condition`` and
    ``_scalar``, and implement :meth:`si`, :meth:`kind` and :meth:`outputs`.
    """

    _scalar: bool = True
    _status: Any  # int8, or an int8 array: one status per position
    _condition: Any  # float, or a float array

    def si(self, name: str) -> SIValue:
        """The SI value (float, complex, or array) of an output, unit-free."""
        raise NotImplementedError

    def kind(self, name: str) -> str:
        """The kind of quantity (a key of :data:`accelab.solver.units.KINDS`) of an output."""
        raise NotImplementedError

    def outputs(self) -> list[str]:
        """The names of the outputs this result gives."""
        raise NotImplementedError

    def __getitem__(self, name: str) -> pint.Quantity:
        return quantity(self.si(name), self.kind(name))

    def _one(self, x: Any) -> Any:
        x = np.asarray(x)
        return x[()] if self._scalar and x.ndim == 0 else (x[0] if self._scalar else x)

    @property
    def valid(self) -> bool | np.ndarray:
        """True where the result can be vouched for (bool or bool array)."""
        v = np.asarray(self._status) == OK
        return bool(self._one(v)) if self._scalar else v

    @property
    def status(self) -> str | np.ndarray:
        """'ok', 'not_assemblable' or 'singular' (a str, or an array of str)."""
        s = np.vectorize(STATUS_NAMES.get, otypes=[object])(np.asarray(self._status))
        return str(self._one(s)) if self._scalar else s

    @property
    def condition(self) -> float | np.ndarray:
        """Dimensionless condition measure (1 best, 0 at a singular position)."""
        c = self._condition
        return float(self._one(c)) if self._scalar else np.asarray(c)

    def to_dict(self, names: Iterable[str] | None = None) -> dict[str, Any]:
        """SI values as plain Python (vectors as [x, y]; arrays as lists)."""
        return {name: as_plain(self.si(name)) for name in (names or self.outputs())}


def as_plain(v: SIValue) -> Any:
    """An SI value as plain Python: a float, [x, y] for a complex vector, or
    (nested) lists for arrays."""
    if np.iscomplexobj(v):
        z = np.asarray(v)
        return np.stack([z.real, z.imag], axis=-1).tolist()
    if isinstance(v, np.ndarray):
        return v.tolist()
    return float(cast(float, v))


def finite_or_refused(answer: dict[str, Any]) -> dict[str, Any]:
    """A batch answer if every number in it is finite, else the error object
    that names the output that overflowed: the batch output is strict JSON
    (no NaN or Infinity) and never holds a number the solver cannot vouch for."""
    where = _non_finite(answer)
    if where is None:
        return answer
    return error_object(
        InvalidInput(
            f"the output {where} overflows a float: the inputs are too large for float64 to hold "
            f"the result; give smaller lengths or speeds (in other units if need be)",
            where,
        )
    )


def _non_finite(value: Any, path: str = "") -> str | None:
    """The path of the first non-finite number in a (nested) answer, or None."""
    if isinstance(value, dict):
        for k, v in value.items():
            found = _non_finite(v, f"{path}.{k}" if path else str(k))
            if found is not None:
                return found
    elif isinstance(value, (list, tuple)):
        for v in value:
            found = _non_finite(v, path)
            if found is not None:
                return found
    elif isinstance(value, float) and not math.isfinite(value):
        return path
    return None
