"""A context in which generating a variant shows no warnings: in a student's
notebook it prints nothing but what the notebook shows.

Nothing of the process is redirected: ``sys.stderr`` stays where it is, so a
progress bar, an error or "interrupted" written by another thread (the grader
runs several submissions at once) always reaches the terminal. numpy's
floating-point warnings are turned off for the calling thread only
(``numpy.errstate`` is thread-local). Python's warning filters are one list
for the whole process, so they are changed only in the main thread; a caller
that runs this in worker threads (``accelab grade``) ignores warnings itself,
from its main thread, for the duration of the run.
"""

import contextlib
import threading
import warnings

import numpy as np


@contextlib.contextmanager
def silenced():
    """No numpy floating-point warnings inside (this thread), and in the main
    thread no Python warnings either. Nothing is redirected."""
    with np.errstate(all="ignore"):
        if threading.current_thread() is threading.main_thread():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                yield
        else:
            yield
