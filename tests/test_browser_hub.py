"""A class on JupyterHub, as docs/guide/deploy.md configures it: the guide's own hub
configuration and each role's configuration folder (read from the guide, its folders and
names replaced by the test's: :mod:`_guide`), JupyterHub (from PyPI) with its proxy
(configurable-http-proxy, from npm), local system accounts created by the test (two
students and an instructor), each user's server started as that account from an
environment every account can run, nbgrader's JupyterHub authentication with the course's
groups, the students' servers without the instructor's menus. The class's folder is made
as the guide says (root makes it, the instructor's ``accelab assign --exchange`` lays out
the course and the exchange in it).

Each person logs in through the hub's login page in headless Chromium. The students
fetch the assignment from the Assignments panel (its notebook shows each one's own
values: the JupyterHub user) and submit as themselves; one tries to submit as the other,
which the hub refuses, then again with the hub's check turned off: collect goes by the
folder's owner, so it is his own submission, hers is untouched and the instructor is
told. The instructor collects with formgrader and grades with ``accelab grade``.
Screenshots in ``build/screenshots/hub-*``.
"""

import csv
import os
import secrets
import shutil
import subprocess
import time
from pathlib import Path

import _guide as guide
import pytest
from _lab import (
    BUILD,
    LAPTOP,
    SHARED,
    account,
    assignments_panel,
    browser,
    button_in,
    cells,
    click_in_row,
    click_menu,
    close,
    dismiss_toasts,
    extra_config_dir,
    formgrader_modal,
    free_port,
    http_ok,
    in_panel,
    lab_ready,
    menu_labels,
    need_accounts,
    need_browser,
    open_path,
    run_as,
    shared_venv,
    shot,
    tracebacks,
    type_into_cell,
    wait,
    wait_idle,
)

pytestmark = pytest.mark.slow

#: the guide's people (ann and hal study, prof teaches) as the test's accounts
PEOPLE = {"ann": "hub_ann", "hal": "hub_hal", "prof": "hub_prof"}
STUDENTS = (PEOPLE["ann"], PEOPLE["hal"])
INSTRUCTOR = PEOPLE["prof"]
COURSE_ID = "mech101"
HUB = SHARED / "hub-class"
#: the guide's /srv/mech101: the class's folder, the instructor's (course/ and exchange/)
CLASS_DIR = HUB / "srv-mech101"
PASSWORD = secrets.token_hex(8)

#: what the test adds to the guide's hub configuration: where it listens and keeps its
#: files, one password for everyone in place of PAM (the accounts have none), the page's
#: app exposed for the test to read, the tests' page configuration (no build check at each
#: page load: tests/_lab.py), and patience on a loaded machine
TEST_ONLY = """
# ---- added by tests/test_browser_hub.py to the guide's configuration above
c.JupyterHub.ip = "127.0.0.1"
c.JupyterHub.port = {port}
c.JupyterHub.hub_port = {hub_port}
c.ConfigurableHTTPProxy.api_url = "http://127.0.0.1:{proxy_port}"
c.JupyterHub.db_url = "sqlite:///{folder}/jupyterhub.sqlite"
c.JupyterHub.cookie_secret_file = "{folder}/jupyterhub_cookie_secret"
c.ConfigurableHTTPProxy.pid_file = "{folder}/proxy.pid"
c.JupyterHub.authenticator_class = "dummy"
c.DummyAuthenticator.password = {password!r}
c.Spawner.args = ["--LabApp.expose_app_in_browser=True"]
# the tests' page configuration after the role's (tests/_lab.py: no build check at each load)
_role_config = c.Spawner.environment["JUPYTER_CONFIG_PATH"]
c.Spawner.environment["JUPYTER_CONFIG_PATH"] = lambda spawner: (
    _role_config(spawner) + ":{extra_config}"
)
c.Spawner.start_timeout = 120
c.Spawner.http_timeout = 120
"""


def need_proxy():
    if not shutil.which("configurable-http-proxy"):
        message = "JupyterHub's proxy is missing: npm install -g configurable-http-proxy"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)


