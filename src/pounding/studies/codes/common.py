"""What every code's separation check shares: the modal response spectrum analysis of a
model's buildings at their contact points (:func:`modal_point_peak`), the checks of the
parameters (:func:`check_fields`), the rows of neighbours' displacements combined by a
code's rule (:func:`separation_rows`), and the table the check returns (:class:`CodeCheck`,
one row per contact level of each pair of neighbours).

Units: m, s inside; the table's ``to_dict`` states its units (mm).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.units import G

__all__ = ["COMBINATIONS", "SPECTRUM_DAMPING", "CodeCheck", "CodeCheckRow", "building_periods",
           "check_fields", "cqc_matrix",
           "modal_point_peak", "pair_contacts", "separation_rows"]

FloatArray = NDArray[np.float64]

COMBINATIONS: dict[str, str] = {
    "cqc": "CQC (complete quadratic combination, Der Kiureghian 1981) of the modal "
           "displacements, modal correlation at the spectrum's 5 % damping",
    "srss": "SRSS (square root of the sum of the squares) of the modal displacements",
}
"""Modal combination rules, by name (ASCE 7-22 §12.9.1.3; EN 1998-1 §4.3.3.3.2)."""

SPECTRUM_DAMPING = 0.05
"""The damping ratio the code spectra are for, used in the CQC correlation."""


def cqc_matrix(omegas: FloatArray, zeta: float) -> FloatArray:
    """Der Kiureghian's (1981) correlation ρ_ij of modes i, j of equal damping ζ:
    ``8 ζ² (1 + β) β^1.5 / ((1 − β²)² + 4 ζ² β (1 + β)²)``, ``β = ω_j/ω_i`` (Chopra,
    *Dynamics of Structures*, eq. 13.7.10)."""
    beta = omegas[np.newaxis, :] / omegas[:, np.newaxis]
    z2 = zeta * zeta
    return (8.0 * z2 * (1.0 + beta) * beta ** 1.5
            / ((1.0 - beta * beta) ** 2 + 4.0 * z2 * beta * (1.0 + beta) ** 2))


def modal_point_peak(building: Any, point: Any, sa_g: Callable[[FloatArray], Any],
                     combination: str = "cqc") -> tuple[float, list[float]]:
    """Peak displacement [m] of one contact point of a building by modal response spectrum
    analysis, every mode kept (Chopra §13.8).

    Mode n contributes ``r_n = Σ_j w_j Γ_n φ_jn D_n`` with ``D_n = Sa(T_n) (T_n/2π)²`` and
    ``w_j`` the point's floor weights (1 at a floor; the storey's ``1 − ξ, ξ`` on a column);
    the peaks combine by SRSS, ``sqrt(Σ r_n²)``, or CQC, ``sqrt(Σ_i Σ_j ρ_ij r_i r_j)``.

    Parameters
    ----------
    building : a building with ``modes()`` (shear or matrix building)
    point : :class:`pounding.contact.geometry.ContactPoint`
    sa_g : callable
        The spectrum used, pseudo-acceleration [g] at an array of periods [s].
    combination : {"cqc", "srss"}

    Returns
    -------
    peak : float
        The combined peak [m].
    modal : list of float
        ``r_n`` of each mode [m] (signed), longest period first.
    """
    if combination not in COMBINATIONS:
        raise ValueError(f"combination: must be one of {', '.join(COMBINATIONS)} "
                         f"(got {combination!r})")
    modes = building.modes()
    periods = np.asarray(modes.periods, dtype=float)
    sd = np.asarray(sa_g(periods), dtype=float) * G * (periods / (2.0 * np.pi)) ** 2
    per_floor = np.asarray(modes.modal_contributions, dtype=float) * sd[np.newaxis, :]
    r = np.asarray(point.of(per_floor.T), dtype=float)  # (n_modes,)
    if combination == "srss":
        peak = math.sqrt(float(np.sum(r * r)))
    else:
        rho = cqc_matrix(2.0 * np.pi / periods, SPECTRUM_DAMPING)
        with np.errstate(over="ignore", invalid="ignore"):  # (refused below)
            quad = float(r @ rho @ r)
        peak = math.sqrt(max(0.0, quad)) if math.isfinite(quad) else math.nan
    if not (math.isfinite(peak) and np.isfinite(r).all()):
        raise ValueError(f"spectrum: the modal displacements of building "
                         f"{building.name or '?'} are not finite numbers (a spectral value "
                         f"of {float(np.max(np.abs(sa_g(periods)))):.3g} g); check the "
                         "spectrum's parameters")
    return peak, [float(v) for v in r]


def check_fields(p: Any, *, positive: Sequence[str] = (), at_least_one: Sequence[str] = (),
                 choices: dict[str, tuple[Sequence[Any], str]] | None = None) -> None:
    """The checks every code's parameters share, each failure one line naming the field and
    the value: ``positive`` fields finite and > 0, ``at_least_one`` fields finite and ≥ 1,
    ``choices`` fields one of their values (``name: (values, clause)``, a string field
    compared in upper case and stored so), and ``p.combination`` one of
    :data:`COMBINATIONS` where ``p`` has one."""
    from pounding.validation import positive as check_positive

    for name in positive:
        check_positive(name, getattr(p, name))
    for name in at_least_one:
        value = getattr(p, name)
        if value is not None and not (isinstance(value, (int, float))
                                      and math.isfinite(value) and value >= 1.0):
            raise ValueError(f"{name}: must be finite and >= 1 (got {value!r})")
    for name, (allowed, clause) in (choices or {}).items():
        value = getattr(p, name)
        key = str(value).strip().upper() if isinstance(value, str) else value
        if key not in allowed:
            raise ValueError(f"{name}: must be one of {', '.join(map(str, allowed))} "
                             f"({clause}) (got {value!r})")
        object.__setattr__(p, name, key)
    combination = getattr(p, "combination", "cqc")
    if combination not in COMBINATIONS:
        raise ValueError(f"combination: must be one of {', '.join(COMBINATIONS)} "
                         f"(got {combination!r})")


def separation_rows(model: Any, displacement: Callable[[Any, Any], float], *,
                    same_site: str, apart: str | None, same_property: bool = True,
                    rule: str = "srss", floor_factor: tuple[float, str] | None = None
                    ) -> tuple[CodeCheckRow, ...]:
    """One :class:`CodeCheckRow` per contact level of ``model``'s pairs of neighbours.

    Parameters
    ----------
    displacement : callable
        ``displacement(building, point)``: the code's displacement [m] of ``building`` at
        the contact ``point``.
    same_site, apart : str
        The clause of the rule for buildings on one property, and of the property-line
        setback (``None``: the code has one rule; ``same_property`` is then ignored).
    rule : {"srss", "sum"}
        How the two displacements combine on one property: ``sqrt(d1² + d2²)`` or
        ``d1 + d2``. Across a property line each building keeps its own: ``d1 + d2``.
    floor_factor : (float, str), optional
        A factor on the separation where the two floors meet at the same elevation, and
        its clause.
    """
    rows = []
    for c in pair_contacts(model):
        d = [displacement(model.buildings[point.building], point)
             for point in (c.left, c.right)]
        if not all(math.isfinite(x) for x in d):  # (never a NaN read as 0 mm and "OK")
            raise ValueError(f"spectrum: the code's displacement at {c.label} is not a finite "
                             f"number ({d[0]!r}, {d[1]!r}); check the spectrum's parameters")
        if same_property or apart is None:
            required = math.hypot(d[0], d[1]) if rule == "srss" else d[0] + d[1]
            clause = same_site
        else:
            required, clause = d[0] + d[1], apart
        if floor_factor is not None and c.is_floor_to_floor:
            required *= floor_factor[0]
            clause += f" × {floor_factor[0]:g} {floor_factor[1]}"
        rows.append(CodeCheckRow(f"B{c.pair + 1}-B{c.pair + 2}", c.label, float(c.elevation),
                                 d[0], d[1], required, float(c.gap), clause))
    return tuple(rows)


def pair_contacts(model: Any) -> list[Any]:
    """The contacts between neighbouring buildings (not a moat wall's, not a bumper's pad),
    pair by pair, bottom to top. Refuses a model the check does not cover, in one line."""
    if getattr(model, "walls", None):
        raise ValueError("model: code-check covers gaps between buildings; the model's moat "
                         "wall(s) ([[wall]]) are not covered yet (remove them)")
    if any(c.tag for c in model.contacts):
        raise ValueError("model: code-check reads the gap between the buildings; a bumper in "
                         "the gap ([[device]] bumper) is not covered (remove it)")
    contacts = [c for c in model.contacts if not c.on_wall]
    if any(c.left.twist is not None or c.right.twist is not None for c in contacts):
        raise ValueError("model: code-check takes each building's modes along the row; "
                         "buildings in plan (twisting floors) are not covered yet")
    if not contacts:
        raise ValueError(f"model: code-check needs two or more neighbouring buildings "
                         f"(got {len(model.buildings)} building(s) and no contact)")
    return contacts


@dataclass(frozen=True)
class CodeCheckRow:
    """One contact level of one pair: the code's displacements, the separation it asks for
    and the model's gap (all in m)."""

    pair: str
    contact: str
    elevation: float
    left: float
    right: float
    required: float
    gap: float
    clause: str

    @property
    def ok(self) -> bool:
        """The model's gap is at least the required separation."""
        return self.gap >= self.required


