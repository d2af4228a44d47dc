"""Studies built on the simulator: many runs, one question each.

* :mod:`pounding.studies.gap` — the separation gap: the critical gap by simulation
  (:func:`critical_gaps` → :class:`GapStudy`) beside the code rules ABS, SRSS and DDC
  (:func:`abs_sum`, :func:`srss`, :func:`ddc`, :func:`cqc_correlation`), from simulated
  peaks or a :class:`DesignSpectrum` (from :mod:`pounding.spectra`, re-exported here). See
  ``docs/gap.md``.
* :mod:`pounding.studies.sweep` — parameter sweeps on Dask (``docs/sweep.md``).
* :mod:`pounding.studies.fragility` — fragility curves from a record suite
  (``docs/fragility.md``).
* :mod:`pounding.studies.mitigation` — retrofit options compared (``docs/mitigation.md``).

Names are imported on first use (PEP 562): importing a sub-package (say
:mod:`pounding.studies.sweep.table`, to read a sweep's table) loads neither the gap study
nor the model, SciPy or numba.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    "DesignSpectrum": "pounding.spectra",
    "fundamental_mode": "pounding.spectra",
    "spectral_displacements": "pounding.spectra",
    **{name: "pounding.studies.gap" for name in ("GapStudy", "critical_gaps", "hermite_max")},
    **{name: "pounding.studies.separation_rules" for name in (
        "RULES", "abs_sum", "code_gaps", "cqc_correlation", "ddc", "srss")},
}
"""Public name → the module that defines it."""

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


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.spectra import DesignSpectrum, fundamental_mode, spectral_displacements
    from pounding.studies.gap import GapStudy, critical_gaps, hermite_max
    from pounding.studies.separation_rules import (
        RULES,
        abs_sum,
        code_gaps,
        cqc_correlation,
        ddc,
        srss,
    )
