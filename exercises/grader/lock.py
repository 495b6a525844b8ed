"""One ``accelab grade`` or ``accelab assign`` per course at a time.

The lock is an advisory ``flock`` on ``COURSE/.accelab/lock``: the kernel
releases it when its holder ends, however it ends (a kill -9 leaves no stale
lock). nbgrader's own commands (``export``, formgrader's manual grading,
``collect``) do not take it and keep working beside a grading run.
"""

import contextlib
import datetime
import fcntl
import json
import os
import sys


class CourseBusy(RuntimeError):
    """Another accelab command holds the course; the message says which and what to do."""


def lock_path(course_dir):
    return os.path.join(course_dir, ".accelab", "lock")


def _holder(fd):
    try:
        os.lseek(fd, 0, os.SEEK_SET)
        info = json.loads(os.read(fd, 4096).decode("utf-8"))
        return (
            f"`{info['command']}` (process {int(info['pid'])}, started {info['started']})"
            if isinstance(info, dict)
            else "another accelab command"
        )
    except (OSError, ValueError, KeyError, TypeError):
        return "another accelab command"


@contextlib.contextmanager
def course_lock(course_dir, command):
    """Hold the course for ``command`` (words, for the message another one gets).

    Raises :class:`CourseBusy` at once if another accelab command holds it.
    """
    path = lock_path(course_dir)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o644)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise CourseBusy(
                f"course {course_dir} is busy: {_holder(fd)} is working on it. Wait for it to "
                f"finish (or stop it with Ctrl-C), then run this command again"
            ) from None
        info = {
            "command": command,
            "pid": os.getpid(),
            "started": datetime.datetime.now().strftime("%Y-%m-%d %H:%M:%S"),
            "argv": sys.argv[:8],
        }
        try:  # only to tell another command who holds the course
            os.ftruncate(fd, 0)
            os.pwrite(fd, json.dumps(info).encode("utf-8"), 0)
        except OSError:
            pass
        yield
    finally:
        os.close(fd)  # releases the lock
