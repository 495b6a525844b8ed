"""accelab.lazy_iri: jsonschema's IRI grammar compiled when a schema asks for it, with the
same answers as compiled at import (each case in a fresh interpreter)."""

import json
import os
import subprocess
import sys

import pytest

pytest.importorskip("rfc3987_syntax", reason="jsonschema's non-GPL format extras are absent")

#: IRIs and not-IRIs, checked as jsonschema checks the "iri" and "iri-reference" formats
CHECK = r"""
import json, sys
if sys.argv[1] == "deferred":
    from accelab.lazy_iri import defer_iri_grammar
    assert defer_iri_grammar()
import nbformat, jsonschema
compiled_at_import = "lark" in sys.modules
checker = jsonschema.Draft7Validator.FORMAT_CHECKER
texts = ["http://example.org/a?b#c", "http://\u4f8b\u3048.jp/\u30d1\u30b9", "a b", "://", "../x",
         "mailto:ann@example.org", ""]
from concurrent.futures import ThreadPoolExecutor  # the first checks from four threads at once
with ThreadPoolExecutor(4) as pool:
    first = list(pool.map(lambda t: checker.conforms(t, "iri"), texts * 4))
answers = {fmt: [checker.conforms(t, fmt) for t in texts] for fmt in ("iri", "iri-reference")}
assert first == answers["iri"] * 4
print(json.dumps({"compiled_at_import": compiled_at_import, "answers": answers}))
"""


#: a process that compiles the grammar at import, as outside the test environment (whose
#: start-up file defers it in every process: .ci/lazy_iri_pth.py)
EAGER = dict(os.environ, ACCELAB_EAGER_IRI="1")


def _run(mode):
    done = subprocess.run(
        [sys.executable, "-c", CHECK, mode], capture_output=True, text=True, timeout=120, env=EAGER
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_the_grammar_waits_for_a_schema_and_answers_the_same():
    deferred, eager = _run("deferred"), _run("eager")
    assert eager["compiled_at_import"] and not deferred["compiled_at_import"]
    assert deferred["answers"] == eager["answers"]
    assert True in deferred["answers"]["iri"] and False in deferred["answers"]["iri"]


def test_the_command_defers_it():
    """``accelab`` puts the stand-in in place before any command imports nbformat."""
    probe = (
        "import contextlib, io, sys\nfrom accelab.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(SystemExit):\n"
        "    main(['--help'])\n"
        "print(type(sys.modules.get('rfc3987_syntax')).__name__)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, timeout=120, env=EAGER
    )
    assert done.stdout.strip() == "_Deferred", done.stdout + done.stderr


PROBE = "import sys; print(type(sys.modules.get('rfc3987_syntax')).__name__)"


def test_every_process_of_the_test_environment_defers_it():
    """The test environment's start-up file (``make venv`` writes it: .ci/lazy_iri_pth.py)
    defers the grammar in the processes the tests start that are not accelab's (JupyterLab,
    JupyterHub, nbgrader); ``ACCELAB_EAGER_IRI=1`` turns it off."""
    import _venv

    assert _venv.tests_only() == list(_venv.TESTS_ONLY), (
        "the venv has no start-up file: .venv/bin/python .ci/lazy_iri_pth.py writes it"
    )

    def probe(env):
        done = subprocess.run(
            [sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=60, env=env
        )
        assert done.returncode == 0 and not done.stderr, done.stderr
        return done.stdout.strip()

    assert probe(dict(os.environ)) == "_Deferred"
    assert probe(EAGER) == "NoneType"
