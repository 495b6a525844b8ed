"""The instructor's workflow of the README, end to end, through nbgrader's real
exchange, with every student a local account of their own (made here with
useradd: the tests run as root): assign and release; students fetch, work and
hand in; the instructor collects, grades (sandbox), releases feedback; the
students fetch it.

Among the students, attackers: one hands in under other students' names (another
student's id, markup, bytes that are not UTF-8), one makes an inbound folder by
hand with links to the instructor's files, a special file and a timestamp.txt
an hour before the due date, handed in after it. What must hold: no unearned
point, nothing read that a student must not read, nothing changed outside the
student's own submission, every other student graded.
"""

import csv
import datetime
import json
import os
import re
import shutil
import stat
import sys
import time

import _forked as forked
import nbformat
import pytest
from _accounts import PREFIX, account, class_folder, home_of, nbgrader_as, python_as, remove
from _exercises_helpers import answers_code

from accelab.exercises.variant import variant_json

# one term (module fixture) in one worker; the students' accounts (tests/_accounts.py) are made
# by one worker at a time
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("accounts")]

SECRET = "instructor-only-7dx9"
#: roster id -> account (the roster maps them: an account need not be its id)
ACCOUNTS = {s: PREFIX + s for s in ("ann", "bob", "mal", "eve", "lee")}
MARKUP = "<img src=x onerror=alert(1)>"
NOT_UTF8 = os.fsdecode(b"m\xffx")


def run(program, args, cwd, check=True):
    """The instructor's ``PROGRAM ARGS`` (accelab or nbgrader) in ``cwd``, in a process of
    its own (forked from this one: tests/_forked.py)."""
    env = dict(os.environ)
    env.pop("JUPYTERHUB_USER", None)
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")
    proc = forked.run(list(args), env=env, cwd=cwd, program=program)
    if check:
        assert proc.returncode == 0, (args, proc.stdout[-2000:], proc.stderr[-3000:])
    return proc


def instructor(*args, cwd):
    return run("nbgrader", args, cwd)


def accelab(*args, cwd, check=True):
    return run("accelab", args, cwd, check=check)


def student_home(sid, base, exchange):
    home = home_of(ACCOUNTS[sid], base)
    path = os.path.join(home, "nbgrader_config.py")
    with open(path, "w") as fh:
        fh.write(
            f"c = get_config()\nc.CourseDirectory.course_id = 'mech101'\n"
            f"c.Exchange.root = {exchange!r}\n"
        )
    os.chmod(path, 0o644)
    return home


def given(home, sid, released):
    """The released notebook in the student's home, theirs (as fetch_assignment makes it)."""
    uid, gid = account(ACCOUNTS[sid])
    folder = os.path.join(home, "A")
    os.makedirs(folder, exist_ok=True)
    shutil.copy(released, folder)
    for path in (folder, os.path.join(folder, "A.ipynb")):
        os.chown(path, uid, gid)


def answers(course, sid):
    """Answer-cell code for student ``sid`` (name -> code), from the published variant."""
    return answers_code(json.loads(json.dumps(variant_json(course, "A", sid))))


def work(home, sid, course, wrong=False):
    """The student writes answers in the fetched notebook's answer cells."""
    path = os.path.join(home, "A", "A.ipynb")
    nb = nbformat.read(path, as_version=4)
    code = answers(course, sid)
    for cell in nb.cells:
        gid = cell.metadata.get("nbgrader", {}).get("grade_id", "")
        name = gid[len("answer_") :]
        if gid.startswith("answer_") and name in code:
            cell.source = code[name].replace("Q_(", "-Q_(") if wrong else code[name]
    nbformat.write(nb, path)
    return nb


PROBE = """
import os, sqlite3
out = []
for path in [{course!r}, {course!r} + "/gradebook.db", {inbound!r}]:
    try:
        out.append((path, "listed" if os.path.isdir(path) else "read", len(
            os.listdir(path) if os.path.isdir(path) else open(path, "rb").read())))
    except OSError as exc:
        out.append((path, type(exc).__name__))
for old, new in [({exchange!r} + "/mech101", {exchange!r} + "/mine"),
                 ({inbound!r}, {inbound!r} + "-x")]:
    try:
        os.rename(old, new)
        out.append(("RENAMED", old))
    except OSError as exc:
        out.append((old, type(exc).__name__))
try:
    os.mkdir({exchange!r} + "/mech101/outbound/A/x")
    out.append(("WROTE OUTBOUND",))
except OSError as exc:
    out.append(("outbound", type(exc).__name__))
print(out)
"""

#: nbgrader's command run in a student's process as nbgrader's own tests run it (initialize,
#: start, reset): several commands of one account in one interpreter, not one each
NBGRADER_HERE = """
from jupyter_core.application import NoStart
from nbgrader.apps.nbgraderapp import NbGraderApp
def nbgrader(*args):
    app = NbGraderApp.instance()
    try:
        app.initialize(list(args))
        app.start()
    except NoStart:
        pass
    finally:
        app.reset()
"""

