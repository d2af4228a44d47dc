"""Embedded footings: Pais & Kausel's embedment factors (NIST GCR 12-917-21 Table 2-2b) on the
springs and the sidewalls' radiation dashpots, against the formulas written out here from
their text, Gazetas' (1991) other set of factors, Luco et al.'s (1978) published dashpots of
an embedded cylinder, Veletsos & Meek's period, and a run from the command line.

No published worked example of an embedded footing could be reached: the springs of (b) are
computed by hand here from the formula text (NIST Table 2-2a/2-2b as transcribed in the
sources named in :mod:`pounding.structure.foundation.impedance`), independently of the code.
"""

from __future__ import annotations

import itertools
import json
import math
from pathlib import Path

import pytest

from pounding.cli import main
from pounding.structure import ShearBuilding
from pounding.structure.foundation import (
    FlexibleBaseBuilding,
    Footing,
    Soil,
    flexible_base,
    footing_dashpots,
    footing_stiffness,
)
from pounding.structure.foundation.impedance import (
    embedment_factors,
    max_embedment,
    surface_stiffness,
    torsion_embedment_factor,
)

SOIL = Soil(150.0, 1800.0, 0.33)
G, NU = 1800.0 * 150.0 ** 2, 0.33


# (a) -------------------------------------------------------------------------------------

@pytest.mark.parametrize("footing", [Footing(radius=5.0), Footing(length=12.0, width=8.0),
                                     Footing(length=8.0, width=12.0)])
def test_no_embedment_is_the_surface_footing(footing: Footing) -> None:
    """``embedment = 0`` (the default) gives today's springs and dashpots exactly: the
    circle's closed forms, Pais & Kausel's rectangle, the cones' dashpots."""
    assert footing.embedment == 0.0
    k_x, k_r = footing_stiffness(footing, SOIL)
    if footing.radius is not None:
        R = footing.radius
        assert (k_x, k_r) == (8 * G * R / (2 - NU), 8 * G * R ** 3 / (3 * (1 - NU)))
    else:
        L, B = 6.0, 4.0
        along = footing.length == 12.0
        assert k_x == pytest.approx(G * B / (2 - NU) * (
            6.8 * (L / B) ** 0.65 + (2.4 if along else 0.8 * L / B + 1.6)), rel=1e-15)
        assert k_r == pytest.approx(G * B ** 3 / (1 - NU) * (
            3.73 * (L / B) ** 2.4 + 0.27 if along else 3.2 * L / B + 0.8), rel=1e-15)
    assert (k_x, k_r) == surface_stiffness(footing, SOIL)
    c_x, _ = footing_dashpots(footing, SOIL, 9.0)
    assert c_x == 1800.0 * 150.0 * footing.area  # ρ V_s A
    assert embedment_factors(footing) == (1.0, 1.0)
    assert torsion_embedment_factor(footing) == 1.0


# (b) -------------------------------------------------------------------------------------

def test_a_rectangle_by_hand_both_ways() -> None:
    """12 m × 8 m (L = 6, B = 4, L/B = 1.5) embedded D = 3 m (D/B = 0.75), computed here from
    the text of NIST Table 2-2a (surface) and 2-2b (η), to rounding."""
    a, d = 1.5, 0.75
    eta_sway = 1 + (0.33 + 1.34 / (1 + a)) * d ** 0.8
    # along the row = along L: k_x with η_x, rocking k_yy with η_yy ((L/B)⁴)
    k_x = G * 4.0 / (2 - NU) * (6.8 * a ** 0.65 + 2.4) * eta_sway
    k_yy = G * 4.0 ** 3 / (1 - NU) * (3.73 * a ** 2.4 + 0.27) * (
        1 + d + 1.6 / (0.35 + a ** 4) * d ** 2)
    got = footing_stiffness(Footing(length=12.0, width=8.0, embedment=3.0), SOIL)
    assert got == pytest.approx((k_x, k_yy), rel=1e-14)
    # across the row = along B: k_y with η_y = η_x, rocking k_xx with η_xx (L/B)
    k_y = G * 4.0 / (2 - NU) * (6.8 * a ** 0.65 + 0.8 * a + 1.6) * eta_sway
    k_xx = G * 4.0 ** 3 / (1 - NU) * (3.2 * a + 0.8) * (1 + d + 1.6 / (0.35 + a) * d ** 2)
    got = footing_stiffness(Footing(length=8.0, width=12.0, embedment=3.0), SOIL)
    assert got == pytest.approx((k_y, k_xx), rel=1e-14)
    # by hand: 0.75^0.8 = exp(0.8 ln 0.75) = 0.79443, (0.33 + 1.34/2.5) 0.79443 = 0.68797
    assert eta_sway == pytest.approx(1.68797, abs=1e-5)
    assert torsion_embedment_factor(Footing(length=12.0, width=8.0, embedment=3.0)) == \
        pytest.approx(1 + (1.3 + 1.32 / a) * d ** 0.9, rel=1e-14)


