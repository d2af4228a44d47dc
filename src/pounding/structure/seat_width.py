"""Seat widths and the unseating margin of a bridge deck at an expansion joint or an abutment.

A deck falls off its seat when the joint opens by more than the seat can carry. The check a
bridge model's outputs make is

    margin = seat width − peak opening of the joint      (negative: unseated)

and the seat width it is judged against is the minimum support length of the code clause.

Implemented clause (SI in and out, metres and degrees):

* AASHTO LRFD Bridge Design Specifications, Art. 4.7.4.4, Eq. 4.7.4.4-1, the empirical
  minimum support length

      N = (8 + 0.02 L + 0.08 H)(1 + 0.000125 S²)      [N in in; L, H in ft; S in degrees]

  (:func:`aashto_empirical_support_length`), and the percentage of N of Table 4.7.4.4-1 by
  seismic zone (:func:`aashto_lrfd_support_length_percent`,
  :func:`aashto_lrfd_required_support_length`).

The US-customary equation is converted exactly (1 in = 0.0254 m, 1 ft = 0.3048 m, so
0.02 in/ft = 1/600 and 0.08 in/ft = 1/150 of a length):

      N [m] = (0.2032 + L/600 + H/150)(1 + 0.000125 S²)      [L, H in m]

The SI edition of AASHTO rounds these to (200 mm + 0.0017 L + 0.0067 H); against that rounded
form the exact conversion used here is 1.6 % larger in the constant (203.2 mm), 2.0 % smaller
in the L term and 0.5 % smaller in the H term, so the two differ by less than 2 %.

A bridge's seats are checked against a clause object
(:attr:`pounding.structure.bridge.Bridge.seat_clause`): :class:`AashtoLrfdSeatClause`
(the article above, its zone, A_s and skew) or
:class:`GivenSeatWidths` (the widths another clause asks, computed by the engineer and
stated with the clause's name).

Not implemented, for want of a source that could be read and checked (see
docs/bridges.md): the AASHTO Guide Specifications for LRFD Seismic Bridge Design §4.12
(percentages by SDC and the SDC D equation) and the Caltrans Seismic Design Criteria
seat-width equations; give their widths with :class:`GivenSeatWidths`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import ClassVar

INCH_M: float = 0.0254
"""One inch in metres (exact, international inch of 1959)."""

FOOT_M: float = 0.3048
"""One foot in metres (exact, international foot of 1959)."""

AASHTO_LRFD_CLAUSE: str = "AASHTO LRFD Art. 4.7.4.4 (Eq. 4.7.4.4-1, Table 4.7.4.4-1)"
"""The clause :func:`aashto_lrfd_required_support_length` implements, as a SeatCheck names it."""

_SEISMIC_ZONES = (1, 2, 3, 4)


# ==================================================================================== checks
def _length(name: str, value: float) -> float:
    """A finite length ≥ 0 m, or a ValueError naming the argument and the value."""
    v = float(value)
    if not math.isfinite(v) or v < 0.0:
        raise ValueError(f"{name} must be a finite length >= 0 m, got {value!r}")
    return v


def _positive_length(name: str, value: float) -> float:
    v = float(value)
    if not math.isfinite(v) or v <= 0.0:
        raise ValueError(f"{name} must be a finite length > 0 m, got {value!r}")
    return v


def _finite(name: str, value: float) -> float:
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be a finite number in m, got {value!r}")
    return v


def _skew(name: str, value: float) -> float:
    v = float(value)
    if not math.isfinite(v) or not 0.0 <= v < 90.0:
        raise ValueError(f"{name} must be an angle in [0, 90) degrees, got {value!r}")
    return v


# ================================================================== AASHTO LRFD Art. 4.7.4.4
def aashto_empirical_support_length(deck_length_m: float, column_height_m: float,
                                    skew_deg: float) -> float:
    """Empirical minimum support length N of AASHTO LRFD Art. 4.7.4.4, Eq. 4.7.4.4-1 [m].

    ``N = (8 + 0.02 L + 0.08 H)(1 + 0.000125 S²)`` in inches with L and H in feet, converted
    exactly to ``N = (0.2032 + L/600 + H/150)(1 + 0.000125 S²)`` in metres with L and H in
    metres (1 in = 0.0254 m, 1 ft = 0.3048 m).

    Parameters
    ----------
    deck_length_m : float
        L, the length of the bridge deck to the adjacent expansion joint or to the end of
        the bridge deck [m], ≥ 0.
    column_height_m : float
        H, the average height of the columns (or piers) supporting the deck from the seat
        to the next expansion joint [m], ≥ 0; 0 for a single-span bridge.
    skew_deg : float
        S, the skew of the support measured from a line normal to the span [degrees], in
        [0, 90).

    Returns
    -------
    float
        N [m]: 100 % of the empirical support length, before the percentage of
        Table 4.7.4.4-1 (:func:`aashto_lrfd_required_support_length` applies it).

    Raises
    ------
    ValueError
        If a length is negative or not finite, or the skew is outside [0, 90) degrees; the
        message names the argument and its value.
    """
    length = _length("deck_length_m", deck_length_m)
    height = _length("column_height_m", column_height_m)
    skew = _skew("skew_deg", skew_deg)
    base_m = 8.0 * INCH_M + length * (0.02 * INCH_M / FOOT_M) + height * (0.08 * INCH_M / FOOT_M)
    return base_m * (1.0 + 0.000125 * skew * skew)


def aashto_lrfd_support_length_percent(seismic_zone: int,
                                       acceleration_coefficient: float) -> float:
    """Percentage of N required by AASHTO LRFD Table 4.7.4.4-1, by seismic zone [%].

    Zone 1 with A_s < 0.05: 75 (the table's "≥ 75"); zone 1 with A_s ≥ 0.05: 100;
    zones 2, 3 and 4: 150.

    Parameters
    ----------
    seismic_zone : int
        The seismic zone of AASHTO LRFD Art. 3.10.6 (1, 2, 3 or 4).
    acceleration_coefficient : float
        A_s, the peak seismic ground acceleration coefficient modified by the short-period
        site factor (Art. 3.10.4.2) [g], ≥ 0; read only in zone 1.

    Returns
    -------
    float
        The percentage of N (75, 100 or 150).

    Raises
    ------
    ValueError
        If the zone is not 1–4 or A_s is negative or not finite.

    Notes
    -----
    The table was read in one source only (a public fix log quoting AASHTO LRFD 10th ed.,
    2024); it could not be checked against a second one. See docs/bridges.md.
    """
    if isinstance(seismic_zone, bool) or seismic_zone not in _SEISMIC_ZONES:
        raise ValueError(f"seismic_zone must be 1, 2, 3 or 4, got {seismic_zone!r}")
    a_s = float(acceleration_coefficient)
    if not math.isfinite(a_s) or a_s < 0.0:
        raise ValueError("acceleration_coefficient must be a finite coefficient >= 0 (g), "
                         f"got {acceleration_coefficient!r}")
    if seismic_zone == 1:
        return 75.0 if a_s < 0.05 else 100.0
    return 150.0


def aashto_lrfd_required_support_length(deck_length_m: float, column_height_m: float,
                                        skew_deg: float, seismic_zone: int,
                                        acceleration_coefficient: float) -> float:
    """Minimum support length of AASHTO LRFD Art. 4.7.4.4: the percentage times N [m].

    ``N_req = p/100 · N`` with N of Eq. 4.7.4.4-1 (:func:`aashto_empirical_support_length`)
    and p of Table 4.7.4.4-1 (:func:`aashto_lrfd_support_length_percent`).

    Parameters
    ----------
    deck_length_m, column_height_m, skew_deg : float
        L [m], H [m] and S [degrees] as in :func:`aashto_empirical_support_length`.
    seismic_zone : int
        1–4.
    acceleration_coefficient : float
        A_s [g], ≥ 0.

    Returns
    -------
    float
        The required seat width [m].
    """
    percent = aashto_lrfd_support_length_percent(seismic_zone, acceleration_coefficient)
    return percent / 100.0 * aashto_empirical_support_length(deck_length_m, column_height_m,
                                                             skew_deg)


# ============================================================= the clause of a bridge's seats
@dataclass(frozen=True)
class AashtoLrfdSeatClause:
    """AASHTO LRFD Art. 4.7.4.4 at a bridge's seats: the percentage of Table 4.7.4.4-1 of
    the empirical support length N (:func:`aashto_lrfd_required_support_length`).

    Parameters
    ----------
    seismic_zone : int
        The seismic zone of AASHTO LRFD Art. 3.10.6 (1, 2, 3 or 4).
    acceleration_coefficient : float
        A_s [g], ≥ 0 (read in zone 1 only; default 0).
    skew_deg : float
        S, the skew of the supports [degrees], in [0, 90) (default 0), the same at every
        seat.

    Examples
    --------
    >>> clause = AashtoLrfdSeatClause(seismic_zone=4, acceleration_coefficient=0.4)
    >>> round(clause.required(60.96, 7.62), 5)   # L = 200 ft, H = 25 ft: 150 % of 14 in
    0.5334
    """

    seismic_zone: int
    acceleration_coefficient: float = 0.0
    skew_deg: float = 0.0

    key: ClassVar[str] = "aashto-lrfd"
    """The clause's name in a model file (``seat_clause = { clause = "aashto-lrfd" }``)."""

    name: ClassVar[str] = AASHTO_LRFD_CLAUSE
    """The clause as a :class:`SeatCheck` names it."""

    def __post_init__(self) -> None:
        aashto_lrfd_support_length_percent(self.seismic_zone, self.acceleration_coefficient)
        _skew("skew_deg", self.skew_deg)

    def required(self, deck_length_m: float, column_height_m: float) -> float:
        """The minimum support length [m] for a deck of length L and columns of average
        height H [m] (:func:`aashto_lrfd_required_support_length`)."""
        return aashto_lrfd_required_support_length(deck_length_m, column_height_m,
                                                   self.skew_deg, self.seismic_zone,
                                                   self.acceleration_coefficient)


@dataclass(frozen=True)
class GivenSeatWidths:
    """Required seat widths stated seat by seat, with the clause they come from: for a
    clause this module does not implement (the AASHTO Guide Specifications §4.12, the
    Caltrans SDC), computed by the engineer.

    Parameters
    ----------
    clause : str
        The clause the widths come from, as the outputs name it (e.g. ``"Caltrans SDC 2.0,
        computed by hand"``); not empty.
    required : sequence of float or None
        The required width of every seat of the bridge [m], > 0: the left abutment, each
        joint left to right, the right abutment (None at a seat not checked).
    """

    clause: str
    required: tuple[float | None, ...]

    key: ClassVar[str] = "given"
    """The clause's name in a model file (``seat_clause = { clause = "given", ... }``)."""

    def __init__(self, clause: str, required: Sequence[float | None]) -> None:
        if not isinstance(clause, str) or not clause.strip():
            raise ValueError(f"clause: name the clause the required widths come from (got "
                             f"{clause!r})")
        values = tuple(None if w is None else _positive_length(f"required[{i}]", w)
                       for i, w in enumerate(required))
        object.__setattr__(self, "clause", clause.strip())
        object.__setattr__(self, "required", values)

    @property
    def name(self) -> str:
        """The clause as a :class:`SeatCheck` names it."""
        return self.clause


SeatClause = AashtoLrfdSeatClause | GivenSeatWidths
"""A clause a bridge's seats are checked against."""


# ================================================================================ the margin
def unseating_margin(peak_opening_m: float, seat_width_m: float) -> float:
    """Unseating margin of a seat: seat width − peak opening of the joint [m].

    Parameters
    ----------
    peak_opening_m : float
        The peak relative displacement at the seat in the direction that moves the deck off
        it (the largest opening of the joint, or of the deck end away from the abutment's
        backwall, measured from the position at which the seat width is given) [m]. Finite;
        zero or negative when the joint never opened.
    seat_width_m : float
        The seat width provided [m], > 0.

    Returns
    -------
    float
        The margin [m]; negative means the deck is unseated (it moved farther than the seat
        is wide).

    Raises
    ------
    ValueError
        If the opening is not finite or the seat width is not a finite length > 0.
    """
    opening = _finite("peak_opening_m", peak_opening_m)
    width = _positive_length("seat_width_m", seat_width_m)
    return width - opening


@dataclass(frozen=True)
class SeatCheck:
    """The unseating check of one seat (an expansion joint or an abutment).

    Attributes
    ----------
    seat : str
        The seat's label (e.g. ``"A1"``, ``"J2"``).
    width_m : float
        Seat width provided [m].
    required_m : float or None
        Minimum seat width of the clause [m] (None: no clause checked).
    clause : str or None
        The clause ``required_m`` comes from (None: no clause).
    peak_relative_displacement_m : float
        Peak opening at the seat [m] (see :func:`unseating_margin`).
    margin_m : float
        ``width_m − peak_relative_displacement_m`` [m]; negative: unseated.
    peak_time_s : float or None
        When the opening peaked [s] (None: not known, or the seat never opened).
    deck_length_m, pier_height_m : float or None
        The L and H the clause was evaluated with [m] (None where it reads neither).
    """

    seat: str
    width_m: float
    required_m: float | None
    clause: str | None
    peak_relative_displacement_m: float
    margin_m: float
    peak_time_s: float | None = None
    deck_length_m: float | None = None
    pier_height_m: float | None = None

    @property
    def unseated(self) -> bool:
        """True when the peak opening exceeded the seat width (margin < 0)."""
        return self.margin_m < 0.0

    @property
    def meets_minimum(self) -> bool | None:
        """True when the seat is at least as wide as the clause requires (None: no
        clause)."""
        return None if self.required_m is None else self.width_m >= self.required_m


def check_seat(seat: str, width_m: float, peak_opening_m: float, required_m: float | None,
               clause: str | None = AASHTO_LRFD_CLAUSE, *, peak_time_s: float | None = None,
               deck_length_m: float | None = None,
               pier_height_m: float | None = None) -> SeatCheck:
    """Build the :class:`SeatCheck` of one seat from a run's peak opening.

    Parameters
    ----------
    seat : str
        The seat's label.
    width_m : float
        Seat width provided [m], > 0.
    peak_opening_m : float
        Peak opening of the joint at the seat [m], finite.
    required_m : float or None
        Minimum seat width of the clause [m], ≥ 0 (e.g. from
        :func:`aashto_lrfd_required_support_length`); None: no clause (``clause`` is then
        None too).
    clause : str or None
        The clause ``required_m`` comes from.
    peak_time_s, deck_length_m, pier_height_m : float, optional
        When the opening peaked [s]; the L and H [m] the requirement was evaluated with.

    Returns
    -------
    SeatCheck

    Raises
    ------
    ValueError
        On a bad width, opening or requirement; the message names it and its value.
    """
    required = None if required_m is None else _length("required_m", required_m)
    margin = unseating_margin(peak_opening_m, width_m)
    return SeatCheck(seat=str(seat), width_m=float(width_m), required_m=required,
                     clause=None if required is None else clause,
                     peak_relative_displacement_m=float(peak_opening_m), margin_m=margin,
                     peak_time_s=None if peak_time_s is None else float(peak_time_s),
                     deck_length_m=None if deck_length_m is None else float(deck_length_m),
                     pier_height_m=None if pier_height_m is None else float(pier_height_m))


__all__ = [
    "AASHTO_LRFD_CLAUSE",
    "FOOT_M",
    "INCH_M",
    "AashtoLrfdSeatClause",
    "GivenSeatWidths",
    "SeatCheck",
    "SeatClause",
    "aashto_empirical_support_length",
    "aashto_lrfd_required_support_length",
    "aashto_lrfd_support_length_percent",
    "check_seat",
    "unseating_margin",
]
