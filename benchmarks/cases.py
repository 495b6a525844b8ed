"""The benchmark's fixed, documented set of linkages.

Every case is given twice, in SI floats: as the parameters of its closed-form
kernel (where it has one) and as named vectors and loops (section 7.8), which
the general solver and the high-precision reference both read. The motion of
the input is the same everywhere: omega2 = 10 rad/s, alpha2 = -5 rad/s^2,
jerk2 = 20 rad/s^3 (non-zero, so that every term of the jerk equations counts).

=====================  ==========================================  ===============
case                   linkage                                     crank range
=====================  ==========================================  ===============
fourbar-open           Grashof crank-rocker a, b, c, d = 2, 6, 9,  full turn
                       7 in (the README's fourbar), open circuit
fourbar-crossed        the same, crossed circuit                   full turn
fourbar-nongrashof-    triple rocker a, b, c, d = 5, 4, 6, 3.5 in  between its two
open / -crossed        (s + l = 9.5 > p + q = 9), both circuits    toggles, 1 deg in
slidercrank            offset slider-crank a = 40 mm, b = 120 mm,  full turn
                       offset c = 10 mm, open
invertedslidercrank    a = 4 in, c = 3 in, d = 8 in, gamma = 90    full turn
                       deg, open
fivebar                geared fivebar a, b, c, d, f = 1, 4, 4, 1,  full turn
                       3 in, lam = -2, phi = 30 deg, open
sixbar-watt2           the Watt II sixbar of                       full turn
                       ``accelab.solver.vectorloops.examples`` (2 loops)
sixbar-slider          the sixbar driving a slider of the          full turn
                       examples (2 loops, one unknown length)
eightbar               the Watt II sixbar with a third fourbar     full turn
                       driven by its output rocker (3 loops)
=====================  ==========================================  ===============

The non-Grashof fourbar's crank swings between two toggle positions (links 3
and 4 folded, |O4 - A| = c - b); its benchmark cycle stops 1 degree short of
each, and the stability study (:mod:`.stability`) goes the rest of the way.
"""

import math
from dataclasses import dataclass, field

import numpy as np

IN = 0.0254  # [m] per inch
DEG = math.pi / 180.0  # [rad] per degree
MOTION = {"omega2": 10.0, "alpha2": -5.0, "jerk2": 20.0}  # [rad/s, rad/s^2, rad/s^3]
CYCLE_MARGIN = 1.0 * DEG  # [rad] kept from a toggle position by the benchmark cycle

#: the kernel outputs of each mechanism, and where the loop description holds
#: them: name -> (vector, "angle" | "length", derivative order)
KERNEL_OUTPUTS = {
    "fourbar": {
        f"{q}{k}": (f"R{k}", "angle", n)
        for k in (3, 4)
        for n, q in enumerate(("theta", "omega", "alpha", "jerk"))
    },
    "fivebar": {
        f"{q}{k}": (f"R{k}", "angle", n)
        for k in (3, 4)
        for n, q in enumerate(("theta", "omega", "alpha", "jerk"))
    },
    "slidercrank": dict(
        [(f"{q}3", ("R3", "angle", n)) for n, q in enumerate(("theta", "omega", "alpha", "jerk"))]
        + [(f"d{s}", ("R1", "length", n)) for n, s in enumerate(("", "_dot", "_ddot", "_dddot"))]
    ),
    "invertedslidercrank": dict(
        [
            (f"{q}{k}", (f"R{k}", "angle", n))
            for k in (3, 4)
            for n, q in enumerate(("theta", "omega", "alpha", "jerk"))
        ]
        + [(f"b{s}", ("R3", "length", n)) for n, s in enumerate(("", "_dot", "_ddot", "_dddot"))]
    ),
}
ORDER_WORDS = ("position", "velocity", "acceleration", "jerk")


