"""Real grading, attacked as adversarial students would: `accelab assign`, then
`accelab grade` with nbgrader and the bubblewrap sandbox, on a course where each
submission is one attack (or an honest answer).

Rule checked everywhere: an attack earns no point it did not earn, changes
nothing outside its own submission, and the honest submissions graded beside it
keep their full marks. The answers of honest students come from an outside
check (its own solver, from `accelab variant --json`), never from the package.
"""

import csv
import hashlib
import importlib
import json
import os
import re
import stat
import subprocess
import sys
import time

import _forked as forked
import nbformat
import pytest
from _exercises_helpers import answers_code
from nbformat.v4 import new_code_cell

from accelab.exercises.grader.gradetable import question_names
from accelab.exercises.grader.sandbox import check_sandbox
from accelab.exercises.grader.state import outcome_path
from accelab.exercises.notebook import read_spec
from accelab.exercises.simulate import key_code, submit

pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("grade")]  # one course graded, once

SECRET = "s3cr3t-instructor-token-4711"
#: the assignment's limits: a cell, a whole submission [s]. A cell of image_flood hands the
#: grader 40,000 outputs (about 6 MB; the whole submission takes 4.6 s on a quiet machine);
#: with the whole suite on two cores a cell of it took over 3 s now and then, and two right
#: answers were lost (in full runs, twice this week): 5 s leaves it room
CELL_SECONDS, TOTAL_SECONDS = 5, 20
HONEST = ["ann", "bob"]


def accelab(*args, env=None, check=True):
    """``accelab ARGS`` in a process of its own (forked from this one: tests/_forked.py)."""
    proc = forked.run(list(args), env=env)
    if check:
        assert proc.returncode == 0, proc.stderr
    return proc


def outside(course, student):
    """Answer code for ``student`` from the published variant (what `accelab variant
    --json` prints; the command itself is run once in the fixture) and the
    independent solver."""
    from accelab.exercises.variant import variant_json

    return answers_code(json.loads(json.dumps(variant_json(course, "A", student))))


def _cell(nb, gid):
    return next(c for c in nb.cells if c.metadata.get("nbgrader", {}).get("grade_id") == gid)


def own_answers_after(course, student, probe, which=0):
    """The student's own right answers, with ``probe`` run first in the cell of
    answer number ``which``."""
    code = outside(course, student)
    name = list(code)[which]
    code[name] = probe + code[name]
    return code


def all_wrong(code, units):
    return {n: (f"{n} = Q_(1.0, {units[n]!r})" if units[n] else f"{n} = 'gentle'") for n in code}


def course_snapshot(course):
    """Digest of every file a submission must not change (all but the grader's output)."""
    skip = ("autograded", "feedback", ".accelab", "gradebook.db", "grades_A.csv")
    digest = {}
    for root, _dirs, files in os.walk(course):
        rel = os.path.relpath(root, course)
        if rel.split(os.sep)[0] in skip:
            continue
        for f in files:
            if f in skip:
                continue
            path = os.path.join(root, f)
            st = os.lstat(path)
            if os.path.islink(path):  # a link is its target's name, never followed
                digest[os.path.relpath(path, course)] = "link to " + os.readlink(path)
            elif not stat.S_ISREG(st.st_mode):
                digest[os.path.relpath(path, course)] = "special file"
            else:
                with open(path, "rb") as fh:
                    digest[os.path.relpath(path, course)] = hashlib.sha256(fh.read()).hexdigest()
    return digest


def sandbox_processes():
    """Processes of the sandbox users (uids 61000 and up) still alive that run this
    Python (another grader on the same machine has its own)."""
    out = subprocess.run(["ps", "-eo", "uid=,pid=,args="], capture_output=True, text=True).stdout
    ours = os.path.dirname(sys.executable)
    return [
        line
        for line in out.splitlines()
        if line.split() and int(line.split()[0]) >= 61000 and ours in line
    ]


def collected_at(course, student, notebook, when):
    """Record ``when`` as the exchange's time of a submission, as accelab's collect
    does (the time the grader goes by; timestamp.txt only says what the student
    wrote): here, a time after the due date."""
    from accelab.exercises.grader import intake

    with open(os.path.join(os.path.dirname(notebook), "timestamp.txt"), "w") as fh:
        fh.write(when)  # collect writes the exchange's time there too
    intake.write_record(
        course,
        "A",
        student,
        {
            "source": "exchange",
            "student": student,
            "time": when,
            "notes": [],
            "notebook": intake.sha256_of(notebook),
        },
    )


def lingering_sandbox_processes(wait=20.0):
    """The sandbox processes alive now that are still alive ``wait`` s later (none alive:
    at once). Another grading run at the same time (a parallel test worker, another
    user's) has live kernels of its own, which end within seconds; a process left behind
    by this grading stays (the attacks' sleep two minutes)."""
    alive = sandbox_processes()
    deadline = time.monotonic() + wait
    while alive and time.monotonic() < deadline:
        time.sleep(0.5)
        now = set(sandbox_processes())
        alive = [p for p in alive if p in now]
    return alive


ATTACKS = {}


def attack(fn):
    ATTACKS[fn.__name__] = fn
    return fn


@attack
def solution(course, units, name_of):
    """`name = v.solution('name')` in every answer cell."""
    return {n: f"{n} = v.solution({n!r})" for n in units}, None


