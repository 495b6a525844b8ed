"""The sandbox a submission runs in: bubblewrap (``bwrap``), as an unprivileged
user, seeing only what a notebook needs.

Inside, a submission sees: ``/usr``, the Python installation and its virtual
environment (read-only), the ``accelab`` package's ``__init__``, ``accelab.solver``,
and of ``accelab.exercises`` only its ``__init__`` and the student-side subpackage
``student/`` (the rest, with the families and the grader, is hidden), a private
``/proc`` (its own PID namespace), a small private ``/tmp`` and ``/dev/shm``.
Not the course folder, other submissions, the source notebooks, the gradebook,
the instructor's files or environment (the environment is cleared), nor the
network (a network namespace with only loopback). Every process it starts dies
with it (PID namespace; ``--die-with-parent``). A seccomp filter
(:mod:`.seccomp`) refuses the kernel's key store, new namespaces and mounts, so
nothing passes from one submission to the next graded as the same user.

Run as root (a grading machine or CI), bwrap sets the sandbox up with full
privileges and ``setpriv`` drops to a uid of its own per parallel slot
(:data:`BASE_UID` + slot), with no capabilities and ``no_new_privs``: a real
unprivileged user, so the process limits apply. Run as an ordinary user, bwrap
uses an unprivileged user namespace and the sandbox runs as ``nobody`` inside
it (the instructor's own uid outside).
"""

import atexit
import functools
import importlib
import os
import shutil
import stat
import subprocess
import sys
import tempfile

from . import seccomp

#: first uid of the sandbox users when grading as root (one per parallel slot)
BASE_UID = 61000
#: what the sandbox shows of ``accelab.exercises``: everything else of it is hidden
STUDENT_SIDE = ("__init__.py", "student")
#: working directory (and HOME) inside the sandbox
WORKDIR = "/tmp/work"
#: the sandbox's XDG_CACHE_HOME: the grader's parse of pint's unit definitions, read-only
#: (accelab.solver.unitcache), so that a kernel does not parse them again (0.1 s a run)
CACHE_HOME = "/run/accelab-cache"

INSTALL_HINT = (
    "install bubblewrap (Debian/Ubuntu: `sudo apt-get install bubblewrap`; "
    "Fedora: `sudo dnf install bubblewrap`), and on a machine that restricts "
    "user namespaces grade as root or allow them "
    "(`sysctl kernel.unprivileged_userns_clone=1`)"
)


class Command(list):
    """A command line, and the file descriptors to pass to it (``pass_fds``): the
    caller closes them once the process has started (:func:`close_fds`)."""

    fds = ()


def close_fds(cmd):
    """Close the descriptors a :class:`Command` holds (once its process started)."""
    for fd in getattr(cmd, "fds", ()):
        try:
            os.close(fd)
        except OSError:
            pass


#: the temporary folders of the sandbox's passwd and group: PREFIX<pid>-<random>
ETC_PREFIX = "accelab-etc-"


def remove_stale_etc():
    """Remove the passwd folders that grading processes which no longer run left
    in the temporary directory (a process killed with SIGKILL runs no exit
    handler); only this user's, only of processes that are gone."""
    remove_left_behind(ETC_PREFIX)


def remove_left_behind(prefix):
    """Remove the temporary folders ``PREFIX<pid>-*`` of grading processes that no
    longer run (a process killed with SIGKILL runs no exit handler); only this
    user's, only of processes that are gone, never through a link."""
    root = tempfile.gettempdir()
    try:
        names = os.listdir(root)
    except OSError:
        return
    for name in names:
        if not name.startswith(prefix):
            continue
        pid = name[len(prefix) :].split("-")[0]
        path = os.path.join(root, name)
        try:
            info = os.lstat(path)
        except OSError:
            continue
        if info.st_uid != os.geteuid() or not os.path.isdir(path) or os.path.islink(path):
            continue
        if pid.isdigit() and os.path.exists(f"/proc/{pid}"):
            continue  # its process still runs
        shutil.rmtree(path, ignore_errors=True)


class SandboxUnavailable(RuntimeError):
    """No working sandbox on this machine; the message says how to get one."""


def _package_dir(name):
    module = importlib.import_module(name)
    return os.path.dirname(os.path.abspath(module.__file__))


