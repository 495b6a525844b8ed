"""``accelab assign``: write an assignment's source notebook into a course and,
optionally, run nbgrader's generate_assignment and release_assignment."""

import os

from .assignment import make_spec
from .course import course_id_of, create_course, nbgrader
from .notebook import write_source

DEFAULT_FAMILIES = ["rotation", "fourbar", "tolerance"]


def assign(course_dir, assignment, families=None, units="US", tolerance=0.01, ranges=None,
           roster=(), course_id=None, generate=True, release=False, timeout=10, title=None):
    """Create the assignment; returns the source notebook path."""
    if os.path.exists(os.path.join(course_dir, "nbgrader_config.py")):
        course_id = course_id or course_id_of(course_dir)
    course_id = course_id or "accelab"
    create_course(course_dir, course_id, roster, timeout=timeout)
    spec = make_spec(course_id, assignment, families or DEFAULT_FAMILIES, units, tolerance,
                     ranges)
    path = write_source(course_dir, spec, title)
    if generate or release:
        nbgrader(course_dir, "generate_assignment", assignment, "--force")
    if release:
        nbgrader(course_dir, "release_assignment", assignment, "--force")
    return path