@attack
def patch_checks(course, units, name_of):
    """Replace the notebook's checks, then give wrong answers."""
    code = all_wrong(units, units)
    first = next(iter(code))
    code[first] = (
        "import accelab.exercises.student.runtime as r\n"
        "r.check_format = lambda *a, **k: print('right')\n"
        "import builtins; builtins.AssertionError = type('X', (Exception,), {})\n" + code[first]
    )
    return code, None


@attack
def load_alice(course, units, name_of):
    """Load another student's values in the notebook, then give her right answers."""

    def edit(nb):
        nb.cells.insert(2, new_code_cell("v = load_variant(SPEC, 'ann')\nv.show(1)"))

    return outside(course, "ann"), edit


@attack
def id_alice(course, units, name_of):
    """Change the notebook's own student id to another student's, then her answers."""

    def edit(nb):
        nb.cells.insert(
            2,
            new_code_cell(
                "import os\nos.environ['ACCELAB_STUDENT_ID'] = 'ann'\n"
                "v = load_variant(SPEC, student_id())"
            ),
        )

    return outside(course, "ann"), edit


@attack
def copy_alice(course, units, name_of):
    """Another student's answers, the notebook left alone."""
    return outside(course, "ann"), None


@attack
def self_study(course, units, name_of):
    """The self-study variant's answers."""
    return outside(course, "self-study"), None


@attack
def key_from_imports(course, units, name_of):
    """Look for the key in anything importable or readable in the kernel."""
    probe = """
import importlib, os, sys, glob
found = []
for mod in ("accelab.exercises.grader", "accelab.exercises.grader.key",
            "accelab.exercises.assignment", "accelab.exercises.problem",
            "accelab.exercises.families", "accelab.exercises.practice",
            "accelab.exercises.simulate", "accelab.exercises.variant", "accelab.exercises.expr"):
    try:
        importlib.import_module(mod); found.append(mod)
    except Exception as exc:
        print("no", mod, type(exc).__name__)
from accelab import exercises
print("exercises files:", sorted(os.listdir(os.path.dirname(exercises.__file__))))
print("readable json:", [p for d in ("/tmp", "/work", "/root", "/home", os.path.dirname(
    exercises.__file__)) for p in glob.glob(d + "/**/*.json", recursive=True)][:5])
print("FOUND", found)
"""
    code = all_wrong(units, units)
    first = next(iter(code))
    code[first] = probe + code[first]
    return code, None


@attack
def read_course(course, units, name_of):
    """Read the course folder, the gradebook, other submissions and /proc; write into the course."""
    probe = f"""
import os, glob
for path in [{course!r}, {course + "/gradebook.db"!r}, {course + "/source/A/A.ipynb"!r},
             {course + "/submitted"!r}, "/root", "/home", "/work"]:
    try:
        print(path, "->", os.listdir(path) if os.path.isdir(path) else open(path, "rb").read(80))
    except Exception as exc:
        print(path, "->", type(exc).__name__)
for pid in os.listdir("/proc"):
    if pid.isdigit():
        try:
            print("environ", pid, open(f"/proc/{{pid}}/environ", "rb").read()[:4000])
        except Exception as exc:
            print("environ", pid, type(exc).__name__)
try:
    os.makedirs({course + "/source/A"!r}, exist_ok=True)
    open({course + "/source/A/owned.txt"!r}, "w").write("owned")
    print("WROTE INTO THE COURSE")
except Exception as exc:
    print("write ->", type(exc).__name__)
print(sorted(os.environ))
"""
    return own_answers_after(course, "read_course", probe), None


@attack
def background_gradebook(course, units, name_of):
    """A detached process that outlives the notebook and edits the gradebook."""
    probe = f"""
import os, time, sqlite3
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        time.sleep(4)
        try:
            db = sqlite3.connect({course + "/gradebook.db"!r})
            db.execute("update grade set auto_score = 0")
            db.commit()
        except Exception:
            pass
        open("/tmp/still-alive", "w").write("yes")
        time.sleep(120)
    os._exit(0)
"""
    return own_answers_after(course, "background_gradebook", probe), None


@attack
def exit_first(course, units, name_of):
    """`os._exit(1)` in the first answer cell; the rest right."""
    code = outside(course, "exit_first")
    first = next(iter(code))
    code[first] = "import os\nos._exit(1)"
    return code, None


@attack
def ignore_interrupt(course, units, name_of):
    """A loop that ignores Ctrl-C and SIGINT in one answer cell; the rest right."""
    code = outside(course, "ignore_interrupt")
    name = list(code)[1]
    code[name] = (
        "import signal\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\nwhile True:\n"
        "    try:\n        pass\n    except BaseException:\n        pass"
    )
    return code, None


@attack
def sleepy(course, units, name_of):
    """Many cells each under the cell limit: the whole submission is limited."""

    def edit(nb):
        for _ in range(20):
            nb.cells.insert(2, new_code_cell(f"import time\ntime.sleep({CELL_SECONDS - 0.5})"))

    return outside(course, "sleepy"), edit


def same_ids(path, ids):
    """Give the cells of the notebook at ``path`` the ids ``ids`` maps theirs to (a copy
    made by hand in the file keeps its cell's id; nbformat.write would rename it)."""
    with open(path, encoding="utf-8") as fh:
        nb = json.load(fh)
    for cell in nb["cells"]:
        cell["id"] = ids.get(cell["id"], cell["id"])
    with open(path, "w", encoding="utf-8") as fh:
        json.dump(nb, fh)


