"""The package as users get it: the wheel, installed into a fresh virtual environment.

The test builds the wheel from a clean copy of the repository (no stale build/ can leak
into it), reads its top-level names (exactly ``accelab``), installs it with --no-deps into
a new venv, and from a folder with no checkout runs ``accelab demo`` (the worked case,
then a course graded in the sandbox), ``accelab course --out DIR``, and one of the
notebooks it writes; ``import solver`` (a 0.1 name) fails there.

The venv gets its dependencies from the test environment's site-packages, hard-linked
(fast, no network, and real files: the grading sandbox shows the venv's own prefix, so
they must be inside it), without the editable install of the checkout. The venv lives
under the checkout's build/ so that the links stay on one filesystem; the folder it runs
in is a temporary one outside the checkout.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

import pytest
from _venv import TESTS_ONLY, linked_venv

import accelab

ROOT = Path(__file__).resolve().parents[1]
#: what a clean copy of the repository leaves out: the environment, outputs, caches, VCS
NOT_SOURCE = (".venv", "build", ".git", "*.egg-info", "__pycache__", ".pytest_cache")
#: the notebook run from the installed wheel: quick, and it reads course data the wheel must
#: ship (course/benchmark.json, through accelab.course.HERE)
NOTEBOOK = "11_speed_accuracy"

pytestmark = pytest.mark.slow


#: each step's command, time and (when slow) output, kept for a reader of a slow run: once in
#: a while this test has taken 300 s instead of 20 and passed
STEPS = ROOT / "build" / "test-artifacts" / "wheel-steps.log"


def run(argv, cwd, env, timeout=600):
    start = time.monotonic()
    env = dict(env, PIP_DISABLE_PIP_VERSION_CHECK="1")  # pip asks no index for its version
    done = subprocess.run(
        argv, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout, check=False
    )
    seconds = time.monotonic() - start
    STEPS.parent.mkdir(parents=True, exist_ok=True)
    with open(STEPS, "a") as log:
        log.write(
            f"{time.strftime('%H:%M:%S')} {seconds:7.1f} s  {' '.join(map(str, argv))[:200]}\n"
        )
        if seconds > 60:
            log.write(f"--- stdout\n{done.stdout[-6000:]}\n--- stderr\n{done.stderr[-6000:]}\n")
    assert done.returncode == 0, (
        f"{' '.join(map(str, argv))} exited with {done.returncode}:\n"
        f"{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    )
    return done


def build_wheel(out):
    """The wheel of a clean copy of the repository, built offline; its path."""
    source = out / "source"
    shutil.copytree(ROOT, source, ignore=shutil.ignore_patterns(*NOT_SOURCE), symlinks=True)
    argv = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation"]
    run([*argv, "--quiet", "-w", str(out / "dist"), str(source)], cwd=out, env=dict(os.environ))
    wheels = list((out / "dist").glob("accelab-*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


def top_level_names(wheel):
    """The names the wheel puts into site-packages: its .dist-info aside, and its .data
    folder, whose files go elsewhere (share/jupyter: the JupyterLab extension)."""
    with zipfile.ZipFile(wheel) as z:
        names = {n.split("/", 1)[0] for n in z.namelist()}
    return {n for n in names if not n.endswith((".dist-info", ".data"))}


def fresh_venv(where):
    """A new venv whose site-packages holds the test environment's packages (hard links,
    or copies across filesystems) but not the editable install of this checkout."""
    venv = where / "venv"
    linked_venv(venv)
    tests_only = [p.name for p in venv.glob("lib/python*/site-packages/*") if p.name in TESTS_ONLY]
    assert not tests_only, f"{tests_only}: the test environment's, not a user's"
    return venv


def test_the_wheel_installs_and_runs_as_users_get_it(tmp_path):
    build = ROOT / "build"
    build.mkdir(exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="wheel-test-", dir=build))
    try:
        wheel = build_wheel(work)
        assert top_level_names(wheel) == {"accelab"}, "the wheel installs one top-level name"
        assert wheel.name.startswith(f"accelab-{accelab.__version__}-")

        venv = fresh_venv(work)
        python = str(venv / "bin" / "python")
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
        env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"
        env["MPLBACKEND"] = "Agg"
        pip = [python, "-m", "pip", "install", "--quiet", "--no-deps", "--no-index"]
        run([*pip, str(wheel)], cwd=work, env=env)

        away = tmp_path / "elsewhere"  # no checkout here, nor above
        away.mkdir()
        found = run(
            [python, "-c", "import accelab, json; print(json.dumps(accelab.__file__))"],
            cwd=away,
            env=env,
        )
        assert json.loads(found.stdout).startswith(str(venv)), "accelab from the wheel"
        for old in ("solver", "exercises", "course", "benchmarks"):
            refused = subprocess.run(
                [python, "-c", f"import {old}"], cwd=away, env=env, capture_output=True, text=True
            )
            assert refused.returncode != 0 and "ModuleNotFoundError" in refused.stderr, old

        accelab_cmd = str(venv / "bin" / "accelab")
        demo = run([accelab_cmd, "demo"], cwd=away, env=env)
        assert "Worked case (Example 7-1)" in demo.stdout
        assert (away / "build" / "demo-course" / "grades_A.csv").is_file(), demo.stdout[-2000:]
        # the right submission scores full marks: its kernel ran in the sandbox with the deps
        assert re.search(r"^ada\s.*\b12/12\b", demo.stdout, re.MULTILINE), demo.stdout[-2000:]

        run([accelab_cmd, "course", "--out", "my-course"], cwd=away, env=env)
        course = away / "my-course"
        assert (course / f"{NOTEBOOK}.ipynb").is_file() and (course / "FAMILIES.md").is_file()
        # executed by nbclient in the installed environment, through the tests' runner (a file
        # of the checkout loaded by its path, nothing of it put on sys.path): its waits for the
        # kernel's messages look again each second (docs/notebooks.py: notebook_client)
        runner = ROOT / "docs" / "notebooks.py"
        execute = (
            "import importlib.util, nbformat\n"
            f"spec = importlib.util.spec_from_file_location('runner', {str(runner)!r})\n"
            "runner = importlib.util.module_from_spec(spec)\n"
            "spec.loader.exec_module(runner)\n"
            f"nb = nbformat.read('{NOTEBOOK}.ipynb', as_version=4)\n"
            "runner.notebook_client(nb, timeout=300, kernel_name='python3').execute()\n"
            "print(sum(len(c.get('outputs', [])) for c in nb.cells if c.cell_type == 'code'))\n"
        )
        done = run([python, "-c", execute], cwd=course, env=env)
        assert int(done.stdout.split()[-1]) > 0, "the notebook ran and shows its outputs"
    finally:
        shutil.rmtree(work, ignore_errors=True)
