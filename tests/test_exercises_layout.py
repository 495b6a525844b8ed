"""A course's layout (accelab.exercises.layout): the course folder private, the
exchange outside it with the permissions nbgrader's exchange expects; what can be
repaired is repaired with a message, the rest refused with what to do. And the
rules of what a submission is (accelab.exercises.grader.intake): ids are names,
times are read safely."""

import datetime
import os
import stat

import pytest
from _accounts import PREFIX, account

from accelab.exercises.grader import intake
from accelab.exercises.layout import (
    LayoutError,
    exchange_problem,
    prepare_exchange,
    private_course,
)

#: the students' accounts (tests/_accounts.py) are made by one worker at a time
pytestmark = pytest.mark.xdist_group("accounts")
#: the tests that make a second account need root (as the tests run in CI)
as_root = pytest.mark.skipif(os.geteuid() != 0, reason="makes local accounts: run as root")


def mode(path):
    return stat.S_IMODE(os.lstat(path).st_mode)


def test_a_new_exchange_gets_nbgraders_permissions(tmp_path):
    said = []
    root = prepare_exchange(str(tmp_path / "exchange"), "mech101", str(tmp_path / "c"), said.append)
    assert mode(root) == 0o1777 and said
    course = os.path.join(root, "mech101")
    assert mode(course) == 0o755
    assert mode(os.path.join(course, "inbound")) == 0o1733
    assert mode(os.path.join(course, "outbound")) == 0o755
    assert mode(os.path.join(course, "feedback")) == 0o711
    assert exchange_problem(root, "mech101") is None


def test_an_exchange_without_the_sticky_bit_is_repaired_and_said(tmp_path):
    root = tmp_path / "exchange"
    (root / "mech101" / "inbound").mkdir(parents=True)
    os.chmod(root, 0o777)
    os.chmod(root / "mech101" / "inbound", 0o777)
    assert "without the sticky bit" in exchange_problem(str(root), "mech101")
    said = []
    prepare_exchange(str(root), "mech101", None, said.append)
    assert mode(root) == 0o1777 and mode(root / "mech101" / "inbound") == 0o1733
    assert any("sticky" in m for m in said) and any("inbound" in m for m in said)


@as_root
def test_a_course_folder_in_the_exchange_that_is_not_yours_is_refused(tmp_path):
    root = tmp_path / "exchange"
    root.mkdir()
    os.chmod(root, 0o1777)
    hijack = root / "mech101"
    hijack.mkdir()
    uid, gid = account(PREFIX + "mal")
    os.chown(hijack, uid, gid)
    with pytest.raises(LayoutError, match="belongs to axlmal, not to you"):
        prepare_exchange(str(root), "mech101", None, print)
    assert "not your folder" in exchange_problem(str(root), "mech101")
    os.rmdir(hijack)
    os.symlink(tmp_path, hijack)
    with pytest.raises(LayoutError, match="is a link"):
        prepare_exchange(str(root), "mech101", None, print)


def test_an_exchange_inside_the_course_or_under_a_folder_others_can_write_is_refused(tmp_path):
    course = tmp_path / "course"
    course.mkdir()
    with pytest.raises(LayoutError, match="inside the course folder"):
        prepare_exchange(str(course / "exchange"), "c", str(course), print)
    open_dir = tmp_path / "open"
    open_dir.mkdir()
    os.chmod(open_dir, 0o777)
    with pytest.raises(LayoutError, match="writable by other users"):
        prepare_exchange(str(open_dir / "exchange"), "c", str(course), print)


@as_root
def test_a_readable_course_folder_is_made_private(tmp_path):
    course = tmp_path / "course"
    course.mkdir()
    os.chmod(course, 0o755)
    said = []
    private_course(str(course), (), said.append)
    assert mode(course) == 0o700 and "readable by other users" in said[0]
    # a group with a student in it loses its access; a graders' group keeps it
    student = PREFIX + "ann"
    _, gid = account(student)
    os.chown(course, 0, gid)
    os.chmod(course, 0o2770)
    said = []
    private_course(str(course), [student], said.append)
    assert mode(course) & 0o070 == 0 and "includes students" in said[0]
    os.chmod(course, 0o2770)
    private_course(str(course), ["nobody-here"], said.append)
    assert mode(course) == 0o2770


