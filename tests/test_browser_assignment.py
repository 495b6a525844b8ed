"""An assignment as a student and an instructor meet it, driven in JupyterLab in headless
Chromium, without JupyterHub: the student is a local account (created by the test) with
a JupyterLab of its own, the instructor is this account with the course folder.

The student opens the Assignments panel, fetches the assignment, runs it (it shows the
values of the account nbgrader's exchange submits as), answers in the answer cells,
presses Validate (which fails, naming whose values the notebook shows, when a cell loaded
another student's values, and otherwise says that the values are judged at grading) and
submits. The instructor collects with formgrader, grades with ``accelab grade`` and with
formgrader's autograde button (through the sandbox), looks at the submission in formgrader
(its equations typeset by a local MathJax), releases feedback, and the student fetches it.
Screenshots of every step are kept in ``build/screenshots/``.
"""

import csv
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import _guide as guide
import pytest
from _lab import (
    LAPTOP,
    NARROW,
    SHARED,
    Lab,
    account,
    assignments_panel,
    browser,
    button_in,
    cell_node,
    cells,
    click_in_row,
    click_menu,
    close,
    close_dialog,
    close_modal,
    dialog_text,
    dismiss_toasts,
    formgrader_modal,
    in_panel,
    lab_ready,
    menu_labels,
    need_accounts,
    need_browser,
    open_path,
    shared_venv,
    shot,
    tracebacks,
    type_into_cell,
    wait,
    wait_idle,
)

#: one worker runs the module's tests, in order: they share the class its fixture makes
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("lab-class")]

STUDENT = "lab_ann"
COURSE_ID = "mech101"
CLASS = SHARED / "lab-class"


@pytest.fixture(scope="module")
def klass():
    """The class on one machine, set up with the guide's own commands
    (docs/guide/deploy.md, read by :mod:`_guide`): root makes the class's folder (the
    instructor's: here this account), the instructor's ``accelab assign --exchange``
    lays out the course (private) and the exchange beside it and releases A; the
    student's account gets the guide's student configuration (the exchange, the course,
    no instructor's menus)."""
    need_browser()
    need_accounts()
    shared_venv()
    shutil.rmtree(CLASS, ignore_errors=True)
    CLASS.parent.mkdir(parents=True, exist_ok=True)
    roster = CLASS.parent / "lab-class-roster.csv"  # the instructor's, outside the class's
    roster.write_text(f"id,first_name,last_name\n{STUDENT},Ann,Lab\n")
    places = {"/srv/mech101": str(CLASS), "prof": "root", "~/roster.csv": str(roster)}
    subprocess.run(guide.command(guide.block("sh", "install -d"), places), check=True)
    argv = guide.command(guide.block("sh", "accelab assign", "--course-id"), places)
    argv[argv.index("--families") + 1] = "tolerance"  # one family of the guide's three: time
    assert argv[:2] == ["accelab", "assign"], argv
    accelab(*argv[1:], cwd=CLASS)
    guide.assert_layout(CLASS, os.geteuid())
    course, exchange = CLASS / "course", CLASS / "exchange"
    home = Path(account(STUDENT).pw_dir)
    for old in ("A", ".local/share/jupyter/nbgrader_cache"):  # a run before this one
        shutil.rmtree(home / old, ignore_errors=True)
    return {
        "exchange": exchange,
        "course": course,
        "home": home,
        "student_cfg": guide.write_role(CLASS / "jupyter-student", "student", places, hub=False),
    }


def accelab(*args, cwd):
    env = dict(os.environ)
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env["PATH"]
    proc = subprocess.run(
        [sys.executable, "-m", "accelab", *args], cwd=cwd, env=env, capture_output=True, text=True
    )
    assert proc.returncode == 0, (args, proc.stdout[-2000:], proc.stderr[-3000:])
    return proc


def nbgrader(*args, cwd):
    env = dict(os.environ)
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env["PATH"]
    proc = subprocess.run(
        [sys.executable, "-m", "nbgrader", *args], cwd=cwd, env=env, capture_output=True, text=True
    )
    assert proc.returncode == 0, (args, proc.stdout[-2000:], proc.stderr[-3000:])
    return proc


@pytest.fixture(scope="module")
def student_lab(klass):
    server = Lab(
        klass["home"], user=STUDENT, config_dirs=[klass["student_cfg"]], log_name="lab-student"
    ).start()
    yield server
    server.stop()


