"""Unit tests of the problem side of the exercises: seeding, the expr
evaluator, the generators and the published variant (fast; no nbgrader)."""

import json
import math
import os
import subprocess
import sys

import pytest
from _exercises_helpers import answer_value, answers_code
from _exercises_helpers import fourbar as outside_fourbar

from accelab.exercises import expr
from accelab.exercises.assignment import build_variant, make_spec
from accelab.exercises.families import FAMILIES, generate
from accelab.exercises.families.common import MIN_CONDITION, GenerationError
from accelab.exercises.grader.key import key_value
from accelab.exercises.problem import solve_cases
from accelab.exercises.seeding import seed_for
from accelab.solver.units import Q_

SPEC = make_spec("mech101", "A", ["rotation", "fourbar", "tolerance"])


# ---- seeding -------------------------------------------------------------------------------


def test_seed_is_sha256_based_and_frozen():
    # frozen values: a change here would give every student a new variant
    assert seed_for("mech101", "A", "alice", 1, "rotation") == 3438168229952889947
    assert seed_for("a") == 8286459498212470165
    assert seed_for("ab", "c") != seed_for("a", "bc")


def test_variant_is_the_same_in_another_process_with_another_hash_seed():
    code = (
        "import json; from accelab.exercises.assignment import build_variant, make_spec; "
        "s = make_spec('mech101', 'A', ['rotation', 'fourbar', 'tolerance']); "
        "print(json.dumps(build_variant(s, 'alice').public(), sort_keys=True))"
    )
    outs = [
        subprocess.run(
            [sys.executable, "-c", code],
            capture_output=True,
            text=True,
            env=dict(os.environ, PYTHONHASHSEED=h),
            check=True,
        ).stdout
        for h in ("1", "977")
    ]
    assert outs[0] == outs[1]
    assert json.loads(outs[0]) == json.loads(
        json.dumps(build_variant(SPEC, "alice").public(), sort_keys=True)
    )


def test_students_get_different_variants():
    givens = {
        json.dumps([p.given for p in build_variant(SPEC, s).problems])
        for s in ("alice", "bob", "carol", "dave", "erin", "frank")
    }
    assert len(givens) == 6


# ---- expr ----------------------------------------------------------------------------------

OUT = {"A": {"A": [3.0, 4.0], "alpha3": -2.0}, "B": {"A": [0.0, 1.0]}}


@pytest.mark.parametrize(
    "text, value",
    [
        ("abs(A.A)", 5.0),
        ("real(A.A)", 3.0),
        ("imag(A.A) / 2", 2.0),
        ("-A.alpha3 * 1.5", 3.0),
        ("angle(B.A)", math.pi / 2),
        ("abs(B.A - A.A)", math.hypot(3.0, 3.0)),
        ("A.alpha3 + 1", -1.0),
    ],
)
def test_expr_evaluates(text, value):
    assert expr.evaluate(text, OUT) == pytest.approx(value)


@pytest.mark.parametrize(
    "text, word",
    [
        ("__import__('os')", "called"),
        ("A.A ** 2", "Pow"),
        ("open.x", None),
        ("A", "Name"),
        ("'x'", "numbers"),
        ("abs(A.A, 1)", "called"),
        ("A.A[0]", "Subscript"),
        ("(lambda: 1)()", "called"),
        ("A.A.real", "LABEL.KEY"),
        ("1 +", "parse"),
    ],
)
def test_expr_refuses_anything_else(text, word):
    with pytest.raises(expr.ExprError) as err:
        expr.evaluate(text, OUT)
    if word:
        assert word in str(err.value)


def test_expr_names_missing_labels_and_keys():
    with pytest.raises(expr.ExprError, match="case 'C'"):
        expr.evaluate("abs(C.A)", OUT)
    with pytest.raises(expr.ExprError, match="no output 'J'"):
        expr.evaluate("abs(A.J)", OUT)
    assert expr.labels("abs(B.A - A.A)") == ["A", "B"]


# ---- generators ----------------------------------------------------------------------------


@pytest.mark.parametrize("family", sorted(FAMILIES))
@pytest.mark.parametrize("units", ["US", "SI"])
def test_family_variants_are_deterministic_well_conditioned_and_sized(family, units):
    seen = set()
    for seed in range(8):
        p = generate(family, seed, units=units)
        assert p.to_dict() == generate(family, seed, units=units).to_dict()
        seen.add(json.dumps(p.given, sort_keys=True))
        for a in p.answers:
            outputs = solve_cases(a.cases)
            for out in outputs.values():
                assert out["ok"] and out.get("condition", 1.0) >= MIN_CONDITION
            value = key_value(a, outputs)
            if a.kind == "choice":
                assert value in a.choices
            elif a.kind == "construction":  # judged step by step (test_polygon_grading)
                assert value.phase == a.expr and value.task.phase(a.expr).steps
            else:
                assert math.isfinite(value) and value != 0.0
            lengths = [
                v
                for case in a.cases.values()
                for k, v in case.items()
                if k in ("a", "b", "c", "d", "f", "p") and isinstance(v, str)
            ]
            unit = "in" if units == "US" else "mm"
            assert all(v.endswith(unit) for v in lengths if family != "tolerance")
            assert all(len(v.split()[0]) <= 6 for v in lengths)  # textbook precision
    assert len(seen) >= 7


