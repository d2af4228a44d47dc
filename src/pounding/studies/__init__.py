"""Studies built on the simulator: many runs, one question each.

* :mod:`pounding.studies.gap` — the separation gap: the critical gap by simulation
  (:func:`critical_gaps` → :class:`GapStudy`) beside the code rules ABS, SRSS and DDC
  (:func:`abs_sum`, :func:`srss`, :func:`ddc`, :func:`cqc_correlation`), from simulated
  peaks or a :class:`DesignSpectrum` (from :mod:`pounding.spectra`, re-exported here). See
  ``docs/gap.md``.
"""

from pounding.spectra import DesignSpectrum, fundamental_mode, spectral_displacements
from pounding.studies.gap import (
    RULES,
    GapStudy,
    abs_sum,
    code_gaps,
    cqc_correlation,
    critical_gaps,
    ddc,
    hermite_max,
    srss,
)

__all__ = [
    "RULES",
    "DesignSpectrum",
    "GapStudy",
    "abs_sum",
    "code_gaps",
    "cqc_correlation",
    "critical_gaps",
    "ddc",
    "fundamental_mode",
    "hermite_max",
    "spectral_displacements",
    "srss",
]