@pytest.fixture(scope="module")
def instructor_lab(klass):
    from accelab.exercises.nbgrader_course import JUPYTER_DATA

    server = Lab(
        klass["course"],  # the course's own nbgrader_config.py: its exchange and collect
        env_extra={"JUPYTER_PATH": JUPYTER_DATA},  # formgrader's math offline (deploy guide)
        log_name="lab-instructor",
    ).start()
    yield server
    server.stop()


@pytest.fixture(scope="module")
def driver(klass):
    d = browser(LAPTOP)
    yield d
    close(d)


# ---------------------------------------------------------------- nbgrader's panels


def validate(driver):
    """Save, press the notebook's Validate button, and return the dialog's (title, body)."""
    from selenium.webdriver.common.by import By

    command_save(driver)
    button = wait(
        lambda: next(
            (
                b
                for b in driver.find_elements(
                    By.CSS_SELECTOR,
                    ".jp-NotebookPanel-toolbar jp-button, .jp-NotebookPanel-toolbar button",
                )
                if b.text.strip() == "Validate" and b.is_displayed()
            ),
            None,
        ),
        30,
        what="the Validate button",
    )
    button.click()
    return dialog_text(driver)


def command_save(driver):
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys

    ActionChains(driver).key_down(Keys.CONTROL).send_keys("s").key_up(Keys.CONTROL).perform()
    wait(
        lambda: in_panel(driver, "return !w.context.model.dirty"),
        30,
        what="the notebook to be saved",
    )


# ---------------------------------------------------------------- the student
def test_student_fetches_answers_validates_and_submits(klass, student_lab, driver):
    from selenium.webdriver.common.by import By

    from accelab.exercises.notebook import read_spec
    from accelab.exercises.simulate import key_code

    driver.get(student_lab.url("lab"))
    lab_ready(driver)
    time.sleep(2)
    dismiss_toasts(driver)
    items = menu_labels(driver, "Nbgrader")
    assert "Assignment List" in items, items
    assert not {"Formgrader", "Create assignment", "Course List"} & set(items), (
        f"a student sees the instructor's menus: {items}"
    )
    assert not driver.find_elements(By.XPATH, "//*[text()='Create Assignment']"), (
        "a student sees the Create Assignment sidebar"
    )
    shot(driver, "student-1-lab")

    assignments_panel(driver)
    shot(driver, "student-2-released")
    button_in(driver, "#released_assignments_list", "Fetch").click()
    wait(
        lambda: (klass["home"] / "A" / "A.ipynb").exists(),
        60,
        what="the assignment to be fetched into the student's home",
    )
    button_in(driver, "#fetched_assignments_list", "Submit")
    shot(driver, "student-3-fetched")

    open_path(driver, student_lab, "A/A.ipynb")
    shot(driver, "student-4-opened")
    click_menu(driver, "Run", "Run All Cells")
    wait_idle(driver)
    nb = cells(driver)
    params = next(c for c in nb if "load_variant(SPEC" in c["source"])
    assert (
        f"These are the values of student '{STUDENT}' (the account nbgrader's exchange"
        in (params["text"])
    ), params["text"]
    cell_node(driver, params["index"])
    shot(driver, "student-5-whose-values")
    # before any answer, the first check says what is missing (and Run All stops there)
    first_check = next(c for c in nb if "check_format(" in c["source"])
    assert first_check["errors"], "an empty answer passes its check"
    cell_node(driver, first_check["index"])
    shot(driver, "student-5-unanswered-check")

    code = key_code(read_spec(klass["course"], "A"), STUDENT)  # the right answers
    answer_cells = [
        c for c in cells(driver) if c["type"] == "code" and "YOUR ANSWER HERE" in c["source"]
    ]
    names = in_panel(
        driver,
        "return w.content.widgets.map(c => ((c.model.getMetadata && c.model.getMetadata("
        "'nbgrader')) || {}).grade_id || '')",
    )
    answered = 0
    for c in answer_cells:
        grade_id = names[c["index"]]
        assert grade_id.startswith("answer_"), grade_id
        name = grade_id[len("answer_") :]
        type_into_cell(driver, c["index"], code[name])
        answered += 1
    assert answered == len(code), (answered, sorted(code))
    wait_idle(driver)
    click_menu(driver, "Run", "Run All Cells")
    wait_idle(driver)
    assert not tracebacks(driver), tracebacks(driver)
    last = answer_cells[-1]["index"]
    cell_node(driver, last)
    shot(driver, "student-6-answered")
    shot(driver, "student-6-answered-narrow", size=NARROW)

    # another student's values loaded in a cell of its own: Validate names them and fails
    in_panel(driver, "w.content.activeCellIndex = arguments[1];", params["index"])
    driver.execute_script("window.jupyterapp.commands.execute('notebook:insert-cell-below')")
    time.sleep(0.5)
    type_into_cell(driver, params["index"] + 1, "v = load_variant(SPEC, 'lab_hal')")
    wait_idle(driver)
    title, body = validate(driver)
    shot(driver, "student-7-validate-someone-elses-values")
    assert "lab_hal" in body and f"collect it as student '{STUDENT}'" in body, body
    close_dialog(driver)
    in_panel(driver, "w.content.activeCellIndex = arguments[1];", params["index"] + 1)
    driver.execute_script("window.jupyterapp.commands.execute('notebook:delete-cell')")
    time.sleep(0.5)
    assert not any("lab_hal" in c["source"] for c in cells(driver))

    title, body = validate(driver)
    shot(driver, "student-8-validated")
    assert "judged when the assignment is graded" in body, (title, body)
    assert "Success! Your notebook passes all the tests." not in body, body
    close_dialog(driver)

    assignments_panel(driver)
    button_in(driver, "#fetched_assignments_list", "Submit").click()
    wait(
        lambda: any(
            "A" in e.text
            for e in driver.find_elements(By.CSS_SELECTOR, "#submitted_assignments_list .list_item")
        ),
        60,
        what="the submission to be listed",
    )
    shot(driver, "student-9-submitted")
    inbound = klass["exchange"] / COURSE_ID / "inbound"
    ours = [p for p in inbound.iterdir() if p.name.startswith(f"{STUDENT}+A+")]
    assert ours and all(p.stat().st_uid == account(STUDENT).pw_uid for p in ours)