def _as_root():
    return os.geteuid() == 0


def _own_unit_cache():
    """The grader's folder of pint's parsed unit definitions, if it has one: a real
    folder of this user's (never a link), which the sandbox shows read-only."""
    from accelab.solver.unitcache import cache_folder

    folder = cache_folder()
    try:
        info = os.lstat(folder) if folder else None
    except OSError:
        return None
    if info is None or not stat.S_ISDIR(info.st_mode) or info.st_uid != os.geteuid():
        return None
    return str(folder)


class SandboxCommand:
    """Builds the bwrap command line that runs ``argv`` in a sandbox."""

    def __init__(self, bwrap=None):
        self.bwrap = bwrap or shutil.which("bwrap")
        self.prefixes = sorted({os.path.realpath(p) for p in (sys.prefix, sys.base_prefix)})
        self.accelab_dir = _package_dir("accelab")
        self.solver_dir = _package_dir("accelab.solver")
        self.exercises_dir = _package_dir("accelab.exercises")
        self.unit_cache = _own_unit_cache()
        self._etc = None

    def _etc_files(self):
        """A passwd and group that name the sandbox's user (getpass and friends),
        in a temporary folder removed when this process ends (and, if it was
        killed, by the next one: :func:`remove_stale_etc`); made again if
        something removed it from the shared temporary directory."""
        if self._etc is None or not os.path.isfile(os.path.join(self._etc, "group")):
            remove_stale_etc()
            folder = tempfile.mkdtemp(prefix=f"{ETC_PREFIX}{os.getpid()}-")
            atexit.register(shutil.rmtree, folder, True)
            with open(os.path.join(folder, "passwd"), "w") as fh:
                fh.write(
                    "root:x:0:0::/:/usr/sbin/nologin\n"
                    f"student:x:{BASE_UID}:{BASE_UID}::{WORKDIR}:/usr/sbin/nologin\n"
                    "nobody:x:65534:65534::/:/usr/sbin/nologin\n"
                )
            with open(os.path.join(folder, "group"), "w") as fh:
                fh.write(f"root:x:0:\nstudent:x:{BASE_UID}:\nnogroup:x:65534:\n")
            os.chmod(folder, 0o755)
            self._etc = folder
        return self._etc

    def command(self, argv, slot=0, env=None, limits=None):
        """The full command line for ``argv`` (a list) in slot ``slot``."""
        if not self.bwrap:
            raise SandboxUnavailable(f"bubblewrap (bwrap) is not installed: {INSTALL_HINT}")
        limits = limits or {}
        args = [
            self.bwrap,
            "--unshare-pid",
            "--unshare-net",
            "--unshare-ipc",
            "--unshare-uts",
            "--unshare-cgroup-try",
            "--die-with-parent",
            "--new-session",
            "--hostname",
            "sandbox",
            "--clearenv",
        ]
        if not _as_root():
            args += ["--unshare-user", "--uid", "65534", "--gid", "65534", "--disable-userns"]
        args += ["--ro-bind", "/usr", "/usr"]
        for link in ("bin", "lib", "lib64", "sbin", "lib32"):
            path = os.path.join("/", link)
            if os.path.islink(path):
                args += ["--symlink", os.readlink(path), path]
            elif os.path.isdir(path):
                args += ["--ro-bind", path, path]
        etc = self._etc_files()
        for name in ("passwd", "group"):
            args += ["--ro-bind", os.path.join(etc, name), f"/etc/{name}"]
        for name in ("ld.so.cache", "localtime", "nsswitch.conf"):
            if os.path.exists(f"/etc/{name}"):
                args += ["--ro-bind", f"/etc/{name}", f"/etc/{name}"]
        args += ["--proc", "/proc"]
        for name in ("keys", "key-users"):  # no key of the machine's, not even its name
            if os.path.exists(f"/proc/{name}"):
                args += ["--ro-bind", "/dev/null", f"/proc/{name}"]
        args += [
            "--dev",
            "/dev",
            "--perms",
            "1777",
            "--size",
            str(int(limits.get("disk_bytes", 64 << 20))),
            "--tmpfs",
            "/tmp",
            "--perms",
            "1777",
            "--size",
            str(int(limits.get("shm_bytes", 16 << 20))),
            "--tmpfs",
            "/dev/shm",
        ]
        bound = []
        for path in self.prefixes:
            args += self._dirs_to(path, bound) + ["--ro-bind", path, path]
            bound.append(path)
        if not self._inside(self.accelab_dir, bound):  # the package's __init__ alone
            init = os.path.join(self.accelab_dir, "__init__.py")
            args += self._dirs_to(self.accelab_dir, bound)
            args += ["--perms", "0755", "--dir", self.accelab_dir, "--ro-bind", init, init]
        if not self._inside(self.solver_dir, bound):
            args += self._dirs_to(self.solver_dir, bound)
            args += ["--ro-bind", self.solver_dir, self.solver_dir]
            bound.append(self.solver_dir)
        # exercises: an empty directory with only its __init__ and student/ in it
        args += self._dirs_to(self.exercises_dir, bound)
        args += ["--perms", "0755", "--tmpfs", self.exercises_dir]
        for name in STUDENT_SIDE:
            path = os.path.join(self.exercises_dir, name)
            args += ["--ro-bind", path, path]
        if self.unit_cache:
            inside = os.path.join(CACHE_HOME, "accelab", os.path.basename(self.unit_cache))
            args += self._dirs_to(inside, bound) + ["--ro-bind", self.unit_cache, inside]
            args += ["--setenv", "XDG_CACHE_HOME", CACHE_HOME]
        args += ["--perms", "1777", "--dir", WORKDIR, "--chdir", WORKDIR]
        for key, value in (env or {}).items():
            args += ["--setenv", key, value]
        rules = seccomp.program()
        fds = ()
        if rules is not None:
            fds = (seccomp.filter_fd(rules),)
            args += ["--seccomp", str(fds[0])]
        args += ["--"]
        if _as_root():
            uid = str(BASE_UID + int(slot))
            args += [
                "setpriv",
                f"--reuid={uid}",
                f"--regid={uid}",
                "--clear-groups",
                "--inh-caps=-all",
                "--bounding-set=-all",
                "--no-new-privs",
            ]
        cmd = Command(args + list(argv))
        cmd.fds = fds
        return cmd

    @staticmethod
    def _inside(path, bound):
        return any(path == b or path.startswith(b.rstrip("/") + "/") for b in bound)

    def _dirs_to(self, path, bound):
        """``--dir`` for each ancestor of ``path`` not under a bound directory, so
        that the unprivileged user can walk down to it."""
        args, parts = [], []
        parent = os.path.dirname(path)
        while parent not in ("/", ""):
            parts.append(parent)
            parent = os.path.dirname(parent)
        for ancestor in reversed(parts):
            if not self._inside(ancestor, bound):
                args += ["--perms", "0755", "--dir", ancestor]
        return args


