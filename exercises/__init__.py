"""Randomized exercises on acceleration analysis, graded with nbgrader: the
student's kernel only reports, the grader judges outside it.

The student's side (the only modules a graded notebook can import inside the
grading sandbox):

* :mod:`exercises.runtime` -- what a notebook imports: the student's values, the
  visible checks of form and dimension;
* :mod:`exercises.answers` -- reading an answer (one place, both sides);
* :mod:`exercises.kernel` -- runs a submission's cells inside the sandbox.

The instructor's side:

* :mod:`exercises.families` -- one generator per problem family, ``(seed,
  ranges=None, units="US") -> Problem``; :mod:`exercises.assignment` -- specs and
  variants; :mod:`exercises.seeding` -- stable seeds; :mod:`exercises.expr` -- the
  safe evaluator of an answer's ``expr``; :mod:`exercises.problem` -- the data;
* :mod:`exercises.notebook`, :mod:`exercises.nbgrader_course`,
  :mod:`exercises.assign`, :mod:`exercises.variant`, :mod:`exercises.demo`,
  :mod:`exercises.cli` -- the nbgrader course and the commands;
* :mod:`exercises.grader` -- the key, the sandbox, judging and the grade table;
* :mod:`exercises.practice` -- ungraded practice with instant feedback, for
  self-study (never part of a graded assignment).
"""
