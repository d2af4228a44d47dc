"""Record scaling (``pounding.spectra.scaling``, ``pounding suite``, ``record.sa_g``) checked
against computations that share no code with it: each scaled record's spectrum recomputed
by the plain reference (matrix exponentials, ``pounding.spectra.reference``) or SciPy
``solve_ivp``, PGAs read off the raw samples, the least-squares factor found by a numerical
minimiser, and the dispersion by Python's ``statistics``."""

from __future__ import annotations

import csv
import math
import statistics

import numpy as np
import pytest
from scipy.optimize import minimize_scalar
from spectra_ivp import ivp_peaks

from pounding.cli import main
from pounding.config import load_config
from pounding.ground_motion import bundled_suite
from pounding.spectra import DesignSpectrum, scale_suite, scale_to_sa
from pounding.spectra.reference import reference_peaks
from pounding.spectra.scaling import code_period_range
from pounding.units import G

T1 = 1.0
TARGET = DesignSpectrum.asce7(1.0, 0.6)  # ASCE 7 §11.4.6: Sa(1 s) = S_D1 = 0.6 g


@pytest.fixture(scope="module")
def suite():
    """Four records of the bundled suite, their first 12 s (the strong motion)."""
    return [m.trimmed(12.0) for m in list(bundled_suite())[:4]]


def psa_g_reference(motion, periods, factor=1.0):
    """PSA [g] of the record times ``factor`` by the plain reference."""
    sd, _ = reference_peaks(factor * np.asarray(motion.accel), motion.dt, periods, [0.05])
    return sd[0] * (2 * np.pi / np.asarray(periods)) ** 2 / G


def test_period_range_is_the_codes():
    # EN 1998-1 §3.2.3.1.2(4): 0.2 T1 to 2 T1; ASCE 7-22 §16.2.3.1: lower bound at most 0.2 T1
    assert code_period_range(1.5, "en1998-1") == pytest.approx((0.3, 3.0))
    assert code_period_range(1.5, "asce7-22") == pytest.approx((0.3, 3.0))


def test_each_record_to_sa_t1(suite):
    r = scale_suite(suite, TARGET, T1, method="sa")
    for m, f in zip(suite, r.factors, strict=True):
        u, _ = ivp_peaks(f * np.asarray(m.accel), m.dt, T1, 0.05)
        assert u * (2 * math.pi / T1) ** 2 / G == pytest.approx(0.6, rel=1e-8)
    assert r.dispersion[r.at_period] == pytest.approx(0.0, abs=1e-12)


def test_each_record_to_the_targets_pga(suite):
    r = scale_suite(suite, TARGET, T1, method="pga")
    for m, f in zip(suite, r.factors, strict=True):
        # ASCE 7 §11.4.6: Sa(0) = 0.4 S_DS
        assert f * np.max(np.abs(m.accel)) / G == pytest.approx(0.4, rel=1e-12)


def test_one_factor_keeps_the_mean_at_90_percent_of_the_target(suite):
    r = scale_suite(suite, TARGET, T1, method="code", n_periods=25)
    assert np.all(r.factors == r.factors[0])
    f = r.factors[0]
    inside = (r.periods >= 0.2 * T1) & (r.periods <= 2 * T1)
    t = r.periods[inside]
    mean = np.mean([psa_g_reference(m, t, f) for m in suite], axis=0)
    ratio = mean / TARGET.sa_g(t)
    assert ratio.min() == pytest.approx(0.9, rel=1e-6)  # binding at one period
    assert np.all(ratio >= 0.9 * (1 - 1e-6))


