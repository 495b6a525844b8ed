"""Signatures on the API pages write a default as the code does.

autodoc writes a default by its ``repr``: ``say=print`` in the code reads
``say=<built-in function print>`` on the page, and a dataclass field made by
``field(default_factory=list)`` reads ``notes=<factory>``; neither is Python nor what a
reader would type. A default that is a function or a class is written by its name
(``say=print``), a field's factory by what it makes (``notes=[]``; a class ``C`` as ``C()``).
Every other default keeps autodoc's text (``tol=1e-13``, ``accounts=()``), so a number
is never hidden behind the name of a constant.
"""

import dataclasses
import inspect

#: what a reader writes for what these factories make
MADE_BY = {list: "[]", dict: "{}", tuple: "()", set: "set()"}


def _named(value):
    """The name a reader would type for ``value``, or None to keep its repr."""
    if inspect.isroutine(value) or inspect.isclass(value):
        return getattr(value, "__qualname__", None) or getattr(value, "__name__", None)
    return None


def _factories(obj):
    """A dataclass's fields made by a factory: ``{name: how the made value reads}``."""
    if not (inspect.isclass(obj) and dataclasses.is_dataclass(obj)):
        return {}
    return {
        f.name: MADE_BY.get(f.default_factory) or f"{_named(f.default_factory)}()"
        for f in dataclasses.fields(obj)
        if f.default_factory is not dataclasses.MISSING
    }


def readable_defaults(app, what, name, obj, options, signature, return_annotation):
    """``autodoc-process-signature``: each default a function, class or factory makes
    written as the code would write it."""
    if not signature:
        return None
    try:
        parameters = inspect.signature(obj).parameters.values()
    except (TypeError, ValueError):  # no signature to read (a builtin, some classes)
        return None
    made = _factories(obj)
    for p in parameters:
        if p.default is inspect.Parameter.empty:
            continue
        shown = made.get(p.name) or _named(p.default)
        if shown:
            signature = signature.replace(f"{p.name}={p.default!r}", f"{p.name}={shown}")
    return signature, return_annotation


def setup(app):
    app.connect("autodoc-process-signature", readable_defaults)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
