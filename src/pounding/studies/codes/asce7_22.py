"""ASCE/SEI 7-22 §12.12 structural separation, with the elastic displacements of the
model's own modal response spectrum analysis (§12.9.1). See ``docs/codes.md``.

* eq. (12.12-1): ``δ_M = C_d δ_max / I_e``, the maximum inelastic response displacement at
  a critical location, ``δ_max`` the maximum elastic displacement there;
* eq. (12.12-2): adjacent structures on the same property are separated by at least
  ``δ_MT = sqrt(δ_M1² + δ_M2²)``;
* a structure adjoining a property line (not common to a public way) is set back from it
  by at least its own ``δ_M``: two neighbours on two properties, the line between them,
  need ``δ_M1 + δ_M2``.

``δ_max`` comes from the modal response spectrum analysis of §12.9.1: every mode of each
building, the design response spectrum of §11.4.6 (``S_DS``, ``S_D1``, ``T_L``), each
mode's displacement from the spectrum divided by ``R/I_e`` (§12.9.1.2), combined by CQC
(or SRSS, §12.9.1.3). The scaling of §12.9.1.4 to the equivalent lateral force procedure's
base shear is **not** applied (it needs the ELF's ``C_s`` and the seismic weight).

Units: m, s; spectral values in g.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pounding.studies.codes.common import (
    COMBINATIONS,
    CodeCheck,
    CodeCheckRow,
    building_periods,
    modal_point_peak,
    pair_contacts,
)
from pounding.validation import positive

__all__ = ["CODE", "TITLE", "Asce722Parameters", "check"]

CODE = "asce7-22"
TITLE = "ASCE/SEI 7-22 §12.12"

CLAUSES: dict[str, str] = {
    "§11.4.6": "Sa = S_DS (0.4 + 0.6 T/T0) for T < T0; S_DS to T_S; S_D1/T to T_L; "
               "S_D1 T_L/T² beyond (T0 = 0.2 S_D1/S_DS, T_S = S_D1/S_DS)",
    "§12.9.1.2": "modal displacement u_n = Γ_n φ_n Sa(T_n) g (T_n/2π)² × I_e/R",
    "§12.9.1.3": "modal combination: CQC (or SRSS)",
    "eq. 12.12-1": "δ_M = C_d δ_max / I_e",
    "eq. 12.12-2": "δ_MT = sqrt(δ_M1² + δ_M2²) (adjacent structures on the same property)",
    "§12.12 (property line)": "setback from a property line ≥ δ_M of the structure: "
                              "δ_M1 + δ_M2 for two properties",
}
"""The clauses the check cites, with their formulas."""


@dataclass(frozen=True)
class Asce722Parameters:
    """The inputs of the ASCE 7-22 check.

    Attributes
    ----------
    sds, sd1 : float
        Design spectral accelerations S_DS, S_D1 [g] (§11.4.5), > 0.
    tl : float
        Long-period transition period T_L [s] (§11.4.6), > 0.
    cd : float
        Deflection amplification factor C_d (Table 12.2-1), > 0.
    r : float
        Response modification coefficient R (Table 12.2-1), > 0.
    ie : float
        Importance factor I_e (Table 1.5-2), > 0.
    same_property : bool
        Eq. 12.12-2 (true) or two property-line setbacks (false).
    combination : {"cqc", "srss"}
    """

    sds: float
    sd1: float
    tl: float
    cd: float
    r: float
    ie: float
    same_property: bool = True
    combination: str = "cqc"

    def __post_init__(self) -> None:
        for name in ("sds", "sd1", "tl", "cd", "r", "ie"):
            positive(name, getattr(self, name))
        if self.combination not in COMBINATIONS:
            raise ValueError(f"combination: must be one of {', '.join(COMBINATIONS)} "
                             f"(got {self.combination!r})")


PARAMETERS = Asce722Parameters
"""The parameters of this code's check."""


def check(model: Any, p: Asce722Parameters) -> CodeCheck:
    """The separation ASCE 7-22 §12.12 asks for at every contact level of ``model``,
    beside the model's gap (:class:`~pounding.studies.codes.common.CodeCheck`)."""
    from pounding.spectra import DesignSpectrum

    spectrum = DesignSpectrum.asce7(p.sds, p.sd1, p.tl)

    def design_sa_g(periods: Any) -> Any:  # §12.9.1.2: the spectrum divided by R/I_e
        return spectrum.sa_g(periods) * p.ie / p.r

    rows = []
    for c in pair_contacts(model):
        peaks = []
        for point in (c.left, c.right):
            d_max, _ = modal_point_peak(model.buildings[point.building], point, design_sa_g,
                                        p.combination)
            peaks.append(p.cd * d_max / p.ie)  # eq. 12.12-1
        if p.same_property:
            required = (peaks[0] ** 2 + peaks[1] ** 2) ** 0.5
            clause = "eq. 12.12-2"
        else:
            required = peaks[0] + peaks[1]
            clause = "§12.12 (property line)"
        rows.append(CodeCheckRow(f"B{c.pair + 1}-B{c.pair + 2}", c.label, float(c.elevation),
                                 peaks[0], peaks[1], required, float(c.gap), clause))
    return CodeCheck(
        code=CODE, title=TITLE,
        displacement="δ_M = C_d δ_max / I_e (eq. 12.12-1), δ_max by modal response spectrum "
                     "analysis (§12.9.1)",
        rows=tuple(rows),
        parameters={"sds_g": p.sds, "sd1_g": p.sd1, "tl_s": p.tl, "cd": p.cd, "r": p.r,
                    "ie": p.ie, "same_property": p.same_property,
                    "combination": p.combination},
        assumptions=(
            "linear elastic analysis of each building alone (its modes at initial stiffness)",
            ("the two-period design response spectrum of §11.4.6 (S_DS, S_D1, T_L), 5 % "
            "damping; ASCE 7-22 asks for the multi-period spectrum where it is available "
            "(give that as a table: not yet read by code-check)"),
            ("δ_max: every mode, spectrum divided by R/I_e (§12.9.1.2), combined by "
            f"{COMBINATIONS[p.combination]}; §12.9.1.4 scaling to the ELF base shear not "
            "applied"),
            "the critical location is the contact point itself (no torsion: planar model)",
            ("adjacent structures on the same property (eq. 12.12-2)" if p.same_property else
             "two properties: each building set back δ_M from the line between them"),
        ),
        clauses=dict(CLAUSES),
        periods=building_periods(model.buildings),
    )
