"""What the browser tests of the real path share: headless Chromium with a screenshot
of each step (``build/screenshots/``), local accounts, a virtual environment other
accounts can run (root's Python is out of their reach), JupyterLab servers started
as one account or another, and the moves a person makes in JupyterLab.

JupyterLab runs with ``expose_app_in_browser`` so that a test can wait for the
kernel and find cells; what a person does (open a file, Run All, move a slider,
type an answer, press Validate, Fetch, Submit) is done with clicks and keys.
"""

import contextlib
import fcntl
import hashlib
import json
import os
import pwd
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BUILD = ROOT / "build"
SHOTS = BUILD / "screenshots"
CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"


def _reachable(path):
    """True when every folder above ``path`` lets other accounts through."""
    return all(p.stat().st_mode & 0o001 for p in Path(path).resolve().parents)


#: where the files other accounts use live (their environment, the class's exchange and
#: configuration): build/ when other accounts can reach it, else a folder of /var/tmp
SHARED = BUILD if _reachable(BUILD) else Path("/var/tmp/accelab-lab")
#: the environment other accounts run: Debian's python3, this environment's packages
SHARED_VENV = SHARED / "lab-venv"
#: what the browser tests need in it besides accelab's dependencies (the test extra's)
SHARED_EXTRAS = ("ipywidgets", "jupyterhub")
LAPTOP = (1366, 768)
NARROW = (700, 900)


# ---------------------------------------------------------------- preconditions
def need_browser():
    """Skip unless headless Chromium, its driver and selenium are there."""
    if not (os.path.exists(CHROMIUM) and os.path.exists(DRIVER)):
        pytest.skip("chromium and chromium-driver are not installed (apt-get install them)")
    pytest.importorskip("selenium.webdriver", reason="selenium is not installed")


def need_accounts():
    """Skip unless this test may create local accounts (root, useradd, Debian's python3)."""
    if os.geteuid() != 0 or not shutil.which("useradd"):
        pytest.skip("creating local accounts needs root and useradd")
    if not os.path.exists("/usr/bin/python3"):
        pytest.skip("the other accounts' environment needs Debian's python3")
    probe = subprocess.run(
        ["/usr/bin/python3", "-c", "import venv, ensurepip"], capture_output=True
    )
    if probe.returncode != 0:
        pytest.skip("Debian's python3 has no venv module: apt-get install python3-venv")


# ---------------------------------------------------------------- browser
def shm_flags():
    """``--disable-dev-shm-usage`` where /dev/shm is small (a container's 64 MB): Chromium
    then keeps its shared memory in files under /tmp, on disk. Where /dev/shm is large
    enough, as on a machine of its own, it stays in memory (measured on the course's Lab
    test, five runs each: 31.7 busy cpu-s with the flag, 28.8 without)."""
    try:
        st = os.statvfs("/dev/shm")
    except OSError:
        return ["--disable-dev-shm-usage"]
    return [] if st.f_bavail * st.f_frsize >= 1 << 30 else ["--disable-dev-shm-usage"]


