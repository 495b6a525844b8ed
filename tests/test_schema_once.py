"""accelab.exercises.grader.schema_once: nbgrader's cell-metadata check with its schema
checked once per process, and the same verdict, error for error, as jsonschema's own."""

import copy
import json
import os

import jsonschema
import pytest
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

from accelab.exercises.grader import schema_once

nbgrader_common = pytest.importorskip("nbgrader.nbgraderformat.common")
from nbgrader.nbgraderformat import MetadataValidator, ValidationError  # noqa: E402

GOOD = {
    "schema_version": 3,
    "grade": True,
    "locked": False,
    "solution": True,
    "task": False,
    "grade_id": "answer_a",
    "points": 1,
}
#: metadata a submission may forge, each wrong in its own way (the schema leaves the rest,
#: such as a missing grade_id, to nbgrader's checks after it)
BAD = [
    dict(GOOD, grade="yes"),
    dict(GOOD, points=-1),
    dict(GOOD, schema_version=2),
    dict(GOOD, grade_id=7, points="x"),
    "not a mapping",
    [],
]


def _schema():
    with open(os.path.join(os.path.dirname(nbgrader_common.__file__), "v3.json")) as fh:
        return json.load(fh)


def _verdict(validate, instance, schema):
    try:
        validate(copy.deepcopy(instance), schema)
    except jsonschema.ValidationError as exc:
        return (exc.message, list(exc.absolute_path), exc.validator)
    return None


def test_every_verdict_is_jsonschemas_own():
    schema = _schema()
    stand_in = schema_once._SchemaCheckedOnce(jsonschema)
    for instance in [GOOD, *BAD]:
        assert _verdict(stand_in.validate, instance, schema) == _verdict(
            jsonschema.validate, instance, schema
        ), instance
    assert _verdict(stand_in.validate, GOOD, schema) is None
    no_id = {k: v for k, v in GOOD.items() if k != "grade_id"}
    assert _verdict(stand_in.validate, no_id, schema) is None
    assert all(_verdict(stand_in.validate, bad, schema) for bad in BAD)


def test_the_schema_is_checked_once_and_a_bad_schema_on_every_call():
    checked = []

    class Counting:  # jsonschema, counting the checks of schemas
        def __getattr__(self, name):
            return getattr(jsonschema, name)

        class validators:
            @staticmethod
            def validator_for(schema):
                kind = jsonschema.validators.validator_for(schema)

                class Counted:  # the validator class, its schema checks counted
                    @staticmethod
                    def check_schema(s, *args, **kwargs):
                        checked.append(1)
                        return kind.check_schema(s, *args, **kwargs)

                    def __new__(cls, *args, **kwargs):
                        return kind(*args, **kwargs)

                return Counted

    stand_in = schema_once._SchemaCheckedOnce(Counting())
    schema = _schema()
    for _ in range(20):
        stand_in.validate(GOOD, schema)
        stand_in.validate(GOOD, copy.deepcopy(schema))  # the same schema, read again
    assert len(checked) == 1
    broken = dict(schema, type=12)
    for _ in range(2):
        with pytest.raises(jsonschema.SchemaError):
            stand_in.validate(GOOD, broken)
    assert len(checked) == 3


def test_nbgraders_validator_uses_it_and_judges_notebooks_as_before():
    assert schema_once.check_schemas_once()
    assert schema_once.check_schemas_once()  # once: not wrapped twice
    assert isinstance(nbgrader_common.jsonschema, schema_once._SchemaCheckedOnce)
    assert nbgrader_common.jsonschema.ValidationError is jsonschema.ValidationError
    cells = [new_markdown_cell("# A"), new_code_cell("x = 1", metadata={"nbgrader": GOOD})]
    MetadataValidator().validate_nb(new_notebook(cells=cells))
    forged = new_code_cell("x = 1", metadata={"nbgrader": dict(GOOD, points="all")})
    with pytest.raises(ValidationError):
        MetadataValidator().validate_nb(new_notebook(cells=[forged]))
