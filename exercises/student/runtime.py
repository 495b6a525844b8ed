"""What a student's notebook imports: the registry, the student id, the student's
statement (given values and what is asked) and the visible checks.

The kernel only reports. Nothing here holds, computes or judges an expected
value: a student's values are checked for form and dimension (the visible test
cells), and the grader judges them later, in its own process, against the key
it computes for the submitter (:mod:`accelab.exercises.grader`).

The notebook shows the values of the student that nbgrader will collect its
submission as (:mod:`.identity`: the JupyterHub user, else the id nbgrader's exchange
submits this account's work as, else an explicit ``ACCELAB_STUDENT``); with none of
them it shows the self-study values and says how to set the id, and its checks fail
until one is set. Its checks (Validate) also fail when the values it shows are not
the submitter's. While a submission is graded, the sandbox hands this module the
submitter's statement before any cell runs, and only that one can be loaded.
"""

import os

from accelab.solver.units import Q_, ureg

from .answers import MISSING, Asked, describe, read
from .identity import identify

__all__ = ["ureg", "Q_", "student_id", "load_variant", "check_format", "CheckFailed", "SELF_STUDY"]


class CheckFailed(AssertionError):
    """A visible check that failed: shown in the notebook as its one sentence (what to
    fix), not as a traceback through this module."""

    def _render_traceback_(self):  # IPython shows these lines in place of a traceback
        return [f"\x1b[0;31mCheck failed\x1b[0m: {self}"]


SELF_STUDY = "self-study"
#: the sandbox's statement while grading, the loaded variant, the ids a
#: notebook asked for that it was not given
_state = {"grading": None, "variant": None, "refused": [], "spec": None}


def student_id(spec=None):
    """The id whose values a notebook of the assignment ``spec`` shows: the student
    nbgrader will collect its submission as (:func:`.identity.identify`), else
    ``"self-study"``. While a submission is graded: the id the grader gave."""
    if _state["grading"] is not None:
        for var in ("ACCELAB_STUDENT_ID", "JUPYTERHUB_USER"):
            value = os.environ.get(var, "").strip()
            if value:
                return value
        return SELF_STUDY
    return identify(spec if spec is not None else _state["spec"]).student or SELF_STUDY


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
            except Exception:  # noqa: BLE001 -- a word (the circuit) stays text
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
    assignment ``spec``, remembered for the visible checks. Outside grading it
    says whose values they are and why (or how to set the student id)."""
    _state["spec"] = spec
    grading = _state["grading"]
    student = str(student if student is not None else student_id(spec))
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
        # the instructor's side draws the variant; it is never reached inside the grading
        # sandbox (which hands over the statement first), where it is not there at all
        from ..assignment import statement_of

        statement = statement_of(spec, student)
    nv = NotebookVariant(statement)
    _state["variant"] = nv
    if grading is None:
        print(_whose(nv.student, identify(spec)))
    return nv


def _whose(shown, identity):
    """The sentence under the parameter cell: whose values the notebook shows."""
    if identity.student is None:
        return (
            "These are the SELF-STUDY values: no student id was found (no JupyterHub user, "
            "no assignment of this course that nbgrader's exchange released to this account, "
            "no ACCELAB_STUDENT). If you are a student of the course, set your id and run the "
            "notebook again from the top: put `%env ACCELAB_STUDENT=your-id` in a cell above "
            "this one (or start Jupyter with ACCELAB_STUDENT=your-id). Until then its checks "
            "fail."
        )
    if shown != identity.student:
        return (
            f"These are the values of student {shown!r}, but this notebook will be collected as "
            f"student {identity.student!r} ({identity.how}) and graded against "
            f"{identity.student!r}'s values: run the notebook from the top without changing "
            f"this cell."
        )
    return f"These are the values of student {shown!r} ({identity.how})."


def _not_the_submitters():
    """Why the loaded values are not those of the student the notebook will be
    collected as, or None when they are (outside grading only)."""
    nv = _state["variant"]
    identity = identify(_state["spec"])
    if identity.student is not None and nv.student == identity.student:
        return None
    if identity.student is None:
        return (
            "This notebook shows the self-study values, not a student's: no student id was "
            "found (no JupyterHub user, no assignment of this course released to this account "
            "by nbgrader's exchange, no ACCELAB_STUDENT). Set your id (`%env "
            "ACCELAB_STUDENT=your-id` in a cell above the parameter cell) and run the notebook "
            "from the top."
        )
    return (
        f"This notebook shows the values of student {nv.student!r}, but nbgrader will collect "
        f"it as student {identity.student!r} ({identity.how}), whose values differ: its "
        f"answers would be judged against {identity.student!r}'s values. Run the notebook from "
        f"the top (Restart Kernel and Run All Cells) without changing its parameter cell."
    )


def check_format(name, namespace):
    """Visible test: the answer exists, has a usable form and the right
    dimension. Raises AssertionError with what to fix. It never looks at the
    value itself: that is judged when the assignment is graded."""
    nv = _state["variant"]
    if nv is None:
        raise CheckFailed("the parameter cell has not run: run the notebook from the top")
    if name not in nv.asked:
        raise CheckFailed(f"this notebook has no graded answer {name!r}")
    if _state["grading"] is None:
        problem = _not_the_submitters()
        if problem:
            raise CheckFailed(problem)
    value = namespace.get(name, MISSING) if namespace is not None else MISSING
    reading = read(nv.asked[name], describe(value), ureg)
    if not reading.ok:
        raise CheckFailed(reading.problem)
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
