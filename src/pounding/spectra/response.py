"""Elastic response spectra of ground-motion records: :func:`response_spectrum` and
:class:`ResponseSpectrum`.

The oscillator ``ü + 2ζω u̇ + ω² u = −a_g(t)``, at rest at the record's first sample, is
solved exactly for a record that is linear between samples (Nigam & Jennings 1969, BSSA
59(2), 909–922), and its peaks are located inside the steps as well as at the samples, so
the spectrum does not depend on where the samples happen to fall (``docs/spectra.md``).
The compiled kernel is :mod:`pounding.spectra._kernel`; :mod:`pounding.spectra.reference`
is the plain NumPy/SciPy computation it is tested against.

Units: periods in s, damping ratios as fractions (0.05 = 5 %), ``sd`` in m, ``psv`` in
m/s, ``psa`` and ``sa_abs`` in m/s² (``psa_g``, ``sa_abs_g``: in g).
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.ground_motion.motion import GroundMotion
from pounding.units import G

__all__ = ["CSV_COLUMNS", "PERIOD_RANGE", "ResponseSpectrum", "check_damping", "check_periods",
           "default_periods", "parse_damping", "parse_periods", "response_spectrum", "to_csv"]

FloatArray = NDArray[np.float64]

CSV_COLUMNS = ("record", "damping", "period_s", "sd_m", "psv_m_s", "psa_g", "sa_abs_g")
"""Columns of :meth:`ResponseSpectrum.to_csv` (units in the names: s, m, m/s, g)."""


SPECTRA_COMPILE_S: float = 5.0
"""Seconds (CPU, one core) numba spends compiling the response spectra's kernel
(:func:`pounding.spectra._kernel.peaks`) the first time on a machine: El Centro's first
spectrum took 5.3–5.6 s of CPU on an empty ``NUMBA_CACHE_DIR`` against 0.44 s once cached
(the project's 2-core machine at load 2–4, 2026-11-28). Later processes load it from
numba's cache. What the
command line says before it compiles (:func:`pounding.compiled_cache.before_first_call`)."""


def default_periods() -> FloatArray:
    """100 periods [s] log-spaced from 0.02 s to 5 s (``parse_periods("0.02:5:100")``)."""
    return np.geomspace(0.02, 5.0, 100)


def _checked(values: ArrayLike, name: str, what: str, ok: Any, rule: str) -> FloatArray:
    """``values`` as a 1-D float array, or a one-line ValueError naming the first one that
    ``ok`` refuses."""
    try:
        x = np.atleast_1d(np.asarray(values, dtype=float)).ravel()
    except (TypeError, ValueError):
        raise ValueError(f"{name}: must be numbers (got {values!r})") from None
    if x.size == 0:
        raise ValueError(f"{name}: give at least one {what} (got none)")
    bad = ~(np.isfinite(x) & ok(x))
    if np.any(bad):
        raise ValueError(f"{name}: every {what} must be {rule} (got {x[bad][0]:g})")
    return x


PERIOD_RANGE: tuple[float, float] = (1e-9, 1e9)
"""Periods [s] a spectrum is computed at, both ends included. The kernel is exact to
round-off over all of it (:mod:`pounding.spectra._kernel`): at the short end the oscillator
follows the ground (PSA → PGA with damping), at the long end it stays put while the ground
moves (Sd → the peak ground displacement of the record linear between samples); beyond,
nothing changes but the risk of a period typed in the wrong unit."""


def check_periods(periods: ArrayLike, name: str = "periods") -> FloatArray:
    """Periods [s] as a 1-D float array, each finite and > 0, and within
    :data:`PERIOD_RANGE`.

    Raises
    ------
    ValueError
        ``"<name>: every period must be finite and > 0 s (got <value>)"`` for the first bad
        one, or naming the first outside :data:`PERIOD_RANGE`.
    """
    t = _checked(periods, name, "period", lambda t: t > 0.0, "finite and > 0 s")
    lo, hi = PERIOD_RANGE
    out = (t < lo) | (t > hi)
    if np.any(out):
        raise ValueError(f"{name}: every period must be from {lo:g} s to {hi:g} s (got "
                         f"{t[out][0]:g}): beyond, the oscillator follows the ground or "
                         "stays put and its response no longer changes")
    return t


def check_damping(damping: ArrayLike, name: str = "damping") -> FloatArray:
    """Damping ratios [-] as a 1-D float array, each in [0, 1) (0.05 = 5 %).

    Raises
    ------
    ValueError
        ``"<name>: every damping ratio must be in [0, 1), ... (got <value>)"`` for the first
        bad one.
    """
    return _checked(damping, name, "damping ratio", lambda z: (z >= 0.0) & (z < 1.0),
                    "in [0, 1), a fraction of critical (0.05 = 5 %)")


def _numbers(spec: str, name: str) -> list[float]:
    items = [s.strip() for s in str(spec).split(",")]
    if not spec.strip() or any(not s for s in items):
        raise ValueError(f"{name}: give comma-separated numbers (got {spec!r})")
    try:
        return [float(s) for s in items]
    except ValueError:
        raise ValueError(f"{name}: give comma-separated numbers (got {spec!r})") from None


def parse_periods(spec: str, name: str = "periods") -> FloatArray:
    """Periods from a command-line spec: a comma list (``"0.1,0.5,1"``) or
    ``"FIRST:LAST:N"``, N periods log-spaced from FIRST to LAST inclusive
    (``"0.05:4:300"``).

    Raises
    ------
    ValueError
        Naming ``name`` and the spec, for anything else or a period ≤ 0.
    """
    text = str(spec).strip()
    if ":" in text:
        parts = [p.strip() for p in text.split(":")]
        try:
            if len(parts) != 3:
                raise ValueError
            first, last, count = float(parts[0]), float(parts[1]), int(parts[2])
        except ValueError:
            raise ValueError(f"{name}: give FIRST:LAST:N (N log-spaced periods, e.g. "
                             f"0.05:4:300) or a comma list (got {spec!r})") from None
        check_periods([first, last], name)
        if count < 1 or count > 100_000:
            raise ValueError(f"{name}: N must be from 1 to 100000 (got {count})")
        if count > 1 and not last > first:
            raise ValueError(f"{name}: LAST must be larger than FIRST (got {spec!r})")
        return np.geomspace(first, last, count) if count > 1 else np.array([first])
    return check_periods(_numbers(text, name), name)


def parse_damping(spec: str, name: str = "damping") -> FloatArray:
    """Damping ratios from a comma list (``"0.05,0.02"``), each in [0, 1)."""
    return check_damping(_numbers(str(spec), name), name)


@dataclass(frozen=True, eq=False)
class ResponseSpectrum:
    """Elastic response spectra of one record, for every damping ratio and period.

    Attributes
    ----------
    periods : (n_periods,) array
        Oscillator periods T [s].
    damping : (n_damping,) array
        Damping ratios ζ [-] (0.05 = 5 %).
    sd : (n_damping, n_periods) array
        Peak relative displacement Sd = max |u| [m].
    psv : (n_damping, n_periods) array
        Pseudo-velocity PSV = ω Sd [m/s] (ω = 2π/T).
    psa : (n_damping, n_periods) array
        Pseudo-acceleration PSA = ω² Sd [m/s²].
    sa_abs : (n_damping, n_periods) array
        Peak absolute acceleration max |ü + a_g| = max |2ζω u̇ + ω² u| [m/s²].
    record : str
        Name of the record.
    pga : float
        Peak ground acceleration of the record [m/s²].
    """

    periods: FloatArray
    damping: FloatArray
    sd: FloatArray
    psv: FloatArray
    psa: FloatArray
    sa_abs: FloatArray
    record: str = "record"
    pga: float = math.nan

    @property
    def psa_g(self) -> FloatArray:
        """PSA in g (standard gravity, 9.80665 m/s²)."""
        return self.psa / G

    @property
    def sa_abs_g(self) -> FloatArray:
        """Peak absolute acceleration in g."""
        return self.sa_abs / G

    def rows(self) -> list[tuple[str, float, float, float, float, float, float]]:
        """One row per damping and period, in :data:`CSV_COLUMNS` order and units."""
        out = []
        for k, zeta in enumerate(self.damping):
            for j, t in enumerate(self.periods):
                out.append((self.record, float(zeta), float(t), float(self.sd[k, j]),
                            float(self.psv[k, j]), float(self.psa_g[k, j]),
                            float(self.sa_abs_g[k, j])))
        return out


def csv_text(columns: tuple[str, ...], rows: list[tuple[Any, ...]]) -> str:
    """CSV text: the column names (each with its unit: ``period_s``, ``psa_g``), then the
    rows (numbers to 10 digits); no comment line, so pandas, Excel and R read it with
    their defaults."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(columns)
    for row in rows:
        writer.writerow([f"{x:.10g}" if isinstance(x, float) else x for x in row])
    return buf.getvalue()


def to_csv(spectra: list[ResponseSpectrum]) -> str:
    """CSV text of several spectra, :data:`CSV_COLUMNS`: damping as a fraction of critical,
    ``period_s`` [s], ``sd_m`` [m], ``psv_m_s`` [m/s], ``psa_g``, ``sa_abs_g`` [g =
    9.80665 m/s²]."""
    return csv_text(CSV_COLUMNS, [row for spec in spectra for row in spec.rows()])


def response_spectrum(motion: GroundMotion, periods: ArrayLike | None = None,
                      damping: ArrayLike = 0.05) -> ResponseSpectrum:
    """Elastic response spectra of a record: Sd, PSV, PSA and peak absolute acceleration.

    Exact for a record that is linear between samples (Nigam & Jennings 1969), with the
    oscillator at rest at the first sample and the peaks located inside the steps
    (``docs/spectra.md``); the response is followed over the record's duration only. Exact
    at every period of :data:`PERIOD_RANGE`, far below the step (PSA → PGA) and far above
    the duration (Sd → the peak ground displacement).

    Parameters
    ----------
    motion : GroundMotion
        The record (acceleration in m/s², step ``dt``).
    periods : array_like, optional
        Periods T [s], each > 0 (default :func:`default_periods`: 0.02–5 s, 100 log-spaced).
    damping : float or array_like
        Damping ratio(s) ζ [-], each in [0, 1) (default 0.05).

    Returns
    -------
    ResponseSpectrum
        Arrays shaped (n_damping, n_periods): ``sd`` [m], ``psv`` [m/s], ``psa`` [m/s²],
        ``sa_abs`` [m/s²].

    Raises
    ------
    ValueError
        For a period ≤ 0 or outside :data:`PERIOD_RANGE`, or a damping ratio outside
        [0, 1), naming it.
    """
    t = default_periods() if periods is None else check_periods(periods)
    z = check_damping(damping)
    sd, sa = compute_peaks(np.asarray(motion.accel, dtype=float)[None, :], motion.dt, t, z,
                           np.ones((1, 1)), absolute=True)
    w = 2.0 * np.pi / t
    sd2 = sd[:, :, 0]
    return ResponseSpectrum(periods=t, damping=z, sd=sd2, psv=sd2 * w, psa=sd2 * w ** 2,
                            sa_abs=sa[:, :, 0], record=motion.name, pga=motion.pga)


def compute_peaks(accel: FloatArray, dt: float, periods: FloatArray, damping: FloatArray,
                  weights: FloatArray, absolute: bool) -> tuple[FloatArray, FloatArray]:
    """Run the compiled kernel (:func:`pounding.spectra._kernel.peaks`): peak ``|u|`` [m]
    and peak absolute acceleration [m/s²], shaped (n_damping, n_periods, n_directions)."""
    from pounding.compiled_cache import before_first_call
    from pounding.spectra._kernel import peaks

    before_first_call(peaks, "the response-spectrum kernel", SPECTRA_COMPILE_S)
    # a writable copy: a record's read-only array would be another type to numba, and
    # compile the kernel a second time
    return peaks(np.array(accel, dtype=np.float64, order="C"), float(dt),
                 np.ascontiguousarray(2.0 * np.pi / periods, dtype=np.float64),
                 np.ascontiguousarray(damping, dtype=np.float64),
                 np.ascontiguousarray(weights, dtype=np.float64), bool(absolute))
