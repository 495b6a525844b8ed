"""CONTRIBUTING.md's walk-throughs, followed as written.

In a copy of the repository, the code blocks of "Add a mechanism" and "Add an exercise
family" (those marked ``python file=PATH``, a new file, and ``python insert=PATH``, an entry
of a registry) are written where they say, with the steps the guide states in words (the
exports, the rows of docs/conventions.md, the README's list of classes, the notebook that
names the family); then the
copy's own tests of the registries and of the typed API pass, ``accelab solve scotchyoke``
answers, the family draws its problems, and ruff (lint and format) and mypy are clean.
Leaving the registry entry out fails with the message the guide quotes.

The copy is imported through its installed layout (.ci/layout.py), with the checkout's
editable install taken out of the way (a sitecustomize beside the layout), from a folder
that holds nothing else.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
GUIDE = ROOT / "CONTRIBUTING.md"
BLOCK = re.compile(r"^```python (file|insert)=(\S+)\n(.*?)^```", re.MULTILINE | re.DOTALL)
ROWS = re.compile(r"^```text\n(\| `scotchyoke` .*?)^```", re.MULTILINE | re.DOTALL)
#: where a registry's tuple of entries ends (solver/registry.py, exercises/families/__init__.py)
END_OF_ENTRIES = "\n    )\n}\n"
#: where the guide puts a new entry elsewhere: a mechanism before the rotation's (step 4)
BEFORE = {"solver/registry.py": '        Registered(\n            "rotation",\n'}
NOT_SOURCE = (".venv", "build", ".git", "*.egg-info", "__pycache__", ".pytest_cache", ".mypy_cache")

pytestmark = pytest.mark.slow
#: the copy's tests that read the registries and the typed API
TESTS = ("test_registry.py", "test_public_api_typed.py", "test_layers.py")
#: what the walk-throughs write
NEW = (
    "solver/kernels/scotchyoke.py",
    "solver/mechanisms/scotchyoke.py",
    "exercises/families/piston.py",
)
PYTEST = (sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider")


def sub(path, old, new):
    text = path.read_text()
    assert text.count(old) == 1, (path, old)
    path.write_text(text.replace(old, new))


def follow(tree):
    """Do in ``tree`` what the guide says for the Scotch yoke and the piston family."""
    blocks = BLOCK.findall(GUIDE.read_text())
    assert [(k, p) for k, p, _ in blocks] == [
        ("file", "solver/kernels/scotchyoke.py"),
        ("file", "solver/mechanisms/scotchyoke.py"),
        ("insert", "solver/registry.py"),
        ("file", "exercises/families/piston.py"),
        ("insert", "exercises/families/__init__.py"),
    ]
    for kind, path, code in blocks:
        target = tree / path
        if kind == "file":
            target.write_text(code)
        else:  # one more entry in the registry's tuple: where the guide says
            text = target.read_text()
            at = text.index(BEFORE[path]) if path in BEFORE else text.index(END_OF_ENTRIES) + 1
            target.write_text(text[:at] + code + text[at:])
    # step 3: the exports
    sub(
        tree / "solver/mechanisms/__init__.py",
        "from .slidercrank import SliderCrank\n",
        "from .scotchyoke import ScotchYoke\nfrom .slidercrank import SliderCrank\n",
    )
    sub(
        tree / "solver/mechanisms/__init__.py",
        '    "SlottedLink",\n',
        '    "SlottedLink",\n    "ScotchYoke",\n',
    )
    sub(
        tree / "solver/__init__.py", "    RotatingPoint,\n", "    RotatingPoint,\n    ScotchYoke,\n"
    )
    sub(
        tree / "solver/__init__.py",
        '    "SlottedLink",\n',
        '    "SlottedLink",\n    "ScotchYoke",\n',
    )
    # step 5: the two rows of docs/conventions.md, before the rotation's
    loops_row, outputs_row = ROWS.search(GUIDE.read_text()).group(1).strip().splitlines()
    conventions = tree / "docs/conventions.md"
    sub(
        conventions,
        "| `rotation` | `p`, the radius",
        loops_row + "\n| `rotation` | `p`, the radius",
    )
    sub(conventions, "| `rotation` | `A A_t A_n J`", outputs_row + "\n| `rotation` | `A A_t A_n J`")
    # step 7: the README's list of mechanism classes
    sub(
        tree / "README.md",
        "`RotatingPoint` and `SlottedLink` in this release",
        "`RotatingPoint`, `SlottedLink` and `ScotchYoke` in this release",
    )
    # the family, step 3: the notebook that teaches it names it
    notebook = tree / "course/04_slider_crank_engine.py"
    text = notebook.read_text()
    line = next(x for x in text.splitlines() if "famil" in x and "`slidercrank`" in x)
    notebook.write_text(text.replace(line, line.rstrip(".") + " and `piston`."))


def test_the_walk_throughs_work_as_written(tmp_path):
    tree = tmp_path / "repo"
    shutil.copytree(ROOT, tree, ignore=shutil.ignore_patterns(*NOT_SOURCE), symlinks=True)
    follow(tree)
    layout = tree / "build" / "typecheck"
    subprocess.run([sys.executable, str(tree / ".ci" / "layout.py"), str(layout)], check=True)
    (layout / "sitecustomize.py").write_text(
        "import sys\n"
        "sys.meta_path[:] = [f for f in sys.meta_path\n"
        "                    if not getattr(f, '__module__', '').startswith('__editable__')]\n"
    )
    env = dict(os.environ, PYTHONPATH=str(layout), MPLBACKEND="Agg")
    bin_dir = Path(sys.executable).parent
    away = tmp_path / "elsewhere"  # the working folder: '' on sys.path finds nothing there
    away.mkdir()
    if (ROOT / ".mypy_cache").is_dir():  # a contributor's cache, as `make lint` leaves it (a copy)
        shutil.copytree(ROOT / ".mypy_cache", away / ".mypy_cache")

    def run(*argv, ok=True):
        done = subprocess.run(
            argv, cwd=away, env=env, capture_output=True, text=True, timeout=600, check=False
        )
        assert (done.returncode == 0) == ok, (
            f"{argv}:\n{done.stdout[-4000:]}\n{done.stderr[-2000:]}"
        )
        return done.stdout

    where = run(sys.executable, "-c", "import accelab.solver as s; print(s.__file__)")
    assert where.startswith(str(layout)), "the copy is the package under test"
    tests = [str(tree / "tests" / t) for t in TESTS]
    run(*PYTEST, *tests)
    # fuzzed without a word from the guide (tests/test_fuzz.py reads the registry): scaled by
    # powers of two and of ten, the same angles and the lengths scaled, or refused
    fuzz = run(*PYTEST, str(tree / "tests" / "test_fuzz.py"), "-k", "scotchyoke")
    assert "2 passed" in fuzz, fuzz[-2000:]
    families = str(tree / "tests" / "test_exercises_families.py")
    run(*PYTEST, families, "-k", "test_family_variants and piston")  # drawn in US and SI
    answer = run(
        sys.executable, "-m", "accelab", "solve", "scotchyoke", "a=2 in", "theta2=30 deg",
        "omega2=10 rad/s", "--json",
    )  # fmt: skip
    assert '"d_ddot"' in answer and '"ok": true' in answer
    code = "from accelab.exercises.practice import practice\nprint(practice('piston', 3).problem)"
    assert "piston" in run(sys.executable, "-c", code)
    new = [str(tree / p) for p in NEW]
    config = ("--config", str(tree / "pyproject.toml"))
    run(str(bin_dir / "ruff"), "check", *config, *new)
    run(str(bin_dir / "ruff"), "format", "--check", *config, *new)
    run(str(bin_dir / "mypy"), "--config-file", str(tree / "pyproject.toml"))
    # a step left out: the mechanism's registry entry
    (tree / "solver" / "registry.py").write_text((ROOT / "solver" / "registry.py").read_text())
    test = str(tree / "tests" / "test_registry.py") + "::test_every_mechanism_class_is_registered"
    assert "add its entry to REGISTRY in solver/registry.py" in run(*PYTEST, test, ok=False)
