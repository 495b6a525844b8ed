"""Former name of :mod:`course.kit` (kept for the old site builder, which
puts ``course/`` on the path); the notebooks import ``course.kit``."""

from course.kit import *  # noqa: F401,F403
from course.kit import __all__  # noqa: F401