@pytest.mark.parametrize(
    "name, problem",
    [
        ("ann", None),
        ("ann-lee.2", None),
        ("zoë", None),
        ("", "is empty"),
        ("../../etc/x", "path"),
        (".hidden", "path"),
        (os.fsdecode(b"m\xffx"), "UTF-8"),
        (b"m\xffx", "UTF-8"),
        ("<img src=x onerror=alert(1)>", "never has"),
        ("a+b", "never has"),
        (" padded", "spaces"),
        ("\u202eevil", "control"),
        ("x" * 65, "longer"),
        ("bob", "not on the roster"),
    ],
)
def test_an_id_is_a_name_on_the_roster(name, problem):
    got = intake.id_problem(name, ["ann", "ann-lee.2", "zoë"] if problem != "UTF-8" else None)
    if name == "bob" or name == "zoë":
        got = intake.id_problem(name, ["ann", "zoë"])
    assert (got is None) if problem is None else (problem in got), got
    shown = intake.shown(name)
    assert shown.isascii() and not any(c in shown for c in "<>&\"'`\x1b")


@pytest.mark.parametrize(
    "text, problem, ok",
    [
        ("2026-01-01 10:00:00.000000 UTC", None, True),
        ("yesterday-ish", None, False),
        ("99999999999999999999", None, False),
        ("2026-13-45 99:99", None, False),
        (None, "missing", False),
        ("2999-01-01 00:00:00 UTC", None, False),
    ],
)
def test_a_timestamp_is_read_safely_and_noted(text, problem, ok):
    when, note = intake.timestamp_note(text, problem, None)
    assert (when is not None) == ok
    assert (note is None) == ok and (note is None or "graded as on time" in note)
    record = datetime.datetime(2026, 1, 1, 11, 0)
    when, note = intake.timestamp_note(text, problem, record)
    assert when == record  # the exchange's record is the time, whatever the file says
    assert note is not None and "exchange" in note


def test_an_older_courses_configuration_gets_accelabs_collect(tmp_path):
    """A course whose nbgrader_config.py predates accelab's collect gets it added (with
    a message); its exchange, if inside the course folder, is refused with what to do."""
    from accelab.exercises.layout import course_config, prepare

    course = tmp_path / "course"
    course.mkdir(mode=0o700)
    config = course / "nbgrader_config.py"
    config.write_text(
        "c = get_config()\nc.CourseDirectory.course_id = 'old'\n"
        f"c.Exchange.root = {str(tmp_path / 'exchange')!r}\n"
    )
    said = []
    prepare(str(course), "old", None, (), said.append)
    assert "AccelabCollect" in str(course_config(str(course)).ExchangeFactory.collect)
    assert any("both added" in m for m in said)
    config.write_text(config.read_text() + f"c.Exchange.root = {str(course / 'exchange')!r}\n")
    with pytest.raises(LayoutError, match="inside the course folder"):
        prepare(str(course), "old", None, (), said.append)


def test_assign_upgrades_an_older_configuration_all_or_nothing(tmp_path, monkeypatch):
    """accelab assign gives an older course's configuration accelab's collect in its
    staged copy: swapped in with the new assignment, and not at all when the
    assignment fails; a new course is built private (mode 700), with no exchange
    inside it, and the roster's account names are kept with the roster."""
    from accelab.exercises.assign import assign
    from accelab.exercises.layout import course_config

    course = str(tmp_path / "course")
    assign(course, "A", ["rotation"], roster=["ann"], generate=False, say=print)
    assert mode(course) == 0o700 and not os.path.exists(os.path.join(course, "exchange"))
    path = os.path.join(course, "nbgrader_config.py")
    with open(path) as fh:
        old = "".join(line for line in fh if "Collect" not in line and "HTMLExporter" not in line)
    with open(path, "w") as fh:
        fh.write(old)
    import accelab.exercises.assign as assign_module

    def full_disk(*args, **kwargs):
        raise OSError(28, "No space left on device")

    with monkeypatch.context() as patched:  # fails inside the build, after the upgrade
        patched.setattr(assign_module, "write_source", full_disk)
        with pytest.raises(OSError):
            assign(course, "B", ["rotation"], generate=False, say=print)
    assert open(path).read() == old and not os.path.exists(os.path.join(course, "source", "B"))
    said = []
    roster = [{"id": "bob", "account": "bob1"}]
    assign(course, "B", ["rotation"], roster=roster, generate=False, say=said.append)
    assert "AccelabCollect" in str(course_config(course).ExchangeFactory.collect)
    assert any(m.startswith(f"{path} did not use accelab's collect") for m in said), said
    assert intake.id_of_account(course, "bob1") == "bob"
    assert not [f for f in os.listdir(os.path.join(course, ".accelab")) if "staging" in f]