def browser(size=LAPTOP):
    """A headless Chromium window of ``size`` (width, height) px."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    profile = tempfile.mkdtemp(prefix="accelab-lab-chromium-")
    for flag in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        *shm_flags(),
        "--hide-scrollbars",
        "--force-device-scale-factor=1",
        f"--window-size={size[0]},{size[1]}",
        f"--user-data-dir={profile}",
    ):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(options=options, service=Service(DRIVER))
    driver.set_page_load_timeout(90)
    driver.set_script_timeout(180)
    driver._accelab_profile = profile
    return driver


def close(driver):
    with contextlib.suppress(Exception):
        driver.quit()
    shutil.rmtree(getattr(driver, "_accelab_profile", ""), ignore_errors=True)


def shot(driver, name, size=None):
    """Save a screenshot ``build/screenshots/<name>.png`` (at ``size``, if given, then
    back); returns its path."""
    SHOTS.mkdir(parents=True, exist_ok=True)
    before = driver.get_window_size() if size else None
    if size:
        driver.set_window_size(*size)
        time.sleep(0.8)  # JupyterLab lays itself out again
    path = SHOTS / f"{name}.png"
    driver.save_screenshot(str(path))
    if before:
        driver.set_window_size(before["width"], before["height"])
        time.sleep(0.5)
    return path


def wait(predicate, timeout=60, every=0.25, what="a condition"):
    """Poll ``predicate`` until it returns something true; that value, or AssertionError."""
    end = time.monotonic() + timeout
    last = None
    while time.monotonic() < end:
        try:
            value = predicate()
        except Exception as exc:  # a page still loading
            last = exc
            value = None
        if value:
            return value
        time.sleep(every)
    raise AssertionError(f"timed out after {timeout} s waiting for {what} (last error: {last})")


# ---------------------------------------------------------------- accounts
def account(name):
    """The local account ``name`` (created, with a home, if it is not there)."""
    try:
        return pwd.getpwnam(name)
    except KeyError:
        subprocess.run(["useradd", "-m", "-s", "/bin/bash", name], check=True)
        return pwd.getpwnam(name)


def as_account(name, env_extra=None):
    """``(Popen keyword arguments, environment)`` to run a process as ``name``."""
    user = pwd.getpwnam(name)
    env = {
        "HOME": user.pw_dir,
        "USER": name,
        "LOGNAME": name,
        "SHELL": "/bin/bash",
        "LANG": "C.UTF-8",
        "PATH": f"{SHARED_VENV}/bin:/usr/bin:/bin",
        "MPLBACKEND": "module://matplotlib_inline.backend_inline",
    }
    env.update(env_extra or {})
    kw = {"user": user.pw_uid, "group": user.pw_gid, "extra_groups": [], "cwd": user.pw_dir}
    return kw, env


def run_as(name, args, env_extra=None, check=True, cwd=None):
    """Run ``args`` as the account ``name``; the CompletedProcess."""
    kw, env = as_account(name, env_extra)
    if cwd:
        kw["cwd"] = cwd
    proc = subprocess.run(args, env=env, capture_output=True, text=True, **kw)
    if check:
        assert proc.returncode == 0, (args, proc.stdout[-2000:], proc.stderr[-3000:])
    return proc


# ---------------------------------------------------------------- the shared environment
#: what a clean copy of the checkout leaves out when the wheel is built from it
NOT_SOURCE = (
    ".venv",
    "build",
    ".git",
    "*.egg-info",
    "__pycache__",
    ".pytest_cache",
    ".mypy_cache",
    ".ruff_cache",
    ".hypothesis",
)
#: folders of the copy that do not go into the wheel (a change there installs nothing anew)
NOT_PACKAGED = ("tests", "docs")

_venv_ready = []


def _source_digest(source):
    """A digest of the path and content of every file of ``source`` that can go into the
    wheel."""
    digest = hashlib.sha256()
    for path in sorted(p for p in Path(source).rglob("*") if p.is_file()):
        rel = path.relative_to(source)
        if rel.parts[0] not in NOT_PACKAGED:
            digest.update(str(rel).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()[:16]


def _pip(argv, what):
    """Run ``argv`` (a pip command); on failure, an AssertionError that shows pip's
    output (its error is on stdout or stderr, at the end)."""
    proc = subprocess.run(argv, capture_output=True, text=True)
    assert proc.returncode == 0, (
        f"{what} failed (exit {proc.returncode}): {' '.join(map(str, argv))}\n"
        f"{proc.stdout[-2000:]}\n{proc.stderr[-4000:]}"
    )


def shared_venv():
    """A venv of Debian's python3 in ``SHARED/lab-venv`` that every account can run,
    with accelab (built from this checkout as a wheel, so with its JupyterLab
    extension) and this environment's packages, the very same versions (ipywidgets and
    JupyterHub among them: the test extra has them): their files hard-linked from this
    environment (:mod:`_venv`), their console scripts and Jupyter's data files with
    them, nothing downloaded or resolved again. The packages are linked once (until this
    environment's change), accelab installed again when its source changed.

    The wheel is built from a private copy of the checkout, never in place: two
    in-place builds at once (test processes in parallel) share the checkout's build/
    and remove each other's files ("error: [Errno 2] No such file or directory"), and
    an old build/lib can leak stale modules into the wheel. Test processes take turns
    (a file lock): one makes the venv, the others find it made."""
    if _venv_ready:
        return SHARED_VENV
    SHARED.mkdir(parents=True, exist_ok=True)
    with open(SHARED / ".lab-venv.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        _make_shared_venv()
    os.chmod(SHARED, 0o755)
    _venv_ready.append(True)
    return SHARED_VENV


def _make_shared_venv():
    import _venv

    packages = _venv.packages()
    missing = [
        name
        for name in SHARED_EXTRAS
        if not any(p.lower().startswith(name + "-") for p in packages)
    ]
    assert not missing, f"{missing} not installed: pip install -e '.[test]'"
    linked = packages + _venv.tests_only()  # a venv made before the start-up file is made again
    stamp = SHARED_VENV / f".deps-{hashlib.sha256(' '.join(linked).encode()).hexdigest()[:16]}"
    py = SHARED_VENV / "bin" / "python"
    with tempfile.TemporaryDirectory(prefix="accelab-lab-wheel-") as work:
        source, dist = Path(work) / "source", Path(work) / "dist"
        shutil.copytree(ROOT, source, ignore=shutil.ignore_patterns(*NOT_SOURCE), symlinks=True)
        built = SHARED_VENV / f".accelab-{_source_digest(source)}"
        if stamp.exists() and built.exists():
            return  # made from this source, with these packages
        # offline, with this environment's setuptools (the test extra has it)
        _pip(
            [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q"]
            + ["-w", str(dist), str(source)],
            "building accelab's wheel",
        )
        wheel = next(dist.glob("accelab-*.whl"))
        if not stamp.exists():
            shutil.rmtree(SHARED_VENV, ignore_errors=True)
            _venv.linked_venv(SHARED_VENV, "/usr/bin/python3", data=True, as_tests_run=True)
        # with the pip this environment has (linked with the rest), offline
        _pip(
            [str(py), "-m", "pip", "install", "-q", "--no-deps", "--no-index", "--force-reinstall"]
            + [str(wheel)],
            "installing accelab into the shared venv",
        )
        stamp.write_text("\n".join(packages) + "\n")
        for old in SHARED_VENV.glob(".accelab-*"):
            old.unlink()
        built.write_text(wheel.name)


# ---------------------------------------------------------------- servers
def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def http_ok(url):
    try:
        with urllib.request.urlopen(url, timeout=5) as r:
            return 200 <= r.status < 400
    except Exception:
        return False


#: what the tests add to every JupyterLab's page configuration: no check, at each page load,
#: whether JupyterLab's assets need a build (a node process and ~0.4 cpu-s of the server's
#: each time; the environments' JupyterLab is built, nothing of the tests builds it)
TEST_PAGE_CONFIG = {"buildCheck": False, "buildAvailable": False}


def extra_config_dir():
    """A Jupyter configuration folder, readable by every account, that holds the tests'
    page configuration (:data:`TEST_PAGE_CONFIG`); last on a server's JUPYTER_CONFIG_PATH,
    its keys merge with the role's (the guide's ``disabledExtensions`` stay as they are)."""
    folder = SHARED / "lab-test-config"
    page = folder / "labconfig" / "page_config.json"
    if not page.exists() or json.loads(page.read_text()) != TEST_PAGE_CONFIG:
        page.parent.mkdir(parents=True, exist_ok=True)
        part = page.with_name(f".page_config.{os.getpid()}.json")
        part.write_text(json.dumps(TEST_PAGE_CONFIG))
        part.replace(page)
        for path in (SHARED, folder, page.parent):
            path.chmod(0o755)
        page.chmod(0o644)
    return folder


class Lab:
    """A JupyterLab server (``jupyter lab``) of ``user`` (None: this process's account
    and environment) serving ``root_dir``, started by the test.

    Its workspaces (the layout JupyterLab restores: which documents are open) are the
    server's own, in a fresh folder: a page never restores what another test, or an
    earlier run as the same account, left open (a notebook started a kernel, formgrader
    loaded in its frame, before the test did anything)."""

    def __init__(self, root_dir, user=None, config_dirs=(), env_extra=None, log_name="lab"):
        self.root_dir = str(root_dir)
        self.user = user
        self.port = free_port()
        self.token = secrets.token_hex(16)
        self.log_path = BUILD / "screenshots" / f"{log_name}.log"
        self.log_path.parent.mkdir(parents=True, exist_ok=True)
        self.workspaces = Path(tempfile.mkdtemp(prefix="accelab-lab-workspaces-"))
        if user:
            os.chown(self.workspaces, pwd.getpwnam(user).pw_uid, pwd.getpwnam(user).pw_gid)
        extra = {"JUPYTERLAB_WORKSPACES_DIR": str(self.workspaces)}
        extra.update(env_extra or {})
        extra["JUPYTER_CONFIG_PATH"] = os.pathsep.join(
            [str(d) for d in config_dirs] + [str(extra_config_dir())]
        )
        if user:
            self.kw, self.env = as_account(user, extra)
            jupyter = str(SHARED_VENV / "bin" / "jupyter")
        else:
            self.kw = {}
            self.env = dict(os.environ)
            self.env.pop("JUPYTERHUB_USER", None)
            self.env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
            self.env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + self.env["PATH"]
            self.env.update(extra)
            jupyter = os.path.join(os.path.dirname(sys.executable), "jupyter")
        self.env.pop("ACCELAB_STATIC", None)
        self.args = [
            jupyter,
            "lab",
            "--no-browser",
            "--ip=127.0.0.1",
            f"--port={self.port}",
            f"--ServerApp.token={self.token}",
            f"--ServerApp.root_dir={self.root_dir}",
            "--LabApp.expose_app_in_browser=True",
            "--ServerApp.open_browser=False",
        ]
        if not user and os.geteuid() == 0:
            self.args.append("--allow-root")
        self.proc = None

    def start(self, timeout=120):
        kw = dict(self.kw)
        kw["cwd"] = self.root_dir
        self._log = open(self.log_path, "w")
        self.proc = subprocess.Popen(
            self.args, env=self.env, stdout=self._log, stderr=subprocess.STDOUT, **kw
        )
        wait(
            lambda: self.proc.poll() is None and http_ok(self.url("api/status")),
            timeout,
            what=f"JupyterLab of {self.user or 'root'} (log: {self.log_path})",
        )
        return self

    def url(self, path="lab"):
        return f"http://127.0.0.1:{self.port}/{path}?token={self.token}"

    def stop(self):
        if self.proc and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(20)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(10)
        if self.proc:
            self._log.close()
        shutil.rmtree(self.workspaces, ignore_errors=True)


# ---------------------------------------------------------------- JupyterLab moves
def lab_ready(driver, timeout=120):
    """Wait until JupyterLab has started (its app is exposed and restored)."""
    wait(
        lambda: driver.execute_script(
            "return !!(window.jupyterapp && window.jupyterapp.shell && "
            "document.querySelector('#jp-main-dock-panel'))"
        ),
        timeout,
        what="JupyterLab to start",
    )
    driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "window.jupyterapp.restored.then(() => done(true));"
    )


#: JavaScript: ``w``, the panel of the file last opened (``arguments[0]``: its path)
PANEL = (
    "const w = [...window.jupyterapp.shell.widgets('main')]"
    ".find(w => w.context && w.context.path === arguments[0]);"
)


def in_panel(driver, body, *args):
    return driver.execute_script(PANEL + body, getattr(driver, "_accelab_path", ""), *args)


def open_path(driver, lab, path):
    """Open ``path`` (relative to the server's root) in JupyterLab: in the JupyterLab of
    ``lab`` the page shows, as its file browser does (JupyterLab's ``docmanager:open``:
    a document already open is brought to the front, as it is); else as a link does (the
    page loaded with the path)."""
    here = lab.url("lab").split("?")[0]
    if driver.current_url.startswith(here) and driver.execute_script(
        "return !!(window.jupyterapp && window.jupyterapp.shell)"
    ):
        lab_ready(driver)
        command(driver, "docmanager:open", {"path": path})
    else:
        driver.get(lab.url(f"lab/tree/{path}"))
        lab_ready(driver)
    driver._accelab_path = path
    wait(
        lambda: in_panel(
            driver,
            "return !!(w && w.sessionContext && w.sessionContext.session && "
            "w.sessionContext.session.kernel && w.content.widgets.length)",
        ),
        120,
        what=f"{path} to open with a kernel",
    )
    dismiss_toasts(driver)


def dismiss_toasts(driver):
    """Close JupyterLab's notifications (the news question), as a person would."""
    from selenium.webdriver.common.by import By

    for button in driver.find_elements(
        By.CSS_SELECTOR, ".jp-toast-button, .Toastify__close-button"
    ):
        if button.text.strip() in ("No", "") and button.is_displayed():
            with contextlib.suppress(Exception):
                button.click()


def kernel_idle(driver):
    """True when the current notebook's kernel is idle and no cell waits to run."""
    return in_panel(
        driver,
        "if (!w || !w.sessionContext || !w.sessionContext.session) return false;"
        "const k = w.sessionContext.session.kernel;"
        "if (!k || k.status !== 'idle') return false;"
        "const prompts = [...w.node.querySelectorAll('.jp-InputPrompt')].map(p => p.textContent);"
        "return !prompts.some(t => t.includes('*'));",
    )


def wait_idle(driver, timeout=300):
    time.sleep(0.5)
    wait(lambda: kernel_idle(driver), timeout, every=0.5, what="the kernel to finish")


def command(driver, name, args=None):
    """Run a JupyterLab command (as its menu item or shortcut does)."""
    driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "window.jupyterapp.commands.execute(arguments[0], arguments[1] || {})"
        ".then(() => done(true), e => done(String(e)));",
        name,
        args,
    )


