"""Damping-from-restitution formulas (pounding.contact.restitution).

References, all independent of the module:

* the seed paper's Table 1 as printed (copied from the paper's text, not from the code);
* each formula re-typed from its source (FORMULAS.md) and evaluated with ``math``;
* for Anagnostopoulos' ζ, the physics it encodes: a damped linear oscillator released at
  ``δ = 0, δ̇ = v0`` returns to ``δ = 0`` half a damped period later with speed
  ``v0 exp(−π ζ / sqrt(1 − ζ²))`` — so that expression must give back ``e``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.contact import FORMULAS, formula
from pounding.contact.restitution import (
    TABLE1_E,
    TABLE1_ZETA,
    chi_flores,
    chi_gonthier,
    chi_hunt_crossley,
    chi_lankarani_nikravesh,
    zeta_anagnostopoulos,
    zeta_jankowski,
    zeta_mahmoud,
    zeta_naderpour,
)

# Seed paper (Naderpour, Khatami & Barros 2015), Table 1, as printed.
PAPER_TABLE1_E = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)
PAPER_TABLE1_ZETA = (320.71, 78.59, 32.74, 16.39, 8.74, 4.62, 2.26, 0.90, 0.21)

ALL_FUNCTIONS = [zeta_anagnostopoulos, zeta_jankowski, zeta_mahmoud, zeta_naderpour,
                 chi_hunt_crossley, chi_lankarani_nikravesh, chi_flores, chi_gonthier]


# --------------------------------------------------------------------------- by hand
def hand_anagnostopoulos(e):
    ln = math.log(e)
    return -ln / math.sqrt(math.pi**2 + ln**2)


def hand_jankowski(e):
    return 4.5 * math.sqrt(5.0) * (1 - e * e) / (e * (e * (9 * math.pi - 16) + 16))


def hand_mahmoud(e):
    return (1 - e * e) / (e * (e * (math.pi - 2) + 2))


def hand_naderpour(e):
    return ((1 - e * e) / (e * (math.sqrt(math.pi) * (0.5 * e + 1 / math.pi) - e))) ** 2


def hand_schwager_poschel(e):
    """ζ of the clipped Kelvin–Voigt law by bisection on Schwager & Pöschel's (2007) e(ζ),
    Granular Matter 9:465–469, eq 22 for ζ < 1 (enough for e ≥ exp(−2) ≈ 0.135)."""
    def e_of(z):
        return math.exp(-z * (math.pi - 2 * math.asin(z)) / math.sqrt(1 - z * z))
    lo, hi = 0.0, 1.0 - 1e-15
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if e_of(mid) > e else (lo, mid)
    return 0.5 * (lo + hi)


HAND = {
    "anagnostopoulos": hand_anagnostopoulos,
    "schwager-poschel": hand_schwager_poschel,
    "jankowski": hand_jankowski,
    "mahmoud": hand_mahmoud,
    "naderpour": hand_naderpour,
    "hunt-crossley": lambda e: 3 * (1 - e) / 2,
    "lankarani-nikravesh": lambda e: 3 * (1 - e * e) / 4,
    "flores": lambda e: 8 * (1 - e) / (5 * e),
    "gonthier": lambda e: (1 - e * e) / e,
}


def test_code_table_is_the_papers_table():
    assert tuple(TABLE1_E) == PAPER_TABLE1_E
    assert tuple(TABLE1_ZETA) == PAPER_TABLE1_ZETA


@pytest.mark.parametrize("e, printed", list(zip(PAPER_TABLE1_E, PAPER_TABLE1_ZETA)))
def test_naderpour_reproduces_seed_table1(e, printed):
    # the table truncates some entries (32.745 printed as 32.74): 0.01 absolute
    assert zeta_naderpour(e) == pytest.approx(printed, abs=0.01)
    assert hand_naderpour(e) == pytest.approx(printed, abs=0.01)


@pytest.mark.parametrize("key", sorted(HAND))
@pytest.mark.parametrize("e", [0.3, 0.5, 0.85, 1.0])
def test_formula_matches_hand_computation(key, e):
    assert FORMULAS[key](e) == pytest.approx(HAND[key](e), rel=1e-13, abs=1e-15)


def test_hand_values_at_e_half():
    """Pencil-and-paper values at e = 0.5 (four significant digits)."""
    assert zeta_anagnostopoulos(0.5) == pytest.approx(0.69315 / math.sqrt(9.86960 + 0.48045), rel=1e-4)
    assert zeta_anagnostopoulos(0.5) == pytest.approx(0.21545, rel=1e-4)
    assert zeta_jankowski(0.5) == pytest.approx(10.0623 * 0.75 / (0.5 * 22.1372), rel=1e-4)
    assert zeta_mahmoud(0.5) == pytest.approx(0.75 / (0.5 * 2.57080), rel=1e-4)
    assert zeta_naderpour(0.5) == pytest.approx((0.75 / (0.5 * (1.77245 * 0.56831 - 0.5))) ** 2, rel=1e-3)
    assert chi_hunt_crossley(0.5) == pytest.approx(0.75)
    assert chi_lankarani_nikravesh(0.5) == pytest.approx(0.5625)
    assert chi_flores(0.5) == pytest.approx(1.6)
    assert chi_gonthier(0.5) == pytest.approx(1.5)


@pytest.mark.parametrize("e", [0.05, 0.3, 0.65, 0.99])
def test_anagnostopoulos_is_the_damped_half_period(e):
    """The damped oscillator's return speed ratio exp(−πζ/sqrt(1−ζ²)) gives e back."""
    z = zeta_anagnostopoulos(e)
    assert 0.0 < z < 1.0
    assert math.exp(-math.pi * z / math.sqrt(1 - z * z)) == pytest.approx(e, rel=1e-13)


