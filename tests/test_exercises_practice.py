"""Self-study practice: instant feedback on a problem drawn for practice, never
one of a graded assignment."""

import pytest

from accelab.exercises.assignment import build_variant, make_spec
from accelab.exercises.families import FAMILIES
from accelab.exercises.practice import practice
from accelab.solver.units import Q_


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_practice_accepts_the_right_answer_and_refuses_a_wrong_one(family, capsys):
    p = practice(family, seed=11)
    for name, asked in p.asked.items():
        if asked.kind == "construction":  # checked step by step (test_polygon_rules)
            with pytest.raises(ValueError, match="builder"):
                p.check(name, 1.0)
            assert p.reveal(name).startswith(b"\x89PNG")
            continue
        right = p.reveal(name)
        assert p.check(name, right)
        if asked.kind == "choice":
            wrong = next(c for c in asked.choices if c != right)
        else:
            wrong = right * 1.5
        assert not p.check(name, wrong)
        out = capsys.readouterr().out
        assert "right" in out and ("not within" in out or "judgement" in out or "direction" in out)
    assert practice(family, seed=11).problem.given == p.problem.given
    assert "not graded" in p._repr_markdown_()


def test_practice_says_why_not():
    p = practice("fourbar", seed=5)
    a3 = p.reveal("alpha3")
    assert not p.check("alpha3", -a3)
    assert not p.check("alpha3", Q_(a3.magnitude, "rad/s"))
    assert not p.check("A_B_ang", p.reveal("A_B_ang") + Q_(180, "deg"))
    with pytest.raises(KeyError):
        p.check("alpha9", 1.0)


def test_practice_values_are_never_a_graded_variants():
    spec = make_spec("mech101", "A", sorted(FAMILIES))
    graded = {
        (p.family, tuple(sorted(p.given.items())))
        for s in ("ann", "bob", "cy", "di", "ed")
        for p in build_variant(spec, s).problems
    }
    for family in FAMILIES:
        for seed in range(8):
            p = practice(family, seed=seed)
            assert (family, tuple(sorted(p.problem.given.items()))) not in graded
            # on the half-steps: a graded length of the default ranges is a multiple of 0.5 in
            for value in p.problem.given.values():
                if str(value).endswith(" in"):
                    assert float(value.split()[0]) % 0.5 != 0.0


@pytest.mark.parametrize("family", list(FAMILIES))
def test_the_answers_table_shows_every_answer_as_revealed(family, capsys):
    """What a course page folds under a practice problem: every answer, each one
    that the problem's own check accepts."""
    p = practice(family, seed=5)
    table = p.answers()._repr_markdown_()
    assert "(seed 5)" in table
    for name in p.asked:
        assert f"`{name}`" in table
        if p.asked[name].kind == "construction":
            assert "data:image/png;base64," in table
            continue
        assert p.check(name, p.reveal(name))
    assert len(repr(p.answers()).splitlines()) == len(p.asked)
