"""What the course notebooks share: the ``explore`` control, number formatting,
one plotting style, and :func:`stated`, which ties a number the prose states
to the value the notebook computes.

``explore(draw, theta2=(0, 360, 5, 30), omega2=(...))`` shows sliders in a live
Jupyter session. Executed headless (the tests and the site build set
``ACCELAB_STATIC=1``) it draws the same figure at a few values of the first
slider instead, side by side, so a printed or static page still shows what
moving the slider teaches.

Every control works over its whole range: :func:`range_values` lists the values a
person reaches by moving each slider to its ends and a few steps in between, and
:func:`check_ranges` draws them all. With ``ACCELAB_CHECK_WIDGETS`` set to a file
name (the course tests set it), ``explore`` runs that check before it draws and
appends what it checked to that file as one JSON line, and :func:`check_explored`
checks them all again after the notebook's last cell; a failing value raises.
In a live notebook a value that ``draw`` cannot draw shows a sentence in place
of the figure, never a traceback.

>>> from accelab.course.kit import explore
>>> def draw(theta2, omega2):
...     fig, ax = plt.subplots()
...     ...                       # one figure for these values
...     return fig
>>> explore(draw, theta2=(0, 360, 5, 30, "deg"), omega2=(-20, 20, 1, 10, "rad/s"))
"""

import io
import json
import math
import os

import matplotlib.pyplot as plt
import numpy as np

from accelab.solver import Q_
from accelab.solver.graphical import style as _style

#: colours of the vector kinds, as the graphical constructions draw them
COLORS = {kind: spec["color"] for kind, spec in _style.COMPONENT.items()}
#: line styles of the vector kinds (they also read in greyscale)
LINESTYLES = {kind: spec["linestyle"] for kind, spec in _style.COMPONENT.items()}
#: a neutral grey for links, and the two circuits of a fourbar
LINK_COLOR = "#4d4d4d"
CIRCUIT_COLORS = {"open": _style.OKABE_ITO["blue"], "crossed": _style.OKABE_ITO["vermillion"]}

#: standard gravity: the g in "accelerations in g" (pint's ``g`` is the gram)
G0 = Q_(1, "standard_gravity")

#: panels of the static figure when the first slider's values are not given
STATIC_FRAMES = 4
_STATIC_DPI = 100
#: widest static figure [px]: two panels side by side on a page about 760 px wide
STATIC_WIDTH = 960
#: widest static figure on a phone [px]: its panels one above the other
NARROW_WIDTH = 470

__all__ = [
    "COLORS",
    "LINESTYLES",
    "LINK_COLOR",
    "CIRCUIT_COLORS",
    "G0",
    "use_style",
    "is_static",
    "static_values",
    "small_multiples",
    "explore",
    "range_values",
    "check_ranges",
    "check_explored",
    "cartesian",
    "polar",
    "in_g",
    "vector",
    "point_label",
    "stated",
    "measure",
]


def use_style():
    """Matplotlib settings every notebook starts with: readable at page width; and one
    cache of typeset math for all the notebook's figures (:mod:`accelab.course.mathtext_cache`)."""
    from accelab.course.mathtext_cache import install

    install()
    plt.rcParams.update(
        {
            "figure.figsize": (6.4, 4.0),
            "figure.dpi": _STATIC_DPI,
            "savefig.dpi": _STATIC_DPI,
            "font.size": 11,
            "axes.titlesize": 12,
            "axes.labelsize": 11,
            "legend.fontsize": 10.5,
            "xtick.labelsize": 10.5,
            "ytick.labelsize": 10.5,
            "axes.grid": True,
            "grid.alpha": 0.3,
            "axes.spines.top": False,
            "axes.spines.right": False,
            "figure.constrained_layout.use": True,
        }
    )


def is_static():
    """True when sliders cannot be shown: executed headless (``ACCELAB_STATIC``
    set to anything but ``0``), no ipywidgets, or not inside a Jupyter kernel."""
    if os.environ.get("ACCELAB_STATIC", "0") not in ("", "0"):
        return True
    try:
        import ipywidgets  # noqa: F401
        from IPython import get_ipython
    except ImportError:
        return True
    shell = get_ipython()
    return shell is None or not hasattr(shell, "kernel")


def _parse(name, spec):
    if not isinstance(spec, (tuple, list)) or len(spec) not in (4, 5):
        raise ValueError(
            f"explore: {name} must be (min, max, step, default) or "
            f"(min, max, step, default, unit), e.g. {name}=(0, 360, 5, 30, 'deg'); "
            f"got {spec!r}"
        )
    lo, hi, step, default = spec[:4]
    unit = spec[4] if len(spec) == 5 else ""
    if not lo <= default <= hi or step <= 0:
        raise ValueError(f"explore: {name} needs min <= default <= max and step > 0 (got {spec!r})")
    return lo, hi, step, default, unit


