"""The separation-gap study: critical gap by simulation, code rules, design spectra, CLI."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from matplotlib.figure import Figure
from scipy.integrate import quad

from pounding.cli import main
from pounding.config import dump_toml, load_config
from pounding.ground_motion import el_centro, read_record
from pounding.ground_motion.bundled import bundled_folder
from pounding.integrate import simulate
from pounding.model import ContactSpec, PoundingModel
from pounding.plot.gap import plot_gap_study
from pounding.structure import ShearBuilding
from pounding.studies import (
    DesignSpectrum,
    abs_sum,
    code_gaps,
    cqc_correlation,
    critical_gaps,
    ddc,
    hermite_max,
    spectral_displacements,
    srss,
)

ROOT = Path(__file__).resolve().parents[2]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
TEN = ROOT / "examples" / "two_10_storey.toml"
RECORDS = Path(str(bundled_folder()))
ELC = RECORDS / "elcentro_1940_IV_ELC9_180_PEER.AT2"
NWH = RECORDS / "northridge_1994_newhall_360_RSN1044.AT2"
SHORT = 6.0
"""Seconds simulated in most tests (El Centro's strong motion starts at once)."""


@pytest.fixture(scope="module")
def seed() -> PoundingModel:
    return load_config(SEED).build().model


@pytest.fixture(scope="module")
def ten() -> PoundingModel:
    return load_config(TEN).build().model


@pytest.fixture(scope="module")
def elc():
    return el_centro().trimmed(SHORT)


# ============================================================================ CQC ρ
def test_rho_hand_computed_values() -> None:
    # T1/T2 = 0.5, ζ = 5 % both: num = 8·0.05·(0.05 + 0.5·0.05)·0.5^1.5 = 0.010606602,
    # den = (1 − 0.25)² + 4·0.0025·0.5·1.25 + 4·0.005·0.25 = 0.57375
    assert cqc_correlation(0.5, 1.0, 0.05, 0.05) == pytest.approx(0.010606601717798 / 0.57375,
                                                                  rel=1e-12)
    assert cqc_correlation(1.0, 1.0, 0.05, 0.05) == pytest.approx(1.0, abs=1e-15)
    # equal periods, unequal damping: ρ = 2 sqrt(ζ1 ζ2) / (ζ1 + ζ2) = 2·0.04/0.10 = 0.8
    assert cqc_correlation(2.0, 2.0, 0.02, 0.08) == pytest.approx(0.8, rel=1e-12)
    # T1/T2 = 0.9, ζ1 = 0.02, ζ2 = 0.08: num = 8·0.04·(0.02 + 0.072)·0.9^1.5 = 0.0251433,
    # den = 0.0361 + 0.0064·0.9·1.81 + 0.0272·0.81 = 0.0685... by hand → 0.366645
    r = 0.9
    num = 8 * 0.04 * (0.02 + r * 0.08) * r ** 1.5
    den = (1 - r * r) ** 2 + 4 * 0.0016 * r * (1 + r * r) + 4 * (0.0004 + 0.0064) * r * r
    assert cqc_correlation(0.9, 1.0, 0.02, 0.08) == pytest.approx(num / den, rel=1e-14)
    assert cqc_correlation(0.9, 1.0, 0.02, 0.08) == pytest.approx(0.366645, abs=1e-6)
    # symmetric: swap both oscillators
    assert cqc_correlation(1.0, 0.9, 0.08, 0.02) == pytest.approx(0.366645, abs=1e-6)
    # undamped
    assert cqc_correlation(1.0, 1.0, 0.0, 0.0) == 1.0
    assert cqc_correlation(1.0, 2.0, 0.0, 0.0) == 0.0
    with pytest.raises(ValueError, match="period1"):
        cqc_correlation(0.0, 1.0, 0.05, 0.05)


def _white_noise_rho(t1: float, t2: float, z1: float, z2: float) -> float:
    """Correlation of two stationary oscillator displacements under white noise."""
    w1, w2 = 2 * math.pi / t1, 2 * math.pi / t2

    def h(w: float, wn: float, z: float) -> complex:
        return 1.0 / (wn * wn - w * w + 2j * z * wn * w)

    top = 200 * max(w1, w2)
    kw = {"points": [w1, w2], "limit": 2000}
    c = quad(lambda w: (h(w, w1, z1) * np.conj(h(w, w2, z2))).real, 0, top, **kw)[0]
    a = quad(lambda w: abs(h(w, w1, z1)) ** 2, 0, top, **kw)[0]
    b = quad(lambda w: abs(h(w, w2, z2)) ** 2, 0, top, **kw)[0]
    return c / math.sqrt(a * b)


@pytest.mark.parametrize("args", [(0.5, 1.0, 0.05, 0.05), (0.5, 1.0, 0.02, 0.10),
                                  (1.0, 0.5, 0.02, 0.10), (0.9, 1.0, 0.02, 0.08)])
def test_rho_is_the_white_noise_correlation(args: tuple[float, float, float, float]) -> None:
    """The convention r = T1/T2 with (ζ1 + r ζ2) is the exact random-vibration value; the
    other ratio (r = T2/T1) would be off by 6–60 % here for unequal damping."""
    assert cqc_correlation(*args) == pytest.approx(_white_noise_rho(*args), rel=1e-6)
    t1, t2, z1, z2 = args
    if z1 != z2:
        wrong = cqc_correlation(t2, t1, z1, z2)  # i.e. r = T2/T1 in the same formula
        assert abs(wrong - _white_noise_rho(*args)) > 0.05 * _white_noise_rho(*args)


# ============================================================================ rules
def test_rule_order_and_limits() -> None:
    rng = np.random.default_rng(4)
    u1, u2 = rng.uniform(0, 0.3, 200), rng.uniform(0, 0.3, 200)
    rho = rng.uniform(0, 1, 200)
    a, s, d = abs_sum(u1, u2), srss(u1, u2), ddc(u1, u2, rho)
    assert np.all(a >= s) and np.all(s >= d - 1e-15) and np.all(d >= np.abs(u1 - u2) - 1e-15)
    np.testing.assert_allclose(ddc(u1, u2, 1.0), np.abs(u1 - u2), atol=1e-15)
    np.testing.assert_allclose(ddc(u1, u2, 0.0), s, rtol=1e-14)
    np.testing.assert_allclose(ddc(u1, u2, -1.0), a, rtol=1e-14)
    assert ddc(0.1, 0.1, 1.0) == 0.0  # never sqrt of a negative round-off
    assert ddc(0.1, 0.05, 1.0 - 1e-9) == pytest.approx(0.05, abs=1e-5)  # ρ → 1
    assert ddc(0.1, 0.05, 1e-9) == pytest.approx(srss(0.1, 0.05), rel=1e-8)  # ρ → 0
    assert abs_sum(0.03, 0.04) == pytest.approx(0.07)
    assert srss(0.03, 0.04) == pytest.approx(0.05)
    assert set(code_gaps([0.03], [0.04], 0.0)) == {"ABS", "SRSS", "DDC"}
    with pytest.raises(ValueError, match="rho"):
        ddc(0.1, 0.1, 1.5)


# ============================================================================ Hermite maximum
def test_hermite_max_is_exact_for_cubics_and_close_for_a_sine() -> None:
    t = np.arange(0.0, 1.0001, 0.25)
    y = -(t - 0.4) ** 3 + 0.1 * (t - 0.4) ** 2  # a cubic: reproduced exactly
    dy = -3 * (t - 0.4) ** 2 + 0.2 * (t - 0.4)
    fine = np.linspace(0, 1, 200001)
    yf = -(fine - 0.4) ** 3 + 0.1 * (fine - 0.4) ** 2
    val, when = hermite_max(y, dy, 0.25)
    assert float(val) == pytest.approx(yf.max(), abs=1e-10)
    assert float(when) == pytest.approx(fine[np.argmax(yf)], abs=1e-4)
    # a sine sampled 20 times a period: the peak between samples, within h⁴ω⁴/384
    w, h = 2 * math.pi, 0.1
    ts = np.arange(0.0, 2.0, h)  # peaks at t = 0.25, 1.25: halfway between samples
    val, when = hermite_max(np.sin(w * ts), w * np.cos(w * ts), h)
    assert np.sin(w * ts).max() < 0.96
    assert float(when) == pytest.approx(0.25, abs=1e-2)
    assert abs(float(val) - 1.0) < (h * w) ** 4 / 384
    # columns are independent
    vals, _ = hermite_max(np.stack([np.sin(w * ts), -np.sin(w * ts)], 1),
                          np.stack([w * np.cos(w * ts), -w * np.cos(w * ts)], 1), h)
    assert vals.shape == (2,) and abs(vals[1] - 1.0) < 1e-3


# ============================================================================ simulation
def test_critical_gap_is_exact_no_impact_above_one_below(seed: PoundingModel, ten: PoundingModel,
                                                         elc) -> None:
    """gap = critical·(1 + 1e-3): no impact; gap = critical·(1 − 1e-3): at least one."""
    for model in (seed, ten):
        study = critical_gaps(model, elc)
        g = float(study.governing()[0])
        assert g > 0.01
        k = int(np.argmax(study.max_critical))
        assert study.critical[0, k] == g
        for factor, hits in ((1 + 1e-3, False), (1 - 1e-3, True)):
            r = simulate(dataclasses.replace(model, gaps=[g * factor]), elc)
            assert (r.n_impacts > 0) == hits, (model.name, factor, r.n_impacts)
        # the first impact below is at the governing level, near the time of the maximum
        r = simulate(dataclasses.replace(model, gaps=[g * (1 - 1e-3)]), elc)
        assert r.impacts["contact"].iloc[0] == study.labels[k]
        assert r.impacts["start"].iloc[0] == pytest.approx(study.time_of_max[0, k], abs=0.01)


def test_accuracy_against_a_0p1_ms_run(ten: PoundingModel, elc) -> None:
    """Hermite-refined maxima at the default 1 ms step agree with a 0.1 ms-step run to
    1e-8 m; the raw 1 ms samples alone would miss the peaks by up to ~1e-6 m."""
    study = critical_gaps(ten, elc)
    assert study.dt == pytest.approx(1e-3)
    fine = critical_gaps(ten, elc, dt=1e-4)
    np.testing.assert_allclose(study.critical, fine.critical, rtol=0, atol=1e-10)
    runs = [simulate(PoundingModel([b], [], ContactSpec("linear-spring", k=1.0)), elc, dt=1e-4,
                     free_stepping="exact") for b in ten.buildings]
    sampled = np.array([(runs[0].displacement[:, c.left_floor]
                         - runs[1].displacement[:, c.right_floor]).max() for c in ten.contacts])
    # the 0.1 ms samples are lower bounds, at most (1e-4·ω)²/8 · amplitude below the peak
    assert np.all(study.critical[0] >= sampled - 1e-12)
    np.testing.assert_allclose(study.critical[0], sampled, rtol=0, atol=1e-8)


def test_identical_buildings_never_touch(elc) -> None:
    b = ShearBuilding.uniform(4, 3e5, 5e8, 3.0, name="twin")
    model = PoundingModel([b, b], [0.0], ContactSpec("linear-spring", k=1e9))
    study = critical_gaps(model, elc)
    assert np.all(study.critical == 0.0) and np.all(study.peak_relative == 0.0)
    assert study.rho[0] == pytest.approx(1.0, abs=1e-12)
    rules = study.rules_from_peaks()
    np.testing.assert_allclose(rules["DDC"], 0.0, atol=1e-15)
    assert np.all(rules["SRSS"] > 0)
    # any positive gap is never closed (at gap 0 the floors touch from the start)
    assert simulate(dataclasses.replace(model, gaps=[1e-9]), elc).n_impacts == 0


def test_study_quantities_and_rules(seed: PoundingModel, ten: PoundingModel, elc) -> None:
    nwh = read_record(NWH).trimmed(SHORT)
    study = critical_gaps(ten, [elc, nwh])
    assert study.critical.shape == (2, 10) and study.n_levels == 10
    np.testing.assert_allclose(study.elevation, 3.2 * np.arange(1, 11))
    assert study.records == (elc.name, nwh.name)
    np.testing.assert_allclose(study.max_critical, study.critical.max(0))
    np.testing.assert_allclose(study.mean_critical, study.critical.mean(0))
    # one-sided closing never exceeds the two-sided peak, which never exceeds ABS per record
    assert np.all(study.critical <= study.peak_relative + 1e-15)
    per_record = study.rules_from_peaks("record")
    assert np.all(per_record["ABS"] >= study.peak_relative - 1e-12)
    rules = study.rules_from_peaks("mean")
    assert np.all(rules["ABS"] >= rules["SRSS"]) and np.all(rules["SRSS"] >= rules["DDC"])
    assert study.rho[0] == pytest.approx(cqc_correlation(*study.period, *study.zeta))
    np.testing.assert_allclose(study.period, [b.fundamental_period for b in ten.buildings])
    df = study.to_frame()
    assert len(df) == 10 and "DDC_peaks_m" in df and "ABS_peaks/max" in df
    fig = plot_gap_study(study, DesignSpectrum.asce7(1.0, 0.6))
    assert isinstance(fig, Figure) and fig.axes[0].get_xlabel() == "separation gap [mm]"
    assert "[m]" in fig.axes[0].get_ylabel()
    # the seed pair: one level
    one = critical_gaps(seed, elc)
    assert one.critical.shape == (1, 1) and one.elevation[0] == 3.0


def test_bad_inputs_of_the_api(seed: PoundingModel, elc) -> None:
    alone = PoundingModel([seed.buildings[0]], [], seed.contact)
    # (a moat wall beside one building is studied since issue 24: the message says so)
    with pytest.raises(ValueError, match="two or more buildings, or a building beside a moat"):
        critical_gaps(alone, elc)
    with pytest.raises(ValueError, match="at least one ground motion"):
        critical_gaps(seed, [])
    with pytest.raises(ValueError, match="GroundMotion"):
        critical_gaps(seed, [np.zeros(3)])  # type: ignore[list-item]
    a = ShearBuilding.sdof(1e5, period=0.5, height=3.0)
    b = ShearBuilding.sdof(1e5, period=0.5, height=4.0)
    with pytest.raises(ValueError, match="no shared floor level"):
        critical_gaps(PoundingModel([a, b], [0.01], seed.contact, floor_to_column=False), elc)
    # the 3 m slab faces the 4 m building's column: one floor-to-column level
    assert [c.label for c in PoundingModel([a, b], [0.01], seed.contact).contacts] == \
        ["B1F1-B2S1@0.75"]


# ============================================================================ design spectra
def test_design_spectrum_tables_and_asce7(tmp_path: Path) -> None:
    sd = DesignSpectrum([0.0, 1.0, 2.0], [0.0, 0.1, 0.3], kind="Sd", units="m")
    assert sd.sd(1.5) == pytest.approx(0.2)
    sa = DesignSpectrum([0.0, 1.0, 2.0], [1.0, 1.0, 0.5], kind="Sa", units="g")
    assert sa.sd(1.0) == pytest.approx(9.80665 / (2 * math.pi) ** 2)
    assert sa.sd(1.5) == pytest.approx(0.75 * 9.80665 * (1.5 / (2 * math.pi)) ** 2)
    with pytest.raises(ValueError, match="outside the table"):
        sa.sd(2.5)
    with pytest.raises(ValueError, match="increasing"):
        DesignSpectrum([0.0, 1.0, 1.0], [1, 1, 1])
    with pytest.raises(ValueError, match="kind"):
        DesignSpectrum([0.0, 1.0], [1, 1], kind="Sv")
    asce = DesignSpectrum.asce7(1.0, 0.6, tl=8.0)  # T0 = 0.12 s, TS = 0.6 s
    g = 9.80665
    for t, sa_g in ((0.0, 0.4), (0.06, 0.7), (0.3, 1.0), (1.2, 0.5), (10.0, 0.6 * 8 / 100)):
        assert asce.sd(t) == pytest.approx(sa_g * g * (t / (2 * math.pi)) ** 2, rel=1e-3), t
    # SDOF: Γ1 φ1 = 1, so the floor displacement is Sd(T)
    b = ShearBuilding.sdof(2e5, period=0.8)
    assert spectral_displacements(b, asce)[0] == pytest.approx(asce.sd(0.8), rel=1e-12)
    # uniform building: Γ1 φ1 rises to the roof, roof value > Sd(T1) (Γ1 φ1,roof ≈ 1.27)
    u = spectral_displacements(ShearBuilding.uniform(10, 6e5, 8e8, 3.2), asce)
    assert np.all(np.diff(u) > 0) and 1.2 < u[-1] / asce.sd(1.1513) < 1.35
    # files
    f = tmp_path / "s.toml"
    f.write_text('name = "site"\nkind = "Sa"\nunits = "m/s2"\nperiods = [0.0, 4.0]\n'
                 'values = [2.0, 2.0]\n', encoding="utf-8")
    s = DesignSpectrum.from_file(f)
    assert s.name == "site" and s.sd(2.0) == pytest.approx(2.0 * (2 / (2 * math.pi)) ** 2)
    f.write_text("asce7 = { sds = 1.0, sd1 = 0.6 }\n", encoding="utf-8")
    assert DesignSpectrum.from_file(f).sd(1.2) == pytest.approx(asce.sd(1.2))
    f.write_text("kind = \"Sa\"\nperiods = [0.0, 4.0]\n", encoding="utf-8")
    with pytest.raises(ValueError, match="values: required"):
        DesignSpectrum.from_file(f)
    with pytest.raises(ValueError, match="no such spectrum file"):
        DesignSpectrum.from_file(tmp_path / "none.toml")


# ============================================================================ CLI
def test_cli_seed_pair_two_records(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                   seed: PoundingModel) -> None:
    png, csv = tmp_path / "gap.png", tmp_path / "gap.csv"
    code = main(["gap", str(SEED), "--records", str(ELC), str(NWH), "--duration", "5",
                 "--plot", str(png), "--csv", str(csv)])
    out = capsys.readouterr().out
    assert code == 0, out
    for text in ("critical separation gap [mm]", "R1", "R2", "mean", "max", "ABS", "SRSS",
                 "DDC", "as recorded, not scaled", "governing critical gap"):
        assert text in out, text
    motions = [read_record(ELC), read_record(NWH)]
    study = critical_gaps(seed, motions, duration=5.0)
    for v in (*study.critical[:, 0], study.mean_critical[0], study.max_critical[0]):
        assert f"{1000 * v:.1f}" in out  # every gap of the screen in mm
    assert png.stat().st_size > 1000 and csv.read_text().count("\n") == 2  # header, one level


def test_cli_ten_storey_spectrum_and_default_record(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    spec = tmp_path / "spec.toml"
    spec.write_text("asce7 = { sds = 1.0, sd1 = 0.6, tl = 8.0 }\n", encoding="utf-8")
    png = tmp_path / "g.png"
    assert main(["gap", str(TEN), "--records", str(ELC), "--records", str(NWH),
                 "--duration", "4", "--design", str(spec), "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    assert "design spectrum" in out and "u1 [mm]" in out and out.count("B1-B2") >= 20
    assert png.is_file()
    # no --records: the model file's [record]
    assert main(["gap", str(TEN), "--duration", "3"]) == 0
    out = capsys.readouterr().out
    assert "[record] of the model file" in out and "El Centro" in out


def test_cli_applies_the_model_scaling(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = {"record": {"bundled": "el_centro", "pga_g": 0.4},
            "building": [{"mass": 2e5, "period": 0.5}, {"mass": 3e5, "period": 1.0}],
            "contact": {"law": "linear-spring", "k": 1e9, "gap": 0.02}}
    m = tmp_path / "m.toml"
    m.write_text(dump_toml(data), encoding="utf-8")
    assert main(["gap", str(m), "--records", str(NWH), "--duration", "3"]) == 0
    out = capsys.readouterr().out
    assert "scaled to PGA 0.4 g" in out and "PGA 0.400 g" in out
    assert main(["gap", str(m), "--records", str(NWH), "--duration", "3", "--unscaled"]) == 0
    out = capsys.readouterr().out
    assert "as recorded" in out and "PGA 0.590 g" in out


def test_cli_bad_inputs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["gap", str(SEED), "--records", str(tmp_path / "missing.AT2")]) == 2
    err = capsys.readouterr().err
    assert "missing.AT2: no such file" in err and "Traceback" not in err
    one = tmp_path / "one.toml"
    one.write_text(dump_toml({"record": {"bundled": "el_centro"},
                              "building": [{"mass": 2e5, "period": 0.5}]}), encoding="utf-8")
    assert main(["gap", str(one)]) == 2
    assert "needs two or more buildings, or a building beside a moat wall" in \
        capsys.readouterr().err
    assert main(["gap", str(SEED), str(ELC)]) == 2
    assert "give record files after --records" in capsys.readouterr().err
    assert main(["gap", str(tmp_path / "nope.toml")]) == 2
    assert "no such model file" in capsys.readouterr().err
    bad = tmp_path / "bad.toml"
    bad.write_text("kind = \"Sa\"\nperiods = [0.6, 1.0]\nvalues = [1.0, 1.0]\n", encoding="utf-8")
    assert main(["gap", str(SEED), "--duration", "2", "--design", str(bad)]) == 2
    assert "outside the table" in capsys.readouterr().err
