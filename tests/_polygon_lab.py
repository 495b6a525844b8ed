"""JupyterLab in headless Chromium, for the polygon builder's browser tests.

:func:`lab` starts a JupyterLab server on a free port in a folder (the app is
exposed to the page, so a test can run JupyterLab commands such as
``notebook:run-all-cells`` and ``docmanager:save``); :func:`browser` opens
Debian's Chromium through its chromedriver at a window width (a phone's 390 px
by device emulation). Both end what they started.
"""

import contextlib
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time

from _lab import shm_flags

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"


def missing():
    """Why the browser tests cannot run here, or None."""
    if not (shutil.which("chromium") or os.path.exists(CHROMIUM)):
        return "chromium is not installed (apt-get install chromium chromium-driver)"
    if not (shutil.which("chromedriver") or os.path.exists(CHROMEDRIVER)):
        return "chromedriver is not installed (apt-get install chromium-driver)"
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "selenium is not installed (pip install -e '.[test]')"
    try:
        import jupyterlab  # noqa: F401
    except ImportError:
        return "jupyterlab is not installed"
    return None


def _free_port():
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


@contextlib.contextmanager
def lab(folder, env=None):
    """A JupyterLab server on ``folder``; yields its base URL (with the token)."""
    port = _free_port()
    token = "accelab-polygon-test"
    bindir = os.path.dirname(sys.executable)
    run_env = dict(os.environ, **(env or {}))
    run_env["PATH"] = bindir + os.pathsep + run_env.get("PATH", "")
    run_env.pop("ACCELAB_STATIC", None)
    run_env.setdefault("MPLBACKEND", "Agg")
    home = tempfile.mkdtemp(prefix="accelab-lab-home-")
    run_env["JUPYTER_CONFIG_DIR"] = os.path.join(home, "config")
    run_env["JUPYTER_RUNTIME_DIR"] = os.path.join(home, "runtime")
    run_env["JUPYTERLAB_WORKSPACES_DIR"] = os.path.join(home, "workspaces")
    settings = os.path.join(home, "settings")
    run_env["JUPYTERLAB_SETTINGS_DIR"] = settings
    notify = os.path.join(settings, "@jupyterlab", "apputils-extension")
    os.makedirs(notify)
    with open(os.path.join(notify, "notification.jupyterlab-settings"), "w") as fh:
        fh.write('{"fetchNews": "false", "checkForUpdates": false}')
    log = open(os.path.join(home, "lab.log"), "w")
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "jupyterlab",
            "--no-browser",
            f"--port={port}",
            "--ServerApp.ip=127.0.0.1",
            f"--ServerApp.token={token}",
            f"--ServerApp.root_dir={folder}",
            "--allow-root",
            "--LabApp.expose_app_in_browser=True",
            "--LabApp.news_url=",
            "--ServerApp.disable_check_xsrf=True",
        ],
        stdout=log,
        stderr=subprocess.STDOUT,
        env=run_env,
        start_new_session=True,
        cwd=folder,
    )
    try:
        deadline = time.monotonic() + 90
        while time.monotonic() < deadline:
            try:
                socket.create_connection(("127.0.0.1", port), 1).close()
                break
            except OSError:
                if proc.poll() is not None:
                    raise RuntimeError(f"JupyterLab did not start; see {log.name}") from None
                time.sleep(0.3)
        yield f"http://127.0.0.1:{port}", token
    finally:
        try:
            os.killpg(proc.pid, 15)
            proc.wait(timeout=20)
        except (OSError, subprocess.TimeoutExpired):
            with contextlib.suppress(OSError):
                os.killpg(proc.pid, 9)
        log.close()
        shutil.rmtree(home, ignore_errors=True)


