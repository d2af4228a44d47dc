"""`pounding code-check` (issue 29): the separation of ASCE 7-22 §12.12 and EN 1998-1
§4.4.2.7 on a pair of 2-storey shear buildings whose modes are known in closed form, the
numbers computed here by hand from the clauses' formulas (docs/codes.md); bad input; the
output file."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from model_documents import two_storey_pair

from pounding.cli import main

G = 9.80665
M = 1.0e5            # kg per floor, both buildings
K_A, K_B = 4.0e7, 8.0e7   # N/m per storey
GAP = 0.05           # m
MODEL = two_storey_pair(K_A, K_B, M, GAP)


def _closed_form_modes(k: float, m: float) -> list[tuple[float, tuple[float, float]]]:
    """Two equal storeys (mass m, stiffness k): ω² = (k/m) (3 ∓ √5)/2, mode shape (1, 2 − λ),
    Γ = Σφ / Σφ² (equal masses): returns (T_n, Γ_n φ_n at floors 1 and 2)."""
    out = []
    for lam in ((3.0 - math.sqrt(5.0)) / 2.0, (3.0 + math.sqrt(5.0)) / 2.0):
        omega = math.sqrt(lam * k / m)
        phi = (1.0, 2.0 - lam)
        gamma = sum(phi) / sum(p * p for p in phi)
        out.append((2.0 * math.pi / omega, (gamma * phi[0], gamma * phi[1])))
    return out


def _asce_sa(t: float, sds: float, sd1: float, tl: float) -> float:
    """ASCE 7-22 §11.4.6 (two-period spectrum), by hand."""
    t0, ts = 0.2 * sd1 / sds, sd1 / sds
    if t < t0:
        return sds * (0.4 + 0.6 * t / t0)
    if t <= ts:
        return sds
    return sd1 / t if t <= tl else sd1 * tl / t ** 2


def _ec8_design_sa(t: float, ag: float, s: float, tb: float, tc: float, td: float,
                   q: float, beta: float = 0.2) -> float:
    """EN 1998-1 §3.2.2.5 eqs. 3.13–3.16, by hand."""
    if t <= tb:
        return ag * s * (2 / 3 + t / tb * (2.5 / q - 2 / 3))
    if t <= tc:
        return ag * s * 2.5 / q
    if t <= td:
        return max(ag * s * 2.5 / q * tc / t, beta * ag)
    return max(ag * s * 2.5 / q * tc * td / t ** 2, beta * ag)


def _srss_floor(modes: list[tuple[float, tuple[float, float]]], sa_g, floor: int) -> float:
    """SRSS of Γ_n φ_n Sa(T_n) g (T_n/2π)² at a floor."""
    return math.sqrt(sum((gphi[floor] * sa_g(t) * G * (t / (2 * math.pi)) ** 2) ** 2
                         for t, gphi in modes))


def _cqc_floor(modes: list[tuple[float, tuple[float, float]]], sa_g, floor: int,
               zeta: float = 0.05) -> float:
    r = [gphi[floor] * sa_g(t) * G * (t / (2 * math.pi)) ** 2 for t, gphi in modes]
    total = 0.0
    for i, (ti, _) in enumerate(modes):
        for j, (tj, _) in enumerate(modes):
            b = ti / tj  # ω_j / ω_i
            rho = (8 * zeta ** 2 * (1 + b) * b ** 1.5
                   / ((1 - b * b) ** 2 + 4 * zeta ** 2 * b * (1 + b) ** 2))
            total += rho * r[i] * r[j]
    return math.sqrt(total)


@pytest.fixture(scope="module")
def model_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    p = tmp_path_factory.mktemp("codecheck") / "pair.toml"
    p.write_text(MODEL, encoding="utf-8")
    return p


@pytest.fixture(scope="module")
def model(model_file: Path):
    from pounding.config import load_config

    return load_config(model_file).build()[0]


def test_modes_are_the_closed_form(model) -> None:
    """The check reads the model's modes: they are the hand ones (so the hand numbers below
    rest on the same structure, not on the function's output)."""
    for building, k in zip(model.buildings, (K_A, K_B)):
        modes = building.modes()
        for n, (t, gphi) in enumerate(_closed_form_modes(k, M)):
            assert modes.periods[n] == pytest.approx(t, rel=1e-10)
            assert modes.modal_contributions[:, n] == pytest.approx(gphi, rel=1e-10)


