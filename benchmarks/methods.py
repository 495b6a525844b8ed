"""The ways of computing the same kinematics that the benchmark compares.

Each :class:`Method` turns a case and its crank angles into a ``run``
callable (the work that is timed) and an ``extract`` callable (turns what
``run`` returned into SI arrays named like the case's outputs; not timed).
The work is always the same: the given crank angles, the case's input
motion, every output the method can give up to its ``order`` (3: position
to jerk; 2: position to acceleration).

Methods:

``kernels``
    the closed forms through the unit-free layer, vectorised over the cycle;
``units``
    the same through the unit-aware API (``accelab.solver.FourBar`` ...): Quantities
    in, the outputs read as Quantities;
``scalar``
    a Python loop calling the closed forms at one crank angle at a time;
``loops``
    the general vector-loop solver (``accelab.solver.VectorLoopLinkage``) on the
    case's loops, at each convergence tolerance it offers;
``fd-h``
    the closed-form position (order 0) differentiated by central finite
    differences of step h in theta2 (chain rule for the time derivatives);
``graphical``
    the step-by-step graphical construction (``accelab.solver.graphical``), one
    position at a time, to acceleration;
peers (:mod:`.peers`) when installed.
"""

import importlib
import inspect
import math

import numpy as np

from accelab.solver.registry import DRAWABLE

from .cases import MOTION

#: finite-difference steps in theta2 [rad]
FD_STEPS = (1e-2, 1e-3, 1e-4, 1e-5, 1e-6)
#: tolerances tried on the general solver, when it takes one
LOOP_TOLERANCES = (1e-4, 1e-6, 1e-8, 1e-10)

_UNIT_CLASSES = {
    "fourbar": "FourBar",
    "slidercrank": "SliderCrank",
    "invertedslidercrank": "InvertedSliderCrank",
    "fivebar": "GearedFiveBar",
}
_LOOP_ATTRS = {
    ("angle", 0): "angle",
    ("angle", 1): "omega",
    ("angle", 2): "alpha",
    ("angle", 3): "jerk",
    ("length", 0): "length",
    ("length", 1): "length_dot",
    ("length", 2): "length_ddot",
    ("length", 3): "length_dddot",
}


class NotApplicable(Exception):
    """The method cannot do this case's work."""


class Method:
    """One method at one setting.

    Attributes
    ----------
    key : str
        Unique name, e.g. ``fd-h1e-04``.
    label : str
        What the charts call it.
    family : str
        Methods of one family share a colour.
    order : int
        Highest derivative it gives (3 jerk, 2 acceleration).
    setting : float or None
        Its knob (finite-difference step [rad], tolerance), if any.
    vectorised : bool
        Whether one call does the whole cycle.
    """

    def __init__(self, key, label, family, order, prepare, setting=None, vectorised=True):
        self.key, self.label, self.family, self.order = key, label, family, order
        self._prepare, self.setting, self.vectorised = prepare, setting, vectorised

    def prepare(self, case, theta2):
        """``(run, extract)`` for this case; raises :class:`NotApplicable`."""
        return self._prepare(case, np.asarray(theta2, dtype=float))

    def describe(self):
        return {
            "key": self.key,
            "label": self.label,
            "family": self.family,
            "order": self.order,
            "setting": self.setting,
            "vectorised": self.vectorised,
        }


def _closed_form(case):
    if case.mechanism == "loops":
        raise NotApplicable(f"{case.name} has no closed form")


def _names(case, order):
    return [k for k, (_, _, n) in case.outputs.items() if n <= order]


# --- the closed forms ----------------------------------------------------------
def _kernels(case, theta2):
    _closed_form(case)
    names = _names(case, 3)

    def run():
        return case.kernel(theta2)

    def extract(m):
        return {k: np.asarray(getattr(m, k), dtype=float) for k in names}

    return run, extract


