"""Running submissions without a sandbox, when an instructor explicitly accepts
the risk (``accelab grade --unsafe-no-sandbox``).

The kernel then runs as a plain child process with the instructor's rights:
it gets a cleared environment, its own temporary working directory and the
same resource limits, but it can read the course folder (source notebooks,
gradebook), change files and outlive the grading. Use it only for submissions
you trust, e.g. your own tests of an assignment.

The working directories are made in one temporary folder of this process,
``accelab-unsafe-<pid>-*``, removed when the process ends (and, if it was
killed, by the next one that grades without a sandbox).
"""

import atexit
import os
import shutil
import tempfile
import threading

from .sandbox import remove_left_behind

#: the temporary folder of a grading process's working directories: PREFIX<pid>-<random>
PREFIX = "accelab-unsafe-"


class UnsandboxedCommand:
    """The same interface as :class:`~accelab.exercises.grader.sandbox.SandboxCommand`."""

    def __init__(self):
        self._root = None
        self._lock = threading.Lock()

    def _workroot(self):
        with self._lock:
            if self._root is None or not os.path.isdir(self._root):
                remove_left_behind(PREFIX)
                self._root = tempfile.mkdtemp(prefix=f"{PREFIX}{os.getpid()}-")
                atexit.register(shutil.rmtree, self._root, True)
            return self._root

    def command(self, argv, slot=0, env=None, limits=None):
        workdir = tempfile.mkdtemp(prefix=f"slot{int(slot)}-", dir=self._workroot())
        env = dict(env or {}, HOME=workdir, MPLCONFIGDIR=os.path.join(workdir, ".matplotlib"))
        assignments = [f"{k}={v}" for k, v in env.items()]
        return ["env", "-i", "-C", workdir, *assignments, *argv]
