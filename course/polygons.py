"""What the polygon builder says when a construction goes wrong, as a table a
notebook (or a static page, where the builder cannot run) can show.

:func:`classic_mistakes` makes each classic mistake of the graphical method on
the exact construction of a case (the wrong sense of a normal component, a
tangential line along its link, a term laid from the wrong point, the wrong
scale, the Coriolis term forgotten or halved, a read-off sign) and reports the
message the builder's rules (:mod:`accelab.exercises.student.polygon.rules`) give
for it: the very text a student sees.
"""

import copy
import re

from accelab.exercises.student.polygon.record import read_steps
from accelab.exercises.student.polygon.rules import judge_phase
from accelab.exercises.student.polygon.task import ideal_steps, task_of_case

__all__ = ["classic_mistakes", "Table"]


def _xy(z):
    return [z.real, z.imag]


def _edit(steps, name, fn, op="vector"):
    out = copy.deepcopy(steps)
    for s in out:
        if s["op"] == op and s.get("name") == name:
            fn(s)
    return out


def _turned(s, turn):
    tail, tip = complex(*s["tail"]), complex(*s["tip"])
    s["tip"] = _xy(tail + (tip - tail) * turn)


def _mistakes(task):
    """``[(phase, what the student did, steps, key judged)]`` for the mechanism."""
    acc = task.phase("acceleration")
    vel = task.phase("velocity")
    a = ideal_steps(acc)
    v = ideal_steps(vel)
    out = []
    if task.mechanism in ("fourbar", "slidercrank"):
        out.append(
            (
                "acceleration",
                "laid $\\mathbf{A}^n_A$ from $O_2$ toward $A$ (outward)",
                _edit(a, "A_A^n", lambda s: _turned(s, -1)),
                "vector:A_A^n",
            )
        )
        out.append(
            (
                "acceleration",
                "drew the line of $\\mathbf{A}^t_{BA}$ along $AB$",
                _edit(a, "A_BA^t", lambda s: s.update(angle=s["angle"] + 90), "line"),
                "line:A_BA^t",
            )
        )
        out.append(
            (
                "acceleration",
                "drew $\\mathbf{A}^n_A$ at the wrong scale (its length in units typed as squares)",
                _edit(a, "A_A^n", lambda s: _turned(s, acc.scale)),
                "vector:A_A^n",
            )
        )
    if task.mechanism == "fourbar":
        An = acc.term("A_B^n").vector
        A_A = acc.term("A_A^t").vector + acc.term("A_A^n").vector
        out.append(
            (
                "acceleration",
                "laid $\\mathbf{A}^n_B$ from the tip of $\\mathbf{A}_A$",
                _edit(a, "A_B^n", lambda s: s.update(tail=_xy(A_A), tip=_xy(A_A + An))),
                "vector:A_B^n",
            )
        )
    if task.mechanism == "invertedslidercrank":
        tip = acc.term("A_A4^n").vector
        forgot = [s for s in a if s.get("name") != "A_cor"]
        forgot = _edit(forgot, "A_slip", lambda s: s.update(through=_xy(tip)), "line")
        out.append(
            (
                "acceleration",
                "forgot the Coriolis term: drew the line of $\\mathbf{A}_{slip}$ through the "
                "tip of $\\mathbf{A}^n_{A_4}$",
                forgot,
                "line:A_slip",
            )
        )
        out.append(
            (
                "acceleration",
                "drew the Coriolis term as $\\omega_4 V_{slip}$ (without the 2)",
                _edit(a, "A_cor", lambda s: _turned(s, 0.5)),
                "vector:A_cor",
            )
        )
        out.append(
            (
                "acceleration",
                "turned $\\mathbf{V}_{slip}$ the wrong way for the Coriolis term",
                _edit(a, "A_cor", lambda s: _turned(s, -1)),
                "vector:A_cor",
            )
        )
    first = vel.reads[0]
    symbol = "\\" + first.label[:-1] + "_" + first.label[-1]  # omega3 -> \omega_3
    out.append(
        (
            "velocity",
            f"read ${symbol}$ with the wrong sign",
            _edit(v, first.name, lambda s: s.update(value=-s["value"]), "read"),
            f"read:{first.name}",
        )
    )
    return out


def tex(text):
    """A message in the builder's plain notation (``A_BA^t``, ``omega2^2``, ``O2A``)
    with its symbols as the chapter typesets them (Markdown math)."""

    def vector(m):
        sub = re.sub(r"^([A-Z])(\d)$", r"\1_\2", m.group(2))
        sup = f"^{{{m.group(3)}}}" if m.group(3) else ""
        return f"$\\mathbf{{{m.group(1)}}}{sup}_{{{sub}}}$"

    text = re.sub(r"\b([AV])_([A-Za-z0-9]+)(?:\^([nt]))?\b", vector, text)
    text = re.sub(
        r"\b(omega|alpha)(\d)(\^2)?",
        lambda m: f"$\\{m.group(1)}_{m.group(2)}{'^2' if m.group(3) else ''}$",
        text,
    )
    text = re.sub(r"\bO(\d)", r"$O_\1$", text)
    return re.sub(r"/s\^2", "/s\u00b2", text)


class Table:
    """A Markdown table (a notebook shows it rendered; ``str`` is the text)."""

    def __init__(self, text):
        self.text = text

    def _repr_markdown_(self):
        return self.text

    def __repr__(self):
        return self.text


def classic_mistakes(case):
    """The classic mistakes on the construction of ``case`` and what the builder
    says of each (a :class:`Table`)."""
    task = task_of_case(case)
    rows = []
    for phase, did, steps, key in _mistakes(task):
        judgement = judge_phase(task.phase(phase), read_steps(steps), list(task.phases.values()))
        said = tex(judgement.by_key()[key].message).replace("|", "\\|")
        rows.append(f"| {did} | {said} |")
    return Table("| the student | the builder says |\n|---|---|\n" + "\n".join(rows))