def _scalar(case, theta2):
    _closed_form(case)
    names = _names(case, 3)
    module = importlib.import_module(f"accelab.solver.kernels.{case.mechanism}")
    p, m = case.params, MOTION
    solve = module.solve
    angles = [float(t) for t in theta2]
    w, al, jk, circuit = m["omega2"], m["alpha2"], m["jerk2"], case.circuit

    def run():
        return [
            solve(**p, theta2=t, omega2=w, alpha2=al, jerk2=jk, circuit=circuit) for t in angles
        ]

    def extract(results):
        return {k: np.array([float(getattr(r, k)) for r in results]) for k in names}

    return run, extract


def unit_mechanism(case):
    """The unit-aware object of a closed-form case, geometry as Quantities."""
    from accelab import solver
    from accelab.solver.units import Q_

    _closed_form(case)
    cls = getattr(solver, _UNIT_CLASSES[case.mechanism])
    geometry = {}
    for k, v in case.params.items():
        if k == "lam":
            geometry[k] = v
        elif k in ("gamma", "phi"):
            geometry[k] = Q_(v, "rad")
        else:
            geometry[k] = Q_(v, "m")
    return cls(**geometry)


def unit_inputs(theta2):
    """The input motion as Quantities (built once, outside the timed work)."""
    from accelab.solver.units import Q_

    t = theta2 if np.ndim(theta2) else float(theta2)
    return {
        "theta2": Q_(t, "rad"),
        "omega2": Q_(MOTION["omega2"], "rad/s"),
        "alpha2": Q_(MOTION["alpha2"], "rad/s^2"),
        "jerk2": Q_(MOTION["jerk2"], "rad/s^3"),
    }


def _units(case, theta2):
    mech = unit_mechanism(case)
    names = _names(case, 3)
    inputs = unit_inputs(theta2)
    circuit = case.circuit

    def run():
        r = mech.solve(**inputs, circuit=circuit)
        return {k: getattr(r, k) for k in names}

    def extract(q):
        return {k: np.asarray(v.to_base_units().magnitude, dtype=float) for k, v in q.items()}

    return run, extract


# --- the general solver ----------------------------------------------------------
def loop_tolerance_parameter():
    """Name of the convergence-tolerance argument of
    :meth:`accelab.solver.VectorLoopLinkage.solve`, or None if it has none."""
    from accelab.solver import VectorLoopLinkage

    params = inspect.signature(VectorLoopLinkage.solve).parameters
    for name in ("tol", "tolerance", "xtol", "rtol"):
        if name in params:
            return name
    return None


def loop_default_tolerance():
    """The default of that argument (None if there is none)."""
    from accelab.solver import VectorLoopLinkage

    name = loop_tolerance_parameter()
    if name is None:
        return None
    default = inspect.signature(VectorLoopLinkage.solve).parameters[name].default
    return float(default) if isinstance(default, (int, float)) else None


def loop_linkage(case):
    from accelab.solver import VectorLoopLinkage

    from .cases import description

    return VectorLoopLinkage(**description(case))


def _loops_with(tol):
    def prepare(case, theta2):
        from accelab.solver.units import Q_

        linkage = loop_linkage(case)
        names = _names(case, 3)
        inputs = unit_inputs(theta2)
        inputs["theta2"] = Q_(np.atleast_1d(theta2), "rad")
        kw = {}
        if tol is not None:
            kw[loop_tolerance_parameter()] = tol

        def run():
            return linkage.solve(**inputs, **kw)

        def extract(r):
            out = {}
            for k in names:
                vec, kind, n = case.outputs[k]
                q = getattr(r.vectors[vec], _LOOP_ATTRS[(kind, n)])
                v = np.asarray(q.to_base_units().magnitude, dtype=float)
                if kind == "angle" and n == 0:
                    v = np.angle(np.exp(1j * v))
                out[k] = v
            return out

        return run, extract

    return prepare