def static_values(lo, hi, step, frames=STATIC_FRAMES):
    """``frames`` values from lo to hi on the slider's step grid. A slider over a
    whole turn (its ends 360 apart) skips the end that repeats the start."""
    periodic = math.isclose(hi - lo, 360.0)
    n = frames if periodic else frames - 1
    span = (hi - lo) * (frames - 1) / n if periodic else hi - lo
    raw = lo + span * np.arange(frames) / max(frames - 1, 1)
    snapped = lo + np.round((raw - lo) / step) * step
    return [float(v) if not float(v).is_integer() else int(v) for v in snapped]


#: how a slider's name reads on a figure and beside a slider (mathtext; ipywidgets
#: typesets the same $...$ in a live notebook)
SLIDER_NAMES = {
    "theta2": r"$\theta_2$",
    "omega2": r"$\omega_2$",
    "alpha2": r"$\alpha_2$",
    "delta3": r"$\delta_3$",
    "lam": r"$\lambda$",
    "phi": r"$\phi$",
    "p": r"$p$",
    "c": r"$c$",
    "rod_mm": r"rod $b$",
    "speed": "crank speed",
    "log10_h": r"$\log_{10} h$",
}
#: units as they read on a figure
_UNIT_TEXT = {"deg": "\u00b0", "rad/s^2": "rad/s\u00b2", "rad/s**2": "rad/s\u00b2"}


def _symbol(name):
    return SLIDER_NAMES.get(name, name)


def _unit_text(unit):
    unit = _UNIT_TEXT.get(unit, unit)
    return unit.replace("**", "^").replace("^2", "\u00b2").replace("^3", "\u00b3")


def _label(name, value, unit):
    """``θ₂ = 30°``: a slider's value as a panel of the static figure names it."""
    text = _unit_text(unit)
    number = f"{value:g}".replace("-", "\u2212")  # a true minus sign
    if text and name.strip().lower() == unit.strip().lower():  # "rpm = 6 rpm" reads "6 rpm"
        return f"{number} {text}"
    sep = "" if text == "\u00b0" else " "
    return f"{_symbol(name)} = {number}{sep}{text}".strip()


def _description(name, unit):
    """A live slider's label: ``$\\theta_2$ [deg]``, never ``rpm [rpm]``."""
    if unit and name.strip().lower() == unit.strip().lower():
        return name
    return f"{_symbol(name)} [{_unit_text(unit)}]" if unit else _symbol(name)