def click_menu(driver, *labels):
    """Click a path of the main menu, e.g. ``click_menu(d, "Run", "Run All Cells")``."""
    from selenium.webdriver.common.by import By

    top = wait(
        lambda: next(
            (
                e
                for e in driver.find_elements(By.CSS_SELECTOR, ".lm-MenuBar-itemLabel")
                if e.text.strip() == labels[0]
            ),
            None,
        ),
        30,
        what=f"the menu {labels[0]}",
    )
    top.click()
    for label in labels[1:]:
        item = wait(
            lambda label=label: next(
                (
                    e
                    for e in driver.find_elements(By.CSS_SELECTOR, ".lm-Menu-itemLabel")
                    if e.text.strip() == label and e.is_displayed()
                ),
                None,
            ),
            30,
            what=f"the menu item {label}",
        )
        item.click()


def menu_labels(driver, top):
    """The item labels of the main menu ``top`` (opened, read, closed)."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    found = [
        e
        for e in driver.find_elements(By.CSS_SELECTOR, ".lm-MenuBar-itemLabel")
        if e.text.strip() == top
    ]
    if not found:
        return None
    found[0].click()
    time.sleep(0.5)
    labels = [
        e.text.strip()
        for e in driver.find_elements(By.CSS_SELECTOR, ".lm-Menu-itemLabel")
        if e.is_displayed() and e.text.strip()
    ]
    driver.switch_to.active_element.send_keys(Keys.ESCAPE)
    return labels


def cells(driver):
    """The current notebook's cells as dicts: type, source, and the text (stdout, plain
    text and Markdown), errors (tracebacks and stderr) and images of their outputs, read
    from the notebook's model (JupyterLab does not keep cells out of view in the page)."""
    return in_panel(
        driver,
        """
        const text = v => Array.isArray(v) ? v.join('') : (v || '');
        return w.content.widgets.map((c, i) => {
          const outs = (c.model.type === 'code' && c.model.outputs) ? c.model.outputs.toJSON() : [];
          return {
            index: i,
            type: c.model.type,
            source: c.model.sharedModel.getSource(),
            text: outs.map(o => o.output_type === 'stream' ? text(o.text) :
                    o.output_type === 'error' ? o.ename + ': ' + o.evalue :
                    text((o.data || {})['text/markdown'] || (o.data || {})['text/plain']))
                  .join('\\n'),
            errors: outs.filter(o => o.output_type === 'error' ||
                                    (o.output_type === 'stream' && o.name === 'stderr'))
                        .map(o => o.output_type === 'error'
                                  ? o.ename + ': ' + o.evalue : text(o.text)),
            images: outs.filter(o => o.data && o.data['image/png'])
                        .map(o => text(o.data['image/png']).length),
          };
        });
        """,
    )