#: mal's three hand-ins under other names: ``nbgrader submit A --student CLAIM`` for each
SUBMITS = (
    NBGRADER_HERE
    + """
for claim in {claims!r}:
    nbgrader("submit", "A", "--student", claim)
"""
)

#: an honest student's term: ``nbgrader fetch_assignment A``, the answers written into the
#: fetched notebook's answer cells, ``nbgrader submit A``
FETCH_WORK_SUBMIT = (
    NBGRADER_HERE
    + """
import nbformat
nbgrader("fetch_assignment", "A")
nb = nbformat.read("A/A.ipynb", as_version=4)
code = {code!r}
for cell in nb.cells:
    gid = cell.metadata.get("nbgrader", {{}}).get("grade_id", "")
    if gid.startswith("answer_") and gid[len("answer_"):] in code:
        cell.source = code[gid[len("answer_"):]]
nbformat.write(nb, "A/A.ipynb")
nbgrader("submit", "A")
"""
)

#: what eve does by hand: an inbound folder named an hour before the due date
HANDMADE = """
import os, shutil
folder = os.path.join({inbound!r}, "eve+A+" + {early!r} + "+handmade")
os.mkdir(folder)
shutil.copy("A/A.ipynb", folder)
open(os.path.join(folder, "timestamp.txt"), "w").write({early!r})
os.symlink({secret!r}, os.path.join(folder, "notes.txt"))
os.symlink({course!r} + "/gradebook.db", os.path.join(folder, "gradebook.db"))
os.mkfifo(os.path.join(folder, "pipe"))
os.chmod(folder, 0o777)
print(folder)
"""


@pytest.fixture(scope="module")
def klass():
    base = class_folder()
    try:
        yield _term(base)
    finally:
        remove(base)


def _term(base):
    course, exchange = os.path.join(base, "course"), os.path.join(base, "exchange")
    secret = os.path.join(base, "instructor-secret.txt")
    with open(secret, "w") as fh:
        fh.write(SECRET)
    os.chmod(secret, 0o600)
    roster = os.path.join(base, "roster.csv")
    with open(roster, "w") as fh:
        fh.write("id,account\n" + "".join(f"{s},{a}\n" for s, a in ACCOUNTS.items()) + "ivy,\n")
    accelab(
        "assign",
        *("--course", course, "--assignment", "A", "--course-id", "mech101"),
        *("--roster", roster, "--families", "rotation", "--exchange", exchange),
        *("--timeout", "5", "--time-limit", "30", "--release"),
        cwd=base,
    )
    with open(os.path.join(course, "nbgrader_config.py"), "a") as fh:
        fh.write("c.LateSubmissionPlugin.penalty_method = 'zero'\n")
    inbound = os.path.join(exchange, "mech101", "inbound")
    homes = {s: student_home(s, base, exchange) for s in ACCOUNTS}
    for sid in ("ann", "bob"):  # fetch, answer and hand in, as the student
        code = FETCH_WORK_SUBMIT.format(code=answers(course, sid))
        python_as(ACCOUNTS[sid], code, cwd=homes[sid])
    for sid in ("mal", "lee", "eve"):  # the same notebook, without the time nbgrader takes
        given(homes[sid], sid, os.path.join(exchange, "mech101", "outbound", "A", "A.ipynb"))
    # mal: wrong answers, handed in under bob's id, a markup id and bytes that are not UTF-8
    work(homes["mal"], "bob", course, wrong=True)
    python_as(ACCOUNTS["mal"], SUBMITS.format(claims=("bob", MARKUP, NOT_UTF8)), cwd=homes["mal"])
    probe = python_as(
        ACCOUNTS["mal"],
        PROBE.format(course=course, inbound=inbound, exchange=exchange),
        cwd=homes["mal"],
    )
    # the due date passes; lee hands in late, and eve makes her folder by hand
    from accelab.exercises.assign import set_due

    due = datetime.datetime.now(datetime.timezone.utc).replace(tzinfo=None)
    set_due(course, "mech101", "A", due.isoformat())
    time.sleep(1.5)
    work(homes["lee"], "lee", course)
    nbgrader_as(ACCOUNTS["lee"], "submit", "A", cwd=homes["lee"])
    work(homes["eve"], "eve", course)  # her own right answers
    early = (due - datetime.timedelta(hours=1)).strftime("%Y-%m-%d %H:%M:%S.%f UTC")
    handmade = python_as(
        ACCOUNTS["eve"],
        HANDMADE.format(inbound=inbound, early=early, secret=secret, course=course),
        cwd=homes["eve"],
    ).strip()
    # a hard link to the instructor's file in her folder (what fs.protected_hardlinks
    # stops on this machine, made here as root)
    os.link(secret, os.path.join(handmade, "hard.txt"))
    collected = instructor("collect", "A", cwd=course)
    graded = accelab(
        "grade", "--course", course, "--assignment", "A", "--quiet", cwd=course, check=False
    )
    with open(os.path.join(course, "grades_A.csv")) as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    instructor("release_feedback", "A", cwd=course)
    nbgrader_as(ACCOUNTS["ann"], "fetch_feedback", "A", cwd=homes["ann"])
    return {
        "base": base,
        "course": course,
        "exchange": exchange,
        "homes": homes,
        "rows": rows,
        "probe": probe,
        "collected": collected.stdout + collected.stderr,
        "graded": graded,
        "handmade": handmade,
    }


