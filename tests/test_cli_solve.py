"""The ``accelab solve`` command: the batch contract (docs/conventions.md#batch-format) and
the table."""

import json
import subprocess
import sys

import pytest

from accelab.cli import main
from accelab.solver.batch import read_case, solve_case, solve_cases

GOOD = {
    "mechanism": "fourbar",
    "a": "2 in",
    "b": "6 in",
    "c": "9 in",
    "d": "7 in",
    "theta2": "30 deg",
    "omega2": "10 rad/s",
    "alpha2": "-5 rad/s^2",
}


def run_cli(args, stdin=None):
    return subprocess.run(
        [sys.executable, "-m", "accelab", *args],
        input=stdin,
        capture_output=True,
        text=True,
        timeout=120,
    )


def test_batch_mixed_cases_in_order(tmp_path):
    cases = [
        GOOD,
        dict(GOOD, d="17 in"),  # not assemblable
        dict(GOOD, b="6 s"),  # wrong dimension
        dict(GOOD, circuit="sideways"),  # unknown circuit
        {"mechanism": "sixbar"},  # unknown mechanism
        dict(GOOD, colour="red"),  # unknown key
        {k: v for k, v in GOOD.items() if k != "omega2"},  # missing key
        dict(GOOD, a="-2 in"),  # non-positive length
        dict(GOOD, a="nan in"),  # non-finite length
        "not an object",
        dict(GOOD, circuit="crossed"),
    ]
    path = tmp_path / "cases.json"
    path.write_text(json.dumps(cases))
    p = run_cli(["solve", "--cases", str(path)])
    assert p.returncode == 1, p.stderr
    out = json.loads(p.stdout)
    assert [r["ok"] for r in out] == [True] + [False] * 9 + [True]
    kinds = [r.get("error") for r in out[1:10]]
    assert kinds == ["not_assemblable"] + ["invalid_input"] * 8
    assert all(r["message"] for r in out[1:10])
    assert out[0]["circuit"] == "open" and out[-1]["circuit"] == "crossed"
    assert isinstance(out[0]["A_B"], list) and len(out[0]["A_B"]) == 2
    for key in (
        "theta3",
        "theta4",
        "omega3",
        "omega4",
        "alpha3",
        "alpha4",
        "jerk3",
        "jerk4",
        "A_A",
        "A_B",
        "A_BA",
        "J_A",
        "J_B",
    ):
        assert key in out[0]


def test_batch_exit_codes(tmp_path):
    path = tmp_path / "ok.json"
    path.write_text(json.dumps([GOOD]))
    assert run_cli(["solve", "--cases", str(path)]).returncode == 0
    p = run_cli(["solve", "--cases", "-"], stdin=json.dumps([GOOD, GOOD]))
    assert p.returncode == 0 and len(json.loads(p.stdout)) == 2
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    p = run_cli(["solve", "--cases", str(bad)])
    assert p.returncode == 2 and "cannot use" in p.stderr
    p = run_cli(["solve", "--cases", str(tmp_path / "missing.json")])
    assert p.returncode == 2
    obj = tmp_path / "obj.json"
    obj.write_text(json.dumps(GOOD))
    assert run_cli(["solve", "--cases", str(obj)]).returncode == 2


def test_every_mechanism_reports_its_outputs():
    cases = [
        GOOD,
        dict(GOOD, p="3 in", delta3="30 deg", jerk2="100 rad/s^3", theta1="5 deg"),
        {
            "mechanism": "slidercrank",
            "a": "40 mm",
            "b": "120 mm",
            "c": "-5 mm",
            "theta2": "60 deg",
            "omega2": "3000 rpm",
            "alpha2": "0 rad/s^2",
        },
        {
            "mechanism": "invertedslidercrank",
            "a": "4 in",
            "c": "3 in",
            "d": "8 in",
            "gamma": "90 deg",
            "theta2": "45 deg",
            "omega2": "20 rad/s",
            "alpha2": "1 rad/s^2",
            "circuit": "crossed",
        },
        {
            "mechanism": "fivebar",
            "a": "1 in",
            "b": "4 in",
            "c": "4 in",
            "d": "1 in",
            "f": "3 in",
            "lam": -2,
            "phi": "30 deg",
            "theta2": "40 deg",
            "omega2": "10 rad/s",
            "alpha2": "0 rad/s^2",
        },
        {
            "mechanism": "rotation",
            "p": "4 in",
            "theta2": "30 deg",
            "omega2": "-20 rad/s",
            "alpha2": "15 rad/s^2",
        },
    ]
    want = {
        "fourbar": "theta3 theta4 omega3 omega4 alpha3 alpha4 jerk3 jerk4 A_A A_B A_BA J_A J_B",
        "slidercrank": "theta3 omega3 alpha3 jerk3 d d_dot d_ddot d_dddot A_A A_B A_BA J_A J_B",
        "invertedslidercrank": "theta3 theta4 omega3 omega4 alpha3 alpha4 jerk3 jerk4 b b_dot "
        "b_ddot A_A A_B A_BA A_coriolis",
        "fivebar": "theta3 theta4 theta5 omega3 omega4 omega5 alpha3 alpha4 alpha5 jerk3 "
        "jerk4 A_A A_B A_C A_BA",
        "rotation": "A A_t A_n J",
    }
    results = solve_cases(cases)
    for case, res in zip(cases, results):
        assert res["ok"], res
        assert set(want[case["mechanism"]].split()) <= set(res), case["mechanism"]
    assert {"A_P", "J_P"} <= set(results[1])
    assert "circuit" not in results[-1]


