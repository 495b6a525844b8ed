"""``accelab ARGV`` (or ``nbgrader ARGV``) in a process of its own, forked from the
test's process instead of started as a new interpreter.

A grading test needs a real process for what it checks: one that kill -9 ends at a
stage, that Ctrl-C stops, that holds the course while another grader tries it, or
that grades with an environment of its own. A new interpreter spends 2-3 s of CPU
importing nbgrader, nbformat and accelab before it does any of that; a fork starts
with them imported. The child is made what a new process would be: its own
environment (``TMPDIR`` included), its standard streams on files, stdin from
/dev/null, the signal handlers Python starts with, no exit handler of the test's
process (its own run at a normal exit, as in a new interpreter: the sandbox's
passwd folder is removed), and accelab's per-process state (the sandbox's passwd folder,
the fault counters, the keys) fresh; the check that bubblewrap works here, made by the
test's process, is kept. Then it runs the command's own entry
point (``accelab.cli.main``, nbgrader's ``main``) and exits with its status.

:class:`Forked` has what the tests use of :class:`subprocess.Popen` (pid, poll,
send_signal, wait, communicate, returncode: minus the signal when a signal ended
it); :func:`run` is :func:`subprocess.run` with ``capture_output=True, text=True``.
"""

import atexit
import logging
import os
import signal
import subprocess
import sys
import tempfile
import time


def _warm(program, argv):
    """Import, once, in the test's process, what the command imports (each fork then starts
    with it): accelab's command line; nbgrader's gradebook and apps for the commands that
    use them (``accelab grade``, ``accelab assign``, nbgrader's own)."""
    import accelab.cli  # noqa: F401

    if program == "nbgrader" or (argv and argv[0] in ("grade", "assign")):
        import nbgrader.apps.api
        import nbgrader.apps.nbgraderapp  # noqa: F401

        from accelab.exercises.grader import grade  # noqa: F401


def _fresh_state():
    """accelab's per-process state as a new interpreter has it."""
    from accelab.exercises import files
    from accelab.exercises.grader import nbgrader_step, sandbox, stop

    if sandbox.sandbox.cache_info().currsize:
        # bubblewrap, checked to work here by the test's process (a bwrap run that imports the
        # student's runtime: 0.35 s), stays checked; the passwd folder the sandbox shows is
        # the child's own, made as that check makes it in a new process: in its TMPDIR, the
        # ones of killed graders removed first, removed itself at its exit
        builder = sandbox.sandbox()
        builder._etc = None
        builder._etc_files()
    files._COUNTS.clear()
    nbgrader_step._KEYS.clear()
    stop.HALT.clear()
    stop._RECEIVED[0] = None


def _accelab(argv):
    from accelab.cli import main

    return main(list(argv))


def _nbgrader(argv):
    from nbgrader.apps.nbgraderapp import NbGraderApp

    NbGraderApp.clear_instance()  # a new process has none
    NbGraderApp.launch_instance(argv=list(argv))
    return 0


PROGRAMS = {"accelab": _accelab, "nbgrader": _nbgrader}


def _child(program, argv, env, cwd, out_fd, err_fd):
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.dup2(out_fd, 1)
    os.dup2(err_fd, 2)
    sys.stdin = open(0, closefd=False)
    sys.stdout = open(1, "w", buffering=1, closefd=False)
    sys.stderr = open(2, "w", buffering=1, closefd=False)
    sys.__stdout__, sys.__stderr__ = sys.stdout, sys.stderr
    os.environ.clear()
    os.environ.update(env)
    if cwd:
        os.chdir(cwd)
    tempfile.tempdir = None
    atexit._clear()
    signal.signal(signal.SIGINT, signal.default_int_handler)
    for signum in (signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT, signal.SIGUSR1):
        signal.signal(signum, signal.SIG_DFL)
    logging.root.handlers.clear()  # pytest's capture; a new process has none
    logging.root.setLevel(logging.WARNING)
    _fresh_state()
    try:
        status = PROGRAMS[program](argv)
    except SystemExit as exc:
        code = exc.code
        if code is None:
            status = 0
        elif isinstance(code, int):
            status = code
        else:
            print(code, file=sys.stderr)
            status = 1
    except KeyboardInterrupt:
        import traceback

        traceback.print_exc()
        status = None
    atexit._run_exitfuncs()
    sys.stdout.flush()
    sys.stderr.flush()
    if status is None:  # as Python does for an uncaught KeyboardInterrupt
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGINT)
    return int(status or 0)


class Forked:
    """``PROGRAM ARGV`` in a forked process (see the module); like ``subprocess.Popen``
    with ``stdout=PIPE, stderr=PIPE, text=True``."""

    def __init__(self, argv, env=None, cwd=None, program="accelab"):
        _warm(program, list(argv))
        self.args = [program, *argv]
        self.returncode = None
        self._out = tempfile.TemporaryFile()
        self._err = tempfile.TemporaryFile()
        env = dict(os.environ if env is None else env)
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # the child never returns into the test
            status = 70
            try:
                status = _child(program, argv, env, cwd, self._out.fileno(), self._err.fileno())
            except BaseException:
                import traceback

                try:
                    traceback.print_exc()
                    sys.stderr.flush()
                finally:
                    status = 1
            finally:
                os._exit(status)
        self.pid = pid

    def poll(self):
        if self.returncode is None:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                self.returncode = os.waitstatus_to_exitcode(status)
        return self.returncode

    def wait(self, timeout=None):
        deadline = None if timeout is None else time.monotonic() + timeout
        while self.poll() is None:
            if deadline is not None and time.monotonic() > deadline:
                raise subprocess.TimeoutExpired(self.args, timeout)
            time.sleep(0.02)
        return self.returncode

    def send_signal(self, signum):
        if self.returncode is None:
            os.kill(self.pid, signum)

    def kill(self):
        self.send_signal(signal.SIGKILL)

    def communicate(self, timeout=None):
        self.wait(timeout)
        return self._read(self._out), self._read(self._err)

    @staticmethod
    def _read(fh):
        fh.seek(0)
        text = fh.read().decode("utf-8")
        fh.close()
        return text


def run(argv, env=None, cwd=None, program="accelab", timeout=None):
    """``subprocess.run([PROGRAM, *argv], capture_output=True, text=True)``, forked."""
    proc = Forked(argv, env=env, cwd=cwd, program=program)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        raise
    return subprocess.CompletedProcess(proc.args, proc.returncode, out, err)