@functools.lru_cache(maxsize=1)
def sandbox():
    """The machine's :class:`SandboxCommand`, checked once to really work.

    Raises :class:`SandboxUnavailable` with what to do when it does not.
    """
    builder = SandboxCommand()
    probe = (
        "import os, sys; "
        "import accelab.exercises.student.kernel, accelab.exercises.student.runtime; "
        "from accelab import exercises; "
        "hidden = not os.path.exists(os.path.join(os.path.dirname(exercises.__file__), "
        "'grader')); print(os.getuid() != 0 and hidden and len(os.listdir('/proc')) > 0)"
    )
    cmd = None
    try:
        cmd = builder.command([sys.executable, "-I", "-c", probe], env={"PATH": "/usr/bin"})
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=60, pass_fds=cmd.fds)
    except SandboxUnavailable:
        raise
    except (OSError, subprocess.SubprocessError) as exc:
        raise SandboxUnavailable(f"bubblewrap could not run ({exc}): {INSTALL_HINT}") from None
    finally:
        close_fds(cmd)
    if proc.returncode != 0 or proc.stdout.strip() != "True":
        detail = (proc.stderr.strip().splitlines() or ["no output"])[-1][:300]
        raise SandboxUnavailable(
            f"bubblewrap does not work on this machine ({detail}): {INSTALL_HINT}"
        )
    return builder


def check_sandbox():
    """None when a sandbox works here, else the message that says how to get one."""
    try:
        sandbox()
    except SandboxUnavailable as exc:
        return str(exc)
    return None
