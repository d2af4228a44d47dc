"""Spectra: what a single-degree-of-freedom oscillator's peak response is, as a function of
its period.

* :mod:`pounding.spectra.design` -- code design spectra: :class:`DesignSpectrum`, a table of
  Sa or Sd against the period (from TOML or CSV), the ASCE 7-16 §11.4.6 spectrum
  (:meth:`DesignSpectrum.asce7`), the Eurocode 8 spectrum, EN 1998-1 §3.2.2.2
  (:meth:`DesignSpectrum.eurocode8`), and those of NZS 1170.5, NBCC 2020 and IS 1893
  (:mod:`pounding.spectra.code_spectra`);
* :mod:`pounding.spectra.modal` -- a building's peak floor displacements from a spectrum,
  fundamental mode only (:func:`spectral_displacements`, :func:`fundamental_mode`);
* :mod:`pounding.spectra.response` -- elastic response spectra of records (Sd, PSV, PSA,
  absolute acceleration), exact for records linear between samples
  (:func:`response_spectrum`, :class:`ResponseSpectrum`); its compiled kernel is
  :mod:`pounding.spectra._kernel`, tested against :mod:`pounding.spectra.reference`;
* :mod:`pounding.spectra.rotd` -- RotD50, RotD100 (Boore 2010) and the geometric mean of two
  horizontal components (:func:`rotd_spectrum`, :class:`RotDSpectrum`);
* :mod:`pounding.spectra.scaling` -- a suite of records scaled to a target spectrum: to
  Sa(T1) or PGA record by record, one factor for the suite by ASCE 7-22 §16.2.3 or EN 1998-1
  §3.2.3.1.2, or a least-squares fit of each log-spectrum (:func:`scale_suite`,
  :class:`SuiteScaling`); a record scaled to an Sa(T1) (:func:`scale_to_sa`) or to an
  average spectral acceleration over a period range (:func:`sa_avg`, :func:`scale_to_saavg`).

Nothing here imports numba until a spectrum is computed. See ``docs/spectra.md``.

Used by the gap study (:mod:`pounding.studies.gap`, ``docs/gap.md``).
"""

from pounding.spectra.design import DesignSpectrum
from pounding.spectra.modal import fundamental_mode, spectral_displacements
from pounding.spectra.response import ResponseSpectrum, response_spectrum
from pounding.spectra.rotd import RotDSpectrum, rotd_spectrum
from pounding.spectra.scaling import SuiteScaling, sa_avg, scale_suite, scale_to_sa, scale_to_saavg

__all__ = ["DesignSpectrum", "ResponseSpectrum", "RotDSpectrum", "SuiteScaling",
           "fundamental_mode", "response_spectrum", "rotd_spectrum", "sa_avg", "scale_suite",
           "scale_to_sa", "scale_to_saavg", "spectral_displacements"]
