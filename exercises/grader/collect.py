"""``nbgrader collect`` for an accelab course: who and when from what a student
cannot forge, and files, never links.

The course's ``nbgrader_config.py`` installs :class:`AccelabCollect` in place of
nbgrader's file-exchange collect (``c.ExchangeFactory.collect``), so ``nbgrader
collect`` and formgrader's collect button both use it. Against nbgrader's own:

* the submitter is the account that owns the folder in ``inbound/`` (mapped to a
  roster id, :func:`~.intake.id_of_account`), not the name written into the
  folder's name: ``nbgrader submit --student ann`` from another account is that
  account's submission, with a note that names the claim; a folder whose owner
  is no student on the roster is refused, and the others are collected;
* the time is the exchange's record: the newest change time of the folder and
  of everything in it (a user can move it later, never earlier); the latest
  submission, and the last one before the due date with ``--before-duedate``,
  are chosen by it; ``timestamp.txt`` is cross-checked (:func:`~.intake.timestamp_note`)
  and ``submitted/<id>/<A>/timestamp.txt`` is written from the record;
* only regular files the submitter owns are read (no link is followed, a hard
  link to someone else's file and special files are left, each with a note),
  within nbgrader's size limits, through file descriptors opened without
  following links, into a new folder swapped in whole;
* one bad folder (a name that does not parse, a file that cannot be read) is
  refused with a note and never stops the others.

What it learnt is kept in the submission's record (:mod:`.intake`), and refused
folders in ``.accelab/intake/<A>/refused.json``.
"""

import hashlib
import os
import secrets
import shutil
import stat

from nbgrader.api import Gradebook, MissingEntry
from nbgrader.exchange.default.collect import ExchangeCollect

from ..layout import exchange_problem
from ..nbgrader_course import roster_ids
from . import intake

#: the files nbgrader's submit writes beside the notebooks, read here, never copied as they are
STAMP, SECRET = "timestamp.txt", "submission_secret.txt"


class Refused(Exception):
    """A folder that is not collected; the message says why."""


def _split_name(name, assignment):
    """The claimed id of an inbound folder ``<id>+<assignment>+<time>[+<random>]``,
    or None when the name is not one of ``assignment``."""
    parts = name.split("+")
    for tail in (3, 2):  # with and without nbgrader's random string
        k = len(parts) - tail
        if k >= 1 and parts[k] == assignment:
            return "+".join(parts[:k])
    return None


def tree_time(path):
    """The newest change time [ns] of a folder and of everything in it (not
    following links), at most MAX_ENTRIES entries deep MAX_DEPTH."""
    newest = os.lstat(path).st_ctime_ns
    seen = 0
    stack = [(path, 0)]
    while stack:
        folder, depth = stack.pop()
        with os.scandir(folder) as entries:
            for entry in entries:
                seen += 1
                if seen > intake.MAX_ENTRIES:
                    return newest
                st = entry.stat(follow_symlinks=False)
                newest = max(newest, st.st_ctime_ns)
                if stat.S_ISDIR(st.st_mode) and depth < intake.MAX_DEPTH:
                    stack.append((entry.path, depth + 1))
    return newest


