"""Defer jsonschema's IRI grammar until a schema asks for it.

Every ``accelab`` command that reads a notebook imports nbformat, which imports
jsonschema. With the non-GPL format extras installed (Jupyter installs them),
jsonschema's import imports ``rfc3987_syntax``, whose import compiles Earley parsers
of the IRI grammar (RFC 3987): about 0.8 s of CPU in every process, for the formats
``iri`` and ``iri-reference`` that no schema nbformat or nbgrader validates uses
(python-jsonschema/jsonschema#1428).

:func:`defer_iri_grammar` puts a stand-in under that name before jsonschema is
imported. Its functions import the real module when first called, then call it:
what jsonschema checks, and the answer, are unchanged; only when the grammar is
compiled changes.
"""

import importlib
import importlib.util
import sys
import threading
import types

NAME = "rfc3987_syntax"


def defer_iri_grammar():
    """Put the stand-in for ``rfc3987_syntax`` in place (a no-op when jsonschema or the
    grammar is already imported, or when the grammar is not installed). Returns True
    when the stand-in is in place."""
    if NAME in sys.modules or "jsonschema" in sys.modules:
        return isinstance(sys.modules.get(NAME), _Deferred)
    if importlib.util.find_spec(NAME) is None:
        return False
    sys.modules[NAME] = _Deferred(NAME)
    return True


_LOADING = threading.Lock()


def _real():
    """The real module (imported on first use, in place of the stand-in; one thread
    imports it, the others wait for it)."""
    with _LOADING:
        module = sys.modules.get(NAME)
        if isinstance(module, _Deferred):
            del sys.modules[NAME]
            try:
                module = importlib.import_module(NAME)
            except BaseException:
                sys.modules.setdefault(NAME, _Deferred(NAME))
                raise
        return module


class _Deferred(types.ModuleType):
    """``rfc3987_syntax`` until first use: every attribute is the real one's, and the
    functions jsonschema imports by name load the grammar when called."""

    @staticmethod
    def is_valid_syntax(term, value):
        return _real().is_valid_syntax(term, value)

    @staticmethod
    def parse(term, value):
        return _real().parse(term, value)

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(_real(), name)