def test_rotation_values_match_eq_7_2_independently():
    p = generate("rotation", 11)
    for a in p.answers:
        assert key_value(a) == pytest.approx(
            Q_(answer_value(a.public()), a.unit or "").to_base_units().magnitude, rel=1e-9
        )


def test_fourbar_key_matches_an_independent_solution():
    for seed in range(5):
        p = generate("fourbar", seed)
        case = p.answers[0].cases["L"]
        ref = outside_fourbar(case)
        out = solve_cases({"L": case})["L"]
        assert out["alpha3"] == pytest.approx(ref["alpha3"], rel=1e-8)
        assert out["alpha4"] == pytest.approx(ref["alpha4"], rel=1e-8)
        assert complex(*out["A_B"]) == pytest.approx(ref["A_B"], rel=1e-8)


def test_instructor_ranges_apply_and_bad_ranges_fail_clearly():
    p = generate("rotation", 3, ranges={"p": ("2 in", "3 in"), "omega": (50, 50)})
    assert p.given["p"] in ("2 in", "2.5 in", "3 in") and p.given["omega"] in (
        "50 rad/s",
        "-50 rad/s",
    )
    p = generate("fourbar", 3, units="SI", ranges={"a": (20, 40)})
    assert 20 <= float(p.given["a"].split()[0]) <= 40
    with pytest.raises(ValueError, match="unknown range 'q'"):
        generate("rotation", 1, ranges={"q": (1, 2)})
    with pytest.raises(ValueError, match="upper end"):
        generate("rotation", 1, ranges={"p": (3, 2)})
    with pytest.raises(ValueError, match="units must be"):
        generate("rotation", 1, units="imperial")
    with pytest.raises(ValueError, match="unknown problem family"):
        generate("cam", 1)
    with pytest.raises(GenerationError, match="widen the ranges"):  # never assemblable
        generate("fourbar", 1, ranges={"a": (20, 20), "b": (3, 3), "c": (3, 3), "d": (4, 4)})


def test_tolerance_never_sits_on_a_level():
    for seed in range(30):
        p = generate("tolerance", seed)
        g = key_value(p.answers[0]) / 9.80665
        assert all(abs(g - level) >= 0.05 * level for level in (0.5, 3.5, 9.0))


# ---- published variant ---------------------------------------------------------------------


def test_public_variant_has_no_answers_and_exprs_reproduce_the_key():
    v = build_variant(SPEC, "alice")
    pub = v.public()
    text = json.dumps(pub)
    for a in v.answers.values():
        if a.kind != "choice":
            key = key_value(a)
            assert f"{key:.6g}"[:6] not in text or abs(key) < 10
    names = [a["name"] for a in pub["answers"]]
    assert names == list(v.answers)
    assert all(n.startswith(("p1_", "p2_", "p3_")) for n in names)
    choice = [a for a in pub["answers"] if a["kind"] == "choice"]
    assert choice and all("expr" not in a and a["choices"] for a in choice)
    for a in pub["answers"]:
        assert set(a) >= {"name", "unit", "cases", "kind"}
        for case in a["cases"].values():
            assert "mechanism" in case and "theta2" in case
        if a["kind"] not in ("choice", "construction"):
            assert expr.labels(a["expr"]) == sorted(a["cases"])
    # the outside check's code (independent solver) answers every question right
    code = answers_code(pub)
    from accelab.exercises.grader.judge import judge
    from accelab.exercises.grader.key import key_of
    from accelab.exercises.student.answers import describe
    from accelab.solver.units import ureg

    key = key_of(v)
    ns = {"Q_": Q_}
    for name, line in code.items():
        exec(line, ns)
        verdict = judge(
            v.answers[name].asked(),
            describe(ns[name]),
            key.values[name],
            v.tolerance,
            v.angle_tolerance,
            ureg,
        )
        assert verdict.ok, verdict.message


def test_variant_cli_json(tmp_path, capsys):
    from accelab.cli import main
    from accelab.exercises.notebook import write_source

    spec = make_spec("mech101", "A", ["rotation", "tolerance"], units="SI")
    write_source(str(tmp_path), spec)
    assert (
        main(
            [
                "variant",
                "--course",
                str(tmp_path),
                "--assignment",
                "A",
                "--student",
                "bob",
                "--json",
            ]
        )
        == 0
    )
    pub = json.loads(capsys.readouterr().out)
    assert pub["student"] == "bob" and pub["units"] == "SI"
    assert pub == json.loads(json.dumps(build_variant(spec, "bob").public()))
    assert (
        main(["variant", "--course", str(tmp_path), "--assignment", "Z", "--student", "bob"]) == 2
    )
    assert "accelab assign" in capsys.readouterr().err
