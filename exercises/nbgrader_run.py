"""``nbgrader ARGS`` run in this process, as the ``nbgrader`` command runs it from a
course folder: the same application (:class:`nbgrader.apps.nbgraderapp.NbGraderApp`),
the same command line, the same configuration files (the Jupyter paths', then the
course folder's, which nbgrader finds in its working folder), the same log on its
stderr; what it prints and its exit status are given back as a
:class:`subprocess.CompletedProcess`.

A new interpreter for each run spent about 2.5 s of CPU importing nbgrader before it
did anything (``accelab assign`` runs generate_assignment, and release_assignment with
``--release``). nbgrader's own test suite runs its commands in-process the same way
(``initialize``, ``start``, ``reset``); its converters change the working folder
themselves (``BaseConverter.start``). Here the working folder is the course folder for
the run's duration (one run at a time in this process), and what nbgrader changes of
the process (the working folder it puts first on ``sys.path``, the application
singletons) is undone afterwards.
"""

import contextlib
import io
import os
import subprocess
import sys
import threading

from .nbgrader_course import ensure_path

_ONE_AT_A_TIME = threading.Lock()


def nbgrader_here(course_dir, *args):
    """Run ``nbgrader ARGS`` in ``course_dir``, in this process (see the module);
    returns a CompletedProcess with its exit status, stdout and stderr (text)."""
    from jupyter_core.application import NoStart
    from nbgrader.apps.nbgraderapp import NbGraderApp

    ensure_path()  # nbgrader's gradebook calls `alembic` from PATH
    out, err = io.StringIO(), io.StringIO()
    status = 0
    with _ONE_AT_A_TIME:
        cwd, hook = os.getcwd(), sys.excepthook
        folder = os.path.realpath(course_dir)  # what os.getcwd() gives there
        before = sys.path.count(folder)
        try:
            os.chdir(folder)
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                NbGraderApp.clear_instance()
                app = NbGraderApp.instance()  # its log goes to the stderr set here
                try:
                    app.initialize(list(args))
                    app.start()
                except NoStart:  # the end of a run (JupyterApp.launch_instance takes it so)
                    pass
                except SystemExit as exc:
                    status = _status(exc.code, err)
                except Exception:  # noqa: BLE001 - a crash of nbgrader's: said on its stderr
                    import traceback

                    traceback.print_exc()
                    status = 1
                finally:
                    app.reset()
        finally:
            os.chdir(cwd)
            while sys.path.count(folder) > before:  # nbgrader's apps put it first, each
                sys.path.remove(folder)
            sys.excepthook = hook
    return subprocess.CompletedProcess(["nbgrader", *args], status, out.getvalue(), err.getvalue())


def _status(code, err):
    """The exit status ``sys.exit(code)`` gives (a message is printed on stderr, status 1)."""
    if code is None:
        return 0
    if isinstance(code, int):
        return code
    print(code, file=err)
    return 1