def test_eurocode_8_also_keeps_the_mean_pga_at_ag_s(suite):
    ec8 = DesignSpectrum.eurocode8(0.4, "C", 1)  # a_g S = 0.4 × 1.15 = 0.46 g
    r = scale_suite(suite, ec8, 0.5, method="code", code="en1998-1", n_periods=25)
    f = r.factors[0]
    pga = np.array([np.max(np.abs(m.accel)) / G for m in suite])
    assert f * pga.mean() >= 0.46 * (1 - 1e-12)
    spectral = scale_suite(suite, ec8, 0.5, method="code", code="asce7-22", n_periods=25)
    assert f == pytest.approx(max(spectral.factors[0], 0.46 / pga.mean()), rel=1e-12)


def test_least_squares_on_the_log_spectrum_is_the_minimiser(suite):
    r = scale_suite(suite, TARGET, T1, method="lsq", n_periods=30)
    inside = (r.periods >= 0.2 * T1) & (r.periods <= 2 * T1)
    for i in range(len(suite)):
        def cost(lnf, i=i):
            return float(np.sum((lnf + np.log(r.unscaled[i, inside])
                                 - np.log(r.target_g[inside])) ** 2))
        best = minimize_scalar(cost, bracket=(-3.0, 3.0), tol=1e-12)
        assert math.log(r.factors[i]) == pytest.approx(best.x, abs=1e-6)


def test_mean_dispersion_and_flags(suite):
    r = scale_suite(suite, TARGET, T1, method="sa", limits=(0.9, 1.1))
    j = 3
    values = [f * s for f, s in zip(r.factors, r.unscaled[:, j], strict=True)]
    assert r.mean[j] == pytest.approx(statistics.fmean(values), rel=1e-12)
    assert r.dispersion[j] == pytest.approx(statistics.stdev(math.log(v) for v in values),
                                            rel=1e-12)
    assert list(r.flagged) == [not (0.9 <= f <= 1.1) for f in r.factors]


def test_a_record_scaled_to_sa_in_a_model_file(tmp_path):
    model = tmp_path / "m.toml"
    model.write_text('[record]\nbundled = "el_centro"\nduration = 8\nsa_g = 0.8\n'
                     'sa_period = 0.5\n[[building]]\nmass = 2e5\nperiod = 0.5\n'
                     '[[building]]\nmass = 3e5\nperiod = 1.0\n[contact]\n'
                     'law = "kelvin-voigt"\nk = 9.3e8\ne = 0.65\ngap = 0.02\n')
    gm = load_config(model).record.load()
    u, _ = ivp_peaks(gm.accel, gm.dt, 0.5, 0.05)
    assert u * (2 * math.pi / 0.5) ** 2 / G == pytest.approx(0.8, rel=1e-8)
    assert scale_to_sa(gm, 0.4, 0.5).pga == pytest.approx(gm.pga / 2, rel=1e-9)


@pytest.mark.parametrize("change, message", [
    ("sa_g = 0.8", "record.sa_period: sa_g = 0.8 g needs the period"),
    ("sa_g = 0.8\nsa_period = 0.5\npga_g = 0.3",
     "give one of scale, pga_g, sa_g and saavg_g"),
    ("sa_period = 0.5", "record.sa_period: only with sa_g"),
    ("sa_g = 0.8\nsa_period = 0.5\nsa_damping = 1.0", "record.sa_damping: must be in [0, 1) (got 1)"),
])
def test_bad_sa_keys_are_one_line(tmp_path, capsys, change, message):
    model = tmp_path / "m.toml"
    model.write_text(f'[record]\nbundled = "el_centro"\n{change}\n[[building]]\nmass = 2e5\n'
                     'period = 0.5\n[[building]]\nmass = 3e5\nperiod = 1.0\n[contact]\n'
                     'law = "kelvin-voigt"\nk = 9.3e8\ne = 0.65\ngap = 0.02\n')
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(tmp_path / "o"), "--no-figures"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0]
    assert not (tmp_path / "o").exists()


