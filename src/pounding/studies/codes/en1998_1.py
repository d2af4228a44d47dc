"""EN 1998-1:2004 §4.4.2.7 seismic joints, with the displacements of §4.3.4 from the
model's own modal response spectrum analysis (§4.3.3.3). See ``docs/codes.md``.

* eq. (4.23), §4.3.4(1): ``d_s = q_d d_e``, ``d_e`` the displacement from a linear analysis
  on the design spectrum of §3.2.2.5, ``q_d`` the displacement behaviour factor (``= q``
  unless otherwise specified);
* §4.4.2.7(2)b: buildings on the same property are separated by at least the SRSS of
  their ``d_s`` at the corresponding level; §4.4.2.7(2)a: on different properties, each is
  at least its own ``d_s`` from the property line (``d_s1 + d_s2`` between them);
* §4.4.2.7(3): where the floor elevations of the two are the same, that distance may be
  reduced by a factor 0.7 (applied here at each contact of floor to floor).

The design spectrum (§3.2.2.5, eqs. 3.13–3.16, recommended β = 0.2):
``a_g S [2/3 + T/T_B (2.5/q − 2/3)]`` to T_B, ``a_g S 2.5/q`` to T_C,
``max(a_g S 2.5/q T_C/T, β a_g)`` to T_D, ``max(a_g S 2.5/q T_C T_D/T², β a_g)`` beyond,
with ``S, T_B, T_C, T_D`` of Tables 3.2/3.3 (:data:`pounding.spectra.design.EC8_GROUND_TYPES`).

Units: m, s; spectral values in g.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from pounding.studies.codes.common import (
    COMBINATIONS,
    CodeCheck,
    building_periods,
    check_fields,
    modal_point_peak,
    separation_rows,
)

__all__ = ["CODE", "TITLE", "En19981Parameters", "check", "design_spectrum_sa_g"]

CODE = "en1998-1"
TITLE = "EN 1998-1:2004 §4.4.2.7"

CLAUSES: dict[str, str] = {
    "§3.2.2.5": "design spectrum S_d(T): a_g S [2/3 + T/T_B (2.5/q − 2/3)] (T ≤ T_B); "
                "a_g S 2.5/q (≤ T_C); max(a_g S 2.5/q T_C/T, β a_g) (≤ T_D); "
                "max(a_g S 2.5/q T_C T_D/T², β a_g) (T > T_D)",
    "§4.3.3.3.2": "modal combination: SRSS of independent modes, else CQC",
    "eq. 4.23": "d_s = q_d d_e (§4.3.4(1)), q_d = q unless otherwise specified",
    "§4.4.2.7(2)b": "same property: distance ≥ SRSS of d_s of the two at the level",
    "§4.4.2.7(2)a": "property line: distance to it ≥ d_s of the building (d_s1 + d_s2)",
    "§4.4.2.7(3)": "floor elevations the same: the distance may be reduced by 0.7",
}
"""The clauses the check cites, with their formulas."""

FLOOR_LEVEL_FACTOR = 0.7
"""§4.4.2.7(3)."""


def design_spectrum_sa_g(periods: Any, *, ag: float, ground_type: str, spectrum_type: int,
                         q: float, beta: float = 0.2) -> Any:
    """EN 1998-1 §3.2.2.5 design spectrum S_d(T) [g] (eqs. 3.13–3.16), ``ag = γ_I a_gR`` [g]."""
    from pounding.spectra.design import EC8_GROUND_TYPES

    soil, tb, tc, td = EC8_GROUND_TYPES[spectrum_type][ground_type]
    t = np.asarray(periods, dtype=float)
    tt = np.where(t > 0.0, t, 1.0)
    plateau = ag * soil * 2.5 / q
    floor = beta * ag
    return np.where(t <= tb, ag * soil * (2.0 / 3.0 + t / tb * (2.5 / q - 2.0 / 3.0)),
                    np.where(t <= tc, plateau,
                             np.where(t <= td, np.maximum(plateau * tc / tt, floor),
                                      np.maximum(plateau * tc * td / tt ** 2, floor))))


@dataclass(frozen=True)
class En19981Parameters:
    """The inputs of the EN 1998-1 check.

    Attributes
    ----------
    agr : float
        Reference peak ground acceleration on ground A, a_gR [g], > 0.
    ground_type : {"A", "B", "C", "D", "E"}
    spectrum_type : {1, 2}
    q : float
        Behaviour factor q (§3.2.2.5), ≥ 1.
    importance : float
        Importance factor γ_I (§4.2.5), > 0; a_g = γ_I a_gR.
    qd : float, optional
        Displacement behaviour factor q_d (§4.3.4); default q.
    beta : float
        Lower bound factor β of §3.2.2.5(4) (recommended 0.2), ≥ 0.
    same_property : bool
        §4.4.2.7(2)b (true) or (2)a (false).
    combination : {"cqc", "srss"}
    """

    agr: float
    ground_type: str
    spectrum_type: int
    q: float
    importance: float = 1.0
    qd: float | None = None
    beta: float = 0.2
    same_property: bool = True
    combination: str = "cqc"

    def __post_init__(self) -> None:
        from pounding.spectra.design import EC8_GROUND_TYPES

        check_fields(self, positive=("agr", "importance"), at_least_one=("q", "qd"),
                     choices={"spectrum_type": ((1, 2), "EN 1998-1 §3.2.2.2(2)")})
        if not (self.beta >= 0.0 and np.isfinite(self.beta)):
            raise ValueError(f"beta: must be finite and >= 0 (got {self.beta!r})")
        check_fields(self, choices={"ground_type": (tuple(EC8_GROUND_TYPES[self.spectrum_type]),
                                                    "EN 1998-1 Table 3.1")})

    @property
    def displacement_factor(self) -> float:
        """q_d (q where not given)."""
        return self.q if self.qd is None else self.qd


PARAMETERS = En19981Parameters
"""The parameters of this code's check."""


