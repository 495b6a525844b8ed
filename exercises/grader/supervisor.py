"""Running one submission's plan in the sandbox, from outside it.

The supervisor starts the sandboxed kernel (:mod:`accelab.exercises.student.kernel`), hands it
the submitter's statement, sends the cells one at a time and asks for a report
at each test cell. It keeps the clock: each cell has ``cell_seconds``, the whole
submission ``total_seconds`` (restarts and replays included). A cell that runs
over its time, ends the process (``os._exit``, a crash, a signal, a memory
limit) or sends something that is not a reply costs that cell: the sandbox is
killed with every process in it, a new one starts, the cells that ran before
are replayed (their outputs kept from the first run), the cell is skipped, and
the run goes on. Nothing the sandbox sends is trusted beyond being data of a
bounded size.
"""

import json
import os
import select
import signal
import struct
import subprocess
import sys
import time
from dataclasses import dataclass, field

from ..student.kernel import MAX_FRAME
from .sandbox import WORKDIR, close_fds

#: seconds the sandbox may take to start and take the statement
START_SECONDS = 30.0
#: seconds a report may take (reading a few variables)
REPORT_SECONDS = 5.0


@dataclass(frozen=True)
class Limits:
    """What one submission may use."""

    cell_seconds: float = 10.0  # [s] wall time of one cell
    total_seconds: float = 60.0  # [s] wall time of the whole submission
    cpu_seconds: int = 60  # [s] CPU time of each process
    memory_bytes: int = 1536 << 20  # [bytes] address space of each process
    processes: int = 64  # processes of the sandbox user
    file_bytes: int = 16 << 20  # [bytes] largest file it may write
    disk_bytes: int = 64 << 20  # [bytes] its /tmp (a tmpfs)
    output_chars: int = 20000  # [characters] kept per stream and cell
    total_output_chars: int = 200000  # [characters] kept over the whole submission
    # caps paid here, in the grader's process (the kernel's own caps are the student's to
    # change): what one submission can put into its feedback page and the gradebook
    outputs_per_cell: int = 100  # outputs kept per cell (streams, displays)
    total_outputs: int = 1000  # outputs kept over the whole submission
    images_per_cell: int = 20  # PNG images kept per cell
    total_images: int = 100  # PNG images kept over the whole submission
    image_bytes: int = 1 << 20  # [bytes] largest PNG image kept (decoded)
    total_image_bytes: int = 8 << 20  # [bytes] PNG images kept over the whole submission
    image_side: int = 4000  # [pixels] widest and tallest PNG image kept
    image_pixels: int = 8_000_000  # [pixels] largest PNG image kept (width x height)

    def for_kernel(self):
        return {
            "memory_bytes": self.memory_bytes,
            "cpu_seconds": self.cpu_seconds,
            "processes": self.processes,
            "file_bytes": self.file_bytes,
            "output_chars": self.output_chars,
        }


class SandboxBroken(Exception):
    """The sandbox itself did not start (not the submission's doing)."""


class Failure(Exception):
    """The sandbox did not answer as it should; ``cause`` says how, for the student."""

    def __init__(self, cause):
        super().__init__(cause)
        self.cause = cause


@dataclass
class CellRun:
    """What became of one step: ``status`` is ok, error, timeout, died, garbled,
    or not_run; ``message`` is the cause in words for the student."""

    status: str
    outputs: list = field(default_factory=list)
    message: str = ""
    seconds: float = 0.0


@dataclass
class RunResult:
    """The run of a plan: per step index its :class:`CellRun`; per answer name
    the report of what it held at its test cell; who the notebook loaded."""

    cells: dict
    reports: dict
    loaded: list
    refused: list
    seconds: float
    starts: int
    error: str = ""

    def to_dict(self):
        return {
            "cells": {str(k): vars(v) for k, v in self.cells.items()},
            "reports": self.reports,
            "loaded": self.loaded,
            "refused": self.refused,
            "seconds": self.seconds,
            "starts": self.starts,
            "error": self.error,
        }


