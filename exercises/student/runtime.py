"""What a student's notebook imports: the registry, the student id, the student's
statement (given values and what is asked) and the visible checks.

The kernel only reports. Nothing here holds, computes or judges an expected
value: a student's values are checked for form and dimension (the visible test
cells), and the grader judges them later, in its own process, against the key
it computes for the submitter (:mod:`accelab.exercises.grader`).

The student id comes from, in order: ``ACCELAB_STUDENT_ID``, ``JUPYTERHUB_USER``
(the student's own server), and else the self-study default ``"self-study"``.
While a submission is graded, the sandbox hands this module the submitter's
statement before any cell runs, and only that one can be loaded.
"""

import os

from accelab.solver.units import Q_, ureg

from .answers import MISSING, Asked, describe, read

__all__ = ["ureg", "Q_", "student_id", "load_variant", "check_format", "SELF_STUDY"]

SELF_STUDY = "self-study"
#: the sandbox's statement while grading, the loaded variant, the ids a
#: notebook asked for that it was not given
_state = {"grading": None, "variant": None, "refused": []}


def student_id():
    """The id whose values this notebook shows."""
    for var in ("ACCELAB_STUDENT_ID", "JUPYTERHUB_USER"):
        value = os.environ.get(var, "").strip()
        if value:
            return value
    return SELF_STUDY


class NotebookVariant:
    """One student's statement as the notebook uses it: shows the given values
    and knows what each answer asks for (name, unit, kind). No answers."""

    def __init__(self, statement):
        self.student = str(statement["student"])
        self.statement = statement
        self.problems = statement["problems"]
        self.asked = {a["name"]: Asked.from_dict(a) for p in self.problems for a in p["asked"]}

    def given(self, number):
        """The given values of problem ``number`` (1-based) as Quantities
        (words such as the circuit stay strings): ``g = v.given(1); g["a"]``."""
        out = {}
        for symbol, text in self.problems[number - 1]["given"].items():
            try:
                out[symbol] = Q_(text)
            except Exception:  # noqa: BLE001 - pint raises many types for a word: it stays text
                out[symbol] = text
        return out

    def show(self, number):
        """Display the given values of problem ``number`` (1-based)."""
        table = GivenValues(self.student, self.problems[number - 1]["given"])
        try:
            from IPython.display import display

            display(table)
        except ImportError:  # outside IPython
            print(repr(table))

    def __repr__(self):
        return (
            f"<values of student {self.student!r}: {len(self.problems)} problem(s), "
            f"answers {', '.join(self.asked)}>"
        )


class GivenValues:
    """A student's given values: a table in a notebook, plain text elsewhere."""

    def __init__(self, student, given):
        self.student, self.given = student, dict(given)

    def _repr_markdown_(self):
        rows = "\n".join(f"| ${_tex(k)}$ | {v} |" for k, v in self.given.items())
        return (
            f"**Your values** (student `{self.student}`):\n\n| given | value |\n|---|---|\n{rows}"
        )

    def __repr__(self):
        width = max((len(k) for k in self.given), default=0)
        rows = "\n".join(f"  {k:<{width}} = {v}" for k, v in self.given.items())
        return f"Your values (student `{self.student}`):\n{rows}"


def _tex(symbol):
    greek = {
        "theta": "\\theta",
        "omega": "\\omega",
        "alpha": "\\alpha",
        "delta": "\\delta",
        "gamma": "\\gamma",
        "phi": "\\phi",
        "lam": "\\lambda",
        "dt": "\\Delta t",
    }
    for word, tex in greek.items():
        if symbol.startswith(word):
            rest = symbol[len(word) :].lstrip("_")
            return tex + (f"_{{{rest}}}" if rest else "")
    return symbol if symbol != "circuit" else "\\text{circuit}"


def load_variant(spec, student=None):
    """The values of ``student`` (default: :func:`student_id`) for the
    assignment ``spec``, remembered for the visible checks."""
    student = str(student if student is not None else student_id())
    grading = _state["grading"]
    if grading is not None:
        if student != grading["student"]:
            _state["refused"].append(student)
            raise LookupError(
                f"while a submission is graded, a notebook gets only its submitter's values: "
                f"this one asked for the values of {student!r}. It is graded against the "
                "submitter's own values."
            )
        statement = grading
    else:
        from .assignment import statement_of  # not available inside the grading sandbox

        statement = statement_of(spec, student)
    nv = NotebookVariant(statement)
    _state["variant"] = nv
    return nv


def check_format(name, namespace):
    """Visible test: the answer exists, has a usable form and the right
    dimension. Raises AssertionError with what to fix. It never looks at the
    value itself: that is judged when the assignment is graded."""
    nv = _state["variant"]
    if nv is None:
        raise AssertionError("the parameter cell has not run: run the notebook from the top")
    if name not in nv.asked:
        raise AssertionError(f"this notebook has no graded answer {name!r}")
    value = namespace.get(name, MISSING) if namespace is not None else MISSING
    reading = read(nv.asked[name], describe(value), ureg)
    if not reading.ok:
        raise AssertionError(reading.problem)
    print(
        f"{name}: form and dimension are fine (its value is judged when the assignment is graded)"
    )


def set_grading_statement(statement):
    """Called by the sandbox's kernel (:mod:`accelab.exercises.student.kernel`) before any cell
    runs: the submitter's statement, the only one a graded notebook can load."""
    _state["grading"] = statement
    _state["refused"] = []


def loaded_student():
    """(id of the variant the notebook loaded last, ids it asked for and was refused)."""
    nv = _state["variant"]
    return (nv.student if nv is not None else None), list(_state["refused"])