@attack
def duplicated_pair(course, units, name_of):
    """A copy-pasted answer + test cell pair, the copies keeping their cells' ids in the
    file (``edit.written``); the answers right."""
    ids = {}  # a copy's id while nbformat writes it -> its cell's

    def edit(nb):
        name = next(iter(units))
        answer, test = _cell(nb, f"answer_{name}"), _cell(nb, f"test_{name}")
        at = nb.cells.index(test) + 1
        for k, cell in enumerate((test, answer)):
            copy = nbformat.from_dict(json.loads(json.dumps(cell)))
            # an id no cell has, for nbformat.write, which renames repeated ids (the cell's
            # own id changed in its last two letters was its own id when they were "cc")
            copy.id = f"accelab-copy-{k}"
            ids[copy.id] = cell.id
            nb.cells.insert(at, copy)

    edit.written = lambda path: same_ids(path, ids)
    return outside(course, "duplicated_pair"), edit


@attack
def fork_bomb(course, units, name_of):
    """A fork bomb in one answer cell; the rest right."""
    probe = (
        "import os\npids = []\nwhile True:\n    try:\n        pids.append(os.fork())\n"
        "    except OSError:\n        break\n    if pids[-1] == 0:\n"
        "        import time; time.sleep(60); os._exit(0)\n"
    )
    return own_answers_after(course, "fork_bomb", probe, which=1), None


@attack
def memory_hog(course, units, name_of):
    """Ask for 10 GB, then grow a list until the limit; the answers right."""
    code = outside(course, "memory_hog")
    first = next(iter(code))
    code[first] = (
        "try:\n    big = bytearray(10 ** 10)\nexcept MemoryError:\n"
        "    print('no 10 GB')\nhog = []\nwhile True:\n    hog.append(bytearray(10 ** 7))\n"
    )
    return code, None


@attack
def disk_filler(course, units, name_of):
    """Fill the disk: one huge file, then many files; the answers right."""
    probe = (
        "import os\nfor i in range(10 ** 6):\n    try:\n"
        "        open(f'/tmp/fill{i}', 'wb').write(b'x' * 10 ** 7)\n"
        "    except OSError as exc:\n        print('stopped at', i, exc.errno)\n"
        "        break\n"
    )
    return own_answers_after(course, "disk_filler", probe), None


@attack
def print_100mb(course, units, name_of):
    """Print 100 MB; the answers right."""
    probe = "print('x' * 100_000_000)\nimport os\nos.write(1, b'y' * 10 ** 7)\n"
    return own_answers_after(course, "print_100mb", probe), None


@attack
def forged_metadata(course, units, name_of):
    """Forge nbgrader's cell metadata: every grade cell worth 100 points, a new
    "bonus" grade cell that passes, a test cell turned into a solution cell and a
    hidden test's source emptied; the first answer right, the others wrong."""
    code = all_wrong(units, units)
    first = next(iter(code))
    code[first] = outside(course, "forged_metadata")[first]

    def edit(nb):
        for cell in nb.cells:
            meta = cell.metadata.get("nbgrader", {})
            if meta.get("grade"):
                meta["points"] = 100
        names = list(units)
        test = _cell(nb, f"test_{names[1]}")
        test.source = "pass"
        test.metadata["nbgrader"].update(solution=True, locked=False)
        bonus = new_code_cell("print('all right')")
        bonus.metadata["nbgrader"] = {
            "grade": True,
            "solution": False,
            "locked": False,
            "grade_id": "bonus",
            "points": 1000,
            "schema_version": 3,
        }
        nb.cells.append(bonus)

    return code, edit


@attack
def script_for_the_instructor(course, units, name_of):
    """HTML and script in a markdown cell, a javascript: link and an HTML raw cell,
    meant to run in the instructor's formgrader or feedback page; the answers right."""

    def edit(nb):
        nb.cells.insert(
            3,
            nbformat.v4.new_markdown_cell(
                "Notes <script>window.accelabOwned = 1</script> [see](javascript:accelabOwned=1)\n"
                '<img src=x onerror="accelabOwned=1">'
            ),
        )
        nb.cells.insert(
            3,
            nbformat.v4.new_raw_cell(
                "<script>window.accelabOwned = 2</script>", metadata={"raw_mimetype": "text/html"}
            ),
        )

    return outside(course, "script_for_the_instructor"), edit


#: a value with any units text: what a forged object in the kernel can report
ODD = "class Odd:\n    def __init__(self, m, u):\n        self.magnitude, self.units = m, u\n"


@attack
def units_power(course, units, name_of):
    """Every answer a value whose units text is 'm/s**2 * 9**9**8': a power the grader
    would compute for hours, for this student and again for each other's key."""
    return {n: ODD + f"{n} = Odd(1.0, 'm/s**2 * 9**9**8')" for n in units}, None


@attack
def units_db(course, units, name_of):
    """One answer in 'm/s**2*dB' (pint parses it, but cannot use it); the rest right."""
    code = outside(course, "units_db")
    first = next(iter(code))
    code[first] = ODD + f"{first} = Odd(1.0, 'm/s**2*dB')"
    return code, None


