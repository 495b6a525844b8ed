"""A player for the course's animations: play, pause, step, a frame slider.

:func:`player_html` turns lists of frames (PNG bytes) into one self-contained
piece of HTML: the first frame as an image, buttons to play and pause, to
step one frame back or forward and to go to the first frame, a slider over
the frames with the value of the input angle of the frame shown, and a speed
control. The keyboard works too when the player has the focus: space plays
and pauses, the arrow keys step. It needs nothing from the network, so it
works in Jupyter (a trusted notebook runs the script of an HTML output), on
the documentation site and in a saved HTML page.

A player may hold several renditions of one animation (``{"wide": frames,
"narrow": frames}``): each is marked ``accelab-wide`` / ``accelab-narrow``,
the site's stylesheet shows the one that fits the screen (a small ``<style>``
in the HTML does the same in Jupyter), and one set of controls drives both.

The frames are ``data:`` URIs in a JSON list inside the player; the site's
build writes them out to image files (``docs/_ext/accelab_docs.py``), so a
page loads only the frames it plays.
"""

import base64
import html
import json
import uuid

__all__ = ["player_html", "STYLE", "SCRIPT"]

#: the layout of the player, scoped to its class (the site's stylesheet adds to it)
STYLE = """
.accelab-player { max-width: 100%; margin: 0 auto; }
.accelab-player .accelab-frames { position: relative; }
.accelab-player img { display: block; max-width: 100%; height: auto; margin: 0 auto; }
.accelab-player .accelab-controls { display: flex; flex-wrap: wrap; align-items: center;
  gap: .35rem .5rem; margin: .4rem 0 .2rem; font-size: .95rem; }
.accelab-player button { font: inherit; min-width: 2.6rem; min-height: 2.2rem; padding: 0 .5rem;
  border: 1px solid #888; border-radius: .3rem; background: #f4f4f4; color: #222; cursor: pointer; }
.accelab-player button:hover { background: #e6e6e6; }
.accelab-player button.accelab-play { min-width: 5.2rem; font-weight: 600; }
.accelab-player input[type=range] { flex: 1 1 10rem; min-width: 8rem; }
.accelab-player .accelab-readout { min-width: 7.5rem; font-variant-numeric: tabular-nums; }
.accelab-player select { font: inherit; }
@media (max-width: 599.98px) { .accelab-player .accelab-wide { display: none; } }
@media (min-width: 600px) { .accelab-player .accelab-narrow { display: none; } }
"""

#: the player's behaviour; one copy per page is enough, each player finds its own elements
SCRIPT = """
(function () {
  function setup(root) {
    if (root.dataset.ready) return;
    root.dataset.ready = "1";
    var data = JSON.parse(root.querySelector("script.accelab-frames-data").textContent);
    var imgs = {};
    root.querySelectorAll("img[data-rendition]").forEach(function (img) {
      imgs[img.dataset.rendition] = img;
    });
    var n = data.labels.length, k = 0, timer = null;
    var slider = root.querySelector("input[type=range]");
    var readout = root.querySelector(".accelab-readout");
    var play = root.querySelector("button.accelab-play");
    var speed = root.querySelector("select");
    function show(i) {
      k = (i + n) % n;
      Object.keys(imgs).forEach(function (r) { imgs[r].src = data.frames[r][k]; });
      slider.value = k;
      readout.textContent = data.labels[k];
    }
    function stop() {
      if (timer) { clearInterval(timer); timer = null; }
      play.textContent = "\\u25B6 Play"; play.setAttribute("aria-label", "Play");
    }
    function start() {
      stop();
      timer = setInterval(function () { show(k + 1); }, data.interval / parseFloat(speed.value));
      play.textContent = "\\u275A\\u275A Pause"; play.setAttribute("aria-label", "Pause");
    }
    play.addEventListener("click", function () { timer ? stop() : start(); });
    function on(cls, go) {
      root.querySelector("button." + cls).addEventListener("click", function () { stop(); go(); });
    }
    on("accelab-back", function () { show(k - 1); });
    on("accelab-next", function () { show(k + 1); });
    on("accelab-first", function () { show(0); });
    slider.addEventListener("input", function () { stop(); show(parseInt(slider.value, 10)); });
    speed.addEventListener("change", function () { if (timer) start(); });
    root.addEventListener("keydown", function (e) {
      if (e.target === speed) return;
      if (e.key === " " || e.key === "k") { e.preventDefault(); timer ? stop() : start(); }
      else if (e.key === "ArrowLeft") { e.preventDefault(); stop(); show(k - 1); }
      else if (e.key === "ArrowRight") { e.preventDefault(); stop(); show(k + 1); }
    });
    // load the frames of the rendition in view once, so that playing is smooth
    Object.keys(imgs).forEach(function (r) {
      if (imgs[r].offsetParent === null) return;
      data.frames[r].forEach(function (src) { var im = new Image(); im.src = src; });
    });
    show(0);
  }
  function all() { document.querySelectorAll(".accelab-player").forEach(setup); }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", all);
  else all();
})();
"""