def test_suite_command_prints_writes_and_draws(tmp_path, capsys):
    target = tmp_path / "site.toml"
    target.write_text('asce7 = { sds = 1.0, sd1 = 0.6 }\n')
    out_csv, out_png = tmp_path / "f.csv", tmp_path / "s.png"
    assert main(["suite", "--design", str(target), "--t1", "1.0", "--csv", str(out_csv),
                 "--plot", str(out_png)]) == 0
    text = capsys.readouterr().out
    assert "mean / target over the range: lowest 0.900" in text
    rows = list(csv.reader(out_csv.read_text().splitlines()))  # no comment line
    assert rows[0] == ["record", "factor", "flagged", "pga_g", "scaled_pga_g", "sa_t1_g",
                       "scaled_sa_t1_g"]
    assert len(rows) == 1 + len(bundled_suite())
    factors = {float(r[1]) for r in rows[1:]}
    assert len(factors) == 1  # one factor for the suite
    assert out_png.stat().st_size > 10_000


@pytest.mark.parametrize("args, message", [
    (["--t1", "0"], "--t1 must be > 0 (got 0)"),
    (["--t1", "1", "--method", "mean"], "Invalid value for '--method'"),
    (["--t1", "1", "--damping", "0.05,0.02"], "--damping: suite scaling uses one damping"),
    (["--t1", "1", "--range", "2,1"], "period_range: the lower period must be below"),
    (["--t1", "3"], "target: spectrum"),  # the table below ends at 2 s
])
def test_suite_bad_input_is_one_line(tmp_path, capsys, args, message):
    target = tmp_path / "site.csv"
    target.write_text("period_s,sa_g\n0.0,0.4\n0.5,1.0\n2.0,0.3\n")
    capsys.readouterr()
    assert main(["suite", "--design", str(target), *args, "--csv",
                 str(tmp_path / "f.csv")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert not (tmp_path / "f.csv").exists()


def test_a_folder_with_no_record_is_one_line(tmp_path, capsys):
    (tmp_path / "notes.txt").write_text("not a record\n")
    target = tmp_path / "site.toml"
    target.write_text('asce7 = { sds = 1.0, sd1 = 0.6 }\n')
    capsys.readouterr()
    assert main(["suite", str(tmp_path), "--design", str(target), "--t1", "1"]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_the_example_target_is_the_asce7_spectrum_it_says():
    from pounding.example_files import example_path, examples

    spec = DesignSpectrum.from_file(example_path("spectrum_asce7_site"))
    # ASCE 7 §11.4.6 with S_DS = 1.0 g, S_D1 = 0.6 g: Sa = S_D1 / T on T_S < T < T_L
    assert spec.sa_g(1.0) == pytest.approx(0.6, rel=1e-12)
    assert spec.sa_g(0.3) == pytest.approx(1.0, rel=1e-12)
    assert {e.name: e.kind for e in examples()}["spectrum_asce7_site.toml"] == "spectrum"


def test_period_inputs_of_the_scalings_are_checked():
    """Periods outside the range a spectrum is computed over, and counts of periods that
    would allocate without end, are refused in one line naming the argument."""
    import time

    from pounding.ground_motion import el_centro
    from pounding.spectra.scaling import saavg_periods, scale_to_sa

    gm = el_centro()
    with pytest.raises(ValueError, match=r"^sa_period: every period must be from 1e-09 s to "
                                         r"1e\+09 s \(got 1e\+12\)"):
        scale_to_sa(gm, 0.3, 1e12)
    with pytest.raises(ValueError, match=r"^saavg_periods: every period must be from"):
        saavg_periods([1e-12, 1.0])
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r"^saavg_n: an integer from 2 to 100000 \(got "
                                         r"1000000000000\)"):
        saavg_periods([0.2, 3.0], 10**12)
    assert time.perf_counter() - start < 1.0
    with pytest.raises(ValueError, match=r"^n_periods: an integer from 2 to 100000 \(got "
                                         r"1000000000000\)"):
        scale_suite([gm], TARGET, T1, n_periods=10**12)
    with pytest.raises(ValueError, match=r"^period: every period must be from"):
        scale_suite([gm], TARGET, 1e10)