def test_read_case_rejects_batch_arrays_and_bools():
    with pytest.raises(Exception, match="lam"):
        read_case(
            {
                "mechanism": "fivebar",
                "a": "1 in",
                "b": "4 in",
                "c": "4 in",
                "d": "1 in",
                "f": "3 in",
                "lam": True,
                "phi": "0 deg",
                "theta2": "0 deg",
                "omega2": "1 rad/s",
                "alpha2": "0 rad/s^2",
            }
        )
    assert solve_case(dict(GOOD, delta3="10 deg"))["error"] == "invalid_input"


def test_table_in_the_users_units(capsys):
    status = main(
        [
            "solve",
            "fourbar",
            "a=2 in",
            "b=6 in",
            "c=9 in",
            "d=7 in",
            "theta2=30 deg",
            "omega2=10 rad/s",
            "alpha2=-5 rad/s^2",
        ]
    )
    out = capsys.readouterr().out
    assert status == 0
    assert "fourbar (open circuit)" in out
    assert "in/s²" in out and "deg" in out and "rad/s²" in out
    line = next(row for row in out.splitlines() if row.startswith("alpha3"))
    assert float(line.split()[1]) == pytest.approx(8.76875, rel=1e-5)


def test_single_json_and_errors(capsys):
    assert (
        main(
            [
                "solve",
                "slidercrank",
                "a=40 mm",
                "b=120 mm",
                "theta2=60 deg",
                "omega2=3000 rpm",
                "--json",
            ]
        )
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] and out["circuit"] == "open" and "d_ddot" in out
    assert (
        main(
            [
                "solve",
                "fourbar",
                "a=2 in",
                "b=6 in",
                "c=9 in",
                "d=17 in",
                "theta2=30 deg",
                "omega2=10 rad/s",
            ]
        )
        == 1
    )
    assert "not_assemblable" in capsys.readouterr().err
    assert main(["solve", "fourbar", "a"]) == 2


def test_help_everywhere_has_examples():
    p = run_cli(["--help"])
    assert p.returncode == 0 and "examples:" in p.stdout
    p = run_cli(["solve", "--help"])
    assert p.returncode == 0 and "--cases" in p.stdout and "examples:" in p.stdout


def test_python_m_accelab_runs_the_whole_command(tmp_path):
    """``python -m accelab`` is the ``accelab`` command."""
    path = tmp_path / "ok.json"
    path.write_text(json.dumps([GOOD]))
    p = subprocess.run(
        [sys.executable, "-m", "accelab", "solve", "--cases", str(path)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 0 and json.loads(p.stdout)[0]["ok"], p.stderr
    p = subprocess.run(
        [sys.executable, "-m", "accelab", "--help"], capture_output=True, text=True, timeout=120
    )
    assert p.returncode == 0 and "bench" in p.stdout and "assign" in p.stdout


def test_ctrl_c_while_the_commands_load_is_one_line(monkeypatch, capsys):
    """The console script imports accelab.cli, then calls main: the commands' modules
    (nbgrader, matplotlib, ... behind them) load inside main, where a Ctrl-C is said in one
    line with status 130 (it printed a traceback when it came during those imports)."""
    import importlib

    import accelab.cli as cli

    real = importlib.import_module

    def interrupted(name, *args):
        if name in cli.LAYERS:
            raise KeyboardInterrupt
        return real(name, *args)

    monkeypatch.setattr(importlib, "import_module", interrupted)
    assert cli.main(["solve", "--help"]) == 130
    err = capsys.readouterr().err
    assert err.strip() == "accelab: interrupted" and "Traceback" not in err
    out = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys, accelab.cli; print(sorted(m for m in sys.modules "
            "if m.endswith('.cli') and m.startswith('accelab.')))",
        ],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    assert out.strip() == "['accelab.cli']", out


def test_the_command_starts_numpy_without_blas_threads():
    """``accelab`` sets OPENBLAS_NUM_THREADS=1 before numpy loads (its OpenBLAS would start a
    thread per core that spins ~0.1 cpu-s, unused by the commands: the process has one thread
    then), and keeps a value the user set."""
    import os

    probe = (
        "import os, sys\n"
        "from accelab.cli import main\n"
        "try:\n"
        "    main(['solve', '--help'])\n"
        "except SystemExit:\n"
        "    pass\n"
        "threads = open('/proc/self/status').read().split('Threads:')[1].split()[0]\n"
        "print('numpy' in sys.modules, os.environ.get('OPENBLAS_NUM_THREADS'), threads)\n"
    )
    for given, expected in ((None, "True 1 1"), ("4", "True 4")):
        env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
        if given:
            env["OPENBLAS_NUM_THREADS"] = given
        p = subprocess.run(
            [sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=120
        )
        assert p.returncode == 0, p.stderr
        assert p.stdout.strip().splitlines()[-1].startswith(expected), p.stdout[-300:]