@pytest.mark.parametrize("depth_ratio", [0.25, 0.5, 1.0, 1.75])
def test_a_circle_agrees_with_gazetas_own_factors(depth_ratio: float) -> None:
    """A circle takes Pais & Kausel's square of the same area (sway) or inertia (rocking);
    Gazetas' (1991) factors for the circle itself (B = L = R, full sidewall contact d = D,
    A_w = 2πRD, z_w = D/2; the other column of NIST Table 2-2b, written out here) agree within
    1 % in sway up to the deepest taken (D/R = 1.75) and 5 % in rocking for D/R ≤ 1 (9.4 %
    at D/R = 1.75)."""
    R = 4.0
    D = depth_ratio * R
    eta_x, eta_r = embedment_factors(Footing(radius=R, embedment=D))
    area_w, z_w = 2 * math.pi * R * D, D / 2
    gazetas_x = (1 + 0.15 * math.sqrt(D / R)) * (1 + 0.52 * (z_w * area_w / R ** 3) ** 0.4)
    gazetas_r = 1 + 1.26 * (D / R) * (1 + (D / R) * 1.0 ** -0.2 * 1.0 ** 0.5)
    assert eta_x == pytest.approx(gazetas_x, rel=0.01)
    assert eta_r == pytest.approx(gazetas_r, rel=0.05 if depth_ratio <= 1.0 else 0.095)


@pytest.mark.parametrize("h, c_hh, c_mm", [(0.0, 3.14, 1.36), (0.5, 7.43, 3.29),
                                           (1.0, 11.72, 7.36)])
def test_a_cylinder_radiates_as_luco_et_al_1978_at_high_frequency(h: float, c_hh: float,
                                                                  c_mm: float) -> None:
    """Luco et al. (1978), Table 3.3, "analytic a0 → ∞" (as quoted by a verification
    catalogue of SSI benchmarks): a rigid cylinder of radius a embedded h·a in a half-space,
    ν = 1/4, dashpots over ρ V_s a² (sway) and ρ V_s a⁴ (rocking about the base centre).
    The cone's base plus the sidewalls at a high frequency (b0 ≈ 1e4) give them within
    0.1 % (the printed values have two decimals; the catalogue's h = 2, beyond the deepest
    embedment taken, is left out)."""
    soil = Soil(1.0, 1.0, 0.25)
    c_x, c_r = footing_dashpots(Footing(radius=1.0, embedment=h), soil, 1e4)
    assert c_x == pytest.approx(c_hh, rel=1e-3)
    assert c_r == pytest.approx(c_mm, rel=1e-3)


# (c) -------------------------------------------------------------------------------------

@pytest.mark.parametrize("shape", [{"radius": 5.0}, {"length": 12.0, "width": 8.0},
                                   {"length": 8.0, "width": 12.0}])
def test_springs_and_dashpots_grow_with_the_embedment(shape: dict[str, float]) -> None:
    deepest = max_embedment(shape.get("radius"), shape.get("length"), shape.get("width"))
    depths = [deepest * i / 8 for i in range(9)]
    values = [(*footing_stiffness(Footing(**shape, embedment=d), SOIL),
               *footing_dashpots(Footing(**shape, embedment=d), SOIL, 9.0),
               torsion_embedment_factor(Footing(**shape, embedment=d))) for d in depths]
    for before, after in itertools.pairwise(values):
        assert all(b < a for b, a in zip(before, after)), (before, after)


def test_too_deep_or_negative_is_refused_in_one_line() -> None:
    with pytest.raises(ValueError, match=r"^foundation.embedment must be <= 8 m, the footing's "
                                         r"width .* \(got 8.5 m\)$"):
        Footing(length=12.0, width=8.0, embedment=8.5)
    assert max_embedment(5.0) == pytest.approx(2 * (3 * math.pi / 16) ** 0.25 * 5.0)
    with pytest.raises(ValueError, match=r"foundation.embedment \[m\] must be >= 0 "
                                         r"\(got -1\)"):
        Footing(radius=5.0, embedment=-1.0)


# (d) -------------------------------------------------------------------------------------

