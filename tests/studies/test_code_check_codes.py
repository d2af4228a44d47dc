"""`pounding code-check` for NZS 1170.5, NBCC 2020, IS 1893 and ASCE 7-22's equivalent
lateral force route (issue 29): each code's design spectrum at periods in every branch,
and each worked example of docs/codes.md on the 2-storey shear buildings whose modes are
known in closed form, the numbers computed here by hand from the clauses' formulas (not
by the modules' functions); bad input; the file.

Tolerances: the hand numbers use the same closed forms as the library's eigen-solution, so
they agree to round-off (rel 1e-9); the docs' printed digits to their last digit."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from model_documents import two_storey_pair

from pounding.cli import main

G = 9.80665
M = 1.0e5
K_A, K_B = 4.0e7, 8.0e7
GAP = 0.05

LAMBDAS = ((3.0 - math.sqrt(5.0)) / 2.0, (3.0 + math.sqrt(5.0)) / 2.0)


def _modes(k: float) -> list[tuple[float, tuple[float, float], float]]:
    """Two equal storeys (mass M, stiffness k): ω² = (k/M) λ, λ = (3 ∓ √5)/2, shape
    (1, 2 − λ); returns (T_n, Γ_n φ_n at floors 1 and 2, effective mass M_n*)."""
    out = []
    for lam in LAMBDAS:
        phi = (1.0, 2.0 - lam)
        gamma = sum(phi) / sum(p * p for p in phi)
        out.append((2.0 * math.pi / math.sqrt(lam * k / M), (gamma * phi[0], gamma * phi[1]),
                    M * sum(phi) ** 2 / sum(p * p for p in phi)))
    return out


def _srss(k: float, sa_g, floor: int) -> float:
    """SRSS of Γ_n φ_n Sa(T_n) g (T_n/2π)² at a floor [m]."""
    return math.sqrt(sum((gphi[floor] * sa_g(t) * G * (t / (2 * math.pi)) ** 2) ** 2
                         for t, gphi, _ in _modes(k)))


def _model_file(tmp: Path, ka: float = K_A, kb: float = K_B) -> Path:
    p = tmp / "pair.toml"
    p.write_text(two_storey_pair(ka, kb, M, GAP), encoding="utf-8")
    return p


@pytest.fixture(scope="module")
def model_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _model_file(tmp_path_factory.mktemp("codes"))


@pytest.fixture(scope="module")
def model(model_file: Path):
    from pounding.config import load_config

    return load_config(model_file).build()[0]


# -- the spectra, branch by branch, against values worked out by hand -------------------

def test_nzs1170_5_spectrum_by_hand() -> None:
    """C(T) = C_h(T) Z R (Table 3.1's modal C_h, Z R ≤ 0.7)."""
    from pounding.spectra import DesignSpectrum

    c = DesignSpectrum.nzs1170_5(0.4, 1.0, "C")
    # C: 1.33 + 1.6 T/0.1 | 2.93 | 2 (0.5/T)^0.75 | 1.32/T | 3.96/T², × 0.4
    for t, ch in ((0.0, 1.33), (0.05, 2.13), (0.2, 2.93), (1.0, 2.0 * 0.5 ** 0.75),
                  (2.0, 0.66), (4.0, 3.96 / 16.0)):
        assert c.sa_g(t) == pytest.approx(0.4 * ch, rel=1e-12), t
    d = DesignSpectrum.nzs1170_5(0.3, 1.0, "d")
    for t, ch in ((0.05, 2.06), (0.4, 3.0), (1.0, 2.4 * 0.75 ** 0.75), (2.5, 2.14 / 2.5)):
        assert d.sa_g(t) == pytest.approx(0.3 * ch, rel=1e-12), t
    e = DesignSpectrum.nzs1170_5(0.3, 1.0, "E")
    assert e.sa_g(0.8) == pytest.approx(0.9, rel=1e-12)
    assert e.sa_g(1.2) == pytest.approx(0.3 * 3.0 / 1.2 ** 0.75, rel=1e-12)
    a = DesignSpectrum.nzs1170_5(0.6, 1.8, "A")  # Z R = 1.08 → 0.7
    assert a.sa_g(0.2) == pytest.approx(0.7 * 2.35, rel=1e-12)
    assert a.sa_g(1.0) == pytest.approx(0.7 * 1.6 * 0.5 ** 0.75, rel=1e-12)
    with pytest.raises(ValueError, match="site_class"):
        DesignSpectrum.nzs1170_5(0.4, 1.0, "F")


def test_nbcc2020_spectrum_by_hand() -> None:
    """S(T): S(0.2) below 0.2 s, linear between the six periods, S(10) beyond."""
    from pounding.spectra import DesignSpectrum

    s = DesignSpectrum.nbcc2020([0.8, 0.7, 0.4, 0.2, 0.06, 0.02], t_max=12.0)
    for t, v in ((0.0, 0.8), (0.2, 0.8), (0.35, 0.75), (1.5, 0.3), (7.0, 0.044),
                 (10.0, 0.02), (12.0, 0.02)):
        assert s.sa_g(t) == pytest.approx(v, rel=1e-12), t
    with pytest.raises(ValueError, match="values"):
        DesignSpectrum.nbcc2020([0.8, 0.7, 0.4])


def test_is1893_spectrum_by_hand() -> None:
    """A_h = (Z/2)(I/R) Sa/g, Sa/g = 1 + 15T | 2.5 | 1.00/T, 1.36/T, 1.67/T."""
    from pounding.spectra import DesignSpectrum

    f = 0.36 / 2 * 1.2 / 5
    for soil, corner, c in (("I", 0.40, 1.00), ("II", 0.55, 1.36), ("3", 0.67, 1.67)):
        s = DesignSpectrum.is1893(0.36, 1.2, 5.0, soil)
        for t, sa in ((0.0, 1.0), (0.06, 1.9), (0.1, 2.5), (corner, 2.5), (1.0, c),
                      (4.0, c / 4.0)):
            assert s.sa_g(t) == pytest.approx(f * sa, rel=1e-12), (soil, t)
    with pytest.raises(ValueError, match="outside"):
        DesignSpectrum.is1893(0.36, 1.2, 5.0, "II").sa_g(4.5)


# -- the worked examples of docs/codes.md ------------------------------------------------

def test_nzs1170_5_worked_example(model) -> None:
    """d = (μ/k_μ(T1)) × SRSS on C(T) (§7.2.1.1 with §5.2.1), SRSS of the two (§7.4)."""
    from pounding.studies.codes import code_check

    check = code_check(model, "nzs1170.5", z=0.4, ru=1.0, site_class="C", mu=4.0,
                       combination="srss")

    def c_of_t(t: float) -> float:  # class C, by hand
        ch = (1.33 + 1.6 * t / 0.1 if t < 0.1 else 2.93 if t < 0.3 else
              min(2.93, 2.0 * (0.5 / t) ** 0.75) if t <= 1.5 else 1.32 / t)
        return 0.4 * ch

    def k_mu(t1: float) -> float:  # §5.2.1.1, classes A-D
        t = max(t1, 0.4)
        return 4.0 if t >= 0.7 else 3.0 * t / 0.7 + 1.0

    for floor, row in enumerate(check.rows):
        d = [4.0 / k_mu(_modes(k)[0][0]) * _srss(k, c_of_t, floor) for k in (K_A, K_B)]
        assert row.left == pytest.approx(d[0], rel=1e-9)
        assert row.right == pytest.approx(d[1], rel=1e-9)
        assert row.required == pytest.approx(math.hypot(*d), rel=1e-9)
    # docs/codes.md: roof 74.76 and 56.76 mm, 93.87 mm required
    assert [round(1e3 * v, 2) for v in (check.rows[1].left, check.rows[1].right,
                                        check.rows[1].required)] == [74.76, 56.76, 93.87]
    apart = code_check(model, "nzs1170.5", z=0.4, ru=1.0, site_class="C", mu=4.0,
                       combination="srss", same_property=False)
    assert apart.rows[1].required == pytest.approx(check.rows[1].left + check.rows[1].right)
    assert apart.rows[1].clause == "§7.4 (boundary)"


def test_nbcc2020_worked_example(model) -> None:
    """Deflection × R_d R_o / I_E of the analysis on S(T) I_E/(R_d R_o): the elastic
    deflection on S(T); SRSS of the two (4.1.8.14(1))."""
    from pounding.studies.codes import code_check

    table = (0.8, 0.7, 0.4, 0.2, 0.06, 0.02)
    check = code_check(model, "nbcc2020", s_table=",".join(map(str, table)), rd=5.0,
                       ro=1.5, ie=1.0, combination="srss")

    def s_of_t(t: float) -> float:  # linear between 0.2 and 0.5 s, 0.5 and 1 s, by hand
        if t <= 0.2:
            return 0.8
        return 0.8 - 0.1 * (t - 0.2) / 0.3 if t <= 0.5 else 0.7 - 0.3 * (t - 0.5) / 0.5

    for floor, row in enumerate(check.rows):
        d = [_srss(k, s_of_t, floor) for k in (K_A, K_B)]
        assert row.left == pytest.approx(d[0], rel=1e-9)
        assert row.right == pytest.approx(d[1], rel=1e-9)
        assert row.required == pytest.approx(math.hypot(*d), rel=1e-9)
        assert row.clause == "4.1.8.14(1)"
    assert [round(1e3 * v, 2) for v in (check.rows[1].left, check.rows[1].right,
                                        check.rows[1].required)] == [52.25, 28.07, 59.31]
    # R_d R_o / I_E undoes the reduction: other factors, the same deflections
    other = code_check(model, "nbcc2020", s_table=table, rd=2.0, ro=1.3, ie=1.5,
                       combination="srss")
    assert other.rows[1].required == pytest.approx(check.rows[1].required, rel=1e-12)


def test_is1893_worked_example(model) -> None:
    """R Δ, Δ on A_h = (Z/2)(I/R)(Sa/g); R/2 (Δ1 + Δ2) at floors of equal elevation."""
    from pounding.studies.codes import code_check

    check = code_check(model, "is1893", z=0.36, importance=1.2, r=5.0, soil_type="II",
                       combination="srss")

    def a_h(t: float) -> float:  # soil II, every period here on the plateau or its ramp
        return 0.36 / 2 * 1.2 / 5.0 * (1 + 15 * t if t <= 0.1 else 2.5 if t <= 0.55
                                       else 1.36 / t)

    for floor, row in enumerate(check.rows):
        delta = [_srss(k, a_h, floor) for k in (K_A, K_B)]
        assert row.left == pytest.approx(5.0 * delta[0], rel=1e-9)
        assert row.right == pytest.approx(5.0 * delta[1], rel=1e-9)
        assert row.required == pytest.approx(5.0 / 2 * (delta[0] + delta[1]), rel=1e-9)
        assert row.clause == "§7.11.3 × 0.5 (R/2)"
    assert [round(1e3 * v, 2) for v in (check.rows[1].left, check.rows[1].right,
                                        check.rows[1].required)] == [40.59, 20.29, 30.44]


def test_asce7_22_elf_worked_example(model) -> None:
    """C_s = S_DS/(R/I_e) (eq. 12.8-2, below eq. 12.8-3's cap), V = C_s W, W = g Σm,
    F_x = C_vx V with k of §12.8.3, δ_xe of a shear building: storey drift = storey
    shear / k; δ_M = C_d δ_xe / I_e; SRSS of the two (eq. 12.12-2)."""
    from pounding.studies.codes import code_check

    check = code_check(model, "asce7-22", sds=1.0, sd1=0.6, tl=8.0, cd=5.5, r=8.0, ie=1.25,
                       procedure="elf", s1=0.75)
    deltas = []
    for k_storey in (K_A, K_B):
        t1 = _modes(k_storey)[0][0]
        assert 1.0 / 6.4 < 0.6 / (t1 * 6.4)          # eq. 12.8-2 governs
        assert 1.0 / 6.4 > 0.5 * 0.75 / 6.4          # above eq. 12.8-6
        v = 1.0 / 6.4 * 2 * M * G
        kk = 1.0 if t1 <= 0.5 else 1.0 + (t1 - 0.5) / 2.0
        f1, f2 = (v * h ** kk / (3.0 ** kk + 6.0 ** kk) for h in (3.0, 6.0))
        d1 = (f1 + f2) / k_storey
        d2 = d1 + f2 / k_storey
        deltas.append((5.5 * d1 / 1.25, 5.5 * d2 / 1.25))
    for floor, row in enumerate(check.rows):
        assert row.left == pytest.approx(deltas[0][floor], rel=1e-9)
        assert row.right == pytest.approx(deltas[1][floor], rel=1e-9)
        assert row.required == pytest.approx(math.hypot(deltas[0][floor], deltas[1][floor]),
                                             rel=1e-9)
    assert [round(1e3 * v, 2) for v in (check.rows[1].left, check.rows[1].right,
                                        check.rows[1].required)] == [56.21, 28.09, 62.83]
    a = check.parameters["buildings"]["A"]
    assert a["C_s_by"] == "eq. 12.8-2" and a["V_kN"] == pytest.approx(2 * M * G / 6.4e3)


def test_asce7_22_modal_drift_scaling_12_9_1_4_2(tmp_path: Path) -> None:
    """Two flexible buildings (T1 = 2.27 and 1.61 s), S1 = 0.75 g: C_s is set by eq. 12.8-6
    (0.5 S1/(R/I_e) = 0.0586 above S_D1/(T R/I_e) and 0.044 S_DS I_e), the modal base
    shear V_t (SRSS of M_n* Sa_n I_e/R g) is below C_s W: δ_max × C_s W/V_t. Without S1
    (or with S1 < 0.6 g) nothing is scaled."""
    from pounding.config import load_config
    from pounding.studies.codes import code_check

    ka, kb = 2.0e6, 4.0e6
    flexible = load_config(_model_file(tmp_path, ka, kb)).build()[0]
    site = dict(sds=1.0, sd1=0.6, tl=8.0, cd=5.5, r=8.0, ie=1.25, combination="srss")
    scaled = code_check(flexible, "asce7-22", s1=0.75, **site)
    plain = code_check(flexible, "asce7-22", **site)
    low = code_check(flexible, "asce7-22", s1=0.5, **site)

    def sa(t: float) -> float:  # §11.4.6 beyond T_S = 0.6 s, × I_e/R
        return (1.0 if t <= 0.6 else 0.6 / t) * 1.25 / 8.0

    for side, k in (("left", ka), ("right", kb)):
        modes = _modes(k)
        v_t = math.sqrt(sum((m_eff * sa(t) * G) ** 2 for t, _, m_eff in modes))
        cs = max(min(1.0 / 6.4, 0.6 / (modes[0][0] * 6.4)), 0.044 * 1.25, 0.5 * 0.75 / 6.4)
        assert cs == pytest.approx(0.5 * 0.75 / 6.4)
        factor = cs * 2 * M * G / v_t
        assert factor > 1.0
        for floor in (0, 1):
            d_m = 5.5 / 1.25 * _srss(k, sa, floor)
            assert getattr(plain.rows[floor], side) == pytest.approx(d_m, rel=1e-9)
            assert getattr(low.rows[floor], side) == pytest.approx(d_m, rel=1e-9)
            assert getattr(scaled.rows[floor], side) == pytest.approx(factor * d_m, rel=1e-9)
    b = scaled.parameters["buildings"]["A"]
    assert b["C_s_by"] == "eq. 12.8-6" and b["drift_scale_12.9.1.4.2"] > 1.0


ISOLATED = """
name = "isolated beside fixed"
[record]
bundled = "el_centro"
[[building]]
name = "isolated"
n_storeys = 3
mass = 4.0e5
period = 0.4
height = 3.2
damping = { rayleigh = [0.05, 0.05], modes = [1, 2] }
isolator = { law = "friction-pendulum", radius = 2.0, mu = 0.05, base_mass = 5.0e5, base_height = 1.0 }
[[building]]
name = "fixed"
n_storeys = 3
mass = 4.0e5
period = 0.4
height = 3.2
damping = { rayleigh = [0.05, 0.05], modes = [1, 2] }
[contact]
law = "linear-spring"
k = 1.0e9
gap = 0.2
"""


def test_elf_refuses_a_base_isolated_building(tmp_path: Path) -> None:
    """§12.8 is for a fixed base: a building on isolators is refused, one line naming
    --procedure; the modal route still runs."""
    from pounding.config import load_config
    from pounding.studies.codes import code_check

    p = tmp_path / "isolated.toml"
    p.write_text(ISOLATED, encoding="utf-8")
    model = load_config(p).build()[0]
    site = dict(sds=1.0, sd1=0.6, tl=8.0, cd=5.5, r=8.0, ie=1.0)
    with pytest.raises(ValueError, match="procedure: .*Chapter 17"):
        code_check(model, "asce7-22", procedure="elf", **site)
    assert code_check(model, "asce7-22", **site).rows


# -- the command: options of one code refused with another, the file ---------------------

NZS = ["--code", "nzs1170.5", "--z", "0.4", "--ru", "1", "--site-class", "C", "--mu", "4"]


@pytest.mark.parametrize(("argv", "field"), [
    ([*NZS, "--sds", "1"], "--sds"),
    (NZS[:-2], "--mu"),
    ([*NZS[:6], "--site-class", "F", "--mu", "4"], "site_class"),
    ([*NZS[:-1], "0.5"], "mu"),
    (["--code", "nbcc2020", "--s-table", "0.8,0.7", "--rd", "5", "--ro", "1.5", "--ie", "1"],
     "s_table"),
    (["--code", "nbcc2020", "--s-table", "0.8,0.7,0.4,0.2,0.06,0.02", "--rd", "5",
      "--ro", "1.5", "--ie", "1", "--q", "3"], "--q"),
    (["--code", "is1893", "--z", "0.36", "--importance", "1.2", "--r", "5",
      "--soil-type", "IV"], "soil_type"),
    (["--code", "is1893", "--z", "0.36", "--importance", "1.2", "--r", "5",
      "--soil-type", "II", "--property-line"], "--property-line"),
    (["--code", "en1998-1", "--agr", "0.3", "--ground-type", "C", "--spectrum-type", "1",
      "--q", "3", "--procedure", "elf"], "--procedure"),
    (["--code", "asce7-22", "--sds", "1", "--sd1", "0.6", "--tl", "8", "--cd", "5",
      "--r", "8", "--ie", "1", "--s1", "-0.5"], "s1"),
    (["--code", "asce7-22", "--sds", "1", "--sd1", "0.6", "--tl", "8", "--cd", "5",
      "--r", "8", "--ie", "1", "--z", "0.4"], "--z"),
])
def test_bad_input_is_one_line_exit_2(model_file: Path, tmp_path: Path, argv: list[str],
                                      field: str, capsys: pytest.CaptureFixture[str],
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    assert main(["code-check", str(model_file), *argv, "--out", "out"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("error:") and field in err, err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("argv", "symbol", "clause", "required"), [
    (NZS, "d B1", "§7.4 (same site)", 93.87),
    (["--code", "nbcc2020", "--s-table", "0.8,0.7,0.4,0.2,0.06,0.02", "--rd", "5",
      "--ro", "1.5", "--ie", "1"], "Δ B1", "4.1.8.14(1)", 59.31),
    (["--code", "is1893", "--z", "0.36", "--importance", "1.2", "--r", "5",
      "--soil-type", "II"], "RΔ B1", "§7.11.3 × 0.5 (R/2)", 30.44),
    (["--code", "asce7-22", "--procedure", "elf", "--sds", "1", "--sd1", "0.6", "--tl", "8",
      "--cd", "5.5", "--r", "8", "--ie", "1.25"], "δ_M B1", "eq. 12.12-2", 62.83),
])
def test_cli_prints_and_writes(model_file: Path, tmp_path: Path, argv: list[str],
                               symbol: str, clause: str, required: float,
                               capsys: pytest.CaptureFixture[str],
                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    assert main(["code-check", str(model_file), *argv, "--combination", "srss",
                 "--out", "check"]) == 0
    out = capsys.readouterr().out
    assert symbol in out and clause in out
    data = json.loads((tmp_path / "check" / "code_check.json").read_text(encoding="utf-8"))
    assert data["levels"][1]["required_mm"] == pytest.approx(required, abs=0.005)
    assert data["levels"][1]["clause"] == clause
    assert any("linear" in a for a in data["assumptions"])


def test_long_periods(tmp_path: Path) -> None:
    """A very flexible pair (T1 = 12.7 and 9.0 s): NZS 1170.5 and NBCC 2020 go on with
    their long-period branches (3 b/T², S(10)) beyond their tables' 10 s; IS 1893's Sa/g
    ends at 4 s: refused, one line naming the model and the period."""
    from pounding.config import load_config
    from pounding.plausibility import PlausibilityWarning
    from pounding.studies.codes import code_check

    with pytest.warns(PlausibilityWarning, match="above 10 s"):  # meant: beyond 10 s
        soft = load_config(_model_file(tmp_path, 4.0e7 / 625, 8.0e7 / 625)).build()[0]
    nzs = code_check(soft, "nzs1170.5", z=0.4, ru=1.0, site_class="C", mu=1.0,
                     combination="srss")
    t1 = _modes(4.0e7 / 625)[0][0]
    assert t1 == pytest.approx(12.708, abs=1e-3)
    assert nzs.rows[1].left == pytest.approx(
        _srss(4.0e7 / 625, lambda t: 0.4 * (3.96 / t ** 2 if t > 3 else 1.32 / t if t > 1.5
                                            else min(2.93, 2 * (0.5 / t) ** 0.75)), 1),
        rel=1e-9)
    nbcc = code_check(soft, "nbcc2020", s_table="0.8,0.7,0.4,0.2,0.06,0.02", rd=1, ro=1,
                      ie=1, combination="srss")
    assert nbcc.rows[1].left > 0.0
    with pytest.raises(ValueError, match=r"model: building A's first period is 12\.7 s"):
        code_check(soft, "is1893", z=0.36, importance=1.2, r=5.0, soil_type="II")


def test_the_command_names_the_librarys_codes_and_procedures() -> None:
    """`--code` and `--procedure` offer what the library checks, no more, no less; each
    code's options are its parameters (so one is refused with another code)."""
    from pounding.cli.commands_code_check import Procedure, SeparationCode
    from pounding.studies.codes import CODES, code_parameters
    from pounding.studies.codes.asce7_22 import PROCEDURES

    assert [c.value for c in SeparationCode] == list(CODES)
    assert [p.value for p in Procedure] == list(PROCEDURES)
    assert set(code_parameters("nzs1170.5")) == {"z", "ru", "site_class", "mu",
                                                 "same_property", "combination"}
    assert {k for k, needed in code_parameters("asce7-22").items() if needed} == {
        "sds", "sd1", "tl", "cd", "r", "ie"}


@pytest.mark.parametrize("argv", [
    ["--code", "nbcc2020", "--s-table", "1e300,0.75,0.42,0.26,0.085,0.03", "--rd", "5", "--ro",
     "1.5", "--ie", "1"],
    ["--code", "asce7-22", "--sds", "1e300", "--sd1", "1e300", "--tl", "8", "--cd", "5.5",
     "--r", "8", "--ie", "1", "--combination", "srss"],
    ["--code", "asce7-22", "--sds", "1e300", "--sd1", "1e300", "--tl", "8", "--cd", "5.5",
     "--r", "8", "--ie", "1", "--procedure", "elf", "--s1", "1"],
    ["--code", "en1998-1", "--agr", "1e300", "--ground-type", "C", "--spectrum-type", "1",
     "--q", "3"]], ids=["nbcc-cqc", "asce-srss", "asce-elf", "en1998"])
def test_an_overflowing_spectrum_is_one_line_never_ok(argv, tmp_path, capsys) -> None:
    """A spectrum so large the modal sums overflow: one line, exit 2, nothing written (an
    overflowed CQC sum was read as 0 mm and "OK", and the command exited 0 with inf)."""
    from pounding.cli import main

    model = Path(__file__).resolve().parents[2] / "examples" / "two_10_storey.toml"
    capsys.readouterr()
    assert main(["code-check", str(model), *argv, "--out", str(tmp_path / "c")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: spectrum"), err
    assert not (tmp_path / "c").exists()
