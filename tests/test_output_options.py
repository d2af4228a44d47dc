"""Output-file options of every command are checked before any work: a folder where the
file goes, a parent that is a file, or a figure suffix no format has is one line naming the
option, exit status 2, and nothing is computed or written."""

from __future__ import annotations

from pathlib import Path

import pytest

from pounding.cli import main
from pounding.io.files import FIGURE_SUFFIXES

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
TARGET = ROOT / "examples" / "spectrum_asce7_site.toml"
ELC = ROOT / "src" / "pounding" / "data" / "records" / "elcentro_1940_IV_ELC9_180_PEER.AT2"


def test_figure_suffixes_are_formats_matplotlib_writes():
    import matplotlib.pyplot as plt

    fig = plt.figure()
    supported = {f".{s}" for s in fig.canvas.get_supported_filetypes()}
    plt.close(fig)
    assert set(FIGURE_SUFFIXES) <= supported


@pytest.mark.parametrize("args, option", [
    (["zeta", "--plot", "{d}/fig.xyz"], "--plot"),
    (["audit", "--csv", "{f}/a.csv"], "--csv"),
    (["ellipse", "--plot", "{d}/e.xyz"], "--plot"),
    (["spectrum", str(ELC), "--csv", "{f}/x.csv"], "--csv"),
    (["spectrum", str(ELC), "--plot", "{d}"], "--plot"),
    (["suite", "--design", str(TARGET), "--t1", "1", "--csv", "{f}/x.csv"], "--csv"),
    (["gap", str(SEED), "--plot", "{d}/g.txt"], "--plot"),
    (["report", "{d}", "--html", "{d}"], "--html"),
])
def test_a_bad_output_file_is_one_line_before_any_work(tmp_path, capsys, args, option):
    afile = tmp_path / "afile"
    afile.write_text("a file, not a folder\n")
    argv = [a.format(d=tmp_path, f=afile) for a in args]
    capsys.readouterr()
    assert main(argv) == 2
    captured = capsys.readouterr()
    err = captured.err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {option}:"), err
    assert captured.out == ""  # nothing computed and printed first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]
