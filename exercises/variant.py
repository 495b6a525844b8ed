"""``accelab variant``: one student's variant, without the answers, so that any
outside solver can answer it.

JSON shape::

    {"course": ..., "assignment": ..., "student": ..., "units": "US", "tolerance": 0.01,
     "problems": [{"number": 1, "family": ..., "title": ..., "statement": ...,
                   "given": {...}, "answers": [...]}],
     "answers": [{"name": "p1_A_A_x", "problem": 1, "kind": "number", "unit": "in/s^2",
                  "description": ..., "cases": {"A": {batch case}}, "expr": "real(A.A)",
                  "quantity_required": false}, ...]}

``expr`` is evaluated in SI (m, rad, s) over the batch outputs of ``cases``
(vectors as complex numbers); convert the result to ``unit``. Choice answers
have ``"kind": "choice"`` and ``choices``, and no expr.
"""

import json

from .assignment import build_variant
from .notebook import read_spec
from .silence import silenced


def variant_json(course_dir, assignment, student):
    """The public variant of ``student`` as a dict."""
    spec = read_spec(course_dir, assignment)
    with silenced():
        return build_variant(spec, student).public()


def format_text(v):
    lines = [
        f"{v['course']} / {v['assignment']} / student {v['student']} ({v['units']} units, "
        f"tolerance {100 * v['tolerance']:g}%)"
    ]
    for p in v["problems"]:
        lines.append(f"\nProblem {p['number']}: {p['title']}")
        lines += [f"  {k} = {val}" for k, val in p["given"].items()]
        for a in p["answers"]:
            what = a["unit"] or a.get("choices") or f"a construction: {a.get('construction')}"
            lines.append(f"  find {a['name']} [{what}]: {a['description']}")
    return "\n".join(lines)


def dumps(v):
    return json.dumps(v, indent=1)
