"""What a student's notebook imports: the registry, the student id, the variant,
and the checks that its test cells run.

The student id comes from, in order: ``ACCELAB_STUDENT_ID`` (set by the course's
autograde preprocessor for each submission), ``JUPYTERHUB_USER`` (the student's
own server), and else the self-study default ``"self-study"``. The variant is
recomputed from the spec and that id every time, never stored in the notebook.
"""

import os

from solver.units import Q_, ureg

from .assignment import build_variant
from .grading import check_format as _check_format, grade as _grade, quiet
from .problem import key_value

__all__ = ["ureg", "Q_", "student_id", "load_variant", "check_format", "check_value"]

SELF_STUDY = "self-study"
_current = {}
_MISSING = object()


def student_id():
    """The id whose variant this notebook shows and is graded against."""
    for var in ("ACCELAB_STUDENT_ID", "JUPYTERHUB_USER"):
        value = os.environ.get(var, "").strip()
        if value:
            return value
    return SELF_STUDY


class NotebookVariant:
    """A variant as the notebook uses it: shows the given values, checks answers."""

    def __init__(self, variant):
        self.variant = variant
        self.answers = variant.answers
        self._key = {}

    def show(self, number):
        """Display the given values of problem ``number`` (1-based)."""
        p = self.variant.problems[number - 1]
        rows = "\n".join(f"| ${_tex(k)}$ | {v} |" for k, v in p.given.items())
        text = (f"**Your values** (student `{self.variant.student}`):\n\n"
                f"| given | value |\n|---|---|\n{rows}")
        try:
            from IPython.display import Markdown, display
            display(Markdown(text))
        except ImportError:  # outside IPython
            print(text)

    def solution(self, name):
        """The key value as a Quantity in the asked unit (instructor's source only)."""
        a = self.answers[name]
        value = self.expected(name)
        if a.kind == "choice":
            return value
        return Q_(value, ureg.Quantity(1.0, a.unit or "").to_base_units().units).to(a.unit or "")

    def expected(self, name):
        if name not in self._key:
            with quiet():
                self._key[name] = key_value(self.answers[name])
        return self._key[name]


def _tex(symbol):
    greek = {"theta": "\\theta", "omega": "\\omega", "alpha": "\\alpha", "delta": "\\delta",
             "gamma": "\\gamma", "phi": "\\phi", "lam": "\\lambda", "dt": "\\Delta t"}
    for word, tex in greek.items():
        if symbol.startswith(word):
            rest = symbol[len(word):].lstrip("_")
            return tex + (f"_{{{rest}}}" if rest else "")
    return symbol if symbol != "circuit" else "\\text{circuit}"


def load_variant(spec, student=None):
    """Build (and remember, for the test cells) the variant of ``student``."""
    with quiet():
        nv = NotebookVariant(build_variant(spec, student if student is not None else student_id()))
    _current["variant"] = nv
    return nv


def _lookup(name, namespace):
    nv = _current.get("variant")
    if nv is None:
        raise AssertionError("the parameter cell has not run: run the notebook from the top")
    if name not in nv.answers:
        raise AssertionError(f"this notebook has no graded answer {name!r}")
    value = namespace.get(name, _MISSING) if namespace is not None else _MISSING
    return nv, nv.answers[name], value


def check_format(name, namespace):
    """Visible test: the answer exists, has a usable format and the right
    dimension. Raises AssertionError with what to fix."""
    nv, answer, value = _lookup(name, namespace)
    message = _check_format(answer, None if value is _MISSING else value,
                            defined=value is not _MISSING)
    if message:
        raise AssertionError(message)
    print(f"{name}: format and dimension are fine")


def check_value(name, namespace):
    """Hidden test: the value within the assignment's tolerance of the solver's.
    Raises AssertionError with a hint (never the expected value)."""
    nv, answer, value = _lookup(name, namespace)
    result = _grade(answer, None if value is _MISSING else value, nv.expected(name),
                    nv.variant.tolerance, defined=value is not _MISSING)
    if not result.ok:
        raise AssertionError(result.message)
    print(result.message)
