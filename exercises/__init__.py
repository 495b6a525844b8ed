"""Randomized exercises on acceleration analysis, graded by nbgrader against the solver.

* :mod:`exercises.families` -- one generator per problem family, ``(seed, ranges=None,
  units="US") -> Problem``;
* :mod:`exercises.seeding` -- the stable seed of a (course, assignment, student);
* :mod:`exercises.expr` -- the safe evaluator of an answer's ``expr`` (answer key and
  published variant use the same one);
* :mod:`exercises.grading` -- dimension, then value, with hints;
* :mod:`exercises.runtime` -- what the student's notebook imports;
* :mod:`exercises.notebook`, :mod:`exercises.course`, :mod:`exercises.autograde`,
  :mod:`exercises.variant`, :mod:`exercises.demo` -- the nbgrader side and the CLI.
"""