FLOOD = """
import struct, sys, zlib, base64
def png(width, height):
    def chunk(kind, data):
        crc = struct.pack(">I", zlib.crc32(kind + data))
        return struct.pack(">I", len(data)) + kind + data + crc
    head = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return base64.b64encode(b"\\x89PNG\\r\\n\\x1a\\n" + chunk(b"IHDR", head)
        + chunk(b"IDAT", zlib.compress(b"\\x00\\x00")) + chunk(b"IEND", b"")).decode()
import gc
main = next(  # the kernel's own module's namespace, found among all objects
    d for d in gc.get_objects() if isinstance(d, dict) and "serve" in d and "run_cell" in d
)
tiny, huge = png(1, 1), png(30000, 30000)
def image(text):
    return {"output_type": "display_data", "data": {"image/png": text}, "metadata": {}}
original = main["run_cell"]
replies = []
def flood(*args, **kwargs):
    reply = original(*args, **kwargs)
    replies.append(1)
    many = 40000 if len(replies) <= 3 else 150
    reply["outputs"] = list(reply["outputs"]) + [image(huge)] + [image(tiny)] * many
    return reply
main["run_cell"] = flood
"""


@attack
def image_flood(course, units, name_of):
    """Patch the kernel's run_cell to add a 30000 x 30000 PNG and 1x1 PNGs to every reply:
    40,000 to the first three (a reply as large as a frame may be, 6.7 of 8 MiB), 150 to each
    other, past the caps of a cell (100 outputs, 20 images) and, over a few cells, of the
    notebook (1000, 100); the answers right. (40,000 in every reply took 4 s of the 20 s
    limit on an idle machine, and ran out of it at six test workers on two cores.)"""
    return own_answers_after(course, "image_flood", FLOOD), None


@attack
def keyring_namespaces(course, units, name_of):
    """A key added to the sandbox user's keyring; unshare(CLONE_NEWUSER | CLONE_NEWNS);
    the answers right."""
    probe = (
        "import ctypes, os\nlibc = ctypes.CDLL(None, use_errno=True)\n"
        "libc.syscall.restype = ctypes.c_long\n"
        "nr = 248 if os.uname().machine == 'x86_64' else 217\n"
        "key = libc.syscall(nr, b'user', b'accelab', b'left-behind', 11, ctypes.c_int(-4))\n"
        "print('add_key', key, os.strerror(ctypes.get_errno()))\n"
        "got = libc.unshare(0x10000000 | 0x00020000)\n"
        "print('unshare', got, os.strerror(ctypes.get_errno()))\n"
    )
    return own_answers_after(course, "keyring_namespaces", probe), None


#: submissions whose timestamp.txt is malformed, missing, or in the future
TIMES = {"badtime": "yesterday-ish 25:99", "notime": None, "futuretime": "2099-01-01 00:00:00 UTC"}
#: folders in submitted/ whose names are no student id
BAD_IDS = {os.fsdecode(b"m\xffx"): "m\\xffx", "<img src=x onerror=alert(1)>": "\\x3cimg"}

ROSTER = [*HONEST, *ATTACKS, "absent", "late", "broken", "huge", "linked", "linkextra", *TIMES]


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    reason = check_sandbox()
    assert reason is None, f"the sandbox must work in CI: {reason}"
    course = str(tmp_path_factory.mktemp("course") / "mech")
    roster = tmp_path_factory.mktemp("roster") / "roster.csv"
    roster.write_text("id\n" + "\n".join(ROSTER) + "\n")
    accelab(
        "assign",
        "--course",
        course,
        "--assignment",
        "A",
        "--course-id",
        "attacks",
        "--roster",
        str(roster),
        "--timeout",
        str(CELL_SECONDS),
        "--time-limit",
        str(TOTAL_SECONDS),
        "--release",
        "--due",
        "2040-01-01 00:00",
    )
    with open(os.path.join(course, "nbgrader_config.py"), "a") as fh:
        fh.write("c.LateSubmissionPlugin.penalty_method = 'zero'\n")
    published = json.loads(
        accelab(
            "variant", "--course", course, "--assignment", "A", "--student", "ann", "--json"
        ).stdout
    )
    assert published == json.loads(
        json.dumps(
            importlib.import_module("accelab.exercises.variant").variant_json(course, "A", "ann")
        )
    )
    units = {a["name"]: a["unit"] for a in published["answers"]}
    for s in HONEST:
        submit(course, "A", s, outside(course, s))
    for name, make in ATTACKS.items():
        code, edit = make(course, units, None)
        path = submit(course, "A", name, code, edit=edit)
        if hasattr(edit, "written"):  # what the attack does to the file itself
            edit.written(path)
    submit(course, "A", "stranger", outside(course, "stranger"))  # not on the roster
    for name in BAD_IDS:  # as if an exchange without accelab's collect had put them there
        submit(course, "A", name, outside(course, "ann"))
    for name, text in TIMES.items():
        folder = os.path.dirname(submit(course, "A", name, outside(course, name)))
        stamp = os.path.join(folder, "timestamp.txt")
        if text is None:
            os.unlink(stamp)
        else:
            with open(stamp, "w") as fh:
                fh.write(text)
    extra = os.path.dirname(submit(course, "A", "linkextra", outside(course, "linkextra")))
    secret = os.path.join(os.path.dirname(course), "instructor-secret.txt")
    with open(secret, "w") as fh:
        fh.write(SECRET)
    os.chmod(secret, 0o600)
    os.symlink(secret, os.path.join(extra, "notes.txt"))
    os.symlink(os.path.join(course, "gradebook.db"), os.path.join(extra, "gradebook.db"))
    os.link(secret, os.path.join(extra, "hard.txt"))
    os.mkfifo(os.path.join(extra, "pipe"))
    late = submit(course, "A", "late", outside(course, "late"))
    collected_at(course, "late", late, "2040-01-02 10:00:00.000000 UTC")
    os.makedirs(os.path.join(course, "submitted", "broken", "A"))
    with open(os.path.join(course, "submitted", "broken", "A", "A.ipynb"), "w") as fh:
        fh.write('{"cells": [ ' + SECRET)  # as if collect had copied a secret file
    os.makedirs(os.path.join(course, "submitted", "linked", "A"))
    os.symlink(
        os.path.join(course, "nbgrader_config.py"),
        os.path.join(course, "submitted", "linked", "A", "A.ipynb"),
    )
    huge = submit(course, "A", "huge", outside(course, "huge"))
    nb = nbformat.read(huge, as_version=4)  # 60 MB of text that would be read in full
    nb.cells.append(nbformat.v4.new_markdown_cell("x" * 60_000_000))
    nbformat.write(nb, huge)
    before = course_snapshot(course)
    env = dict(os.environ, ACCELAB_TEST_SECRET=SECRET)
    start = time.monotonic()
    proc = accelab(
        "grade",
        "--course",
        course,
        "--assignment",
        "A",
        "--jobs",
        "2",
        "--quiet",
        env=env,
        check=False,
    )
    seconds = time.monotonic() - start
    print(
        f"\naccelab grade: {len(os.listdir(os.path.join(course, 'submitted')))} submissions "
        f"in {seconds:.1f} s\n{proc.stdout[-600:]}"
    )
    # long enough for a process that outlived its notebook to act (it waits 4 s): 5 s after
    # its submission's sandbox ended (the outcome saved then), usually long past
    ended = outcome_path(course, "A", "background_gradebook")
    since = time.time() - os.path.getmtime(ended) if os.path.exists(ended) else 0.0
    time.sleep(max(0.0, 5 - since))
    with open(os.path.join(course, "grades_A.csv")) as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    return {
        "course": course,
        "rows": rows,
        "proc": proc,
        "before": before,
        "units": units,
        "seconds": seconds,
        "names": question_names(course, "A"),
    }


