"""The sandbox and its supervisor, without nbgrader: what a submission can see
and do, and how the supervisor copes with a kernel that dies, hangs or lies."""

import os
import sys
import tempfile

import pytest

from accelab.exercises.grader.plan import Step
from accelab.exercises.grader.sandbox import check_sandbox, sandbox
from accelab.exercises.grader.supervisor import Limits, run_plan

STATEMENT = {
    "student": "bob",
    "course": "c",
    "assignment": "A",
    "units": "US",
    "tolerance": 0.01,
    "angle_tolerance": 1.0,
    "problems": [
        {
            "family": "rotation",
            "title": "t",
            "statement": "s",
            "given": {"p": "2 in"},
            "asked": [
                {
                    "name": "x",
                    "unit": "in/s^2",
                    "description": "d",
                    "kind": "number",
                    "choices": [],
                    "quantity_required": False,
                }
            ],
        }
    ],
}
LOAD = (
    "from accelab.exercises.student.runtime import ureg, Q_, load_variant, student_id\n"
    "v = load_variant({}, student_id())\n"
)


@pytest.fixture(scope="module")
def command():
    reason = check_sandbox()
    assert reason is None, f"the sandbox must work here: {reason}"
    return sandbox()


def run(command, *sources, report=("x",), **limits):
    steps = [Step(k, "code", source) for k, source in enumerate(sources)]
    steps += [Step(len(steps) + k, "report", name=name) for k, name in enumerate(report)]
    return run_plan(
        steps, STATEMENT, command, Limits(**{"cell_seconds": 4, "total_seconds": 20, **limits})
    )


def text(result):
    return "".join(
        o.get("text", "") + o.get("evalue", "") + str(o.get("data", ""))
        for c in result.cells.values()
        for o in c.outputs
    )


def test_the_sandbox_sees_only_what_a_notebook_needs(command):
    probe = f"""
import os, socket, sys
print("uid", os.getuid(), "pids", sorted(p for p in os.listdir("/proc") if p.isdigit()))
print("env", sorted(os.environ))
for path in ({os.path.dirname(os.path.abspath(__file__))!r}, "/etc/shadow", "/root/.bashrc",
             {sys.prefix + "/../tests"!r}):
    print(path, os.path.exists(path))
try:
    socket.create_connection(("1.1.1.1", 80), timeout=2); print("NETWORK")
except OSError as exc:
    print("no network", exc.errno)
from accelab import exercises
print("exercises", sorted(os.listdir(os.path.dirname(exercises.__file__))))
print("student", sorted(f for f in os.listdir(os.path.dirname(exercises.__file__) + "/student")
                        if f.endswith(".py")))
"""
    r = run(command, LOAD, probe, "x = Q_(3, 'in/s^2')")
    out = text(r)
    assert "uid 0" not in out and "NETWORK" not in out and "no network" in out
    assert "exercises ['__init__.py', 'student']" in out
    assert "student ['__init__.py', 'answers.py', 'identity.py', 'kernel.py', 'runtime.py']" in out
    assert "True" not in out.split("env")[1]  # no test folder, no /etc/shadow, no /root
    env = out.split("env ")[1].split("\n")[0]
    assert "ACCELAB_STUDENT_ID" in env and "SECRET" not in env and "USER" not in env
    pids = out.split("pids ")[1].split("\n")[0]
    assert len(eval(pids)) <= 4  # its own processes only
    assert r.reports["x"] == {"state": "quantity", "magnitude": 3.0, "units": "inch / second ** 2"}


def test_the_graders_parse_of_the_units_is_read_and_cannot_be_written(command):
    """pint's parsed definitions (accelab.solver.unitcache) come from the grader's
    cache, shown read-only: a kernel neither parses them again nor can plant a file
    there for the next submission."""
    from accelab.solver.unitcache import cache_folder

    assert command.unit_cache == str(cache_folder()), "the grader wrote its cache on import"
    probe = """
import functools, os
import flexparser.flexparser as fp
from accelab.solver.unitcache import cache_folder, new_registry
parsed = []
_parse = fp.Parser.parse_file
@functools.wraps(_parse)  # its name is part of pint's cache key
def parse_file(self, path):
    parsed.append(path)
    return _parse(self, path)
fp.Parser.parse_file = parse_file
new_registry()
print("parsed", parsed)
folder = cache_folder()
print("cache", folder, sorted(os.listdir(folder)) != [])
try:
    open(os.path.join(folder, "planted.pickle"), "wb").write(b"x"); print("WRITTEN")
except OSError as exc:
    print("refused", exc.errno)
"""
    out = text(run(command, LOAD, probe, "x = Q_(3, 'in/s^2')"))
    assert "cache /run/accelab-cache/accelab/pint-" in out and " True" in out, out
    assert "parsed []" in out, out  # the registry came from the cache, whole
    assert "WRITTEN" not in out and "refused 30" in out, out  # EROFS


