"""Read a vector-loop description (docs/conventions.md#vector-loop-format)
into index arrays of SI floats that the unit-free Newton-Raphson core uses.

Each vector v has a length L_v (fixed, or an unknown: a slider) and an angle

    theta_v = k_v * base_v + o_v

where base_v is the input angle theta2, one unknown angle, or nothing (a
fixed angle), after resolving chains of ``follow`` (rigid offsets within a
link, gear ratios). Loops are signed sums of vectors equal to zero; points
are signed sums of vectors measured from the origin of the first vector's
tail (the ground pivot O2 in the usual descriptions).
"""

import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InvalidInput
from ..units import show, to_si

_TERM = re.compile(r"\s*([+-]?)\s*([A-Za-z_][A-Za-z0-9_]*)\s*")

#: the most vectors a description may have (an eightbar has 14), the longest
#: vector name and the longest loop or point string [characters]: every part
#: of a description is read in bounded time
MAX_VECTORS = 200
MAX_NAME = 40
MAX_SUM = 2000


@dataclass
class LoopModel:
    """A checked description in SI, as arrays indexed by vector."""

    names: list  # vector names, in order
    loop_names: list  # the loop strings, for messages
    signs: np.ndarray  # (n_loops, n_vectors) of -1, 0, +1
    point_names: list
    point_signs: np.ndarray  # (n_points, n_vectors)
    length: np.ndarray  # fixed lengths (NaN where unknown)
    length_unknown: np.ndarray  # index into q of the length, or -1
    angle_unknown: np.ndarray  # index into q of the base angle, or -1
    angle_input: np.ndarray  # True where the base is theta2
    angle_ratio: np.ndarray  # k_v
    angle_offset: np.ndarray  # o_v [rad]
    guess: np.ndarray  # starting values of q (angles [rad], lengths [m])
    unknown_is_length: np.ndarray  # per q entry
    unknown_names: list  # "R3.angle", "S.length" per q entry
    length_scale: float  # a typical length [m], for tolerances

    @property
    def n_unknowns(self):
        return len(self.guess)


def loop_terms(text, names):
    """A checked loop or point ``text`` as [(vector index, sign)], in its order."""
    return [
        (names.index(m.group(2)), -1.0 if m.group(1) == "-" else 1.0)
        for m in _TERM.finditer(text.strip())
    ]


def _parse_sum(text, names, what):
    if not isinstance(text, str) or not text.strip():
        raise InvalidInput(
            f"{what} must be a signed sum of vector names like 'R2 + R3 - R4 - R1' "
            f"(got {show(text)})",
            what,
        )
    if len(text) > MAX_SUM:
        raise InvalidInput(
            f"{what} is {len(text)} characters long; a loop or point is at most {MAX_SUM}", what
        )
    signs = np.zeros(len(names))
    pos = 0
    first = True
    text = text.strip()
    while pos < len(text):
        m = _TERM.match(text, pos)
        if not m or (not first and not m.group(1)):
            raise InvalidInput(
                f"cannot read {what} at {show(text[pos:])}: write a signed "
                f"sum of vector names like 'R2 + R3 - R4 - R1'",
                what,
            )
        name = m.group(2)
        if name not in names:
            raise InvalidInput(
                f"{what} names an unknown vector {show(name)}; the vectors are {', '.join(names)}",
                what,
            )
        signs[names.index(name)] += -1.0 if m.group(1) == "-" else 1.0
        pos = m.end()
        first = False
    return signs


def _quantity(spec, key, name, kind):
    try:
        return to_si(spec[key], f"{name}.{key}", kind)
    except InvalidInput as exc:
        raise InvalidInput(f"vector {name}: {exc}", f"{name}.{key}") from None


