"""The closed forms of three more codes' design spectra, behind
:meth:`~pounding.spectra.design.DesignSpectrum.nzs1170_5`,
:meth:`~pounding.spectra.design.DesignSpectrum.nbcc2020` and
:meth:`~pounding.spectra.design.DesignSpectrum.is1893` (``docs/codes.md`` names the source
each was read from):

* NZS 1170.5:2004 §3.1: the elastic site spectrum ``C(T) = C_h(T) Z R N(T, D)`` with the
  spectral shape factor ``C_h(T)`` of the modal method for site classes A–E, ``Z R ≤ 0.7``;
* NBCC 2020 Sentence 4.1.8.4: the design spectral acceleration ``S(T)`` from the site's
  values at 0.2, 0.5, 1.0, 2.0, 5.0 and 10 s, linear between them;
* IS 1893 (Part 1):2016 §6.4: ``Sa/g`` for soil types I–III (5 % damping), to 4 s.

Units: periods in s, spectral accelerations in g.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.validation import positive

__all__ = ["IS1893_SOIL_CORNERS", "NBCC_PERIODS", "NZS_SITE_CLASSES", "is1893",
           "is1893_sa_g", "nbcc2020", "nbcc2020_sa_g", "nzs1170_5", "nzs_spectral_shape"]

FloatArray = NDArray[np.float64]

NZS_SITE_CLASSES: dict[str, tuple[float, float, float, float, float, float, float]] = {
    # class: (C_h(0), rise to the plateau over 0-0.1 s, plateau, end of plateau T_p [s],
    #         a of a (T_r/T)^0.75 to 1.5 s, T_r [s], b of b/T from 1.5 to 3 s)
    "A": (1.00, 1.35, 2.35, 0.3, 1.60, 0.50, 1.05),
    "B": (1.00, 1.35, 2.35, 0.3, 1.60, 0.50, 1.05),
    "C": (1.33, 1.60, 2.93, 0.3, 2.00, 0.50, 1.32),
    "D": (1.12, 1.88, 3.00, 0.56, 2.40, 0.75, 2.14),
    "E": (1.12, 1.88, 3.00, 1.0, 3.00, 1.00, 3.32),
}
"""NZS 1170.5:2004 Table 3.1, the spectral shape factor C_h(T) of the modal and time-history
methods, as formulas: ``C_h(0) + rise T/0.1`` below 0.1 s, the plateau to ``T_p``,
``a (T_r/T)^0.75`` to 1.5 s, ``b/T`` to 3 s, ``3 b/T²`` beyond (capped at the plateau)."""

NBCC_PERIODS: tuple[float, ...] = (0.2, 0.5, 1.0, 2.0, 5.0, 10.0)
"""The periods [s] at which NBCC 2020 gives the site's S(T) (Sentence 4.1.8.4)."""

IS1893_SOIL_CORNERS: dict[str, tuple[float, float]] = {
    "I": (0.40, 1.00), "II": (0.55, 1.36), "III": (0.67, 1.67)}
"""IS 1893 (Part 1):2016 §6.4: by soil type (rock or hard soil, medium or stiff, soft), the
end of the 2.5 plateau of Sa/g T_c [s] and the coefficient c of the ``c/T`` branch beyond
(1.00/T, 1.36/T, 1.67/T: not exactly 2.5 T_c)."""


def nzs_spectral_shape(periods: Any, site_class: str) -> FloatArray:
    """C_h(T) of NZS 1170.5 Table 3.1 (modal method) for ``site_class`` A–E."""
    c0, rise, plateau, tp, a, tr, b = NZS_SITE_CLASSES[site_class]
    t = np.asarray(periods, dtype=float)
    tt = np.where(t > 0.0, t, 1.0)  # the branches beyond 0.1 s never use it at T = 0
    out = np.where(t < 0.1, c0 + rise * t / 0.1,
                   np.where(t < tp, plateau,
                            np.where(t <= 1.5, a * (tr / tt) ** 0.75,
                                     np.where(t <= 3.0, b / tt, 3.0 * b / tt ** 2))))
    return np.asarray(np.minimum(out, plateau), dtype=float)