def check(model: Any, p: En19981Parameters) -> CodeCheck:
    """The seismic joint EN 1998-1 §4.4.2.7 asks for at every contact level of ``model``,
    beside the model's gap (:class:`~pounding.studies.codes.common.CodeCheck`)."""
    ag = p.importance * p.agr

    def sa_g(periods: Any) -> Any:
        return design_spectrum_sa_g(periods, ag=ag, ground_type=p.ground_type,
                                    spectrum_type=p.spectrum_type, q=p.q, beta=p.beta)

    qd = p.displacement_factor

    def d_s(building: Any, point: Any) -> float:  # eq. 4.23
        return qd * modal_point_peak(building, point, sa_g, p.combination)[0]

    rows = separation_rows(model, d_s, same_site="§4.4.2.7(2)b", apart="§4.4.2.7(2)a",
                           same_property=p.same_property,
                           floor_factor=(FLOOR_LEVEL_FACTOR, "§4.4.2.7(3)"))
    return CodeCheck(
        code=CODE, title=TITLE,
        displacement="d_s = q_d d_e (eq. 4.23), d_e by modal response spectrum analysis "
                     "(§4.3.3.3) on the design spectrum (§3.2.2.5)",
        rows=rows,
        parameters={"agr_g": p.agr, "importance": p.importance, "ag_g": ag,
                    "ground_type": p.ground_type, "spectrum_type": p.spectrum_type,
                    "q": p.q, "qd": qd, "beta": p.beta, "same_property": p.same_property,
                    "combination": p.combination},
        assumptions=(
            "linear elastic analysis of each building alone (its modes at initial stiffness)",
            ("the design spectrum of §3.2.2.5 with the recommended S, T_B, T_C, T_D of "
            "Tables 3.2/3.3 (no National Annex values), periods beyond 4 s by eq. 3.16"),
            f"d_e: every mode, combined by {COMBINATIONS[p.combination]}",
            ("§4.3.4(2) (d_s need not exceed the elastic spectrum's value) not used: "
            "conservative"),
            ("the 0.7 of §4.4.2.7(3) at every floor-to-floor contact; none where a floor "
            "meets a column"),
            ("same property (§4.4.2.7(2)b)" if p.same_property else
             "two properties: each building d_s from the line between them (§4.4.2.7(2)a)"),
        ),
        clauses=dict(CLAUSES),
        periods=building_periods(model.buildings),
    )