@pytest.mark.parametrize("fn", ALL_FUNCTIONS, ids=lambda f: f.__name__)
def test_elastic_limit_is_undamped(fn):
    assert abs(fn(1.0)) <= 1e-15


@pytest.mark.parametrize("fn", ALL_FUNCTIONS, ids=lambda f: f.__name__)
def test_damping_decreases_with_e(fn):
    e = np.linspace(0.05, 1.0, 40)
    assert np.all(np.diff(fn(e)) < 0)


@pytest.mark.parametrize("fn", ALL_FUNCTIONS, ids=lambda f: f.__name__)
@pytest.mark.parametrize("shape", [(5,), (2, 3), (1, 4, 2)])
def test_vectorised_shape_and_values(fn, shape):
    e = np.linspace(0.1, 0.95, int(np.prod(shape))).reshape(shape)
    out = fn(e)
    assert isinstance(out, np.ndarray)
    assert out.shape == shape
    key = next(k for k, f in FORMULAS.items() if f.function is fn)
    expected = np.vectorize(HAND[key])(e)
    np.testing.assert_allclose(out, expected, rtol=1e-13)


@pytest.mark.parametrize("fn", ALL_FUNCTIONS, ids=lambda f: f.__name__)
def test_scalar_in_scalar_out(fn):
    assert isinstance(fn(0.5), float)


@pytest.mark.parametrize("fn", ALL_FUNCTIONS, ids=lambda f: f.__name__)
@pytest.mark.parametrize("bad, shown", [(0.0, "0"), (-0.2, "-0.2"), (1.5, "1.5"),
                                         (float("nan"), "nan"), ([0.5, 2.0], "2")])
def test_bad_e_raises_naming_parameter_and_value(fn, bad, shown):
    with pytest.raises(ValueError) as info:
        fn(bad)
    msg = str(info.value)
    assert "e " in msg or msg.startswith("e")
    assert f"got {shown}" in msg


def test_unknown_formula_names_the_key():
    with pytest.raises(ValueError, match="nope"):
        formula("nope")
    with pytest.raises(ValueError, match="formula"):
        formula("nope")


def test_formula_lookup_is_case_insensitive_and_registry_consistent():
    assert formula("Anagnostopoulos") is FORMULAS["anagnostopoulos"]
    from pounding.contact import LAWS

    for key, f in FORMULAS.items():
        assert f.key == key
        assert f.kind in ("zeta", "chi")
        assert f.derived_for in LAWS
        assert (f.kind == "chi") == (f.derived_for == "hunt-crossley")


# --------------------------------------------------------------------------- audit
AUDIT_COLUMNS = ["formula", "law", "intended", "target_e", "damping", "achieved_e", "error",
                 "separated", "energy_error", "peak_force", "duration"]


