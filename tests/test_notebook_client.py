"""The notebook runner of the site build and the tests (``docs/notebooks.py``:
``notebook_client``) waits for a kernel's messages in slices of a second, so that a
wake-up pyzmq's poller missed costs a second, not the cell's whole timeout; it still
gives up when the timeout has passed, and its kernels run notebooks as nbclient's do.
``execute`` (the course tests' and the README figures' runner) runs a check after the last
cell and leaves it out, and refuses an error or stderr with the notebook as it ran."""

import asyncio
from queue import Empty

import pytest

from docs import notebooks

MESSAGE = {"parent_header": {"msg_id": "m1"}, "content": {"status": "ok"}}


class Clock:
    """A monotonic clock the fake channel moves on as it waits."""

    def __init__(self):
        self.now = 1000.0

    def __call__(self):
        return self.now


def channel(clock, replies):
    """A channel's ``get_msg``: each call takes the next of ``replies`` (a message, or
    None: the poll saw nothing and waited its whole timeout); the timeouts asked for."""
    asked = []

    async def get_msg(timeout=None):
        asked.append(timeout)
        reply = replies.pop(0)
        if reply is None:
            clock.now += timeout
            raise Empty
        return reply

    return get_msg, asked


@pytest.fixture
def clock(monkeypatch):
    clock = Clock()
    monkeypatch.setattr(notebooks.time, "monotonic", clock)
    return clock


def test_a_missed_wake_up_costs_one_slice(clock):
    get_msg, asked = channel(clock, [None, MESSAGE])
    got = asyncio.run(notebooks.in_slices(get_msg)(timeout=300))
    assert got is MESSAGE
    assert asked == [notebooks.POLL_SLICE, notebooks.POLL_SLICE]


def test_without_a_message_it_gives_up_when_the_timeout_has_passed(clock):
    get_msg, asked = channel(clock, [None, None, None])
    with pytest.raises(Empty):
        asyncio.run(notebooks.in_slices(get_msg, every=1.0)(timeout=2.5))
    assert asked == [1.0, 1.0, 0.5]
    assert clock.now == 1002.5


def test_with_no_timeout_it_waits_until_a_message_comes(clock):
    get_msg, asked = channel(clock, [None, None, None, MESSAGE])
    assert asyncio.run(notebooks.in_slices(get_msg)(timeout=None)) is MESSAGE
    assert asked == [notebooks.POLL_SLICE] * 4


def test_a_zero_timeout_polls_once(clock):
    get_msg, asked = channel(clock, [None])
    with pytest.raises(Empty):
        asyncio.run(notebooks.in_slices(get_msg)(timeout=0))
    assert asked == [0.0]


@pytest.mark.slow
def test_its_kernel_clients_wait_in_slices_and_run_a_notebook():
    import nbformat

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("print(6 * 7)")])
    client = notebooks.notebook_client(nb, timeout=60, kernel_name="python3")
    with client.setup_kernel():
        for name in ("shell_channel", "iopub_channel"):
            get_msg = getattr(client.kc, name).get_msg
            assert get_msg.__name__ == "get_msg_in_slices", name
        client.execute_cell(nb.cells[0], 0)
    assert nb.cells[0].outputs[0]["text"] == "42\n"


def _written(tmp_path, *sources):
    import nbformat

    path = tmp_path / "nb.ipynb"
    nbformat.write(
        nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(s) for s in sources]), path
    )
    return path


def test_execute_runs_a_check_after_the_last_cell_and_leaves_it_out(tmp_path):
    """The course tests' check cell (``after``) runs in the notebook's kernel, in ``cwd``,
    with ``env``; the notebook returned is the notebook's own cells, without timings."""
    import os

    path = _written(tmp_path, "import os\nx = 6 * 7", "print(os.environ['MARK'], os.getcwd())")
    here = tmp_path / "run"
    here.mkdir()
    env = dict(notebooks.kernel_env(), MARK="marked")
    nb = notebooks.execute(path, 60, cwd=here, env=env, after="assert x == 42, x")
    assert len(nb.cells) == 2
    assert nb.cells[1].outputs[0]["text"] == f"marked {os.path.realpath(here)}\n"
    assert "execution" not in nb.cells[0].metadata  # the docs cache matches cells by content


@pytest.mark.parametrize(
    ("cells", "after", "says"),
    [
        (["x = 1"], "assert x == 2, 'the check failed'", "the check failed"),
        (["x = 1", "1 / 0"], "x", "ZeroDivisionError"),
        (["import sys\nprint('careful', file=sys.stderr)"], None, "wrote to stderr"),
    ],
)
def test_execute_refuses_an_error_or_stderr_with_the_notebook_as_it_ran(
    tmp_path, cells, after, says
):
    path = _written(tmp_path, *cells)
    with pytest.raises(notebooks.NotebookFailed, match=says) as failed:
        notebooks.execute(path, 60, after=after)
    assert [c.source for c in failed.value.notebook.cells] == cells  # the check left out
