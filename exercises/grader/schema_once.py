"""nbgrader's check of cell metadata, with its schema checked once instead of once per cell.

nbgrader checks the ``nbgrader`` metadata of each cell with ``jsonschema.validate``,
which first checks the schema itself against JSON Schema's metaschema, on every call.
A submission has its cells checked three times (the two sanitizing passes of
``accelab grade`` and nbgrader's autograde, then autograde's last step), so in a run of
``accelab grade`` that check of an unchanging schema took about an eighth of the
grader's own CPU time (2 of 16 cpu-s grading 47 notebooks).

:func:`check_schemas_once` gives nbgrader's validator module a stand-in for
``jsonschema`` whose ``validate`` checks each distinct schema once, keeps the
validator, and then does exactly what ``jsonschema.validate`` does: the best-matching
error of the instance is raised, or nothing. A schema that is itself invalid still
raises ``SchemaError``, on each call. Every other name is the real jsonschema's.
"""

import json
import threading

import jsonschema
from jsonschema.exceptions import best_match

__all__ = ["check_schemas_once"]


class _SchemaCheckedOnce:
    """``jsonschema`` as nbgrader's validator module sees it, with a ``validate`` that
    keeps one validator per distinct schema."""

    def __init__(self, module):
        self._module = module
        self._validators = {}
        self._lock = threading.Lock()

    def __getattr__(self, name):
        return getattr(self._module, name)

    def validate(self, instance, schema, cls=None, *args, **kwargs):
        if cls is not None or args or kwargs:  # not nbgrader's call: the real one
            return self._module.validate(instance, schema, cls, *args, **kwargs)
        key = json.dumps(schema, sort_keys=True)
        validator = self._validators.get(key)
        if validator is None:
            kind = self._module.validators.validator_for(schema)
            kind.check_schema(schema)  # raises SchemaError: then nothing is kept
            validator = kind(schema)
            with self._lock:
                self._validators.setdefault(key, validator)
        error = best_match(validator.iter_errors(instance))
        if error is not None:
            raise error


def check_schemas_once():
    """Put the stand-in in nbgrader's metadata validator (once per process; a no-op
    if nbgrader's module is not laid out as expected). Returns True when in place."""
    try:
        from nbgrader.nbgraderformat import common
    except ImportError:
        return False
    current = getattr(common, "jsonschema", None)
    if isinstance(current, _SchemaCheckedOnce):
        return True
    if current is not jsonschema:
        return False
    common.jsonschema = _SchemaCheckedOnce(jsonschema)
    return True