@dataclass
class Case:
    """One linkage of the benchmark.

    Attributes
    ----------
    name, title : str
    mechanism : str
        Kernel module name (``fourbar`` ...) or ``loops`` (no closed form).
    params : dict
        Kernel geometry [m, rad, -] (empty for ``loops``).
    circuit : str
    vectors : dict
        Named vectors in SI: ``{"length": float | "unknown", "angle": float |
        "input" | "unknown" | {"follow": NAME, "ratio": k, "offset": rad}}``.
    loops : list of str
        Signed sums of vector names that close to zero.
    guess : dict
        Guesses [rad or m] for the unknowns at the first crank angle of the
        cycle; for closed-form cases they come from the kernel.
    outputs : dict
        Output name -> (vector, "angle" | "length", order).
    span : (float, float)
        First and last crank angle of the benchmark cycle [rad].
    full_turn : bool
        True when the crank turns fully (the cycle then omits the end point).
    limits : list of float
        Crank angles of the toggle (limit) positions [rad], if any.
    """

    name: str
    title: str
    mechanism: str
    params: dict
    circuit: str
    vectors: dict
    loops: list
    outputs: dict = field(default_factory=dict)
    guess: dict = field(default_factory=dict)
    span: tuple = (0.0, 2.0 * math.pi)
    full_turn: bool = True
    limits: list = field(default_factory=list)

    def theta2(self, n):
        """``n`` crank angles over the benchmark cycle [rad]."""
        lo, hi = self.span
        return np.linspace(lo, hi, n, endpoint=not self.full_turn)

    def kernel(self, theta2, order=3, **motion):
        """Solve with the closed-form kernel (unit-free); returns a Motion."""
        import importlib

        module = importlib.import_module(f"accelab.solver.kernels.{self.mechanism}")
        m = dict(MOTION, **motion)
        return module.solve(
            **self.params,
            theta2=theta2,
            omega2=m["omega2"],
            alpha2=m["alpha2"],
            jerk2=m["jerk2"],
            circuit=self.circuit,
            order=order,
        )

    def kernel_guess(self, theta2):
        """Unknowns [rad or m] of the loop description at one crank angle,
        read off the closed-form position (this picks the circuit)."""
        m = self.kernel(np.asarray(float(theta2)), order=0)
        guess = {}
        for name, (vec, kind, n) in self.outputs.items():
            if n == 0 and self.vectors[vec].get(kind) == "unknown":
                guess[vec] = float(getattr(m, name))
        return guess

    def distance_to_limit(self, theta2):
        """Distance [rad] from each crank angle to the nearest toggle position."""
        theta2 = np.asarray(theta2, dtype=float)
        if not self.limits:
            return np.full(theta2.shape, np.inf)
        d = [np.abs(np.angle(np.exp(1j * (theta2 - t)))) for t in self.limits]
        return np.min(d, axis=0)


def _fourbar_vectors(a, b, c, d):
    return (
        {
            "R1": {"length": d, "angle": 0.0},
            "R2": {"length": a, "angle": "input"},
            "R3": {"length": b, "angle": "unknown"},
            "R4": {"length": c, "angle": "unknown"},
        },
        ["R2 + R3 - R4 - R1"],
    )


def _fourbar(name, title, a, b, c, d, circuit):
    vectors, loops = _fourbar_vectors(a, b, c, d)
    case = Case(
        name,
        title,
        "fourbar",
        dict(a=a, b=b, c=c, d=d),
        circuit,
        vectors,
        loops,
        KERNEL_OUTPUTS["fourbar"],
    )
    # toggle positions: |O4 - A| = |b - c| or b + c (law of cosines in theta2)
    for s in (abs(b - c), b + c):
        cos_t = (a * a + d * d - s * s) / (2.0 * a * d)
        if -1.0 < cos_t < 1.0:
            t = math.acos(cos_t)
            case.limits += [t, 2.0 * math.pi - t]
    if case.limits:
        t = min(case.limits)
        case.span = (t + CYCLE_MARGIN, 2.0 * math.pi - t - CYCLE_MARGIN)
        case.full_turn = False
    return case


