"""Seat widths and the unseating margin (issue 28): AASHTO LRFD Art. 4.7.4.4 worked by hand
for a two-span and a five-span bridge, a third-party check case, the SI edition's rounded
coefficients, unit conversions, monotonicity and bad input."""

from __future__ import annotations

import dataclasses
import itertools
import math

import pytest

from pounding.structure.seat_width import (
    AASHTO_LRFD_CLAUSE,
    FOOT_M,
    INCH_M,
    SeatCheck,
    aashto_empirical_support_length,
    aashto_lrfd_required_support_length,
    aashto_lrfd_support_length_percent,
    check_seat,
    unseating_margin,
)

FT = FOOT_M
IN = INCH_M
REL = 1e-12  # the functions are a few flops: hand values agree to round-off


def n_si(l_ft: float, h_ft: float, skew: float) -> float:
    """N [m] from L, H in feet (the hand examples are set in US units)."""
    return aashto_empirical_support_length(l_ft * FT, h_ft * FT, skew)


# ============================================================================ unit conversions
def test_units_are_the_exact_international_inch_and_foot():
    assert INCH_M == 0.0254
    assert FOOT_M == 0.3048
    assert FOOT_M / INCH_M == pytest.approx(12.0, rel=1e-15)


def test_si_form_is_the_exact_conversion_of_the_us_equation():
    # N [m] = (0.2032 + L/600 + H/150)(1 + 0.000125 S^2): 8 in = 0.2032 m, 0.02 in/ft = 1/600,
    # 0.08 in/ft = 1/150
    for length, height, skew in [(0.0, 0.0, 0.0), (60.0, 8.0, 0.0), (137.2, 11.3, 37.0)]:
        expected = (0.2032 + length / 600.0 + height / 150.0) * (1.0 + 0.000125 * skew**2)
        assert aashto_empirical_support_length(length, height, skew) == pytest.approx(
            expected, rel=REL)


def test_single_span_bridge_has_no_column_term():
    # single span, L = 100 ft, H = 0: N = 8 + 0.02*100 = 10 in exactly
    assert n_si(100.0, 0.0, 0.0) == pytest.approx(10.0 * IN, rel=REL)
    assert aashto_empirical_support_length(0.0, 0.0, 0.0) == pytest.approx(0.2032, rel=REL)


# ========================================================================= two-span bridge
def test_two_span_bridge_by_hand():
    """Two 100 ft spans, continuous deck, one 25 ft pier, expansion joints at the abutments:
    at either abutment L = 200 ft and H = 25 ft.

    S = 0:  N = 8 + 0.02*200 + 0.08*25 = 8 + 4 + 2 = 14.0 in = 0.3556 m
    S = 20: 1 + 0.000125*400 = 1.05, N = 14.7 in = 0.37338 m
    Table 4.7.4.4-1: zone 1, A_s = 0.04 -> 75 % = 11.025 in; zone 1, A_s = 0.10 -> 14.7 in;
    zone 4 -> 150 % = 22.05 in = 0.56007 m
    """
    assert n_si(200.0, 25.0, 0.0) == pytest.approx(0.3556, rel=REL)
    assert n_si(200.0, 25.0, 20.0) == pytest.approx(0.37338, rel=REL)
    L, H = 200.0 * FT, 25.0 * FT
    assert aashto_lrfd_required_support_length(L, H, 20.0, 1, 0.04) == pytest.approx(
        11.025 * IN, rel=REL)
    assert aashto_lrfd_required_support_length(L, H, 20.0, 1, 0.10) == pytest.approx(
        14.7 * IN, rel=REL)
    assert aashto_lrfd_required_support_length(L, H, 20.0, 4, 0.40) == pytest.approx(
        0.56007, rel=REL)


