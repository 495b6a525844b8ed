"""Linkages written as vector loops, shipped as examples and used by the tests,
the course and the benchmark. Each function returns a description dict in
the format of docs/conventions.md#vector-loop-format (without the input motion)."""


def fourbar(
    a="2 in",
    b="6 in",
    c="9 in",
    d="7 in",
    p="3 in",
    delta3="40 deg",
    guess3="90 deg",
    guess4="130 deg",
):
    """The fourbar of eq. 7.6 with a coupler point P (eq. 7.32)."""
    return {
        "vectors": {
            "R1": {"length": d, "angle": "0 deg"},
            "R2": {"length": a, "angle": "input"},
            "R3": {"length": b, "angle": "unknown", "guess": guess3},
            "R4": {"length": c, "angle": "unknown", "guess": guess4},
            "RP": {"length": p, "angle": {"follow": "R3", "offset": delta3}},
        },
        "loops": ["R2 + R3 - R4 - R1"],
        "points": {"A": "R2", "B": "R2 + R3", "P": "R2 + RP"},
    }


def slidercrank(a="40 mm", b="120 mm", c="10 mm", guess3="170 deg", guess_d="150 mm"):
    """The offset slider-crank of eq. 4.14b: a e2 - b e3 - c e4 - d e1 = 0."""
    return {
        "vectors": {
            "R2": {"length": a, "angle": "input"},
            "R3": {"length": b, "angle": "unknown", "guess": guess3},
            "R4": {"length": c, "angle": "90 deg"},
            "R1": {"length": "unknown", "guess": guess_d, "angle": "0 deg"},
        },
        "loops": ["R2 - R3 - R4 - R1"],
        "points": {"A": "R2", "B": "R1 + R4"},
    }


def invertedslidercrank(
    a="4 in", c="3 in", d="8 in", gamma="90 deg", guess4="80 deg", guess_b="6 in"
):
    """The inverted slider-crank (section 7.3; theta3 = theta4 + gamma, eq. 4.18)."""
    return {
        "vectors": {
            "R1": {"length": d, "angle": "0 deg"},
            "R2": {"length": a, "angle": "input"},
            "R4": {"length": c, "angle": "unknown", "guess": guess4},
            "R3": {
                "length": "unknown",
                "guess": guess_b,
                "angle": {"follow": "R4", "offset": gamma},
            },
        },
        "loops": ["R2 - R3 - R4 - R1"],
        "points": {"A": "R2", "B": "R1 + R4"},
    }


def fivebar(
    a="1 in",
    b="4 in",
    c="4 in",
    d="1 in",
    f="3 in",
    lam=-2,
    phi="30 deg",
    guess3="60 deg",
    guess4="120 deg",
):
    """The geared fivebar (section 7.4): link 5 follows the input with the gear ratio
    (eq. 7.28c)."""
    return {
        "vectors": {
            "R1": {"length": f, "angle": "0 deg"},
            "R2": {"length": a, "angle": "input"},
            "R3": {"length": b, "angle": "unknown", "guess": guess3},
            "R4": {"length": c, "angle": "unknown", "guess": guess4},
            "R5": {"length": d, "angle": {"follow": "R2", "ratio": lam, "offset": phi}},
        },
        "loops": ["R2 + R3 - R4 - R5 - R1"],
        "points": {"A": "R2", "B": "R2 + R3", "C": "R1 + R5"},
    }


def watt2_sixbar():
    """A Watt II sixbar: a crank-rocker fourbar O2-A-B-O4 whose rocker, extended to
    C, drives a second fourbar O4-C-D-O6 (two loops, four unknown angles)."""
    return {
        "vectors": {
            "R1": {"length": "7 in", "angle": "0 deg"},
            "R2": {"length": "2 in", "angle": "input"},
            "R3": {"length": "6 in", "angle": "unknown", "guess": "95 deg"},
            "R4": {"length": "9 in", "angle": "unknown", "guess": "130 deg"},
            "R4C": {"length": "4 in", "angle": {"follow": "R4", "offset": "-150 deg"}},
            "R5": {"length": "8 in", "angle": "unknown", "guess": "0 deg"},
            "R6": {"length": "6 in", "angle": "unknown", "guess": "-80 deg"},
            "R7": {"length": "9 in", "angle": "10 deg"},
        },
        "loops": ["R2 + R3 - R4 - R1", "R4C + R5 - R6 - R7"],
        "points": {"A": "R2", "B": "R2 + R3", "C": "R1 + R4C", "D": "R1 + R4C + R5"},
    }


def sixbar_slider():
    """A sixbar that drives a slider: the crank-rocker fourbar's rocker, extended
    to C, pushes a rod C-D whose end D slides on a horizontal line 3 in below O4
    (a fourbar followed by a slider-crank dyad; unknowns theta3, theta4, theta5
    and the slider position S)."""
    return {
        "vectors": {
            "R1": {"length": "7 in", "angle": "0 deg"},
            "R2": {"length": "2 in", "angle": "input"},
            "R3": {"length": "6 in", "angle": "unknown", "guess": "95 deg"},
            "R4": {"length": "9 in", "angle": "unknown", "guess": "130 deg"},
            "R4C": {"length": "4 in", "angle": {"follow": "R4", "offset": "180 deg"}},
            "R5": {"length": "10 in", "angle": "unknown", "guess": "-20 deg"},
            "H": {"length": "3 in", "angle": "-90 deg"},
            "S": {"length": "unknown", "guess": "10 in", "angle": "0 deg"},
        },
        "loops": ["R2 + R3 - R4 - R1", "R4C + R5 - H - S"],
        "points": {"A": "R2", "B": "R2 + R3", "C": "R1 + R4C", "D": "R1 + H + S"},
    }


EXAMPLES = {
    "fourbar": fourbar,
    "slidercrank": slidercrank,
    "invertedslidercrank": invertedslidercrank,
    "fivebar": fivebar,
    "watt2_sixbar": watt2_sixbar,
    "sixbar_slider": sixbar_slider,
}
