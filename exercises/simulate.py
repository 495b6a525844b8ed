"""Simulated submissions (for the demo and the tests): the released notebook
with its answer cells filled in, dropped into ``submitted/<student>/<A>/``."""

import datetime
import os

import nbformat


def fill(nb, code):
    """Put ``code[name]`` (source text) into the answer cell ``answer_<name>``."""
    for cell in nb.cells:
        gid = cell.metadata.get("nbgrader", {}).get("grade_id", "")
        if gid.startswith("answer_") and gid[len("answer_") :] in code:
            cell.source = code[gid[len("answer_") :]]
    return nb


def submit(course_dir, assignment, student, code, edit=None):
    """Write a submission whose answer cells hold ``code`` (name -> source).

    ``edit(nb)`` may change the notebook further (delete a cell, ...).
    Returns the submitted notebook's path.
    """
    release = os.path.join(course_dir, "release", assignment, f"{assignment}.ipynb")
    nb = fill(nbformat.read(release, as_version=4), code)
    if edit:
        nb = edit(nb) or nb
    folder = os.path.join(course_dir, "submitted", student, assignment)
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, f"{assignment}.ipynb")
    nbformat.write(nb, path)
    with open(os.path.join(folder, "timestamp.txt"), "w") as fh:
        fh.write(datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S.%f %Z"))
    return path


def key_code(spec, student, transform=None):
    """Answer code from the grader's key for ``student``: ``name = Q_(value, unit)``.

    ``transform(answer, quantity)`` may return other source text (a wrong
    answer, another unit, ...) or None to keep the right one. (Simulations and
    tests only: the key never enters a student's notebook.)
    """
    from accelab.solver.units import Q_

    from .grader.key import key_for

    key = key_for(spec, student)
    code = {}
    for name, a in key.variant.answers.items():
        value = key.values[name]
        if a.kind != "choice":
            base = Q_(1.0, a.unit or "").to_base_units().units
            value = Q_(value, base).to(a.unit or "")
        text = transform(a, value) if transform else None
        if text is None:
            text = (
                f"{name} = {value!r}"
                if a.kind == "choice"
                else f"{name} = Q_({value.magnitude!r}, {a.unit!r})"
            )
        code[name] = text
    return code