# ---------------------------------------------------------------- the instructor
def formgrader(driver, lab, page=None):
    """Open formgrader from JupyterLab (Nbgrader > Formgrader) and switch into its frame;
    or, with ``page``, go to that page of formgrader (as its links do, in a page of its
    own: JupyterLab is not loaded again)."""
    from selenium.webdriver.common.by import By

    driver.switch_to.default_content()
    if page:
        driver.get(lab.url(page))
        wait(lambda: driver.execute_script("return document.readyState") == "complete", 60)
        time.sleep(1)
        return
    driver.get(lab.url("lab"))
    lab_ready(driver)
    dismiss_toasts(driver)
    click_menu(driver, "Nbgrader", "Formgrader")
    frame = wait(
        lambda: next(
            (f for f in driver.find_elements(By.CSS_SELECTOR, "iframe") if f.is_displayed()), None
        ),
        60,
        what="formgrader's frame",
    )
    driver.switch_to.frame(frame)
    wait(lambda: driver.execute_script("return document.readyState") == "complete", 60)
    time.sleep(1.5)


def grades(course):
    with open(course / "grades_A.csv") as fh:
        return {r["student"]: r for r in csv.DictReader(fh)}


def test_instructor_collects_grades_and_releases_feedback(
    klass, instructor_lab, student_lab, driver
):
    from selenium.webdriver.common.by import By

    course = klass["course"]
    # the student's JupyterLab stays open in its window (the student's tab); the
    # instructor works in a tab of their own
    student_window = None
    if driver.current_url.startswith(student_lab.url("lab").split("?")[0]):
        student_window = driver.current_window_handle
        driver.switch_to.new_window("tab")
    formgrader(driver, instructor_lab)
    shot(driver, "instructor-1-formgrader")
    click_in_row(driver, "A", "collect")
    modal, text = formgrader_modal(driver)
    shot(driver, "instructor-2-collected")
    assert "Successfully collected" in text, text
    close_modal(driver, modal)
    assert (course / "submitted" / STUDENT / "A" / "A.ipynb").exists()

    # the command line: accelab grade (sandbox, judge, gradebook, feedback, CSV)
    proc = accelab("grade", "--course", str(course), "--assignment", "A", cwd=course)
    assert "1 submission(s) graded" in proc.stdout, proc.stdout
    row = grades(course)[STUDENT]
    assert float(row["total"]) == float(row["max"]) > 0, row

    # formgrader's autograde button: the same judgement, through the sandbox
    formgrader(driver, instructor_lab, "formgrader/manage_submissions/A")
    shot(driver, "instructor-3-submissions")
    click_in_row(driver, STUDENT, "autograde")
    modal, text = formgrader_modal(driver)
    shot(driver, "instructor-4-autograded")
    assert "Successfully autograded" in text or "autograded" in text.lower(), text
    close_modal(driver, modal)
    driver.refresh()
    row = wait(
        lambda: next(
            (r for r in driver.find_elements(By.CSS_SELECTOR, "tbody tr") if STUDENT in r.text),
            None,
        ),
        60,
    )
    score = row.find_element(By.CSS_SELECTOR, "td.score").text
    assert score and score.split("/")[0].strip() == score.split("/")[1].strip(), score

    # the submission in formgrader: its equations typeset by the server's own MathJax
    from nbgrader.api import Gradebook

    with Gradebook("sqlite:///" + str(course / "gradebook.db"), COURSE_ID) as gb:
        submission = gb.find_submission_notebook("A", "A", STUDENT).id
    formgrader(driver, instructor_lab, f"formgrader/submissions/{submission}/")
    wait(
        lambda: driver.execute_script(
            "return !!(window.MathJax && MathJax.Hub) && "
            "document.querySelectorAll('.MathJax_CHTML, .MathJax, mjx-container').length > 0"
        ),
        90,
        what="MathJax to typeset the submission's equations (offline)",
    )
    sources = driver.execute_script(
        "return [...document.scripts].map(s => s.src).filter(s => s.includes('MathJax'))"
    )
    assert sources and all("/static/jupyter_server_mathjax/" in s for s in sources), sources
    driver.execute_script(
        "document.querySelector('.MathJax').scrollIntoView({block: 'center'}); "
        "window.scrollBy(0, 150);"
    )
    time.sleep(0.5)
    shot(driver, "instructor-5-formgrade-math")

    formgrader(driver, instructor_lab, "formgrader/manage_assignments")
    click_in_row(driver, "A", "generate-feedback")
    modal, text = formgrader_modal(driver)
    assert "Successfully generated feedback" in text, text
    close_modal(driver, modal)
    click_in_row(driver, "A", "release-feedback")
    modal, text = formgrader_modal(driver)
    shot(driver, "instructor-6-feedback-released")
    assert "Successfully released feedback" in text, text
    close_modal(driver, modal)
    driver.switch_to.default_content()

    # the student fetches the feedback from the Assignments panel (back in the student's
    # tab, or the student's JupyterLab opened when this test runs alone)
    if student_window:
        driver.switch_to.window(student_window)
    else:
        driver.get(student_lab.url("lab"))
        lab_ready(driver)
        dismiss_toasts(driver)
    assignments_panel(driver)
    button_in(driver, "#submitted_assignments_list", "Fetch Feedback").click()
    feedback = klass["home"] / "A" / "feedback"
    pages = wait(
        lambda: list(feedback.rglob("A.html")) if feedback.exists() else None,
        60,
        what="the feedback to be fetched",
    )
    text = pages[0].read_text()
    assert f"Graded against the values of student {STUDENT}" in text
    time.sleep(1)
    shot(driver, "student-10-feedback-fetched")

    # a resubmission: the documented collect command (--update) picks it up
    before = (course / "submitted" / STUDENT / "A" / "timestamp.txt").read_text()
    inbound = klass["exchange"] / COURSE_ID / "inbound"
    sent = {p.name for p in inbound.iterdir()}
    time.sleep(1.1)  # a new timestamp: nbgrader's are to the second
    button_in(driver, "#fetched_assignments_list", "Submit").click()
    # the exchange has it once its folder is in the inbound and its timestamp written
    wait(
        lambda: any(
            p.name.startswith(f"{STUDENT}+A+")
            and (p / "timestamp.txt").is_file()
            and (p / "timestamp.txt").read_text().strip()
            for p in inbound.iterdir()
            if p.name not in sent
        ),
        60,
        what="the resubmission to reach the exchange",
    )
    nbgrader("collect", "--update", "A", cwd=course)
    after = (course / "submitted" / STUDENT / "A" / "timestamp.txt").read_text()
    assert after != before, "nbgrader collect --update did not pick up the resubmission"
