"""The layers of the code and which may import which (README, "How the code
is laid out"), checked on the source: the AST of every module, so an import
that breaks a rule fails here even if nothing runs it.

    accelab        the command: may import every layer; none imports it
    exercises      problem generators, grading     -> solver
    benchmarks     speed and accuracy, beside      -> solver, exercises (grading speed)
    course, docs   clients (notebooks, site)       -> solver, exercises, benchmarks, course
    solver         the library                     -> solver only

Inside the library: the kernels are unit-free numpy (no pint, nothing of the
unit-aware layers above them), and the graphical constructions never ask the
analytic solvers (mechanisms, kernels, vector loops) for an answer.

An import counts wherever it stands (top level or inside a function), and so
does a module named by a string (``importlib.import_module("exercises.cli")``).
"""

import ast
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
PROJECT = ("accelab", "solver", "exercises", "benchmarks", "course", "docs")

#: layer -> the project's top-level packages it may import
MAY_IMPORT = {
    "accelab": set(PROJECT),
    "solver": {"solver"},
    "exercises": {"solver", "exercises"},
    "benchmarks": {"solver", "exercises", "benchmarks"},   # they measure grading too
    "course": {"solver", "exercises", "benchmarks", "course"},
    "docs": {"solver", "exercises", "benchmarks", "course", "docs"},
}

#: subpackages of the library and what of the library they must not import
MUST_NOT = {
    "solver.kernels": ("solver.mechanisms", "solver.vectorloops", "solver.graphical",
                       "solver.batch", "solver.cases", "solver.units", "solver.cli", "pint"),
    "solver.graphical": ("solver.mechanisms", "solver.kernels", "solver.vectorloops",
                         "solver.batch"),
}

#: arrows up allowed as exceptions: none (the command is ``accelab``, or
#: ``python -m accelab``; the library has no entry point of its own)
COMPATIBILITY = set()

_NAMED = re.compile(r"^(%s)(\.[A-Za-z_]\w*)+$" % "|".join(PROJECT))


def modules():
    """(dotted name, path) of every Python module of the project's layers."""
    for top in PROJECT:
        base = ROOT / top
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*.py")):
            rel = path.relative_to(ROOT).with_suffix("")
            parts = list(rel.parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            yield ".".join(parts), path


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
                base = base[:len(base) - (node.level - 1)]
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
                if (_NAMED.match(head) or head in PROJECT) and _is_module(head):
                    found.add(head)
    return found


def _is_module(dotted):
    """Whether ``dotted`` names a module or package of the project (so that a
    string like ``"accelab.json"`` does not count)."""
    path = ROOT.joinpath(*dotted.split("."))
    return path.with_suffix(".py").is_file() or (path / "__init__.py").is_file()


def violations():
    bad = []
    for name, path in modules():
        layer = name.split(".")[0]
        for target in sorted(imports(name, path)):
            top = target.split(".")[0]
            if any(name == n and (target == t or target.startswith(t + "."))
                   for n, t in COMPATIBILITY):
                continue
            if top in PROJECT and top not in MAY_IMPORT[layer]:
                bad.append(f"{path.relative_to(ROOT)}: {layer} imports {target}")
            for sub, banned in MUST_NOT.items():
                if name == sub or name.startswith(sub + "."):
                    for b in banned:
                        if target == b or target.startswith(b + "."):
                            bad.append(f"{path.relative_to(ROOT)}: {sub} imports {target}")
    return bad


def test_no_import_breaks_the_layers():
    assert violations() == []


def test_the_walk_sees_every_layer_and_the_rules_bite(tmp_path, monkeypatch):
    names = {name for name, _ in modules()}
    for top in ("accelab", "solver", "exercises", "benchmarks"):
        assert top in names
    assert {"solver.kernels.fourbar", "accelab.cli", "benchmarks.reference"} <= names
    # a relative import, an import inside a function and a module named by a
    # string are all seen
    fake = tmp_path / "solver" / "cli"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text(
        "from ..kernels import fourbar\n"
        "def f():\n    import exercises.cli\n"
        "LAYERS = ['benchmarks.cli']\n")
    found = imports("solver.cli", fake / "__init__.py")
    assert {"solver.kernels", "exercises.cli", "benchmarks.cli"} <= found


@pytest.mark.parametrize("module", ["solver", "exercises", "benchmarks"])
def test_compatibility_entries_are_the_only_arrows_up(module):
    """Nothing of the library reaches the application layer."""
    ups = [(name, t) for name, path in modules() if name.split(".")[0] == module
           for t in imports(name, path) if t.split(".")[0] == "accelab"]
    assert all(any(n == name and (t == up or t.startswith(up + ".")) for name, up in COMPATIBILITY)
               for n, t in ups)
