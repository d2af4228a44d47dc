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

Not implemented, for want of a source read (see docs/bridges.md): the AASHTO Guide
Specifications for LRFD Seismic Bridge Design §4.12 (percentages by SDC and the SDC D
equation) and the Caltrans Seismic Design Criteria seat-width equations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

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
    required_m : float
        Minimum seat width of the clause [m].
    clause : str
        The clause ``required_m`` comes from.
    peak_relative_displacement_m : float
        Peak opening at the seat [m] (see :func:`unseating_margin`).
    margin_m : float
        ``width_m − peak_relative_displacement_m`` [m]; negative: unseated.
    """

    seat: str
    width_m: float
    required_m: float
    clause: str
    peak_relative_displacement_m: float
    margin_m: float

    @property
    def unseated(self) -> bool:
        """True when the peak opening exceeded the seat width (margin < 0)."""
        return self.margin_m < 0.0

    @property
    def meets_minimum(self) -> bool:
        """True when the seat is at least as wide as the clause requires."""
        return self.width_m >= self.required_m


def check_seat(seat: str, width_m: float, peak_opening_m: float, required_m: float,
               clause: str = AASHTO_LRFD_CLAUSE) -> SeatCheck:
    """Build the :class:`SeatCheck` of one seat from a run's peak opening.

    Parameters
    ----------
    seat : str
        The seat's label.
    width_m : float
        Seat width provided [m], > 0.
    peak_opening_m : float
        Peak opening of the joint at the seat [m], finite.
    required_m : float
        Minimum seat width of the clause [m], ≥ 0 (e.g. from
        :func:`aashto_lrfd_required_support_length`).
    clause : str
        The clause ``required_m`` comes from.

    Returns
    -------
    SeatCheck

    Raises
    ------
    ValueError
        On a bad width, opening or requirement; the message names it and its value.
    """
    required = _length("required_m", required_m)
    margin = unseating_margin(peak_opening_m, width_m)
    return SeatCheck(seat=str(seat), width_m=float(width_m), required_m=required,
                     clause=clause, peak_relative_displacement_m=float(peak_opening_m),
                     margin_m=margin)


__all__ = [
    "AASHTO_LRFD_CLAUSE",
    "FOOT_M",
    "INCH_M",
    "SeatCheck",
    "aashto_empirical_support_length",
    "aashto_lrfd_required_support_length",
    "aashto_lrfd_support_length_percent",
    "check_seat",
    "unseating_margin",
]
