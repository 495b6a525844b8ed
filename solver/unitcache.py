"""pint's unit definitions, parsed once per machine instead of once per process.

Building pint's default registry parses its definitions file, about 0.2 s of
CPU in every process that reads a quantity: each ``accelab`` command, each
notebook kernel, each grader. pint can keep the parsed definitions on disk
(its ``cache_folder``); :func:`new_registry` gives it a folder of accelab's
own, one per pint installation, in the user's cache directory
(``$XDG_CACHE_HOME/accelab``, else ``~/.cache/accelab``): ``pint-VERSION-TAG``,
the tag a digest of where that pint is installed. One per version, because
pint's cache key names the definitions and the Python version, not pint's; one
per installation, because pint names a parsed file by its content but keeps in
it the absolute path of each file it imports (``default_en.txt`` imports
``constants_en.txt``): a parse written by another environment sends a reader
to that environment's file. Where that file is gone, or out of sight (the
grading sandbox shows no other environment), a shared folder fails, and each
process parses the definitions again.

The cache is only a shortcut: where the folder cannot be made or written
(a read-only home, a sandbox), or what it holds cannot be read (a file
half-written by a killed process), the registry is built from the
definitions as without it, and an unreadable folder is removed so that the
next process writes it afresh. The cache is read only by the account that
wrote it (it lives in that account's home).
"""

import hashlib
import os
import shutil
from pathlib import Path

import pint

__all__ = ["new_registry", "cache_folder", "installation_tag"]


def cache_folder() -> Path | None:
    """Where this pint installation's parsed definitions are kept, or None (no home).
    A relative ``XDG_CACHE_HOME`` is ignored, as the XDG specification says."""
    base = os.environ.get("XDG_CACHE_HOME", "")
    if not os.path.isabs(base):
        home = os.path.expanduser("~")
        if not os.path.isabs(home):
            return None
        base = os.path.join(home, ".cache")
    return Path(base) / "accelab" / f"pint-{pint.__version__}-{installation_tag()}"


def installation_tag() -> str:
    """12 hex digits naming the folder pint is installed in (its real path)."""
    where = os.path.dirname(os.path.realpath(pint.__file__))
    return hashlib.sha256(where.encode()).hexdigest()[:12]


def new_registry() -> pint.UnitRegistry:
    """pint's default registry, from the cached parse where there is one."""
    folder = cache_folder()
    if folder is not None:
        try:
            return pint.UnitRegistry(cache_folder=folder)
        except Exception:  # noqa: BLE001 - any failure of the cache: build without it
            shutil.rmtree(folder, ignore_errors=True)
    return pint.UnitRegistry()