def nbcc2020_sa_g(periods: Any, values: Any) -> FloatArray:
    """S(T) [g]: the site's ``values`` at :data:`NBCC_PERIODS`, S(0.2) below 0.2 s, linear
    between, S(10) beyond 10 s."""
    t = np.asarray(periods, dtype=float)
    return np.asarray(np.interp(t, NBCC_PERIODS, np.asarray(values, dtype=float)), dtype=float)


def is1893_sa_g(periods: Any, soil_type: str) -> FloatArray:
    """Sa/g of IS 1893 (Part 1):2016 §6.4 (5 % damping): ``1 + 15 T`` to 0.1 s, 2.5 to
    ``T_c``, ``c/T`` to 4 s (``T_c``, ``c`` of :data:`IS1893_SOIL_CORNERS`)."""
    tc, c = IS1893_SOIL_CORNERS[soil_type]
    t = np.asarray(periods, dtype=float)
    tt = np.where(t > 0.0, t, 1.0)
    return np.asarray(np.where(t <= 0.1, 1.0 + 15.0 * t,
                               np.where(t <= tc, 2.5, c / tt)), dtype=float)


Closed = tuple[Callable[[FloatArray], FloatArray], FloatArray, str]
"""A code's spectrum as ``(formula of T → Sa [g], corner periods [s], name)``."""


def _scaled(t: Any, *, shape: Callable[[Any], FloatArray], factor: float) -> FloatArray:
    """``factor × shape(t)``: a code's spectral shape scaled to the site [g]."""
    return factor * np.asarray(shape(t), dtype=float)


def nzs1170_5(z: float, return_factor: float, site_class: str) -> Closed:
    """NZS 1170.5 §3.1: ``C(T) = C_h(T) min(Z R, 0.7)`` (N = 1), checked inputs."""
    z = positive("z", z)
    ru = positive("return_factor", return_factor)
    site = str(site_class).strip().upper()
    if site not in NZS_SITE_CLASSES:
        raise ValueError(f"site_class: must be one of A, B, C, D, E (NZS 1170.5 §3.1.3) "
                         f"(got {site_class!r})")
    formula = functools.partial(_scaled, factor=min(z * ru, 0.7),
                                shape=functools.partial(nzs_spectral_shape, site_class=site))
    return (formula, np.array([0.1, NZS_SITE_CLASSES[site][3], 1.5, 3.0]),
            f"NZS 1170.5 site class {site} (Z={z:g}, R={ru:g})")


def nbcc2020(values: Any) -> Closed:
    """NBCC 2020 S(T) from its six values (:func:`nbcc2020_sa_g`), checked inputs."""
    v = np.asarray(values, dtype=float).ravel()
    if v.size != len(NBCC_PERIODS) or not np.all(np.isfinite(v)) or np.any(v < 0.0) \
            or v[0] <= 0.0:
        raise ValueError("values: need S(T) at 0.2, 0.5, 1, 2, 5 and 10 s, 6 finite "
                         f"numbers >= 0 [g], the first > 0 (got {v.tolist()!r})")
    return (functools.partial(nbcc2020_sa_g, values=v), np.array(NBCC_PERIODS),
            "NBCC 2020 S(T) (" + ", ".join(f"{x:g}" for x in v) + " g)")


def is1893(z: float, importance: float, r: float, soil_type: str) -> Closed:
    """IS 1893 §6.4: ``A_h = (Z/2)(I/R) Sa/g`` (:func:`is1893_sa_g`), checked inputs."""
    factor = positive("z", z) / 2.0 * positive("importance", importance) / positive("r", r)
    soil = {"1": "I", "2": "II", "3": "III"}.get(str(soil_type).strip(),
                                                str(soil_type).strip().upper())
    if soil not in IS1893_SOIL_CORNERS:
        raise ValueError(f"soil_type: must be I, II or III (IS 1893 (Part 1):2016 Table 4) "
                         f"(got {soil_type!r})")
    formula = functools.partial(_scaled, factor=factor,
                                shape=functools.partial(is1893_sa_g, soil_type=soil))
    return (formula, np.array([0.1, IS1893_SOIL_CORNERS[soil][0]]),
            f"IS 1893 soil type {soil} (Z={z:g}, I={importance:g}, R={r:g})")
