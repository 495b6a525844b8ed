"""The installed layout of the package as a tree of symbolic links, for tools that read
source files by import name but cannot see setuptools' editable finder (mypy).

``python .ci/layout.py build/typecheck`` makes ``build/typecheck/accelab/`` whose
subpackages link to the repository's folders as setup.py maps them (``accelab/solver`` ->
``solver/`` ...): ``mypy`` with ``MYPYPATH=build/typecheck`` then checks
``accelab.solver`` where it really is. The mapping is read from setup.py (its ``LAYERS``),
so this script holds no copy of it.
"""

import ast
import os
import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def layers():
    """setup.py's ``LAYERS``: import name -> repository folder."""
    tree = ast.parse((ROOT / "setup.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "LAYERS" for t in node.targets
        ):
            return ast.literal_eval(node.value)
    raise SystemExit("setup.py has no LAYERS mapping")


def build(out):
    """Write the link tree under ``out`` (made afresh); returns the package's folder."""
    out = Path(out).resolve()
    if out.exists():
        shutil.rmtree(out)
    for name, folder in layers().items():
        target = out.joinpath(*name.split("."))
        source = ROOT / folder
        if name == "accelab":  # the top package: its files, beside the linked subpackages
            target.mkdir(parents=True)
            for f in sorted(source.glob("*.py")) + sorted(source.glob("*.typed")):
                os.symlink(os.path.relpath(f, target), target / f.name)
        else:
            target.parent.mkdir(parents=True, exist_ok=True)
            os.symlink(os.path.relpath(source, target.parent), target)
    return out / "accelab"


if __name__ == "__main__":
    print(build(sys.argv[1] if len(sys.argv) > 1 else ROOT / "build" / "typecheck"))
