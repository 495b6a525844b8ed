"""An outside check for the exercises tests: answers a published variant
(``accelab variant --json``) without the project's solver or evaluator.

Its own pint registry, its own closed forms (rotation: eq. 7.2; fourbar:
position by Norton's eq. 4.10, velocity and acceleration by solving the
differentiated vector loop as 2x2 linear systems), and Python's eval over the
published expr with abs/angle/real/imag.
"""

import cmath
import functools
import math
from types import SimpleNamespace

import numpy as np
import pint


@functools.cache
def ureg():
    """This module's own registry, made when first asked for (half a second: only the
    test worker that checks exercises pays it)."""
    return pint.UnitRegistry()


def si(text):
    """A case value in SI (m, rad, rad/s, ...), by this module's own registry."""
    if isinstance(text, (int, float)):
        return float(text)
    return float(ureg().Quantity(text).to_base_units().magnitude)


def rotation(case):
    p, t, w, al = (si(case[k]) for k in ("p", "theta2", "omega2", "alpha2"))
    e = cmath.exp(1j * t)
    return {"A": p * (al * 1j - w * w) * e}


def fourbar(case):
    a, b, c, d = (si(case[k]) for k in "abcd")
    t2, w2, al2 = (si(case[k]) for k in ("theta2", "omega2", "alpha2"))
    K1, K2, K3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    A = math.cos(t2) - K1 - K2 * math.cos(t2) + K3
    B = -2 * math.sin(t2)
    C = K1 - (K2 + 1) * math.cos(t2) + K3
    root = math.sqrt(B * B - 4 * A * C)
    sign = -1 if case.get("circuit", "open") == "open" else 1
    t4 = 2 * math.atan2(-B + sign * root, 2 * A)
    e2, e4 = cmath.exp(1j * t2), cmath.exp(1j * t4)
    e3 = (d + c * e4 - a * e2) / b
    t3 = cmath.phase(e3)
    e3 = cmath.exp(1j * t3)
    # velocity: a w2 j e2 + b w3 j e3 - c w4 j e4 = 0
    M = np.array(
        [[(1j * b * e3).real, (-1j * c * e4).real], [(1j * b * e3).imag, (-1j * c * e4).imag]]
    )
    rhs = -(1j * a * w2 * e2)
    w3, w4 = np.linalg.solve(M, [rhs.real, rhs.imag])
    # acceleration: a(al2 j - w2^2)e2 + b(al3 j - w3^2)e3 - c(al4 j - w4^2)e4 = 0
    rhs = -(a * (al2 * 1j - w2 * w2) * e2 - b * w3 * w3 * e3 + c * w4 * w4 * e4)
    al3, al4 = np.linalg.solve(M, [rhs.real, rhs.imag])
    return {
        "theta3": t3,
        "theta4": t4,
        "omega3": w3,
        "omega4": w4,
        "alpha3": al3,
        "alpha4": al4,
        "A_A": a * (al2 * 1j - w2 * w2) * e2,
        "A_B": c * (al4 * 1j - w4 * w4) * e4,
    }


SOLVERS = {"rotation": rotation, "fourbar": fourbar}
FUNCS = {
    "abs": abs,
    "angle": lambda z: cmath.phase(complex(z)),
    "real": lambda z: complex(z).real,
    "imag": lambda z: complex(z).imag,
}
#: Table 7-1 levels the tolerance statement gives [g]
LEVELS = [(0.5, "gentle"), (3.5, "strong"), (9.0, "extreme"), (math.inf, "intolerable")]


def answer_value(answer):
    """(value in the asked unit, unit) for a number answer of the published variant."""
    outputs = {
        label: SimpleNamespace(**SOLVERS[case["mechanism"]](case))
        for label, case in answer["cases"].items()
    }
    value = eval(answer["expr"], {"__builtins__": {}}, dict(FUNCS, **outputs))
    base = ureg().Quantity(1.0, answer["unit"] or "").to_base_units().units
    return float(ureg().Quantity(value, base).to(answer["unit"] or "").magnitude)


def answers_code(variant):
    """Answer-cell code for every graded answer of a published variant."""
    code, g = {}, None
    for a in variant["answers"]:
        if a["kind"] == "choice":
            continue
        value = answer_value(a)
        if a["unit"] == "g_0":
            g = value
        code[a["name"]] = f"{a['name']} = Q_({value!r}, {a['unit']!r})"
    for a in variant["answers"]:
        if a["kind"] == "choice":
            verdict = next(word for level, word in LEVELS if g < level)
            code[a["name"]] = f"{a['name']} = {verdict!r}"
    return code
