"""Where a course's folders live and who may read them: a layout students can
neither read nor hijack.

* The **course folder** (source notebooks, gradebook, submissions, outcomes,
  feedback, keys' inputs) is private to the instructor: no access for other
  users, and for its group only when the group was given full access on purpose
  and no student is in it (a graders' group: ``chgrp graders DIR; chmod 2770 DIR``).
* The **exchange** is outside it, where students can reach it, with the
  permissions nbgrader's exchange expects: its root world-writable with the
  sticky bit (no one renames or deletes another's entry), each course's folder
  the instructor's and not writable by others, ``inbound`` writable but not
  listable and sticky (a student hands in but sees no one's submission),
  ``outbound`` read-only, ``feedback`` reachable only by the name nbgrader gives
  each page. Every folder above the exchange is the instructor's or root's and
  not writable by others (or sticky, as ``/tmp``), so that no one can swap it.

:func:`prepare` creates or repairs this (``accelab assign``) and says what it
changed; what it cannot repair (a folder owned by someone else, a link where a
folder should be) stops it with a :class:`LayoutError` that says what to do.
:func:`check` repairs the course folder and reports the rest (``accelab grade``).
"""

import grp
import importlib.util
import os
import pwd
import stat

#: the folder of accelab's templates (formgrader's submission page with the ids escaped),
#: which formgrader searches before nbgrader's own (``FORMGRADER_TEMPLATES``)
#:
#: :meta hide-value:
TEMPLATES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "templates")
FORMGRADER_TEMPLATES = os.path.join(
    os.path.dirname(os.path.abspath(importlib.util.find_spec("nbgrader").origin)),
    "server_extensions",
    "formgrader",
    "templates",
)
#: mode of the exchange's root, ``0o1777``: every account may add to it, and only an
#: entry's owner may remove it (the sticky bit); a course's folder has ``COURSE_MODE``
#: (``0o755``), its subfolders the modes of ``SUBFOLDERS``
#:
#: :meta hide-value:
ROOT_MODE = 0o1777
COURSE_MODE = 0o755
SUBFOLDERS = {"inbound": 0o1733, "outbound": 0o755, "feedback": 0o711}


class LayoutError(ValueError):
    """The layout is unsafe and cannot be repaired here; the message says what to do."""


def _owner(uid):
    try:
        return pwd.getpwuid(uid).pw_name
    except KeyError:
        return f"uid {uid}"


def _trusted(uid):
    return uid in (0, os.geteuid())


def _ancestors_problem(path):
    """Why a folder above ``path`` would let another user swap it, or None."""
    parent = os.path.dirname(os.path.realpath(path))
    while True:
        try:
            st = os.stat(parent)
        except OSError:
            return None
        writable = st.st_mode & 0o022
        if not _trusted(st.st_uid) or (writable and not st.st_mode & stat.S_ISVTX):
            return (
                f"{parent}, above {path}, is "
                + (f"owned by {_owner(st.st_uid)}" if not _trusted(st.st_uid) else "")
                + (" and " if not _trusted(st.st_uid) and writable else "")
                + ("writable by other users" if writable else "")
                + f": another user could move {path} and put their own in its place; "
                "use a folder whose every parent is yours or root's and not writable by others"
            )
        if parent == "/":
            return None
        parent = os.path.dirname(parent)


def inside(path, folder):
    path, folder = os.path.realpath(path), os.path.realpath(folder)
    return path == folder or path.startswith(folder.rstrip("/") + "/")


def students_in_group(gid, accounts):
    """The accounts (of a roster) that are members of group ``gid``."""
    try:
        members = set(grp.getgrgid(gid).gr_mem)
    except KeyError:
        members = set()
    found = []
    for account in accounts:
        try:
            primary = pwd.getpwnam(account).pw_gid
        except KeyError:
            continue
        if account in members or primary == gid:
            found.append(account)
    return found


