"""Make every Python process of the test environment defer jsonschema's IRI grammar.

The ``accelab`` command defers it itself (``accelab/lazy_iri.py``): importing jsonschema
with Jupyter's format extras compiles Earley parsers of RFC 3987 that no notebook schema
uses, 0.8-1.4 cpu-s per process on this 2-core machine. The tests also start processes that
are not accelab's: JupyterLab's and JupyterHub's servers, nbgrader's commands, Sphinx
(about fifteen per ``make test``). This writes a ``.pth`` file into the venv's
site-packages (``make venv``) that puts the same stand-in in place as each of them starts;
what jsonschema answers is unchanged (``tests/test_lazy_iri.py``), only when the grammar
is compiled. The tests' other accounts' environment links it with the rest
(``tests/_venv.py``).

It is the test environment's, never the package's: accelab's wheel installs no ``.pth``
and changes nothing in a user's other processes (``tests/test_wheel.py`` installs it into
a fresh venv, without this). ``ACCELAB_EAGER_IRI=1`` turns it off for one process.
"""

import sysconfig
from pathlib import Path

#: after the editable install's finder (``.pth`` files are read in name order)
NAME = "zz-accelab-tests-lazy-iri.pth"
#: one line, as site.py runs a line that begins with "import"; silent where accelab is
#: not importable (the grading sandbox shows only the student-side modules)
LINE = (
    "import os; exec('try:\\n from accelab.lazy_iri import defer_iri_grammar\\n"
    " defer_iri_grammar()\\nexcept Exception:\\n pass') "
    "if not os.environ.get('ACCELAB_EAGER_IRI') else None\n"
)


def main():
    path = Path(sysconfig.get_paths()["purelib"]) / NAME
    path.write_text(LINE)
    print(path)


if __name__ == "__main__":
    main()