class Kernel:
    """One sandboxed kernel process and its two pipes."""

    def __init__(self, command, limits):
        self.command, self.limits, self.proc = command, limits, None

    def start(self, argv_of, env):
        cmd_r, cmd_w = os.pipe()
        rep_r, rep_w = os.pipe()
        argv = argv_of(cmd_r, rep_w)
        cmd = None
        try:
            cmd = self.command(argv, env)
            self.proc = subprocess.Popen(
                cmd,
                pass_fds=(cmd_r, rep_w, *getattr(cmd, "fds", ())),
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                start_new_session=True,
            )
        finally:
            os.close(cmd_r)
            os.close(rep_w)
            close_fds(cmd)
        self.cmd_w, self.rep_r = cmd_w, rep_r

    def call(self, message, seconds):
        """Send ``message`` and wait up to ``seconds`` for the reply."""
        body = json.dumps(message).encode("utf-8")
        try:
            os.write(self.cmd_w, struct.pack(">I", len(body)))
            view = memoryview(body)
            while view:
                view = view[os.write(self.cmd_w, view) :]
        except OSError:
            raise Failure(self._death()) from None
        deadline = time.monotonic() + seconds
        head = self._read(4, deadline)
        (size,) = struct.unpack(">I", head)
        if size > MAX_FRAME:
            raise Failure(
                f"the notebook's process sent {size} bytes at once, over the limit of {MAX_FRAME}"
            )
        try:
            reply = json.loads(self._read(size, deadline).decode("utf-8"))
        except (ValueError, RecursionError):  # not JSON, or nested too deep to read
            raise Failure("the notebook's process sent something that is not a reply") from None
        if not isinstance(reply, dict):
            raise Failure("the notebook's process sent something that is not a reply")
        return reply

    def _read(self, n, deadline):
        data = bytearray()  # grown in place: a frame of megabytes comes a pipe's worth at a time
        while len(data) < n:
            left = deadline - time.monotonic()
            if left <= 0:
                raise Failure("timeout")
            ready, _, _ = select.select([self.rep_r], [], [], left)
            if not ready:
                raise Failure("timeout")
            chunk = os.read(self.rep_r, n - len(data))
            if not chunk:
                raise Failure(self._death())
            data += chunk
        return bytes(data)

    def _death(self):
        try:
            code = self.proc.wait(timeout=2)
        except subprocess.TimeoutExpired:
            return "the notebook's process stopped answering"
        if code in (-signal.SIGKILL, 128 + signal.SIGKILL, 137):
            return (
                "the notebook's process was killed (a memory or process limit, or a "
                "signal it sent itself)"
            )
        if code in (-signal.SIGXCPU, 128 + signal.SIGXCPU):
            return "the notebook's process used up its CPU time"
        return f"the notebook's process ended (exit status {code}: os._exit, exit() or a crash)"

    def stop(self):
        """Kill the sandbox and every process in it; close the pipes."""
        if self.proc is None:
            return
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except OSError:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            pass
        for fd in (self.cmd_w, self.rep_r):
            try:
                os.close(fd)
            except OSError:
                pass
        if self.proc.stderr:
            self.proc.stderr.close()
        self.proc = None


def kernel_env(student):
    """The sandbox's whole environment: nothing of the instructor's."""
    return {
        "PATH": f"{os.path.dirname(sys.executable)}:/usr/bin:/bin",
        "HOME": WORKDIR,
        "TMPDIR": "/tmp",
        "LANG": "C.UTF-8",
        "MPLBACKEND": "Agg",
        "MPLCONFIGDIR": f"{WORKDIR}/.matplotlib",
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "MKL_NUM_THREADS": "1",
        "PYTHONDONTWRITEBYTECODE": "1",
        "PYTHONWARNINGS": "ignore",
        "ACCELAB_STUDENT_ID": str(student),
        "NBGRADER_EXECUTION": "autograde",
    }


