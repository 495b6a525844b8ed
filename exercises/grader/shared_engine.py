"""One SQLAlchemy engine per gradebook and process, for nbgrader's Gradebook objects.

nbgrader opens a new ``Gradebook`` in each of its steps, for each notebook, and each
``Gradebook`` makes a new SQLAlchemy engine. An engine keeps its own cache of compiled
SQL, so every query was compiled again for every step of every notebook: about a
sixth of the grader's own CPU time (2.5 of 16 cpu-s grading 47 notebooks).

:func:`share_engines` makes nbgrader's ``create_engine`` return the engine it made
before for the same database URL and options, in this process. What reaches the
database is unchanged: the shared engine keeps no pool of connections (SQLAlchemy's
``NullPool``), so each ``Gradebook`` opens its own connection to the file as it is then
(a gradebook copied or swapped in between is the one read), and any number of them may
be open at once, in any threads, as when each had its own engine; only the compiled
statements and the dialect are kept. A process made by ``fork`` makes its own engines
(an engine is never shared across processes).
"""

import os
import threading

__all__ = ["share_engines"]


def share_engines():
    """Put the sharing ``create_engine`` in nbgrader's gradebook module (once per
    process; a no-op if nbgrader is absent or laid out otherwise). Returns True when
    in place."""
    try:
        from nbgrader import api
    except ImportError:
        return False
    current = getattr(api, "create_engine", None)
    if getattr(current, "shares_engines", False):
        return True
    if current is None:
        return False
    api.create_engine = _sharing(current)
    return True


def _sharing(create_engine):
    engines = {}
    lock = threading.Lock()

    def shared_create_engine(url, *args, **kwargs):
        from sqlalchemy.pool import NullPool

        kwargs.setdefault("poolclass", NullPool)  # a connection per Gradebook, as before
        key = (os.getpid(), str(url), repr(args), repr(sorted(kwargs.items())))
        with lock:
            engine = engines.get(key)
            if engine is None:
                engine = engines[key] = create_engine(url, *args, **kwargs)
        return engine

    shared_create_engine.shares_engines = True
    return shared_create_engine