def score(g, student):
    return {n: float(g["rows"][student][n]) for n in g["names"]}


def total(g, student):
    return sum(score(g, student).values())


def autograded_text(g, student):
    path = os.path.join(g["course"], "autograded", student, "A", "A.ipynb")
    return open(path).read() if os.path.exists(path) else ""


def feedback_text(g, student):
    """The feedback page's text, without its style sheets and scripts."""
    path = os.path.join(g["course"], "feedback", student, "A", "A.html")
    if not os.path.exists(path):
        return ""
    text = open(path).read()
    return re.sub(r"<(style|script)\b.*?</\1>", "", text, flags=re.S)


# ---- the honest and the outside check -------------------------------------------------------


def test_outside_check_gets_full_marks(graded):
    n = len(graded["names"])
    for s in HONEST:
        assert total(graded, s) == n, graded["rows"][s]
        assert graded["rows"][s]["notes"] == ""


def test_another_students_answers_get_zero_and_say_whose(graded):
    for s in ("copy_alice", "load_alice", "id_alice"):
        s_score = score(graded, s)
        numbers = [n for n, u in graded["units"].items() if u]
        assert all(s_score[n] == 0.0 for n in numbers), (s, graded["rows"][s])
        assert "student ann" in graded["rows"][s]["notes"], graded["rows"][s]["notes"]
        assert "student ann" in feedback_text(graded, s)
    assert "self-study" in graded["rows"]["self_study"]["notes"]
    assert all(score(graded, "self_study")[n] == 0.0 for n, u in graded["units"].items() if u)


# ---- one test per attack ----------------------------------------------------------------------


def test_solution_from_the_notebook_gets_nothing(graded):
    assert total(graded, "solution") == 0.0


def test_patched_checks_get_nothing(graded):
    assert total(graded, "patch_checks") == 0.0


def test_no_key_is_importable_or_readable_in_the_kernel(graded):
    text = autograded_text(graded, "key_from_imports")
    assert "FOUND []" in text, text[:3000]
    assert "families" not in text.split("exercises files:")[1].split("\\n")[0]
    assert total(graded, "key_from_imports") == 0.0


def test_course_files_and_other_processes_are_invisible(graded):
    text = autograded_text(graded, "read_course")
    # (a write "into the course" lands in the sandbox's own /tmp when the course is under /tmp)
    assert SECRET not in text and SECRET not in feedback_text(graded, "read_course")
    assert "SQLite format" not in text and "BEGIN SOLUTION" not in text
    assert not os.path.exists(os.path.join(graded["course"], "source", "A", "owned.txt"))
    assert total(graded, "read_course") == len(graded["names"])  # its own answers still count


def set_aside(course):
    """The files the grader set aside from submissions (links, special files, bad
    timestamps), by the path they had in the course."""
    moved = set()
    root = os.path.join(course, ".accelab", "set-aside", "A")
    for student in os.listdir(root) if os.path.isdir(root) else []:
        for dirpath, _, files in os.walk(os.path.join(root, student)):
            for f in files:
                rel = os.path.relpath(os.path.join(dirpath, f), os.path.join(root, student))
                moved.add(os.path.join("submitted", student, "A", rel.split(os.sep, 1)[1]))
    return moved


