"""A bridge's seats (issue 28): the clause objects worked by hand in inches and feet, the L
and H each seat is evaluated with (the end frame at an abutment, the larger requirement of
the two frames at a joint), the given widths of a clause the library does not implement,
and the checks of a bridge's seat widths and clause."""

from __future__ import annotations

import copy
import pickle

import pytest

from pounding.contact.spec import ContactSpec
from pounding.model import PoundingModel
from pounding.structure.bridge import Abutment, Bearing, Bridge, BridgeFrame, Pier, Restrainer
from pounding.structure.seat_width import (
    AASHTO_LRFD_CLAUSE,
    FOOT_M,
    INCH_M,
    AashtoLrfdSeatClause,
    GivenSeatWidths,
    check_seat,
)

FT, IN = FOOT_M, INCH_M
REL = 1e-12


def _frame(spans_ft: list[float] | None, piers_ft: list[float]) -> BridgeFrame:
    """A frame on piers of the heights given [ft], its deck at 40 ft (every deck of a
    bridge at one level)."""
    return BridgeFrame(1.0e6, [Pier(h * FT, 5.0e7, 1.0e5) for h in piers_ft],
                       Bearing.elastomeric(2.0e7), deck_elevation=40 * FT,
                       spans=None if spans_ft is None else [s * FT for s in spans_ft])


# Three frames, set in feet: F1 two 100 ft spans on piers of 25 and 35 ft (L = 200 ft,
# H = 30 ft); F2 one 150 ft span on a 40 ft pier; F3 three 90 ft spans on two 20 ft piers
# (L = 270 ft, H = 20 ft). Skew 20 deg: 1 + 0.000125*400 = 1.05. Zone 3: 150 % of N.
#   N(F1) = (8 + 0.02*200 + 0.08*30) * 1.05 = 14.4 * 1.05 = 15.12 in -> 22.68 in
#   N(F2) = (8 + 0.02*150 + 0.08*40) * 1.05 = 14.2 * 1.05 = 14.91 in -> 22.365 in
#   N(F3) = (8 + 0.02*270 + 0.08*20) * 1.05 = 15.0 * 1.05 = 15.75 in -> 23.625 in
# A1 reads F1; J1 the larger of F1, F2 (F1); J2 the larger of F2, F3 (F3); A2 reads F3.
THREE = [([100.0, 100.0], [25.0, 35.0]), ([150.0], [40.0]), ([90.0, 90.0, 90.0], [20.0, 20.0])]
BY_HAND = {  # seat: (required [in], L [ft], H [ft])
    "A1": (22.68, 200.0, 30.0),
    "J1": (22.68, 200.0, 30.0),
    "J2": (23.625, 270.0, 20.0),
    "A2": (23.625, 270.0, 20.0),
}


def _bridge(widths=(0.7, 0.6, 0.6, 0.7), clause=None, frames=THREE, **kw) -> Bridge:
    return Bridge([_frame(s, p) for s, p in frames], [0.02] * (len(frames) - 1),
                  abutments=(Abutment(0.05), Abutment(0.05)), seat_widths=widths,
                  seat_clause=clause, **kw)


def test_aashto_clause_object_by_hand() -> None:
    """Zone 2, L = 300 ft, H = 30 ft, S = 15 deg: N = (8 + 6 + 2.4)(1 + 0.000125*225)
    = 16.4 * 1.028125 = 16.86125 in; 150 % = 25.291875 in = 0.642413625 m. Zone 1 with
    A_s = 0.04, L = 100 ft, H = 0: 75 % of 10 in = 7.5 in = 0.1905 m."""
    clause = AashtoLrfdSeatClause(seismic_zone=2, skew_deg=15.0)
    assert clause.required(300 * FT, 30 * FT) == pytest.approx(25.291875 * IN, rel=REL)
    assert clause.required(300 * FT, 30 * FT) == pytest.approx(0.642413625, rel=REL)
    low = AashtoLrfdSeatClause(1, acceleration_coefficient=0.04)
    assert low.required(100 * FT, 0.0) == pytest.approx(0.1905, rel=REL)
    assert AashtoLrfdSeatClause(1, acceleration_coefficient=0.05).required(
        100 * FT, 0.0) == pytest.approx(10 * IN, rel=REL)
    assert clause.name == AASHTO_LRFD_CLAUSE and clause.key == "aashto-lrfd"


@pytest.mark.parametrize("kwargs, message", [
    ({"seismic_zone": 5}, "seismic_zone must be 1, 2, 3 or 4, got 5"),
    ({"seismic_zone": 2, "acceleration_coefficient": -0.1}, "acceleration_coefficient"),
    ({"seismic_zone": 2, "skew_deg": 90.0}, "skew_deg must be an angle in [0, 90)"),
])
def test_aashto_clause_object_refuses_bad_values(kwargs, message) -> None:
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("(", r"\(")
                       .replace(")", r"\)")):
        AashtoLrfdSeatClause(**kwargs)


def test_each_seat_reads_the_l_and_h_of_the_deck_on_it() -> None:
    bridge = _bridge(clause=AashtoLrfdSeatClause(3, 0.3, skew_deg=20.0))
    seats = bridge.seats()
    assert [s.name for s in seats] == ["A1", "J1", "J2", "A2"]
    for s in seats:
        need_in, l_ft, h_ft = BY_HAND[s.name]
        assert s.required_m == pytest.approx(need_in * IN, rel=REL), s.name
        assert s.deck_length_m == pytest.approx(l_ft * FT, rel=REL), s.name
        assert s.pier_height_m == pytest.approx(h_ft * FT, rel=REL), s.name
        assert s.clause == AASHTO_LRFD_CLAUSE
    # the hand table's products, written out (in): a slip in BY_HAND would show here
    assert 1.5 * 1.05 * (8 + 0.02 * 150 + 0.08 * 40) == pytest.approx(22.365)
    assert [s.width_m for s in seats] == [0.7, 0.6, 0.6, 0.7]


