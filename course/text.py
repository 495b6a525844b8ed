"""Results as a reader wants them: sentences and tables, not raw values.

A notebook cell that ends in a bare number shows ``np.float64(3.99...)``; a
``print`` of an f-string shows monospace text that runs off a phone's screen.
These helpers show a result as rendered Markdown instead, so that the page
typesets its symbols, keeps units with every number and rounds each number to
the digits it deserves:

>>> table(["", r"$\\alpha_3$ [rad/s²]", r"$\\alpha_4$ [rad/s²]"],
...       [["analytic", num(8.7688), num(39.43)], ["graphical", num(8.7688), num(39.43)]])
>>> say(f"The piston reaches {num(2093, 3)} g at 6000 rpm.")

``num`` writes a number with a given count of significant digits, a true
minus sign and a thin space between thousands (``−65 000``); ``vec`` writes
a vector (a complex Quantity or number) by size and direction, ``xy`` by its
components, each with its unit.
"""

import math
import re
import textwrap

import numpy as np

__all__ = ["num", "sci", "unit_text", "vec", "xy", "table", "say", "Text"]

MINUS = "\u2212"
THIN = "\u202f"  # a narrow space that never breaks a number across lines
NBSP = "\u00a0"  # between a number and its unit

#: units as a reader writes them
_UNITS = {
    "in/s^2": "in/s²",
    "m/s^2": "m/s²",
    "ft/s^2": "ft/s²",
    "rad/s^2": "rad/s²",
    "rad/s^3": "rad/s³",
    "in/s^3": "in/s³",
    "m/s^3": "m/s³",
    "deg": "°",
}


def unit_text(unit):
    """``"in/s^2"`` -> ``"in/s²"`` (and ``"deg"`` -> ``"°"``)."""
    unit = str(unit).replace("**", "^")
    return _UNITS.get(unit, unit.replace("^2", "²").replace("^3", "³"))


def num(x, sig=4, decimals=None):
    """``x`` with ``sig`` significant digits (or ``decimals`` after the point),
    a true minus sign and narrow no-break spaces between thousands: ``-65000.4`` ->
    ``"−65 000"``. A Quantity gives its magnitude."""
    x = float(getattr(x, "magnitude", x))
    if not math.isfinite(x):
        return "—"
    if decimals is None:
        if x == 0:
            decimals = 0
        else:
            place = sig - 1 - math.floor(math.log10(abs(x)))
            x = round(x, place)
            decimals = max(0, place)
    text = f"{abs(x):,.{decimals}f}"
    if abs(x) < 10000:  # 4-digit numbers keep their digits together
        text = text.replace(",", "")
    text = text.replace(",", THIN)
    if float(text.replace(THIN, "")) == 0:
        return text
    return (MINUS if x < 0 else "") + text


def sci(x, sig=2):
    """``x`` in powers of ten, as inline math: ``4.0e-08`` -> ``$4.0\\times10^{-8}$``."""
    x = float(getattr(x, "magnitude", x))
    if not math.isfinite(x):
        return "—"
    if x == 0:
        return "$0$"
    e = math.floor(math.log10(abs(x)))
    m = x / 10**e
    if round(abs(m), sig - 1) >= 10:
        m, e = m / 10, e + 1
    mant = f"{m:.{sig - 1}f}"
    return f"${mant}\\times10^{{{e}}}$" if mant not in ("1", "1.0") else f"$10^{{{e}}}$"


def _complex(z, unit):
    if hasattr(z, "to") and unit:
        z = z.to(unit)
    return complex(getattr(z, "magnitude", z))


def vec(z, unit=None, sig=4):
    """A vector by size and direction: ``"3250 in/s² at −45.0°"``."""
    c = _complex(z, unit)
    ang = math.degrees(math.atan2(c.imag, c.real))
    u = f"{NBSP}{unit_text(unit)}" if unit else ""
    return f"{num(abs(c), sig)}{u} at {num(ang, decimals=1)}°"


def xy(z, unit=None, sig=4):
    """A vector by its components: ``"(−1109, −1226) m/s²"``."""
    c = _complex(z, unit)
    u = f"{NBSP}{unit_text(unit)}" if unit else ""
    return f"({num(c.real, sig)}, {num(c.imag, sig)}){u}"


class Text:
    """Markdown a notebook shows rendered (``_repr_markdown_``)."""

    def __init__(self, markdown):
        self.markdown = markdown

    def _repr_markdown_(self):
        return self.markdown

    def __repr__(self):
        return self.markdown


def _display(obj):
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:  # plain Python: print the Markdown
        print(obj.markdown)
        return
    if get_ipython() is None:
        print(obj.markdown)
    else:
        display(obj)


#: a number and the unit after it stay on one line ("367.1 m/s²", "37 g", "800 rpm")
_UNIT_AFTER = re.compile(
    r"(\d) (?=(?:m/s|in/s|ft/s|rad/s|rad\b|rpm|g\b|mm\b|in\b|m\b|s\b|µs|lbf|lb\b|N\b|kN|L\b|%))"
)


def _keep_units(text):
    return _UNIT_AFTER.sub("\\1" + NBSP, text)


def _cell(x):
    if isinstance(x, (float, np.floating)):
        return num(x)
    return _keep_units(str(x).replace("|", "\\|").replace("\n", " "))


def table(header, rows, align=None, show=True):
    """A Markdown table, shown (or, with ``show=False``, returned as :class:`Text`).

    Parameters
    ----------
    header : list of str
        Column titles (Markdown: ``$\\alpha_3$ [rad/s²]``).
    rows : list of lists
        Cells: text, or numbers (written by :func:`num`).
    align : str, optional
        One letter per column, ``l``, ``r`` or ``c`` (default: the first
        column left, the others right).
    """
    align = align or "l" + "r" * (len(header) - 1)
    rule = {"l": ":--", "r": "--:", "c": ":-:"}
    lines = [
        "| " + " | ".join(_cell(h) for h in header) + " |",
        "|" + "|".join(rule[a] for a in align) + "|",
    ]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows]
    out = Text("\n".join(lines) + "\n")
    if not show:
        return out
    _display(out)
    return None


def say(markdown, show=True):
    """A sentence (Markdown, math allowed) shown as rendered text (or, with
    ``show=False``, returned as :class:`Text`)."""
    out = Text(_keep_units(textwrap.dedent(str(markdown)).strip()) + "\n")
    if not show:
        return out
    _display(out)
    return None