def test_nothing_outside_a_submission_changed(graded):
    """Only the grader's own changes: what it set aside from submissions."""
    moved = set_aside(graded["course"])
    assert {k: v for k, v in graded["before"].items() if k not in moved} == course_snapshot(
        graded["course"]
    )


def test_a_process_that_outlives_its_notebook_is_gone_and_did_nothing(graded):
    assert lingering_sandbox_processes() == []
    assert total(graded, "background_gradebook") == len(graded["names"])
    # the gradebook still holds the honest students' full marks (read again after the wait)
    from accelab.exercises.grader.gradetable import rows_of

    _, rows = rows_of(graded["course"], "A")
    for r in rows:
        if r["student"] in HONEST:
            assert r["total"] == len(graded["names"])


def test_os_exit_costs_only_its_answer(graded):
    s = score(graded, "exit_first")
    first = graded["names"][0]
    assert s[first] == 0.0 and total(graded, "exit_first") == len(graded["names"]) - 1
    assert "process ended" in feedback_text(graded, "exit_first")


def test_a_loop_that_ignores_interrupts_costs_only_its_answer(graded):
    s = score(graded, "ignore_interrupt")
    assert s[graded["names"][1]] == 0.0
    assert total(graded, "ignore_interrupt") == len(graded["names"]) - 1
    assert "time limit" in feedback_text(graded, "ignore_interrupt")


def test_the_whole_submission_is_time_limited(graded):
    outcome = json.load(
        open(os.path.join(graded["course"], ".accelab", "outcomes", "A", "sleepy.json"))
    )
    assert outcome["seconds"] <= TOTAL_SECONDS + 5
    assert "ran out" in feedback_text(graded, "sleepy")


def test_a_duplicated_pair_is_graded(graded):
    path = os.path.join(graded["course"], "submitted", "duplicated_pair", "A", "A.ipynb")
    with open(path, encoding="utf-8") as fh:
        ids = [c["id"] for c in json.load(fh)["cells"]]
    assert len(set(ids)) == len(ids) - 2, "the copies repeat their cells' ids in the file"
    assert total(graded, "duplicated_pair") == len(graded["names"])
    assert "appears 2 times" in graded["rows"]["duplicated_pair"]["notes"]


def test_fork_bomb_memory_hog_and_full_disk_cost_only_their_cells(graded):
    n = len(graded["names"])
    assert total(graded, "fork_bomb") >= n - 1
    assert total(graded, "memory_hog") >= n - 1
    assert total(graded, "disk_filler") >= n - 1
    assert lingering_sandbox_processes() == []


def test_printing_100_mb_is_cut(graded):
    assert total(graded, "print_100mb") >= len(graded["names"]) - 1
    path = os.path.join(graded["course"], "autograded", "print_100mb", "A", "A.ipynb")
    assert os.path.getsize(path) < 2_000_000
    assert (
        os.path.getsize(os.path.join(graded["course"], "feedback", "print_100mb", "A", "A.html"))
        < 3_000_000
    )


def test_forged_cell_metadata_earns_nothing(graded):
    """Points, grade cells and test sources come from the instructor's source, not
    from the submission: only the one right answer counts, at its own weight."""
    assert total(graded, "forged_metadata") == 1.0, graded["rows"]["forged_metadata"]
    assert "bonus" not in graded["rows"]["forged_metadata"]
    notes = graded["rows"]["forged_metadata"]["notes"]
    assert "metadata of 11 cell(s) was changed" in notes and "bonus (not graded)" in notes, notes
    from nbgrader.api import Gradebook

    db = "sqlite:///" + os.path.join(graded["course"], "gradebook.db")
    with Gradebook(db, course_id="attacks") as gb:
        sub = gb.find_submission("A", "forged_metadata")
        assert (sub.score, sub.max_score) == (1.0, len(graded["names"]))


def test_a_students_html_never_runs_in_the_instructors_pages(graded):
    assert total(graded, "script_for_the_instructor") == len(graded["names"])
    html = open(
        os.path.join(graded["course"], "feedback", "script_for_the_instructor", "A", "A.html")
    ).read()
    assert "accelabOwned" in html  # what the student wrote is shown, as text
    for live in ("<script>window.accelabOwned", "<img src=x onerror", 'href="javascript:'):
        assert live not in html, live
    # formgrader renders the autograded notebook with the same markdown filter
    from nbconvert.filters.markdown import markdown2html

    nb = nbformat.read(
        os.path.join(graded["course"], "autograded", "script_for_the_instructor", "A", "A.ipynb"),
        as_version=4,
    )
    shown = "".join(
        markdown2html(c.source)
        for c in nb.cells
        if c.cell_type != "code" and not c.metadata.get("nbgrader", {}).get("locked")
    )
    assert "accelabOwned" in shown and "<script>window" not in shown
    assert all(c.cell_type != "raw" for c in nb.cells)


# ---- the instructor's side -------------------------------------------------------------------


