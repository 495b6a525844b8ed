"""What a submission is, taken from what a student cannot forge.

Everything a student hands in can be forged: the folder's name (the id nbgrader's
``submit --student`` writes into it), ``timestamp.txt``, the files in it. So:

* **who**: the submitter is the account that owns the submission's folder in the
  exchange (nbgrader's own cross-check, made a rule), mapped to a roster id
  (:func:`id_of_account`); the name in the folder is only cross-checked, and a
  folder handed in under another student's name is graded as its owner's, with
  a note (:mod:`.collect`);
* **when**: the exchange's own record, the newest change time (``ctime``) of the
  folder and of every file in it, which a user can move forward (by changing
  something) but never back; ``timestamp.txt`` is only cross-checked, and a
  mismatch is graded with a note;
* **ids are names**, not paths or markup (:func:`id_problem`): a folder whose name
  is not a roster id, not UTF-8, path-like or holding markup is refused with a
  note naming it (:func:`shown`), and the others are graded;
* **files, not links**: only regular files the submitter owns are collected; a
  link, a hard link to someone else's file or a special file is never followed
  or read; in ``submitted/`` the grader sets such entries aside before nbgrader
  sees them (:func:`prepare`), and a feedback folder keeps only what the grader
  wrote (:func:`clean_feedback`).

What collect learnt of a submission (and what grading adds) is kept in a record,
``.accelab/intake/<assignment>/<student>.json``: its notes reach the grade table
and the student's feedback (:func:`notes_of`).
"""

import datetime
import errno
import fnmatch
import hashlib
import json
import os
import secrets
import shutil
import stat
import unicodedata

from ..nbgrader_course import roster_ids

#: longest student id [characters]
MAX_ID = 64
#: characters an id never holds: markup, quotes, and what a URL or a shell reads
#: specially (formgrader puts ids into links and pages; nbgrader refuses ``+`` and ``*``)
NOT_IN_IDS = set("<>&\"'`\\/?#%+*")
#: how far timestamp.txt may be from the exchange's record before it is noted [s]
TIME_SLACK = 600.0
#: how far in the future a timestamp may be (clocks differ a little) [s]
FUTURE_SLACK = 300.0
#: nbgrader's timestamp format (its Exchange.timestamp_format, in UTC)
TIME_FORMAT = "%Y-%m-%d %H:%M:%S.%f UTC"
#: the longest timestamp.txt and submission_secret.txt read [bytes]
MAX_SMALL_FILE = 300
#: how deep folders in a submission are read, and how many entries at most
MAX_DEPTH = 4
MAX_ENTRIES = 200


# ---- ids -------------------------------------------------------------------------------------


def id_problem(name, roster=None):
    """Why ``name`` (a folder name or a claimed id, str or bytes) cannot be a student
    id, as words for a note, or None when it can.

    An id is a name: valid UTF-8, 1 to :data:`MAX_ID` characters, no spaces or
    control characters, nothing of a path (``/``, a backslash, a leading ``.``,
    ``-`` or ``~``), no markup, quotes or backquotes (``<``, ``>``, ``&``), nothing
    nbgrader's exchange or a URL reads specially (``+ * ? # %``); and, when the
    course has a roster, on it.
    """
    if isinstance(name, bytes):
        try:
            name = name.decode("utf-8")
        except UnicodeDecodeError:
            return "is not valid UTF-8"
    if not isinstance(name, str):
        return "is not a name"
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:  # a folder name of bytes that are not UTF-8
        return "is not valid UTF-8"
    if not name:
        return "is empty"
    if len(name) > MAX_ID:
        return f"is longer than {MAX_ID} characters"
    if name in (".", "..") or name[0] in ".-~" or "/" in name or "\\" in name:
        return "looks like a path, not a name"
    if any(ch in NOT_IN_IDS for ch in name):
        bad = "".join(sorted({ch for ch in name if ch in NOT_IN_IDS}))
        return f"holds characters a student id never has ({shown(bad)})"
    if any(ch.isspace() or unicodedata.category(ch)[0] in "CZ" for ch in name):
        return "holds spaces or control characters"
    if roster and name not in roster:
        return "is not on the roster"
    return None


