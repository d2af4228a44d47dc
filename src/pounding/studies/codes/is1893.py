"""IS 1893 (Part 1):2016 §7.11.3 separation between adjacent units or buildings, with the
storey displacements of §7.11.1 from the model's own modal response spectrum analysis
(§7.7.5) on the design spectrum of §6.4. See ``docs/codes.md`` (which says what of the
standard's text was read and what was not).

* §6.4: ``A_h = (Z/2) (I/R) (Sa/g)`` with ``Sa/g`` for soil types I–III
  (:meth:`~pounding.spectra.design.DesignSpectrum.is1893`);
* §7.11.1: the storey displacements Δ under the design lateral force (on ``A_h``);
* §7.11.3: two adjacent buildings (or units) are separated by ``R (Δ1 + Δ2)``; where their
  floor levels are at the same elevation, by ``(R/2) (Δ1 + Δ2)``.

The table's displacement of each building is ``R Δ``. Units: m, s; spectral values in g.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pounding.studies.codes.common import (
    COMBINATIONS,
    CodeCheck,
    building_periods,
    check_fields,
    modal_point_peak,
    separation_rows,
)

__all__ = ["CODE", "TITLE", "Is1893Parameters", "check"]

CODE = "is1893"
TITLE = "IS 1893 (Part 1):2016 §7.11.3"

CLAUSES: dict[str, str] = {
    "§6.4": "A_h = (Z/2)(I/R)(Sa/g); Sa/g = 1 + 15T (T ≤ 0.1 s), 2.5 (≤ T_c), c/T "
            "(≤ 4 s); T_c, c = 0.40, 1.00 / 0.55, 1.36 / 0.67, 1.67 (soil I/II/III)",
    "§7.7.5": "modal response spectrum analysis: CQC (or SRSS)",
    "§7.11.1": "Δ: storey displacement under the design lateral force",
    "§7.11.3": "separation ≥ R (Δ1 + Δ2)",
    "§7.11.3 (R/2)": "floor levels at the same elevation: R/2 in place of R",
}
"""The clauses the check cites, with their formulas."""

FLOOR_LEVEL_FACTOR = 0.5
"""§7.11.3: R/2 in place of R where the floor levels coincide."""


@dataclass(frozen=True)
class Is1893Parameters:
    """The inputs of the IS 1893 check.

    Attributes
    ----------
    z : float
        Zone factor Z (Table 3: 0.10, 0.16, 0.24, 0.36 for zones II–V), > 0.
    importance : float
        Importance factor I (Table 8), > 0.
    r : float
        Response reduction factor R (Table 9), ≥ 1.
    soil_type : {"I", "II", "III"}
        Rock or hard soil, medium or stiff soil, soft soil (also 1, 2, 3).
    combination : {"cqc", "srss"}
    """

    z: float
    importance: float
    r: float
    soil_type: str
    same_property: bool = True
    combination: str = "cqc"

    def __post_init__(self) -> None:
        from pounding.spectra.code_spectra import IS1893_SOIL_CORNERS

        soil = str(self.soil_type).strip()
        object.__setattr__(self, "soil_type", {"1": "I", "2": "II", "3": "III"}.get(soil, soil))
        check_fields(self, positive=("z", "importance"), at_least_one=("r",),
                     choices={"soil_type": (tuple(IS1893_SOIL_CORNERS),
                                            "IS 1893 (Part 1):2016 Table 4")})
        if not self.same_property:
            raise ValueError("property_line: IS 1893 §7.11.3 has one rule, R (Δ1 + Δ2), "
                             "already the sum of the two")


PARAMETERS = Is1893Parameters
"""The parameters of this code's check."""


def check(model: Any, p: Is1893Parameters) -> CodeCheck:
    """The separation IS 1893 §7.11.3 asks for at every contact level of ``model``, beside
    the model's gap (:class:`~pounding.studies.codes.common.CodeCheck`)."""
    from pounding.spectra import DesignSpectrum

    for name, periods in building_periods(model.buildings).items():
        if periods[0] > 4.0:
            raise ValueError(f"model: building {name}'s first period is {periods[0]:.3g} s, "
                             "beyond the 4 s where IS 1893 §6.4's Sa/g ends (a site-specific "
                             "spectrum is needed there): not covered")
    spectrum = DesignSpectrum.is1893(p.z, p.importance, p.r, p.soil_type)

    def r_delta(building: Any, point: Any) -> float:  # R Δ (§7.11.1, §7.11.3)
        return p.r * modal_point_peak(building, point, spectrum.sa_g, p.combination)[0]

    rows = separation_rows(model, r_delta, same_site="§7.11.3", apart=None, rule="sum",
                           floor_factor=(FLOOR_LEVEL_FACTOR, "(R/2)"))
    return CodeCheck(
        code=CODE, title=TITLE,
        displacement="R Δ, Δ the displacement by modal response spectrum analysis (§7.7.5) "
                     "on A_h = (Z/2)(I/R)(Sa/g) (§6.4, §7.11.1)",
        rows=rows,
        parameters={"z": p.z, "importance": p.importance, "r": p.r,
                    "soil_type": p.soil_type, "combination": p.combination},
        assumptions=(
            "linear elastic analysis of each building alone (its modes at initial stiffness)",
            ("the design spectrum of §6.4 for the soil type, 5 % damping, to 4 s (a longer "
             "period is refused)"),
            (f"Δ: every mode, combined by {COMBINATIONS[p.combination]}; no scaling to the "
             "equivalent static base shear (§7.7.3), which scales forces"),
            "one R for both buildings (the command's --r)",
            ("R/2 at every floor-to-floor contact; R where a floor meets a column"),
            ("§7.11.3 read as quoted on a forum (R × the combined deflections); the R/2 "
             "sentence was not read (docs/codes.md)"),
        ),
        clauses=dict(CLAUSES),
        periods=building_periods(model.buildings),
    )