@dataclass(frozen=True)
class CodeCheck:
    """A code's separation check of a model, floor by floor.

    Attributes
    ----------
    code : str
        The code's key (``"asce7-22"``, ``"en1998-1"``, ``"nzs1170.5"``, ``"nbcc2020"``,
        ``"is1893"``).
    title : str
        The code's name and edition.
    displacement : str
        What the ``left`` and ``right`` columns are (δ_M, d_s, d, Δ, R Δ), with the
        clause.
    rows : tuple of CodeCheckRow
    parameters : dict
        The code's inputs as used (including defaults taken); ``"buildings"``, where
        present, what the code derived per building (ASCE 7-22: T, C_s, W, V, …).
    assumptions : tuple of str
        What the check assumes, in plain words.
    clauses : dict
        Clause → formula, for every clause the numbers cite.
    periods : dict
        Building name → its periods [s] (longest first).
    """

    code: str
    title: str
    displacement: str
    rows: tuple[CodeCheckRow, ...]
    parameters: dict[str, Any]
    assumptions: tuple[str, ...]
    clauses: dict[str, str]
    periods: dict[str, list[float]] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        """Every level's gap meets the code."""
        return all(row.ok for row in self.rows)

    def to_dict(self) -> dict[str, Any]:
        """The check as JSON-ready data (lengths in mm, periods in s)."""
        return {
            "code": self.code,
            "title": self.title,
            "units": "mm (displacements, separations, gaps), m (elevation), s (periods)",
            "displacement": self.displacement,
            "parameters": self.parameters,
            "assumptions": list(self.assumptions),
            "clauses": self.clauses,
            "periods_s": self.periods,
            "ok": self.ok,
            "levels": [
                {"pair": r.pair, "contact": r.contact, "elevation_m": r.elevation,
                 "left_mm": 1e3 * r.left, "right_mm": 1e3 * r.right,
                 "required_mm": 1e3 * r.required, "gap_mm": 1e3 * r.gap, "ok": r.ok,
                 "clause": r.clause}
                for r in self.rows],
        }


def building_periods(buildings: Sequence[Any]) -> dict[str, list[float]]:
    """Each building's periods [s], by name (``B1``, … where it has none)."""
    return {(b.name or f"B{i + 1}"): [float(t) for t in b.modes().periods]
            for i, b in enumerate(buildings)}
