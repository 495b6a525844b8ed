"""The polygon builder as a student uses it: JupyterLab in headless Chromium, real
pointer events (a mouse at 1366 px, a finger at a phone's 390 px), the feedback
read off the page, the notebook saved, then graded by `accelab grade`.

* practice (Example 7-1): a right velocity polygon, step by step, each step said
  right as it is made; then the classic mistakes on the acceleration polygon (the
  wrong sense of A_A^n, the line of A_BA^t along the link), each named in the
  chapter's terms and marked on the canvas; undo; "Show the next step";
* an assignment: the student's released notebook opened and run in JupyterLab, a
  right velocity polygon and a half-finished acceleration polygon drawn, the
  notebook saved; the saved notebook graded through `accelab grade` scores
  exactly what was drawn right;
* the practice at 390 px with touch (last: the phone's page is the one test that
  needs JupyterLab loaded at another size; the others share one page).

Screenshots are kept in ``build/test-artifacts/polygon/`` (or
``$ACCELAB_ARTIFACTS``) and were looked at when these tests were written.
"""

import cmath
import csv
import datetime
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import time

import nbformat
import pytest
from _polygon_lab import (
    browser,
    choose,
    click,
    command,
    console_errors,
    drag,
    find,
    lab,
    message,
    missing,
    open_notebook,
    resize,
    tap,
    type_into,
    wait,
)

pytest.importorskip("selenium", reason="selenium is not installed (pip install -e '.[test]')")

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.actions import interaction
from selenium.webdriver.common.actions.action_builder import ActionBuilder
from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from accelab.exercises.grader.key import key_for
from accelab.exercises.grader.sandbox import check_sandbox
from accelab.exercises.notebook import read_spec
from accelab.exercises.student.polygon.record import MIMETYPE
from accelab.exercises.student.polygon.task import task_of_case
from accelab.exercises.student.polygon.widget import STORE
from accelab.solver.graphical.gallery import EXAMPLE_7_1

#: one worker: the module's JupyterLab and its course (module fixtures) are made once
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("polygon-lab")]

ROOT = pathlib.Path(__file__).resolve().parent.parent
ARTIFACTS = (
    pathlib.Path(os.environ.get("ACCELAB_ARTIFACTS", ROOT / "build" / "test-artifacts")) / "polygon"
)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    reason = missing()
    if reason:
        pytest.skip(reason)
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    root = tmp_path_factory.mktemp("lab")
    nb = nbformat.v4.new_notebook(
        cells=[
            nbformat.v4.new_code_cell(
                "from accelab.exercises.student.polygon import PolygonBuilder\n"
                "from accelab.solver.graphical.gallery import EXAMPLE_7_1\n"
                "PolygonBuilder.from_case(EXAMPLE_7_1, title='Example 7-1').show()"
            )
        ]
    )
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nbformat.write(nb, root / "practice.ipynb")
    return root


def shot(driver, name):
    el = driver.find_element("css selector", "[data-testid=polygon-builder]")
    driver.execute_script("arguments[0].scrollIntoView({block: 'start'})", el)
    time.sleep(0.4)
    driver.save_screenshot(str(ARTIFACTS / f"{name}.png"))


def start(driver, base, token, path, again=False, in_page=False):
    open_notebook(driver, base, token, path, again=again, in_page=in_page)
    command(driver, "notebook:run-all-cells", wait_for_it=False)
    wait(
        driver,
        "return document.querySelector("
        "'[data-testid=polygon-builder] .apb-canvas [data-testid=pole]')",
        timeout=180,
        what="the builder",
    )
    time.sleep(0.5)


