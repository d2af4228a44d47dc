"""Spectrum-compatible records (`pounding match`, :mod:`pounding.spectra.matching`): the
corrected wavelet adds no drift, the matched spectrum is within ±10 % of the target by the
repository's spectrum AND by an independent SciPy integration, the PEER AT2 written is read
back, the reported PGV/PGD/Arias changes agree with an independent computation, and bad
input is one line, exit 2, nothing written."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, trapezoid
from scipy.signal import lsim

from pounding.cli import main
from pounding.ground_motion import el_centro, read_record
from pounding.ground_motion.writers import at2_text
from pounding.spectra import DesignSpectrum, response_spectrum
from pounding.spectra.matching import corrected_wavelet, match_record, sdof_displacements
from pounding.units import G

ROOT = Path(__file__).resolve().parents[2]
TARGET = ROOT / "src" / "pounding" / "examples" / "spectrum_asce7_site.toml"
SITE = DesignSpectrum.asce7(1.0, 0.6, 8.0)


@pytest.fixture(scope="module")
def matched():  # El Centro (40 s at 0.01 s) to the ASCE 7 site spectrum, 0.05-4 s
    return match_record(el_centro(), SITE, (0.05, 4.0))


def _independent_psa(accel: np.ndarray, dt: float, period: float, zeta: float = 0.05,
                     refine: int = 20) -> float:
    """PSA [m/s²] by scipy.signal.lsim on the record linear between samples, sampled
    ``refine`` times finer (so the peak between samples is found to ~(π/refine/N)²)."""
    t = np.arange(accel.size) * dt
    fine = np.linspace(0.0, t[-1], (accel.size - 1) * refine + 1)
    w = 2.0 * math.pi / period
    _, u, _ = lsim(([-1.0], [1.0, 2.0 * zeta * w, w * w]), np.interp(fine, t, accel), fine,
                   interp=True)
    return float(w * w * np.max(np.abs(u)))


def test_corrected_wavelet_adds_no_velocity_or_displacement() -> None:
    t = np.arange(2001) * 0.01
    for peak, period in ((10.0, 1.0), (0.3, 2.0), (19.5, 0.5), (8.0, 4.0)):
        f = corrected_wavelet(t, peak, period)
        v = cumulative_trapezoid(f, t, initial=0.0)
        d = cumulative_trapezoid(v, t, initial=0.0)
        assert abs(v[-1]) < 1e-12 * np.max(np.abs(v)) + 1e-14
        assert abs(d[-1]) < 1e-12 * np.max(np.abs(d)) + 1e-14
    # away from the ends the correction is small: the Gaussian-tapered cosine nearly
    # integrates to zero by itself (its transform at 0 is γ√π exp(−(ω'γ)²/4))
    tau = t - 10.0 + math.atan2(math.sqrt(1 - 0.0025), 0.05) / (2 * math.pi * math.sqrt(1 - 0.0025))
    raw = np.cos(2 * math.pi * math.sqrt(1 - 0.0025) * tau) * np.exp(-(tau / 1.178) ** 2)
    assert np.max(np.abs(corrected_wavelet(t, 10.0, 1.0) - raw)) < 1e-4
    # Δt_j (eq. 14) puts a crest of the oscillator's response at the peak time asked:
    # a local extremum there (measured 10.01 s), of the size of the largest (0.79 of it,
    # which comes a cycle later while the wavelet still drives it)
    u = sdof_displacements(corrected_wavelet(t, 10.0, 1.0), 0.01, 1.0)
    k = int(np.argmax(np.abs(u[990:1011]))) + 990
    assert abs(t[k] - 10.0) <= 0.02 and abs(u[k]) > 0.75 * np.max(np.abs(u))


def test_filter_response_against_lsim() -> None:
    gm = el_centro().trimmed(10.0)
    for period in (0.05, 0.7, 3.0):
        w = 2 * math.pi / period
        _, y, _ = lsim(([-1.0], [1, 0.1 * w, w * w]), gm.accel, gm.time, interp=True)
        u = sdof_displacements(gm.accel, gm.dt, period)
        assert np.max(np.abs(u - y)) < 1e-9 * np.max(np.abs(y))


def test_matched_spectrum_within_ten_percent(matched) -> None:
    assert matched.converged and matched.max_misfit <= 0.10
    # the repository's exact spectrum on another grid than the one checked inside
    periods = np.geomspace(0.05, 4.0, 131)
    psa = response_spectrum(matched.motion, periods).psa_g[0]
    assert np.max(np.abs(psa / SITE.sa_g(periods) - 1.0)) <= 0.10
    # the seed was far off: the matching did something
    seed = response_spectrum(el_centro(), periods).psa_g[0]
    assert np.max(np.abs(seed / SITE.sa_g(periods) - 1.0)) > 0.5
    # an independent SDOF integration (SciPy lsim) at a few periods
    for period in (0.1, 0.3, 1.0, 2.0, 3.5):
        ind = _independent_psa(matched.motion.accel, matched.motion.dt, period) / G
        rep = response_spectrum(matched.motion, [period]).psa_g[0, 0]
        assert ind == pytest.approx(rep, rel=2e-3)
        assert abs(ind / SITE.sa_g(period) - 1.0) <= 0.10


def test_no_baseline_drift_added(matched) -> None:
    t = matched.motion.time
    v = cumulative_trapezoid(matched.motion.accel, t, initial=0.0)
    d = cumulative_trapezoid(v, t, initial=0.0)
    seed = el_centro()
    v0 = cumulative_trapezoid(seed.accel, t, initial=0.0)
    d0 = cumulative_trapezoid(v0, t, initial=0.0)
    # the wavelets add nothing: what is left is the scaled seed's own (PEER processed)
    assert v[-1] == pytest.approx(matched.scale_factor * v0[-1], abs=1e-9)
    assert d[-1] == pytest.approx(matched.scale_factor * d0[-1], abs=1e-9)
    assert abs(v[-1]) < 1e-3 * np.max(np.abs(v)) and abs(d[-1]) < 1e-3 * np.max(np.abs(d))


def test_measures_against_independent_computation(matched) -> None:
    m = matched.measures()
    for key, gm in (("original", el_centro()), ("matched", matched.motion)):
        k = 0 if key == "original" else 1
        v = cumulative_trapezoid(gm.accel, gm.time, initial=0.0)
        d = cumulative_trapezoid(v, gm.time, initial=0.0)
        arias = math.pi / (2 * G) * trapezoid(gm.accel ** 2, gm.time)
        assert m["PGV [m/s]"][k] == pytest.approx(np.max(np.abs(v)), rel=1e-12)
        assert m["PGD [m]"][k] == pytest.approx(np.max(np.abs(d)), rel=1e-12)
        assert m["Arias intensity [m/s]"][k] == pytest.approx(arias, rel=1e-12)
        assert m["PGA [g]"][k] == pytest.approx(np.max(np.abs(gm.accel)) / G, rel=1e-12)
    # El Centro's Arias intensity in this digitisation: 1.70 m/s (independent of pounding)
    assert m["Arias intensity [m/s]"][0] == pytest.approx(1.70, abs=0.01)


def _short_seed(tmp_path: Path) -> Path:
    seed = tmp_path / "seed.AT2"
    seed.write_text(at2_text(el_centro().trimmed(20.0), "seed", "El Centro, first 20 s"),
                    encoding="utf-8")
    return seed


def test_cli_writes_an_at2_read_back(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    seed, out = _short_seed(tmp_path), tmp_path / "m.AT2"
    assert main(["match", str(seed), "--target", str(TARGET), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    for word in ("PGV [m/s]", "PGD [m]", "Arias intensity [m/s]", "final velocity", "record:"):
        assert word in text, word
    back = read_record(out)
    direct = match_record(read_record(seed), SITE, (0.05, 4.0))
    assert back.dt == pytest.approx(0.01, rel=1e-12) and back.npts == direct.motion.npts
    assert np.max(np.abs(back.accel - direct.motion.accel)) <= 5e-8 * direct.motion.pga
    psa = response_spectrum(back, np.geomspace(0.05, 4.0, 60)).psa_g[0]
    assert np.max(np.abs(psa / SITE.sa_g(np.geomspace(0.05, 4.0, 60)) - 1.0)) <= 0.10
    ratio = direct.measures()["Arias intensity [m/s]"]
    assert f"{ratio[1] / ratio[0]:.3f}" in text
    # again: refused without --overwrite, replaced with it (pounding match wrote it)
    before = out.read_bytes()
    assert main(["match", str(seed), "--target", str(TARGET), "--out", str(out)]) == 2
    assert out.read_bytes() == before
    assert main(["match", str(seed), "--target", str(TARGET), "--out", str(out),
                 "--overwrite"]) == 0


@pytest.mark.parametrize(("args", "field"), [
    (["--range", "0.05,x"], "--range"),
    (["--range", "4,0.05"], "--range"),
    (["--tolerance", "0"], "--tolerance"),
    (["--damping", "1.5"], "--damping"),
    (["--range", "0.05,15"], "--range"),
])
def test_bad_input_one_line_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                   args: list[str], field: str) -> None:
    seed, out = _short_seed(tmp_path), tmp_path / "m.AT2"
    assert main(["match", str(seed), "--target", str(TARGET), "--out", str(out), *args]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error:") and field in err[0]
    assert not out.exists()


def test_out_never_overwrites_a_users_file(tmp_path: Path,
                                           capsys: pytest.CaptureFixture[str]) -> None:
    seed = _short_seed(tmp_path)
    users = tmp_path / "mine.AT2"
    users.write_text("my own record\n", encoding="utf-8")
    assert main(["match", str(seed), "--target", str(TARGET), "--out", str(users),
                 "--overwrite"]) == 2
    assert users.read_text(encoding="utf-8") == "my own record\n"
    assert main(["match", str(seed), "--target", str(TARGET), "--out",
                 str(tmp_path / "m.txt")]) == 2
    assert not (tmp_path / "m.txt").exists()
    err = capsys.readouterr().err
    assert "not a record pounding match wrote" in err and ".AT2" in err


def test_not_reached_exits_1_and_writes_nothing(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    seed, out = _short_seed(tmp_path), tmp_path / "m.AT2"
    assert main(["match", str(seed), "--target", str(TARGET), "--out", str(out),
                 "--iterations", "1", "--tolerance", "0.01"]) == 1
    assert "nothing written" in capsys.readouterr().err
    assert not out.exists()
