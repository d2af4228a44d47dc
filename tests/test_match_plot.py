"""`pounding match --plot`: the figure of a match — target with its ±tolerance band, the
seed's spectrum (as given and scaled) and the matched spectrum, PSA in g against period in
s — drawn from the match's own spectra, and refused before any work when it cannot be
written."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.ground_motion import el_centro
from pounding.ground_motion.writers import at2_text
from pounding.plot.matching import plot_match
from pounding.spectra import DesignSpectrum, response_spectrum
from pounding.spectra.matching import match_record
from pounding.units import G

ROOT = Path(__file__).resolve().parents[1]
TARGET = ROOT / "src" / "pounding" / "examples" / "spectrum_asce7_site.toml"


@pytest.fixture(scope="module")
def short_match():
    seed = el_centro().trimmed(10.0)
    target = DesignSpectrum.from_file(TARGET)
    return seed, target, match_record(seed, target, (0.1, 2.0))


def test_the_figure_draws_the_matchs_spectra_in_g_against_s(short_match):
    seed, target, result = short_match
    fig = plot_match(result, seed.name, target.name)
    ax = fig.axes[0]
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    t = result.periods
    # the seed's spectrum, recomputed here from the record
    np.testing.assert_allclose(lines[f"{seed.name} (seed)"].get_ydata(),
                               response_spectrum(seed, t).psa[0] / G, rtol=1e-9)
    np.testing.assert_allclose(lines[target.name].get_ydata(), target.sa_g(t), rtol=1e-12)
    matched = next(v for k, v in lines.items() if k.startswith("matched"))
    np.testing.assert_allclose(matched.get_ydata(),
                               response_spectrum(result.motion, t).psa[0] / G, rtol=1e-9)
    band = ax.collections[0].get_paths()[0].vertices[:, 1]
    assert band.min() == pytest.approx(0.9 * target.sa_g(t).min(), rel=1e-9)
    assert band.max() == pytest.approx(1.1 * target.sa_g(t).max(), rel=1e-9)
    assert ax.get_xscale() == "log"
    assert "[g]" in ax.get_ylabel() and "[s]" in ax.get_xlabel()


def test_match_writes_the_figure(tmp_path, short_match):
    seed, _, _ = short_match
    rec = tmp_path / "seed.AT2"
    rec.write_text(at2_text(seed, "seed", "El Centro, 10 s"))
    out, fig = tmp_path / "m.AT2", tmp_path / "match.png"
    assert main(["match", str(rec), "--target", str(TARGET), "--range", "0.1,2",
                 "--out", str(out), "--plot", str(fig)]) == 0
    assert out.is_file() and fig.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_plot_that_cannot_be_written_is_refused_before_any_work(tmp_path, capsys):
    rec = tmp_path / "seed.AT2"
    rec.write_text(at2_text(el_centro().trimmed(5.0), "seed", "El Centro, 5 s"))
    assert main(["match", str(rec), "--target", str(TARGET), "--out",
                 str(tmp_path / "m.AT2"), "--plot", str(tmp_path / "match.xyz")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--plot" in err[0] and "match.xyz" in err[0], err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["seed.AT2"]
