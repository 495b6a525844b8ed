# Every target sets itself up: a fresh machine needs only Python 3 and pip.
# The venv's Python: the faster of python3 on PATH and the system's (.ci/python.py says why);
# `make venv PYTHON=python3.12` chooses one
PYTHON ?= $(shell python3 .ci/python.py 2>/dev/null || echo python3)
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
# nbgrader calls `alembic`, so the venv's bin/ must be on PATH for every job.
export PATH := $(CURDIR)/$(BIN):$(PATH)
export MPLBACKEND := Agg

.PHONY: venv pip-install lint typecheck test test-fast explore demo figures docs bench bench-grading clean

venv: $(STAMP)

$(STAMP): pyproject.toml
	@command -v bwrap >/dev/null 2>&1 || { \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    apt-get install -y -q bubblewrap >/dev/null 2>&1 || \
	    { apt-get update -q >/dev/null && apt-get install -y -q bubblewrap >/dev/null; }; \
	  else echo "accelab: grading runs submissions in bubblewrap: sudo apt-get install bubblewrap" >&2; fi; }
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	@# uv (from PyPI, into the venv) installs the same packages as pip in half the time (a clean
	@# clone's `make venv` 26 -> 13 s on 2 cores: parallel downloads, bytecode compiled on every
	@# core); where uv cannot be had or cannot install (no wheel for this platform, an index
	@# that only pip is configured for), pip does it
	$(BIN)/python -m pip install --quiet uv >/dev/null 2>&1 && \
	  $(BIN)/uv pip install --quiet --python $(BIN)/python --compile-bytecode \
	    --upgrade-package pip pip -e ".[test]" || \
	  { echo "accelab: uv did not install the packages; pip does" >&2; \
	    $(MAKE) --no-print-directory pip-install; }
	@# an editable install leaves out data files: accelab's JupyterLab extension is linked in
	mkdir -p $(VENV)/share/jupyter/labextensions
	ln -sfn $(CURDIR)/exercises/lab $(VENV)/share/jupyter/labextensions/accelab-lab
	@# the processes the tests start that are not accelab's (JupyterLab, JupyterHub, nbgrader)
	@# defer jsonschema's IRI grammar as the accelab command does: the test environment's only
	$(BIN)/python .ci/lazy_iri_pth.py >/dev/null
	touch $(STAMP)

# the same with pip alone (uv's fall-back): pip compiles what it installs one file after another,
# compileall does it on every core (the install 25 -> 22 s on 2 cores); a file that does not
# compile is skipped, as pip does
pip-install:
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet --no-compile -e ".[test]"
	-$(BIN)/python -m compileall -q -j 0 $$($(BIN)/python -c \
	  "import sysconfig; print(sysconfig.get_path('purelib'))") >/dev/null 2>&1

# ruff (lint and format, pyproject's rules) and mypy (pyproject's [tool.mypy]); their versions are
# pinned in pyproject's `lint` extra, which the `test` extra takes in (the tests run them too)
lint: $(STAMP)
	@# the format first: a line too long (E501) that `ruff format` would split is then reported
	@# as "would reformat", which says what to run
	$(BIN)/ruff format --check . || { echo "accelab: $(BIN)/ruff format . writes it" >&2; exit 1; }
	$(BIN)/ruff check .
	$(MAKE) --no-print-directory typecheck

# mypy on the package as installed: .ci/layout.py writes its layout as links in build/typecheck,
# and names mypy's cache for its set of modules (a file added or removed starts a fresh one:
# mypy 2.4's incremental cache can keep a new module missing, .ci/layout.py says more)
typecheck: $(STAMP)
	@cache=$$($(BIN)/python .ci/layout.py build/typecheck --mypy-cache) && \
	  echo "$(BIN)/mypy --cache-dir $$cache" && $(BIN)/mypy --cache-dir "$$cache"

# in parallel (pytest-xdist), half as many workers again as cores: the end-to-end tests wait
# for browsers, servers and time limits part of the time; pyproject's addopts keep shared
# builds in one worker
JOBS ?= $(shell python3 -c "import os; print(max(2, 3 * len(os.sched_getaffinity(0)) // 2))")

# the source compiled once, before the tests start hundreds of processes that import it (commands,
# kernels, graders, the site build): where PYTHONDONTWRITEBYTECODE is set, each of them would
# compile it again (__pycache__ is ignored by git, and the wheel leaves it out)
COMPILE := $(BIN)/python -m compileall -q accelab solver course exercises benchmarks docs tests >/dev/null
# pytest loads the plugins the tests use by name (pyproject's addopts: xdist, hypothesis) and no
# other: a plugin found by its entry point has its whole distribution's asserts rewritten at
# import (all of hypothesis, in each worker, each collection 4.9 -> 4.15 cpu-s). numpy's OpenBLAS
# starts a thread per core at import that spins about 0.1 cpu-s before it sleeps; nothing here
# multiplies matrices large enough to use it, and the tests start hundreds of short processes
# that import numpy (the grader's sandbox sets the same for its kernels: supervisor.py)
PYTEST := OPENBLAS_NUM_THREADS=1 PYTEST_DISABLE_PLUGIN_AUTOLOAD=1 $(BIN)/python -m pytest
test: $(STAMP)
	$(COMPILE)
	$(PYTEST) -q -n $(JOBS)

test-fast: $(STAMP)
	$(COMPILE)
	$(PYTEST) -q -n $(JOBS) -m "not slow"

# the property tests with random draws, 50 times as many as `make test`'s fixed ones (tests/
# conftest.py): after changing a kernel, a reference or a strategy (about 4 min on 2 cores)
explore: $(STAMP)
	$(COMPILE)
	ACCELAB_HYPOTHESIS=explore $(PYTEST) -q -n $(JOBS) \
	  tests/test_kernels_accuracy.py tests/test_kernels_limits.py tests/test_fuzz.py

demo: $(STAMP)
	$(BIN)/accelab demo

figures: $(STAMP)
	$(BIN)/accelab figures --out figures

# the documentation site in build/docs: course (notebooks executed, with a cache), instructor's
# guide, API reference, conventions, benchmark; warnings are errors
docs: $(STAMP)
	$(BIN)/python -m sphinx -W --keep-going -q -b html -d build/docs-doctrees docs build/docs
	@echo "the site is in build/docs/index.html"

bench: $(STAMP)
	$(BIN)/accelab bench --out build/bench

# grading speed: 20 submissions of the demo assignment, sandbox, feedback and CSV
bench-grading: $(STAMP)
	$(BIN)/python -m accelab.benchmarks.grading --students 20 --jobs 2 --out build/bench

clean:
	rm -rf build .pytest_cache
