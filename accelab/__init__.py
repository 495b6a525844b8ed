"""accelab: acceleration analysis of planar linkages, as a library, a course and graded exercises.

One import package. Its subpackages are the project's layers, each kept in its own top-level
folder of the repository and mapped here when installed (``setup.py``; the README's "How the
code is laid out"):

* :mod:`accelab.solver` (``solver/``) -- the library: unit-free kernels, the unit-aware
  mechanisms, the vector-loop solver, the graphical constructions;
* :mod:`accelab.exercises` (``exercises/``) -- problem generators, nbgrader integration and
  grading, with the student-side code that runs in the grading sandbox;
* :mod:`accelab.benchmarks` (``benchmarks/``) -- speed against accuracy, beside the library;
* :mod:`accelab.course` (``course/``) -- the notebooks and what they share.

The application layer is this folder itself: :mod:`accelab.cli` builds the ``accelab``
command out of the subcommands each layer registers (``register(subparsers)``). It may
import every layer and no layer imports it (``tests/test_layers.py``).

Importing ``accelab`` alone imports nothing else: the grading sandbox imports it on the way
to the student-side modules.
"""

#: the release, in one place (pyproject.toml and the documentation site read it)
__version__ = "0.2.0"
