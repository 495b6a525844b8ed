"""The student's side of the exercises: the only code of :mod:`accelab.exercises` that
a graded notebook can import inside the grading sandbox (the sandbox shows this folder
and ``exercises/__init__.py``, and hides the rest: generators, key, grader).

* :mod:`.runtime` -- what a notebook imports: the student's values, the visible checks
  of form and dimension;
* :mod:`.answers` -- reading an answer (one place, both sides: the grader reads the
  kernel's reports with it too);
* :mod:`.kernel` -- runs a submission's cells inside the sandbox and reports what the
  answer variables hold. It only reports; the grader judges, in its own process.

Nothing here imports the instructor's side (``tests/test_layers.py``), and nothing here
holds or computes an expected value.
"""
