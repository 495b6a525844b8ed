"""The instructor's guide (docs/guide/deploy.md) as the browser tests run it: its code
blocks, each found by what it holds, with the guide's folders and names replaced by the
test's (``places``). What the guide gives is what runs: a test that needs a setting the
guide does not give adds it after the guide's text and says why."""

import json
import os
import re
import shlex
import stat
from pathlib import Path

GUIDE = Path(__file__).resolve().parents[1] / "docs" / "guide" / "deploy.md"
#: a fenced block, at the margin or indented under a list item
_FENCE = re.compile(r"^( *)```(\w*)\n(.*?)^\1```", re.M | re.S)


def blocks(lang):
    """The guide's code blocks in ``lang``, their indentation removed."""
    found = []
    for m in _FENCE.finditer(GUIDE.read_text(encoding="utf-8")):
        if m.group(2) == lang:
            pad = m.group(1)
            lines = m.group(3).splitlines(keepends=True)
            found.append("".join(line.removeprefix(pad) for line in lines))
    return found


def block(lang, *holding, lacking=()):
    """The one ``lang`` block of the guide that holds every string of ``holding`` and
    none of ``lacking``."""
    found = [
        b for b in blocks(lang) if all(h in b for h in holding) and not any(x in b for x in lacking)
    ]
    assert len(found) == 1, (
        f"{GUIDE} has {len(found)} {lang} blocks holding {holding} (and not {lacking}): "
        "the test runs the guide's own configuration, so it must find exactly one"
    )
    return found[0]


def adapted(text, places):
    """``text`` with each of the guide's folders and names (keys of ``places``: a path
    or a whole word) replaced by the test's, in one pass: the longest first where two
    start at one place, and a replacement is never read again (the test's folder may
    hold a word of the guide, such as /tmp/prof/... for the name ``prof``)."""
    keys = sorted(places, key=len, reverse=True)
    alternatives = [
        rf"\b{re.escape(k)}\b" if re.fullmatch(r"\w+", k) else re.escape(k) for k in keys
    ]
    if not alternatives:
        return text
    return re.sub("|".join(alternatives), lambda m: places[m.group(0)], text)


def command(text, places):
    """A shell block of the guide (one command, continued with backslashes) as argv."""
    return shlex.split(adapted(text, places).replace("\\\n", " "))


def role_files(role, hub):
    """The files of ``role``'s Jupyter configuration folder, as the guide gives them:
    {path in the folder: text}. On a hub, each role's folder (``/etc/jupyter-ROLE``);
    without one, the student's own nbgrader configuration (the exchange and the course)
    and the same settings of JupyterLab and its server."""
    if role == "instructor":
        assert hub, "without a hub the instructor's server starts in the course folder"
        return {
            "nbgrader_config.py": block("python", "CourseDirectory.root", "JupyterHubAuthPlugin"),
            "jupyter_server_config.json": block("json", "Content-Security-Policy"),
        }
    config = (
        block("python", "JupyterHubAuthPlugin", lacking=("CourseDirectory.root",))
        if hub
        else block("python", "c.CourseDirectory.course_id", lacking=("JupyterHubAuthPlugin",))
    )
    return {
        "nbgrader_config.py": config,
        "labconfig/page_config.json": block("json", "disabledExtensions"),
        "jupyter_server_config.json": block("json", "jpserver_extensions"),
    }


def write_role(folder, role, places, hub):
    """Write ``role``'s configuration folder (:func:`role_files`, adapted) into
    ``folder``, readable by every account; returns ``folder``."""
    folder = Path(folder)
    for name, text in role_files(role, hub).items():
        text = adapted(text, places)
        if name.endswith(".json"):
            json.loads(text)  # the guide's JSON is JSON
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    for path in (folder, *folder.rglob("*")):
        path.chmod(0o755 if path.is_dir() else 0o644)
    return folder


#: a folder's line in the guide's drawing of the layout: its name, then its mode as ls shows it
_DRAWN = re.compile(r"(?P<name>[\w.-]+)/\s+(?P<mode>d[r-][w-][xsS-][r-][w-][xsS-][r-][w-][xtT-])")


def layout():
    """The folders of the guide's drawing of a course's layout, each with the mode it
    gives: {path under the class's folder: mode as ``ls -l`` shows it}."""
    drawing = block("text", "exchange/", "inbound/")
    found, stack = {}, []
    for line in drawing.splitlines()[1:]:  # below the class's folder
        m = _DRAWN.search(line)
        name = re.search(r"[\w.-]+/", line)
        if name is None:
            continue
        depth = name.start() // 4 - 1  # the tree: 4 columns a level, the first under it
        stack[depth:] = [name.group(0).rstrip("/")]
        if m and m.start() == name.start():
            found["/".join(stack)] = m.group("mode")
    return found


def assert_layout(folder, uid):
    """The class's ``folder`` is laid out as the guide draws it: each drawn folder with
    its mode, and owned by ``uid`` (the instructor, who ran ``accelab assign``)."""
    drawn = layout()
    assert {"course", "exchange", "exchange/mech101/inbound"} <= set(drawn), drawn
    found = {}
    for rel in drawn:
        st = os.lstat(Path(folder) / rel)
        found[rel] = (stat.filemode(st.st_mode), st.st_uid)
    assert found == {rel: (mode, uid) for rel, mode in drawn.items()}, found
