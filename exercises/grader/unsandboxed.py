"""Running submissions without a sandbox, when an instructor explicitly accepts
the risk (``accelab grade --unsafe-no-sandbox``).

The kernel then runs as a plain child process with the instructor's rights:
it gets a cleared environment, its own temporary working directory and the
same resource limits, but it can read the course folder (source notebooks,
gradebook), change files and outlive the grading. Use it only for submissions
you trust, e.g. your own tests of an assignment.
"""

import os
import tempfile


class UnsandboxedCommand:
    """The same interface as :class:`~accelab.exercises.grader.sandbox.SandboxCommand`."""

    def command(self, argv, slot=0, env=None, limits=None):
        workdir = tempfile.mkdtemp(prefix="accelab-unsafe-")
        env = dict(env or {}, HOME=workdir, MPLCONFIGDIR=os.path.join(workdir, ".matplotlib"))
        assignments = [f"{k}={v}" for k, v in env.items()]
        return ["env", "-i", "-C", workdir, *assignments, *argv]
