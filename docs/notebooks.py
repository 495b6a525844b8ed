"""The course notebooks as the documentation build and the tests execute them.

Every ``course/NN_slug.py`` (jupytext percent format) is executed headless:
working directory ``course/``, ``ACCELAB_STATIC=1`` (so ``accelab.course.kit.explore``
draws its static small multiples instead of sliders) and matplotlib's inline
backend; the notebooks import the installed package, never the repository's folders.

Executed notebooks are kept in a jupyter-cache folder, the one MyST-NB reads
when ``make docs`` builds the site (``nb_execution_mode = "cache"``). The
folder's name is a digest of the code the notebooks run (``solver/``,
``exercises/``, ``course/*.py`` other than the notebooks), because the cache
itself only keys a notebook by its code cells: a change to the solver must
execute the notebooks again. ``tests/test_course.py`` executes each notebook
once per session and stores it there (:func:`store`), so the site test that
follows builds the site without executing anything again.
"""

import hashlib
import os
import re
import shutil
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
COURSE = ROOT / "course"
CACHE_ROOT = ROOT / "build" / "docs-cache"
CELL_TIMEOUT = 300  # s per cell
#: the longest one wait for a kernel's message lasts before the socket is looked at again [s]
POLL_SLICE = 1.0
#: the code the executed notebooks depend on (besides the notebooks' own cells)
CODE = ("solver", "exercises", "accelab", "benchmarks", "course")

__all__ = [
    "sources",
    "kernel_env",
    "set_kernel_env",
    "cache_path",
    "execute",
    "notebook_client",
    "in_slices",
    "store",
    "problems",
    "NotebookFailed",
]


class NotebookFailed(RuntimeError):
    """A notebook raised in a cell or wrote to stderr; the message lists where."""


def sources(course=COURSE):
    """The course notebooks, in order: ``course/NN_*.py``."""
    return sorted(Path(course).glob("[0-9][0-9]_*.py"))


def kernel_env(base=None):
    """Environment of the kernel: headless figures and the inline backend. The notebooks
    import the installed package (``accelab.solver``, ``accelab.course.kit``), never the
    repository's folders."""
    env = dict(os.environ if base is None else base)
    env["ACCELAB_STATIC"] = "1"
    env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
    env.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    return env


def set_kernel_env():
    """Make this process's environment the kernel's (kernels inherit it)."""
    os.environ.update(kernel_env())


def _code_files():
    for name in CODE:
        top = ROOT / name
        if not top.is_dir():
            continue
        for path in sorted(top.rglob("*.py")):
            if name == "course" and path.parent == COURSE and path.name[:2].isdigit():
                continue  # the notebooks themselves: the cache keys them by their cells
            if "__pycache__" not in path.parts:
                yield path


def code_digest():
    """A digest of every source file the notebooks' outputs depend on."""
    h = hashlib.sha256()
    for path in _code_files():
        h.update(str(path.relative_to(ROOT)).encode())
        h.update(path.read_bytes())
    return h.hexdigest()[:16]


def cache_path(prune=False):
    """The jupyter-cache folder for the code as it is now; ``prune`` deletes the
    folders of older code."""
    path = CACHE_ROOT / code_digest()
    if prune and CACHE_ROOT.is_dir():
        for old in CACHE_ROOT.iterdir():
            if old != path and old.is_dir():
                shutil.rmtree(old, ignore_errors=True)
    return path


def read(source):
    """The notebook of a jupytext source, as MyST-NB reads it."""
    import jupytext

    nb = jupytext.read(source, fmt="py:percent")
    nb.metadata.setdefault(
        "kernelspec", {"name": "python3", "display_name": "Python 3", "language": "python"}
    )
    return nb


def problems(nb):
    """Error outputs and stderr text of an executed notebook, one line each."""
    out = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        for o in cell.get("outputs", []):
            if o.output_type == "error":
                out.append(f"cell {i}: {o.ename}: {o.evalue}")
            elif o.output_type == "stream" and o.name == "stderr":
                out.append(f"cell {i}: stderr: {o.text.strip()[:500]}")
    return out


def in_slices(get_msg, every=POLL_SLICE):
    """``get_msg(timeout)`` of a kernel client's channel (async), waiting in slices of
    ``every`` seconds: a new poll of the socket each slice, until the message comes or
    ``timeout`` has passed (then ``queue.Empty``, as ``get_msg`` raises it)."""
    from queue import Empty

    async def get_msg_in_slices(timeout=None):
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            left = None if deadline is None else deadline - time.monotonic()
            wait = every if left is None else max(0.0, min(every, left))
            try:
                return await get_msg(timeout=wait)
            except Empty:
                if left is not None and left <= every:
                    raise

    return get_msg_in_slices


_client_class = []


