"""The polygon builder's rules, reader and task, without a browser.

* the task (the construction a student must make, from accelab.solver.graphical)
  agrees with the analytic solver: an independent method;
* a finished construction is right step by step; each classic mistake is caught
  and named in the chapter's terms (wrong sense of a normal component,
  tangential along the link, Coriolis forgotten, wrong scale), without the value;
* the tolerances are the stated ones (1 deg, 2% of the largest vector);
* the record reader refuses what is not a construction, quoting nothing;
* the widget's Python side checks each step (practice), only records (assignment),
  refuses a malformed step, and keeps the construction in its cell's output.
"""

import cmath
import copy
import json
import math

import pytest

from accelab.exercises.student.polygon import PolygonBuilder
from accelab.exercises.student.polygon.record import (
    MAX_STEPS,
    MIMETYPE,
    RecordError,
    read_record,
    read_steps,
)
from accelab.exercises.student.polygon.rules import judge_phase, next_step, step_feedback
from accelab.exercises.student.polygon.task import ideal_steps, task_of_case
from accelab.solver import FourBar, InvertedSliderCrank, SliderCrank
from accelab.solver.graphical.gallery import EXAMPLE_7_1, INVERTED_SLIDER_CRANK, SLIDER_CRANK

CASES = {
    "fourbar": EXAMPLE_7_1,
    "slidercrank": SLIDER_CRANK,
    "invertedslidercrank": INVERTED_SLIDER_CRANK,
}


@pytest.fixture(scope="module")
def tasks():
    return {m: task_of_case(c) for m, c in CASES.items()}


def steps_of(task, phase):
    return ideal_steps(task.phase(phase))


def judge(task, phase, steps):
    return judge_phase(task.phase(phase), read_steps(steps), list(task.phases.values()))


def result(j, key):
    return j.by_key()[key]


def moved(steps, name, fn, phase="acceleration", op="vector"):
    out = copy.deepcopy(steps)
    for s in out:
        if s["phase"] == phase and s["op"] == op and s.get("name") == name:
            fn(s)
    return out


def turn(s, degrees):
    """Turn a vector step about its tail."""
    tail, tip = complex(*s["tail"]), complex(*s["tip"])
    v = (tip - tail) * cmath.exp(1j * math.radians(degrees))
    s["tip"] = [(tail + v).real, (tail + v).imag]


def stretch(s, k):
    tail, tip = complex(*s["tail"]), complex(*s["tip"])
    v = (tip - tail) * k
    s["tip"] = [(tail + v).real, (tail + v).imag]


# ---- the task against the analytic solver --------------------------------------------------


def test_the_task_agrees_with_the_analytic_solver(tasks):
    """The construction the student is judged against is the package's geometric
    construction; the analytic closed forms are an independent check of it."""
    t = tasks["fourbar"]
    r = FourBar(a="2 in", b="6 in", c="9 in", d="7 in").solve(
        theta2="30 deg", omega2="10 rad/s", alpha2="-5 rad/s^2"
    )
    acc = t.phase("acceleration")
    reads = {x.name: x.value for p in t.phases.values() for x in p.reads}
    assert reads["omega3"] == pytest.approx(r.omega3.to("rad/s").magnitude, rel=1e-9)
    assert reads["alpha3"] == pytest.approx(r.alpha3.to("rad/s^2").magnitude, rel=1e-9)
    assert reads["alpha4"] == pytest.approx(r.alpha4.to("rad/s^2").magnitude, rel=1e-9)
    A_B = r.A_B.to("m/s^2").magnitude
    assert acc.term("A_B").vector == pytest.approx(complex(A_B), rel=1e-9)
    assert acc.X == pytest.approx(complex(A_B), rel=1e-9)
    s = SliderCrank(a="40 mm", b="120 mm", c="10 mm").solve(
        theta2="60 deg", omega2="30 rad/s", alpha2="-200 rad/s^2"
    )
    sc = {x.name: x.value for p in tasks["slidercrank"].phases.values() for x in p.reads}
    assert sc["d_ddot"] == pytest.approx(s.d_ddot.to("m/s^2").magnitude, rel=1e-9)
    assert sc["alpha3"] == pytest.approx(s.alpha3.to("rad/s^2").magnitude, rel=1e-9)
    i = InvertedSliderCrank(a="40 mm", c="50 mm", d="100 mm", gamma="70 deg").solve(
        theta2="60 deg", omega2="30 rad/s", alpha2="-200 rad/s^2"
    )
    ti = tasks["invertedslidercrank"]
    isc = {x.name: x.value for p in ti.phases.values() for x in p.reads}
    assert isc["alpha4"] == pytest.approx(i.alpha4.to("rad/s^2").magnitude, rel=1e-9)
    assert isc["b_ddot"] == pytest.approx(i.b_ddot.to("m/s^2").magnitude, rel=1e-9)
    A_cor = complex(i.A_coriolis.to("m/s^2").magnitude)
    assert ti.phase("acceleration").term("A_cor").vector == pytest.approx(A_cor, rel=1e-9)