ASCE = {"sds": 1.0, "sd1": 0.6, "tl": 8.0, "cd": 5.5, "r": 8.0, "ie": 1.25}


@pytest.mark.parametrize("combination", ["srss", "cqc"])
def test_asce7_22_by_hand(model, combination: str) -> None:
    """δ_max = modal combination of the spectrum × I_e/R (§12.9.1.2); δ_M = C_d δ_max/I_e
    (eq. 12.12-1); δ_MT = sqrt(δ_M1² + δ_M2²) (eq. 12.12-2)."""
    from pounding.studies.codes import code_check

    check = code_check(model, "asce7-22", combination=combination, **ASCE)

    def design(t: float) -> float:
        return _asce_sa(t, ASCE["sds"], ASCE["sd1"], ASCE["tl"]) * ASCE["ie"] / ASCE["r"]

    combine = _srss_floor if combination == "srss" else _cqc_floor
    assert len(check.rows) == 2
    for floor, row in enumerate(check.rows):
        delta_m = [ASCE["cd"] * combine(_closed_form_modes(k, M), design, floor) / ASCE["ie"]
                   for k in (K_A, K_B)]
        assert row.left == pytest.approx(delta_m[0], rel=1e-9)
        assert row.right == pytest.approx(delta_m[1], rel=1e-9)
        assert row.required == pytest.approx(math.hypot(*delta_m), rel=1e-9)
        assert row.gap == pytest.approx(GAP)
        assert row.elevation == pytest.approx(3.0 * (floor + 1))
        assert row.clause == "eq. 12.12-2"
        assert row.ok is (GAP >= math.hypot(*delta_m))
    # the worked example of docs/codes.md (SRSS), worked there digit by digit: roof
    # δ_M 51.68 and 25.84 mm, 57.8 mm required, the 50 mm gap not OK
    if combination == "srss":
        assert 1e3 * check.rows[1].left == pytest.approx(51.68, abs=0.005)
        assert 1e3 * check.rows[1].right == pytest.approx(25.84, abs=0.005)
        assert 1e3 * check.rows[1].required == pytest.approx(57.78, abs=0.005)
        assert not check.rows[1].ok
        assert 1e3 * check.rows[0].required == pytest.approx(35.76, abs=0.005)
        assert check.rows[0].ok
    # the property line: each building set back its own δ_M
    apart = code_check(model, "asce7-22", combination=combination, same_property=False,
                       **ASCE)
    for row, alone in zip(check.rows, apart.rows):
        assert alone.required == pytest.approx(row.left + row.right, rel=1e-12)


EC8 = {"agr": 0.3, "ground_type": "C", "spectrum_type": 1, "q": 3.0, "importance": 1.2}


def test_en1998_1_by_hand(model) -> None:
    """d_e on the §3.2.2.5 design spectrum, d_s = q_d d_e (eq. 4.23), SRSS of the two
    (§4.4.2.7(2)b) × 0.7 where floors meet floors (§4.4.2.7(3))."""
    from pounding.studies.codes import code_check

    ag = EC8["importance"] * EC8["agr"]

    def design(t: float) -> float:  # ground C, type 1: S 1.15, T_B 0.2, T_C 0.6, T_D 2.0
        return _ec8_design_sa(t, ag, 1.15, 0.2, 0.6, 2.0, EC8["q"])

    check = code_check(model, "en1998-1", combination="srss", **EC8)
    for floor, row in enumerate(check.rows):
        d_s = [EC8["q"] * _srss_floor(_closed_form_modes(k, M), design, floor)
               for k in (K_A, K_B)]
        assert row.left == pytest.approx(d_s[0], rel=1e-9)
        assert row.right == pytest.approx(d_s[1], rel=1e-9)
        assert row.required == pytest.approx(0.7 * math.hypot(*d_s), rel=1e-9)
        assert "§4.4.2.7(3)" in row.clause
    # docs/codes.md's worked example: roof d_s 77.80 and 38.90 mm, 0.7 × 86.98 = 60.89 mm
    assert 1e3 * check.rows[1].left == pytest.approx(77.80, abs=0.005)
    assert 1e3 * check.rows[1].right == pytest.approx(38.90, abs=0.005)
    assert 1e3 * check.rows[1].required == pytest.approx(60.89, abs=0.005)
    qd = code_check(model, "en1998-1", combination="srss", qd=4.5, **EC8)
    assert qd.rows[1].left == pytest.approx(1.5 * check.rows[1].left, rel=1e-12)