class Hub:
    """A JupyterHub started by the test (as root), and the address of each user's server."""

    def __init__(self, folder, venv, port):
        self.folder, self.venv, self.port = folder, venv, port
        self.log_path = BUILD / "screenshots" / "hub.log"
        self.proc = None

    def start(self):
        env = dict(os.environ)
        env["PATH"] = f"{self.venv}/bin:/usr/local/bin:/usr/bin:/bin"
        for var in ("JUPYTERHUB_USER", "JUPYTER_CONFIG_PATH", "JUPYTER_PATH", "PYTHONPATH"):
            env.pop(var, None)
        self.log_path.parent.mkdir(parents=True, exist_ok=True)
        self._log = open(self.log_path, "w")
        self.proc = subprocess.Popen(
            [
                f"{self.venv}/bin/jupyterhub",
                "-f",
                str(self.folder / "jupyterhub_config.py"),
            ],
            cwd=self.folder,
            env=env,
            stdout=self._log,
            stderr=subprocess.STDOUT,
        )
        wait(
            lambda: self.proc.poll() is None and http_ok(self.url("hub/login")),
            120,
            what=f"JupyterHub (log: {self.log_path})",
        )
        return self

    def url(self, path=""):
        return f"http://127.0.0.1:{self.port}/{path}"

    def stop(self):
        if self.proc and self.proc.poll() is None:
            self.proc.terminate()  # the hub stops the users' servers and its proxy
            try:
                self.proc.wait(60)
            except subprocess.TimeoutExpired:
                self.proc.kill()
        if self.proc:
            self._log.close()


class Server:
    """A user's server behind the hub (``url`` as ``_lab.Lab`` gives it)."""

    def __init__(self, hub, user):
        self.hub, self.user = hub, user

    def url(self, path="lab"):
        return self.hub.url(f"user/{self.user}/{path}")


def venv_paths(venv):
    """(site-packages, JUPYTER_DATA) of the shared venv, as its Python says."""
    out = subprocess.run(
        [
            f"{venv}/bin/python",
            "-c",
            "import sysconfig; from accelab.exercises.nbgrader_course import JUPYTER_DATA; "
            "print(sysconfig.get_paths()['purelib']); print(JUPYTER_DATA)",
        ],
        capture_output=True,
        text=True,
        check=True,
        cwd="/",  # not the checkout, whose accelab/ folder is not the package
    ).stdout.split()
    return out[0], out[1]


@pytest.fixture(scope="module")
def hub():
    """The class of the guide: its hub configuration, each role's folder, the class's
    folder made by root and the course made in it by the instructor, as the guide says."""
    need_browser()
    need_accounts()
    need_proxy()
    venv = shared_venv()
    site, jupyter_data = venv_paths(venv)

    shutil.rmtree(HUB, ignore_errors=True)
    HUB.mkdir(parents=True)
    os.chmod(HUB, 0o755)
    for name in PEOPLE.values():
        home = Path(account(name).pw_dir)
        for old in ("A", ".local/share/jupyter/nbgrader_cache", ".jupyter/lab"):
            shutil.rmtree(home / old, ignore_errors=True)
    places = {
        "/srv/mech101": str(CLASS_DIR),
        "/opt/accelab/lib/python3.11/site-packages": site,
        "/opt/accelab": str(venv),
        "/etc/jupyter-": f"{HUB}/jupyter-",
        **PEOPLE,
    }
    config = guide.adapted(guide.block("python", "c.JupyterHub.spawner_class"), places)
    assert f'"{jupyter_data}"' in config, "the guide's JUPYTER_PATH is not JUPYTER_DATA"
    port = free_port()
    config += TEST_ONLY.format(
        port=port,
        hub_port=free_port(),
        proxy_port=free_port(),
        folder=HUB,
        password=PASSWORD,
        extra_config=extra_config_dir(),
    )
    (HUB / "jupyterhub_config.py").write_text(config)
    for role in ("student", "instructor"):
        guide.write_role(HUB / f"jupyter-{role}", role, places, hub=True)

    # root, once: the class's folder, the instructor's
    install = guide.command(guide.block("sh", "install -d"), places)
    subprocess.run(install, check=True)
    # the instructor, in a terminal of their JupyterLab (its environment and folder): the
    # course, its exchange, the assignment released (one family of the guide's three: time)
    prof = account(INSTRUCTOR)
    roster = Path(prof.pw_dir) / "roster.csv"
    roster.write_text("id,first_name,last_name\n" + "".join(f"{s},{s},Hub\n" for s in STUDENTS))
    os.chown(roster, prof.pw_uid, prof.pw_gid)
    places["~/roster.csv"] = str(roster)
    assign = guide.command(guide.block("sh", "accelab assign", "--course-id"), places)
    assign[assign.index("--families") + 1] = "tolerance"
    env = {"JUPYTER_CONFIG_PATH": f"{HUB}/jupyter-instructor"}
    run_as(INSTRUCTOR, assign, env, cwd=CLASS_DIR)
    course, exchange = CLASS_DIR / "course", CLASS_DIR / "exchange"
    guide.assert_layout(CLASS_DIR, prof.pw_uid)  # as the guide draws it

    server = Hub(HUB, venv, port).start()
    yield {"hub": server, "exchange": exchange, "course": course, "venv": venv}
    server.stop()