def shown(name, limit=MAX_ID):
    """A name as a note shows it, safe anywhere it is printed (a terminal, a CSV, a
    web page): printable ASCII, with markup, quotes, backslashes, control and
    non-ASCII characters and bytes that are not UTF-8 written as escapes
    (``\\x3c``, ``\\xff``), cut to ``limit`` characters."""
    if isinstance(name, bytes):
        text = name.decode("utf-8", "backslashreplace")
    else:
        try:
            text = str(name).encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
        except UnicodeEncodeError:
            text = str(name).encode("utf-8", "backslashreplace").decode("ascii")
    out = []
    for ch in text:  # (a backslash stays: the escapes backslashreplace wrote)
        if " " <= ch <= "~" and ch not in "<>&\"'`":
            out.append(ch)
        elif ord(ch) < 0x100:
            out.append(f"\\x{ord(ch):02x}")
        elif ord(ch) < 0x10000:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(f"\\U{ord(ch):08x}")
    text = "".join(out)
    return text if len(text) <= limit else text[: limit - 3] + "..."


# ---- accounts --------------------------------------------------------------------------------


def accounts_path(course_dir):
    return os.path.join(course_dir, ".accelab", "accounts.json")


def account_map(course_dir):
    """account name -> roster id, where the two differ (from the roster's
    ``account`` column); every other account is its own id."""
    try:
        with open(accounts_path(course_dir), encoding="utf-8") as fh:
            data = json.load(fh)
    except (OSError, ValueError):
        return {}
    return {str(k): str(v) for k, v in data.items()} if isinstance(data, dict) else {}


def save_accounts(course_dir, roster):
    """Keep the ``account`` of each roster row that has one (dicts with ``id``)."""
    mapping = account_map(course_dir)
    for row in roster:
        if isinstance(row, dict) and str(row.get("account") or "").strip():
            mapping[str(row["account"]).strip()] = str(row["id"])
    if mapping:
        write_atomic(accounts_path(course_dir), json.dumps(mapping, indent=1, sort_keys=True))


def account_of_uid(uid):
    """The account name of a uid, or None when the machine has no such account."""
    import pwd

    try:
        return pwd.getpwuid(uid).pw_name
    except KeyError:
        return None


def id_of_account(course_dir, account, roster=None):
    """The roster id of an account (None when it is not a student of the course)."""
    if account is None:
        return None
    roster = roster_ids(course_dir) if roster is None else roster
    sid = account_map(course_dir).get(account, account)
    if id_problem(sid, roster):
        return None
    return sid


# ---- time ------------------------------------------------------------------------------------


def utcnow():
    return datetime.datetime.now(datetime.timezone.utc).replace(tzinfo=None)


def from_ns(ns):
    """A naive UTC datetime (as nbgrader's gradebook keeps them) of a file time [ns]."""
    return datetime.datetime.fromtimestamp(ns / 1e9, datetime.timezone.utc).replace(tzinfo=None)


def format_time(when):
    return when.strftime(TIME_FORMAT)


def parse_time(text):
    """A timestamp's text as a naive UTC datetime, or None when it is not a date
    and time nbgrader would read (any error of the parser is a None)."""
    from nbgrader.utils import parse_utc

    text = text.strip()
    if not text or len(text) > 64 or not text[:4].isdigit():
        return None
    try:
        when = parse_utc(text)
    except Exception:  # noqa: BLE001 - dateutil raises ValueError, OverflowError, TypeError ...
        return None
    if not isinstance(when, datetime.datetime) or not 1970 <= when.year <= 9000:
        return None
    return when


def read_small(path=None, dir_fd=None, name=None):
    """The text of a small regular file (timestamp.txt, submission_secret.txt), read
    without following a link and without blocking; (text, problem)."""
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY
    try:
        fd = os.open(name if dir_fd is not None else path, flags, dir_fd=dir_fd)
    except FileNotFoundError:
        return None, "missing"
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            return None, "a link"
        return None, "unreadable"
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return None, "not a file"
        data = os.read(fd, MAX_SMALL_FILE + 1)
    finally:
        os.close(fd)
    if len(data) > MAX_SMALL_FILE:
        return None, "too long"
    try:
        return data.decode("utf-8"), None
    except UnicodeDecodeError:
        return None, "not text"