@pytest.mark.parametrize("mechanism", list(CASES))
def test_each_polygon_closes_and_its_steps_are_the_chapters(tasks, mechanism):
    t = tasks[mechanism]
    for phase in t.phases.values():
        assert abs(phase.end("L") - phase.end("R")) <= 1e-12 * phase.largest
        ops = [s.op for s in phase.steps]
        assert ops.index("line") > max(k for k, o in enumerate(ops) if o == "vector" and k < 4)
        assert ops.count("point") == 1 and ops[-1] == "read"
        assert len(phase.unknowns) == 2
    names = [t.name for t in t.phase("acceleration").terms]
    assert ("A_cor" in names) == (mechanism == "invertedslidercrank")


# ---- a right construction, and the classic mistakes ----------------------------------------


@pytest.mark.parametrize("mechanism", list(CASES))
def test_a_finished_construction_is_right_in_every_step(tasks, mechanism):
    t = tasks[mechanism]
    for phase in t.phases:
        j = judge(t, phase, steps_of(t, phase))
        assert j.credit == 1.0, [r.message for r in j.results if not r.ok]
        assert not j.notes


def test_the_order_of_the_knowns_on_a_side_is_free(tasks):
    """A_A^n laid first from the pole, then A_A^t from its tip: the same sum."""
    t = tasks["fourbar"]
    ph = t.phase("acceleration")
    An, At = ph.term("A_A^n").vector, ph.term("A_A^t").vector
    steps = steps_of(t, "acceleration")
    for s in steps:
        if s.get("name") == "A_A^n":
            s["tail"], s["tip"] = [0, 0], [An.real, An.imag]
        elif s.get("name") == "A_A^t":
            s["tail"], s["tip"] = [An.real, An.imag], [(An + At).real, (An + At).imag]
    assert judge(t, "acceleration", steps).credit == 1.0


def test_wrong_sense_of_a_normal_component(tasks):
    t = tasks["fourbar"]
    bad = moved(steps_of(t, "acceleration"), "A_BA^n", lambda s: turn(s, 180))
    r = result(judge(t, "acceleration", bad), "vector:A_BA^n")
    assert not r.ok and "A_BA^n has the wrong sense: A_BA^n points from B toward A" in r.message
    bad = moved(steps_of(t, "acceleration"), "A_A^n", lambda s: turn(s, 180))
    r = result(judge(t, "acceleration", bad), "vector:A_A^n")
    assert "A_A^n points from A toward O2" in r.message


def test_a_tangential_line_drawn_along_the_link(tasks):
    t = tasks["fourbar"]
    bad = moved(
        steps_of(t, "acceleration"),
        "A_BA^t",
        lambda s: s.update(angle=s["angle"] + 90.0),
        op="line",
    )
    j = judge(t, "acceleration", bad)
    r = result(j, "line:A_BA^t")
    assert not r.ok
    assert "is perpendicular to AB, not along it: A_BA^t is perpendicular to BA" in r.message
    assert not result(j, "point:X").ok  # the crossing moves with it


def test_coriolis_forgotten(tasks):
    t = tasks["invertedslidercrank"]
    ph = t.phase("acceleration")
    tip = ph.term("A_A4^n").vector
    bad = [s for s in steps_of(t, "acceleration") if s.get("name") != "A_cor"]
    bad = moved(bad, "A_slip", lambda s: s.update(through=[tip.real, tip.imag]), op="line")
    j = judge(t, "acceleration", bad)
    missing = result(j, "vector:A_cor")
    assert missing.missing and "needs the Coriolis term A_cor = 2 omega4 V_slip" in missing.message
    line = result(j, "line:A_slip")
    assert not line.ok and "A_cor is not drawn" in line.message
    assert "perpendicular to the slide" in line.message
    assert not result(j, "point:X").ok
    assert j.credit < 0.75


