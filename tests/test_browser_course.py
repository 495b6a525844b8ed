"""The course as a student meets it: the notebooks written by ``accelab course``, opened
in JupyterLab in headless Chromium, run with Run All, their sliders moved to their ends
and a few steps between (each must redraw its figure, never show a traceback), and a
practice problem answered in its answers cell, which must check the problem shown above
it. Screenshots of each step are kept in ``build/screenshots/`` (at a laptop's size and
in a narrow window).

One notebook is driven by default (09, whose slider broke after Run All: its slider, and
its practice problem), to keep the suite's time; ``ACCELAB_BROWSER_ALL=1`` drives the
sliders of every notebook. Every control of every
notebook is also drawn over its whole range, without a browser, when the course tests
execute the notebooks (``tests/test_course.py``, ``kit.check_ranges``).
"""

import os
import re
import subprocess
import sys
import time

import pytest
from _lab import (
    LAPTOP,
    NARROW,
    Lab,
    browser,
    cell_node,
    cells,
    click_menu,
    close,
    in_panel,
    need_browser,
    open_path,
    scroll_to,
    shot,
    tracebacks,
    type_into_cell,
    wait,
    wait_idle,
)

import accelab.course

#: one worker: the module's JupyterLab (a module fixture) is started once
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("course-lab")]

DEFAULT = ("09_jerk",)
NOTEBOOKS = [p.stem for p in accelab.course.notebooks()]
DRIVEN = NOTEBOOKS if os.environ.get("ACCELAB_BROWSER_ALL") else list(DEFAULT)


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    need_browser()
    folder = tmp_path_factory.mktemp("my-course")
    subprocess.run(
        [sys.executable, "-m", "accelab", "course", "--out", str(folder), "--force"],
        check=True,
        capture_output=True,
    )
    server = Lab(folder, log_name="lab-course").start()
    yield server
    server.stop()


@pytest.fixture(scope="module")
def driver(lab):
    d = browser(LAPTOP)
    yield d
    close(d)


def run_all(driver):
    click_menu(driver, "Run", "Run All Cells")
    wait_idle(driver, timeout=300)


def interacts(driver):
    """The notebook's live explore() outputs (ipywidgets' interact boxes)."""
    return in_panel(driver, "return [...w.node.querySelectorAll('.widget-interact')]")


def figure_of(box):
    """(image signature, error text) of an explore() output."""
    from selenium.webdriver.common.by import By

    imgs = box.find_elements(By.CSS_SELECTOR, "img")
    errors = [
        e.text
        for e in box.find_elements(
            By.CSS_SELECTOR, '[data-mime-type="application/vnd.jupyter.stderr"]'
        )
    ]
    sig = ";".join(f"{len(i.get_attribute('src'))}:{i.get_attribute('src')[-80:]}" for i in imgs)
    text = box.text
    return sig, errors, text


def shown(readout):
    """A slider's readout as text with an ASCII minus."""
    return readout.text.strip().replace("\u2212", "-")


def move(driver, box, handle, keys, readout, expected=None):
    """Press ``keys`` on a slider's handle; wait for its readout to say ``expected`` (or
    to change) and the figure to be redrawn; (signature, errors, text, readout) after."""
    before = shown(readout)
    scroll_to(driver, handle)
    handle.click()
    for key in keys:
        handle.send_keys(key)
        time.sleep(0.15)
    wait(
        lambda: shown(readout) == expected if expected else shown(readout) != before,
        30,
        what=f"the slider to show {expected or 'another value'} (shows {readout.text!r})",
    )
    time.sleep(0.6)
    wait_idle(driver, timeout=60)
    time.sleep(0.4)
    return (*figure_of(box), shown(readout))


def _fmt(value, template):
    """The readout text of ``value`` in the style of ``template`` (int or one decimal...)."""
    if "." in template:
        decimals = len(template.split(".")[1])
        return f"{value:.{decimals}f}"
    return str(int(round(value)))