def read_description(case):
    """Check a ``loops`` description and convert it to a :class:`LoopModel`.

    Raises
    ------
    InvalidInput
        Unknown vector names, a follow chain that loops, missing guesses,
        unknowns not twice the loops, bad units; the message says what to fix.
    """
    vectors = case.get("vectors")
    if not isinstance(vectors, dict) or not vectors:
        raise InvalidInput(
            "a loops case needs 'vectors': an object of named vectors, e.g. "
            '{"R2": {"length": "2 in", "angle": "input"}}',
            "vectors",
        )
    loops = case.get("loops")
    if not isinstance(loops, list) or not loops:
        raise InvalidInput(
            "a loops case needs 'loops': a list like [\"R2 + R3 - R4 - R1\"]", "loops"
        )
    points = case.get("points", {}) or {}
    if not isinstance(points, dict):
        raise InvalidInput("'points' must be an object of point names to vector sums", "points")
    if len(vectors) > MAX_VECTORS:
        raise InvalidInput(
            f"a loops case has at most {MAX_VECTORS} vectors (got {len(vectors)})", "vectors"
        )
    long = [k for k in vectors if not isinstance(k, str) or len(k) > MAX_NAME or not k]
    if long:
        raise InvalidInput(
            f"vector names are 1 to {MAX_NAME} characters (got {show(long[0])})", "vectors"
        )
    if not all(isinstance(p, str) and 0 < len(p) <= MAX_NAME for p in points):
        raise InvalidInput(f"point names are 1 to {MAX_NAME} characters", "points")
    if not all(isinstance(text, str) for text in loops):
        raise InvalidInput('each loop must be a string like "R2 + R3 - R4 - R1"', "loops")
    names = list(vectors)
    n = len(names)
    length = np.full(n, np.nan)
    length_unknown = np.full(n, -1)
    guesses, is_length, unknown_names = [], [], []
    raw_angle = {}
    for i, name in enumerate(names):
        spec = vectors[name]
        if not isinstance(spec, dict) or "length" not in spec or "angle" not in spec:
            raise InvalidInput(f"vector {name} needs 'length' and 'angle'", name)
        extra = set(spec) - {"length", "angle", "guess", "guess_length", "guess_angle"}
        if extra:
            raise InvalidInput(f"vector {name} has unknown key(s) {sorted(extra)}", name)
        angle = spec["angle"]
        both = spec["length"] == "unknown" and angle == "unknown"
        if spec["length"] == "unknown":
            key = "guess_length" if both or "guess_length" in spec else "guess"
            if key not in spec:
                raise InvalidInput(
                    f"vector {name} has an unknown length and needs a guess "
                    f"length ('{key}': '7 in')",
                    name,
                )
            guesses.append(_quantity(spec, key, name, "length"))
            is_length.append(True)
            unknown_names.append(f"{name}.length")
            length_unknown[i] = len(guesses) - 1
        else:
            length[i] = _quantity(spec, "length", name, "length")
            if not length[i] >= 0:
                raise InvalidInput(f"vector {name}: length must be >= 0", name)
        raw_angle[name] = angle
        if angle == "unknown":
            key = "guess_angle" if both or "guess_angle" in spec else "guess"
            if key not in spec:
                raise InvalidInput(
                    f"vector {name} has an unknown angle and needs a guess "
                    f"angle ('{key}': '90 deg'); the guess picks the assembly",
                    name,
                )
            guesses.append(_quantity(spec, key, name, "angle"))
            is_length.append(False)
            unknown_names.append(f"{name}.angle")
    angle_index = {name: k for k, name in enumerate(unknown_names) if name.endswith(".angle")}

    angle_unknown = np.full(n, -1)
    angle_input = np.zeros(n, dtype=bool)
    ratio = np.zeros(n)
    offset = np.zeros(n)

    def resolve(name):
        """(base, ratio, offset) of a vector's angle: the chain of follows
        walked to its end (without recursion: a chain may be long)."""
        chain: list[str] = []
        k = 1.0
        o: Any = 0.0  # the offsets summed [rad] (to_si gives a float or an array)
        while True:
            if name in chain:
                shown = " -> ".join(chain[chain.index(name) :] + [name])
                raise InvalidInput(
                    f"follow chain loops back on itself ({show(shown)}): one "
                    f"vector in it must have an input, unknown or fixed angle",
                    name,
                )
            chain.append(name)
            angle = raw_angle[name]
            if isinstance(angle, str) and angle == "input":
                return "input", k, o
            if isinstance(angle, str) and angle == "unknown":
                return angle_index[f"{name}.angle"], k, o
            if isinstance(angle, dict):
                target = angle.get("follow")
                if not isinstance(target, str) or target not in raw_angle:
                    raise InvalidInput(
                        f"vector {name} follows {show(target)}, which is not a "
                        f"vector (the vectors are {', '.join(names)})",
                        name,
                    )
                extra = set(angle) - {"follow", "offset", "ratio"}
                if extra:
                    raise InvalidInput(
                        f"vector {name}: unknown follow key(s) {show(sorted(map(str, extra)))}",
                        name,
                    )
                r = angle.get("ratio", 1.0)
                if isinstance(r, bool) or not isinstance(r, (int, float)) or not np.isfinite(r):
                    raise InvalidInput(
                        f"vector {name}: follow ratio must be a number (got {show(r)})", name
                    )
                off = to_si(angle.get("offset", 0), f"{name}.offset", "angle")
                # this vector's angle is r * (target's angle) + off
                o = o + k * off
                k = k * r
                name = target
                continue
            return None, 0.0, k * to_si(angle, f"{name}.angle", "angle") + o

    for i, name in enumerate(names):
        base, k, o = resolve(name)
        ratio[i], offset[i] = k, o
        if base == "input":
            angle_input[i] = True
        elif base is not None:
            angle_unknown[i] = base
    if not angle_input.any():
        raise InvalidInput(
            'no vector is driven by the input: give one vector "angle": '
            '"input" (or one that follows it)',
            "vectors",
        )
    signs = np.array([_parse_sum(text, names, f"loop {text!r}") for text in loops])
    n_unknowns = len(guesses)
    if n_unknowns != 2 * len(loops):
        raise InvalidInput(
            f"{len(loops)} loop(s) give {2 * len(loops)} scalar equations but "
            f"there are {n_unknowns} unknowns ({', '.join(unknown_names) or 'none'}"
            f"); add or remove loops or unknowns so they match",
            "loops",
        )
    point_names = list(points)
    point_signs = (
        np.array([_parse_sum(points[p], names, f"point {p}") for p in point_names])
        if point_names
        else np.zeros((0, n))
    )
    fixed = length[~np.isnan(length)]
    scale = (
        float(
            np.max(
                np.abs(
                    np.concatenate([fixed, np.array(guesses)[is_length] if any(is_length) else []])
                )
            )
        )
        if n
        else 1.0
    )
    return LoopModel(
        names,
        list(loops),
        signs,
        point_names,
        point_signs,
        length,
        length_unknown,
        angle_unknown,
        angle_input,
        ratio,
        offset,
        np.array(guesses, dtype=float),
        np.array(is_length, dtype=bool),
        unknown_names,
        scale or 1.0,
    )