@contextlib.contextmanager
def browser(width=1366, height=1000):
    """Headless Chromium at ``width`` CSS px (a phone below 500 px)."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium") or CHROMIUM
    profile = tempfile.mkdtemp(prefix="accelab-polygon-chromium-")
    for flag in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        *shm_flags(),
        f"--window-size={max(width, 500)},{height}",
        f"--user-data-dir={profile}",
    ):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(
        options=options, service=Service(shutil.which("chromedriver") or CHROMEDRIVER)
    )
    driver.set_page_load_timeout(90)
    driver.set_script_timeout(180)
    driver._accelab_size = (width, height)
    if width < 500:
        resize(driver, width, height)
    try:
        yield driver
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def resize(driver, width=1366, height=1000):
    """Make the browser ``width`` CSS px wide (a phone below 500 px: its screen emulated,
    390 px at twice the pixels, with touch), as :func:`browser` opens it; the page shown
    takes the new size when it is loaded again."""
    if (width, height) == getattr(driver, "_accelab_size", None) and width >= 500:
        return
    driver.set_window_size(max(width, 500), height)
    if width < 500:
        driver.execute_cdp_cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": width, "height": 844, "deviceScaleFactor": 2, "mobile": True},
        )
        driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True})
    else:
        driver.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})
        driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": False})
    driver._accelab_size = (width, height)
    driver._accelab_resized = True  # the page shown is of the size before


def wait(driver, script, timeout=180, poll=0.25, what="the page"):
    """Run ``script`` (returns a value) until it is truthy; returns it."""
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        try:
            last = driver.execute_script(script)
        except Exception as exc:  # the page is still loading
            last = exc
        if last and not isinstance(last, Exception):
            return last
        time.sleep(poll)
    raise TimeoutError(f"waited {timeout} s for {what}; last: {last!r}")


#: JavaScript: close the documents the page shows (``arguments[1]``: only the notebook
#: ``arguments[0]``, and only if it is saved; else all, what they hold unsaved left behind as
#: a new page leaves it) and open ``arguments[0]`` as the file browser does; true when done
_OPEN_IN_PAGE = """
const done = arguments[arguments.length - 1];
const [path, again] = [arguments[0], arguments[1]];
const app = window.jupyterapp;
if (!app || !app.shell) { done(false); return; }
const docs = Array.from(app.shell.widgets('main')).filter((w) => w.context);
const mine = docs.filter((w) => w.context.path === path);
if (again && (!mine.length || mine.some((w) => w.context.model.dirty))) { done(false); return; }
const closing = again ? mine : docs;
for (const w of closing) { w.context.model.dirty = false; w.close(); }
const t0 = Date.now();
const opened = () => app.commands.execute('docmanager:open', {path})
  .then(() => done(true), () => done(false));
const closed = () => closing.every((w) => w.isDisposed) ? opened()
  : (Date.now() - t0 > 30000 ? done(false) : setTimeout(closed, 50));
closed();
"""


def open_notebook(driver, base, token, path, again=False, in_page=False):
    """Open ``path`` (relative to the server's folder) in JupyterLab, in a fresh
    workspace (nothing of an earlier session restored), and wait until its
    kernel is idle. JupyterLab is not loaded again when the page shows this server's
    JupyterLab at the browser's size: with ``again``, the notebook ``path``, saved, is
    closed and opened again as the file browser opens it; with ``in_page``, every
    document is closed (unsaved changes left behind, as a new page leaves them) and
    ``path`` opened so. Its kernel is its session's, as in a new page."""
    import uuid

    here = (
        (again or in_page)
        and not getattr(driver, "_accelab_resized", False)
        and driver.current_url.startswith(f"{base}/lab")
    )
    if not (here and driver.execute_async_script(_OPEN_IN_PAGE, path, again)):
        space = f"t{uuid.uuid4().hex[:10]}"
        driver.get(f"{base}/lab/workspaces/{space}/tree/{path}?token={token}&reset")
        driver._accelab_resized = False
    panel = (
        "(window.jupyterapp && Array.from(window.jupyterapp.shell.widgets('main'))"
        f".find((w) => w.sessionContext && w.context && w.context.path === {path!r}))"
    )
    wait(
        driver,
        f"const p = {panel}; return !!(p && p.sessionContext.session "
        "&& p.sessionContext.session.kernel);",
        what="the notebook and its kernel",
    )
    wait(
        driver,
        f"const k = {panel}.sessionContext.session.kernel;"
        "return k.status === 'idle' && k.connectionStatus === 'connected';",
        what="an idle kernel",
    )
    driver.execute_script(f"window.jupyterapp.shell.activateById({panel}.id);")
    if driver.execute_script("return window.innerWidth") < 700:
        # a phone: the notebook alone, as a student on one would set it (the side panels
        # closed, one document at a time)
        driver.execute_script(
            "const s = window.jupyterapp.shell; s.collapseLeft(); s.collapseRight();"
            "s.mode = 'single-document';"
        )
        time.sleep(0.5)


def command(driver, name, wait_for_it=True):
    """Run a JupyterLab command (e.g. ``docmanager:save``); ``wait_for_it=False``
    starts it and returns (``notebook:run-all-cells`` resolves only when every cell ran)."""
    if not wait_for_it:
        driver.execute_script("window.jupyterapp.commands.execute(arguments[0]);", name)
        return
    driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "window.jupyterapp.commands.execute(arguments[0]).then(() => done(true),"
        " (e) => done(String(e)));",
        name,
    )


