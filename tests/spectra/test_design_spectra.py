"""Design spectra (``pounding.spectra.design``): Eurocode 8 (EN 1998-1:2004 §3.2.2.2)
against values worked by hand at the corner periods and inside every branch, and a user's
table read from CSV or TOML; every kind works in ``pounding gap --design``."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.spectra import DesignSpectrum

ROOT = Path(__file__).resolve().parents[2]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
G = 9.80665


def test_eurocode8_type1_ground_c_by_hand() -> None:
    """Type 1, ground C (Table 3.2: S = 1.15, T_B = 0.2, T_C = 0.6, T_D = 2.0 s),
    a_gR = 0.25 g, γ_I = 1.2, so a_g = 0.3 g and a_g S = 0.345 g; ζ = 5 %, η = 1."""
    s = DesignSpectrum.eurocode8(0.25, "C", 1, importance=1.2)
    hand = {0.0: 0.345,              # eq. 3.2 at T = 0: a_g S
            0.1: 0.345 * 1.75,       # eq. 3.2: 1 + (0.1/0.2)(2.5 − 1)
            0.2: 0.8625,             # T_B: 2.5 a_g S
            0.4: 0.8625,             # eq. 3.3
            0.6: 0.8625,             # T_C
            1.0: 0.8625 * 0.6,       # eq. 3.4: × T_C/T
            2.0: 0.8625 * 0.3,       # T_D
            3.0: 0.115,              # eq. 3.5: 0.8625 × 0.6 × 2 / 9
            4.0: 0.0646875}          # 0.8625 × 1.2 / 16
    for t, sa in hand.items():
        assert s.sa_g(t) == pytest.approx(sa, rel=1e-12), t
        assert s.sd(t) == pytest.approx(sa * G * (t / (2 * math.pi)) ** 2, rel=1e-12), t
    assert s.periods[0] == 0.0 and s.periods[-1] == 4.0
    assert {0.2, 0.6, 2.0} <= set(s.periods.tolist())  # the corners are table points
    assert s.name == "EN 1998-1 Type 1, ground C (agR=0.25 g, γI=1.2, ζ=5 %)"


def test_eurocode8_type2_ground_d_by_hand() -> None:
    """Type 2, ground D (Table 3.3: S = 1.8, T_B = 0.1, T_C = 0.3, T_D = 1.2 s),
    a_g = 0.1 g: a_g S = 0.18 g, plateau 0.45 g."""
    s = DesignSpectrum.eurocode8(0.1, "d", spectrum_type=2)
    for t, sa in {0.0: 0.18, 0.05: 0.315, 0.1: 0.45, 0.3: 0.45, 0.6: 0.225, 1.2: 0.1125,
                  2.0: 0.0405}.items():
        assert s.sa_g(t) == pytest.approx(sa, rel=1e-12), t


@pytest.mark.parametrize("ground, values", [
    ("A", (1.0, 0.15, 0.4, 2.0)), ("B", (1.2, 0.15, 0.5, 2.0)), ("E", (1.4, 0.15, 0.5, 2.0))])
def test_eurocode8_other_ground_types(ground: str, values: tuple[float, ...]) -> None:
    soil, tb, tc, td = values
    s = DesignSpectrum.eurocode8(0.2, ground)
    assert s.sa_g(0.0) == pytest.approx(0.2 * soil)
    assert s.sa_g(tb) == s.sa_g(tc) == pytest.approx(0.5 * soil)
    assert s.sa_g(td) == pytest.approx(0.5 * soil * tc / td)


def test_eurocode8_damping_correction() -> None:
    """η = sqrt(10/(5 + ξ)) ≥ 0.55, ξ in % (eq. 3.6): ζ = 2 % gives η = sqrt(10/7);
    ζ = 30 % would give 0.5345, held at 0.55. At T = 0 η does not enter."""
    base = DesignSpectrum.eurocode8(0.25, "B")
    low = DesignSpectrum.eurocode8(0.25, "B", damping=0.02)
    high = DesignSpectrum.eurocode8(0.25, "B", damping=0.30)
    assert low.sa_g(0.3) / base.sa_g(0.3) == pytest.approx(math.sqrt(10 / 7), rel=1e-12)
    assert high.sa_g(1.0) / base.sa_g(1.0) == pytest.approx(0.55, rel=1e-12)
    assert low.sa_g(0.0) == base.sa_g(0.0) == pytest.approx(0.3)
    # eq. 3.2 still joins the plateau at T_B: a_g S 2.5 η
    assert low.sa_g(0.15) == pytest.approx(0.3 * 2.5 * math.sqrt(10 / 7), rel=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    ({"agr": 0.0}, "agr must be > 0 (got 0)"),
    ({"agr": 0.2, "ground_type": "S1"}, "ground_type: must be one of A, B, C, D, E"),
    ({"agr": 0.2, "spectrum_type": 3}, "spectrum_type: must be 1 or 2"),
    ({"agr": 0.2, "damping": 1.0}, "damping must be in [0, 1) (got 1)"),
    ({"agr": 0.2, "importance": -1.0}, "importance must be > 0 (got -1)"),
    ({"agr": 0.2, "t_max": 6.0}, "t_max: EN 1998-1 eq. 3.5 ends at 4 s"),
])
def test_eurocode8_bad_parameters(kwargs: dict, message: str) -> None:
    with pytest.raises(ValueError) as info:
        DesignSpectrum.eurocode8(**kwargs)
    assert message in str(info.value)


def test_user_table_in_csv_and_toml(tmp_path: Path) -> None:
    csv = tmp_path / "site.csv"
    csv.write_text("# site-specific spectrum, 5 %\nperiod_s,sa_g\n0,0.4\n0.2,1.0\n1.0,0.6\n"
                   "4.0,0.15\n", encoding="utf-8")
    s = DesignSpectrum.from_file(csv)
    assert s.name == "site" and s.kind == "Sa" and s.units == "g"
    assert s.sa_g(0.6) == pytest.approx(0.8)  # linear between (0.2, 1.0) and (1.0, 0.6)
    assert s.sd(0.6) == pytest.approx(0.8 * G * (0.6 / (2 * math.pi)) ** 2)
    sd = tmp_path / "sd.csv"
    sd.write_text("period_s,sd_m\n0,0\n2,0.2\n", encoding="utf-8")
    assert DesignSpectrum.from_file(sd).sd(1.5) == pytest.approx(0.15)
    ms2 = tmp_path / "ms2.csv"
    ms2.write_text("sa_m_s2,period_s\n9.80665,0\n4.903325,2\n", encoding="utf-8")
    assert DesignSpectrum.from_file(ms2).sa_g(1.0) == pytest.approx(0.75)
    toml = tmp_path / "ec8.toml"
    toml.write_text('eurocode8 = { agr = 0.25, ground_type = "C", type = 1, importance = 1.2 }'
                    "\n", encoding="utf-8")
    assert DesignSpectrum.from_file(toml).sa_g(1.0) == pytest.approx(0.5175, rel=1e-12)


@pytest.mark.parametrize("name, text, message", [
    ("a.csv", "period,sa\n0,1\n", "the header (line 1) must name the columns period_s and "
                                  "one of sa_g, sa_m_s2, sd_m"),
    ("b.csv", "period_s,sa_g\n0,1\n1,x\n", "data line 2: period_s and sa_g must be numbers"),
    ("h.toml", "root:x:0:0\n", "not a valid TOML spectrum file (at line 1, column 5)"),
    ("c.csv", "period_s,sa_g\n0,1\n", "need at least 2 periods"),
    ("d.csv", "# nothing\n", "no header line"),
    ("e.toml", 'eurocode8 = { agr = 0.2, soil = "B" }\n', "eurocode8 needs agr [g] and "
                                                         "optionally ground_type"),
    ("f.toml", "eurocode8 = { agr = 0.2 }\nasce7 = { sds = 1.0, sd1 = 0.6 }\n",
     "give one of asce7 and eurocode8, not both"),
    ("g.toml", 'eurocode8 = { agr = 0.2, ground_type = "F" }\n', "ground_type: must be one"),
])
def test_bad_spectrum_files_are_one_line(tmp_path: Path, name: str, text: str,
                                         message: str) -> None:
    f = tmp_path / name
    f.write_text(text, encoding="utf-8")
    with pytest.raises(ValueError) as info:
        DesignSpectrum.from_file(f)
    assert str(info.value).startswith(f"{f}: ") and message in str(info.value)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("name, text", [
    ("ec8.toml", 'eurocode8 = { agr = 0.3, ground_type = "B" }\n'),
    ("site.csv", "period_s,sa_g\n0,0.4\n0.2,1.0\n1.0,0.6\n4.0,0.15\n"),
])
def test_every_kind_works_in_pounding_gap(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                          name: str, text: str) -> None:
    spec = tmp_path / name
    spec.write_text(text, encoding="utf-8")
    assert main(["gap", str(SEED), "--duration", "2", "--design", str(spec)]) == 0
    out = capsys.readouterr().out
    s = DesignSpectrum.from_file(spec)
    assert "u1 [mm]" in out and f"B1 {1000 * float(s.sd(0.5)):.1f}" in out


def test_asce7_is_evaluated_exactly_off_the_table() -> None:
    """ASCE 7-16 §11.4.6 with S_DS = 1, S_D1 = 0.6, T_L = 8 s: T0 = 0.12 s, T_S = 0.6 s."""
    s = DesignSpectrum.asce7(1.0, 0.6, tl=8.0)
    for t, sa in {0.0: 0.4, 0.06: 0.7, 0.12: 1.0, 0.6: 1.0, 0.7: 0.6 / 0.7, 8.0: 0.075,
                  11.0: 0.6 * 8 / 121}.items():
        assert s.sa_g(t) == pytest.approx(sa, rel=1e-12), t
    np.testing.assert_allclose(s.values, s.formula(s.periods))  # type: ignore[misc]
