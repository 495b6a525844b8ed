"""accelab's course: acceleration analysis of planar linkages, one notebook per topic.

The notebooks are kept as jupytext percent-format scripts (``NN_slug.py``) with
no outputs in git; ``tests/test_course.py`` executes every one of them, and
``make docs`` publishes them as the course section of the documentation
site in ``build/docs/`` (see ``docs/``). :mod:`course.coursekit` holds the little
the notebooks share (the ``explore`` control, number formatting, plot style).
"""
