"""pint's unit definitions, parsed once per machine instead of once per process.

Building pint's default registry parses its definitions file, about 0.2 s of
CPU in every process that reads a quantity: each ``accelab`` command, each
notebook kernel, each grader. pint can keep the parsed definitions on disk
(its ``cache_folder``); :func:`new_registry` gives it a folder of accelab's
own, one per pint version (pint's cache key names the definitions and the
Python version, not pint's), in the user's cache directory
(``$XDG_CACHE_HOME/accelab``, else ``~/.cache/accelab``).

The cache is only a shortcut: where the folder cannot be made or written
(a read-only home, a sandbox), or what it holds cannot be read (a file
half-written by a killed process), the registry is built from the
definitions as without it, and an unreadable folder is removed so that the
next process writes it afresh. The cache is read only by the account that
wrote it (it lives in that account's home).
"""

import os
import shutil
from pathlib import Path

import pint

__all__ = ["new_registry", "cache_folder"]


def cache_folder() -> Path | None:
    """Where this pint version's parsed definitions are kept, or None (no home).
    A relative ``XDG_CACHE_HOME`` is ignored, as the XDG specification says."""
    base = os.environ.get("XDG_CACHE_HOME", "")
    if not os.path.isabs(base):
        home = os.path.expanduser("~")
        if not os.path.isabs(home):
            return None
        base = os.path.join(home, ".cache")
    return Path(base) / "accelab" / f"pint-{pint.__version__}"


def new_registry() -> pint.UnitRegistry:
    """pint's default registry, from the cached parse where there is one."""
    folder = cache_folder()
    if folder is not None:
        try:
            return pint.UnitRegistry(cache_folder=folder)
        except Exception:  # noqa: BLE001 - any failure of the cache: build without it
            shutil.rmtree(folder, ignore_errors=True)
    return pint.UnitRegistry()