def test_wrong_scale_and_unit_slips_are_named(tasks):
    t = tasks["fourbar"]
    ph = t.phase("acceleration")
    for factor, words in ((ph.scale, "the polygon's scale"), (12.0, "inches against feet")):
        bad = moved(steps_of(t, "acceleration"), "A_A^n", lambda s, k=factor: stretch(s, k))
        r = result(judge(t, "acceleration", bad), "vector:A_A^n")
        assert not r.ok and "too long" in r.message and words in r.message
    tv = tasks["invertedslidercrank"]
    bad = moved(steps_of(tv, "acceleration"), "A_cor", lambda s: stretch(s, 0.5))
    r = result(judge(tv, "acceleration", bad), "vector:A_cor")
    assert (
        "too short: its length is 2 omega4 V_slip" in r.message
        and "doubled or a halved" in r.message
    )


def test_a_read_value_with_the_wrong_sign(tasks):
    t = tasks["fourbar"]
    bad = moved(
        steps_of(t, "velocity"), "omega3", lambda s: s.update(value=-s["value"]), "velocity", "read"
    )
    r = result(judge(t, "velocity", bad), "read:omega3")
    assert not r.ok and r.message.startswith("omega3 has the wrong sign")


def test_tolerances_are_the_stated_ones(tasks):
    """1 deg on directions; 2% of the polygon's largest vector on lengths."""
    t = tasks["fourbar"]
    ph = t.phase("acceleration")
    for deg, ok in ((0.9, True), (1.2, False)):
        bad = moved(steps_of(t, "acceleration"), "A_A^n", lambda s, d=deg: turn(s, d))
        assert result(judge(t, "acceleration", bad), "vector:A_A^n").ok is ok
    n = abs(ph.term("A_A^n").vector)
    for extra, ok in ((0.019, True), (0.021, False)):
        k = 1 + extra * ph.largest / n
        bad = moved(steps_of(t, "acceleration"), "A_A^n", lambda s, k=k: stretch(s, k))
        assert result(judge(t, "acceleration", bad), "vector:A_A^n").ok is ok


def test_no_message_states_the_expected_value(tasks):
    for t in tasks.values():
        for phase in t.phases:
            steps = steps_of(t, phase)
            wrong = [moved(steps, s.get("name"), lambda x: stretch(x, 1.7), phase) for s in steps]
            wrong += [moved(steps, s.get("name"), lambda x: turn(x, 33), phase) for s in steps]
            for bad in wrong:
                for r in judge(t, phase, bad).results:
                    for term in t.phase(phase).terms:
                        size = abs(term.vector) * t.phase(phase).factor
                        assert f"{size:.4g}" not in r.message
                        assert f"{size:.3g} " not in r.message


def test_a_missing_construction_gets_nothing(tasks):
    t = tasks["fourbar"]
    j = judge(t, "velocity", [])
    assert j.credit == 0.0 and all(r.missing for r in j.results)


def test_a_line_for_a_known_term_is_said_to_be_a_vector(tasks):
    t = tasks["fourbar"]
    extra = {"op": "line", "phase": "velocity", "name": "V_A", "through": [0, 0], "angle": 0.0}
    j = judge(t, "velocity", steps_of(t, "velocity") + [extra])
    assert any("lay it as a vector" in n for n in j.notes)


# ---- instant feedback and the next step ------------------------------------------------------


def test_instant_feedback_judges_each_step_as_it_is_made(tasks):
    t = tasks["fourbar"]
    steps = read_steps(steps_of(t, "velocity")[:1])
    fb = step_feedback(t, steps)
    assert fb == [{"ok": True, "message": "V_A: right"}]
    again = read_steps(steps_of(t, "velocity")[:1] * 2)
    fb = step_feedback(t, again)
    assert fb[0]["ok"] is None and "replaced" in fb[0]["message"] and fb[1]["ok"]


def test_the_next_step_is_shown_on_request(tasks):
    t = tasks["fourbar"]
    ph = t.phase("acceleration")
    first = next_step(ph, [])
    assert first["key"] == "vector:A_A^t" and first["ghost"]["op"] == "vector"
    assert "from the pole" in first["text"] and "squares" in first["text"]
    words = next_step(ph, [], numbers=False)
    assert words["ghost"] is None and "squares" not in words["text"]
    done = read_steps(steps_of(t, "acceleration"))
    assert next_step(ph, done) is None
    half = read_steps(steps_of(t, "acceleration")[:4])
    assert next_step(ph, half)["key"] == "line:A_BA^t"