def judged(driver, n, timeout=60):
    """Wait for the n-th step of the polygon's list to be judged; its mark and message."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        items = driver.execute_script(
            "return Array.from(document.querySelectorAll("
            "'[data-testid=polygon-builder] [data-testid=steps] li')).map(li => "
            "[li.className, li.querySelector('.apb-why').textContent])"
        )
        if len(items) >= n and (items[n - 1][0] or items[n - 1][1]):
            time.sleep(0.2)
            return items[n - 1]
        time.sleep(0.1)
    raise TimeoutError(f"step {n} was not judged")


def visible(driver, points):
    """Zoom out until every polygon point [SI] is on the canvas."""
    from _polygon_lab import screen

    for _ in range(6):
        try:
            for z in points:
                screen(driver, z)
            return
        except AssertionError:
            click(driver, "zoom-out")
            time.sleep(0.2)
    raise AssertionError("the points do not fit on the canvas")


def velocity_by_pointer(driver, phase, touch, check=True):
    """The velocity polygon of Example 7-1 (or any fourbar), by real pointer input."""
    V_A, V_BA, V_B, X = (
        phase.term("V_A").vector,
        phase.term("V_BA").vector,
        phase.term("V_B").vector,
        phase.X,
    )
    visible(driver, [0j, V_A, X, 0.4 * V_B])
    click(driver, "tool-vector")
    choose(driver, "vector-name", "V_A")
    drag(driver, 0j, V_A, touch=touch)
    assert judged(driver, 1)[0] == "ok" or not check
    click(driver, "tool-line")
    choose(driver, "line-name", "V_BA")
    drag(driver, V_A, V_A + 0.5 * V_BA, touch=touch)
    choose(driver, "line-name", "V_B")
    drag(driver, 0j, 0.4 * V_B, touch=touch)
    judged(driver, 3)
    click(driver, "tool-point")
    tap(driver, X, touch=touch)
    judged(driver, 4)
    click(driver, "tool-vector")
    choose(driver, "vector-name", "V_BA")
    drag(driver, V_A, X, touch=touch)
    choose(driver, "vector-name", "V_B")
    drag(driver, 0j, X, touch=touch)
    judged(driver, 6)
    click(driver, "tool-read")
    reads = {r.name: r.value for r in phase.reads}
    type_into(driver, "read-omega3", f"{reads['omega3']:.3f}")
    click(driver, "enter-omega3")
    type_into(driver, "read-omega4", f"{reads['omega4']:.3f}")
    click(driver, "enter-omega4")
    return judged(driver, 8)


def zoom(driver):
    """The polygon canvas's zoom [CSS px per display unit]."""
    return json.loads(find(driver, "canvas").get_attribute("data-view"))["z"]


def marks(driver):
    return driver.execute_script(
        "return Array.from(document.querySelectorAll("
        "'[data-testid=polygon-builder] [data-testid=steps] li')).map(li => li.className)"
    )


@pytest.fixture(scope="module")
def driver(folder):
    """One Chromium for the module, made a laptop's or a phone's by each test (each test
    opens its notebook in a fresh page and workspace)."""
    with browser(1366) as d:
        yield d