def _si(text, kind):
    from accelab.solver.units import Q_

    return Q_(text).m_as("m" if kind == "length" else "rad")


def from_example(name, title, desc):
    """A loops case from a description of :mod:`accelab.solver.vectorloops.examples`
    (quantity strings) converted to SI, its guesses included."""
    vectors, guess = {}, {}
    for vname, v in desc["vectors"].items():
        out = {}
        length, angle = v["length"], v["angle"]
        out["length"] = "unknown" if length == "unknown" else _si(length, "length")
        if isinstance(angle, dict):
            out["angle"] = {
                "follow": angle["follow"],
                "ratio": float(angle.get("ratio", 1)),
                "offset": _si(angle.get("offset", "0 deg"), "angle"),
            }
        elif angle in ("input", "unknown"):
            out["angle"] = angle
        else:
            out["angle"] = _si(angle, "angle")
        if "guess" in v:
            guess[vname] = _si(v["guess"], "length" if length == "unknown" else "angle")
        vectors[vname] = out
    outputs = {}
    for vname, v in vectors.items():
        for kind in ("angle", "length"):
            if v[kind] == "unknown":
                words = (
                    ("theta", "omega", "alpha", "jerk")
                    if kind == "angle"
                    else ("length", "length_dot", "length_ddot", "length_dddot")
                )
                for n, w in enumerate(words):
                    outputs[f"{vname}.{w}"] = (vname, kind, n)
    return Case(name, title, "loops", {}, "open", vectors, desc["loops"], outputs, guess)


def eightbar():
    """An eightbar as three vector loops (section 7.8).

    The Watt II sixbar of the examples (crank-rocker O2-A-B-O4, whose rocker,
    extended to C, drives the fourbar O4-C-D-O6) with a third fourbar
    O6-E-F-O8 driven by link 6 extended to E: eight links (ground, 2, 3, 4, 5,
    6, 7, 8), ten pin joints, one degree of freedom, six unknown angles.
    Lengths in inches; the output rocker 8 swings about O8 = O6 + (8, -2) in.
    """
    from accelab.solver.vectorloops.examples import watt2_sixbar

    desc = watt2_sixbar()
    vectors = dict(desc["vectors"])
    vectors.update(
        {
            "R6E": {"length": "5 in", "angle": {"follow": "R6", "offset": "120 deg"}},
            "R8": {"length": "7 in", "angle": "unknown", "guess": "-10 deg"},
            "R9": {"length": "6 in", "angle": "unknown", "guess": "80 deg"},
            "R10": {"length": "8.246211251235321 in", "angle": "-14.036243467926479 deg"},
        }
    )
    return {
        "vectors": vectors,
        "loops": desc["loops"] + ["R6E + R8 - R9 - R10"],
        "points": dict(desc["points"], E="R1 + R7 + R6E"),
    }


def _closed_form_guess(case):
    case.guess = case.kernel_guess(case.span[0])
    return case