# ======================================================================== five-span bridge
# Five 120 ft spans, skew 30 deg at every support, piers P1..P4 of 20, 30, 40, 30 ft; one
# expansion joint at P3 splits the deck into frame 1 (A1-P3, 360 ft) and frame 2 (P3-A2,
# 240 ft). The averages H are those of the columns under each frame as the test states them.
# Skew factor: 1 + 0.000125*30^2 = 1.1125.
FIVE_SPAN = [
    # seat,           L ft,  H ft, N by hand [in]
    ("A1",            360.0, 25.0, (8 + 7.2 + 2.0) * 1.1125),   # 17.2  -> 19.135
    ("P3, frame 1",   360.0, 30.0, (8 + 7.2 + 2.4) * 1.1125),   # 17.6  -> 19.58
    ("P3, frame 2",   240.0, 35.0, (8 + 4.8 + 2.8) * 1.1125),   # 15.6  -> 17.355
    ("A2",            240.0, 30.0, (8 + 4.8 + 2.4) * 1.1125),   # 15.2  -> 16.91
]


@pytest.mark.parametrize(("seat", "l_ft", "h_ft", "n_in"), FIVE_SPAN)
def test_five_span_bridge_by_hand(seat, l_ft, h_ft, n_in):
    assert n_si(l_ft, h_ft, 30.0) == pytest.approx(n_in * IN, rel=REL), seat
    # zone 3: 150 %
    assert aashto_lrfd_required_support_length(l_ft * FT, h_ft * FT, 30.0, 3, 0.3) == \
        pytest.approx(1.5 * n_in * IN, rel=REL), seat


def test_five_span_hand_numbers_as_printed():
    # the products above, written out (in): guards against a slip in the table
    assert [round(n, 4) for *_, n in FIVE_SPAN] == [19.135, 19.58, 17.355, 16.91]


# ==================================================== third-party check case, SI edition
def test_third_party_check_case():
    """Check case of a public fix log of a bridge-substructure calculator (AASHTO LRFD 10th ed.
    Art. 4.7.4.4): abutment end of a 200 ft unit, H = 20 ft, S = 0 -> N = 13.60 in; zone 2 and
    zone 3 -> 150 % = 20.40 in; zone 1 (A_s = 0.12) -> 100 % = 13.60 in. Printed to 0.01 in."""
    L, H = 200.0 * FT, 20.0 * FT
    assert aashto_empirical_support_length(L, H, 0.0) / IN == pytest.approx(13.60, abs=0.005)
    for zone, a_s, printed in [(2, 0.15, 20.40), (3, 0.25, 20.40), (1, 0.12, 13.60)]:
        got = aashto_lrfd_required_support_length(L, H, 0.0, zone, a_s) / IN
        assert got == pytest.approx(printed, abs=0.005), zone


@pytest.mark.parametrize("length", [0.0, 15.0, 60.0, 250.0])
@pytest.mark.parametrize("height", [0.0, 6.0, 25.0])
@pytest.mark.parametrize("skew", [0.0, 30.0, 60.0])
def test_within_two_percent_of_the_si_edition(length, height, skew):
    """The SI edition's rounded form N = (200 + 0.0017 L + 0.0067 H)(1 + 0.000125 S^2) mm
    (quoted in Bridge and Highway Structure Rehabilitation and Repair, p. 106; the same
    form in KDS 24 17 11 4.2.8(3) with L, H in m: 200 + 1.67 L + 6.66 H): each coefficient is
    within 2 % of the exact conversion, so N is too."""
    rounded_mm = (200.0 + 0.0017 * length * 1e3 + 0.0067 * height * 1e3) * (
        1.0 + 0.000125 * skew**2)
    exact_mm = aashto_empirical_support_length(length, height, skew) * 1e3
    assert exact_mm == pytest.approx(rounded_mm, rel=0.02)
    korean_mm = (200.0 + 1.67 * length + 6.66 * height) * (1.0 + 0.000125 * skew**2)
    assert exact_mm == pytest.approx(korean_mm, rel=0.02)


# ============================================================================ monotonicity
def test_skew_longer_deck_and_taller_columns_raise_n():
    base = aashto_empirical_support_length(60.0, 8.0, 10.0)
    assert aashto_empirical_support_length(60.0, 8.0, 11.0) > base
    assert aashto_empirical_support_length(61.0, 8.0, 10.0) > base
    assert aashto_empirical_support_length(60.0, 9.0, 10.0) > base
    skews = [aashto_empirical_support_length(60.0, 8.0, s) for s in range(0, 90, 5)]
    assert all(b > a for a, b in itertools.pairwise(skews))
    # at S -> 90 the skew factor tends to 1 + 0.000125*8100 = 2.0125 (89.999 deg: 2.012477)
    assert aashto_empirical_support_length(60.0, 8.0, 89.999) / skews[0] == pytest.approx(
        2.0125, abs=3e-5)