def test_practice_right_then_each_classic_mistake_with_a_mouse(server, folder, driver):
    base, token = server
    (folder / STORE).unlink(missing_ok=True)  # a fresh start, not an earlier session's steps
    task = task_of_case(EXAMPLE_7_1)
    vel, acc = task.phase("velocity"), task.phase("acceleration")
    d = driver
    resize(d, 1366)
    start(d, base, token, "practice.ipynb")
    assert "Directions are right within 1" in find(d, "polygon-builder").text
    assert "1 square = 5 in/s" in find(d, "scale").text
    velocity_by_pointer(d, vel, touch=False)
    assert marks(d) == ["ok"] * 8, [message(d)]
    assert "8/8" in find(d, "tab-velocity").text
    shot(d, "practice-velocity-1366")
    # the acceleration polygon: the classic mistakes, each said in the chapter's terms
    click(d, "tab-acceleration")
    click(d, "tool-vector")
    visible(d, [0j, acc.term("A_A^t").vector + acc.term("A_A^n").vector, acc.X])
    choose(d, "vector-name", "A_A^t")  # too short to drag at this scale: typed
    type_into(d, "length", f"{abs(acc.term('A_A^t').vector) / 0.0254:.3f}")
    choose(d, "dir-mode", "perp")
    choose(d, "dir-link", "O2A")
    click(d, "sense-1")  # 30 + 270 = 300 deg: perpendicular to O2A, as alpha2 < 0 turns
    click(d, "place")
    assert judged(d, 1)[0] == "ok", message(d)
    tip = acc.term("A_A^t").vector
    An = acc.term("A_A^n").vector
    choose(d, "vector-name", "A_A^n")
    drag(d, tip, tip - An)  # pointing away from O2: the wrong sense
    assert judged(d, 2)[0] == "bad"
    cls, text = message(d)
    assert "bad" in cls and "has the wrong sense" in text and "toward O2" in text, text
    assert d.find_elements("css selector", "[data-testid=canvas] .apb-badge")
    shot(d, "practice-wrong-sense-1366")
    click(d, "undo")
    time.sleep(0.5)
    drag(d, tip, tip + An)
    assert judged(d, 2)[0] == "ok", message(d)
    choose(d, "vector-name", "A_BA^n")
    A_BA_n = acc.term("A_BA^n").vector
    drag(d, tip + An, tip + An + A_BA_n)
    assert judged(d, 3)[0] == "ok", message(d)
    # the line of A_BA^t along the link instead of across it
    click(d, "tool-line")
    choose(d, "line-name", "A_BA^t")
    end = tip + An + A_BA_n
    drag(d, end, end - 0.4 * A_BA_n)
    assert judged(d, 4)[0] == "bad"
    cls, text = message(d)
    assert "bad" in cls and "perpendicular to AB, not along it" in text, text
    shot(d, "practice-tangential-along-the-link-1366")
    # show the next step: what to do, drawn dotted
    click(d, "undo")
    time.sleep(0.4)
    click(d, "next")
    wait(d, "return document.querySelector('[data-testid=ghost]')", what="the next step")
    cls, text = message(d)
    assert "info" in cls and "Lay A" in text, text
    shot(d, "practice-next-step-1366")
    # zoom with Ctrl and the wheel (a touchpad's pinch arrives the same way); a plain
    # wheel is left to scroll the notebook
    canvas = find(d, "canvas")
    before = zoom(d)
    ActionChains(d).scroll_from_origin(ScrollOrigin.from_element(canvas), 0, 120).perform()
    assert zoom(d) == before
    ActionChains(d).key_down(Keys.CONTROL).scroll_from_origin(
        ScrollOrigin.from_element(canvas), 0, -120
    ).key_up(Keys.CONTROL).perform()
    time.sleep(0.3)
    assert zoom(d) > 1.5 * before
    assert not [e for e in console_errors(d) if "polygon" in e.lower()]


@pytest.fixture(scope="module")
def server(folder, course):
    """One JupyterLab for the module; its kernels know the student as ann (as
    JupyterHub would tell them)."""
    with lab(folder, env={"ACCELAB_STUDENT_ID": "ann"}) as (base, token):
        yield base, token


@pytest.fixture(scope="module")
def course(tmp_path_factory, folder):
    reason = check_sandbox()
    assert reason is None, f"the sandbox must work in CI: {reason}"
    course = str(tmp_path_factory.mktemp("course") / "mech")
    roster = tmp_path_factory.mktemp("roster") / "roster.csv"
    roster.write_text("id\nann\n")
    subprocess.run(
        [sys.executable, "-m", "accelab", "assign", "--course", course, "--assignment", "A",
         "--families", "polygon_fourbar", "--roster", str(roster),
         "--due", "2040-01-01 00:00"],
        check=True, capture_output=True,
    )  # fmt: skip
    work = folder / "ann" / "A"
    work.mkdir(parents=True)
    shutil.copy(os.path.join(course, "release", "A", "A.ipynb"), work / "A.ipynb")
    return course


