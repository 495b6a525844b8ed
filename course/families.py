"""The course's page of exercise families, FAMILIES.md, written from the families' registry.

For the instructor, beside the notebooks that ``accelab course --out DIR`` writes: which
notebook teaches each graded family of ``accelab assign``. Every row comes from
:data:`accelab.exercises.families.REGISTRY` (what of the chapter the family practises,
what it asks, the notebooks that teach it) and each notebook's title from its first
heading, so the page never lists a family, or a notebook, the package does not have.
"""

import re

from accelab.exercises.families import REGISTRY

from . import notebooks

NAME = "FAMILIES.md"

INTRO = """\
# Exercise families and the notebooks that teach them

For the instructor: each graded exercise family of `accelab assign` (the generators in
`accelab.exercises.families`) practises what one or two notebooks of the course teach. Assign a
family after its notebooks; a student who is stuck can go back to them, and to their
**Practice** section, whose problems come from the same family but are never those of a graded
assignment.

Sections, equations and figures are those of Robert L. Norton, *Design of Machinery*,
chapter 7, "Acceleration Analysis".
"""


def titles():
    """Notebook stem -> its title, the first Markdown heading ("1. The acceleration of ...")."""
    out = {}
    for path in notebooks():
        heading = re.search(r"^# # (.+)$", path.read_text(), flags=re.MULTILINE)
        out[path.stem] = heading.group(1).strip() if heading else path.stem
    return out


def page():
    """FAMILIES.md: the table of families (from the registry) and the notebooks with none."""
    names = titles()

    def link(stem):
        return f"[{names[stem]}]({stem}.ipynb)"

    rows = [
        f"| `{f.name}` | {f.chapter} | {f.asks} | {', '.join(link(s) for s in f.notebooks)} |"
        for f in REGISTRY.values()
    ]
    taught = {s for f in REGISTRY.values() for s in f.notebooks}
    free = [s for s in names if s not in taught]
    lines = [INTRO, "| family | chapter | what it asks | taught in |", "|---|---|---|---|", *rows]
    if free:
        lines += [
            "",
            "No graded family practises these notebooks; they are for reading and exploring: "
            + ", ".join(link(s) for s in free)
            + ".",
        ]
    return "\n".join(lines) + "\n"