def _uri(png):
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def player_html(renditions, labels, alt, sizes, fps=10):
    """The HTML of a player.

    Parameters
    ----------
    renditions : dict
        ``{"wide": [png bytes, ...], "narrow": [...]}`` (one or more; the
        frames of all renditions correspond one to one).
    labels : list of str
        What each frame shows, in plain text (``"θ₂ = 120°"``), shown beside
        the slider.
    alt : str
        What the animation shows, for a reader who cannot see it.
    sizes : dict
        ``{rendition: (width, height)}`` [px] of the frames.
    fps : float
        Frames per second at normal speed.
    """
    names = list(renditions)
    n = len(labels)
    if any(len(frames) != n for frames in renditions.values()):
        raise ValueError("player_html: every rendition needs one frame per label")
    uid = "accelab-player-" + uuid.uuid4().hex[:10]
    data = {
        "interval": round(1000 / fps),
        "labels": list(labels),
        "frames": {r: [_uri(f) for f in frames] for r, frames in renditions.items()},
    }
    alt_attr = html.escape(alt, quote=True)
    images = "".join(
        f'<img class="accelab-{r}" data-rendition="{r}" src="{data["frames"][r][0]}" '
        f'width="{sizes[r][0]}" height="{sizes[r][1]}" alt="{alt_attr}">'
        for r in names
    )
    speeds = "".join(
        f'<option value="{v}"{" selected" if v == "1" else ""}>{t}</option>'
        for v, t in (
            ("0.25", "\u00bc\u00d7"),
            ("0.5", "\u00bd\u00d7"),
            ("1", "1\u00d7"),
            ("2", "2\u00d7"),
        )
    )
    payload = json.dumps(data).replace("</", "<\\/")
    return _ascii(
        f'<div class="accelab-player" id="{uid}" tabindex="0" role="group" '
        f'aria-label="Animation: {alt_attr}">'
        f"<style>{STYLE}</style>"
        f'<div class="accelab-frames">{images}</div>'
        '<div class="accelab-controls">'
        '<button type="button" class="accelab-first" title="First frame" '
        'aria-label="First frame">\u21e4</button>'
        '<button type="button" class="accelab-back" title="One frame back (\u2190)" '
        'aria-label="One frame back">\u25c0\u2502</button>'
        '<button type="button" class="accelab-play" title="Play or pause (space)" '
        'aria-label="Play">\u25b6 Play</button>'
        '<button type="button" class="accelab-next" title="One frame on (\u2192)" '
        'aria-label="One frame on">\u2502\u25b6</button>'
        f'<input type="range" min="0" max="{n - 1}" step="1" value="0" '
        f'aria-label="Frame" title="Drag to any frame">'
        f'<span class="accelab-readout" aria-live="off">{html.escape(labels[0])}</span>'
        f'<label>speed <select aria-label="Speed">{speeds}</select></label>'
        "</div>"
        f'<script type="application/json" class="accelab-frames-data">{payload}</script>'
        f"<script>{SCRIPT}</script>"
        "</div>"
    )


def _ascii(text):
    """``text`` with every character outside ASCII written as an HTML character
    reference, so that the player reads the same whatever the page's encoding."""
    return text.encode("ascii", "xmlcharrefreplace").decode("ascii")