# ---- the record reader ------------------------------------------------------------------


def record(steps, **extra):
    out = {"format": "accelab-polygon", "version": 1, "student": "ann", "problem": 1,
           "family": "polygon_fourbar", "steps": steps}  # fmt: skip
    out.update(extra)
    return out


def test_a_record_reads_back_as_it_was_written(tasks):
    t = tasks["fourbar"]
    steps = steps_of(t, "velocity") + steps_of(t, "acceleration")
    rec = read_record(json.loads(json.dumps(record(steps))))
    assert len(rec.steps) == len(steps)
    again = read_record(rec.to_dict())
    assert [s.key for s in again.steps] == [s.key for s in rec.steps]


@pytest.mark.parametrize(
    "bad,why",
    [
        ("not a record", "not a construction record"),
        ({"format": "other"}, "not a construction record of this builder"),
        (record([], version=2), "another version"),
        (record([], problem=10**9), "small whole number"),
        (record([], student="x" * 10_000), "short text"),
        (record([{"op": "vector"}] * (MAX_STEPS + 1)), f"more than {MAX_STEPS} steps"),
        (record([[[[[]]]]]), "step 1 is not a step"),
        (record([{"op": "erase", "phase": "velocity"}]), "not a vector, a line"),
        (
            record([{"op": "vector", "phase": "velocity", "name": "V_A", "tail": [0, 0]}]),
            "fields of a vector",
        ),
        (
            record(
                [{"op": "vector", "phase": "jerk", "name": "V_A", "tail": [0, 0], "tip": [1, 1]}]
            ),
            "on no polygon",
        ),
        (
            record(
                [
                    {
                        "op": "vector",
                        "phase": "velocity",
                        "name": "<script>",
                        "tail": [0, 0],
                        "tip": [1, 1],
                    }
                ]
            ),
            "not the name",
        ),
        (
            record(
                [
                    {
                        "op": "vector",
                        "phase": "velocity",
                        "name": "V_A",
                        "tail": [0, 0],
                        "tip": [1e300, 1],
                    }
                ]
            ),
            "sensible size",
        ),
        (
            record(
                [
                    {
                        "op": "vector",
                        "phase": "velocity",
                        "name": "V_A",
                        "tail": [0, 0],
                        "tip": [True, 1],
                    }
                ]
            ),
            "not a number",
        ),
        (
            record([{"op": "read", "phase": "velocity", "name": "omega3", "value": float("nan")}]),
            "finite number",
        ),
        (
            record([{"op": "point", "phase": "velocity", "lines": ["V_B"], "at": [0, 0]}]),
            "two lines",
        ),
    ],
)
def test_a_forged_record_is_refused_quoting_nothing(bad, why):
    with pytest.raises(RecordError) as err:
        read_record(bad)
    assert why in str(err.value)
    assert "<script>" not in str(err.value) and "xxxx" not in str(err.value)


# ---- the widget's Python side (no browser) -------------------------------------------------


def test_the_builder_checks_steps_in_practice(tasks):
    b = PolygonBuilder.from_case(EXAMPLE_7_1)
    assert b.problem["mode"] == "practice" and len(b.problem["phases"]) == 2
    text = json.dumps(b.problem)
    for phase in b.task.phases.values():  # the browser gets no answer
        for term in phase.terms:
            assert f"{abs(term.vector):.6g}" not in text
    b.steps = steps_of(b.task, "velocity")[:1]
    assert b.verdicts == [{"ok": True, "message": "V_A: right"}]
    assert b.summary["velocity"] == {"right": 1, "total": 8}
    b.load(steps_of(b.task, "velocity"))
    assert b.judge("velocity").credit == 1.0
    assert b.record()["steps"][0]["name"] == "V_A"


def test_a_malformed_step_from_the_browser_is_not_taken():
    b = PolygonBuilder.from_case(EXAMPLE_7_1)
    b.steps = [{"op": "vector", "phase": "velocity", "name": "V_A", "tail": [0, 0], "tip": [1, 0]}]
    b.steps = [{"op": "vector", "phase": "velocity", "name": "V_A", "tail": "x", "tip": [1, 0]}]
    assert b.status.startswith("That step was not taken")
    assert b.steps[0]["tail"] == [0, 0]


