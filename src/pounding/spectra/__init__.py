"""Spectra: what a single-degree-of-freedom oscillator's peak response is, as a function of
its period.

* :mod:`pounding.spectra.design` -- code design spectra: :class:`DesignSpectrum`, a table of
  Sa or Sd against the period, and the ASCE 7-16 §11.4.6 spectrum
  (:meth:`DesignSpectrum.asce7`);
* :mod:`pounding.spectra.modal` -- a building's peak floor displacements from a spectrum,
  fundamental mode only (:func:`spectral_displacements`, :func:`fundamental_mode`).

Used by the gap study (:mod:`pounding.studies.gap`, ``docs/gap.md``).
"""

from pounding.spectra.design import DesignSpectrum
from pounding.spectra.modal import fundamental_mode, spectral_displacements

__all__ = ["DesignSpectrum", "fundamental_mode", "spectral_displacements"]
