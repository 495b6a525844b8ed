"""Feedback pages, one student at a time, each file replaced whole.

nbgrader's ``generate_feedback`` removes a student's feedback folder before it
writes the new one, and does the whole class at once: a full disk or a kill
leaves pages missing or cut, and regrading two students rewrites two hundred
pages. Here the same converter (nbgrader's ``GenerateFeedback``, with the
course's preprocessors and the feedback template) renders one student's
autograded notebooks, and every file of the student's feedback folder is
replaced whole (:func:`~accelab.exercises.files.write_atomic`): the page, and
the files ``nbgrader release_feedback`` reads beside it (``timestamp.txt``,
``submission_secret.txt``).
"""

import glob
import os
import stat

from ..files import copy_atomic, write_atomic


def feedback_folder(course_dir, assignment, student):
    return os.path.join(course_dir, "feedback", student, assignment)


def copy_side_files(src, dest):
    """Copy the regular files (not notebooks, not links) at the top of ``src`` to ``dest``."""
    try:
        names = sorted(os.listdir(src))
    except OSError:
        return
    for name in names:
        path = os.path.join(src, name)
        try:
            info = os.lstat(path)
        except OSError:
            continue
        if stat.S_ISREG(info.st_mode) and not name.endswith(".ipynb"):
            copy_atomic(path, os.path.join(dest, name))


class FeedbackPages:
    """Writes feedback pages with nbgrader's converter, set up once per run."""

    def __init__(self, api):
        from nbgrader.converters import GenerateFeedback
        from traitlets.config import Config

        config = Config()
        config.HTMLExporter.template_name = "feedback"
        self.app = GenerateFeedback(coursedir=api.coursedir, parent=api)
        self.app.update_config(config)
        self.exporter = None

    def _exporter(self):
        if self.exporter is None:
            self.exporter = self.app.exporter_class(parent=self.app, config=self.app.config)
            for pp in self.app.preprocessors:
                self.exporter.register_preprocessor(pp)
        return self.exporter

    def write(self, course_dir, assignment, student):
        """Write ``student``'s feedback from their autograded notebooks; returns
        the pages. Raises WriteError (a page and its side files are each whole)."""
        src = os.path.join(course_dir, "autograded", student, assignment)
        dest = feedback_folder(course_dir, assignment, student)
        copy_side_files(src, dest)
        pages = []
        for path in sorted(glob.glob(os.path.join(glob.escape(src), "*.ipynb"))):
            notebook = os.path.splitext(os.path.basename(path))[0]
            resources = {
                "unique_key": notebook,
                "output_files_dir": f"{notebook}_files",
                "nbgrader": {
                    "student": student,
                    "assignment": assignment,
                    "notebook": notebook,
                    "db_url": self.app.coursedir.db_url,
                },
            }
            exporter = self._exporter()
            body, resources = exporter.from_filename(path, resources=resources)
            for name, data in (resources.get("outputs") or {}).items():
                write_atomic(os.path.join(dest, name), data, mode=0o644)
            page = os.path.join(dest, notebook + exporter.file_extension)
            write_atomic(page, body, mode=0o644, stage="feedback")
            pages.append(page)
        return pages