def mode(path):
    return stat.S_IMODE(os.lstat(path).st_mode)


def total(klass, sid):
    return float(klass["rows"][sid]["total"])


def maximum(klass):
    return float(klass["rows"]["ann"]["max"])


def test_the_course_is_private_and_the_exchange_laid_out_as_nbgrader_expects(klass):
    course, exchange = klass["course"], klass["exchange"]
    assert mode(course) & 0o077 == 0
    assert mode(exchange) == 0o1777
    assert mode(os.path.join(exchange, "mech101")) == 0o755
    assert mode(os.path.join(exchange, "mech101", "inbound")) == 0o1733
    assert mode(os.path.join(exchange, "mech101", "outbound")) == 0o755
    assert not os.path.commonpath([course, exchange]) == course


def test_a_student_reads_nothing_of_the_course_and_hijacks_nothing(klass):
    out = klass["probe"]
    assert "listed" not in out and "read'" not in out, out
    assert "RENAMED" not in out and "WROTE OUTBOUND" not in out, out
    assert out.count("PermissionError") == 6, out


def test_honest_students_get_full_marks(klass):
    for sid in ("ann", "bob"):
        row = klass["rows"][sid]
        assert total(klass, sid) == maximum(klass), row
        assert row["notes"] == "", row
    assert "no submission" in klass["rows"]["ivy"]["notes"]
    assert klass["graded"].returncode == 0, klass["graded"].stderr[-2000:]


def test_handing_in_under_other_names_is_the_owners_own_submission(klass):
    """mal handed in as bob, as markup and as bytes that are not UTF-8: each is mal's
    (the account that owns the folder), bob keeps his marks, nothing crashes."""
    row = klass["rows"]["mal"]
    assert total(klass, "mal") == 0.0, row
    assert "handed in under the name m\\xffx by the account axlmal" in row["notes"], row
    submitted = os.listdir(os.path.join(klass["course"], "submitted"))
    assert sorted(submitted) == ["ann", "bob", "eve", "lee", "mal"], submitted
    assert set(klass["rows"]) == {"ann", "bob", "mal", "eve", "lee", "ivy"}
    assert "also handed in under the name(s)" in row["notes"], row
    assert "bob" in row["notes"] and "\\x3cimg src=x onerror=alert(1)\\x3e" in row["notes"]
    assert "<img" not in klass["collected"] and "<img" not in json.dumps(klass["rows"])


def test_the_time_is_the_exchanges_not_the_students(klass):
    """eve's timestamp.txt (and folder name) say an hour before the due date; the
    exchange says after it: she is late, as the honest late student is."""
    for sid in ("eve", "lee"):
        row = klass["rows"][sid]
        assert float(row["score"]) == maximum(klass) and total(klass, sid) == 0.0, row
        assert "late by" in row["notes"], row
    assert "earlier than the exchange's record" in klass["rows"]["eve"]["notes"]


def test_links_hard_links_and_special_files_are_never_collected(klass):
    course = klass["course"]
    folder = os.path.join(course, "submitted", "eve", "A")
    assert sorted(os.listdir(folder)) == ["A.ipynb", "submission_secret.txt", "timestamp.txt"]
    notes = klass["rows"]["eve"]["notes"]
    assert "notes.txt in the submission is a link" in notes, notes
    assert "gradebook.db in the submission is a link" in notes
    assert "pipe in the submission is a special file" in notes
    assert "hard.txt in the submission is a file the submitter does not own" in notes
    feedback = os.path.join(course, "feedback", "eve", "A")
    assert sorted(os.listdir(feedback)) == ["A.html", "submission_secret.txt", "timestamp.txt"]
    for step in ("submitted", "autograded", "feedback"):
        for root, _, files in os.walk(os.path.join(course, step)):
            for f in files:
                with open(os.path.join(root, f), "rb") as fh:
                    assert SECRET.encode() not in fh.read(), (root, f)


def test_feedback_reaches_the_student(klass):
    home = klass["homes"]["ann"]
    pages = [
        os.path.join(root, f)
        for root, _, files in os.walk(os.path.join(home, "A"))
        for f in files
        if f.endswith(".html")
    ]
    assert len(pages) == 1, pages
    assert re.search(r"Graded against the values of student ann\b", open(pages[0]).read())