def test_csv_covers_the_roster_and_names_every_refused_folder(graded):
    """A folder in submitted/ whose name is not a roster id (not on the roster, not
    UTF-8, markup) is refused with a note that names it safely, and never stops the
    others' grading (the honest students' marks are checked above)."""
    rows = graded["rows"]
    assert set(ROSTER) <= set(rows) and "stranger" in rows
    assert rows["absent"]["total"] == "0.0" and "no submission" in rows["absent"]["notes"]
    assert "not on the roster" in rows["stranger"]["notes"]
    assert rows["stranger"]["total"] == "0.0" and "not graded" in rows["stranger"]["notes"]
    for shown in BAD_IDS.values():
        row = next(r for k, r in rows.items() if k.startswith(shown))
        assert row["total"] == "0.0" and "was refused" in row["notes"], row
    text = open(os.path.join(graded["course"], "grades_A.csv"), "rb").read()
    text.decode("utf-8")  # the CSV is UTF-8 whatever the folders' names
    assert b"<img" not in text and b"\xff" not in text
    assert "<img" not in graded["proc"].stdout + graded["proc"].stderr
    from nbgrader.api import Gradebook

    with Gradebook("sqlite:///" + os.path.join(graded["course"], "gradebook.db")) as gb:
        ids = {s.id for s in gb.students}
    assert "stranger" not in ids and not any("<" in i or "\udcff" in i for i in ids)


# ---- what a student hands in: units, images, the clock, links -------------------------------


def test_units_text_is_read_by_the_one_bounded_reader(graded):
    """A power of a power costs its answers and nothing more: refused before any
    arithmetic (the whole run stays quick), and a unit pint cannot use costs only
    its own answer."""
    assert total(graded, "units_power") == 0.0
    assert "cannot read" in feedback_text(graded, "units_power")
    first = graded["names"][0]
    assert score(graded, "units_db")[first] == 0.0
    assert total(graded, "units_db") == len(graded["names"]) - 1, graded["rows"]["units_db"]
    assert "not graded" not in graded["rows"]["units_db"]["notes"]


def test_images_are_capped_by_the_grader_not_the_students_kernel(graded):
    n = len(graded["names"])
    seconds = json.load(open(outcome_path(graded["course"], "A", "image_flood")))["seconds"]
    assert total(graded, "image_flood") == n, (graded["rows"]["image_flood"], seconds)
    page = open(os.path.join(graded["course"], "feedback", "image_flood", "A", "A.html")).read()
    honest = open(os.path.join(graded["course"], "feedback", "ann", "A", "A.html")).read()
    assert len(page) < len(honest) + 1_000_000
    assert page.count("data:image/png") <= honest.count("data:image/png") + 100
    assert "(one of 30000 x 30000)" in page and "left out outputs" in page


def test_no_key_store_and_no_namespaces_in_the_sandbox(graded):
    text = autograded_text(graded, "keyring_namespaces")
    assert "add_key -1 Operation not permitted" in text, text[:2000]
    assert "unshare -1 Operation not permitted" in text
    assert total(graded, "keyring_namespaces") == len(graded["names"])


def test_a_malformed_missing_or_future_timestamp_is_graded_with_a_note(graded):
    for student in TIMES:
        row = graded["rows"][student]
        assert total(graded, student) == len(graded["names"]), row
        assert "graded as on time" in row["notes"] and "Error" not in row["notes"], row
        assert "graded as on time" in feedback_text(graded, student)
        assert "AttributeError" not in feedback_text(graded, student)
    assert "in the future" in graded["rows"]["futuretime"]["notes"]
    assert "no timestamp.txt" in graded["rows"]["notime"]["notes"]


def test_links_and_special_files_in_a_submission_are_never_followed(graded):
    course = graded["course"]
    row = graded["rows"]["linkextra"]
    assert total(graded, "linkextra") == len(graded["names"]), row
    for what in ("notes.txt", "gradebook.db", "hard.txt", "pipe"):
        assert f"{what} in the submission is" in row["notes"], row
    folder = os.path.join(course, "feedback", "linkextra", "A")
    assert sorted(os.listdir(folder)) == ["A.html", "submission_secret.txt", "timestamp.txt"]
    for step in ("autograded", "feedback"):
        for root, _, files in os.walk(os.path.join(course, step)):
            for f in files:
                with open(os.path.join(root, f), "rb") as fh:
                    assert SECRET.encode() not in fh.read(), (root, f)


def test_late_penalty_applies_in_the_csv_as_in_the_feedback(graded):
    row = graded["rows"]["late"]
    assert float(row["score"]) == len(graded["names"])
    assert float(row["total"]) == 0.0 and "late" in row["notes"]
    assert "late" in feedback_text(graded, "late").lower()


def test_unreadable_notebook_gets_zero_with_the_reason(graded):
    row = graded["rows"]["broken"]
    assert row["total"] == "0.0" and "cannot be read" in row["notes"]
    assert "manual" not in row["notes"]
    assert "cannot be read" in feedback_text(graded, "broken")
    # nothing of the file is quoted: it may be any file a link made collect copy
    assert SECRET not in row["notes"] and SECRET not in feedback_text(graded, "broken")
    row = graded["rows"]["linked"]
    assert row["total"] == "0.0" and "a link to another file" in row["notes"], row
    assert "course_id" not in feedback_text(graded, "linked")
    assert graded["proc"].returncode == 1


def test_a_huge_notebook_is_not_read_and_gets_zero_with_the_reason(graded):
    row = graded["rows"]["huge"]
    assert row["total"] == "0.0" and "more than the 50 MB" in row["notes"], row
    assert "Clear All Outputs" in feedback_text(graded, "huge")