def console_errors(driver):
    """The page's SEVERE console messages."""
    try:
        return [e["message"] for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
    except Exception:
        return []


# ---------------------------------------------------------------- driving the builder
BUILDER = "[data-testid=polygon-builder]"


def find(driver, testid, root=None):
    from selenium.webdriver.common.by import By

    scope = root or driver.find_element(By.CSS_SELECTOR, BUILDER)
    if testid == "polygon-builder":
        return scope
    return scope.find_element(By.CSS_SELECTOR, f"[data-testid='{testid}']")


def click(driver, testid, root=None):
    el = find(driver, testid, root)
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", el)
    el.click()


def choose(driver, testid, value, root=None):
    from selenium.webdriver.support.ui import Select

    Select(find(driver, testid, root)).select_by_value(value)


def choose_text(driver, testid, text, root=None):
    from selenium.webdriver.support.ui import Select

    Select(find(driver, testid, root)).select_by_visible_text(text)


def type_into(driver, testid, text, root=None):
    el = find(driver, testid, root)
    el.clear()
    el.send_keys(str(text))


def screen(driver, z, root=None):
    """Offset from the canvas's centre [CSS px] of the polygon point z [SI]."""
    import json

    canvas = find(driver, "canvas", root)
    view = json.loads(canvas.get_attribute("data-view"))
    rect = driver.execute_script(
        "const r = arguments[0].getBoundingClientRect(); return [r.width, r.height];", canvas
    )
    x = (z.real * view["factor"] - view["cx"]) * view["z"]
    y = -(z.imag * view["factor"] - view["cy"]) * view["z"]
    assert abs(x) < rect[0] / 2 and abs(y) < rect[1] / 2, f"{z} is off the canvas"
    return round(x), round(y)


def drag(driver, a, b, touch=False, root=None, steps=6):
    """Press at the polygon point a [SI], move to b, release: a real pointer
    (mouse, or a finger with ``touch``)."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.actions import interaction
    from selenium.webdriver.common.actions.action_builder import ActionBuilder
    from selenium.webdriver.common.actions.pointer_input import PointerInput

    canvas = find(driver, "canvas", root)
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
    (ax, ay), (bx, by) = screen(driver, a, root), screen(driver, b, root)
    if touch:
        finger = PointerInput(interaction.POINTER_TOUCH, "finger")
        actions = ActionBuilder(driver, mouse=finger)
        actions.pointer_action.move_to(canvas, ax, ay).pointer_down()
        for k in range(1, steps + 1):
            actions.pointer_action.move_to(
                canvas, ax + (bx - ax) * k // steps, ay + (by - ay) * k // steps
            )
        actions.pointer_action.pointer_up()
        actions.perform()
        return
    chain = ActionChains(driver, duration=20).move_to_element_with_offset(canvas, ax, ay)
    chain.click_and_hold()
    for k in range(1, steps + 1):
        chain.move_to_element_with_offset(
            canvas, ax + (bx - ax) * k // steps, ay + (by - ay) * k // steps
        )
    chain.release().perform()


def tap(driver, z, touch=False, root=None):
    drag(driver, z, z, touch=touch, root=root, steps=1)


def message(driver, root=None):
    el = find(driver, "message", root)
    return el.get_attribute("class"), el.text


def steps_count(driver, root=None):
    from selenium.webdriver.common.by import By

    return len(find(driver, "steps", root).find_elements(By.CSS_SELECTOR, "li"))


def wait_steps(driver, n, root=None, timeout=30):
    """Wait until the step list shows n steps and the last one is judged."""
    import time

    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if steps_count(driver, root) == n:
            time.sleep(0.3)
            return
        time.sleep(0.1)
    raise TimeoutError(f"the builder did not show {n} steps (shows {steps_count(driver, root)})")