def test_only_the_submitters_values_can_be_loaded(command):
    r = run(command, LOAD, "v2 = load_variant({}, 'alice')", "x = 1.0")
    assert r.refused == ["alice"] and r.loaded == ["bob"]
    assert "only its submitter's values" in text(r)


def test_a_dead_kernel_is_restarted_and_earlier_cells_replayed(command):
    r = run(command, LOAD, "x = Q_(5, 'in/s^2')", "import os\nos._exit(7)", "y = 2")
    statuses = [r.cells[k].status for k in sorted(r.cells)]
    assert statuses[:4] == ["ok", "ok", "died", "ok"] and r.starts == 2
    assert "exit status 7" in r.cells[2].message
    assert r.reports["x"]["magnitude"] == 5.0  # replayed after the restart


def test_a_fork_leaves_the_kernel_to_its_parent(command):
    """A cell that forks: the child runs on with the cell, but it has no pipe to the grader
    and ends where the cell does, so the parent alone answers, the same every time (before,
    both read the grader's next command, and a grade changed from one run to the next). The
    parent then dies: with the child's copy of the pipe closed, its death is seen at once."""
    for _ in range(3):
        r = run(
            command,
            LOAD,
            "import os, time\nchild = os.fork()\ntime.sleep(0.3)",
            "x = Q_(7 if child else 9, 'in/s^2')",
            "if not child:\n    time.sleep(30)\nos.kill(os.getpid(), 9)",
            "y = 1",
        )
        statuses = [r.cells[k].status for k in sorted(r.cells)]
        assert statuses[:3] == ["ok", "ok", "ok"], [r.cells[k].message for k in sorted(r.cells)]
        assert statuses[3] == "died", r.cells[3].message
        assert r.reports["x"]["magnitude"] == 7.0


def test_limits_hold(command):
    r = run(
        command,
        LOAD,
        "import resource\nprint(resource.getrlimit(resource.RLIMIT_NPROC), "
        "resource.getrlimit(resource.RLIMIT_AS))",
        "open('/tmp/big', 'wb').write(b'x' * (64 << 20))",
        "import time\ntime.sleep(30)",
        "x = 1.0",
        cell_seconds=2,
    )
    out = text(r)
    assert "(64, 64)" in out
    assert r.cells[2].status == "error"  # file size / disk limit
    assert r.cells[3].status == "timeout" and "2 s" in r.cells[3].message
    assert r.reports["x"]["magnitude"] == 1.0


def test_the_whole_run_is_time_limited(command):
    r = run(
        command,
        LOAD,
        *["import time\ntime.sleep(1.5)"] * 10,
        "x = 1.0",
        cell_seconds=2,
        total_seconds=5,
    )
    assert r.seconds < 8
    assert "x" not in r.reports
    assert any(c.status == "not_run" for c in r.cells.values())


def test_a_kernel_that_writes_garbage_on_the_protocol_costs_its_cell(command):
    r = run(command, LOAD, "import os, sys\nos.write(int(sys.argv[2]), b'\\xff' * 64)", "x = 2.0")
    assert r.cells[1].status in ("died", "timeout")
    assert r.reports["x"]["magnitude"] == 2.0


FRAME = "import os, sys, struct\nos.write(int(sys.argv[2]), struct.pack('>I', len(body)) + body)"


@pytest.mark.parametrize(
    "body",
    [
        "b'[' * 1_000_000",  # JSON nested too deep to read
        'b\'{"status": "ok", "outputs": 5, "refused": 7, "values": [1]}\'',  # odd shapes
        'b\'{"status": "error", "outputs": [[[]]], "ename": {}, "evalue": []}\'',
    ],
)
def test_a_forged_reply_costs_only_the_submission_never_the_grader(command, body):
    """The kernel is the student's: a reply of any shape, sent in place of the real
    one, is that cell's failure (or garbles that student's own reports) and
    run_plan still returns."""
    r = run(command, LOAD, f"body = {body}\n" + FRAME, "x = 2.0")
    assert set(r.cells) == {0, 1, 2, 3}
    assert r.reports["x"].get("magnitude") in (2.0, None)