def test_an_assignment_builder_records_and_never_judges(tasks):
    from accelab.exercises.assignment import make_spec
    from accelab.exercises.student.runtime import load_variant

    spec = make_spec("mech101", "A", ["polygon_fourbar"])
    v = load_variant(spec, "ann")
    b = PolygonBuilder.for_assignment(v, 1)
    assert b.mode == "assignment" and b.answers["velocity"] == "velocity_polygon"
    b.steps = [{"op": "vector", "phase": "velocity", "name": "V_A", "tail": [0, 0], "tip": [1, 0]}]
    assert b.verdicts[0]["ok"] is None and "graded" in b.verdicts[0]["message"]
    with pytest.raises(RuntimeError):
        b.judge("velocity")
    bundle = b._record_bundle()
    assert read_record(bundle[MIMETYPE]).student == "ann"
    from accelab.exercises.student.polygon import check_construction

    check_construction("velocity_polygon")
    with pytest.raises(AssertionError, match="nothing is drawn"):
        check_construction("acceleration_polygon")


def test_headless_a_practice_builder_shows_the_finished_construction(monkeypatch):
    from IPython.core.interactiveshell import InteractiveShell

    monkeypatch.setenv("ACCELAB_STATIC", "1")
    shell = InteractiveShell.instance()
    shown = []
    monkeypatch.setattr("IPython.display.display", lambda *a, **k: shown.extend(a), raising=True)
    b = PolygonBuilder.from_case(EXAMPLE_7_1)
    b._ipython_display_()
    assert shown and shown[0].data[:4] == b"\x89PNG"
    assert shell is not None


def test_the_course_table_of_classic_mistakes_says_each_rule():
    from accelab.course.polygons import classic_mistakes

    fourbar = str(classic_mistakes(EXAMPLE_7_1))
    assert "has the wrong sense" in fourbar and "not along it" in fourbar
    assert "check the polygon's scale" in fourbar and "start it at the pole" in fourbar
    coriolis = str(classic_mistakes(INVERTED_SLIDER_CRANK))
    assert "needs the Coriolis term" in coriolis and "perpendicular to the slide" in coriolis
    assert "doubled or a halved" in coriolis
    assert fourbar.count("\n|") >= 5 and "$\\mathbf{A}^{n}_{A}$" in fourbar


# ---- every family's variants, drawn exactly and drawn by a careful hand --------------------


def careful(phase, rng, error):
    """A student's drawing with every known vector off by up to ``error`` (a
    fraction of its length) and every direction by up to 0.4 deg, each laid from
    the tip of the last; the lines through the student's own chain ends; the
    crossing where those lines cross; the unknowns drawn to it; the values read
    off the student's own vectors (as the builder's snapping and Measure do)."""
    steps, ends, lines, drawn = [], {"L": 0j, "R": 0j}, {}, {}

    def xy(z):
        return [z.real, z.imag]

    for t in phase.terms:
        if t.known:
            turn = cmath.exp(1j * math.radians(rng.uniform(-0.4, 0.4)))
            v = t.vector * (1 + rng.uniform(-error, error)) * turn
            tail = ends[t.side]
            ends[t.side] = tail + v
            steps.append({"op": "vector", "phase": phase.name, "name": t.name,
                          "tail": xy(tail), "tip": xy(tail + v)})  # fmt: skip
    for t in phase.unknowns:
        first = t is [x for x in phase.side(t.side) if not x.known][0]
        through = ends[t.side] if first else ends["L" if t.side == "R" else "R"]
        angle = math.degrees(cmath.phase(t.vector)) + rng.uniform(-0.4, 0.4)
        lines[t.name] = (through, cmath.exp(1j * math.radians(angle)))
        steps.append({"op": "line", "phase": phase.name, "name": t.name,
                      "through": xy(through), "angle": angle})  # fmt: skip
    (p1, u1), (p2, u2) = (lines[t.name] for t in phase.unknowns)
    w = p2 - p1
    X = p1 + (w.real * u2.imag - w.imag * u2.real) / (u1.conjugate() * u2).imag * u1
    steps.append({"op": "point", "phase": phase.name,
                  "lines": [t.name for t in phase.unknowns], "at": xy(X)})  # fmt: skip
    for t in phase.unknowns:
        first = t is [x for x in phase.side(t.side) if not x.known][0]
        tail, tip = (ends[t.side], X) if first else (X, ends["L" if t.side == "R" else "R"])
        drawn[t.name] = tip - tail
        steps.append({"op": "vector", "phase": phase.name, "name": t.name,
                      "tail": xy(tail), "tip": xy(tip)})  # fmt: skip
    for t in phase.resultants:
        drawn[t.name] = X
        steps.append({"op": "vector", "phase": phase.name, "name": t.name,
                      "tail": [0, 0], "tip": xy(X)})  # fmt: skip
    for r in phase.reads:
        steps.append({"op": "read", "phase": phase.name, "name": r.name,
                      "value": r.of(drawn[r.source])})  # fmt: skip
    return steps