def tracebacks(driver):
    """Cells whose output is an error (a traceback), as (index, first lines)."""
    return [(c["index"], "\n".join(c["errors"])[:600]) for c in cells(driver) if c["errors"]]


def cell_node(driver, index):
    """The page element of cell ``index``, scrolled into view (JupyterLab attaches only
    the cells in view)."""
    driver.execute_async_script(
        PANEL + "const done = arguments[arguments.length - 1];"
        "Promise.resolve(w.content.scrollToItem(arguments[1], 'center'))"
        ".then(() => setTimeout(() => done(true), 300));",
        getattr(driver, "_accelab_path", ""),
        index,
    )
    return in_panel(driver, "return w.content.widgets[arguments[1]].node", index)


def scroll_to(driver, element, block="center"):
    driver.execute_script("arguments[0].scrollIntoView({block: arguments[1]});", element, block)
    time.sleep(0.3)


def type_into_cell(driver, index, text, run=True):
    """Click into code cell ``index``, replace its text by typing ``text`` as a person
    does (select all, type), and run it with Shift+Enter."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    node = cell_node(driver, index)
    scroll_to(driver, node)
    editor = node.find_element(By.CSS_SELECTOR, ".cm-content")
    editor.click()
    ActionChains(driver).key_down(Keys.CONTROL).send_keys("a").key_up(Keys.CONTROL).perform()
    editor.send_keys(Keys.DELETE)
    for line_no, line in enumerate(text.split("\n")):
        if line_no:
            editor.send_keys(Keys.ENTER)
            # the editor indents after a colon; a line typed starts at column 0 here
            ActionChains(driver).key_down(Keys.SHIFT).send_keys(Keys.HOME).key_up(
                Keys.SHIFT
            ).send_keys(Keys.DELETE).perform()
        editor.send_keys(line)
    typed = in_panel(
        driver, "return w.content.widgets[arguments[1]].model.sharedModel.getSource()", index
    )
    assert typed == text, f"typed {text!r}, the cell holds {typed!r}"
    if run:
        ActionChains(driver).key_down(Keys.SHIFT).send_keys(Keys.ENTER).key_up(Keys.SHIFT).perform()


def json_of(driver, lab, api_path):
    """GET a JSON API of the server (as the page, with its token)."""
    with urllib.request.urlopen(lab.url(api_path), timeout=30) as r:
        return json.loads(r.read())


# ---------------------------------------------------------------- nbgrader's pages
def assignments_panel(driver):
    """Open nbgrader's Assignments panel (Nbgrader > Assignment List) and wait for it."""
    from selenium.webdriver.common.by import By

    click_menu(driver, "Nbgrader", "Assignment List")
    wait(
        lambda: (
            driver.find_elements(By.CSS_SELECTOR, "#released_assignments_list")
            and not any(
                e.is_displayed()
                for e in driver.find_elements(By.CSS_SELECTOR, ".list_loading")
                if e.get_attribute("hidden") is None
            )
        ),
        60,
        what="the Assignments panel",
    )
    time.sleep(1)


