"""The installed layout of the package as a tree of symbolic links, for tools that read
source files by import name but cannot see setuptools' editable finder (mypy).

``python .ci/layout.py build/typecheck`` makes ``build/typecheck/accelab/`` whose
subpackages link to the repository's folders as setup.py maps them (``accelab/solver`` ->
``solver/`` ...): ``mypy`` with ``MYPYPATH=build/typecheck`` then checks
``accelab.solver`` where it really is. The mapping is read from setup.py (its ``LAYERS``),
so this script holds no copy of it. With ``--mypy-cache`` it prints the cache folder mypy
is to use for the layout's set of modules (:func:`mypy_cache`) instead.
"""

import ast
import hashlib
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


def mypy_cache(package, root=ROOT / ".mypy_cache"):
    """mypy's cache folder for the package's present set of modules: ``root/files-DIGEST``,
    the digest of the sorted module paths; the caches of other sets are removed.

    mypy 2.4's incremental cache can keep a module's missing submodule missing after the
    file is written (a mechanism's class checked before its kernel existed: "Module
    accelab.solver.kernels has no attribute NAME" on every later run, python/mypy#20799).
    A file added or removed starts a fresh cache (a full check, about 7 s on 2 cores); an
    edit keeps the cache (a fraction of a second)."""
    names = sorted(  # the subpackages are links to folders: followed
        os.path.relpath(os.path.join(folder, f), package)
        for folder, dirs, files in os.walk(package, followlinks=True)
        for f in files
        if f.endswith(".py") and "__pycache__" not in folder
    )
    digest = hashlib.sha1("\n".join(names).encode()).hexdigest()[:12]
    root = Path(root)
    for old in root.glob("files-*"):
        if old.name != f"files-{digest}":
            shutil.rmtree(old, ignore_errors=True)
    return root / f"files-{digest}"


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    package = build(args[0] if args else ROOT / "build" / "typecheck")
    print(mypy_cache(package) if "--mypy-cache" in sys.argv else package)
