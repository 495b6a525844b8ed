"""Feedback pages, one student at a time, each file replaced whole.

nbgrader's ``generate_feedback`` removes a student's feedback folder before it
writes the new one, and does the whole class at once: a full disk or a kill
leaves pages missing or cut, and regrading two students rewrites two hundred
pages. Here the same converter (nbgrader's ``GenerateFeedback``, with the
course's preprocessors and the feedback template) renders one student's
autograded notebook, and the page is replaced whole
(:func:`~accelab.exercises.files.write_atomic`). The student's feedback folder
then holds only what the grader wrote: the page, and the ``timestamp.txt`` and
``submission_secret.txt`` that ``nbgrader release_feedback`` reads, written by
the grader (:func:`.intake.clean_feedback_of`), never a file of the submission.
"""

import os

from ..files import write_atomic
from .intake import clean_feedback_of


def feedback_folder(course_dir, assignment, student):
    return os.path.join(course_dir, "feedback", student, assignment)


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
        """Write ``student``'s feedback page from their autograded notebook (the
        assignment's, never another notebook a submission brought); returns the
        pages. Raises WriteError (each file of the folder is whole)."""
        src = os.path.join(course_dir, "autograded", student, assignment)
        dest = feedback_folder(course_dir, assignment, student)
        pages = []
        path = os.path.join(src, f"{assignment}.ipynb")
        if os.path.isfile(path) and not os.path.islink(path):
            resources = {
                "unique_key": assignment,
                "output_files_dir": f"{assignment}_files",
                "nbgrader": {
                    "student": student,
                    "assignment": assignment,
                    "notebook": assignment,
                    "db_url": self.app.coursedir.db_url,
                },
            }
            exporter = self._exporter()
            body, resources = exporter.from_filename(path, resources=resources)
            page = os.path.join(dest, assignment + exporter.file_extension)
            write_atomic(page, body, mode=0o644, stage="feedback")
            pages.append(page)
        clean_feedback_of(course_dir, assignment, student)
        return pages
