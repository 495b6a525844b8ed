"""Second local accounts for the tests that act as students (the tests run as root).

An account is made with ``useradd`` (no home, no login shell) the first time it is
needed. Its commands run with its own uid and groups (``setpriv``), so nbgrader's
exchange sees that account as the owner of what it hands in. The interpreter of
these tests may live where other accounts cannot reach it (pyenv under
``/root``): each command runs in a mount namespace of its own (``bwrap``, as root)
where every folder above the interpreter, its virtual environment and the project
is reachable (a fresh tmpfs stands over an unreachable parent such as ``/root``,
with the interpreter's folders bound read-only into it); the rest of the file
system is the real one, so every file the account writes is really its own.
"""

import os
import pwd
import shutil
import stat
import subprocess
import sys
import tempfile

import accelab

#: every account these tests make starts with this (none of the machine's own does)
PREFIX = "axl"


def account(name):
    """(uid, gid) of the local account ``name``, made if missing."""
    try:
        info = pwd.getpwnam(name)
    except KeyError:
        subprocess.run(
            ["useradd", "--no-create-home", "--shell", "/usr/sbin/nologin", "--user-group", name],
            check=True,
            capture_output=True,
        )
        info = pwd.getpwnam(name)
    return info.pw_uid, info.pw_gid


def _hidden_top(path):
    """The topmost folder above ``path`` that other accounts cannot enter, or None."""
    parts = os.path.realpath(path).split(os.sep)
    for k in range(2, len(parts)):
        folder = os.sep.join(parts[:k])
        if not os.stat(folder).st_mode & stat.S_IXOTH:
            return folder
    return None


def reachable_binds():
    """bwrap arguments that make the interpreter, its environment and the project
    reachable by any account (read-only), leaving the rest as it is."""
    needed = {
        os.path.realpath(p)
        for p in (
            sys.base_prefix,
            sys.prefix,
            os.path.dirname(os.path.realpath(sys.executable)),
            os.path.dirname(os.path.dirname(os.path.abspath(accelab.__file__))),
        )
    }
    tops = {}
    for path in sorted(needed):
        top = _hidden_top(path)
        if top:
            tops.setdefault(top, []).append(path)
    args = []
    for top, paths in tops.items():
        args += ["--perms", "0755", "--tmpfs", top]
        made = {top}
        for path in paths:
            parent, chain = os.path.dirname(path), []
            while parent not in made and parent.startswith(top + os.sep):
                chain.append(parent)
                parent = os.path.dirname(parent)
            for folder in reversed(chain):
                args += ["--perms", "0755", "--dir", folder]
                made.add(folder)
            args += ["--ro-bind", path, path]
    return args


def class_folder():
    """A fresh folder every account can enter (pytest's own temp folder is root's
    alone); the caller removes it (:func:`remove`)."""
    folder = tempfile.mkdtemp(prefix="accelab-class-", dir="/tmp")
    os.chmod(folder, 0o755)
    return folder


def remove(folder):
    shutil.rmtree(folder, ignore_errors=True)


def home_of(name, base):
    """A home folder for ``name`` under ``base``, the account's own (mode 700)."""
    uid, gid = account(name)
    home = os.path.join(base, "home", name)
    os.makedirs(home, exist_ok=True)
    os.chown(home, uid, gid)
    os.chmod(home, 0o700)
    os.chmod(os.path.dirname(home), 0o755)
    return home


def run_as(name, argv, cwd, env=None, check=True, input=None):
    """Run ``argv`` as the account ``name`` in ``cwd`` (HOME is ``cwd``); returns the
    CompletedProcess (text)."""
    uid, gid = account(name)
    bindir = os.path.dirname(sys.executable)
    environ = {
        "PATH": f"{bindir}:/usr/bin:/bin",
        "HOME": cwd,
        "USER": name,
        "LOGNAME": name,
        "LANG": "C.UTF-8",
        "PYTHONDONTWRITEBYTECODE": "1",
        "MPLBACKEND": "Agg",
        **(env or {}),
    }
    cmd = [shutil.which("bwrap"), "--dev-bind", "/", "/", *reachable_binds(), "--chdir", cwd]
    cmd += ["--", "setpriv", f"--reuid={uid}", f"--regid={gid}", "--init-groups", "env", "-i"]
    cmd += [f"{k}={v}" for k, v in environ.items()] + list(argv)
    proc = subprocess.run(cmd, capture_output=True, text=True, input=input)
    if check:
        assert proc.returncode == 0, (name, argv, proc.stdout[-2000:], proc.stderr[-3000:])
    return proc


def python_as(name, code, cwd, check=True):
    """Run Python ``code`` as the account ``name``; returns its stdout."""
    return run_as(name, [sys.executable, "-c", code], cwd, check=check).stdout


def nbgrader_as(name, *args, cwd, check=True):
    """``nbgrader ARGS`` as the student account ``name``, from its home ``cwd``."""
    return run_as(name, [sys.executable, "-m", "nbgrader", *args], cwd, check=check)
