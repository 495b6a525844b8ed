"""`accelab figures`: the figures of the README and the course, regenerated."""

import os
import subprocess
import sys

import pytest

from accelab.cli import main
from accelab.solver.graphical.gallery import GALLERY


def test_help_lists_the_figures(capsys):
    with pytest.raises(SystemExit):
        main(["figures", "--help"])
    assert "graphical-fourbar" in capsys.readouterr().out


@pytest.mark.slow
def test_figures_command_regenerates_every_figure(tmp_path):
    out = tmp_path / "figs"
    p = subprocess.run(
        [sys.executable, "-m", "accelab", "figures", "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 0, p.stderr
    written = sorted(os.listdir(out))
    assert written == sorted(
        f"{n}-{k}.{e}" for n in GALLERY for k in ("linkage", "polygons") for e in ("png", "svg")
    )
    # the committed figures/ are what the command makes (up to the renderer's bytes)
    repo = os.path.join(os.path.dirname(__file__), os.pardir, "figures")
    for name in written:
        assert os.path.exists(os.path.join(repo, name)), f"figures/{name} is not committed"


def test_figures_unknown_name(capsys):
    assert main(["figures", "--out", "/tmp/never", "--only", "nope"]) == 2
    assert "graphical-fourbar" in capsys.readouterr().err