class _Copy:
    """Copy a submission's regular files, through descriptors that never follow a
    link, checking each file's owner; notes say what was left."""

    def __init__(self, owner, ignore, max_file, max_total):
        self.owner, self.ignore = owner, list(ignore)
        self.max_file, self.left = max_file, max_total
        self.files, self.notes, self.newest, self.count = {}, [], 0, 0

    def leave(self, rel, why):
        self.notes.append(f"{intake.shown(rel)} in the submission is {why}: not collected")

    def tree(self, src_fd, dest, rel="", depth=0):
        for name in sorted(os.listdir(src_fd)):
            relname = os.path.join(rel, name) if rel else name
            if not rel and name in (STAMP, SECRET):
                continue
            if intake.ignored(name, self.ignore):
                continue
            self.count += 1
            if self.count > intake.MAX_ENTRIES:
                self.leave(relname, f"past the first {intake.MAX_ENTRIES} entries")
                return
            st = os.stat(name, dir_fd=src_fd, follow_symlinks=False)
            self.newest = max(self.newest, st.st_ctime_ns)
            why = intake.kind_of(st, self.owner)
            if why:
                self.leave(relname, why)
            elif stat.S_ISDIR(st.st_mode):
                if depth >= intake.MAX_DEPTH:
                    self.leave(relname, f"a folder nested more than {intake.MAX_DEPTH} deep")
                    continue
                flags = os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW
                sub = os.open(name, flags, dir_fd=src_fd)
                try:
                    os.mkdir(os.path.join(dest, name), 0o700)
                    self.tree(sub, os.path.join(dest, name), relname, depth + 1)
                    self.newest = max(self.newest, os.fstat(sub).st_ctime_ns)
                finally:
                    os.close(sub)
            else:
                self.file(src_fd, name, st, os.path.join(dest, name), relname)

    def file(self, src_fd, name, st, dest, relname):
        if st.st_size > self.max_file:
            self.leave(relname, f"larger than {self.max_file // 1000} kB")
            return
        if st.st_size > self.left:
            self.leave(relname, "past the size the exchange takes of one submission")
            return
        flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY
        fd = os.open(name, flags, dir_fd=src_fd)
        try:
            now = os.fstat(fd)
            if (now.st_dev, now.st_ino) != (st.st_dev, st.st_ino) or intake.kind_of(
                now, self.owner
            ):
                self.leave(relname, "changed while it was collected")
                return
            digest, size = hashlib.sha256(), 0
            out = os.open(dest, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
            try:
                while chunk := os.read(fd, 1 << 20):
                    size += len(chunk)
                    if size > min(self.max_file, self.left):
                        raise Refused(f"{intake.shown(relname)} grew while it was collected")
                    digest.update(chunk)
                    view = memoryview(chunk)
                    while view:
                        view = view[os.write(out, view) :]
            finally:
                os.close(out)
            self.left -= size
            self.files[relname] = digest.hexdigest()
            self.newest = max(self.newest, os.fstat(fd).st_ctime_ns)
        finally:
            os.close(fd)


class AccelabCollect(ExchangeCollect):
    """nbgrader's collect with the submitter, the time and the files taken from
    what a student cannot forge (see the module's text)."""

    def _course_dir(self):
        return os.path.abspath(self.coursedir.root or ".")

    def _refuse(self, name, reason):
        self.log.warning("Not collected: %s: %s", intake.shown(name, 120), reason)
        try:
            intake.note_refused(self._course_dir(), self.coursedir.assignment_id, name, reason)
        except OSError as exc:
            self.log.error("could not keep the note on %s: %s", intake.shown(name), exc)

    def init_src(self):
        if self.coursedir.course_id == "":
            self.fail("No course id specified. Re-run with --course flag.")
        self.course_path = os.path.join(self.root, self.coursedir.course_id)
        self.inbound_path = os.path.join(self.course_path, "inbound")
        problem = exchange_problem(self.root, self.coursedir.course_id)
        if problem:
            self.fail(problem)
        if not os.access(self.inbound_path, os.R_OK | os.X_OK):
            self.fail(f"You don't have read permissions for the directory: {self.inbound_path}")
        course_dir, assignment = self._course_dir(), self.coursedir.assignment_id
        roster = roster_ids(course_dir)
        only = self.coursedir.student_id if self.coursedir.student_id not in ("", "*") else None
        if only is None:  # this run says anew what it refused
            intake.clear_refused(course_dir, assignment, "collect")
        records = []
        for name in sorted(os.listdir(self.inbound_path)):
            claimed = _split_name(name, assignment)
            if claimed is None:
                if f"+{assignment}+" in name:
                    self._refuse(name, "its name is not <student>+<assignment>+<time>")
                continue
            path = os.path.join(self.inbound_path, name)
            try:
                st = os.lstat(path)
                if stat.S_ISLNK(st.st_mode) or not stat.S_ISDIR(st.st_mode):
                    raise Refused("it is a link or a file, not a folder")
                account = intake.account_of_uid(st.st_uid)
                sid = intake.id_of_account(course_dir, account, roster)
                if sid is None:
                    who = account if account is not None else f"uid {st.st_uid}"
                    raise Refused(
                        f"it belongs to the account {intake.shown(who)}, which is no student "
                        "on the roster (add the account to the roster, with its id, if it is one)"
                    )
                when = intake.from_ns(tree_time(path))
            except Refused as exc:
                self._refuse(name, str(exc))
                continue
            except OSError as exc:
                self._refuse(name, f"it cannot be read ({exc.strerror})")
                continue
            if only and sid != only:
                continue
            records.append(
                {
                    "username": sid,
                    "filename": name,
                    "timestamp": when,
                    "claimed": claimed,
                    "account": account,
                    "uid": st.st_uid,
                }
            )
        with Gradebook(self.coursedir.db_url, self.coursedir.course_id) as gb:
            try:
                self.duedate = gb.find_assignment(assignment).duedate
            except MissingEntry:
                self.duedate = None
        by_student = {}
        for rec in records:
            by_student.setdefault(rec["username"], []).append(rec)
        self.src_records = []
        for sid, recs in by_student.items():
            recs.sort(key=lambda r: r["timestamp"], reverse=True)
            pick = recs[0]
            if self.before_duedate and self.duedate is not None:
                on_time = [r for r in recs if r["timestamp"] <= self.duedate]
                pick = on_time[0] if on_time else recs[0]
            # every name this account handed in under that is not its own (flagged)
            pick["claims"] = list(
                dict.fromkeys(r["claimed"] for r in recs if r["claimed"] not in (sid, r["account"]))
            )
            self.src_records.append(pick)

    def copy_files(self):
        assignment = self.coursedir.assignment_id
        if not self.src_records:
            self.log.warning(
                "No submissions of '%s' for course '%s' to collect",
                assignment,
                self.coursedir.course_id,
            )
        for rec in self.src_records:
            sid = rec["username"]
            dest = self.coursedir.format_path(self.coursedir.submitted_directory, sid, assignment)
            if os.path.isdir(dest):
                text, _ = intake.read_small(os.path.join(dest, STAMP))
                existing = intake.parse_time(text) if text is not None else None
                new = rec["timestamp"]
                fresher = existing is None or new > existing
                if not (self.update and fresher) and not (self.before_duedate and existing != new):
                    self.log.info(
                        "Submission already collected (use --update for a newer one): %s %s",
                        sid,
                        assignment,
                    )
                    continue
            try:
                self._collect(rec, dest)
            except (OSError, Refused) as exc:
                why = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
                self._refuse(rec["filename"], f"it could not be collected ({why})")

    def _collect(self, rec, dest):
        course_dir, assignment, sid = (
            self._course_dir(),
            self.coursedir.assignment_id,
            rec["username"],
        )
        src = os.path.join(self.inbound_path, rec["filename"])
        parent = os.path.dirname(dest)
        os.makedirs(parent, exist_ok=True)
        tmp = os.path.join(parent, f".{assignment}.collecting-{secrets.token_hex(4)}")
        os.mkdir(tmp, 0o700)
        copier = _Copy(
            rec["uid"],
            self.coursedir.ignore,
            1000 * int(self.coursedir.max_file_size),
            1000 * int(self.coursedir.max_dir_size),
        )
        try:
            src_fd = os.open(src, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW)
            try:
                if os.fstat(src_fd).st_uid != rec["uid"]:
                    raise Refused("its owner changed while it was collected")
                copier.tree(src_fd, tmp)
                stamp, problem = intake.read_small(dir_fd=src_fd, name=STAMP)
                secret, _ = intake.read_small(dir_fd=src_fd, name=SECRET)
                newest = max(copier.newest, os.fstat(src_fd).st_ctime_ns)
            finally:
                os.close(src_fd)
            when = max(rec["timestamp"], intake.from_ns(newest))
            when, note = intake.timestamp_note(stamp, problem, when)
            notes = []
            if rec["claimed"] not in (sid, rec["account"]):  # nbgrader names it by account
                notes.append(
                    f"handed in under the name {intake.shown(rec['claimed'])} by the account "
                    f"{intake.shown(rec['account'])}, whose submission it is: graded as "
                    f"{sid}'s own"
                )
            others = [c for c in rec.get("claims", []) if c != rec["claimed"]]
            if others:
                notes.append(
                    f"the account {intake.shown(rec['account'])} also handed in under the "
                    f"name(s) {', '.join(intake.shown(c) for c in others[:5])} (earlier "
                    "submissions, not graded: only the latest is)"
                )
            notes += [note] if note else []
            notes += copier.notes
            intake.write_atomic(os.path.join(tmp, STAMP), intake.format_time(when))
            intake.write_atomic(
                os.path.join(tmp, SECRET), intake.sane_secret(secret) or secrets.token_hex(64)
            )
            old = None
            if os.path.lexists(dest):
                old = os.path.join(parent, f".{assignment}.replaced-{secrets.token_hex(4)}")
                os.rename(dest, old)
            os.rename(tmp, dest)
            tmp = None
            if old:
                shutil.rmtree(old, ignore_errors=True)
        finally:
            if tmp:
                shutil.rmtree(tmp, ignore_errors=True)
        record = {
            "source": "exchange",
            "student": sid,
            "account": rec["account"],
            "claimed": intake.shown(rec["claimed"]),
            "folder": intake.shown(rec["filename"], 200),
            "time": intake.format_time(when),
            "notebook": copier.files.get(f"{assignment}.ipynb"),
            "files": copier.files,
            "notes": notes,
        }
        intake.write_record(course_dir, assignment, sid, record)
        self.log.info(
            "Collected submission: %s %s (handed in by the account %s, %s)",
            sid,
            assignment,
            intake.shown(rec["account"]),
            intake.format_time(when),
        )
        for n in notes:
            self.log.warning("%s %s: %s", sid, assignment, n)
