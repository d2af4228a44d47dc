"""NBCC 2020 Sentence 4.1.8.14 structural separation, with the deflections of Sentence
4.1.8.13 from the model's own modal response spectrum analysis (Article 4.1.8.12). See
``docs/codes.md`` (which says what of the code's text was read and what was not).

* 4.1.8.13(2): lateral deflections from a linear elastic analysis (on the design spectrum
  ``S(T) I_E / (R_d R_o)``) multiplied by ``R_d R_o / I_E`` are the anticipated
  deflections: the product is the modal deflection on ``S(T)`` itself
  (:meth:`~pounding.spectra.design.DesignSpectrum.nbcc2020`);
* 4.1.8.14(1): adjacent structures are separated by at least the square root of the sum
  of the squares of their individual deflections;
* from a property line: each structure its own deflection (``d1 + d2`` between two
  properties).

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

__all__ = ["CODE", "TITLE", "Nbcc2020Parameters", "check"]

CODE = "nbcc2020"
TITLE = "NBCC 2020 Sentence 4.1.8.14"

CLAUSES: dict[str, str] = {
    "4.1.8.4": "S(T) from the site's values at 0.2, 0.5, 1, 2, 5, 10 s, linear between",
    "4.1.8.12": "modal response spectrum analysis on S(T) I_E / (R_d R_o)",
    "4.1.8.13(2)": "deflections of the linear analysis × R_d R_o / I_E",
    "4.1.8.14(1)": "adjacent structures: separation ≥ SRSS of their deflections",
    "4.1.8.14 (property line)": "each structure its own deflection from the line "
                                "(d1 + d2)",
}
"""The clauses the check cites, with their formulas."""


def parse_s_table(text: str) -> tuple[float, ...]:
    """``"0.8,0.7,0.4,0.2,0.06,0.02"`` → the six S(T) [g]; one line naming the field
    otherwise."""
    try:
        values = tuple(float(v) for v in str(text).split(","))
    except ValueError:
        values = ()
    if len(values) != 6 or not all(np.isfinite(v) and v >= 0.0 for v in values) \
            or values[0] <= 0.0:
        raise ValueError(f"s_table: need S(T) at 0.2, 0.5, 1, 2, 5 and 10 s, six numbers "
                         f">= 0 [g] separated by commas, the first > 0 (got {text!r})")
    return values


@dataclass(frozen=True)
class Nbcc2020Parameters:
    """The inputs of the NBCC 2020 check.

    Attributes
    ----------
    s_table : str or sequence of float
        The site's design S(T) [g] at 0.2, 0.5, 1.0, 2.0, 5.0, 10 s (for its site class),
        as six numbers or a comma-separated string.
    rd, ro : float
        Ductility- and overstrength-related force modification factors R_d, R_o
        (Table 4.1.8.9), > 0.
    ie : float
        Earthquake importance factor I_E (Table 4.1.8.5), > 0.
    same_property : bool
        SRSS of the two (4.1.8.14(1)) or two property-line setbacks (the sum).
    combination : {"cqc", "srss"}
    """

    s_table: Any
    rd: float
    ro: float
    ie: float
    same_property: bool = True
    combination: str = "cqc"

    def __post_init__(self) -> None:
        values = (parse_s_table(self.s_table) if isinstance(self.s_table, str)
                  else parse_s_table(",".join(map(str, self.s_table))))
        object.__setattr__(self, "s_table", values)
        check_fields(self, positive=("rd", "ro", "ie"))


PARAMETERS = Nbcc2020Parameters
"""The parameters of this code's check."""


def check(model: Any, p: Nbcc2020Parameters) -> CodeCheck:
    """The separation NBCC 2020 Sentence 4.1.8.14 asks for at every contact level of
    ``model``, beside the model's gap (:class:`~pounding.studies.codes.common.CodeCheck`)."""
    from pounding.spectra import DesignSpectrum

    longest = max(ts[0] for ts in building_periods(model.buildings).values())
    spectrum = DesignSpectrum.nbcc2020(p.s_table, t_max=max(10.0, 1.01 * longest))
    reduction = p.ie / (p.rd * p.ro)

    def design_sa_g(periods: Any) -> Any:  # 4.1.8.12: the spectrum × I_E / (R_d R_o)
        return spectrum.sa_g(periods) * reduction

    def deflection(building: Any, point: Any) -> float:  # 4.1.8.13(2)
        return modal_point_peak(building, point, design_sa_g, p.combination)[0] / reduction

    rows = separation_rows(model, deflection, same_site="4.1.8.14(1)",
                           apart="4.1.8.14 (property line)", same_property=p.same_property)
    return CodeCheck(
        code=CODE, title=TITLE,
        displacement="deflection × R_d R_o / I_E (4.1.8.13(2)) of the modal response "
                     "spectrum analysis on S(T) I_E/(R_d R_o) (4.1.8.12)",
        rows=rows,
        parameters={"s_table_g": list(p.s_table), "rd": p.rd, "ro": p.ro, "ie": p.ie,
                    "same_property": p.same_property, "combination": p.combination},
        assumptions=(
            "linear elastic analysis of each building alone (its modes at initial stiffness)",
            ("S(T) as given for the site class: S(0.2) below 0.2 s, linear between the six "
             "periods, S(10) beyond; 5 % damping"),
            (f"every mode, combined by {COMBINATIONS[p.combination]}; no torsion (planar "
             "model); the scaling of the dynamic base shear to the equivalent static "
             "force (4.1.8.12) not applied: it scales forces"),
            ("R_d R_o / I_E undoes the reduction: the deflections are those of the elastic "
             "spectrum S(T)"),
            ("the text read is the Ontario Building Code's copy of 4.1.8.13/4.1.8.14 "
             "(docs/codes.md), not NBCC 2020's own; the property-line rule is not in it"),
            ("adjacent structures (SRSS, 4.1.8.14(1))" if p.same_property else
             "two properties: each building its own deflection from the line between them"),
        ),
        clauses=dict(CLAUSES),
        periods=building_periods(model.buildings),
    )