def run_plan(steps, statement, command, limits=Limits(), slot=0):
    """Run ``steps`` (from :func:`accelab.exercises.grader.plan.plan_of`) for the
    submitter whose ``statement`` it is, in sandboxes made by ``command``
    (a :class:`~accelab.exercises.grader.sandbox.SandboxCommand`). Returns a
    :class:`RunResult`; never raises for anything the submission does."""
    start = time.monotonic()
    deadline = start + limits.total_seconds
    env = kernel_env(statement["student"])
    cells, reports = {}, {}
    loaded, refused = [], []
    done = []  # indices of code steps that ran to the end (replayed after a restart)
    budget = Budget(limits)
    starts = 0
    kernel = None

    def argv_of(cmd_fd, rep_fd):
        return [
            sys.executable,
            "-I",
            "-m",
            "accelab.exercises.student.kernel",
            str(cmd_fd),
            str(rep_fd),
            json.dumps(limits.for_kernel()),
        ]

    def command_of(argv, env_):
        return command.command(argv, slot=slot, env=env_, limits={"disk_bytes": limits.disk_bytes})

    def fresh():
        """A new sandbox with the statement and the cells that ran before replayed."""
        nonlocal kernel, starts
        while True:
            if kernel is not None:
                kernel.stop()
            kernel = Kernel(command_of, limits)
            starts += 1
            kernel.start(argv_of, env)
            try:
                kernel.call(
                    {"op": "statement", "statement": statement},
                    min(START_SECONDS, max(deadline - time.monotonic(), 0.1)),
                )
            except Failure as exc:
                detail = (
                    kernel.proc.stderr.read(2000).decode("utf-8", "replace").strip()
                    if kernel.proc and kernel.proc.stderr
                    else ""
                )
                raise SandboxBroken(f"{exc.cause}; {detail}" if detail else exc.cause) from None
            for j in list(done):
                try:
                    kernel.call(
                        {"op": "run", "source": steps[j].source},
                        min(limits.cell_seconds, max(deadline - time.monotonic(), 0.1)),
                    )
                except Failure:
                    done.remove(j)  # it did not replay: go without it
                    break
            else:
                return
            if time.monotonic() >= deadline:
                raise Failure("timeout")

    error = ""
    k = 0
    while k < len(steps):
        step = steps[k]
        left = deadline - time.monotonic()
        if left <= 0:
            break
        t0 = time.monotonic()
        try:
            if kernel is None:
                fresh()
            if step.kind == "code":
                reply = kernel.call(
                    {"op": "run", "source": step.source}, min(limits.cell_seconds, left)
                )
                cells[k] = _readable(_cell_run, reply, time.monotonic() - t0, budget)
                done.append(k)
            else:
                reply = kernel.call(
                    {"op": "report", "names": [step.name]}, min(REPORT_SECONDS, left)
                )
                reports[step.name] = _readable(_report_of, reply, step.name)
                _readable(_note_loaded, reply, loaded, refused)
                cells[k] = CellRun("ok", seconds=time.monotonic() - t0)
        except Failure as exc:
            seconds = time.monotonic() - t0
            cause = exc.cause
            if cause == "timeout":
                limit = limits.cell_seconds if step.kind == "code" else REPORT_SECONDS
                if seconds < limit - 0.5:
                    cause = (
                        f"the submission's time ({limits.total_seconds:g} s in all) ran "
                        "out during this cell"
                    )
                else:
                    cause = f"this cell ran past its time limit of {limit:g} s"
            cells[k] = CellRun(
                "timeout" if "time" in cause else "died", message=cause, seconds=seconds
            )
            if kernel is not None:
                kernel.stop()
                kernel = None
        except (OSError, SandboxBroken) as exc:  # the sandbox could not start at all
            error = f"the sandbox could not start: {exc}"
            break
        k += 1
    if kernel is not None:
        kernel.stop()
    for j in range(len(steps)):
        if j not in cells:
            cells[j] = CellRun(
                "not_run",
                message=error
                or (
                    f"not run: the submission's time ({limits.total_seconds:g} s in all) ran out "
                    "before this cell"
                ),
            )
    return RunResult(cells, reports, loaded, refused, time.monotonic() - start, starts, error)


def _readable(read, reply, *args):
    """``read(reply, *args)``; a reply of a shape the grader does not expect (the
    kernel is the student's: it can send anything) is the cell's failure, never
    the grader's."""
    try:
        return read(reply, *args)
    except (TypeError, AttributeError, ValueError, KeyError, IndexError, RecursionError):
        raise Failure("the notebook's process sent a reply the grader cannot read") from None


def _report_of(reply, name):
    values = reply.get("values")
    report = values.get(name) if isinstance(values, dict) else None
    return report if isinstance(report, dict) else {"state": "garbled"}


def _note_loaded(reply, loaded, refused):
    who = reply.get("loaded")
    if isinstance(who, str) and who[:100] not in loaded:
        loaded.append(who[:100])
    others = reply.get("refused")
    for other in others if isinstance(others, list) else []:
        if isinstance(other, str) and other[:100] not in refused and len(refused) < 20:
            refused.append(other[:100])