SYSCALLS = """
import ctypes, os, platform
libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
NR = {"x86_64": {"add_key": 248, "keyctl": 250, "clone": 56},
      "aarch64": {"add_key": 217, "keyctl": 219, "clone": 220}}[platform.machine()]
def call(name, *args):
    got = libc.syscall(NR[name], *args)
    return got, os.strerror(ctypes.get_errno()) if got < 0 else ""
"""


def test_nothing_passes_between_submissions_through_the_key_store(command):
    """A key added to the sandbox user's keyring would outlive the submission and be
    read by the next one graded in the same slot: the key store is refused."""
    add = (
        SYSCALLS + "print('add', call('add_key', b'user', b'accelab-left', b'left-behind', 11, "
        "ctypes.c_int(-4)))\n"
    )
    read = (
        SYSCALLS
        + "print('search', call('keyctl', 10, ctypes.c_int(-4), b'user', b'accelab-left', 0))\n"
        "print('proc', open('/proc/keys').read() if os.path.exists('/proc/keys') else '')\n"
    )
    first = text(run(command, LOAD, add, "x = 1.0"))
    second = text(run(command, LOAD, read, "x = 1.0"))
    assert "add (-1, 'Operation not permitted')" in first, first
    assert "search (-1, 'Operation not permitted')" in second, second
    assert "keyring" not in second and "left" not in second, second  # not even key names


def test_no_user_namespaces_or_mounts_inside_the_sandbox(command):
    probe = (
        SYSCALLS + "print('unshare', libc.unshare(0x10000000 | 0x00020000), "
        "os.strerror(ctypes.get_errno()))\n"
        "print('clone', call('clone', 0x10000000 | 17, 0, 0, 0, 0))\n"
        "print('mount', libc.mount(b'none', b'/tmp', b'tmpfs', 0, None), "
        "os.strerror(ctypes.get_errno()))\n"
        "import subprocess\n"
        "print('unshare(1)', subprocess.run(['unshare', '-Ur', 'true'], capture_output=True)"
        ".returncode)\n"
        "pid = os.fork()\n"
        "os._exit(0) if pid == 0 else print('fork', os.waitpid(pid, 0)[1])\n"
    )
    out = text(run(command, LOAD, probe, "x = 1.0"))
    assert "unshare -1 Operation not permitted" in out, out
    assert "clone (-1, 'Operation not permitted')" in out
    assert "mount -1 Operation not permitted" in out
    assert "unshare(1) 0" not in out
    assert "fork 0" in out  # an ordinary fork (and the threads of numpy) still work


def test_the_supervisor_caps_images_and_outputs_whatever_the_kernel_sends():
    """The kernel's own caps are the student's to change: the supervisor keeps at
    most so many outputs and images per cell and submission, and refuses an image
    whose header says more pixels than a page should decode."""
    import base64
    import struct
    import zlib

    from accelab.exercises.grader.supervisor import Budget, _cell_run, png_size

    def png(width, height):
        def chunk(kind, data):
            crc = struct.pack(">I", zlib.crc32(kind + data))
            return struct.pack(">I", len(data)) + kind + data + crc

        head = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
        body = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", head) + chunk(b"IEND", b"")
        return base64.b64encode(body).decode()

    assert png_size(png(3, 4)) == (3, 4) and png_size("aGVsbG8=") is None
    image = {"output_type": "display_data", "data": {"image/png": png(1, 1)}, "metadata": {}}
    huge = {"output_type": "display_data", "data": {"image/png": png(30000, 30000)}}
    budget = Budget(Limits())
    runs = [_cell_run({"status": "ok", "outputs": [huge] + [image] * 5000}, 0, budget)]
    runs += [_cell_run({"status": "ok", "outputs": [image] * 50}, 0, budget) for _ in range(9)]
    kept = [sum("image/png" in o.get("data", {}) for o in r.outputs) for r in runs]
    assert kept[0] == Limits().images_per_cell and sum(kept) == Limits().total_images
    assert "one of 30000 x 30000" in runs[0].outputs[-1]["text"]
    assert all(len(r.outputs) <= Limits().outputs_per_cell + 1 for r in runs)


