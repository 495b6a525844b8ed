"""The layers of the code and which may import which (README, "How the code
is laid out"), checked on the source: the AST of every module, so an import
that breaks a rule fails here even if nothing runs it.

Installed, the project is one import package, ``accelab``; each layer is a
top-level folder of the repository mapped into it (``setup.py``):

    accelab/     accelab.cli   the command: may import every layer; none imports it
    exercises/   accelab.exercises   generators, grading   -> solver
    benchmarks/  accelab.benchmarks  beside the library    -> solver, exercises (grading speed)
    course/      accelab.course      the notebooks' kit    -> solver, exercises, benchmarks
    docs/        docs (not installed) the site             -> all but the command
    solver/      accelab.solver      the library           -> solver only

Inside the library: the kernels are unit-free numpy (no pint, nothing of the
unit-aware layers above them), and the graphical constructions never ask the
analytic solvers (mechanisms, kernels, vector loops) for an answer. Inside the
exercises, the student-side code (what the grading sandbox shows a submission)
imports nothing of the instructor's side.

An import counts wherever it stands (top level or inside a function), and so
does a module named by a string (``importlib.import_module("accelab.exercises.cli")``).
The old top-level names (``import solver``) are refused everywhere.
"""

import ast
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
#: import name of each layer -> its folder in the repository
FOLDERS = {
    "accelab": "accelab",
    "accelab.solver": "solver",
    "accelab.exercises": "exercises",
    "accelab.benchmarks": "benchmarks",
    "accelab.course": "course",
    "docs": "docs",
}
#: the names the layers had before they moved into ``accelab``: never imported again
OLD_NAMES = ("solver", "exercises", "benchmarks", "course")
LAYERS = ("app", "solver", "exercises", "benchmarks", "course", "docs")

#: layer -> the layers it may import ("accelab" alone, the namespace, is free to all)
MAY_IMPORT = {
    "app": set(LAYERS),
    "solver": {"solver"},
    "exercises": {"solver", "exercises"},
    "benchmarks": {"solver", "exercises", "benchmarks"},  # they measure grading too
    "course": {"solver", "exercises", "benchmarks", "course"},
    "docs": {"solver", "exercises", "benchmarks", "course", "docs"},
}

#: subpackages and what of the project they must not import
MUST_NOT = {
    "accelab.solver.kernels": (
        "accelab.solver.mechanisms",
        "accelab.solver.vectorloops",
        "accelab.solver.graphical",
        "accelab.solver.batch",
        "accelab.solver.cases",
        "accelab.solver.units",
        "accelab.solver.cli",
        "pint",
    ),
    "accelab.solver.graphical": (
        "accelab.solver.mechanisms",
        "accelab.solver.kernels",
        "accelab.solver.vectorloops",
        "accelab.solver.batch",
    ),
    # the sandbox shows a submission exercises/student/ and nothing else of the exercises
    "accelab.exercises.student": tuple(
        f"accelab.exercises.{p.stem}"
        for p in sorted((ROOT / "exercises").iterdir())
        if p.name not in ("student", "__init__.py", "__pycache__")
        and (p.suffix == ".py" or (p / "__init__.py").is_file())
    ),
}

#: arrows up allowed as exceptions: none (the command is ``accelab``, or
#: ``python -m accelab``; the library has no entry point of its own)
COMPATIBILITY = set()
#: the student side's one import of the instructor's side: ``load_variant`` draws the
#: student's values outside grading; while grading, the sandbox hands the statement over
#: first, so the import is never reached there (tests/test_exercises_sandbox.py)
OUTSIDE_THE_SANDBOX = {("accelab.exercises.student.runtime", "accelab.exercises.assignment")}

_NAMED = re.compile(r"^(accelab|docs)(\.[A-Za-z_]\w*)+$")


def layer_of(dotted):
    """The layer a module (or an imported name) belongs to, "accelab" for the bare
    namespace package, None for anything outside the project."""
    if dotted == "accelab":
        return "accelab"
    for name in ("accelab.solver", "accelab.exercises", "accelab.benchmarks", "accelab.course"):
        if dotted == name or dotted.startswith(name + "."):
            return name.split(".")[1]
    if dotted.startswith("accelab."):
        return "app"
    if dotted == "docs" or dotted.startswith("docs."):
        return "docs"
    return None