def test_design_spectrum_branches_by_hand() -> None:
    """EN 1998-1 eqs. 3.13–3.16 at a period in each branch, and the β a_g floor."""
    from pounding.studies.codes.en1998_1 import design_spectrum_sa_g

    for t in (0.0, 0.1, 0.4, 1.0, 1.9, 2.5, 3.5):
        assert design_spectrum_sa_g(t, ag=0.36, ground_type="C", spectrum_type=1, q=3.0
                                    ) == pytest.approx(_ec8_design_sa(t, 0.36, 1.15, 0.2,
                                                                      0.6, 2.0, 3.0))
    # q = 6, T = 3.5 s: 0.36 × 1.15 × 2.5/6 × 0.6 × 2/3.5² = 0.0169 < β a_g = 0.072
    assert design_spectrum_sa_g(3.5, ag=0.36, ground_type="C", spectrum_type=1, q=6.0
                                ) == pytest.approx(0.2 * 0.36)


@pytest.mark.parametrize(("argv", "field"), [
    (["--code", "nzs1170.5"], "--code"),
    (["--code", "asce7-22", "--sds", "1", "--sd1", "0.6", "--tl", "8", "--r", "8",
      "--ie", "1"], "--cd"),
    (["--code", "asce7-22", "--sds", "1", "--sd1", "0.6", "--tl", "8", "--cd", "-5",
      "--r", "8", "--ie", "1"], "cd"),
    (["--code", "asce7-22", "--sds", "1", "--sd1", "0.6", "--tl", "8", "--cd", "5",
      "--r", "8", "--ie", "1", "--q", "3"], "--q"),
    (["--code", "en1998-1", "--agr", "0.3", "--ground-type", "S1", "--spectrum-type", "1",
      "--q", "3"], "ground_type"),
    (["--code", "en1998-1", "--agr", "0.3", "--ground-type", "C", "--spectrum-type", "1",
      "--q", "0.5"], "q"),
])
def test_bad_input_is_one_line_exit_2(model_file: Path, tmp_path: Path, argv: list[str],
                                      field: str, capsys: pytest.CaptureFixture[str],
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    assert main(["code-check", str(model_file), *argv, "--out", "out"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("error:") and field in err, err
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_cli_table_and_file(model_file: Path, tmp_path: Path,
                            capsys: pytest.CaptureFixture[str],
                            monkeypatch: pytest.MonkeyPatch) -> None:
    """Printed per pair with the clause; nothing written without --out; code_check.json
    with it; a folder pounding did not write is never replaced."""
    monkeypatch.chdir(tmp_path)
    argv = ["code-check", str(model_file), "--code", "asce7-22", "--sds", "1", "--sd1", "0.6",
            "--tl", "8", "--cd", "5.5", "--r", "8", "--ie", "1.25", "--combination", "srss"]
    capsys.readouterr()
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "B1-B2: separation by ASCE/SEI 7-22 §12.12 [mm]" in out
    assert "eq. 12.12-2" in out and "not OK" in out and "57.8" in out
    assert list(tmp_path.iterdir()) == []
    assert main([*argv, "--out", "check"]) == 0
    data = json.loads((tmp_path / "check" / "code_check.json").read_text(encoding="utf-8"))
    assert data["code"] == "asce7-22" and data["ok"] is False
    assert data["levels"][0]["ok"] is True and data["levels"][1]["ok"] is False
    assert data["levels"][1]["required_mm"] == pytest.approx(57.78, abs=0.005)
    assert data["levels"][1]["clause"] == "eq. 12.12-2"
    assert any("linear" in a for a in data["assumptions"])
    # again: refused without --overwrite, replaced with it
    assert main([*argv, "--out", "check"]) == 2
    assert main([*argv, "--out", "check", "--overwrite"]) == 0
    # a folder of the user's is never replaced
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep", encoding="utf-8")
    capsys.readouterr()
    assert main([*argv, "--out", "mine", "--overwrite"]) == 2
    assert (mine / "notes.txt").read_text(encoding="utf-8") == "keep"
    assert sorted(p.name for p in mine.iterdir()) == ["notes.txt"]