def test_percentages_of_table_4_7_4_4_1():
    assert aashto_lrfd_support_length_percent(1, 0.0) == 75.0
    assert aashto_lrfd_support_length_percent(1, 0.0499) == 75.0
    assert aashto_lrfd_support_length_percent(1, 0.05) == 100.0
    for zone in (2, 3, 4):
        assert aashto_lrfd_support_length_percent(zone, 0.0) == 150.0


# ================================================================================= margin
def test_unseating_margin_sign():
    assert unseating_margin(0.30, 0.40) == pytest.approx(0.10, abs=1e-15)
    assert unseating_margin(0.45, 0.40) == pytest.approx(-0.05, abs=1e-15)
    assert unseating_margin(0.0, 0.40) == 0.40
    assert unseating_margin(-0.02, 0.40) == pytest.approx(0.42, abs=1e-15)  # only closed


def test_seat_check_from_a_run():
    required = aashto_lrfd_required_support_length(200.0 * FT, 25.0 * FT, 20.0, 4, 0.4)
    ok = check_seat("A1", 0.60, 0.21, required)
    assert isinstance(ok, SeatCheck)
    assert ok.clause == AASHTO_LRFD_CLAUSE
    assert ok.margin_m == pytest.approx(0.39, abs=1e-15)
    assert ok.meets_minimum and not ok.unseated           # 0.60 m >= 0.56007 m
    bad = check_seat("J2", 0.45, 0.52, required, clause="owner's criterion")
    assert bad.unseated and not bad.meets_minimum
    assert bad.margin_m == pytest.approx(-0.07, abs=1e-15)
    assert bad.clause == "owner's criterion"
    with pytest.raises(dataclasses.FrozenInstanceError):
        bad.margin_m = 1.0  # type: ignore[misc]


# ============================================================================== bad input
@pytest.mark.parametrize(("args", "name", "shown"), [
    ((-1.0, 8.0, 0.0), "deck_length_m", "-1.0"),
    ((math.nan, 8.0, 0.0), "deck_length_m", "nan"),
    ((60.0, -0.5, 0.0), "column_height_m", "-0.5"),
    ((60.0, math.inf, 0.0), "column_height_m", "inf"),
    ((60.0, 8.0, -5.0), "skew_deg", "-5.0"),
    ((60.0, 8.0, 90.0), "skew_deg", "90.0"),
    ((60.0, 8.0, 120.0), "skew_deg", "120.0"),
    ((60.0, 8.0, math.nan), "skew_deg", "nan"),
])
def test_bad_geometry_names_the_argument_and_value(args, name, shown):
    with pytest.raises(ValueError, match=name) as err:
        aashto_empirical_support_length(*args)
    assert shown in str(err.value)
    with pytest.raises(ValueError, match=name):
        aashto_lrfd_required_support_length(*args, 3, 0.3)


@pytest.mark.parametrize(("zone", "a_s", "name"), [
    (0, 0.1, "seismic_zone"), (5, 0.1, "seismic_zone"), (True, 0.1, "seismic_zone"),
    ("2", 0.1, "seismic_zone"), (1, -0.01, "acceleration_coefficient"),
    (1, math.nan, "acceleration_coefficient"),
])
def test_bad_zone_or_coefficient(zone, a_s, name):
    with pytest.raises(ValueError, match=name):
        aashto_lrfd_support_length_percent(zone, a_s)


@pytest.mark.parametrize(("opening", "width", "name"), [
    (math.nan, 0.4, "peak_opening_m"), (math.inf, 0.4, "peak_opening_m"),
    (0.1, 0.0, "seat_width_m"), (0.1, -0.4, "seat_width_m"), (0.1, math.nan, "seat_width_m"),
])
def test_bad_margin_input(opening, width, name):
    with pytest.raises(ValueError, match=name):
        unseating_margin(opening, width)


def test_bad_requirement():
    with pytest.raises(ValueError, match=r"required_m.*-0\.1"):
        check_seat("A1", 0.5, 0.1, -0.1)
