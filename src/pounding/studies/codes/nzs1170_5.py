"""NZS 1170.5:2004 §7.4 separation of buildings, with the design horizontal deflections of
§7.2 from the model's own modal response spectrum analysis (§5.2, §6.3). See
``docs/codes.md`` (which says what of the standard's text was read and what was not).

* §5.2.1: the horizontal design action coefficient ``C_d(T) = C(T) S_p / k_μ``, ``k_μ``
  of §5.2.1.1 at the fundamental period ``T1`` (not less than 0.4 s): for site classes
  A–D ``k_μ = μ`` for ``T1 ≥ 0.7 s``, ``(μ − 1) T1/0.7 + 1`` below; for class E ``k_μ = μ``
  for ``T1 ≥ 1 s`` or ``μ < 1.5``, ``(μ − 1.5) T1 + 1.5`` below;
* §7.2.1.1: the design horizontal deflections are the deflections of the analysis on
  ``C_d(T)`` × ``μ / S_p``; ``S_p`` cancels: ``d = (μ / k_μ) d_e``, ``d_e`` the modal
  deflection on the elastic site spectrum ``C(T)`` (§3.1,
  :meth:`~pounding.spectra.design.DesignSpectrum.nzs1170_5`);
* §7.4: buildings on one site separated by the SRSS of their design deflections at the
  level, from a site boundary by each building's own (``d1 + d2`` between two sites).

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

__all__ = ["CODE", "TITLE", "Nzs11705Parameters", "check", "ductility_factor_k_mu"]

CODE = "nzs1170.5"
TITLE = "NZS 1170.5:2004 §7.4"

CLAUSES: dict[str, str] = {
    "§3.1": "C(T) = C_h(T) Z R N(T,D), Z R ≤ 0.7; C_h(T) of Table 3.1 (modal method)",
    "§5.2.1.1": "k_μ = μ (T1 ≥ 0.7 s; class E: T1 ≥ 1 s), else (μ − 1) T1/0.7 + 1 "
                "(class E: (μ − 1.5) T1 + 1.5), T1 ≥ 0.4 s",
    "§5.2.1": "C_d(T) = C(T) S_p / k_μ",
    "§7.2.1.1": "design deflection = deflection on C_d(T) × μ / S_p = (μ/k_μ) d_e",
    "§7.4 (same site)": "separation ≥ SRSS of the two design deflections at the level",
    "§7.4 (boundary)": "set back from the site boundary ≥ the design deflection (d1 + d2)",
}
"""The clauses the check cites, with their formulas."""


def ductility_factor_k_mu(period: float, mu: float, site_class: str) -> float:
    """k_μ of §5.2.1.1 at the fundamental period (taken ≥ 0.4 s)."""
    t = max(period, 0.4)
    if site_class == "E":
        return mu if (t >= 1.0 or mu < 1.5) else (mu - 1.5) * t + 1.5
    return mu if t >= 0.7 else (mu - 1.0) * t / 0.7 + 1.0


@dataclass(frozen=True)
class Nzs11705Parameters:
    """The inputs of the NZS 1170.5 check.

    Attributes
    ----------
    z : float
        Hazard factor Z (§3.1.4), > 0.
    ru : float
        Return period factor R_u of the ultimate limit state (Table 3.5), > 0.
    site_class : {"A", "B", "C", "D", "E"}
        Site subsoil class (§3.1.3).
    mu : float
        Structural ductility factor μ (§4.3), ≥ 1.
    same_property : bool
        One site (SRSS) or two sites with the boundary between them (the sum).
    combination : {"cqc", "srss"}
    """

    z: float
    ru: float
    site_class: str
    mu: float
    same_property: bool = True
    combination: str = "cqc"

    def __post_init__(self) -> None:
        from pounding.spectra.code_spectra import NZS_SITE_CLASSES

        check_fields(self, positive=("z", "ru"), at_least_one=("mu",),
                     choices={"site_class": (tuple(NZS_SITE_CLASSES), "NZS 1170.5 §3.1.3")})


PARAMETERS = Nzs11705Parameters
"""The parameters of this code's check."""


def check(model: Any, p: Nzs11705Parameters) -> CodeCheck:
    """The separation NZS 1170.5 §7.4 asks for at every contact level of ``model``, beside
    the model's gap (:class:`~pounding.studies.codes.common.CodeCheck`)."""
    from pounding.spectra import DesignSpectrum

    longest = max(ts[0] for ts in building_periods(model.buildings).values())
    spectrum = DesignSpectrum.nzs1170_5(p.z, p.ru, p.site_class,
                                        t_max=max(10.0, 1.01 * longest))
    factors = {}
    for i, b in enumerate(model.buildings):
        t1 = float(b.modes().periods[0])
        factors[b.name or f"B{i + 1}"] = {
            "T1_s": t1, "k_mu": ductility_factor_k_mu(t1, p.mu, p.site_class)}

    def design_deflection(building: Any, point: Any) -> float:  # §7.2.1.1
        i = next(j for j, b in enumerate(model.buildings) if b is building)
        k_mu = factors[building.name or f"B{i + 1}"]["k_mu"]
        d_e = modal_point_peak(building, point, spectrum.sa_g, p.combination)[0]
        return p.mu / k_mu * d_e

    rows = separation_rows(model, design_deflection, same_site="§7.4 (same site)",
                           apart="§7.4 (boundary)", same_property=p.same_property)
    return CodeCheck(
        code=CODE, title=TITLE,
        displacement="design horizontal deflection (μ/S_p) × the deflection on C_d(T) = "
                     "C(T) S_p/k_μ (§7.2.1.1, §5.2.1) = (μ/k_μ) × the modal deflection on "
                     "C(T)",
        rows=rows,
        parameters={"z": p.z, "ru": p.ru, "zr": min(p.z * p.ru, 0.7),
                    "site_class": p.site_class, "mu": p.mu,
                    "same_property": p.same_property, "combination": p.combination,
                    "buildings": factors},
        assumptions=(
            "linear elastic analysis of each building alone (its modes at initial stiffness)",
            ("the elastic site spectrum of §3.1 with the modal-method C_h(T) of Table 3.1, "
             "near-fault factor N(T,D) = 1 (a site 20 km or more from the faults of "
             "Table 3.6, or R ≤ 0.75), 5 % damping"),
            (f"every mode, combined by {COMBINATIONS[p.combination]}; k_μ at each "
             "building's own first-mode period for all its modes"),
            ("S_p cancels (it scales C_d and divides the deflections); the minimum C_d of "
             "§5.2.1.1 not applied (deflections); no P-delta, no drift modification k_dm"),
            ("the texts of §7.2 and §7.4 were not read (docs/codes.md): the μ/S_p scaling "
             "and the SRSS on one site are assumptions, not quotations"),
            ("one site (SRSS)" if p.same_property else
             "two sites: each building set back its design deflection from the boundary"),
        ),
        clauses=dict(CLAUSES),
        periods=building_periods(model.buildings),
    )