def notebook_client(nb, **options):
    """nbclient's ``NotebookClient`` for ``nb`` (``options`` are its own) whose waits for
    the kernel's replies and outputs look at the socket again every :data:`POLL_SLICE` s.

    pyzmq's asyncio poller can miss the wake-up of a message that has already arrived (a
    zmq socket's file descriptor is edge-triggered). nbclient then waits out the whole cell
    timeout before it polls again, finds the reply there and goes on as if nothing had
    happened: in the test suite a notebook of a few seconds once took 304 s, its kernel
    idle. A new poll checks the socket at once, so a missed wake-up costs one slice."""
    if not _client_class:
        from nbclient import NotebookClient
        from nbclient.util import run_sync

        class SlicedClient(NotebookClient):
            async def async_start_new_kernel_client(self):
                kc = await super().async_start_new_kernel_client()
                for channel in (kc.shell_channel, kc.iopub_channel):
                    channel.get_msg = in_slices(channel.get_msg)
                return kc

            # nbclient's blocking form (setup_kernel) calls the base class's coroutine
            start_new_kernel_client = run_sync(async_start_new_kernel_client)

        _client_class.append(SlicedClient)
    return _client_class[0](nb, **options)


def execute(source, timeout=CELL_TIMEOUT, *, cwd=None, env=None, after=None):
    """Execute ``source`` with nbclient; returns the executed notebook.

    ``source`` is a course notebook (``course/NN_slug.py``, jupytext) or a written
    ``.ipynb``; it runs in ``cwd`` (default: its own folder) with ``env`` (default
    :func:`kernel_env`). ``after`` is the source of a cell run after the last one (a check
    of what the cells left behind), taken out of the notebook returned. The cells get no
    timing metadata: the documentation build's cache matches them by content. Raises
    :class:`NotebookFailed` on a cell error or any output to stderr (the failed notebook is
    on the exception as ``.notebook``)."""
    import nbformat
    from nbclient.exceptions import CellExecutionError

    source = Path(source)
    nb = nbformat.read(source, as_version=4) if source.suffix == ".ipynb" else read(source)
    if after:
        nb.cells.append(nbformat.v4.new_code_cell(after))
    client = notebook_client(
        nb,
        timeout=timeout,
        kernel_name="python3",
        startup_timeout=120,
        allow_errors=False,
        record_timing=False,
        resources={"metadata": {"path": str(cwd or source.parent)}},
    )
    try:
        client.execute(env=kernel_env() if env is None else env)
    except CellExecutionError as exc:
        raise _failed(nb, after, f"{source.name} failed:\n{exc}") from None
    except Exception as exc:  # noqa: BLE001  a timeout, a dead kernel: the same verdict, with its kind
        raise _failed(nb, after, f"{source.name} failed: {type(exc).__name__}: {exc}") from None
    if after:
        nb.cells.pop()
    found = problems(nb)
    if found:
        raise _failed(nb, None, f"{source.name} wrote to stderr or failed:\n" + "\n".join(found))
    return nb


def _failed(nb, after, message):
    if after:  # the check cell is not the notebook's
        nb.cells.pop()
    exc = NotebookFailed(message)
    exc.notebook = nb
    return exc


def store(source, nb, seconds=None):
    """Keep an executed notebook in the documentation build's cache (replacing
    any earlier run of the same cells)."""
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn

    cache = get_cache(str(cache_path()))
    data = {"execution_seconds": seconds} if seconds is not None else {}
    cache.cache_notebook_bundle(
        CacheBundleIn(nb, str(Path(source).resolve()), data=data),
        check_validity=False,
        overwrite=True,
    )


def cached(source):
    """The executed notebook of ``source`` from the cache, or None."""
    from jupyter_cache import get_cache

    path = cache_path()
    if not path.is_dir():
        return None
    cache = get_cache(str(path))
    try:
        _, nb = cache.merge_match_into_notebook(read(source))
    except KeyError:
        return None
    return nb


WIDE_IMAGE = re.compile(r"\(data:image/png;base64,([A-Za-z0-9+/=]+)\)\{\.accelab-wide\}")


def figures(nb):
    """The figures of an executed notebook, in order, as base64 PNG: each image/png
    output, and the wide rendition of each figure shown in two renditions
    (``accelab.course.renditions``, a Markdown output)."""
    out = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        for o in cell.get("outputs", []):
            data = o.get("data", {})
            if "image/png" in data:
                out.append(data["image/png"])
            elif "text/markdown" in data:
                text = data["text/markdown"]
                out += WIDE_IMAGE.findall(text if isinstance(text, str) else "".join(text))
    return out


#: figures the README shows: file name -> (notebook, n-th figure of its executed outputs)
README_FIGURES = {"course-piston-acceleration.png": ("04_slider_crank_engine", 2)}


def readme_figures(outdir):
    """Write the course figures the README shows (:data:`README_FIGURES`) into
    ``outdir``, from the executed notebooks (executing those not in the cache);
    returns the paths written."""
    import base64

    written = []
    for name, (stem, k) in README_FIGURES.items():
        source = COURSE / f"{stem}.py"
        nb = cached(source)
        if nb is None:
            nb = execute(source)
            store(source, nb)
        pngs = figures(nb)
        target = Path(outdir) / name
        target.write_bytes(base64.b64decode(pngs[k - 1]))
        written.append(target)
    return written


if __name__ == "__main__":  # python -m docs.notebooks figures/
    import sys

    for path in readme_figures(sys.argv[1] if len(sys.argv) > 1 else ROOT / "figures"):
        print(f"wrote {path}")