@pytest.fixture(scope="module")
def driver(hub):
    d = browser(LAPTOP)
    yield d
    close(d)


def log_in(driver, hub, user):
    """Log in as ``user`` on the hub's login page; wait for the user's JupyterLab."""
    from selenium.webdriver.common.by import By

    driver.delete_all_cookies()
    driver.get(hub.url("hub/logout"))
    driver.delete_all_cookies()
    driver.get(hub.url("hub/login"))
    wait(lambda: driver.find_elements(By.ID, "username_input"), 60, what="the login page")
    driver.find_element(By.ID, "username_input").send_keys(user)
    driver.find_element(By.ID, "password_input").send_keys(PASSWORD)
    shot(driver, f"hub-login-{user}")
    driver.find_element(By.ID, "login_submit").click()
    wait(
        lambda: f"/user/{user}/lab" in driver.current_url,
        180,
        what=f"{user}'s server to start",
    )
    lab_ready(driver)
    time.sleep(1.5)
    dismiss_toasts(driver)
    return Server(hub, user)


def answer_and_submit(driver, server, user, code):
    """Fetch A from the Assignments panel, run it, answer with ``code`` and submit."""
    assignments_panel(driver)
    button_in(driver, "#released_assignments_list", "Fetch").click()
    button_in(driver, "#fetched_assignments_list", "Submit")
    open_path(driver, server, "A/A.ipynb")
    click_menu(driver, "Run", "Run All Cells")
    wait_idle(driver)
    params = next(c for c in cells(driver) if "load_variant(SPEC" in c["source"])
    assert f"These are the values of student '{user}' (your JupyterHub user)" in params["text"]
    grade_ids = in_panel(
        driver,
        "return w.content.widgets.map(c => ((c.model.getMetadata && c.model.getMetadata("
        "'nbgrader')) || {}).grade_id || '')",
    )
    for c in cells(driver):
        gid = grade_ids[c["index"]]
        if gid.startswith("answer_") and gid[len("answer_") :] in code:
            type_into_cell(driver, c["index"], code[gid[len("answer_") :]])
    click_menu(driver, "Run", "Run All Cells")
    wait_idle(driver)
    assert not tracebacks(driver), tracebacks(driver)
    shot(driver, f"hub-{user}-answered")
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys

    ActionChains(driver).key_down(Keys.CONTROL).send_keys("s").key_up(Keys.CONTROL).perform()
    wait(lambda: in_panel(driver, "return !w.context.model.dirty"), 30, what="a save")
    assignments_panel(driver)
    button_in(driver, "#fetched_assignments_list", "Submit").click()
    from selenium.webdriver.common.by import By

    wait(
        lambda: driver.find_elements(By.CSS_SELECTOR, "#submitted_assignments_list .list_item"),
        60,
        what=f"{user}'s submission to be listed",
    )
    shot(driver, f"hub-{user}-submitted")


