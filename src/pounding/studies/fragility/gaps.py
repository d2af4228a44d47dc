"""The gap each record needs at each level, by simulation without contact
(:func:`pounding.studies.gap.critical_gaps`): what the gap analysis of a study
(:mod:`.analysis`) starts from. :mod:`.runner` computes it before the sweep.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.studies.fragility.cases import StudyCases

__all__ = ["NeededGaps", "needed_gaps"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class NeededGaps:
    """The gap each record needs at each level, and the code gaps at the gap level.

    Attributes
    ----------
    levels : (n_levels,)
        Intensities [g] (the study's levels).
    needed : (n_records, n_levels)
        Smallest uniform gap [m] with which the record at that level causes no impact: the
        largest critical gap over every contact level of the model.
    at : float
        The intensity of the gap analysis [g], and
    needed_at : (n_records,)
        each record's needed gap there [m].
    code : dict
        ``ABS``, ``SRSS``, ``DDC`` [m] at ``at``: the rules from the mean peak
        displacements of the records (:meth:`~pounding.studies.gap.GapStudy.rules_from_peaks`),
        largest over the contact levels.
    scaled : bool
        True where the needed gaps at the levels were scaled from those at ``at`` (linear
        buildings: the uncoupled response is proportional to the record), False where
        every level was simulated (yielding storeys).
    """

    levels: FloatArray
    needed: FloatArray
    at: float
    needed_at: FloatArray
    code: dict[str, float]
    scaled: bool


def needed_gaps(cases: StudyCases) -> NeededGaps:
    """The gaps the records need, by simulation without contact
    (:func:`pounding.studies.gap.critical_gaps`), each record scaled exactly as its runs.

    For linear buildings one uncoupled run per building and record at ``at`` gives every
    level: the response to ``λ a_g(t)`` is ``λ`` times that to ``a_g(t)``, so the needed
    gap is proportional to the scale factor, which is proportional to the level. Buildings
    with yielding storeys are simulated at every level.
    """
    from pounding.studies.gap import critical_gaps

    at = float(cases.config.gap_at())
    levels = np.asarray(cases.levels, dtype=float)

    def study_at(level: float) -> Any:
        built = [cases.build(r, level) for r in range(len(cases.records))]
        model, _, solver = built[0]
        return critical_gaps(model, [b.motion for b in built], dt=solver["dt"],
                             duration=solver["duration"])

    gs = study_at(at)
    needed_at = gs.critical.max(axis=1)
    rules = gs.rules_from_peaks("mean")
    code = {k: float(np.max(v)) for k, v in rules.items()}
    inelastic = gs.model.is_inelastic
    if not inelastic:
        needed = needed_at[:, None] * (levels[None, :] / at)
    else:
        needed = np.column_stack([study_at(float(x)).critical.max(axis=1) for x in levels])
    return NeededGaps(levels, needed, at, needed_at, code, scaled=not inelastic)
