"""One cache of typeset math for every figure of a kernel.

Matplotlib typesets each ``$...$`` label with a parser that belongs to one
renderer, that is to one figure, and keeps only its last 50 results. A
notebook draws the same labels ($\\theta_2$, $\\mathbf{A}_B$, ...) on hundreds
of figures (the two renditions of every figure, each frame of an animation,
every value of a slider that ``explore`` checks), so it typesets them again
and again: a third of the time of some notebooks.

:func:`install` makes the parsers share one larger cache, keyed by everything
the result depends on (the text, the DPI, the font, antialiasing, hinting,
the ``mathtext.*`` settings): the same input gives the very same glyphs, so
figures are drawn exactly as before, only sooner. It does nothing if
matplotlib's parser is not the one this was written for (3.x, ``_parse_cached``).
"""

import functools

import matplotlib as mpl
from matplotlib import mathtext

__all__ = ["install"]

#: settings read while typesetting, beside the font (which is part of the key)
_SETTINGS = tuple(k for k in mpl.rcParams if k.startswith("mathtext.")) + ("text.hinting_factor",)
#: results kept (a notebook has a few hundred distinct labels and titles)
SIZE = 4096


def install(size=SIZE):
    """Share one cache of ``size`` results between the math parsers of every
    figure (once per process; later calls do nothing)."""
    cls = mathtext.MathTextParser
    if getattr(cls, "_accelab_shared", False):
        return
    inner = getattr(getattr(cls, "_parse_cached", None), "__wrapped__", None)
    if inner is None:  # another matplotlib: leave it alone
        return
    parsers = {}  # output type -> a parser of that type (they differ by it alone)

    @functools.lru_cache(size)
    def shared(output, s, dpi, prop, antialiased, flags, settings):
        return inner(parsers[output], s, dpi, prop, antialiased, flags)

    def _parse_cached(self, s, dpi, prop, antialiased, load_glyph_flags):
        parsers.setdefault(self._output_type, self)
        settings = tuple(mpl.rcParams[k] for k in _SETTINGS)
        return shared(self._output_type, s, dpi, prop, antialiased, load_glyph_flags, settings)

    cls._parse_cached = _parse_cached
    cls._accelab_shared = True
