"""Randomized exercises on acceleration analysis, graded with nbgrader: the
student's kernel only reports, the grader judges outside it.

The student's side, :mod:`accelab.exercises.student` (``exercises/student/``), is the only
code of this package a graded notebook can import inside the grading sandbox: the
boundary is a folder. It holds the runtime a notebook imports, the one reader of an
answer, and the kernel that runs a submission's cells and only reports.

The instructor's side:

* :mod:`accelab.exercises.families` -- one generator per problem family, ``(seed,
  ranges=None, units="US") -> Problem``; :mod:`accelab.exercises.assignment` -- specs and
  variants; :mod:`accelab.exercises.seeding` -- stable seeds; :mod:`accelab.exercises.expr` -- the
  safe evaluator of an answer's ``expr``; :mod:`accelab.exercises.problem` -- the data;
* :mod:`accelab.exercises.notebook`, :mod:`accelab.exercises.nbgrader_course`,
  :mod:`accelab.exercises.assign`, :mod:`accelab.exercises.variant`, :mod:`accelab.exercises.demo`,
  :mod:`accelab.exercises.cli` -- the nbgrader course and the commands;
* :mod:`accelab.exercises.grader` -- the key, the sandbox, judging and the grade table;
* :mod:`accelab.exercises.practice` -- ungraded practice with instant feedback, for
  self-study (never part of a graded assignment).
"""
