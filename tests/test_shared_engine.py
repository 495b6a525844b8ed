"""accelab.exercises.grader.shared_engine: nbgrader's gradebooks share one engine per
database and process, and still read the file as it is when each is opened."""

import os
import shutil

import pytest

from accelab.exercises.grader.shared_engine import share_engines

api = pytest.importorskip("nbgrader.api")


def _url(path):
    return "sqlite:///" + str(path)


@pytest.fixture(scope="module")
def blank(tmp_path_factory):
    """An empty gradebook, made once, as accelab makes one (nbgrader_course.gradebook)."""
    from accelab.exercises.nbgrader_course import gradebook

    root = tmp_path_factory.mktemp("blank")
    gradebook(root, "default_course").close()
    return root / "gradebook.db"


def _copies(blank, folder, *names):
    for name in names:
        shutil.copy(blank, folder / name)
    return [folder / name for name in names]


def test_gradebooks_share_an_engine_per_database(tmp_path, blank):
    assert share_engines()
    assert share_engines()  # once: not wrapped twice
    one, other = map(_url, _copies(blank, tmp_path, "one.db", "other.db"))
    with api.Gradebook(one) as a, api.Gradebook(one) as b, api.Gradebook(other) as c:
        assert a.engine is b.engine
        assert c.engine is not a.engine
        a.add_student("ann")
        assert [s.id for s in b.students] == ["ann"]
        assert c.students == []
    with api.Gradebook(one) as again:  # the engine outlives close(): its connections do not
        assert [s.id for s in again.students] == ["ann"]


def test_a_gradebook_swapped_in_between_is_the_one_read(tmp_path, blank):
    share_engines()
    (live,) = _copies(blank, tmp_path, "gradebook.db")
    kept = tmp_path / "kept.db"
    with api.Gradebook(_url(live)) as gb:
        gb.add_student("ann")
    shutil.copy(live, kept)
    with api.Gradebook(_url(live)) as gb:
        gb.add_student("bob")
    os.replace(kept, live)  # as a copy put back over the gradebook
    with api.Gradebook(_url(live)) as gb:
        assert [s.id for s in gb.students] == ["ann"]


def test_a_forked_process_makes_its_own_engine(tmp_path, blank):
    share_engines()
    url = _url(_copies(blank, tmp_path, "gradebook.db")[0])
    with api.Gradebook(url) as gb:
        parent = gb.engine
        gb.add_student("ann")
    pid = os.fork()
    if pid == 0:  # the child: exit status 0 only if its engine is new and works
        try:
            with api.Gradebook(url) as gb:
                ok = gb.engine is not parent and [s.id for s in gb.students] == ["ann"]
        except BaseException:
            ok = False
        os._exit(0 if ok else 1)
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0


def test_any_number_of_gradebooks_may_be_open_at_once(tmp_path, blank):
    """As when each had its own engine: no pool to run out of (a pool of 5 + 10 would
    make the 16th wait 30 s, then fail), whatever the threads of a grader or formgrader."""
    import threading

    share_engines()
    url = _url(_copies(blank, tmp_path, "gradebook.db")[0])
    opened, ready, errors = [], threading.Barrier(24), []

    def hold():
        try:
            gb = api.Gradebook(url)
            gb.students  # a query: its connection is taken
            opened.append(gb)
            ready.wait(timeout=20)  # all 24 open at the same time
            gb.close()
        except Exception as exc:  # judged below
            errors.append(exc)

    threads = [threading.Thread(target=hold) for _ in range(24)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(60)
    assert errors == [] and len(opened) == 24
