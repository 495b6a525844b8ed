"""What a student id is: one rule, in one place, for the roster ``accelab assign``
reads (:func:`accelab.exercises.nbgrader_course.check_ids`) and for every folder
name or id a submission brings to collect and grade
(:func:`accelab.exercises.grader.intake.id_problem`, which adds "on the roster").

An id is a name, never a path or markup: valid UTF-8, 1 to :data:`MAX_ID` letters
(any script), digits and ``_ . @ -``, not beginning with ``.`` or ``-``, and not a
name accelab uses for something else (:data:`RESERVED_IDS`). nbgrader's exchange
refuses ``+`` and ``*`` (its file names are ``id+assignment+time``) and puts ids
into paths and globs (``/``, ``?``, ``[``); formgrader puts them into links and
pages (``<``, ``&``, ``#``, ``%``).
"""

import re
import unicodedata

#: longest student id [characters]
MAX_ID = 64
#: what an id may hold: letters (any script), digits and ``_ . @ -``
ID_CHARACTERS = re.compile(r"^[\w.@-]+$")
#: ids that name something else in accelab (the self-study variant, the preview)
RESERVED_IDS = frozenset({"self-study", "preview"})
#: the rule in words, for a message that refuses an id
RULE = (
    f"a student id is 1 to {MAX_ID} letters, digits, '_', '.', '@' or '-', not beginning "
    "with '.' or '-'"
)


def id_problem(name):
    """Why ``name`` (str, or bytes as a folder name may be) cannot be a student id,
    as words that follow the name ("is empty", "begins with '-' ..."), or None
    when it can. Whether it is on a course's roster is not asked here."""
    if isinstance(name, bytes):
        try:
            name = name.decode("utf-8")
        except UnicodeDecodeError:
            return "is not valid UTF-8"
    if not isinstance(name, str):
        return "is not a name"
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:  # a folder name of bytes that are not UTF-8
        return "is not valid UTF-8"
    if not name:
        return "is empty"
    if len(name) > MAX_ID:
        return f"is longer than {MAX_ID} characters"
    if name in RESERVED_IDS:
        return "is reserved by accelab (it names something else there)"
    if name[0] in ".-~":
        return f"begins with {name[0]!r}, as a path or an option does, not a name"
    if "/" in name or "\\" in name:
        return "looks like a path, not a name"
    if ID_CHARACTERS.match(name):
        return None
    blank = {ch for ch in name if ch.isspace() or unicodedata.category(ch)[0] in "CZ"}
    bad = "".join(sorted({ch for ch in name if not ID_CHARACTERS.match(ch)} - blank))
    if bad:  # markup, quotes, what a URL, a glob or nbgrader's exchange reads specially
        return f"holds characters a student id never has ({shown(bad)})"
    return "holds spaces or control characters"


def shown(name, limit=MAX_ID):
    """A name as a note shows it, safe anywhere it is printed (a terminal, a CSV, a
    web page): printable ASCII, with markup, quotes, backslashes, control and
    non-ASCII characters and bytes that are not UTF-8 written as escapes
    (``\\x3c``, ``\\xff``), cut to ``limit`` characters."""
    if isinstance(name, bytes):
        text = name.decode("utf-8", "backslashreplace")
    else:
        try:
            text = str(name).encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
        except UnicodeEncodeError:
            text = str(name).encode("utf-8", "backslashreplace").decode("ascii")
    out = []
    for ch in text:  # (a backslash stays: the escapes backslashreplace wrote)
        if " " <= ch <= "~" and ch not in "<>&\"'`":
            out.append(ch)
        elif ord(ch) < 0x100:
            out.append(f"\\x{ord(ch):02x}")
        elif ord(ch) < 0x10000:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(f"\\U{ord(ch):08x}")
    text = "".join(out)
    return text if len(text) <= limit else text[: limit - 3] + "..."