def path_of(dotted):
    """The repository path of a module of the project (without suffix), or None."""
    for name in sorted(FOLDERS, key=len, reverse=True):
        if dotted == name or dotted.startswith(name + "."):
            rest = dotted[len(name) :].lstrip(".")
            return ROOT.joinpath(FOLDERS[name], *(rest.split(".") if rest else []))
    return None


def modules():
    """(dotted name, path) of every Python module of the project's layers."""
    for name, folder in FOLDERS.items():
        base = ROOT / folder
        for path in sorted(base.rglob("*.py")):
            if "__pycache__" in path.parts or (folder == "accelab" and path.parent != base):
                continue
            if folder == "course" and path.name[:2].isdigit():
                continue  # the notebooks: checked by tests/test_course.py
            parts = list(path.relative_to(base).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            yield ".".join([name] + parts), path


def imports(name, path):
    """Every module ``name`` (at ``path``) imports: import statements (absolute
    and relative, anywhere in the file) and modules named by a string."""
    tree = ast.parse(path.read_text(), str(path))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module
            found.add(module)
            found.update(f"{module}.{alias.name}" for alias in node.names)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            if _NAMED.match(node.value) and _is_module(node.value):
                found.add(node.value)
        elif isinstance(node, ast.JoinedStr) and node.values:
            first = node.values[0]
            if isinstance(first, ast.Constant) and isinstance(first.value, str):
                head = first.value.rstrip(".")
                if _NAMED.match(head) and _is_module(head):
                    found.add(head)
    return found


def _is_module(dotted):
    """Whether ``dotted`` names a module or package of the project (so that a
    string like ``"accelab.json"`` does not count)."""
    path = path_of(dotted)
    return path is not None and (
        path.with_suffix(".py").is_file() or (path / "__init__.py").is_file()
    )


def violations():
    bad = []
    for name, path in modules():
        layer = layer_of(name)
        for target in sorted(imports(name, path)):
            where = path.relative_to(ROOT)
            if target.split(".")[0] in OLD_NAMES:
                bad.append(
                    f"{where}: imports {target}: the old top-level name (now accelab.{target})"
                )
                continue
            if any(
                name == n and (target == t or target.startswith(t + ".")) for n, t in COMPATIBILITY
            ):
                continue
            to = layer_of(target)
            if to not in (None, "accelab") and to not in MAY_IMPORT[layer]:
                bad.append(f"{where}: {layer} imports {target}")
            for sub, banned in MUST_NOT.items():
                if name == sub or name.startswith(sub + "."):
                    for b in banned:
                        if any(name == n and target.startswith(t) for n, t in OUTSIDE_THE_SANDBOX):
                            continue
                        if target == b or target.startswith(b + "."):
                            bad.append(f"{where}: {sub} imports {target}")
    return bad


def test_no_import_breaks_the_layers():
    assert violations() == []


def test_the_walk_sees_every_layer_and_the_rules_bite(tmp_path):
    names = {name for name, _ in modules()}
    for top in (
        "accelab",
        "accelab.solver",
        "accelab.exercises",
        "accelab.benchmarks",
        "accelab.course",
    ):
        assert top in names
    assert {
        "accelab.solver.kernels.fourbar",
        "accelab.cli",
        "accelab.benchmarks.reference",
    } <= names
    assert {layer_of(n) for n in names} == set(LAYERS) | {"accelab"}
    # a relative import, an import inside a function and a module named by a
    # string are all seen
    fake = tmp_path / "solver" / "cli"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text(
        "from ..kernels import fourbar\n"
        "def f():\n    import accelab.exercises.cli\n"
        "LAYERS = ['accelab.benchmarks.cli']\n"
    )
    found = imports("accelab.solver.cli", fake / "__init__.py")
    assert {"accelab.solver.kernels", "accelab.exercises.cli", "accelab.benchmarks.cli"} <= found
    assert layer_of("accelab.exercises.cli") not in MAY_IMPORT["solver"]


@pytest.mark.parametrize("module", ["solver", "exercises", "benchmarks", "course"])
def test_compatibility_entries_are_the_only_arrows_up(module):
    """Nothing of the library reaches the application layer."""
    ups = [
        (name, t)
        for name, path in modules()
        if layer_of(name) == module
        for t in imports(name, path)
        if layer_of(t) == "app"
    ]
    assert all(
        any(n == name and (t == up or t.startswith(up + ".")) for n, up in COMPATIBILITY)
        for name, t in ups
    )