def private_course(course_dir, accounts=(), say=print, create=True):
    """Make the course folder private to the instructor (and a graders' group with
    no student in it). Creates it (mode 700) when missing, unless ``create`` is
    false (a new course built aside and renamed into place with mode 700: only
    the folders above it are checked). Says what it changed; raises
    :class:`LayoutError` when it is not the instructor's."""
    course_dir = os.path.abspath(course_dir)
    if not os.path.lexists(course_dir):
        if not create:
            problem = _ancestors_problem(course_dir)
            if problem:
                raise LayoutError(problem)
            return course_dir
        os.makedirs(course_dir, mode=0o700)
        os.chmod(course_dir, 0o700)
    if os.path.islink(course_dir):
        course_dir = os.path.realpath(course_dir)
    st = os.stat(course_dir)
    if st.st_uid != os.geteuid():
        raise LayoutError(
            f"the course folder {course_dir} belongs to {_owner(st.st_uid)}, not to you: run "
            "accelab as the instructor who owns it (grading writes into it)"
        )
    mode = stat.S_IMODE(st.st_mode)
    new = mode & ~0o007
    if new & 0o070 != 0o070:  # only a group set up on purpose (rwx: graders) keeps access
        new &= ~0o070
    if new & 0o070:
        students = students_in_group(st.st_gid, accounts)
        if students:
            new &= ~0o070
            say(
                f"the group of {course_dir} includes students ({', '.join(students[:5])}): "
                "its group permissions were removed"
            )
    if new != mode:
        os.chmod(course_dir, new)
        say(
            f"{course_dir} was readable by other users (mode {mode:o}): now {new:o}, private "
            "to you" + (" and its group" if new & 0o070 else "")
        )
    problem = _ancestors_problem(course_dir)
    if problem:
        raise LayoutError(problem)
    return course_dir


def _folder(path, mode, say, create=True):
    """Create ``path`` with ``mode``, or check that it is the instructor's folder and
    repair its mode; LayoutError when it is a link or someone else's."""
    if not os.path.lexists(path):
        if not create:
            raise LayoutError(f"{path} does not exist")
        os.mkdir(path)
        os.chmod(path, mode)
        return
    st = os.lstat(path)
    if stat.S_ISLNK(st.st_mode) or not stat.S_ISDIR(st.st_mode):
        raise LayoutError(
            f"{path} is a link or a file, not the exchange's folder (it may have been put there "
            "to take the place of the real one): move it aside and run again"
        )
    if st.st_uid != os.geteuid():
        raise LayoutError(
            f"{path} belongs to {_owner(st.st_uid)}, not to you: someone else made it (perhaps "
            "to take the place of the course's exchange folder); move it aside (as root) and "
            "run again"
        )
    if stat.S_IMODE(st.st_mode) != mode:
        os.chmod(path, mode)
        say(f"{path} had mode {stat.S_IMODE(st.st_mode):o}: now {mode:o}")


def prepare_exchange(root, course_id, course_dir=None, say=print):
    """Create or repair the exchange at ``root`` for ``course_id`` (see the module's
    text). Raises :class:`LayoutError` with what to do when it cannot."""
    root = os.path.abspath(root)
    if course_dir is not None and (inside(root, course_dir) or inside(course_dir, root)):
        raise LayoutError(
            f"the exchange {root} is inside the course folder {course_dir} (or the other way "
            "round): students must reach the exchange and must not reach the course folder; "
            "set c.Exchange.root in nbgrader_config.py (or --exchange) to a folder outside it"
        )
    if not os.path.lexists(root):
        try:
            os.makedirs(root)
            os.chmod(root, ROOT_MODE)
        except OSError as exc:
            raise LayoutError(
                f"cannot create the exchange {root} ({exc.strerror}): create it as root "
                f"(install -d -m 1777 {root}) or choose another folder with --exchange"
            ) from None
        say(f"created the exchange {root} (mode 1777: students hand in there)")
    real = os.path.realpath(root)
    st = os.stat(real)
    if not stat.S_ISDIR(st.st_mode):
        raise LayoutError(f"the exchange {root} is not a folder")
    mode = stat.S_IMODE(st.st_mode)
    if mode != ROOT_MODE:
        if st.st_uid != os.geteuid():
            raise LayoutError(
                f"the exchange {root} has mode {mode:o} and belongs to {_owner(st.st_uid)}: it "
                f"needs 1777 (sticky, so that no student can rename another's folder): run "
                f"chmod 1777 {root} as its owner"
            )
        os.chmod(real, ROOT_MODE)
        say(
            f"the exchange {root} had mode {mode:o}: now 1777 (the sticky bit keeps a student "
            "from renaming the course's folder and putting their own in its place)"
        )
    if not _trusted(st.st_uid):
        raise LayoutError(
            f"the exchange {root} belongs to {_owner(st.st_uid)}: it must be yours or root's "
            "(a student who owns it can rename any folder in it)"
        )
    problem = _ancestors_problem(real)
    if problem:
        raise LayoutError(problem)
    course = os.path.join(real, course_id)
    _folder(course, COURSE_MODE, say)
    for name, sub_mode in SUBFOLDERS.items():
        _folder(os.path.join(course, name), sub_mode, say)
    return real