@pytest.fixture(scope="module")
def audit():
    from pounding.contact.audit import restitution_audit

    return restitution_audit(e=[0.3, 0.7])


def test_audit_columns_and_shape(audit):
    from pounding.contact.audit import PAIRINGS

    assert list(audit.columns) == AUDIT_COLUMNS
    assert len(audit) == 2 * len(PAIRINGS)
    assert sorted(set(audit["target_e"])) == [0.3, 0.7]
    # overdamped Kelvin–Voigt with tension (ζ ≥ 1) creeps back to δ = 0 only
    # asymptotically: x(t) ∝ e^{r1 t} − e^{r2 t} has no positive root, so the bodies stick
    stuck = (audit.law == "kelvin-voigt (tension)") & (audit.damping >= 1.0)
    assert stuck.any()
    assert (audit["separated"] == ~stuck).all()
    assert (audit.loc[stuck, "achieved_e"] == 0.0).all()
    assert (audit["energy_error"] < 1e-8).all()
    np.testing.assert_allclose(audit["error"], audit["achieved_e"] - audit["target_e"], atol=1e-15)
    assert (audit["peak_force"] > 0).all()
    # a contact duration only where the bodies part (stuck: NaN, not when integration stopped)
    assert (audit.loc[~stuck, "duration"] > 0).all() and audit.loc[stuck, "duration"].isna().all()


def test_audit_anagnostopoulos_with_tension_is_exact(audit):
    rows = audit[(audit.formula == "anagnostopoulos") & (audit.law == "kelvin-voigt (tension)")]
    assert len(rows) == 2
    assert rows["intended"].all()
    np.testing.assert_allclose(rows["achieved_e"], rows["target_e"], atol=1e-8)
    np.testing.assert_allclose(rows["damping"], [hand_anagnostopoulos(e) for e in rows["target_e"]],
                               rtol=1e-12)


def test_audit_mahmoud_modified_kv_matches_hand_closed_form(audit):
    """The dashpot-on-approach oscillator: e = exp(−ζθ/sqrt(1−ζ²)), θ = atan(sqrt(1−ζ²)/ζ)."""
    rows = audit[(audit.formula == "mahmoud") & (audit.law == "modified-kelvin-voigt")]
    assert len(rows) == 2
    for _, row in rows.iterrows():
        z = row["damping"]
        assert z == pytest.approx(hand_mahmoud(row["target_e"]), rel=1e-12)
        if z < 1:
            s = math.sqrt(1 - z * z)
            e_hand = math.exp(-z * math.atan2(s, z) / s)
        else:
            # overdamped: ω δ(t)/v0 = (e^{−(ζ−s)τ} − e^{−(ζ+s)τ})/(2s), s = sqrt(ζ²−1), τ = ωt;
            # δ̇ = 0 at τ* = ln((ζ+s)/(ζ−s))/(2s); undamped return gives e = ω δmax / v0
            s = math.sqrt(z * z - 1)
            tau = math.log((z + s) / (z - s)) / (2 * s)
            e_hand = (math.exp(-(z - s) * tau) - math.exp(-(z + s) * tau)) / (2 * s)
        assert row["achieved_e"] == pytest.approx(e_hand, abs=1e-8)


def test_audit_damping_column_is_the_formula_value(audit):
    for _, row in audit.iterrows():
        if row["formula"] in HAND:
            assert row["damping"] == pytest.approx(HAND[row["formula"]](row["target_e"]), rel=1e-12)
        else:  # bilinear: the loop's design e
            assert row["damping"] == row["target_e"]


def test_audit_intended_flags_follow_the_registry(audit):
    for _, row in audit.iterrows():
        if row["formula"] in FORMULAS:
            derived_for = FORMULAS[row["formula"]].derived_for
            assert row["intended"] == row["law"].startswith(derived_for) or (
                row["law"] == "kelvin-voigt (no tension)" and not row["intended"])


def test_audit_rejects_bad_e():
    from pounding.contact.audit import AuditCase, restitution_audit

    with pytest.raises(ValueError, match="got 1.5"):
        restitution_audit(e=[0.5, 1.5])
    with pytest.raises(ValueError, match="v0"):
        AuditCase(v0=-1.0)
