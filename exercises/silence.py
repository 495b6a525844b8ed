"""A context in which warnings are ignored and stray writes to stderr are
dropped: generating a variant in a student's notebook prints nothing but what
the notebook shows."""

import contextlib
import io
import warnings


@contextlib.contextmanager
def silenced():
    """No warnings and no stderr output inside."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with contextlib.redirect_stderr(io.StringIO()):
            yield