def test_two_students_and_an_instructor_on_jupyterhub(hub, driver):
    from selenium.webdriver.common.by import By

    from accelab.exercises.notebook import read_spec
    from accelab.exercises.simulate import key_code

    course, exchange = hub["course"], hub["exchange"]
    spec = read_spec(course, "A")
    inbound = exchange / COURSE_ID / "inbound"
    ann, hal = STUDENTS

    # the first student: right answers
    ann_server = log_in(driver, hub["hub"], ann)
    items = menu_labels(driver, "Nbgrader")
    assert "Assignment List" in items and "Formgrader" not in items, items
    answer_and_submit(driver, ann_server, ann, key_code(spec, ann))

    # the second student: the first one's right answers (wrong for him), and an attempt
    # to submit as her, which the hub refuses (his server may ask only about himself)
    hal_server = log_in(driver, hub["hub"], hal)
    answer_and_submit(driver, hal_server, hal, key_code(spec, ann))
    last = cells(driver)[-1]["index"]
    in_panel(driver, "w.content.activeCellIndex = arguments[1];", last)
    driver.execute_script("window.jupyterapp.commands.execute('notebook:insert-cell-below')")
    time.sleep(0.5)
    type_into_cell(
        driver, last + 1, f"!cd ~ && nbgrader submit A --course {COURSE_ID} --student {ann}"
    )
    wait_idle(driver)
    out = cells(driver)[last + 1]["text"]
    shot(driver, "hub-hal-cannot-submit-as-ann")
    assert "JupyterhubApiError" in out and f"/users/{ann}" in out, out
    submitted = sorted((p.name.split("+")[0], p.stat().st_uid) for p in inbound.iterdir())
    assert submitted == sorted((s, account(s).pw_uid) for s in STUDENTS), (submitted, out)
    # the same without the hub's check (his own settings can drop it): the folder lands in
    # the exchange under her name, but it is his, and collect goes by its owner
    type_into_cell(
        driver,
        last + 1,
        f"!cd ~ && nbgrader submit A --course {COURSE_ID} --student {ann} "
        "--Authenticator.plugin_class=nbgrader.auth.base.NoAuthPlugin",
    )
    wait_idle(driver)
    forged = [
        p
        for p in inbound.iterdir()
        if p.name.startswith(f"{ann}+") and p.stat().st_uid == account(hal).pw_uid
    ]
    assert forged, cells(driver)[last + 1]["text"]

    # the instructor: formgrader is theirs; collect, then grade
    log_in(driver, hub["hub"], INSTRUCTOR)
    items = menu_labels(driver, "Nbgrader")
    assert "Formgrader" in items, items
    click_menu(driver, "Nbgrader", "Formgrader")
    frame = wait(
        lambda: next(
            (f for f in driver.find_elements(By.CSS_SELECTOR, "iframe") if f.is_displayed()), None
        ),
        60,
        what="formgrader",
    )
    driver.switch_to.frame(frame)
    time.sleep(2)
    shot(driver, "hub-prof-formgrader")
    click_in_row(driver, "A", "collect")
    modal, text = formgrader_modal(driver)
    shot(driver, "hub-prof-collected")
    assert "Successfully collected" in text, text
    driver.switch_to.default_content()
    assert sorted(os.listdir(course / "submitted")) == sorted(STUDENTS)

    proc = run_as(
        INSTRUCTOR,
        [f"{hub['venv']}/bin/accelab", "grade", "--course", str(course), "--assignment", "A"],
        cwd=course,
    )
    assert "2 submission(s) graded" in proc.stdout, proc.stdout
    with open(course / "grades_A.csv") as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    # the victim: her own notebook graded, her grade whole
    own = (Path(account(ann).pw_dir) / "A" / "A.ipynb").read_bytes()
    assert (course / "submitted" / ann / "A" / "A.ipynb").read_bytes() == own
    assert float(rows[ann]["total"]) == float(rows[ann]["max"]) > 0, rows[ann]
    # the attacker: what he handed in under her name is his own submission, graded against
    # his values (her answers earn him nothing), and the instructor is told
    assert float(rows[hal]["total"]) < float(rows[hal]["max"]), rows[hal]
    note = f"handed in under the name {ann} by the account {hal}, whose submission it is"
    assert note in rows[hal]["notes"], rows[hal]
    assert f"student {hal}: {note}" in proc.stderr, proc.stderr
    assert "handed in under the name" not in rows[ann]["notes"], rows[ann]
