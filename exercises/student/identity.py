"""Whose values a student's notebook shows: the student that nbgrader will collect
its submission as.

In order (the first that applies):

1. the JupyterHub user (``JUPYTERHUB_USER``): the user's own server on a hub, where
   nbgrader's exchange, or ngshare, submits as that user;
2. inside an assignment that nbgrader's exchange released (the exchange this account
   uses, read from nbgrader's configuration as nbgrader reads it, holds
   ``<course>/outbound/<assignment>``): the student id nbgrader's exchange submits as,
   ``CourseDirectory.student_id`` when configured, else the account's name (nbgrader's
   ``get_username``: the login name, or the hub user on a ``jovyan`` container);
3. an explicit ``ACCELAB_STUDENT`` (or its older spelling ``ACCELAB_STUDENT_ID``);
4. else nobody: the notebook says so and how to set the id (it shows the self-study
   values meanwhile, and its checks fail until an id is set).

Nothing here is trusted by the grader: it judges each submission against the values of
the student it was collected from, whatever the notebook showed.
"""

import os

__all__ = ["Identity", "identify", "exchange_student", "EXPLICIT_VARS"]

#: the variables a student (or a course's set-up) may set to name the student
EXPLICIT_VARS = ("ACCELAB_STUDENT", "ACCELAB_STUDENT_ID")
DEFAULT_EXCHANGE = "/srv/nbgrader/exchange"


class Identity:
    """A student id and how it was found (``student`` is None when none was)."""

    def __init__(self, student, how):
        self.student = student
        self.how = how

    def __repr__(self):
        return f"Identity({self.student!r}, {self.how!r})"


def _nbgrader_config():
    """nbgrader's configuration as its Assignments panel reads it: ``nbgrader_config.py``
    (and ``.json``) of Jupyter's config path, then of the working folder (the last wins).
    An empty dict when there is none or it cannot be read."""
    try:
        from jupyter_core.paths import jupyter_config_path
        from traitlets.config.loader import Config, JSONFileConfigLoader, PyFileConfigLoader
    except ImportError:  # not in a Jupyter environment
        return {}
    config = Config()
    folders = [*reversed(jupyter_config_path()), os.getcwd()]
    for folder in folders:
        for loader in (JSONFileConfigLoader, PyFileConfigLoader):
            name = "nbgrader_config." + ("json" if loader is JSONFileConfigLoader else "py")
            if not os.path.isfile(os.path.join(folder, name)):
                continue
            try:
                config.merge(loader(name, path=folder).load_config())
            except Exception:  # noqa: BLE001 -- a broken config is nbgrader's to report
                continue
    return config


def _account():
    """The name nbgrader's exchange gives this account (``nbgrader.utils.get_username``)."""
    try:
        import pwd

        name = pwd.getpwuid(os.getuid()).pw_name
    except (ImportError, KeyError):
        name = os.environ.get("USER", "") or os.environ.get("USERNAME", "")
    if name == "jovyan":
        return os.environ.get("JUPYTERHUB_USER", "jovyan")
    return name


def exchange_student(spec=None):
    """``(student id, how it was found)`` nbgrader's exchange would submit this
    account's work as, when its exchange released the assignment of ``spec`` (or,
    without ``spec``, any assignment of the configured course); else ``(None, None)``."""
    config = _nbgrader_config()
    exchange = config.get("Exchange", {})
    root = str(exchange.get("root", DEFAULT_EXCHANGE))
    course = (spec or {}).get("course") or config.get("CourseDirectory", {}).get("course_id")
    if not course or not isinstance(course, str):
        return None, None
    outbound = os.path.join(root, course, "outbound")
    assignment = (spec or {}).get("assignment")
    try:
        released = (
            os.path.isdir(os.path.join(outbound, assignment))
            if assignment
            else bool(os.listdir(outbound))
        )
    except OSError:
        released = False
    if not released:
        return None, None
    configured = config.get("CourseDirectory", {}).get("student_id", "*")
    if isinstance(configured, str) and configured.strip() not in ("", "*"):
        return configured.strip(), "CourseDirectory.student_id in nbgrader's configuration"
    account = _account()
    if not account:
        return None, None
    return account, "the account nbgrader's exchange submits this notebook from"


def identify(spec=None):
    """The :class:`Identity` whose values a notebook of ``spec`` shows (module docstring)."""
    hub = os.environ.get("JUPYTERHUB_USER", "").strip()
    if hub:
        return Identity(hub, "your JupyterHub user")
    student, how = exchange_student(spec)
    if student:
        return Identity(student, how)
    for var in EXPLICIT_VARS:
        value = os.environ.get(var, "").strip()
        if value:
            return Identity(value, f"{var} in the notebook's environment")
    return Identity(None, "none found")