# ------------------------------------------------------------ a grader killed at the wrong moment
#: starts argv[1:] as a grader killed at the wrong moment leaves it: its parent gone before
#: bubblewrap could ask to die with it (the grader's session of its own, as the grader gives
#: it); writes the pid of what it started to argv[1]
ORPHAN = """
import os, sys, time
if os.fork() == 0:
    parent = os.getppid()
    while os.getppid() == parent:
        time.sleep(0.01)
    os.setsid()
    with open(sys.argv[1], "w") as fh:
        fh.write(str(os.getpid()))
    os.execv(sys.argv[2], sys.argv[2:])
"""


def _alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def _running(argv):
    """Pids of processes whose command line is ``argv``."""
    found = []
    for name in os.listdir("/proc"):
        try:
            with open(f"/proc/{name}/cmdline", "rb") as fh:
                if fh.read().split(b"\0")[:-1] == [a.encode() for a in argv]:
                    found.append(int(name))
        except OSError:
            pass
    return found


def test_a_sandbox_left_by_a_killed_grader_is_stopped_by_the_next_run(
    command, tmp_path, monkeypatch
):
    """A grader killed between starting bubblewrap and bubblewrap's ``--die-with-parent``
    leaves the sandbox running (seen once: a submission's detached ``sleep`` outlived the
    grader). The next run finds it by the grader its ``/etc/passwd`` names and stops it
    with everything in it; a sandbox whose grader runs is left alone.

    The dead grader's folder is in a temporary directory of this test's own, so that the
    graders other tests run meanwhile (which stop what they find in theirs) leave it to
    this test."""
    import shutil
    import subprocess
    import time

    from accelab.exercises.grader import orphans
    from accelab.exercises.grader.sandbox import ETC_PREFIX

    gone = subprocess.Popen(["true"])
    gone.wait()  # a grading process that has ended
    builder = sandbox()
    live_etc = builder._etc_files()
    etc = tempfile.mkdtemp(prefix=f"{ETC_PREFIX}{gone.pid}-", dir=tmp_path)
    os.chmod(tmp_path, 0o755)  # the sandbox's user reads its passwd there
    for name in ("passwd", "group"):
        shutil.copy(os.path.join(live_etc, name), etc)
    inner = ["sleep", "987654"]
    cmd = builder.command(inner)
    argv = [a.replace(live_etc, etc) for a in cmd]
    pid_file = tmp_path / "pid"
    try:
        subprocess.run(
            [sys.executable, "-c", ORPHAN, str(pid_file), *argv], pass_fds=cmd.fds, check=True
        )
        deadline = time.monotonic() + 30
        while not (pid_file.exists() and pid_file.read_text() and _running(inner)):
            assert time.monotonic() < deadline, "the left-behind sandbox did not start"
            time.sleep(0.05)
        pid = int(pid_file.read_text())
        # beside it, a sandbox of a grader that runs (this process): not touched
        mine = ["sleep", "987653"]
        own_cmd = builder.command(mine)
        own = subprocess.Popen(own_cmd, pass_fds=own_cmd.fds, start_new_session=True)
        monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # where this test's grader was
        assert (pid, gone.pid) in orphans.left_behind()
        assert own.pid not in [p for p, _ in orphans.left_behind()]
        said = orphans.stop_left_behind()
        monkeypatch.undo()
        assert any(f"process {pid}" in s and f"grading process {gone.pid}" in s for s in said)
        deadline = time.monotonic() + 10
        while _alive(pid) or _running(inner):  # bubblewrap, and the sleep inside it
            assert time.monotonic() < deadline, "the left-behind sandbox still runs"
            time.sleep(0.05)
        deadline = time.monotonic() + 30
        while not _running(mine):
            assert time.monotonic() < deadline, "the running grader's sandbox did not start"
            time.sleep(0.05)
        assert own.poll() is None, "a sandbox whose grader runs was stopped"
        os.killpg(own.pid, 9)
        own.wait()
    finally:
        for p in _running(inner) + _running(["sleep", "987653"]):
            try:
                os.kill(p, 9)
            except ProcessLookupError:  # ended since it was listed (the killpg above)
                pass
        shutil.rmtree(etc, ignore_errors=True)
