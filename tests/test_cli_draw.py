"""`accelab draw` (solver/cli/draw.py) end to end."""

import json
import os

import pytest

from accelab.cli import main
from accelab.solver.batch import solve_case
from accelab.solver.graphical.gallery import EXAMPLE_7_1, GALLERY

CASES = [
    EXAMPLE_7_1,
    {
        "mechanism": "fourbar",
        "a": "3 in",
        "b": "4 in",
        "c": "5 in",
        "d": "13 in",
        "theta2": "45 deg",
        "omega2": "100 rpm",
        "alpha2": "0 rad/s^2",
    },  # cannot close
    {
        "mechanism": "slidercrank",
        "a": "40 mm",
        "b": "120 mm",
        "c": "-5 mm",
        "theta2": "120 deg",
        "omega2": "3000 rpm",
        "alpha2": "100 rad/s^2",
        "circuit": "crossed",
    },
    {"mechanism": "loops", "vectors": {}},  # no construction
    {
        "mechanism": "invertedslidercrank",
        "a": "40 mm",
        "c": "50 mm",
        "d": "100 mm",
        "gamma": "70 deg",
        "theta2": "60 deg",
        "omega2": "30 rad/s",
        "alpha2": "-200 rad/s^2",
    },
    {
        "mechanism": "slidercrank",
        "a": "40 mm",
        "b": "40 mm",
        "theta2": "90 deg",
        "omega2": "10 rad/s",
        "alpha2": "0 rad/s^2",
    },  # singular
    {
        "mechanism": "fourbar",
        "a": "2 in",
        "b": "6 s",
        "c": "9 in",
        "d": "7 in",
        "theta2": "30 deg",
        "omega2": "10 rad/s",
        "alpha2": "0 rad/s^2",
    },  # bad unit
    "not a case",
]


def run_draw(tmp_path, capsys, cases, *extra):
    f = tmp_path / "cases.json"
    f.write_text(json.dumps(cases))
    status = main(["draw", str(f), "--out", str(tmp_path / "out"), *extra])
    return status, json.loads(capsys.readouterr().out)


@pytest.mark.slow
def test_draw_batch(tmp_path, capsys):
    status, results = run_draw(tmp_path, capsys, CASES)
    assert status == 1
    assert [r["ok"] for r in results] == [True, False, True, False, True, False, False, False]
    assert [r.get("error") for r in results if not r["ok"]] == [
        "not_assemblable",
        "invalid_input",
        "singular",
        "invalid_input",
        "invalid_input",
    ]
    for r in results:
        if not r["ok"]:
            assert r["message"] and set(r) == {"ok", "error", "message"}
    # the same error kinds as `accelab solve` where it has an answer
    for case, r in zip(CASES, results):
        if not r["ok"] and isinstance(case, dict) and case["mechanism"] != "loops":
            assert solve_case(case)["error"] == r["error"]
    # the values read off the construction, in SI, vectors [x, y]
    ex = results[0]
    ref = solve_case(EXAMPLE_7_1)
    for k in ("alpha3", "alpha4"):
        assert ex[k] == pytest.approx(ref[k], rel=1e-9)
    for k in ("A_A", "A_B", "A_P", "A_BA"):
        assert ex[k] == pytest.approx(ref[k], rel=1e-9)
    assert results[2]["d_ddot"] == pytest.approx(solve_case(CASES[2])["d_ddot"], rel=1e-9)
    assert results[4]["A_coriolis"] == pytest.approx(solve_case(CASES[4])["A_coriolis"], rel=1e-9)
    names = sorted(os.listdir(tmp_path / "out"))
    assert names == sorted(
        f"case{n:03d}-{m}-{k}.{e}"
        for n, m in ((1, "fourbar"), (3, "slidercrank"), (5, "invertedslidercrank"))
        for k in ("linkage", "polygons")
        for e in ("png", "svg")
    )
    assert all(os.path.exists(p) for p in ex["figures"])


def test_draw_all_ok_exits_0_and_step_option(tmp_path, capsys):
    fivebar = GALLERY["graphical-fivebar"]
    status, results = run_draw(
        tmp_path, capsys, [CASES[2], fivebar], "--format", "png", "--step", "3"
    )
    assert status == 0 and results[0]["ok"]
    assert [os.path.basename(p) for p in results[0]["figures"]] == [
        "case001-slidercrank-linkage.png",
        "case001-slidercrank-polygons.png",
    ]
    assert results[1]["A_C"] == pytest.approx(solve_case(fivebar)["A_C"], rel=1e-9)
    status, results = run_draw(tmp_path, capsys, [CASES[2]], "--format", "png", "--step", "99")
    assert status == 1 and results[0]["error"] == "invalid_input"
    assert "--step" in results[0]["message"]


def test_draw_cases_option_and_stdout_layout(tmp_path, capsys, monkeypatch):
    f = tmp_path / "c.json"
    f.write_text(json.dumps([CASES[2], CASES[1]]))
    assert main(["draw", "--cases", str(f), "--out", str(tmp_path), "--format", "png"]) == 1
    out = capsys.readouterr().out
    lines = out.splitlines()
    assert lines[0] == "[" and lines[-1] == "]" and len(lines) == 4  # one case per line
    assert [r["ok"] for r in json.loads(out)] == [True, False]
    assert main(["draw", "--out", str(tmp_path)]) == 2


def test_draw_unusable_file(tmp_path, capsys):
    assert main(["draw", str(tmp_path / "missing.json"), "--out", str(tmp_path)]) == 2
    bad = tmp_path / "bad.json"
    bad.write_text('{"mechanism": "fourbar"}')
    assert main(["draw", str(bad), "--out", str(tmp_path)]) == 2
    assert "JSON list" in capsys.readouterr().err
    bad.write_text("[]")
    assert main(["draw", str(bad), "--out", str(tmp_path), "--format", "gif"]) == 2


def test_help_mentions_example(capsys):
    with pytest.raises(SystemExit):
        main(["draw", "--help"])
    out = capsys.readouterr().out
    assert "accelab draw cases.json --out" in out