# --- finite differences of the position ----------------------------------------------
def fd_with(h):
    def prepare(case, theta2):
        _closed_form(case)
        groups = {}
        for k, (vec, kind, n) in case.outputs.items():
            groups.setdefault((vec, kind), {})[n] = k
        groups = {g: v for g, v in groups.items() if 0 in v}
        module = importlib.import_module(f"accelab.solver.kernels.{case.mechanism}")
        N = theta2.size
        stencil = (theta2[None, :] + h * np.arange(-2, 3)[:, None]).ravel()
        w, al, jk = MOTION["omega2"], MOTION["alpha2"], MOTION["jerk2"]
        p = case.params

        def run():
            m = module.solve(**p, theta2=stencil, omega2=0.0, circuit=case.circuit, order=0)
            out = {}
            for (_vec, kind), names in groups.items():
                f = np.asarray(getattr(m, names[0]), dtype=float).reshape(5, N)
                if kind == "angle":  # differences of angles, unwrapped about the centre
                    f = f[2] + np.angle(np.exp(1j * (f - f[2])))
                d1 = (f[3] - f[1]) / (2 * h)
                d2 = (f[3] - 2 * f[2] + f[1]) / (h * h)
                d3 = (f[4] - 2 * f[3] + 2 * f[1] - f[0]) / (2 * h**3)
                out[names[0]] = _wrap(f[2]) if kind == "angle" else f[2]
                # chain rule: x(theta2(t))
                derivs = {
                    1: d1 * w,
                    2: d2 * w * w + d1 * al,
                    3: d3 * w**3 + 3 * d2 * w * al + d1 * jk,
                }
                for n, name in names.items():
                    if n:
                        out[name] = derivs[n]
            return out

        return run, lambda out: out

    return prepare


def _wrap(x):
    return np.angle(np.exp(1j * x))


# --- the graphical construction ---------------------------------------------------
#: the mechanisms with a graphical construction (the registry says which)
GRAPHICAL = DRAWABLE


def _graphical(case, theta2):
    from accelab.solver.graphical import construct

    if case.mechanism not in GRAPHICAL:
        raise NotApplicable(f"{case.name} has no graphical construction")
    names = _names(case, 2)
    p, m = case.params, MOTION
    angles = [float(t) for t in theta2]

    def run():
        out = []
        for t in angles:
            try:
                out.append(
                    construct(
                        case.mechanism,
                        case.circuit,
                        **p,
                        theta2=t,
                        omega2=m["omega2"],
                        alpha2=m["alpha2"],
                    ).values
                )
            except Exception:  # noqa: BLE001 - a construction that fails reports nothing there
                out.append({})
        return out

    def extract(values):
        return {k: np.array([float(np.real(v.get(k, np.nan))) for v in values]) for k in names}

    return run, extract


def methods(include_peers=True):
    """Every method at every setting, in the order the tables list them."""
    out = [
        Method("kernels", "closed forms, unit-free (vectorised)", "kernels", 3, _kernels),
        Method("units", "closed forms, unit-aware API", "units", 3, _units),
        Method(
            "scalar", "closed forms, scalar Python loop", "scalar", 3, _scalar, vectorised=False
        ),
    ]
    default = loop_default_tolerance()
    out.append(
        Method(
            "loops",
            "vector loops"
            + (f" (default tol {default:.0e})" if default else " (default tolerance)"),
            "loops",
            3,
            _loops_with(None),
            setting=default,
            vectorised=False,
        )
    )
    if loop_tolerance_parameter():
        for tol in LOOP_TOLERANCES:
            if default is None or not math.isclose(tol, default):
                out.append(
                    Method(
                        f"loops-tol{tol:.0e}",
                        f"vector loops, tol {tol:.0e}",
                        "loops",
                        3,
                        _loops_with(tol),
                        setting=tol,
                        vectorised=False,
                    )
                )
    for h in FD_STEPS:
        out.append(
            Method(
                f"fd-h{h:.0e}",
                f"finite differences, h = {h:.0e} rad",
                "fd",
                3,
                fd_with(h),
                setting=h,
            )
        )
    out.append(
        Method("graphical", "graphical construction", "graphical", 2, _graphical, vectorised=False)
    )
    if include_peers:
        from .peers import peer_methods

        out += peer_methods(Method, NotApplicable)
    return out