def button_in(driver, selector, label, timeout=60):
    """The button labelled ``label`` in the element ``selector`` (waited for)."""
    from selenium.webdriver.common.by import By

    return wait(
        lambda: next(
            (
                b
                for b in driver.find_elements(By.CSS_SELECTOR, f"{selector} button")
                if b.text.strip() == label and b.is_displayed() and b.is_enabled()
            ),
            None,
        ),
        timeout,
        what=f"the button {label!r} in {selector}",
    )


def dialog_text(driver, timeout=300):
    """The text of JupyterLab's dialog once it is there; (title, body)."""
    from selenium.webdriver.common.by import By

    box = wait(
        lambda: next(iter(driver.find_elements(By.CSS_SELECTOR, ".jp-Dialog-content")), None),
        timeout,
        every=0.5,
        what="a dialog",
    )
    time.sleep(0.5)
    header = box.find_element(By.CSS_SELECTOR, ".jp-Dialog-header").text
    body = box.find_element(By.CSS_SELECTOR, ".jp-Dialog-body").text
    return header, body


def close_dialog(driver):
    from selenium.webdriver.common.by import By

    for b in driver.find_elements(By.CSS_SELECTOR, ".jp-Dialog-button"):
        if b.is_displayed():
            b.click()
            break
    wait(
        lambda: not driver.find_elements(By.CSS_SELECTOR, ".jp-Dialog-content"),
        30,
        what="the dialog to close",
    )