def test_frames_keep_their_spans() -> None:
    f = _frame([100.0, 100.0], [25.0, 35.0])
    assert f.spans == pytest.approx((100 * FT, 100 * FT), rel=REL)
    assert f.deck_length == pytest.approx(200 * FT, rel=REL)
    assert f.mean_pier_height == pytest.approx(30 * FT, rel=REL)
    assert _frame(None, [25.0]).deck_length is None
    assert f != _frame([120.0, 80.0], [25.0, 35.0])  # (spans are part of the frame)
    with pytest.raises(ValueError, match=r"spans\[1\] must be > 0"):
        BridgeFrame(1e6, [Pier(8.0, 5e7, 1e5)], Bearing.elastomeric(2e7), spans=[30.0, 0.0])


def test_seats_without_a_clause_or_with_given_widths() -> None:
    plain = _bridge(widths=(None, 0.6, None, 0.7)).seats()
    assert [(s.name, s.required_m, s.clause) for s in plain] == [("J1", None, None),
                                                                  ("A2", None, None)]
    given = GivenSeatWidths("Caltrans SDC, by hand", [None, 0.61, 0.5, 0.76])
    seats = _bridge(widths=(None, 0.6, 0.6, 0.7), clause=given).seats()
    assert [(s.name, s.required_m, s.clause, s.deck_length_m) for s in seats] == [
        ("J1", 0.61, "Caltrans SDC, by hand", None), ("J2", 0.5, "Caltrans SDC, by hand", None),
        ("A2", 0.76, "Caltrans SDC, by hand", None)]
    assert _bridge(widths=()).seats() == []


def test_a_check_without_a_clause_has_no_minimum() -> None:
    c = check_seat("J1", 0.3, 0.35, None, peak_time_s=4.0)
    assert c.required_m is None and c.clause is None and c.meets_minimum is None
    assert c.margin_m == pytest.approx(-0.05) and c.unseated and c.peak_time_s == 4.0


@pytest.mark.parametrize("change, message", [
    ({"widths": (0.7, 0.6, 0.6)}, r"seat_widths: need 4 value\(s\), one per seat \(A1, J1, J2, "
                                  r"A2; None where not checked\), got 3"),
    ({"widths": (0.7, -0.6, 0.6, 0.7)}, r"seat_widths\[1\] must be > 0"),
    ({"widths": (None, None, None, None), "clause": AashtoLrfdSeatClause(4)},
     "seat_clause: no seat has a width"),
    ({"clause": GivenSeatWidths("x", [0.5, 0.5, 0.5])},
     r"seat_clause.required: need 4 value\(s\)"),
    ({"clause": GivenSeatWidths("x", [0.5, None, 0.5, 0.5])},
     r"seat_clause.required\[1\]: seat J1 has a width but no required width"),
    ({"clause": "aashto-lrfd"}, "seat_clause: expected an AashtoLrfdSeatClause"),
    ({"frames": [(None, [25.0]), *THREE[1:]], "clause": AashtoLrfdSeatClause(4)},
     r"frames\[0\]: seat A1 is checked against AASHTO LRFD .* give the frame its spans"),
])
def test_bad_seats_are_refused_naming_the_argument(change, message) -> None:
    with pytest.raises(ValueError, match=message):
        _bridge(**change)


def test_a_seat_at_an_end_needs_an_abutment() -> None:
    frames = [_frame(s, p) for s, p in THREE]
    with pytest.raises(ValueError, match=r"seat_widths\[3\]: seat A2 is at an end with no "
                                         r"abutment \(abutments\[1\] is None\)"):
        Bridge(frames, [0.02, 0.02], abutments=(Abutment(0.05), None),
               seat_widths=(0.7, 0.6, 0.6, 0.7))
    assert Bridge(frames, [0.02, 0.02], abutments=(Abutment(0.05), None),
                  seat_widths=(0.7, 0.6, 0.6, None)).seats()[-1].name == "J2"


def test_given_widths_refuse_a_nameless_clause_and_bad_widths() -> None:
    with pytest.raises(ValueError, match="clause: name the clause"):
        GivenSeatWidths("  ", [0.5])
    with pytest.raises(ValueError, match=r"required\[0\] must be a finite length > 0 m"):
        GivenSeatWidths("x", [0.0])


def test_the_model_keeps_its_bridge_and_pickles_with_restrainers() -> None:
    """The model made of a bridge keeps it (its seats are read after a run); a bridge with
    restrainers pickles and deep-copies (a restrainer's link keywords are a read-only
    mapping, which pickle cannot take: before, ``pickle.dumps`` raised TypeError)."""
    bridge = _bridge(clause=AashtoLrfdSeatClause(3, 0.3, 20.0),
                     restrainers=[Restrainer(0, {"kind": "restrainer", "k": 1e7,
                                                 "slack": 0.01})])
    model = PoundingModel.from_bridge(bridge, ContactSpec("kelvin-voigt", k=1e9, e=0.6))
    assert model.bridge is bridge
    back = pickle.loads(pickle.dumps(model))
    assert back.bridge.seats() == bridge.seats()
    assert dict(back.bridge.restrainers[0].link) == {"kind": "restrainer", "k": 1e7,
                                                    "slack": 0.01}
    assert copy.deepcopy(bridge).seats() == bridge.seats()
    with pytest.raises(ValueError, match="bridge: the buildings must be the bridge's frames"):
        PoundingModel(list(bridge.frames)[::-1], [0.02, 0.02], model.contact, bridge=bridge)