def test_an_embedded_footing_shortens_the_period_to_veletsos_meek() -> None:
    """The issue's building (1.0e6 kg, T = 0.5 s, h = 10 m) on the disk R = 5 m embedded
    D = 2 m: T̃ = T √(1 + k/k_x + k (h + D)²/k_φ) with the embedded springs written out here
    (η from the squares of the same area and inertia; the footing rocks about its base, D
    below the ground the height is measured from), shorter than on the surface."""
    m, T, h, R, D = 1.0e6, 0.5, 10.0, 5.0, 2.0
    k = m * (2 * math.pi / T) ** 2
    b_area, b_inertia = R * math.sqrt(math.pi) / 2, R * (3 * math.pi / 16) ** 0.25
    k_x = 8 * G * R / (2 - NU) * (1 + (0.33 + 1.34 / 2) * (D / b_area) ** 0.8)
    k_r = 8 * G * R ** 3 / (3 * (1 - NU)) * (1 + D / b_inertia
                                              + 1.6 / 1.35 * (D / b_inertia) ** 2)
    building = ShearBuilding.sdof(m, period=T, height=h)
    embedded = flexible_base(building, Footing(radius=R, embedment=D), SOIL)
    surface = flexible_base(building, Footing(radius=R), SOIL)
    assert isinstance(embedded, FlexibleBaseBuilding)
    expected = T * math.sqrt(1 + k / k_x + k * (h + D) ** 2 / k_r)
    assert embedded.modes().periods[0] == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(0.6650, abs=5e-5)  # docs/ground.md
    assert embedded.modes().periods[0] < surface.modes().periods[0] == pytest.approx(0.6976,
                                                                                    abs=5e-5)


# (e) -------------------------------------------------------------------------------------

MODEL = """\
[record]
bundled = "el_centro"
[[building]]
mass = 1.0e6
period = 0.5
height = 10.0
foundation = {{ radius = 5.0, embedment = {embedment}, soil = {{ vs = 150.0, density = 1800.0, \
poisson = 0.33 }} }}
[[building]]
mass = 6.0e5
period = 0.7
height = 10.0
[contact]
law = "kelvin-voigt"
k = 1e9
e = 0.65
gap = 0.02
[solver]
duration = 1.0
"""


def test_a_model_file_with_an_embedded_footing_runs_and_reports_it(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = tmp_path / "model.toml"
    model.write_text(MODEL.format(embedment="2.0"))
    assert main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"]) == 0
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    row = summary["foundations"][0]
    assert row["footing"]["embedment_m"] == 2.0
    k_x, k_r = footing_stiffness(Footing(radius=5.0, embedment=2.0), SOIL)
    assert row["k_sway_N_m"] == pytest.approx(k_x, rel=1e-12)
    assert row["k_rocking_N_m_rad"] == pytest.approx(k_r, rel=1e-12)
    assert row["flexible_base_periods_s"][0] == pytest.approx(0.6650, abs=5e-5)


@pytest.mark.parametrize("embedment, expected", [
    ("-1.0", "building[0].foundation.embedment: must be in [0, 1000] m (got -1)"),
    ("9.0", "building[0].foundation.embedment: must be <= 8.76068 m, the footing's width"),
])
def test_a_bad_embedment_is_one_line_exit_2_nothing_written(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], embedment: str,
        expected: str) -> None:
    model = tmp_path / "model.toml"
    model.write_text(MODEL.format(embedment=embedment))
    capsys.readouterr()
    code = main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and expected in err[0], err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.toml"]


def test_the_torsion_spring_takes_its_embedment_factor() -> None:
    """Under a building in plan the footing twists: its embedded torsion spring is the
    surface one (Pais & Kausel's rectangle ``G B³ [4.25 (L/B)^2.45 + 4.06]``, written out
    here) times η_zz = 1 + (1.3 + 1.32/(L/B)) (D/B)^0.9 (NIST GCR 12-917-21 Table 2-2b,
    written out here); the dashpot stays the base's."""
    from pounding.structure.foundation.impedance import footing_torsion

    soil = Soil(150.0, 1800.0, 0.33)
    G = soil.shear_modulus
    L, B, D = 6.0, 4.0, 3.0  # a 12 m × 8 m footing 3 m deep
    surface = G * B ** 3 * (4.25 * (L / B) ** 2.45 + 4.06)
    eta = 1.0 + (1.3 + 1.32 / (L / B)) * (D / B) ** 0.9
    k_t, c_t = footing_torsion(Footing(length=12.0, width=8.0, embedment=D), soil, 9.0)
    assert k_t == pytest.approx(eta * surface, rel=1e-14)
    assert c_t == footing_torsion(Footing(length=12.0, width=8.0), soil, 9.0)[1]
