"""Sandboxes left running by a grading process that was killed.

Each sandbox is a bubblewrap process that the grading process starts itself, with
``--die-with-parent``: when the grader dies, the kernel kills bubblewrap, and with it
every process of the sandbox's PID namespace. That leaves one window: a grader killed
(``kill -9``) after it started bubblewrap but before bubblewrap asked to die with it
leaves the sandbox running, adopted by init, with whatever the submission started in it
(seen once, a detached ``sleep``, in a test that kills the grader at random moments).

Every sandbox names its grader: its ``/etc/passwd`` comes from the grader's folder
``accelab-etc-<grader pid>-*`` (:mod:`.sandbox`). A bubblewrap process of this user whose
grader no longer runs and is not its parent is such a leftover; the next grading run stops
it, and its whole process group, before it starts its own.
"""

import os
import re
import signal
import tempfile

from .sandbox import ETC_PREFIX
from .stop import processes


def _grader_of(argv):
    """The pid of the grader that started the sandbox of command line ``argv``, or None."""
    if not argv or os.path.basename(argv[0]) != "bwrap":
        return None
    pattern = re.compile(
        re.escape(os.path.join(tempfile.gettempdir(), ETC_PREFIX)) + r"(\d+)-[^/]+/passwd"
    )
    for arg in argv:
        m = pattern.fullmatch(arg)
        if m:
            return int(m.group(1))
    return None


def left_behind():
    """Pids of this user's sandboxes whose grader is gone: [(pid, grader pid)]."""
    found = []
    for pid, parent, _, uid, argv in processes():
        if uid != os.geteuid():
            continue
        grader = _grader_of([a.decode("utf-8", "replace") for a in argv])
        if grader is None or parent == grader or os.path.exists(f"/proc/{grader}"):
            continue
        found.append((pid, grader))
    return found


def stop_left_behind():
    """Stop every sandbox that a killed grader left running (each with its process
    group: bubblewrap leads one); returns the messages that say so, one per sandbox."""
    said = []
    for pid, grader in left_behind():
        try:
            if os.getpgid(pid) == pid:
                os.killpg(pid, signal.SIGKILL)
            else:
                os.kill(pid, signal.SIGKILL)
        except OSError:
            continue  # it ended meanwhile
        said.append(
            f"stopped a grading sandbox (process {pid}) that grading process {grader}, "
            f"killed before it could stop it, had left running"
        )
    return said
