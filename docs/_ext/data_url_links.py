"""markdown-it reads the destination of a link or image that is a base64 image
(``data:image/png;base64,...``) with one regular expression instead of a Python step
per character.

The course pages show each figure in two renditions, written by the notebook as
Markdown images whose destination is the PNG itself (``![...](data:image/png;base64,
...)``, :mod:`accelab.course.renditions`). markdown-it-py scans a destination one
character at a time (``parseLinkDestination``) and then percent-encodes it one
character at a time (``normalizeLink`` through ``mdurl``): for the 9 MB of base64
in the course's pages that was about a tenth of a build of this site from scratch.

For such a URL both steps give back the URL unchanged (none of its characters is
escaped, encoded, or ends a destination): the fast path returns exactly what
markdown-it would, and any other destination goes through markdown-it's own code.
``tests/test_docs_data_urls.py`` checks the fast path against markdown-it's own code on
destinations it takes and on destinations it must leave alone, and the HTML markdown-it
renders with and without it. If markdown-it's internals ever differ from what this
expects, it leaves them as they are (the build is then slower, never different).
"""

import re

#: a base64 image as a destination: no character of it is escaped, encoded or ends it
PLAIN_DATA_URL = re.compile(
    r"data:image/(?:png|jpeg|gif|webp|svg\+xml);base64,[A-Za-z0-9+/]*={0,2}"
)
#: the characters that may follow such a destination in a link: its end, or a title
ENDS = frozenset(" \n\t)")


def fast_parse_link_destination(original):
    """``parseLinkDestination`` with the fast path for a plain data URL."""
    result_type = type(original("", 0, 0))  # markdown-it's result (an empty one: not ok)

    def parse(string, pos, maximum):
        found = PLAIN_DATA_URL.match(string, pos, maximum)
        if found is not None:
            end = found.end()
            if end == maximum or string[end] in ENDS:
                result = result_type()
                result.ok, result.pos, result.str = True, end, string[pos:end]
                return result
        return original(string, pos, maximum)

    parse.original = original
    return parse


def fast_normalize_link(original):
    """``MarkdownIt.normalizeLink`` with the fast path for a plain data URL."""

    def normalize(self, url):
        if PLAIN_DATA_URL.fullmatch(url):
            return url
        return original(self, url)

    normalize.original = original
    return normalize


def install():
    """Put the fast paths in markdown-it (once); False if its internals are not the
    ones this module knows."""
    try:
        from markdown_it import MarkdownIt, helpers
    except ImportError:
        return False
    parse = getattr(helpers, "parseLinkDestination", None)
    normalize = getattr(MarkdownIt, "normalizeLink", None)
    if parse is None or normalize is None:
        return False
    if hasattr(parse, "original"):
        return True
    empty = parse("", 0, 0)
    if not all(hasattr(empty, name) for name in ("ok", "pos", "str")) or empty.ok:
        return False
    helpers.parseLinkDestination = fast_parse_link_destination(parse)
    MarkdownIt.normalizeLink = fast_normalize_link(normalize)
    return True


def setup(app):
    install()
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