def _render(fig):
    """The figure as an RGBA array at its own pixel size."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=_STATIC_DPI, facecolor="white")
    buf.seek(0)
    return plt.imread(buf)


def _figure_of(result):
    if result is None:
        return plt.gcf()
    if hasattr(result, "savefig"):
        return result
    if hasattr(result, "figure"):  # an Axes
        return result.figure
    raise TypeError(
        "explore: draw() must return a matplotlib Figure (or an Axes, or None "
        f"after drawing on the current figure); it returned {type(result).__name__}"
    )


def _panels(draw, name, values, fixed):
    images = []
    for v in values:
        fig = _figure_of(draw(**{name: v}, **fixed))
        images.append(_render(fig))
        plt.close(fig)
    return images


def small_multiples(
    draw, name, values, fixed, unit="", columns=None, units=None, width=STATIC_WIDTH, images=None
):
    """One figure: ``draw(name=v, **fixed)`` for each v in ``values``, side by
    side (as many as fit in ``width`` px, or ``columns``), each panel at its
    own resolution and titled with its value."""
    if images is None:
        images = _panels(draw, name, values, fixed)
    h = max(im.shape[0] for im in images)
    w = max(im.shape[1] for im in images)
    if columns is None:  # `width` px wide at most, rows as full as possible
        fit = max(1, min(len(images), width // w))
        columns = math.ceil(len(images) / math.ceil(len(images) / fit))
    rows = math.ceil(len(images) / columns)
    W = columns * w
    units = units or {}
    others = ", ".join(_label(k, v, units.get(k, "")) for k, v in fixed.items())
    header = (
        f"Moving {_symbol(name)}"
        + (f" (with {others})" if others else "")
        + ": in a live notebook, a slider"
    )
    lines = 1 if W >= 8.5 * len(header) else 2  # about 8.5 px per character at 12 pt
    if lines == 2:
        header = header.replace(": in a live", ":\nin a live")
    band = 30  # px for each panel's caption
    head = 14 + 22 * lines
    H = rows * (h + band) + head
    fig = plt.figure(figsize=(W / _STATIC_DPI, H / _STATIC_DPI), dpi=_STATIC_DPI, layout="none")
    fig.text(
        0.5,
        1 - (head / 2) / H,
        header,
        ha="center",
        va="center",
        fontsize=12,
        color="#333333",
        linespacing=1.4,
    )
    for i, im in enumerate(images):
        r, c = divmod(i, columns)
        x0 = c * w + (w - im.shape[1]) / 2
        y_top = head + r * (h + band)
        fig.text(
            (c * w + w / 2) / W,
            1 - (y_top + band / 2) / H,
            _label(name, values[i], unit),
            ha="center",
            va="center",
            fontsize=12,
            fontweight="bold",
        )
        y0 = y_top + band
        ax = fig.add_axes([x0 / W, 1 - (y0 + im.shape[0]) / H, im.shape[1] / W, im.shape[0] / H])
        ax.imshow(im, interpolation="none")
        ax.set_axis_off()
    return fig


def _is_int_slider(lo, hi, step, default):
    return all(float(x).is_integer() for x in (lo, hi, step, default))


def _on_grid(lo, hi, step, k, integer):
    """The value of the k-th step from ``lo`` as a slider gives it (clipped to hi)."""
    if integer:
        return int(min(lo + k * step, hi))
    return float(min(lo + k * step, hi))


def range_values(**sliders):
    """The values a person reaches by moving the controls of ``explore``: each
    slider at its minimum, one and two steps above it, the middle of its range,
    two and one steps below its maximum and its maximum, the others at their
    defaults; then every slider at its minimum together, and at its maximum
    together. A list of ``{name: value}``, each value of the type the slider
    hands ``draw`` (int for an integer slider), without repeats.

    >>> range_values(theta2=(0, 360, 5, 30, "deg"))[:3]
    [{'theta2': 0}, {'theta2': 5}, {'theta2': 10}]
    """
    specs = {k: _parse(k, v) for k, v in sliders.items()}
    defaults = {}
    grids = {}
    for k, (lo, hi, step, default, _) in specs.items():
        integer = _is_int_slider(lo, hi, step, default)
        n = int(math.floor((hi - lo) / step + 1e-9))  # steps from lo to the last one <= hi
        ks = sorted({0, 1, 2, n // 2, n - 2, n - 1, n} & set(range(n + 1)))
        grid = [_on_grid(lo, hi, step, j, integer) for j in ks]
        if not math.isclose(grid[-1], hi):  # the slider's end is not on its step grid
            grid.append(int(hi) if integer else float(hi))
        grids[k] = grid
        defaults[k] = int(default) if integer else float(default)
    out = []
    for k, grid in grids.items():
        out.extend({**defaults, k: v} for v in grid)
    if len(specs) > 1:
        out.append({k: g[0] for k, g in grids.items()})
        out.append({k: g[-1] for k, g in grids.items()})
    unique = []
    for values in out:
        if values not in unique:
            unique.append(values)
    return unique


def check_ranges(draw, *, render=True, **sliders):
    """Draw the figure of every value of :func:`range_values`; raise
    ``AssertionError`` naming the values where ``draw`` failed and why. Returns how
    many figures were drawn.

    ``render=True`` renders each figure to pixels, as the notebook shows it. With
    ``render=False`` each figure is laid out without its pixels (every artist drawn,
    every text measured and its math parsed: the errors of ``draw`` and of laying out
    text and artists), for a second pass over values already rendered once. It saves
    only the rasterizing, about a sixth of a figure's cost: laying out (constrained
    layout, text) is most of it."""
    failed = []
    values = range_values(**sliders)
    for kw in values:
        try:
            fig = _figure_of(draw(**kw))
            if render:
                fig.canvas.draw()  # the errors of laying out text and artists too
            else:
                fig.draw_without_rendering()
            plt.close(fig)
        except Exception as exc:  # noqa: BLE001 -- reported below, with the values
            plt.close("all")
            failed.append(f"{kw}: {type(exc).__name__}: {exc}")
    if failed:
        raise AssertionError(
            f"explore: draw fails at {len(failed)} of {len(values)} values of its controls:\n"
            + "\n".join(failed)
        )
    return len(values)


#: the explore() calls of this kernel, kept while ACCELAB_CHECK_WIDGETS is set
_EXPLORED = []


def _log_check(sliders, drawn, when):
    path = os.environ.get("ACCELAB_CHECK_WIDGETS", "")
    if not path:
        return
    spec = {k: list(v) for k, v in sliders.items()}
    with open(path, "a") as fh:
        fh.write(json.dumps({"sliders": spec, "drawn": drawn, "when": when}) + "\n")


def check_explored():
    """Check every control of this kernel's ``explore`` calls again, as a person
    meets them after Run All: with the notebook's names as the last cells left
    them (a later cell that rebinds a name ``draw`` reads breaks the slider).
    Only while ``ACCELAB_CHECK_WIDGETS`` is set; returns how many figures were drawn.

    What changed since :func:`explore` rendered these values are the names ``draw``
    reads; a rebound name fails in ``draw`` or in laying the figure out, so this pass
    lays each figure out without rendering its pixels (``render=False``)."""
    drawn = 0
    for draw, sliders in _EXPLORED:
        n = check_ranges(draw, render=False, **sliders)
        _log_check(sliders, n, "after the last cell")
        drawn += n
    return drawn


def explore(draw, *, frames=STATIC_FRAMES, values=None, columns=None, **sliders):
    """Sliders for ``draw`` in a live notebook; a static small-multiples figure
    when executed headless.

    Parameters
    ----------
    draw : callable
        ``draw(**values)`` makes one figure (return the Figure) for one value
        of every slider. It must draw at every value a slider reaches (its ends
        included): :func:`check_ranges` tries them.
    frames : int
        Panels of the static figure (values of the first slider, from its
        min to its max on its step grid; a full-turn slider skips 360).
    values : sequence, optional
        The first slider's values for the static figure, instead of ``frames``.
    columns : int, optional
        Panels per row of the static figure (default: as many as fit).
    **sliders : tuple
        ``name=(min, max, step, default)`` or ``(min, max, step, default, unit)``
        for each argument of ``draw``; the first one is the static figure's
        variable, the others stay at their defaults there.
    """
    if not sliders:
        raise ValueError("explore needs at least one slider, e.g. theta2=(0, 360, 5, 30)")
    specs = {k: _parse(k, v) for k, v in sliders.items()}
    if os.environ.get("ACCELAB_CHECK_WIDGETS", ""):
        _log_check(sliders, check_ranges(draw, **sliders), "when explore() ran")
        _EXPLORED.append((draw, dict(sliders)))
    if is_static():
        name, (lo, hi, step, default, unit) = next(iter(specs.items()))
        fixed = {k: s[3] for k, s in list(specs.items())[1:]}
        vals = list(values) if values is not None else static_values(lo, hi, step, frames)
        units = {k: s[4] for k, s in specs.items()}
        images = _panels(draw, name, vals, fixed)
        wide = small_multiples(draw, name, vals, fixed, unit, columns, units, images=images)
        narrow = small_multiples(
            draw, name, vals, fixed, unit, None, units, width=NARROW_WIDTH, images=images
        )
        from accelab.course.renditions import Renditions, png

        alt = f"The figure above drawn at {len(vals)} values of {name}: " + ", ".join(
            f"{v:g}" for v in vals
        )
        _show_object(Renditions(png(wide), png(narrow), alt))
        return None
    import ipywidgets as widgets
    from IPython.display import Markdown, display

    controls = {}
    for k, (lo, hi, step, default, unit) in specs.items():
        kind = widgets.IntSlider if _is_int_slider(lo, hi, step, default) else widgets.FloatSlider
        controls[k] = kind(
            min=lo,
            max=hi,
            step=step,
            value=default,
            description=_description(k, unit),
            continuous_update=False,
            style={"description_width": "initial"},
            layout=widgets.Layout(width="420px", max_width="100%"),
        )

    def update(**kw):
        try:
            fig = _figure_of(draw(**kw))
        except Exception as exc:  # noqa: BLE001 -- a sentence in place of the figure
            plt.close("all")
            at = ", ".join(_label(k, v, specs[k][4]) for k, v in kw.items())
            display(Markdown(f"**Nothing to draw at {at}**: {exc}"))
            return
        _show(fig)

    display(widgets.interactive(update, **controls))
    return None


def _show_object(obj):
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:  # plain Python: nothing to show on
        return
    if get_ipython() is not None:
        display(obj)


def _show(fig):
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:  # plain Python: nothing to show on
        plt.close(fig)
        return
    if get_ipython() is not None:
        display(fig)
    plt.close(fig)


# ---------------------------------------------------------------- numbers
def _parts(z, unit=None):
    """(x, y, magnitude, angle in deg, unit text) of a complex Quantity or number."""
    if hasattr(z, "to") and unit:
        z = z.to(unit)
    if hasattr(z, "magnitude"):
        mag, u = complex(z.magnitude), f"{z.units:~P}"
    else:
        mag, u = complex(z), unit or ""
    return mag.real, mag.imag, abs(mag), math.degrees(math.atan2(mag.imag, mag.real)), u


def cartesian(z, unit=None, digits=4):
    """``x + j y unit`` of a vector given as a complex Quantity (or number)."""
    x, y, _, _, u = _parts(z, unit)
    sign = "+" if y >= 0 else "-"
    return f"({x:.{digits}g} {sign} j{abs(y):.{digits}g}) {u}".rstrip()


def polar(z, unit=None, digits=4):
    """``r @ angle deg`` of a vector: its magnitude and its angle from +x."""
    _, _, r, ang, u = _parts(z, unit)
    return f"{r:.{digits}g} {u} at {ang:.{digits}g} deg".replace("  ", " ")


def in_g(a):
    """A (real) acceleration Quantity, or the magnitude of a vector one, in g."""
    if np.iscomplexobj(getattr(a, "magnitude", a)):
        a = abs(a)
    return (a / G0).to("dimensionless").magnitude


def stated(value, text, unit=None, sig=None):
    """Assert that ``value`` is what the prose says, ``text`` as printed there
    (``"37"``, ``"-23.47"``, ``"2,100"``, ``"1.5e-6"``): equal to within half
    a unit of its last written digit, or of its ``sig``-th significant digit
    when the prose rounds ("about 2100 g" is ``stated(x, "2100", sig=2)``).
    ``value`` may be a Quantity (then give the ``unit`` the prose uses).
    Returns None, so that a cell of checks shows nothing (the page hides it).

    >>> stated(36.96, "37")
    """
    v = value.to(unit).magnitude if unit is not None else getattr(value, "magnitude", value)
    t = text.replace(",", "").replace("\u2009", "").replace(" ", "").replace("\u2212", "-")
    mant = t.lower().split("e")[0]
    exp = int(t.lower().split("e")[1]) if "e" in t.lower() else 0
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    half = 0.5 * 10.0 ** (exp - decimals)
    target = float(t)
    if sig is not None and target != 0:
        half = 0.5 * 10.0 ** (math.floor(math.log10(abs(target))) - sig + 1)
    if not abs(float(v) - target) <= half * (1 + 1e-9):
        raise AssertionError(
            f"the prose says {text}{' ' + unit if unit else ''} but the "
            f"notebook computes {float(v):.6g}: update the prose"
        )
    return None


def measure(functions, repeats=5, min_time=0.01):
    """Median wall-clock time [s] of each of ``functions`` (no arguments):
    one warm-up call each, then ``repeats`` rounds in which every function is
    timed in turn (each run as many times as fill ``min_time``), so that a
    busy machine slows them all alike."""
    import time

    functions = list(functions)
    for f in functions:
        f()
    loops = []
    for f in functions:
        n, t = 1, 0.0
        while True:
            t0 = time.perf_counter()
            for _ in range(n):
                f()
            t = time.perf_counter() - t0
            if t >= min_time or n >= 1 << 20:
                break
            n *= 2
        loops.append(n)
    samples = [[] for _ in functions]
    for _ in range(repeats):
        for k, f in enumerate(functions):
            t0 = time.perf_counter()
            for _ in range(loops[k]):
                f()
            samples[k].append((time.perf_counter() - t0) / loops[k])
    return [float(np.median(s)) for s in samples]


# ---------------------------------------------------------------- drawing
def vector(ax, start, vec, kind="resultant", label=None, scale=1.0, beside=0.0, **_):
    """Draw ``vec`` (complex) as an arrow from ``start`` (complex, drawing units)
    in the colour and line style of its kind, ``scale * vec`` long, as the
    graphical constructions draw them (:func:`accelab.solver.graphical.draw.arrow`).
    ``label`` is placed when the figure is drawn, clear of the figure's lines,
    texts and other labels. ``beside`` [pt] shifts the arrow to its left
    (negative: right), e.g. off a link it lies along. Returns the tip."""
    from accelab.solver.graphical.draw import arrow

    return arrow(ax, start, vec, kind, label, scale, beside)


def point_label(ax, text, z, **kw):
    """Name the point ``z`` (complex, drawing units): the label is placed when the
    figure is drawn, beside the point and clear of the figure's lines, texts and
    other labels (as :func:`vector` places its labels)."""
    from accelab.solver.graphical.labels import labels_of

    labels_of(ax).add_point(text, complex(z), fontsize=kw.pop("fontsize", 11), **kw)
