"""The self-study site in a real browser.

Builds the site from the executed course notebooks (the ones
``tests/test_course.py`` executed in this session, or executes them once),
then opens every page in headless Chromium (Debian's ``chromium`` driven by
its ``chromium-driver`` through Selenium) and checks what a reader sees:

* equations: every ``<math>`` element of the page is in the DOM, laid out by
  the browser's MathML engine (``display: math``), with a non-zero size, also
  inside folded answers; fractions stack; equation numbers sit at the right;
* figures: every image loaded (``naturalWidth > 0``), as many as the build wrote;
* navigation: previous / contents / next links as the outline says, every
  relative link and in-page anchor resolves, and following "next" works;
* nothing loads from the network, and no widget state leaks onto a page.

If Chromium is missing the set-up installs it with apt-get; it skips (saying
why) only when it cannot.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from urllib.parse import unquote, urlparse

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import test_course  # noqa: E402  (shares the session's executed notebooks)
from course.build_site import build  # noqa: E402

pytestmark = pytest.mark.slow

CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--window-size=1100,900"]
PAGES = ["index"] + [p.stem for p in test_course.NOTEBOOKS]


def _ensure_chromium():
    """Paths of chromium and chromedriver, installing them if needed; or a reason to skip."""
    found = [shutil.which("chromium") or (CHROMIUM if os.path.exists(CHROMIUM) else None),
             shutil.which("chromedriver") or (DRIVER if os.path.exists(DRIVER) else None)]
    if all(found):
        return found, None
    if not shutil.which("apt-get"):
        return None, "chromium is not installed and there is no apt-get to install it"
    cmd = ["apt-get", "install", "-y", "-q", "chromium", "chromium-driver"]
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    for attempt in (cmd, ["apt-get", "update", "-q"], cmd):
        try:
            done = subprocess.run(attempt, capture_output=True, text=True, timeout=900, env=env)
        except (OSError, subprocess.TimeoutExpired) as exc:
            return None, f"could not install chromium with apt-get: {exc}"
        if attempt is cmd and done.returncode == 0:
            break
    found = [shutil.which("chromium"), shutil.which("chromedriver")]
    if not all(found):
        return None, ("chromium / chromium-driver are missing and apt-get could not install "
                      f"them: {done.stderr.strip()[-300:]}")
    return found, None


@pytest.fixture(scope="session")
def site(tmp_path_factory):
    """The site built from this session's executed notebooks: (folder, manifest)."""
    ok, failed = test_course.execute_all()
    if not ok:
        pytest.fail("no course notebook executed: " + "; ".join(failed.values())[:500])
    out = tmp_path_factory.mktemp("site")
    manifest = build(ok, out, log=lambda *a: None)
    manifest["failed"] = sorted(failed)
    for stem, path in ok.items():
        manifest["pages"][f"{stem}.html"]["source"] = path
    return out, manifest


@pytest.fixture(scope="session")
def browser():
    paths, reason = _ensure_chromium()
    if reason:
        pytest.skip(reason)
    webdriver = pytest.importorskip("selenium.webdriver", reason="selenium is not installed")
    from selenium.webdriver.chrome.service import Service
    profile = tempfile.mkdtemp(prefix="accelab-chromium-")
    options = webdriver.ChromeOptions()
    options.binary_location = paths[0]
    for flag in FLAGS + [f"--user-data-dir={profile}"]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(options=options, service=Service(paths[1]))
    driver.set_page_load_timeout(60)
    yield driver
    driver.quit()
    shutil.rmtree(profile, ignore_errors=True)


PAGE_STATE = """
document.querySelectorAll('details').forEach(d => d.open = true);   // unfold the answers
const box = e => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
const maths = [...document.querySelectorAll('math')];
const fracs = [...document.querySelectorAll('mfrac')].filter(f => f.children.length === 2);
const eqs = [...document.querySelectorAll('.equation')];
const ext = [...document.querySelectorAll('[src], link[href], script')]
    .map(e => e.getAttribute('src') || e.getAttribute('href') || '')
    .filter(u => /^(https?:)?\\/\\//.test(u));
return {
  title: document.title,
  math: maths.map(m => ({display: getComputedStyle(m).display, box: box(m)})),
  fractions_stacked: fracs.filter(f => box(f.children[0])[3] <= box(f.children[1])[1] + 1).length,
  fractions: fracs.length,
  equations: eqs.map(e => ({math: box(e.querySelector('math')),
                            number: e.querySelector('.eqno') ? box(e.querySelector('.eqno')) : null,
                            right: box(e)[2]})),
  images: [...document.images].map(i => ({src: i.getAttribute('src'), complete: i.complete,
                                          width: i.naturalWidth})),
  links: [...document.querySelectorAll('a[href]')].map(a => a.getAttribute('href')),
  ids: [...document.querySelectorAll('[id]')].map(e => e.id),
  pager: [...document.querySelectorAll('nav.pager')].map(n =>
      [...n.querySelectorAll('a')].map(a => [a.className, a.getAttribute('href')])),
  external: ext,
  text: document.body.innerText,
};
"""


