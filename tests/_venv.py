"""A new virtual environment that holds this test environment's packages without installing
them again: their files hard-linked (copied across filesystems) from this environment into
the new one, so that they are real files inside its prefix (the grading sandbox shows a
venv's own prefix), with no network and no resolver, in a second or two.

The editable install of this checkout is left out: the caller installs accelab into the new
environment itself (from a wheel), as a user gets it. A package whose ``Requires-Python``
excludes the new environment's interpreter (Debian's 3.11.2 is older than some packages
allow) is installed there again by pip, in the newest version that allows it.
"""

import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

#: the editable install of this checkout (setuptools' finder, its .pth and its metadata), and
#: its JupyterLab extension, which the Makefile links into the environment from the checkout
EDITABLE = ("__editable__*", "accelab-*.dist-info", "accelab.egg-link", "accelab-lab")
#: the test environment's own start-up file (``.ci/lazy_iri_pth.py``: jsonschema's IRI grammar
#: deferred in every process): an environment as users get it leaves it out
TESTS_ONLY = ("zz-accelab-tests-lazy-iri.pth",)


def _link(src, dst):
    try:
        os.link(src, dst)
    except OSError:  # another filesystem
        shutil.copy2(src, dst)


def _tree(src, dst, leave_out=()):
    shutil.copytree(
        src,
        dst,
        ignore=shutil.ignore_patterns(*EDITABLE, *leave_out),
        copy_function=_link,
        symlinks=True,
        dirs_exist_ok=True,
    )


def packages():
    """The distributions of this environment (``name-version.dist-info``), without accelab:
    what a linked environment holds."""
    purelib = Path(sysconfig.get_paths()["purelib"])
    return sorted(
        p.name
        for p in purelib.glob("*.dist-info")
        if not p.name.lower().startswith(("accelab-", "accelab.")) and p.is_dir()
    )


def tests_only():
    """The files of :data:`TESTS_ONLY` this environment has."""
    purelib = Path(sysconfig.get_paths()["purelib"])
    return [name for name in TESTS_ONLY if (purelib / name).is_file()]


def _scripts(src_bin, dst_bin, python):
    """The console scripts of this environment's packages (jupyter, jupyterhub, nbgrader,
    ...), made to run with ``python``; compiled tools and the venv's own files are left
    out."""
    old = str(src_bin)
    for path in sorted(Path(src_bin).iterdir()):
        if path.name.startswith(("python", "activate", "Activate")) or not path.is_file():
            continue
        head = path.read_bytes()[:512]
        if not head.startswith(b"#!"):
            continue  # a compiled program (ruff)
        text = path.read_text()
        lines = text.split("\n", 2)
        # pip writes `#!PYTHON`, or for a long path `#!/bin/sh` and an `exec` line
        for k in range(min(2, len(lines))):
            lines[k] = lines[k].replace(f"{old}/python", str(python))
        target = Path(dst_bin) / path.name
        target.write_text("\n".join(lines))
        target.chmod(0o755)


#: run by the new environment's Python: the packages whose Requires-Python excludes it
INCOMPATIBLE = """
import importlib.metadata as md, platform
from packaging.specifiers import SpecifierSet
for d in md.distributions():
    need = d.metadata.get("Requires-Python")
    if need and platform.python_version() not in SpecifierSet(need):
        print(d.metadata["Name"])
"""


def linked_venv(venv, python=sys.executable, data=False, as_tests_run=False):
    """Make the venv ``venv`` of the interpreter ``python`` (a Python of this environment's
    version), holding this environment's packages but not accelab; with ``data``, also their
    console scripts and data files (``share/``: JupyterLab and its extensions; ``etc/``: the
    Jupyter server's extensions); with ``as_tests_run``, also the test environment's own
    start-up file (:data:`TESTS_ONLY`), which an environment as users get it has not.
    Returns the venv's Python."""
    venv = Path(venv)
    subprocess.run(
        [str(python), "-m", "venv", "--without-pip", str(venv)], check=True, capture_output=True
    )
    new_python = venv / "bin" / "python"
    target = subprocess.run(
        [str(new_python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        capture_output=True,
        text=True,
        check=True,
        cwd="/",
    ).stdout.strip()
    _tree(sysconfig.get_paths()["purelib"], target, () if as_tests_run else TESTS_ONLY)
    if data:
        for folder in ("share", "etc"):
            if (Path(sys.prefix) / folder).is_dir():
                _tree(Path(sys.prefix) / folder, venv / folder)
        _scripts(Path(sys.prefix) / "bin", venv / "bin", new_python)
    other = subprocess.run(
        [str(new_python), "-c", INCOMPATIBLE], capture_output=True, text=True, check=True, cwd="/"
    ).stdout.split()
    if other:  # pip (linked with the rest) finds the newest version this Python allows
        pip = [str(new_python), "-m", "pip", "install", "-q", "--no-deps", "--force-reinstall"]
        done = subprocess.run([*pip, *other], capture_output=True, text=True, cwd="/")
        assert done.returncode == 0, (
            f"{other} (their Requires-Python excludes {python}) could not be installed again "
            f"in {venv}:\n{done.stdout[-2000:]}\n{done.stderr[-3000:]}"
        )
    return new_python
