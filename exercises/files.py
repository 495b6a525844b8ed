"""Course files replaced whole or not at all.

Every file the instructor's side writes (grade table, specification, roster,
outcomes, grading records, feedback pages) is written beside its place, flushed
to the disk and renamed over the old one: a full disk, a write error or a kill
at any moment leaves either the old file or the new one, never a part of
either. A failure raises :class:`WriteError`, whose message names the file and
says what to do.

``ACCELAB_FAULT`` (tests only) makes chosen writes fail or the process die at a
named stage; see :func:`fault`.
"""

import errno
import os
import re
import signal
import tempfile

#: what to do, by errno, when a file cannot be written
NEXT_STEP = {
    errno.ENOSPC: "the disk is full: free some space on it",
    errno.EDQUOT: "the disk quota is used up: free some space",
    errno.EROFS: "the file system is read-only: make it writable",
    errno.EACCES: "permission denied: make the folder writable for you",
    errno.EPERM: "permission denied: make the folder writable for you",
    errno.EIO: "the disk reported an input/output error: check the disk",
    errno.EFBIG: "the file would be too large for the file system",
}


class WriteError(OSError):
    """A course file could not be written; the old one, if any, is unchanged."""

    def __init__(self, path, exc):
        self.path = path
        cause = getattr(exc, "strerror", None) or str(exc)
        step = NEXT_STEP.get(getattr(exc, "errno", None), "")
        message = f"could not write {path}: {cause}"
        if step:
            message += f" ({step})"
        super().__init__(getattr(exc, "errno", None) or errno.EIO, message)
        self.message = message

    def __str__(self):
        return self.message


def fault(stage, path=""):
    """The fault-injection hook of the tests: ``ACCELAB_FAULT`` holds entries
    ``kill:STAGE`` or ``kill:STAGE@N`` (the process kills itself with SIGKILL
    the N-th time, 1 by default, it reaches STAGE) and ``enospc:TEXT`` (a write
    of a path that contains TEXT fails as on a full disk), separated by commas.
    Unset (always, outside the tests), it does nothing."""
    spec = os.environ.get("ACCELAB_FAULT")
    if not spec:
        return
    for entry in spec.split(","):
        kind, _, rest = entry.partition(":")
        if kind == "kill":
            name, _, nth = rest.partition("@")
            if name == stage:
                _COUNTS[name] = _COUNTS.get(name, 0) + 1
                if _COUNTS[name] == int(nth or 1):
                    os.kill(os.getpid(), signal.SIGKILL)
        elif kind == "enospc" and stage == "write" and rest and rest in path:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


_COUNTS = {}


def _mode_for(path, default=0o644):
    try:
        return os.stat(path).st_mode & 0o7777
    except OSError:
        return default


def write_atomic(path, data, mode=None, stage="write", durable=True):
    """Replace ``path`` with ``data`` (str, written as UTF-8, or bytes) in one
    step: written beside it, fsynced, renamed over it. Raises
    :class:`WriteError` (the old file unchanged, nothing left beside it).

    ``durable=False`` skips the fsync, for a record whose reader takes a
    damaged file for none (a power cut may leave it empty; a killed process
    never does). The folder is not fsynced: after a power cut a rename may be
    lost, leaving the old file, whole. ``stage`` names the write for
    :func:`fault` (``STAGE-unrenamed``: written beside, not yet renamed)."""
    path = os.fspath(path)
    if isinstance(data, str):
        data = data.encode("utf-8")
    folder = os.path.dirname(os.path.abspath(path))
    tmp = None
    try:
        os.makedirs(folder, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{os.path.basename(path)}.", suffix=".part", dir=folder)
        with os.fdopen(fd, "wb") as fh:
            fault("write", path)
            fh.write(data)
            fh.flush()
            if durable:
                os.fsync(fh.fileno())
        os.chmod(tmp, mode if mode is not None else _mode_for(path))
        fault(f"{stage}-unrenamed")
        os.replace(tmp, path)
        tmp = None
    except OSError as exc:
        raise WriteError(path, exc) from None
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def copy_atomic(src, dest):
    """Replace ``dest`` with a copy of the regular file ``src`` (never through a
    link), unless it holds the same bytes already."""
    fd = os.open(src, os.O_RDONLY | os.O_NOFOLLOW)
    with os.fdopen(fd, "rb") as fh:
        data = fh.read()
    try:
        with open(dest, "rb") as fh:
            if fh.read(len(data) + 1) == data:
                return
    except OSError:
        pass
    write_atomic(dest, data)


#: the name write_atomic gives a file it writes beside its place
PARTIAL = re.compile(r"^\..+\.[A-Za-z0-9_]+\.part$")


def remove_partial(folder, recursive=True):
    """Remove what :func:`write_atomic` left beside its files when its process
    was killed while it wrote (call only where no other writer works: with the
    course lock held). Returns how many it removed."""
    removed = 0
    for root, _dirs, files in os.walk(folder) if os.path.isdir(folder) else []:
        for name in files:
            if PARTIAL.match(name):
                try:
                    os.unlink(os.path.join(root, name))
                    removed += 1
                except OSError:
                    pass
        if not recursive:
            break
    return removed