def timestamp_note(text, problem, record_time=None, now=None):
    """(time, note): what timestamp.txt says, checked against the exchange's record
    (``record_time``) or, without one, against the clock. ``time`` is the time to
    grade by (None: unknown, graded as on time); ``note`` a sentence or None."""
    now = now or utcnow()
    when = parse_time(text) if text is not None else None
    if record_time is not None:
        at = format_time(record_time)
        if problem == "missing":
            return record_time, f"it has no timestamp.txt; the exchange's time, {at}, was used"
        if when is None:
            return record_time, (
                f"its timestamp.txt is not a date and time; the exchange's time, {at}, was used"
            )
        gap = (when - record_time).total_seconds()
        if gap > TIME_SLACK:
            return record_time, (
                f"its timestamp.txt says {format_time(when)}, after the exchange's record of "
                f"{at}; the exchange's time was used"
            )
        if gap < -TIME_SLACK:
            return record_time, (
                f"its timestamp.txt says {format_time(when)}, earlier than the exchange's record "
                f"of {at} (written before it was handed in, or the submission was changed "
                "afterwards); the exchange's time was used"
            )
        return record_time, None
    check = "check when it was submitted"
    if problem == "missing":
        return None, f"it has no timestamp.txt, so its time is unknown: graded as on time ({check})"
    if when is None:
        return None, (
            "its timestamp.txt is not a date and time, so its time is unknown: graded as on "
            f"time ({check})"
        )
    if (when - now).total_seconds() > FUTURE_SLACK:
        return None, (
            f"its timestamp.txt says {format_time(when)}, in the future, so its time is "
            f"unknown: graded as on time ({check})"
        )
    return when, None


def sane_secret(text):
    """A submission secret as nbgrader writes it (hex), or None."""
    text = (text or "").strip()
    if 16 <= len(text) <= 256 and all(ch in "0123456789abcdef" for ch in text):
        return text
    return None


# ---- files -----------------------------------------------------------------------------------


