"""What runs inside the grading sandbox: a submission's cells, one at a time, as
the grader's supervisor (:mod:`accelab.exercises.grader.supervisor`) sends them, and
reports of what the answer variables hold.

This is trusted code in an untrusted process: the student's cells run in this
same interpreter and may change anything here, so nothing it sends is believed
beyond "this is what the notebook claims". The supervisor reads its messages as
bounded data, judges nothing but the reported values, and times it from outside.

Protocol: length-prefixed JSON frames (4-byte big-endian length, then UTF-8
JSON) on two inherited file descriptors, commands in and replies out:

* ``{"op": "statement", "statement": {...}}`` -> ``{"ok": true}``: the
  submitter's statement (:func:`accelab.exercises.student.runtime.set_grading_statement`);
* ``{"op": "run", "source": "..."}`` -> ``{"status": "ok" | "error",
  "outputs": [...]}``: one cell, its outputs as nbformat output dicts (plain
  text and PNG images only, each capped);
* ``{"op": "report", "names": [...]}`` -> ``{"values": {name: report},
  "loaded": ..., "refused": [...]}`` (:func:`accelab.exercises.student.answers.describe`).

Run as ``python -I -m accelab.exercises.student.kernel CMD_FD REPLY_FD LIMITS_JSON``.
"""

import base64
import io
import json
import os
import resource
import struct
import sys

#: largest frame either side accepts [bytes]
MAX_FRAME = 8 * 1024 * 1024


def read_frame(fd, limit=MAX_FRAME):
    """One frame from ``fd``, or None at end of file."""
    head = _read_exactly(fd, 4)
    if head is None:
        return None
    (size,) = struct.unpack(">I", head)
    if size > limit:
        raise ValueError(f"frame of {size} bytes is over the limit of {limit}")
    body = _read_exactly(fd, size)
    if body is None:
        return None
    return json.loads(body.decode("utf-8"))


def _read_exactly(fd, n):
    chunks, got = [], 0
    while got < n:
        chunk = os.read(fd, n - got)
        if not chunk:
            return None
        chunks.append(chunk)
        got += len(chunk)
    return b"".join(chunks)


def write_frame(fd, message):
    body = json.dumps(message, allow_nan=False).encode("utf-8")
    data = struct.pack(">I", len(body)) + body
    while data:
        data = data[os.write(fd, data) :]


class CappedText(io.TextIOBase):
    """A text stream that keeps the first ``limit`` characters and counts the rest."""

    def __init__(self, limit):
        self.limit, self.parts, self.kept, self.dropped = limit, [], 0, 0

    def writable(self):
        return True

    def write(self, text):
        text = str(text)
        room = self.limit - self.kept
        if room > 0:
            self.parts.append(text[:room])
            self.kept += min(room, len(text))
        self.dropped += max(0, len(text) - max(room, 0))
        return len(text)

    def value(self):
        text = "".join(self.parts)
        if self.dropped:
            text += f"\n[... {self.dropped} more characters of output were cut]\n"
        return text


def apply_limits(limits):
    """Resource limits of this process and every process it starts."""
    pairs = [
        (resource.RLIMIT_AS, limits.get("memory_bytes")),
        (resource.RLIMIT_CPU, limits.get("cpu_seconds")),
        (resource.RLIMIT_NPROC, limits.get("processes")),
        (resource.RLIMIT_FSIZE, limits.get("file_bytes")),
        (resource.RLIMIT_CORE, 0),
    ]
    for which, value in pairs:
        if value is not None:
            resource.setrlimit(which, (int(value), int(value)))


def make_shell():
    """An IPython shell in this process (magics and display work; no history file)."""
    from IPython.core.interactiveshell import InteractiveShell
    from traitlets.config import Config

    config = Config()
    config.HistoryManager.enabled = False
    shell = InteractiveShell.instance(config=config)
    shell.showtraceback = lambda *args, **kwargs: None
    shell.showsyntaxerror = lambda *args, **kwargs: None
    return shell


def run_cell(shell, source, limits):
    """Run one cell; its status and outputs (text and PNG, capped)."""
    from IPython.core.displayhook import CapturingDisplayHook
    from IPython.core.displaypub import CapturingDisplayPublisher

    chars = int(limits.get("output_chars", 20000))
    out, err = CappedText(chars), CappedText(chars)
    publisher = CapturingDisplayPublisher()
    saved = sys.stdout, sys.stderr, sys.displayhook, shell.display_pub
    sys.stdout, sys.stderr = out, err
    sys.displayhook = CapturingDisplayHook(shell=shell, outputs=publisher.outputs)
    shell.display_pub = publisher
    try:
        result = shell.run_cell(source, store_history=False)
    finally:
        sys.stdout, sys.stderr, sys.displayhook, shell.display_pub = saved
    outputs = []
    for name, stream in (("stdout", out), ("stderr", err)):
        text = stream.value()
        if text:
            outputs.append({"output_type": "stream", "name": name, "text": text})
    outputs += _displays(publisher.outputs, limits)
    error = result.error_before_exec or result.error_in_exec
    if error is None:
        return {"status": "ok", "outputs": outputs}
    return {
        "status": "error",
        "outputs": outputs,
        "ename": _safe(lambda: type(error).__name__),
        "evalue": _safe(lambda: str(error))[:chars],
    }


