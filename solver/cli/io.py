"""Reading a batch file and writing JSON, for the ``solve`` and ``draw`` commands.

:func:`read_batch` never raises: a file that cannot be used comes back with
the reason (the commands then exit with status 2). It reads UTF-8 with or
without a byte-order mark, refuses nesting too deep to read, and marks a case
that gives a key twice (:data:`DUPLICATES`), so that the case is refused
rather than the last value silently winning. :func:`write_json` writes strict
JSON (no NaN or Infinity).
"""

import json
import sys

from ..cases import DUPLICATES


class _Case(dict):
    """A JSON object read from a batch file."""


def _pairs(pairs):
    obj = _Case()
    twice = []
    for key, value in pairs:
        if key in obj and key not in twice:
            twice.append(key)
        obj[key] = value
    if twice:
        obj[DUPLICATES] = twice
    return obj


def read_batch(path):
    """``(cases, None)`` for a usable batch file (``-`` is stdin), else
    ``(None, reason)``."""
    try:
        if path == "-":
            data = sys.stdin.buffer.read()
        else:
            with open(path, "rb") as f:
                data = f.read()
    except OSError as exc:
        return None, exc.strerror or str(exc)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        return None, f"it is not UTF-8 text (byte {exc.start})"
    try:
        cases = json.loads(text, object_pairs_hook=_pairs)
    except RecursionError:
        return None, "its JSON nests too deep to read"
    except ValueError as exc:
        return None, f"it is not JSON ({exc})"
    if not isinstance(cases, list):
        return None, "the file must hold a JSON list of case objects"
    return cases, None


def write_json(obj, indent=None):
    """``obj`` on stdout as strict JSON and a newline."""
    sys.stdout.write(json.dumps(obj, indent=indent, allow_nan=False) + "\n")