def test_every_familys_constructions_are_judged_right_exact_and_by_a_careful_hand():
    import random

    from accelab.exercises.families import generate
    from accelab.exercises.grader.key import key_value

    rng = random.Random(7)
    sloppy_wrong = 0
    for family in ("polygon_fourbar", "polygon_slidercrank", "polygon_coriolis"):
        for units in ("US", "SI"):
            for seed in range(12):
                key = key_value(generate(family, seed, units=units).answers[0])
                for phase in key.task.phases.values():
                    exact = judge_phase(phase, read_steps(ideal_steps(phase)))
                    assert exact.credit == 1.0, (family, seed, phase.name)
                    hand = judge_phase(phase, read_steps(careful(phase, rng, 0.004)))
                    assert hand.credit == 1.0, [r.message for r in hand.results if not r.ok]
                    sloppy = judge_phase(phase, read_steps(careful(phase, rng, 0.15)))
                    sloppy_wrong += sloppy.credit < 1.0
    assert sloppy_wrong >= 60  # 15% off is caught nearly everywhere (of 72 polygons)


def test_a_construction_is_kept_beside_the_notebook_between_sessions(tmp_path, monkeypatch):
    """In a live kernel the builder keeps its steps in .accelab-polygons.json (the
    notebook's folder) and a new builder of the same problem takes them back; a
    file that is not the builder's own is not read."""
    from accelab.exercises.student.polygon import widget

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(widget, "live", lambda: True)
    first = PolygonBuilder.from_case(EXAMPLE_7_1)
    first.steps = steps_of(first.task, "velocity")[:3]
    store = json.loads((tmp_path / widget.STORE).read_text())
    assert len(store) == 1 and len(next(iter(store.values()))["steps"]) == 3
    again = PolygonBuilder.from_case(EXAMPLE_7_1)
    assert [s["name"] for s in again.steps] == ["V_A", "V_BA", "V_B"]
    assert again.verdicts[0]["ok"] is True
    key = next(iter(store))
    (tmp_path / widget.STORE).write_text(json.dumps({key: {"format": "x", "steps": [[[]]]}}))
    forged = PolygonBuilder.from_case(EXAMPLE_7_1)
    assert forged.steps == [] and "could not be read" in forged.status
    (tmp_path / widget.STORE).write_text("[" * 100_000)  # not even JSON a parser takes
    assert PolygonBuilder.from_case(EXAMPLE_7_1).steps == []


def test_no_drawing_however_odd_makes_the_rules_fail(tasks):
    """Random steps (zero-length vectors, parallel lines, crossings of lines not
    drawn, names of other polygons, huge numbers): every one is judged, none raises."""
    import random

    rng = random.Random(3)

    def pt():
        c = rng.choice([0.0, 1.0, -1.0, 1e-12, 1e11, rng.uniform(-50, 50)])
        return [c, rng.choice([0.0, c, rng.uniform(-50, 50)])]

    for _ in range(600):
        t = rng.choice(list(tasks.values()))
        steps = []
        for _ in range(rng.randint(0, 25)):
            ph = rng.choice(list(t.phases.values()))
            names = [x.name for x in ph.terms + ph.resultants] + [r.name for r in ph.reads]
            names += ["X", "Zz"]
            op = rng.choice(["vector", "line", "point", "read"])
            step = {"op": op, "phase": ph.name}
            if op == "vector":
                step.update(name=rng.choice(names), tail=pt(), tip=pt())
            elif op == "line":
                step.update(name=rng.choice(names), through=pt(), angle=rng.uniform(-720, 720))
            elif op == "point":
                step.update(lines=[rng.choice(names), rng.choice(names)], at=pt())
            else:
                step.update(name=rng.choice(names), value=rng.choice([0.0, 1e11, rng.random()]))
            steps.append(step)
        drawn = read_steps(steps)
        feedback = step_feedback(t, drawn)
        assert len(feedback) == len(drawn)
        assert all(isinstance(f["message"], str) and f["message"] for f in feedback)
        for ph in t.phases.values():
            next_step(ph, drawn)
            next_step(ph, drawn, numbers=False)