def write_atomic(path, text):
    """Write ``text`` beside ``path``, flush it to disk, then rename it over ``path``."""
    folder = os.path.dirname(path)
    os.makedirs(folder, exist_ok=True)
    tmp = os.path.join(folder, f".{os.path.basename(path)}.{secrets.token_hex(4)}.tmp")
    try:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def sha256_of(path):
    """The SHA-256 of a regular file (not followed if a link), or None."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return None
        digest = hashlib.sha256()
        while chunk := os.read(fd, 1 << 20):
            digest.update(chunk)
        return digest.hexdigest()
    finally:
        os.close(fd)


def kind_of(st, owner=None):
    """Why an entry (its ``lstat``) is not a file to collect, or None when it is a
    regular file (owned by ``owner``, when given) or a folder."""
    if stat.S_ISLNK(st.st_mode):
        return "a link to another file"
    if stat.S_ISDIR(st.st_mode):
        return None
    if not stat.S_ISREG(st.st_mode):
        return "a special file (a pipe, socket or device)"
    if owner is not None and st.st_uid != owner:
        return "a file the submitter does not own (a hard link to someone else's file)"
    if owner is None and st.st_nlink > 1:
        return "a hard link to another file"
    return None


def ignored(name, patterns):
    return any(fnmatch.fnmatch(name, p) for p in patterns)


# ---- records ---------------------------------------------------------------------------------


def record_path(course_dir, assignment, student):
    return os.path.join(course_dir, ".accelab", "intake", assignment, f"{student}.json")


def read_record(course_dir, assignment, student):
    try:
        with open(record_path(course_dir, assignment, student), encoding="utf-8") as fh:
            data = json.load(fh)
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def write_record(course_dir, assignment, student, record):
    write_atomic(
        record_path(course_dir, assignment, student), json.dumps(record, indent=1, sort_keys=True)
    )


def refused_path(course_dir, assignment):
    return os.path.join(course_dir, ".accelab", "intake", assignment, "refused.json")


def note_refused(course_dir, assignment, folder, reason, step="collect"):
    """Keep a folder that was refused (at collect or grade) and why, for the instructor."""
    path = refused_path(course_dir, assignment)
    try:
        with open(path, encoding="utf-8") as fh:
            items = json.load(fh)
    except (OSError, ValueError):
        items = []
    entry = {"folder": shown(folder, 120), "reason": reason, "step": step}
    items = [i for i in items if isinstance(i, dict) and i.get("folder") != entry["folder"]]
    items.append(entry)
    write_atomic(path, json.dumps(items[-500:], indent=1))


def clear_refused(course_dir, assignment, step):
    """Forget the folders refused at ``step`` (a new collect of everyone says anew)."""
    path = refused_path(course_dir, assignment)
    try:
        with open(path, encoding="utf-8") as fh:
            items = json.load(fh)
    except (OSError, ValueError):
        return
    kept = [i for i in items if isinstance(i, dict) and i.get("step") != step]
    write_atomic(path, json.dumps(kept, indent=1))


def refusals(course_dir, assignment):
    """Sentences for the instructor: every folder refused at collect or grade."""
    try:
        with open(refused_path(course_dir, assignment), encoding="utf-8") as fh:
            items = json.load(fh)
    except (OSError, ValueError):
        return []
    return [
        f"{i.get('step', 'collect')}: the folder {i.get('folder')} was not collected: "
        f"{i.get('reason')}"
        for i in items
        if isinstance(i, dict)
    ]


def notes_of(course_dir, assignment, student):
    """The notes on who handed a submission in and when, and on what was set aside
    (for the grade table and the student's feedback)."""
    record = read_record(course_dir, assignment, student) or {}
    notes = record.get("notes", [])
    return [str(n) for n in notes if isinstance(n, str)][:20] if isinstance(notes, list) else []


# ---- submitted/ at grading -------------------------------------------------------------------


def submissions(course_dir, assignment, roster=None):
    """(ids, refused) of ``submitted/``: the folders holding ``assignment`` whose
    name is a student id, and [(shown name, reason)] of the others. Nothing is
    changed; a link in place of a folder is never followed."""
    root = os.path.join(course_dir, "submitted")
    roster = roster_ids(course_dir) if roster is None else roster
    try:
        names = os.listdir(root)
    except OSError:
        return [], []
    ids, refused = [], []
    for name in sorted(names):
        try:
            top = os.lstat(os.path.join(root, name))
            inner = os.lstat(os.path.join(root, name, assignment))
        except OSError:
            continue  # no submission of this assignment
        if stat.S_ISLNK(top.st_mode) or stat.S_ISLNK(inner.st_mode):
            refused.append((shown(name), "it is a link to another folder, not a submission"))
            continue
        if not (stat.S_ISDIR(top.st_mode) and stat.S_ISDIR(inner.st_mode)):
            continue
        problem = id_problem(name, roster)
        if problem:
            refused.append((shown(name), f"its name {problem}"))
        else:
            ids.append(name)
    return ids, refused


def prepare(course_dir, assignment, student, now=None):
    """Make ``submitted/<student>/<assignment>/`` what nbgrader may read, and
    record what was found: entries that are not regular files of one link (links,
    hard links, special files) are set aside into ``.accelab/set-aside/``, never
    followed; the time is the exchange's record when collect made one for this
    very notebook, else ``timestamp.txt`` if it is sound (a malformed, missing or
    future one is set aside, and the submission graded as on time, with a note).
    Returns the notes (a folder that cannot be checked is said, never raised)."""
    try:
        return _prepare(course_dir, assignment, student, now)
    except OSError as exc:
        return [f"the submission's folder could not be checked ({exc.strerror or exc})"]


def _prepare(course_dir, assignment, student, now):
    folder = os.path.join(course_dir, "submitted", student, assignment)
    aside = os.path.join(course_dir, ".accelab", "set-aside", assignment, student)
    notes = []
    _set_aside_links(folder, "", aside, notes, 0)
    notebook = os.path.join(folder, f"{assignment}.ipynb")
    digest = sha256_of(notebook)
    stamp_path = os.path.join(folder, "timestamp.txt")
    record = read_record(course_dir, assignment, student) or {}
    if record.get("notebook") == digest and record.get("source") == "exchange":
        when = parse_time(str(record.get("time", "")))
        if when is not None:
            text, _ = read_small(stamp_path)
            if text != format_time(when):
                write_atomic(stamp_path, format_time(when))
            return _keep_notes(course_dir, assignment, student, record, notes)
    text, problem = read_small(stamp_path)
    if record.get("notebook") == digest and record.get("source") == "submitted":
        if text == record.get("stamp"):  # read before, and not changed since
            return _keep_notes(course_dir, assignment, student, record, notes)
    when, note = timestamp_note(text, problem, None, now)
    if note:
        notes.append(note)
        if problem != "missing":
            _move_aside(stamp_path, aside, "timestamp.txt")
            text = None
    record = {
        "source": "submitted",
        "student": student,
        "time": format_time(when) if when else None,
        "notebook": digest,
        "stamp": text,
        "notes": notes,
    }
    write_record(course_dir, assignment, student, record)
    return notes


def _keep_notes(course_dir, assignment, student, record, new):
    """The record's notes with ``new`` ones added (written back when there are)."""
    kept = [n for n in record.get("notes", []) if isinstance(n, str)]
    notes = list(dict.fromkeys(kept + new))
    if notes != kept:
        record["notes"] = notes
        write_record(course_dir, assignment, student, record)
    return notes


def _set_aside_links(folder, rel, aside, notes, depth):
    try:
        names = sorted(os.listdir(os.path.join(folder, rel) if rel else folder))
    except OSError:
        return
    for name in names:
        relname = os.path.join(rel, name) if rel else name
        path = os.path.join(folder, relname)
        try:
            st = os.lstat(path)
        except OSError:
            continue
        why = kind_of(st)
        if why is None and stat.S_ISDIR(st.st_mode):
            if depth >= MAX_DEPTH:
                why = f"a folder nested more than {MAX_DEPTH} deep"
            else:
                _set_aside_links(folder, relname, aside, notes, depth + 1)
                continue
        if why:
            _move_aside(path, aside, relname)
            notes.append(f"{shown(relname)} in the submission is {why}: set aside, not read")


def _move_aside(path, aside, relname):
    """Move an entry out of a submission (a link itself, never what it points to)."""
    target = os.path.join(aside, f"{utcnow():%Y%m%d-%H%M%S}-{secrets.token_hex(3)}", relname)
    try:
        os.makedirs(os.path.dirname(target), mode=0o700, exist_ok=True)
        os.rename(path, target)
    except OSError:
        try:
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.unlink(path)
        except OSError:
            pass


def clean_feedback(course_dir, assignment, students):
    """Each student's feedback folder holds only what the grader wrote: the
    feedback page, and the ``timestamp.txt`` and ``submission_secret.txt`` that
    ``nbgrader release_feedback`` reads, written here (never a student's file,
    nor anything a link in a submission pointed to)."""
    for student in students:
        try:
            _clean_feedback(course_dir, assignment, student)
        except OSError:
            pass  # the page is there or not; release_feedback says which


def _clean_feedback(course_dir, assignment, student):
    keep = f"{assignment}.html"
    folder = os.path.join(course_dir, "feedback", student, assignment)
    if not os.path.isdir(folder) or os.path.islink(folder):
        return
    for name in os.listdir(folder):
        path = os.path.join(folder, name)
        if name == keep and not os.path.islink(path):
            continue
        try:
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.unlink(path)
        except OSError:
            pass
    if not os.path.exists(os.path.join(folder, keep)):
        return
    record = read_record(course_dir, assignment, student) or {}
    when = parse_time(str(record.get("time") or "")) or utcnow()
    write_atomic(os.path.join(folder, "timestamp.txt"), format_time(when))
    text, _ = read_small(
        os.path.join(course_dir, "submitted", student, assignment, "submission_secret.txt")
    )
    secret = sane_secret(text) or secrets.token_hex(64)
    write_atomic(os.path.join(folder, "submission_secret.txt"), secret)