@pytest.mark.parametrize("stem", DRIVEN)
def test_every_slider_redraws_at_its_ends_after_run_all(lab, driver, stem):
    """Run All, then each slider of the notebook to its minimum, two steps above it, its
    maximum and two steps below it: each time the figure is redrawn and no output is
    an error."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    open_path(driver, lab, f"{stem}.ipynb")
    run_all(driver)
    assert not tracebacks(driver), tracebacks(driver)
    for c in cells(driver):  # each explore() cell in view, as a person scrolls to it
        if "\nexplore(" in "\n" + c["source"]:
            cell_node(driver, c["index"])
    boxes = interacts(driver)
    assert boxes, f"{stem}: no live slider (is ipywidgets installed in the kernel?)"
    for b, box in enumerate(boxes):
        scroll_to(driver, box, "start")
        shot(driver, f"course-{stem}-explore{b}-start")
        sliders = box.find_elements(By.CSS_SELECTOR, ".widget-slider")
        assert sliders
        for s, slider in enumerate(sliders):
            handle = slider.find_element(By.CSS_SELECTOR, ".noUi-handle")
            readout = slider.find_element(By.CSS_SELECTOR, ".widget-readout")
            lo = float(handle.get_attribute("aria-valuemin"))
            hi = float(handle.get_attribute("aria-valuemax"))
            start = shown(readout)
            seen = [figure_of(box)[0]]
            moves = [
                ([Keys.HOME], lo, "min"),
                ([Keys.ARROW_RIGHT, Keys.ARROW_RIGHT], None, "min+2"),
                ([Keys.END], hi, "max"),
                ([Keys.ARROW_LEFT, Keys.ARROW_LEFT], None, "max-2"),
            ]
            for keys, value, label in moves:
                expected = _fmt(value, start) if value is not None else None
                sig, errors, text, at = move(driver, box, handle, keys, readout, expected)
                assert not errors, f"{stem} slider {s} at {at}: {errors}"
                assert "Traceback" not in text and "Nothing to draw" not in text, (stem, at)
                assert sig, f"{stem} slider {s} at {at}: no figure"
                seen.append(sig)
                scroll_to(driver, box, "start")
                shot(driver, f"course-{stem}-explore{b}-slider{s}-{label}")
            assert len(set(seen)) > 2, f"{stem}: the figure did not change as the slider moved"
    assert not tracebacks(driver), tracebacks(driver)


def test_practice_checks_the_problem_shown_after_run_all(lab, driver):
    """After Run All (notebook 03's answers cell checked another problem than the one it
    showed), answer the problem shown: the right answer is accepted, a wrong one refused,
    and the screenshots show both at a laptop's size and in a narrow window."""
    from accelab.course.practice import practice

    stem = DEFAULT[0]
    open_path(driver, lab, f"{stem}.ipynb")
    fresh = next(c for c in cells(driver) if c["source"].startswith("mine = practice("))
    if not fresh["text"]:  # (the slider test ran it already in this session)
        run_all(driver)
    assert not tracebacks(driver), tracebacks(driver)
    all_cells = cells(driver)
    fresh = next(c for c in all_cells if c["source"].startswith("mine = practice("))
    family = re.match(r'mine = practice\("(\w+)"\)', fresh["source"]).group(1)
    seed = int(re.search(r"seed (\d+); not graded", fresh["text"]).group(1))
    answers = all_cells[fresh["index"] + 1]
    assert "mine.check(" in answers["source"]
    shown = practice(family, seed=seed, show=False)  # the problem the page shows
    name = next(iter(shown.asked))
    right = shown.reveal(name)
    unit = shown.asked[name].unit
    scroll_to(driver, cell_node(driver, fresh["index"]), "start")
    shot(driver, f"course-{stem}-practice-shown")
    type_into_cell(
        driver,
        answers["index"],
        f'mine.check("{name}", Q_({right.magnitude!r}, "{unit}"))\n'
        f'mine.check("{name}", Q_({-right.magnitude!r}, "{unit}"))',
    )
    wait_idle(driver)
    out = cells(driver)[answers["index"]]["text"]
    verdicts = [line for line in out.splitlines() if line.startswith(f"{name}: ")]
    assert len(verdicts) == 2, out
    assert verdicts[0].startswith(f"{name}: right ("), out
    assert not verdicts[1].startswith(f"{name}: right ("), out
    scroll_to(driver, cell_node(driver, answers["index"]))
    shot(driver, f"course-{stem}-practice-checked")
    shot(driver, f"course-{stem}-practice-checked-narrow", size=NARROW)
    assert not tracebacks(driver), tracebacks(driver)