def formgrader_modal(driver, timeout=300):
    """The text of formgrader's modal once it says something; closed after reading."""
    from selenium.webdriver.common.by import By

    modal = wait(
        lambda: next(
            (m for m in driver.find_elements(By.CSS_SELECTOR, ".modal") if m.is_displayed()), None
        ),
        timeout,
        every=0.5,
        what="formgrader's message",
    )
    time.sleep(0.5)
    text = modal.text
    return modal, text


def close_modal(driver, modal):
    from selenium.webdriver.common.by import By

    for b in modal.find_elements(By.CSS_SELECTOR, ".modal-footer button"):
        if b.is_displayed():
            b.click()
            break
    time.sleep(1)


def click_in_row(driver, row_text, cell_class):
    """Click the link in column ``cell_class`` of the formgrader table row naming ``row_text``."""
    from selenium.webdriver.common.by import By

    row = wait(
        lambda: next(
            (r for r in driver.find_elements(By.CSS_SELECTOR, "tbody tr") if row_text in r.text),
            None,
        ),
        60,
        what=f"the row {row_text}",
    )
    link = wait(
        lambda: next(iter(row.find_elements(By.CSS_SELECTOR, f"td.{cell_class} a")), None),
        60,
        what=f"the {cell_class} button of {row_text}",
    )
    link.click()
