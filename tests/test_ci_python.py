""".ci/python.py: the Python `make venv` builds .venv from (the faster of python3 on PATH and
the system's /usr/bin/python3, among those that can make a venv)."""

import importlib.util
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = ROOT / ".ci" / "python.py"


def load():
    spec = importlib.util.spec_from_file_location("ci_python", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_it_names_a_python_that_can_make_a_venv():
    chosen = subprocess.run(
        [sys.executable, str(SCRIPT)], capture_output=True, text=True, check=True, timeout=60
    ).stdout.strip()
    probe = "import sys, venv, ensurepip; print(sys.version_info >= (3, 10))"
    done = subprocess.run([chosen, "-c", probe], capture_output=True, text=True, timeout=60)
    assert done.stdout.strip() == "True", (chosen, done.stderr)


def test_the_faster_is_chosen_and_none_falls_back_to_python3(monkeypatch, capsys):
    ci_python = load()
    speeds = {
        "python3": (0.05, "/opt/py/bin/python3"),
        "/usr/bin/python3": (0.03, "/usr/bin/python3"),
    }
    monkeypatch.setattr(ci_python, "measured", speeds.get)
    ci_python.main()
    assert capsys.readouterr().out.strip() == "/usr/bin/python3"
    speeds["python3"] = (0.01, "/opt/py/bin/python3")
    ci_python.main()
    assert capsys.readouterr().out.strip() == "/opt/py/bin/python3"
    monkeypatch.setattr(ci_python, "measured", lambda command: None)  # neither can make a venv
    ci_python.main()
    assert capsys.readouterr().out.strip() == "python3"


def test_a_python_that_cannot_make_a_venv_is_not_a_candidate(tmp_path):
    fake = tmp_path / "python3"
    fake.write_text("#!/bin/sh\nexit 1\n")
    fake.chmod(0o755)
    assert load().measured(str(fake)) is None