def _tags(ipynb):
    """The \\tag{...} numbers of a notebook's display equations, in order."""
    import nbformat
    nb = nbformat.read(ipynb, as_version=4)
    text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
    return [m[-1] for m in (re.findall(r"\\tag\*?\{([^}]*)\}", block)
                            for block in re.findall(r"\$\$(.+?)\$\$", text, flags=re.S)) if m]


def _state(browser, path):
    browser.get(path.resolve().as_uri())
    browser.execute_script("return Promise.all([...document.images].map(i => i.decode()"
                           ".catch(() => null)))")
    return browser.execute_script(PAGE_STATE)


@pytest.mark.parametrize("page", PAGES)
def test_page_renders(site, browser, page):
    out, manifest = site
    name = f"{page}.html"
    if name not in manifest["pages"]:
        pytest.skip(f"{page} has no page: its notebook failed to execute (see test_course)")
    info = manifest["pages"][name]
    html = (out / name).read_text()
    st = _state(browser, out / name)
    assert st["title"].startswith(info["title"][:20])

    # equations: all there, laid out as MathML, not empty, fractions stacked
    assert len(st["math"]) == html.count("<math"), "math elements lost by the parser"
    if page != "index":
        assert len(st["math"]) > 0, "a lesson with no equations"
        assert info["equations"] > 0, "no display equations"
    for m in st["math"]:
        assert m["display"] in ("math", "block math", "inline math"), \
            f"<math> not laid out as MathML (display {m['display']!r})"
        left, top, right, bottom = m["box"]
        assert right - left > 0 and bottom - top > 0, "an equation with no size"
    assert st["fractions_stacked"] == st["fractions"], "a fraction is not stacked"
    assert "math-fallback" not in html, "LaTeX that could not be typeset"
    for eq in st["equations"]:
        if eq["number"]:
            num, mth = eq["number"], eq["math"]
            assert abs(num[2] - eq["right"]) < 2, "equation number not at the right"
            mid = (num[1] + num[3]) / 2
            beside = mth[1] - 2 <= mid <= mth[3] + 2 and num[0] >= mth[2] - 1
            below = num[1] >= mth[3] - 2          # a wide equation pushes it to the next line
            assert beside or below, "equation number neither beside nor below its equation"
    if page != "index":   # every \tag of the notebook is shown as the chapter's number
        tags = re.findall(r'class="eqno">\(([^)<]*)\)<', html)
        assert tags == _tags(info["source"]), "equation numbers differ from the notebook's"
        assert all(re.fullmatch(r"\d+\.\d+[a-z]?", t) for t in tags), tags

    # figures: every image loaded, and all that the build wrote are on the page
    assert len(st["images"]) == len(info["figures"])
    for img in st["images"]:
        assert img["complete"] and img["width"] > 0, f"figure not loaded: {img['src']}"
    if page != "index":
        assert st["images"], "a lesson with no figure"

    # navigation and links
    if page != "index":
        for bar in st["pager"]:
            links = dict(bar)
            assert links["contents"] == "index.html"
            assert links.get("prev") == info["prev"]
            assert links.get("next") == info["next"]
    for href in st["links"]:
        target = urlparse(href)
        assert not target.scheme and not target.netloc, f"external link {href}"
        if target.path:
            assert (out / unquote(target.path)).is_file(), f"broken link {href}"
        if target.fragment and not target.path:
            assert target.fragment in st["ids"], f"broken anchor {href}"
    assert not st["external"], f"loads from the network: {st['external']}"
    assert "widget-view+json" not in st["text"] and "interactive(children" not in st["text"]
    severe = [e for e in browser.get_log("browser") if e.get("level") == "SEVERE"]
    assert not severe, severe


def test_outline_and_next_link(site, browser):
    """The index lists every page in order, and following the links walks the course."""
    out, manifest = site
    st = _state(browser, out / "index.html")
    lessons = [h for h in st["links"] if re.match(r"\d\d_.*\.html$", h)]
    expected = sorted(k for k in manifest["pages"] if k != "index.html")
    assert lessons == expected
    browser.get((out / expected[0]).resolve().as_uri())
    for name in expected[1:]:
        browser.find_element("css selector", "nav.pager a.next").click()
        assert browser.current_url.endswith("/" + name)
    browser.find_element("css selector", "nav.pager a.contents").click()
    assert browser.current_url.endswith("/index.html")
