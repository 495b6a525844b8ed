"""Stopping a grading run at once: Ctrl-C (SIGINT), SIGTERM, a closed terminal
(SIGHUP), or an error that ends the run.

nbgrader catches every exception of its autograde (a bare ``except:``), so a
KeyboardInterrupt raised inside it would be taken for the submission's failure.
While :func:`stoppable` is in force, a signal instead sets :data:`HALT` and
kills every sandbox this process started; no new sandbox starts
(:class:`Interruptible`), a run cut short is never judged
(:class:`Stopped`), and the grading loop ends after the submission at hand.
A second Ctrl-C raises KeyboardInterrupt where the program is.
"""

import contextlib
import errno
import os
import signal
import threading
import time

#: set when grading must stop: no sandbox starts, no cut-short run is judged
#:
#: :meta hide-value:
HALT = threading.Event()
#: the signal that stopped the run (None: none, or an error stopped it)
_RECEIVED = [None]
SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
NAMES = {signal.SIGINT: "Ctrl-C", signal.SIGTERM: "SIGTERM", signal.SIGHUP: "SIGHUP"}


class Stopped(Exception):
    """Grading stopped while this submission ran: its run is not a grade."""


class SandboxRefused(OSError):
    """No sandbox starts once grading is stopping."""


def received():
    """The signal that stopped grading, or None."""
    return _RECEIVED[0]


class Interruptible:
    """A sandbox command builder that starts no sandbox once :data:`HALT` is set
    (run_plan then ends at once: it takes the refusal for a sandbox that could
    not start)."""

    def __init__(self, inner):
        self.inner = inner

    def command(self, argv, slot=0, env=None, limits=None):
        if HALT.is_set():
            raise SandboxRefused(errno.ECANCELED, "grading was stopped")
        full = self.inner.command(argv, slot=slot, env=env, limits=limits)
        _PROGRAMS.add(os.fsencode(full[0]))
        if os.path.basename(full[0]) == "env":  # no sandbox: env becomes the kernel's program
            _PROGRAMS.add(os.fsencode(argv[0]))
        return full

    def __getattr__(self, name):
        return getattr(self.inner, name)


#: the programs sandboxes were started with (bwrap; ``env`` without a sandbox)
_PROGRAMS = set()


def processes():
    """(pid, parent pid, process group, owner uid, argv as bytes) of every process, read
    from /proc; a process that ends while it is read is left out."""
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as fh:
                fields = fh.read().rsplit(b")", 1)[1].split()
            with open(f"/proc/{entry}/cmdline", "rb") as fh:
                argv = fh.read().split(b"\0")
            uid = os.stat(f"/proc/{entry}").st_uid
            yield int(entry), int(fields[1]), int(fields[2]), uid, [a for a in argv if a]
        except (OSError, IndexError, ValueError):
            continue


def children():
    """(pid, process group, program) of this process's children."""
    me = os.getpid()
    return [
        (pid, group, argv[0] if argv else b"")
        for pid, parent, group, _, argv in processes()
        if parent == me
    ]


def end_sandboxes():
    """SIGKILL every sandbox this process started, with every process in it:
    each leads its own process group (bubblewrap's PID namespace and
    ``--die-with-parent`` take the rest). Other children are left alone.

    A sandbox still inside ``execve`` shows no program for an instant and is
    missed by one call: :func:`wait_for` repeats it until the run is over."""
    for pid, group, program in children():
        if group == pid and program in _PROGRAMS:
            try:
                os.killpg(group, signal.SIGKILL)
            except OSError:
                pass


def wait_for(threads_alive, seconds=30.0):
    """Kill sandboxes until ``threads_alive()`` is false (a sandbox that was
    starting as the signal came is killed on the next round)."""
    deadline = time.monotonic() + seconds
    while threads_alive() and time.monotonic() < deadline:
        end_sandboxes()
        time.sleep(0.05)


@contextlib.contextmanager
def stoppable():
    """Within: SIGINT, SIGTERM and SIGHUP stop grading (see the module). Outside
    the main thread (where Python delivers signals) it only clears :data:`HALT`."""
    HALT.clear()
    _RECEIVED[0] = None
    if threading.current_thread() is not threading.main_thread():
        try:
            yield
        finally:
            HALT.clear()
        return

    def handler(signum, frame):
        if HALT.is_set() and _RECEIVED[0] is not None:
            raise KeyboardInterrupt  # the second time: stop where it is
        _RECEIVED[0] = signum
        HALT.set()
        end_sandboxes()

    # a hangup ignored on purpose (nohup) stays ignored; Ctrl-C and SIGTERM always stop
    # (a shell starts a background job with SIGINT ignored)
    old = {
        s: signal.signal(s, handler)
        for s in SIGNALS
        if s != signal.SIGHUP or signal.getsignal(s) != signal.SIG_IGN
    }
    try:
        yield
    finally:
        for s, h in old.items():
            signal.signal(s, h)
        HALT.clear()
