"""Preprocessors the course's nbgrader_config.py installs.

* :class:`StudentExecute` -- autograde's execution step: starts each kernel with
  a clean environment (only what a kernel needs: PATH, HOME, locale, temp dir)
  plus ``ACCELAB_STUDENT_ID`` = the submission's student, so the notebook
  recomputes that student's variant; per-cell time limit ``timeout``.
* :class:`HideHiddenTests` -- feedback: removes the hidden-test regions from test
  cells and shortens their error tracebacks to the message, so feedback never
  shows hidden tests or anything they compute.
"""

import os
import re

from nbgrader.preprocessors import Execute, NbGraderPreprocessor
from traitlets import Integer, List, Unicode

#: environment variables a kernel may inherit from the instructor's process
KEEP_ENV = ["PATH", "HOME", "LANG", "LC_ALL", "LC_CTYPE", "TMPDIR", "TEMP", "TMP",
            "SYSTEMROOT", "MPLBACKEND", "VIRTUAL_ENV"]


def kernel_env(student, environ=None, keep=KEEP_ENV):
    """The environment a student's kernel gets: ``keep`` names only, plus the
    student id and nbgrader's execution flag."""
    environ = os.environ if environ is None else environ
    env = {k: environ[k] for k in keep if k in environ}
    env["ACCELAB_STUDENT_ID"] = str(student)
    env["NBGRADER_EXECUTION"] = "autograde"
    env.setdefault("MPLBACKEND", "Agg")
    env["PYTHONWARNINGS"] = "ignore"
    return env


class StudentExecute(Execute):
    """nbgrader's Execute with a clean kernel environment carrying the student id."""

    timeout = Integer(10, allow_none=True,
                      help="Seconds a cell may run before it is interrupted [s]").tag(config=True)
    keep_env = List(Unicode(), default_value=KEEP_ENV,
                    help="Environment variables the kernel inherits").tag(config=True)

    def preprocess(self, nb, resources=None, km=None):
        self._student = (resources or {}).get("nbgrader", {}).get("student") or ""
        return super().preprocess(nb, resources, km)

    # nbconvert's preprocess() starts the kernel through the synchronous wrapper,
    # which calls the base class's coroutine directly: override both entries
    def start_new_kernel(self, **kwargs):
        kwargs["env"] = kernel_env(self._student, keep=self.keep_env)
        return super().start_new_kernel(**kwargs)

    async def async_start_new_kernel(self, **kwargs):
        kwargs["env"] = kernel_env(self._student, keep=self.keep_env)
        return await super().async_start_new_kernel(**kwargs)


HIDDEN = re.compile(r"[ \t]*### BEGIN HIDDEN TESTS.*?### END HIDDEN TESTS[ \t]*\n?", re.S)
ANSI = re.compile(r"\x1b\[[0-9;]*m")


class HideHiddenTests(NbGraderPreprocessor):
    """Feedback only: hidden tests out of the source, tracebacks down to the message."""

    note = Unicode("# (the value check is hidden)\n").tag(config=True)

    def preprocess_cell(self, cell, resources, index):
        meta = cell.metadata.get("nbgrader", {})
        if cell.cell_type == "code" and "### BEGIN HIDDEN TESTS" in cell.source:
            cell.source = HIDDEN.sub(self.note, cell.source)
        if cell.cell_type == "code" and meta.get("grade"):
            for out in cell.get("outputs", []):
                if out.get("output_type") == "error":
                    out["traceback"] = [ANSI.sub("", f"{out.get('ename')}: {out.get('evalue')}")]
        return cell, resources