def test_feedback_never_shows_an_expected_value(graded):
    spec = read_spec(graded["course"], "A")
    first = graded["names"][0]
    # the answers each of them did not give (its own right values are in its own cells)
    for student, names in (
        ("copy_alice", None),
        ("patch_checks", None),
        ("solution", None),
        ("exit_first", [first]),
        ("key_from_imports", None),
    ):
        html = feedback_text(graded, student)
        assert html
        # an embedded image's base64 text is no number shown (its letters may hold any digits)
        html = re.sub(r"data:image/[a-z+]+;base64,[A-Za-z0-9+/=\s]+", "data:image/...", html)
        # nor are the tags' attributes (cell ids such as "b329a621"): only the text shows
        html = re.sub(r"<[^>]*>", " ", html)
        code = key_code(spec, student)
        for name, line in code.items():
            if "Q_(" in line and (names is None or name in names):
                value = float(line.split("Q_(")[1].split(",")[0])
                for text in (repr(value), f"{value:.6g}", f"{value:.5g}", f"{value:.4g}"):
                    pattern = r"(?<![\w.])" + re.escape(text) + r"(?![\w])"
                    found = re.search(pattern, html)
                    assert not found, (
                        student,
                        name,
                        text,
                        html[max(0, found.start() - 300) : found.end() + 100],
                    )


def test_grading_again_gives_the_same_grades_and_one_student_can_be_regraded(graded):
    course = graded["course"]
    proc = accelab(
        "grade", "--course", course, "--assignment", "A", "--student", "ann", "--quiet", check=False
    )
    assert proc.returncode == 0, proc.stderr
    with open(os.path.join(course, "grades_A.csv")) as fh:
        again = {r["student"]: r for r in csv.DictReader(fh)}
    assert again == graded["rows"]
    proc = accelab(
        "grade", "--course", course, "--assignment", "A", "--new", "--quiet", check=False
    )
    assert "0 submission(s) graded" in proc.stdout, proc.stdout[-500:]


def test_assign_refuses_an_assignment_with_submissions_unless_forced(graded):
    course = graded["course"]
    proc = accelab("assign", "--course", course, "--assignment", "A", "--units", "SI", check=False)
    assert proc.returncode == 2 and "already has" in proc.stderr and "--force" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_the_csv_never_hands_a_spreadsheet_a_formula():
    """A student id or note taken from a submission may begin with "=" (the
    exchange takes the id from the student's own environment)."""
    from accelab.exercises.grader.gradetable import _cell_text

    assert _cell_text('=HYPERLINK("http://x", "ok")') == '\'=HYPERLINK("http://x", "ok")'
    assert [_cell_text(t) for t in ("+1", "-x", "@SUM(A1)")] == ["'+1", "'-x", "'@SUM(A1)"]
    assert _cell_text("ann") == "ann" and _cell_text(-1.5) == -1.5 and _cell_text("") == ""


def test_late_work_is_noted_under_every_policy(graded):
    """nbgrader's default policy takes nothing off late work: the grade table still
    says it was late (the last test here: it changes the course's policy)."""
    course = graded["course"]
    with open(os.path.join(course, "nbgrader_config.py"), "a") as fh:
        fh.write("c.LateSubmissionPlugin.penalty_method = 'none'\n")
    proc = accelab("grade", "--course", course, "--assignment", "A", "--student", "late", "--quiet")
    assert "Traceback" not in proc.stderr
    with open(os.path.join(course, "grades_A.csv")) as fh:
        row = next(r for r in csv.DictReader(fh) if r["student"] == "late")
    assert float(row["total"]) == len(graded["names"]), row
    assert "late by" in row["notes"] and "no penalty" in row["notes"], row


def test_formgraders_submission_page_escapes_the_student_id(graded):
    """nbgrader's formgrade page prints the student's id and names as HTML; the
    course's configuration puts accelab's macros in front, which escape them. The
    page is rendered here as formgrader renders it (its own configuration, then the
    course's)."""
    from html.parser import HTMLParser

    from nbconvert.exporters import HTMLExporter
    from nbgrader.server_extensions.formgrader.formgrader import FormgradeExtension

    from accelab.exercises.grader.grade import load_config

    config = FormgradeExtension().build_extra_config()
    config.merge(load_config(graded["course"]))
    exporter = HTMLExporter(config=config)
    markup = "<img src=x onerror=window.accelabOwned=1>"
    resources = {
        "base_url": "/x",
        "notebook_id": "A",
        "assignment_id": "A",
        "submission_id": "s1",
        "index": 0,
        "total": 1,
        "notebook_path": "p",
        "student": markup,
        "first_name": None,
        "last_name": None,
    }
    path = os.path.join(graded["course"], "autograded", "ann", "A", "A.ipynb")
    page, _ = exporter.from_filename(path, resources=resources)
    assert "&lt;img src=x onerror=window.accelabOwned=1&gt;" in page

    class Live(HTMLParser):
        found = []

        def handle_starttag(self, tag, attrs):
            self.found += [v for k, v in attrs if k.startswith("on") and "accelabOwned" in v]

    Live().feed(page)
    assert Live.found == []
    resources.update(student="ann", first_name="<b>Ann</b>", last_name="<i>A</i>")
    page, _ = exporter.from_filename(path, resources=resources)
    assert "&lt;i&gt;A&lt;/i&gt;, &lt;b&gt;Ann&lt;/b&gt;" in page