def all_cases():
    """The documented set, in the order the tables list it (dict name -> Case)."""
    from accelab.solver.vectorloops import examples

    cases = [
        _fourbar(
            "fourbar-open",
            "fourbar, Grashof crank-rocker, open",
            2 * IN,
            6 * IN,
            9 * IN,
            7 * IN,
            "open",
        ),
        _fourbar(
            "fourbar-crossed",
            "fourbar, Grashof crank-rocker, crossed",
            2 * IN,
            6 * IN,
            9 * IN,
            7 * IN,
            "crossed",
        ),
        _fourbar(
            "fourbar-nongrashof-open",
            "fourbar, non-Grashof triple rocker, open",
            5 * IN,
            4 * IN,
            6 * IN,
            3.5 * IN,
            "open",
        ),
        _fourbar(
            "fourbar-nongrashof-crossed",
            "fourbar, non-Grashof triple rocker, crossed",
            5 * IN,
            4 * IN,
            6 * IN,
            3.5 * IN,
            "crossed",
        ),
    ]
    a, b, c = 0.040, 0.120, 0.010
    cases.append(
        Case(
            "slidercrank",
            "offset slider-crank",
            "slidercrank",
            dict(a=a, b=b, c=c),
            "open",
            {
                "R2": {"length": a, "angle": "input"},
                "R3": {"length": b, "angle": "unknown"},
                "R4": {"length": c, "angle": 0.5 * math.pi},
                "R1": {"length": "unknown", "angle": 0.0},
            },
            ["R2 - R3 - R4 - R1"],
            KERNEL_OUTPUTS["slidercrank"],
        )
    )
    a, c, d, gamma = 4 * IN, 3 * IN, 8 * IN, 90 * DEG
    cases.append(
        Case(
            "invertedslidercrank",
            "inverted slider-crank",
            "invertedslidercrank",
            dict(a=a, c=c, d=d, gamma=gamma),
            "open",
            {
                "R1": {"length": d, "angle": 0.0},
                "R2": {"length": a, "angle": "input"},
                "R4": {"length": c, "angle": "unknown"},
                "R3": {
                    "length": "unknown",
                    "angle": {"follow": "R4", "ratio": 1.0, "offset": gamma},
                },
            },
            ["R2 - R3 - R4 - R1"],
            KERNEL_OUTPUTS["invertedslidercrank"],
        )
    )
    p = dict(a=1 * IN, b=4 * IN, c=4 * IN, d=1 * IN, f=3 * IN, lam=-2.0, phi=30 * DEG)
    cases.append(
        Case(
            "fivebar",
            "geared fivebar",
            "fivebar",
            p,
            "open",
            {
                "R1": {"length": p["f"], "angle": 0.0},
                "R2": {"length": p["a"], "angle": "input"},
                "R3": {"length": p["b"], "angle": "unknown"},
                "R4": {"length": p["c"], "angle": "unknown"},
                "R5": {
                    "length": p["d"],
                    "angle": {"follow": "R2", "ratio": p["lam"], "offset": p["phi"]},
                },
            },
            ["R2 + R3 - R4 - R5 - R1"],
            KERNEL_OUTPUTS["fivebar"],
        )
    )
    for case in cases:
        _closed_form_guess(case)
    cases.append(from_example("sixbar-watt2", "Watt II sixbar (2 loops)", examples.watt2_sixbar()))
    cases.append(
        from_example("sixbar-slider", "sixbar driving a slider (2 loops)", examples.sixbar_slider())
    )
    cases.append(from_example("eightbar", "eightbar (3 loops)", eightbar()))
    return {c.name: c for c in cases}


def description(case, guess=None):
    """The case as a loops description (docs/conventions.md#vector-loop-format; quantity
    strings), with guesses (default: the case's) for :class:`accelab.solver.VectorLoopLinkage`."""
    guess = case.guess if guess is None else guess
    vectors = {}
    for name, v in case.vectors.items():
        out = {}
        out["length"] = "unknown" if v["length"] == "unknown" else f"{float(v['length'])!r} m"
        angle = v["angle"]
        if isinstance(angle, dict):
            out["angle"] = {
                "follow": angle["follow"],
                "ratio": angle.get("ratio", 1.0),
                "offset": f"{float(angle.get('offset', 0.0))!r} rad",
            }
        elif angle in ("input", "unknown"):
            out["angle"] = angle
        else:
            out["angle"] = f"{float(angle)!r} rad"
        if name in guess:
            out["guess"] = f"{float(guess[name])!r} {'m' if v['length'] == 'unknown' else 'rad'}"
        vectors[name] = out
    return {"vectors": vectors, "loops": list(case.loops), "points": {}}