def _safe(fn):
    try:
        return str(fn())
    except BaseException:  # noqa: BLE001 - a student's exception whose str() raises anything
        return "(an exception that cannot be printed)"


def _displays(items, limits):
    """Rich outputs reduced to plain text and PNG images (nothing that a browser
    would run), each capped."""
    chars = int(limits.get("output_chars", 20000))
    image_bytes = int(limits.get("image_bytes", 300000))
    outputs = []
    for item in items[:50]:
        data = item.get("data") or {}
        kept = {}
        if isinstance(data.get("text/plain"), str):
            kept["text/plain"] = data["text/plain"][:chars]
        png = data.get("image/png")
        if isinstance(png, bytes):
            png = base64.b64encode(png).decode("ascii")
        if isinstance(png, str) and len(png) <= image_bytes * 4 // 3 + 4:
            kept["image/png"] = png
        if kept:
            outputs.append({"output_type": "display_data", "data": kept, "metadata": {}})
    return outputs


def report(shell, names):
    """What each named variable holds (:func:`accelab.exercises.student.answers.describe`)."""
    from .answers import MISSING, describe

    values = {}
    for name in names:
        values[str(name)] = describe(shell.user_ns.get(str(name), MISSING))
    try:
        from .runtime import loaded_student

        loaded, refused = loaded_student()
    except Exception:  # noqa: BLE001 - the report never fails for it: 'loaded' stays unknown
        loaded, refused = None, []
    return {"values": values, "loaded": loaded, "refused": refused[:20]}


def alias_old_names():
    """The student-side modules under the names accelab 0.1 gave them.

    A notebook released by accelab 0.1 imports ``exercises.runtime`` in its
    locked cells, and nbgrader restores locked cells from the gradebook, so a
    course made then keeps grading (CHANGELOG, 0.2.0). Only here, inside the
    sandbox: nothing of the package installs the old names.
    """
    import types

    from . import answers, runtime

    old = types.ModuleType("exercises", "accelab 0.1's name of accelab.exercises")
    old.__path__ = []
    old.runtime, old.answers = runtime, answers
    for name, module in (
        ("exercises", old),
        ("exercises.runtime", runtime),
        ("exercises.answers", answers),
    ):
        sys.modules.setdefault(name, module)


def _leave_the_pipes(cmd_fd, reply_fd):
    """A process forked from a cell (``os.fork``) runs on with the cell, but without the
    grader's pipes: it cannot take the grader's next command from its parent, nor keep
    the reply pipe open after its parent dies; :func:`serve` ends it with the cell."""

    def in_child():
        for fd in (cmd_fd, reply_fd):
            try:
                os.close(fd)
            except OSError:
                pass

    os.register_at_fork(after_in_child=in_child)


def serve(cmd_fd, reply_fd, limits):
    shell = make_shell()
    alias_old_names()
    kernel = os.getpid()
    _leave_the_pipes(cmd_fd, reply_fd)
    while True:
        message = read_frame(cmd_fd)
        if message is None or message.get("op") == "exit":
            return
        op = message.get("op")
        if op == "statement":
            from .runtime import set_grading_statement

            set_grading_statement(message["statement"])
            reply = {"ok": True}
        elif op == "run":
            reply = run_cell(shell, str(message.get("source", "")), limits)
        elif op == "report":
            reply = report(shell, list(message.get("names", [])))
        else:
            reply = {"error": f"unknown op {op!r}"}
        if os.getpid() != kernel:  # forked in the cell (or a report it ran): ends with it
            os._exit(0)
        write_frame(reply_fd, reply)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    cmd_fd, reply_fd, limits = int(argv[0]), int(argv[1]), json.loads(argv[2])
    apply_limits(limits)
    null = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):  # a cell's raw writes to fd 1 and 2 go nowhere
        os.dup2(null, fd)
    sys.stdout = io.TextIOWrapper(open(1, "wb", closefd=False), write_through=True)
    sys.stderr = io.TextIOWrapper(open(2, "wb", closefd=False), write_through=True)
    serve(cmd_fd, reply_fd, limits)
    os._exit(0)


if __name__ == "__main__":
    main()