class Budget:
    """What a submission may still put into its outputs, over the whole run and in
    the cell at hand (:class:`Limits`); kept here, outside the sandbox."""

    def __init__(self, limits):
        self.limits = limits
        self.chars = limits.total_output_chars
        self.outputs = limits.total_outputs
        self.images = limits.total_images
        self.image_bytes = limits.total_image_bytes
        self.new_cell()

    def new_cell(self):
        self.cell_outputs = self.limits.outputs_per_cell
        self.cell_images = self.limits.images_per_cell
        self.cell_chars = {"stdout": self.limits.output_chars, "stderr": self.limits.output_chars}
        self.left_out = {}  # why -> how many outputs of this cell were left out

    def leave_out(self, why):
        self.left_out[why] = self.left_out.get(why, 0) + 1

    def take_text(self, text, stream=None):
        room = self.chars if stream is None else min(self.chars, self.cell_chars[stream])
        kept = text[: max(room, 0)]
        self.chars -= len(kept)
        if stream is not None:
            self.cell_chars[stream] -= len(kept)
        return kept

    def take_output(self):
        if self.outputs <= 0 or self.cell_outputs <= 0:
            self.leave_out(
                f"outputs past {self.limits.outputs_per_cell} a cell or "
                f"{self.limits.total_outputs} in the notebook"
            )
            return False
        self.outputs -= 1
        self.cell_outputs -= 1
        return True

    def take_image(self, png):
        """Whether the image (base64 text) is kept; the reason is noted when not."""
        if self.images <= 0 or self.cell_images <= 0:
            self.leave_out(
                f"images past {self.limits.images_per_cell} a cell or "
                f"{self.limits.total_images} in the notebook"
            )
            return False
        if len(png) > (self.limits.image_bytes * 4) // 3 + 4:
            self.leave_out(f"images over {self.limits.image_bytes >> 10} KiB")
            return False
        size = png_size(png)
        if size is None:
            self.leave_out("images that are not PNG files")
            return False
        width, height = size
        side, pixels = self.limits.image_side, self.limits.image_pixels
        if width > side or height > side or width * height > pixels:
            self.leave_out(
                f"images over {side} x {side} pixels or {pixels / 1e6:g} million pixels "
                f"(one of {width} x {height})"
            )
            return False
        nbytes = len(png) * 3 // 4
        if nbytes > self.image_bytes:
            self.leave_out(f"images over {self.limits.total_image_bytes >> 20} MiB in all")
            return False
        self.images -= 1
        self.cell_images -= 1
        self.image_bytes -= nbytes
        return True

    def note(self):
        """A stream output that says what of this cell was left out, or None."""
        if not self.left_out:
            return None
        parts = [f"{why}: {n}" for why, n in self.left_out.items()]
        return {
            "output_type": "stream",
            "name": "stderr",
            "text": f"[the grader left out outputs of this cell ({'; '.join(parts)})]\n",
        }


#: a PNG file's first bytes, then its IHDR chunk (length 13) with the width and height
PNG_HEAD = b"\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR"


def png_size(text):
    """(width, height) [pixels] of a base64 PNG image, from its header alone, or None
    when it is not base64 of a PNG file."""
    import base64
    import binascii

    if not isinstance(text, str):
        return None
    try:
        head = base64.b64decode(text[:44].encode("ascii"), validate=True)
        if len(text) % 4 or not head.startswith(PNG_HEAD) or len(head) < 24:
            return None
        base64.b64decode(text.encode("ascii"), validate=True)  # the whole text is base64
    except (binascii.Error, UnicodeEncodeError, ValueError):
        return None
    width, height = struct.unpack(">II", head[16:24])
    return width, height


def _cell_run(reply, seconds, budget):
    """A :class:`CellRun` from a run reply, its outputs checked and capped."""
    budget.new_cell()
    outputs = []
    given = reply.get("outputs")
    for out in given if isinstance(given, list) else []:
        clean = _clean_output(out, budget)
        if clean:
            outputs.append(clean)
    note = budget.note()
    if note:
        outputs.append(note)
    if reply.get("status") == "ok":
        return CellRun("ok", outputs, seconds=seconds)
    ename = str(reply.get("ename", "Error"))[:100]
    evalue = str(reply.get("evalue", ""))[:2000]
    outputs.append(
        {
            "output_type": "error",
            "ename": ename,
            "evalue": evalue,
            "traceback": [f"{ename}: {evalue}"],
        }
    )
    return CellRun("error", outputs, f"this cell raised {ename}: {evalue[:300]}", seconds)


def _clean_output(out, budget):
    """Only stream text, plain-text displays and PNG images, within the budget."""
    if not isinstance(out, dict):
        return None
    kind = out.get("output_type")
    if kind == "stream" and out.get("name") in ("stdout", "stderr"):
        text = out.get("text", "")
        if not isinstance(text, str) or not text or not budget.take_output():
            return None
        text = budget.take_text(text, out["name"])
        return {"output_type": "stream", "name": out["name"], "text": text} if text else None
    if kind == "display_data" and isinstance(out.get("data"), dict):
        text = out["data"].get("text/plain")
        png = out["data"].get("image/png")
        if not (isinstance(text, str) or isinstance(png, str)) or not budget.take_output():
            return None
        data = {}
        if isinstance(png, str) and budget.take_image(png):
            data["image/png"] = png
        if isinstance(text, str):
            kept = budget.take_text(text[: budget.limits.output_chars])
            if kept:
                data["text/plain"] = kept
        return {"output_type": "display_data", "data": data, "metadata": {}} if data else None
    return None
