"""The site build's fast path for base64 images in Markdown (``docs/_ext/data_url_links.py``)
gives markdown-it's own results: the same destination (end, text, ok) and the same
normalized link for the renditions the course pages show, and markdown-it's own code for
every other destination; the HTML markdown-it renders is the same with it and without it."""

import base64
import sys
from pathlib import Path

import pytest

pytest.importorskip("markdown_it")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "docs" / "_ext"))
import data_url_links  # docs/_ext is not a package: its folder is put on the path
from markdown_it import MarkdownIt, helpers

PNG = base64.b64encode(bytes(range(256)) * 40).decode()  # has + and /, ends with "="
ONE = "data:image/png;base64," + PNG
#: text after "](" that the fast path takes, and text it must leave to markdown-it
DESTINATIONS = [
    ONE + ")",
    ONE + ' "a title")',
    ONE + "\n)",
    ONE,  # the end of the text
    "data:image/jpeg;base64,QUJD)",
    "data:image/png;base64,QUJD=x)",  # a character after the padding: markdown-it's own
    "data:image/png;base64,QU(JD))",  # parentheses
    "data:image/png;base64,QU\\)JD)",  # an escape
    "data:image/png;base64,QU%20JD)",  # percent-encoded
    "data:image/png;base64,QUJD\x01)",  # a control character
    "data:text/html;base64,QUJD)",  # not an image
    "DATA:image/png;base64,QUJD)",
    "<data:image/png;base64,QUJD>)",
    "data:image/png;base64,QUJ&amp;D)",
    "figures/plot.png)",
    "https://example.org/a b)",
    ")",
]


@pytest.fixture(scope="module")
def originals():
    assert data_url_links.install()
    parse = helpers.parseLinkDestination
    normalize = MarkdownIt.normalizeLink
    return parse.original, normalize.original


@pytest.mark.parametrize("rest", DESTINATIONS, ids=range(len(DESTINATIONS)))
def test_a_destination_reads_as_markdown_it_reads_it(originals, rest):
    parse, normalize = originals
    text = "![a figure](" + rest
    start = len("![a figure](")
    ours = helpers.parseLinkDestination(text, start, len(text))
    theirs = parse(text, start, len(text))
    assert (ours.ok, ours.pos, ours.str) == (theirs.ok, theirs.pos, theirs.str)
    if theirs.ok:
        md = MarkdownIt()
        assert MarkdownIt.normalizeLink(md, theirs.str) == normalize(md, theirs.str)


def test_the_renditions_render_the_same_html(originals):
    """A Markdown output as accelab.course.renditions writes it, rendered by markdown-it
    with the fast path and with its own code."""
    parse, normalize = originals
    text = (
        f"![The wide figure]({ONE}){{.accelab-wide}}\n"
        f'![The narrow one]({ONE} "title"){{.accelab-narrow}}\n\n'
        f"[a link]({ONE}) and [ref]\n\n[ref]: {ONE}\n"
    )
    fast = MarkdownIt("commonmark").render(text)
    try:
        helpers.parseLinkDestination, MarkdownIt.normalizeLink = parse, normalize
        slow = MarkdownIt("commonmark").render(text)
    finally:
        data_url_links.install()
    assert fast == slow
    assert fast.count(ONE) == 4
