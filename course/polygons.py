"""The polygon builder in a course notebook, and on its static page where the
builder cannot run.

:func:`show_builder` shows a builder: the builder itself in a live notebook; executed
headless (the site, the tests), its finished construction in two renditions (both
polygons side by side, or one above the other on a phone; :mod:`accelab.course.renditions`).
:func:`finished` draws that figure, for any construction task.

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

__all__ = ["classic_mistakes", "Table", "show_builder", "finished", "finished_markdown"]


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


def finished(task, narrow, title=None):
    """A Figure of the finished construction of ``task``: its polygons side by side
    (``narrow=False``, at most :data:`~accelab.course.renditions.WIDE` px across) or
    one above the other (``narrow=True``, for a phone), each with its own scale."""
    from accelab.exercises.student.polygon.figure import FONT, draw_phase
    from accelab.exercises.student.polygon.record import read_steps as read

    from .renditions import panels

    names = list(task.phases)
    n = len(names)
    fig, axes = panels(
        n, narrow, wide=(7.8, 4.4), tall=(4.6, 4.3 * n + 0.4), layout="constrained", squeeze=False
    )
    for ax, name in zip(axes.ravel(), names):
        phase = task.phase(name)
        draw_phase(ax, phase, read(ideal_steps(phase)), title=phase.title)
    if title:
        fig.suptitle(title, fontsize=FONT)
    return fig


def finished_markdown(task, alt, title=None):
    """Markdown of the finished construction of ``task``: both renditions when executed
    headless (the site shows the one that fits the screen), the wide one alone in a live
    notebook."""
    import base64

    from accelab.course.kit import is_static

    from .renditions import Renditions, _escape, png

    wide = png(finished(task, False, title))
    if is_static():
        return Renditions(wide, png(finished(task, True, title)), alt)._repr_markdown_()
    return f"![{_escape(alt)}](data:image/png;base64,{base64.b64encode(wide).decode('ascii')})\n"


def show_builder(builder, alt):
    """Show the polygon ``builder`` (a
    :class:`~accelab.exercises.student.polygon.PolygonBuilder`): in a live notebook the
    builder itself, empty, to construct in; executed headless (a page of the site, where
    nothing can be drawn), its finished construction in two renditions, which the cell's
    caption names. Returns None."""
    from accelab.exercises.student.polygon.widget import live

    from .renditions import show

    if live():
        builder.show()
        return None
    show(lambda narrow: finished(builder.task, narrow), alt=alt)
    return None
