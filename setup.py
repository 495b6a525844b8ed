"""Packaging: the repository's top-level folders are one import package, ``accelab``.

The design keeps ``solver/``, ``exercises/``, ``course/`` and ``benchmarks/`` at the top of
the repository, where a reader sees the architecture; installed, they are subpackages of
``accelab`` (``from accelab.solver import FourBar``), so that the wheel puts exactly one
name into site-packages. Everything else is in ``pyproject.toml``.
"""

from setuptools import find_namespace_packages, setup

#: import name -> the repository folder that holds it
LAYERS = {
    "accelab": "accelab",
    "accelab.solver": "solver",
    "accelab.exercises": "exercises",
    "accelab.course": "course",
    "accelab.benchmarks": "benchmarks",
}

#: every folder is a package, those of data alone too (nbgrader's and nbconvert's templates, the
#: JupyterLab extension), so that setuptools ships their files without a warning
packages = []
for name, folder in LAYERS.items():
    found = find_namespace_packages(folder, exclude=["__pycache__", "*.__pycache__"])
    packages += [name] + [f"{name}.{sub}" for sub in found]

#: accelab's JupyterLab extension (exercises/lab/: nbgrader's Validate message in an accelab
#: assignment), installed where JupyterLab finds extensions
LAB = "share/jupyter/labextensions/accelab-lab"
data_files = [
    (LAB, ["exercises/lab/package.json"]),
    (f"{LAB}/static", ["exercises/lab/static/remoteEntry.js"]),
]

setup(package_dir=LAYERS, packages=packages, data_files=data_files)