def test_an_assignment_drawn_saved_and_graded(folder, course, server, driver):
    base, token = server
    key = key_for(read_spec(course, "A"), "ann")
    task = key.values["velocity_polygon"].task
    vel, acc = task.phase("velocity"), task.phase("acceleration")
    d = driver
    resize(d, 1366)
    # opened in the page of the test before, if it is there (its notebook closed)
    start(d, base, token, "ann/A/A.ipynb", in_page=True)
    assert "judged when the assignment is graded" in find(d, "polygon-builder").text
    last = velocity_by_pointer(d, vel, touch=False, check=False)
    assert last[0] == "" and "judged when the assignment is graded" in last[1]
    # the acceleration polygon: its known terms only (4 of its 12 steps), typed
    click(d, "tab-acceleration")
    click(d, "tool-vector")
    last_on = {}
    for term in [t for t in acc.terms if t.known]:
        choose(d, "vector-name", term.name)
        type_into(d, "length", f"{abs(term.vector) * acc.factor:.6g}")
        choose(d, "dir-mode", "angle")
        type_into(d, "dir-angle", f"{math.degrees(cmath.phase(term.vector)):.4f}")
        start_at = last_on.get(term.side)
        Select(find(d, "from")).select_by_visible_text(
            f"the tip of {start_at}" if start_at else "the pole"
        )
        click(d, "place")
        last_on[term.side] = term.name
        time.sleep(0.6)
    shot(d, "assignment-1366")
    command(d, "docmanager:save")
    time.sleep(2)
    # the next day: the notebook closed, opened and run again brings the construction back
    start(d, base, token, "ann/A/A.ipynb", again=True)
    wait(
        d,
        "return document.querySelectorAll("
        "'[data-testid=polygon-builder] [data-testid=steps] li').length === 8",
        what="the velocity polygon's 8 steps, kept from the last session",
    )
    saved = nbformat.read(folder / "ann" / "A" / "A.ipynb", as_version=4)
    cell = next(c for c in saved.cells if c.metadata["nbgrader"]["grade_id"] == "polygon1")
    data = [o["data"][MIMETYPE] for o in cell.outputs if MIMETYPE in o.get("data", {})]
    assert data and len(data[-1]["steps"]) == 12, data
    # submit and collect, as nbgrader would, then grade
    sub = os.path.join(course, "submitted", "ann", "A")
    os.makedirs(sub)
    shutil.copy(folder / "ann" / "A" / "A.ipynb", os.path.join(sub, "A.ipynb"))
    with open(os.path.join(sub, "timestamp.txt"), "w") as fh:
        fh.write(datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S.%f %Z"))
    proc = subprocess.run(
        [sys.executable, "-m", "accelab", "grade", "--course", course, "--assignment", "A",
         "--quiet"],
        capture_output=True, text=True,
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    with open(os.path.join(course, "grades_A.csv")) as fh:
        row = next(csv.DictReader(fh))
    assert float(row["velocity_polygon"]) == 1.0, row
    assert float(row["acceleration_polygon"]) == pytest.approx(4 / 12, abs=1e-3), row
    assert "exact one" not in row["notes"]  # drawn by hand, not written in
    outcome = json.load(open(os.path.join(course, ".accelab", "outcomes", "A", "ann.json")))
    assert "4 of 12 steps" in outcome["verdicts"]["acceleration_polygon"]["message"]


def test_practice_on_a_phone_with_a_finger(server, folder, driver):
    base, token = server
    (folder / STORE).unlink(missing_ok=True)
    task = task_of_case(EXAMPLE_7_1)
    d = driver
    resize(d, 390)
    start(d, base, token, "practice.ipynb")
    root = find(d, "polygon-builder")
    assert "narrow" in root.get_attribute("class")
    assert "0/8" in find(d, "tab-velocity").text  # nothing kept from another session
    width = d.execute_script(
        "const r = arguments[0]; return [r.scrollWidth, r.clientWidth, "
        "r.getBoundingClientRect().width];",
        root,
    )
    assert width[0] <= width[1] + 1, width  # nothing sticks out sideways
    canvas = find(d, "canvas").rect
    assert canvas["width"] >= 250 and canvas["height"] >= 250
    shot(d, "practice-start-390")
    velocity_by_pointer(d, task.phase("velocity"), touch=True)
    assert marks(d) == ["ok"] * 8, [message(d)]
    shot(d, "practice-velocity-390")
    # two fingers spread apart zoom in; the fit button brings the drawing back
    canvas = find(d, "canvas")
    before = zoom(d)
    pinch = ActionBuilder(d)
    one = pinch.add_pointer_input(interaction.POINTER_TOUCH, "one")
    two = pinch.add_pointer_input(interaction.POINTER_TOUCH, "two")
    one.create_pointer_move(origin=canvas, x=-20, y=0)
    two.create_pointer_move(origin=canvas, x=20, y=0)
    one.create_pointer_down()
    two.create_pointer_down()
    for k in range(1, 6):
        one.create_pointer_move(origin=canvas, x=-20 - 8 * k, y=0, duration=30)
        two.create_pointer_move(origin=canvas, x=20 + 8 * k, y=0, duration=30)
    one.create_pointer_up(0)
    two.create_pointer_up(0)
    pinch.perform()
    time.sleep(0.3)
    assert zoom(d) == pytest.approx(3 * before, rel=0.1)
    assert marks(d) == ["ok"] * 8  # a pinch draws nothing
    click(d, "zoom-fit")
    time.sleep(0.3)
    shot(d, "practice-velocity-fit-390")