def exchange_problem(root, course_id):
    """Why the exchange of ``course_id`` is not safe to collect from, or None
    (nothing is changed)."""
    said = []
    try:
        real = os.path.realpath(root)
        st = os.stat(real)
        if stat.S_IMODE(st.st_mode) & 0o002 and not st.st_mode & stat.S_ISVTX:
            return (
                f"the exchange {root} is writable by everyone without the sticky bit: a student "
                f"could have replaced the course's folder in it; run accelab assign again to "
                f"repair it (or chmod 1777 {root})"
            )
        course = os.path.join(real, course_id)
        for path in (course, os.path.join(course, "inbound")):
            lst = os.lstat(path)
            if stat.S_ISLNK(lst.st_mode) or lst.st_uid != os.geteuid():
                return (
                    f"{path} is not your folder (it belongs to {_owner(lst.st_uid)} or is a "
                    "link): a student may have put their own in its place; move it aside (as "
                    "root) and run accelab assign again"
                )
        inbound = os.stat(os.path.join(course, "inbound"))
        if stat.S_IMODE(inbound.st_mode) & 0o044:
            said.append(
                f"{os.path.join(course, 'inbound')} is readable by other users: students can "
                "list each other's submissions; run accelab assign again to repair it"
            )
    except OSError as exc:
        return f"the exchange {root} cannot be checked ({exc.strerror})"
    return said[0] if said else None


def exchange_of(config):
    """The exchange root a course's nbgrader configuration names."""
    root = config.get("Exchange", {}).get("root") if hasattr(config, "get") else None
    return str(root) if isinstance(root, str) and root else "/usr/local/share/nbgrader/exchange"


def check(course_dir, config, accounts=(), say=print):
    """Before grading: repair the course folder (:func:`private_course`) and report
    what is unsafe about the exchange and the configuration (nothing there is
    changed). Raises :class:`LayoutError` for a course folder that is not yours."""
    course_dir = private_course(course_dir, accounts, say)
    root = exchange_of(config)
    course_id = str(config.get("CourseDirectory", {}).get("course_id") or "")
    if os.path.isdir(root) and inside(root, course_dir):
        say(
            f"the exchange {root} is inside the course folder: students who can hand in can "
            "read the course folder; move it outside (c.Exchange.root in nbgrader_config.py, "
            "and the students' configuration) and run accelab assign again"
        )
    elif os.path.isdir(root) and course_id:
        problem = exchange_problem(root, course_id)
        if problem:
            say(problem)
    collect = config.get("ExchangeFactory", {}).get("collect")
    if "accelab" not in str(collect):
        say(
            "this course's nbgrader_config.py does not use accelab's collect: submissions "
            "collected by nbgrader's own are trusted for who handed them in and when, which a "
            "student can forge; add: from accelab.exercises.grader.collect import "
            "AccelabCollect; c.ExchangeFactory.collect = AccelabCollect"
        )


