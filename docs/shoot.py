"""Screenshots of built pages, as a reader sees them: ``python docs/shoot.py
[--width 390] [--full] PAGE ...`` (PAGE relative to build/docs, e.g.
``course/05_coriolis.html``) writes ``build/docs-shots/<page>-<width>.png``.

The site is served on 127.0.0.1 by a throw-away HTTP server, and headless
Chromium (Debian's chromium + chromium-driver, through Selenium) renders it
after MathJax has typeset the page.
"""

import argparse
import functools
import http.server
import shutil
import sys
import tempfile
import threading
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "build" / "docs"
SHOTS = ROOT / "build" / "docs-shots"
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--no-first-run",
    "--hide-scrollbars",
    "--force-device-scale-factor=1",
]


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(folder):
    """Serve ``folder`` on 127.0.0.1 in a thread; returns (server, base url)."""
    handler = functools.partial(_Quiet, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


def chrome(width, height=900, extra=()):
    """A headless Chromium at this width; returns (driver, profile folder to remove)."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    profile = tempfile.mkdtemp(prefix="accelab-shot-")
    for flag in FLAGS + [
        f"--window-size={width},{height}",
        f"--user-data-dir={profile}",
        *extra,
    ]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    driver = webdriver.Chrome(options=options, service=Service("/usr/bin/chromedriver"))
    driver.set_page_load_timeout(60)
    if width < 500:  # below Chromium's smallest window: emulate the phone's viewport
        driver.execute_cdp_cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": True},
        )
    return driver, profile


WAIT_MATH = """
const done = arguments[arguments.length - 1];
const ready = () => (window.MathJax && MathJax.startup && MathJax.startup.promise)
    ? MathJax.startup.promise : Promise.resolve();
Promise.all([ready(), ...[...document.images].map(i => i.decode().catch(() => null))])
    .then(() => setTimeout(() => done(true), 100), () => done(false));
"""


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pages", nargs="+")
    parser.add_argument("--width", type=int, action="append")
    parser.add_argument("--height", type=int, default=900)
    parser.add_argument("--full", action="store_true", help="the whole page, not one screen")
    parser.add_argument("--scroll", type=int, default=0, help="scroll down this many px first")
    args = parser.parse_args(argv)
    SHOTS.mkdir(parents=True, exist_ok=True)
    server, base = serve(SITE)
    for width in args.width or [1366, 390]:
        driver, profile = chrome(width, args.height)
        driver.set_script_timeout(60)
        try:
            for page in args.pages:
                driver.get(base + page)
                driver.execute_async_script(WAIT_MATH)
                if args.full:
                    h = driver.execute_script("return document.documentElement.scrollHeight")
                    if width < 500:  # the phone's emulated viewport, as tall as the page
                        driver.execute_cdp_cmd(
                            "Emulation.setDeviceMetricsOverride",
                            {
                                "width": width,
                                "height": min(h, 16000),
                                "deviceScaleFactor": 1,
                                "mobile": True,
                            },
                        )
                        driver.execute_async_script(WAIT_MATH)
                    else:
                        driver.set_window_size(width, min(h + 100, 16000))
                elif args.scroll:
                    driver.execute_script(f"window.scrollTo(0, {args.scroll})")
                name = page.replace("/", "_").replace(".html", "") + f"-{width}"
                if args.scroll:
                    name += f"-at{args.scroll}"
                out = SHOTS / f"{name}.png"
                driver.save_screenshot(str(out))
                print(out)
        finally:
            driver.quit()
            shutil.rmtree(profile, ignore_errors=True)
    server.shutdown()


if __name__ == "__main__":
    sys.exit(main())
