"""ASCE/SEI 7-22 §12.12 structural separation, with the elastic displacements of the
model's own modal response spectrum analysis (§12.9.1) or equivalent lateral force
procedure (§12.8). See ``docs/codes.md``.

* eq. (12.12-1): ``δ_M = C_d δ_max / I_e``, the maximum inelastic response displacement at
  a critical location, ``δ_max`` the maximum elastic displacement there;
* eq. (12.12-2): adjacent structures on the same property are separated by at least
  ``δ_MT = sqrt(δ_M1² + δ_M2²)``;
* a structure adjoining a property line (not common to a public way) is set back from it
  by at least its own ``δ_M``: two neighbours on two properties, the line between them,
  need ``δ_M1 + δ_M2``.

``δ_max`` comes from either

* ``procedure="modal"``: the modal response spectrum analysis of §12.9.1, every mode of
  each building, the design response spectrum of §11.4.6 (``S_DS``, ``S_D1``, ``T_L``),
  each mode's displacement from the spectrum divided by ``R/I_e`` (§12.9.1.2), combined by
  CQC (or SRSS, §12.9.1.3); scaled by ``C_s W / V_t`` where §12.9.1.4.2 asks (``C_s`` set
  by eq. 12.8-6 and the modal base shear ``V_t`` below ``C_s W``); the force scaling of
  §12.9.1.4.1 (to 100 % of the ELF base shear) is reported, not applied (it scales forces,
  not displacements);
* ``procedure="elf"``: the equivalent lateral force procedure of §12.8
  (:mod:`pounding.studies.codes.asce7_22_elf`), ``T`` the building's first-mode period.

Units: m, s; spectral values in g.
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
from pounding.units import G

__all__ = ["CODE", "TITLE", "Asce722Parameters", "check"]

CODE = "asce7-22"
TITLE = "ASCE/SEI 7-22 §12.12"

CLAUSES: dict[str, str] = {
    "§11.4.6": "Sa = S_DS (0.4 + 0.6 T/T0) for T < T0; S_DS to T_S; S_D1/T to T_L; "
               "S_D1 T_L/T² beyond (T0 = 0.2 S_D1/S_DS, T_S = S_D1/S_DS)",
    "§12.9.1.2": "modal displacement u_n = Γ_n φ_n Sa(T_n) g (T_n/2π)² × I_e/R",
    "§12.9.1.3": "modal combination: CQC (or SRSS)",
    "§12.9.1.4.2": "drifts × C_s W / V_t where C_s is set by eq. 12.8-6 and V_t < C_s W",
    "eq. 12.8-2": "C_s = S_DS / (R/I_e)",
    "eq. 12.8-3": "C_s ≤ S_D1 / (T (R/I_e)) for T ≤ T_L",
    "eq. 12.8-4": "C_s ≤ S_D1 T_L / (T² (R/I_e)) for T > T_L",
    "eq. 12.8-5": "C_s ≥ max(0.044 S_DS I_e, 0.01) (not for drift, §12.8.6.1)",
    "eq. 12.8-6": "C_s ≥ 0.5 S1 / (R/I_e) where S1 ≥ 0.6 g",
    "§12.8.3": "F_x = C_vx V, C_vx = w_x h_x^k / Σ w_i h_i^k, k = 1 (T ≤ 0.5 s) to 2 "
               "(T ≥ 2.5 s)",
    "eq. 12.8-15": "δ_x = C_d δ_xe / I_e (§12.8.6)",
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
    procedure : {"modal", "elf"}
        §12.9.1 modal response spectrum analysis or §12.8 equivalent lateral force.
    s1 : float, optional
        Mapped S1 [g] (§11.4.2), > 0: eq. 12.8-6 applies where S1 ≥ 0.6 g; without it
        eq. 12.8-6 is not checked.
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
    procedure: str = "modal"
    s1: float | None = None
    same_property: bool = True
    combination: str = "cqc"

    def __post_init__(self) -> None:
        check_fields(self, positive=("sds", "sd1", "tl", "cd", "r", "ie"))
        if self.s1 is not None:
            check_fields(self, positive=("s1",))
        if self.procedure not in PROCEDURES:
            raise ValueError(f"procedure: must be one of {', '.join(PROCEDURES)} "
                             f"(got {self.procedure!r})")


PROCEDURES: dict[str, str] = {
    "modal": "modal response spectrum analysis (§12.9.1)",
    "elf": "equivalent lateral force procedure (§12.8)",
}
"""The analyses δ_max may come from."""

PARAMETERS = Asce722Parameters
"""The parameters of this code's check."""