# what ``accelab assign`` adds to the configuration of a course made before accelab's
# collect and formgrader templates existed (a comment, not a doc comment: the API page would
# print the whole text, whose long names overflow a phone's width)
CONFIG_ADDED = """
# added by accelab assign: the submitter and the time of a submission from what a student
# cannot forge, only regular files collected (accelab.exercises.grader.collect); formgrader's
# submission page with the student's id escaped
from accelab.exercises.grader.collect import AccelabCollect as _AccelabCollect
from accelab.exercises.layout import FORMGRADER_TEMPLATES as _NBGRADER_TEMPLATES
from accelab.exercises.layout import TEMPLATES as _ACCELAB_TEMPLATES
c.ExchangeFactory.collect = _AccelabCollect  # noqa: F821
c.HTMLExporter.extra_template_basedirs = [_ACCELAB_TEMPLATES, _NBGRADER_TEMPLATES]  # noqa: F821
c.HTMLExporter.extra_template_paths = [_NBGRADER_TEMPLATES]  # noqa: F821
"""


def course_config(course_dir):
    """The course's nbgrader configuration (a traitlets Config), or None when it has
    none yet."""
    from traitlets.config.loader import PyFileConfigLoader

    path = os.path.join(course_dir, "nbgrader_config.py")
    if not os.path.exists(path):
        return None
    try:
        return PyFileConfigLoader("nbgrader_config.py", path=course_dir).load_config()
    except Exception as exc:  # noqa: BLE001 - it is Python: any error of the instructor's
        where = f" (line {exc.lineno})" if getattr(exc, "lineno", None) else ""
        raise LayoutError(
            f"{path} cannot be loaded{where}: {type(exc).__name__}: {str(exc)[:300]}; fix it, "
            "or restore it from a backup"
        ) from None


def upgrade_config(course_dir, say=print, named=None):
    """Add accelab's collect and formgrader templates (:data:`CONFIG_ADDED`) to a
    course configuration that predates them (the file replaced whole); says so,
    naming the file as ``named`` (default its path: a staged copy is named as the
    course's own). Nothing is done to a configuration that has them, or to none."""
    from .files import write_atomic

    config = course_config(course_dir)
    if config is None or "accelab" in str(config.get("ExchangeFactory", {}).get("collect")):
        return
    path = os.path.join(course_dir, "nbgrader_config.py")
    with open(path, encoding="utf-8") as fh:
        text = fh.read()
    write_atomic(path, text + CONFIG_ADDED)
    say(
        f"{named or path} did not use accelab's collect (who handed in and when, from what a "
        "student cannot forge) nor escape ids in formgrader's pages: both added at its end"
    )


def prepare(course_dir, course_id, exchange=None, accounts=(), say=print, new=False, upgrade=True):
    """The layout of a course, created or repaired before ``accelab assign`` writes
    anything: the course folder private (:func:`private_course`), an older
    configuration given accelab's collect (:func:`upgrade_config`; ``upgrade``
    false leaves that to the caller, which does it in its staged copy), the
    exchange outside the course (:func:`prepare_exchange`). ``exchange`` is the
    exchange of a new course (default: a folder ``exchange`` beside the course
    folder); an existing course keeps the one its configuration names. ``new``:
    the course folder is not made here (it is built aside and renamed into
    place). Returns the exchange's path."""
    course_dir = private_course(course_dir, accounts, say, create=not new)
    if upgrade:
        upgrade_config(course_dir, say)
    config = course_config(course_dir)
    if config is not None:
        configured = exchange_of(config)
        if exchange and os.path.realpath(exchange) != os.path.realpath(configured):
            raise LayoutError(
                f"the course's nbgrader_config.py names the exchange {configured}, not "
                f"{exchange}: change c.Exchange.root there (and in the students' configuration) "
                "to move it"
            )
        exchange = configured
    exchange = exchange or os.path.join(os.path.dirname(course_dir), "exchange")
    return prepare_exchange(exchange, course_id, course_dir, say)
