"""accelab's application layer: the ``accelab`` command.

It holds no kinematics of its own. :mod:`accelab.cli` builds one command line
out of the subcommands that each layer registers (``register(subparsers)``):

* the solver library (:mod:`solver.cli`): ``solve``, ``draw``, ``figures``;
* the benchmark (:mod:`benchmarks.cli`): ``bench``;
* the exercises (:mod:`exercises.cli`): ``assign``, ``variant``, ``grade``, ``demo``;
* the course (``course.cli``), when that module exists.

This is the top of the import graph: it may import every layer, and no
layer imports it (``tests/test_layers.py``; the README's "How the code is
laid out").
"""