def check(model: Any, p: Asce722Parameters) -> CodeCheck:
    """The separation ASCE 7-22 §12.12 asks for at every contact level of ``model``,
    beside the model's gap (:class:`~pounding.studies.codes.common.CodeCheck`)."""
    from pounding.spectra import DesignSpectrum
    from pounding.studies.codes.asce7_22_elf import elf, modal_base_shear, response_coefficient

    spectrum = DesignSpectrum.asce7(p.sds, p.sd1, p.tl)
    site: dict[str, Any] = {"sds": p.sds, "sd1": p.sd1, "tl": p.tl, "r": p.r, "ie": p.ie,
                            "s1": p.s1}

    def design_sa_g(periods: Any) -> Any:  # §12.9.1.2: the spectrum divided by R/I_e
        return spectrum.sa_g(periods) * p.ie / p.r

    notes: dict[str, Any] = {}
    scale: dict[int, float] = {}
    elfs: dict[int, Any] = {}
    for i, b in enumerate(model.buildings):
        name = b.name or f"B{i + 1}"
        if p.procedure == "elf":
            e = elfs[i] = elf(b, **site)
            notes[name] = {"T_s": e.period, "C_s": e.cs, "C_s_by": e.equation, "k": e.k,
                           "W_kN": 1e-3 * e.weight, "V_kN": 1e-3 * e.base_shear}
            continue
        period = float(b.modes().periods[0])
        v_t = modal_base_shear(b, design_sa_g, p.combination)
        cs, eq = response_coefficient(period, **site, for_drift=False)
        weight = G * float(b.modes().total_mass)
        drift = (cs * weight / v_t if eq == "eq. 12.8-6" and v_t < cs * weight else 1.0)
        scale[i] = drift
        notes[name] = {"T_s": period, "C_s": cs, "C_s_by": eq, "W_kN": 1e-3 * weight,
                       "V_kN": 1e-3 * cs * weight, "V_t_kN": 1e-3 * v_t,
                       "force_scale_12.9.1.4.1": max(1.0, cs * weight / v_t),
                       "drift_scale_12.9.1.4.2": drift}

    def delta_m(building: Any, point: Any) -> float:
        i = next(j for j, b in enumerate(model.buildings) if b is building)
        if p.procedure == "elf":
            d_max = abs(float(point.of(elfs[i].deflections)))
        else:
            d_max = scale[i] * modal_point_peak(building, point, design_sa_g,
                                                p.combination)[0]
        return p.cd * d_max / p.ie  # eq. 12.12-1

    rows = separation_rows(model, delta_m, same_site="eq. 12.12-2",
                           apart="§12.12 (property line)", same_property=p.same_property)
    if p.procedure == "elf":
        how = ("δ_max = δ_x by the ELF (§12.8.6): C_s at each building's first-mode period "
               "(§12.8.6.2), eq. 12.8-5 not considered (§12.8.6.1), F_x = C_vx V (§12.8.3), "
               "W = g × the model's masses, δ_xe = K⁻¹F")
    else:
        how = ("δ_max: every mode, spectrum divided by R/I_e (§12.9.1.2), combined by "
               f"{COMBINATIONS[p.combination]}; × C_s W/V_t where C_s is set by eq. 12.8-6 "
               "(§12.9.1.4.2); the force scaling of §12.9.1.4.1 reported, not applied to "
               "displacements; C_s at the first-mode period (the C_u T_a cap of §12.8.2 "
               "not applied)")
    return CodeCheck(
        code=CODE, title=TITLE,
        displacement=f"δ_M = C_d δ_max / I_e (eq. 12.12-1), δ_max by the "
                     f"{PROCEDURES[p.procedure]}",
        rows=rows,
        parameters={"sds_g": p.sds, "sd1_g": p.sd1, "tl_s": p.tl, "cd": p.cd, "r": p.r,
                    "ie": p.ie, "s1_g": p.s1, "procedure": p.procedure,
                    "same_property": p.same_property, "combination": p.combination,
                    "buildings": notes},
        assumptions=(
            "linear elastic analysis of each building alone (its modes at initial stiffness)",
            ("the two-period design response spectrum of §11.4.6 (S_DS, S_D1, T_L), 5 % "
             "damping; ASCE 7-22 asks for the multi-period spectrum where it is available "
             "(give that as a table: not yet read by code-check)"),
            how,
            ("eq. 12.8-6 checked with S1 = {:g} g".format(p.s1) if p.s1 is not None else
             "eq. 12.8-6 not checked (no S1 given: --s1)"),
            "the critical location is the contact point itself (no torsion: planar model)",
            ("adjacent structures on the same property (eq. 12.12-2)" if p.same_property else
             "two properties: each building set back δ_M from the line between them"),
        ),
        clauses=dict(CLAUSES),
        periods=building_periods(model.buildings),
    )
