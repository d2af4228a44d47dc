"""Scaling a suite of records to a target (design) spectrum, as the codes require before a
response-history analysis.

Four methods, each a factor per record (amplitude scaling: the record's shape is kept):

* ``"sa"`` — each record to the target's Sa at the structure's period T1:
  ``f_i = Sa_target(T1) / Sa_i(T1)``;
* ``"pga"`` — each record to the target's peak ground acceleration (its Sa at T = 0):
  ``f_i = Sa_target(0) / PGA_i``;
* ``"code"`` — **one** factor for the whole suite, the smallest with which the suite's mean
  spectrum is nowhere below 90 % of the target over the code's period range:
  ``F = max_T 0.9 Sa_target(T) / mean_i Sa_i(T)``. ASCE 7-22 §16.2.3.2 (amplitude scaling:
  "the average of the maximum-direction spectra … does not fall below 90 % of the target
  spectrum for any period within the period range" of §16.2.3.1: from at most 0.2 T1 — lower
  where 90 % modal mass needs it — to at least 2 T1), and EN 1998-1:2004 §3.2.3.1.2(4):
  no value of the mean 5 %-damped spectrum below 90 % of the elastic spectrum between
  0.2 T1 and 2 T1, and the mean of the records' PGA not below ``a_g S`` (the target at
  T = 0), which with ``code="en1998-1"`` raises F where it binds;
* ``"lsq"`` — each record by least squares on the logarithm of its spectrum over the range:
  ``ln f_i = mean_T (ln Sa_target(T) − ln Sa_i(T))`` on log-spaced periods (the factor that
  minimises ``Σ_T (ln f_i Sa_i(T) − ln Sa_target(T))²``).

The period range is checked on a log-spaced grid (``n_periods``, the ends and T1 included).
For ``"code"`` the target's corner periods inside the range are added
(:attr:`DesignSpectrum.corners`: where the target bends, the ratio to it can peak between
two grid periods), and the grid is then refined around each of its highest ratios ``0.9 Sa_target / mean`` (every
local maximum within :data:`REFINE_WITHIN` of the highest), zooming in until a step is
below :data:`REFINE_RESOLUTION` of the period, and the periods found join the grid: the
factor holds the mean at ≥ 90 % of the target at every period of the range, not only at the
grid's (a 100-period grid alone let it dip 0.2 % below, near T_S of an ASCE 7 target).
The result reports each record's factor, the suite's mean scaled spectrum and its dispersion
(the standard deviation of ``ln Sa`` across records, ``ddof = 1``), and flags factors
outside the user's limits (default 0.25–4: scaling a record far from its own intensity
distorts its other features). A single horizontal component stands for the
"maximum-direction spectrum" of ASCE 7-22 here (a planar model shakes in one direction);
RotD100 of two components is :func:`pounding.spectra.rotd.rotd_spectrum`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.ground_motion.motion import GroundMotion
from pounding.spectra.design import DesignSpectrum
from pounding.units import G

FloatArray = NDArray[np.float64]

METHODS: tuple[str, ...] = ("code", "sa", "pga", "lsq")
"""Scaling methods (see the module's docstring)."""

CODES: tuple[str, ...] = ("asce7-22", "en1998-1")
"""Codes whose suite rule ``"code"`` applies: ASCE 7-22 §16.2.3, EN 1998-1 §3.2.3.1.2, by
the keys of :data:`pounding.studies.codes.CODES` (one spelling across pounding)."""

RENAMED_CODES: dict[str, str] = {"asce7": "asce7-22", "ec8": "en1998-1"}
"""Keys of the codes before issue 29 (refused, naming the key to use)."""

CODE_RATIO = 0.9
"""The suite's mean spectrum may not fall below this fraction of the target (both codes)."""

REFINE_WITHIN = 0.02
"""For ``"code"``: the local maxima of the ratio on the grid refined — those within this
fraction of the highest."""

REFINE_RESOLUTION = 1e-5
"""For ``"code"``: the refinement stops when its periods are closer than this fraction of
the period (the ratio changes by far less than 1e-6 over it)."""

DEFAULT_LIMITS: tuple[float, float] = (0.25, 4.0)
"""Scale factors outside this range are flagged."""


def code_period_range(t1: float, code: str = "asce7-22") -> tuple[float, float]:
    """The period range [s] a code checks a scaled suite over, for fundamental period T1:
    0.2 T1 to 2 T1 (EN 1998-1 §3.2.3.1.2(4); ASCE 7-22 §16.2.3.1's widest lower bound —
    give a lower one where more modes are needed for 90 % of the mass)."""
    _check_code(code)
    t1 = _period("period", t1)
    return 0.2 * t1, 2.0 * t1


@dataclass(frozen=True, eq=False)
class SuiteScaling:
    """Scale factors of a suite's records and what they make of the suite.

    Attributes
    ----------
    method, code : str
        The method (:data:`METHODS`) and, for ``"code"``, the code (:data:`CODES`).
    target : DesignSpectrum
        The target spectrum.
    period : float
        The structure's fundamental period T1 [s].
    damping : float
        Damping ratio of the records' spectra [-].
    period_range : (float, float)
        Lower and upper period of the range checked [s].
    periods : (n,) array
        Periods of the check [s] (log-spaced over the range, with T1).
    records : tuple of str
        Names of the records, in suite order.
    pga_g : (m,) array
        Each record's PGA, unscaled [g].
    unscaled : (m, n) array
        Each record's PSA on ``periods``, unscaled [g].
    target_g : (n,) array
        The target's Sa on ``periods`` [g].
    factors : (m,) array
        Scale factor of each record [-].
    limits : (float, float)
        Factors outside are flagged.
    """

    method: str
    code: str
    target: DesignSpectrum
    period: float
    damping: float
    period_range: tuple[float, float]
    periods: FloatArray
    records: tuple[str, ...]
    pga_g: FloatArray
    unscaled: FloatArray
    target_g: FloatArray
    factors: FloatArray
    limits: tuple[float, float] = DEFAULT_LIMITS

    @property
    def scaled(self) -> FloatArray:
        """Each record's PSA on ``periods`` after scaling [g], shape (m, n)."""
        return self.factors[:, None] * self.unscaled

    @property
    def mean(self) -> FloatArray:
        """The suite's mean scaled spectrum [g] (arithmetic mean, as both codes take)."""
        return self.scaled.mean(axis=0)

    @property
    def dispersion(self) -> FloatArray:
        """Standard deviation of ln PSA across the scaled records at each period (ddof = 1;
        0 for a single record)."""
        if len(self.records) < 2:
            return np.zeros(self.periods.size)
        return np.log(self.scaled).std(axis=0, ddof=1)

    @property
    def mean_over_target(self) -> FloatArray:
        """The mean scaled spectrum over the target at each period [-]."""
        return self.mean / self.target_g

    @property
    def flagged(self) -> NDArray[np.bool_]:
        """True for a record scaled by a factor outside :attr:`limits`."""
        lo, hi = self.limits
        return (self.factors < lo) | (self.factors > hi)

    @property
    def at_period(self) -> int:
        """Index of T1 in :attr:`periods`."""
        return int(np.argmin(np.abs(self.periods - self.period)))


def scale_suite(motions: Sequence[GroundMotion], target: DesignSpectrum, period: float, *,
                method: str = "code", code: str = "asce7-22", damping: float = 0.05,
                period_range: tuple[float, float] | None = None,
                limits: tuple[float, float] = DEFAULT_LIMITS,
                n_periods: int = 100) -> SuiteScaling:
    """Scale factors that bring a suite of records to a target spectrum.

    Parameters
    ----------
    motions : sequence of GroundMotion
        The records (a :class:`pounding.ground_motion.RecordSuite` is one), at least one.
    target : DesignSpectrum
        The target (design) spectrum; it must cover the period range (and T = 0 for
        ``"pga"`` and for ``"code"`` with ``code="en1998-1"``).
    period : float
        The structure's fundamental period T1 [s].
    method : {"code", "sa", "pga", "lsq"}
        See the module's docstring.
    code : {"asce7-22", "en1998-1"}
        The code whose suite rule ``"code"`` applies.
    damping : float
        Damping ratio of the records' spectra (the target's, usually 0.05).
    period_range : (float, float), optional
        Periods checked [s] (default :func:`code_period_range`).
    limits : (float, float)
        Scale factors outside are flagged (default 0.25–4).
    n_periods : int
        Log-spaced periods over the range (T1 and the ends included).

    Returns
    -------
    SuiteScaling

    Raises
    ------
    ValueError
        One line naming the argument: an unknown method or code, a period or limit that is
        not positive, an empty suite, a target that does not cover the periods needed.
    """
    from pounding.spectra.response import check_damping, response_spectrum

    if method not in METHODS:
        raise ValueError(f"method: one of {', '.join(METHODS)} (got {method!r})")
    _check_code(code)
    t1 = _period("period", period)
    zeta = float(check_damping(damping, "damping")[0])
    lo_lim, hi_lim = (_positive("limits", x) for x in limits)
    if lo_lim >= hi_lim:
        raise ValueError(f"limits: the lower limit must be below the upper (got {lo_lim:g}, "
                         f"{hi_lim:g})")
    lo, hi = code_period_range(t1, code) if period_range is None else (
        _period("period_range", period_range[0]), _period("period_range", period_range[1]))
    if lo >= hi:
        raise ValueError(f"period_range: the lower period must be below the upper (got "
                         f"{lo:g}, {hi:g} s)")
    if not motions:
        raise ValueError("records: the suite has no record")
    log_grid = np.unique(np.concatenate([
        np.geomspace(lo, hi, _count("n_periods", n_periods, 2)), [t1]]))
    periods = log_grid
    if method == "code":
        corners = np.asarray(target.corners, dtype=float)
        periods = np.unique(np.concatenate([log_grid, corners[(corners > lo) & (corners < hi)]]))
    needs_zero = method == "pga" or (method == "code" and code == "en1998-1")
    target_pga = _target_on(target, np.array([0.0]))[0] if needs_zero else math.nan

    def psa(at: FloatArray) -> FloatArray:
        return np.array([response_spectrum(m, at, zeta).psa_g[0] for m in motions])

    unscaled = psa(periods)
    if method == "code":
        periods, unscaled = _refined(periods, unscaled, _target_on(target, periods), lo, hi,
                                     psa, lambda at: _target_on(target, at))
    target_g = _target_on(target, periods)
    pga_g = np.array([m.pga / G for m in motions])
    inside = (periods >= lo) & (periods <= hi)
    j1 = int(np.argmin(np.abs(periods - t1)))
    if method == "sa":
        factors = target_g[j1] / unscaled[:, j1]
    elif method == "pga":
        factors = target_pga / pga_g
    elif method == "lsq":
        factors = np.exp(np.mean(np.log(target_g[inside]) - np.log(unscaled[:, inside]),
                                 axis=1))
    else:
        f = float(np.max(CODE_RATIO * target_g[inside] / unscaled[:, inside].mean(axis=0)))
        if code == "en1998-1":
            f = max(f, float(target_pga / pga_g.mean()))
        factors = np.full(len(motions), f)
    return SuiteScaling(method=method, code=code, target=target, period=t1, damping=zeta,
                        period_range=(lo, hi), periods=periods,
                        records=tuple(m.name for m in motions), pga_g=pga_g,
                        unscaled=unscaled, target_g=target_g, factors=np.asarray(factors),
                        limits=(lo_lim, hi_lim))


def _refined(periods: FloatArray, unscaled: FloatArray, target_g: FloatArray, lo: float,
             hi: float, psa: Callable[[FloatArray], FloatArray],
             target_on: Callable[[FloatArray], FloatArray]) -> tuple[FloatArray, FloatArray]:
    """The grid with the periods where the ratio ``target / mean`` peaks between its
    periods added (and the records' spectra there).

    Each local maximum of the ratio on the grid within :data:`REFINE_WITHIN` of the highest
    is bracketed by its neighbours; the bracket is sampled at 16 log-spaced periods (and any
    target corner in it), narrowed to the neighbours of the best, and sampled again, until
    its periods are within :data:`REFINE_RESOLUTION` of each other. The ratio of a
    5 %-damped spectrum varies over a few per cent of the period, so the maxima worth a
    look are near those of the grid.
    """
    inside = np.flatnonzero((periods >= lo) & (periods <= hi))
    ratio = target_g[inside] / unscaled[:, inside].mean(axis=0)
    padded = np.concatenate([[-np.inf], ratio, [-np.inf]])
    peaks = np.flatnonzero((padded[1:-1] >= padded[:-2]) & (padded[1:-1] >= padded[2:]))
    peaks = peaks[ratio[peaks] >= (1.0 - REFINE_WITHIN) * ratio.max()]
    added_t: list[FloatArray] = []
    added_s: list[FloatArray] = []
    for k in peaks[np.argsort(-ratio[peaks])][:10]:
        a = periods[inside[max(k - 1, 0)]]
        b = periods[inside[min(k + 1, inside.size - 1)]]
        best_t, best_r = periods[inside[k]], ratio[k]
        while b / a - 1.0 > REFINE_RESOLUTION:
            at = np.geomspace(a, b, 16)[1:-1]
            s = psa(at)
            added_t.append(at)
            added_s.append(s)
            r = target_on(at) / s.mean(axis=0)
            j = int(np.argmax(r))
            if r[j] > best_r:
                best_t, best_r = at[j], r[j]
            step = (b / a) ** (1.0 / 15.0)
            a, b = max(best_t / step, a), min(best_t * step, b)
    if not added_t:
        return periods, unscaled
    t_all = np.concatenate([periods, *added_t])
    s_all = np.concatenate([unscaled, *added_s], axis=1)
    t_new, first = np.unique(t_all, return_index=True)
    return t_new, s_all[:, first]


def scale_to_sa(motion: GroundMotion, sa_g: float, period: float,
                damping: float = 0.05) -> GroundMotion:
    """The record scaled so that its pseudo-acceleration at ``period`` [s] and ``damping``
    is ``sa_g`` [g]: the intensity measure Sa(T1) of incremental dynamic analysis
    (Vamvatsikos & Cornell 2002) and of the ``"sa"`` method."""
    from pounding.spectra.response import response_spectrum

    t = _period("sa_period", period)
    target = _positive("sa_g", sa_g)
    own = float(response_spectrum(motion, np.array([t]), damping).psa_g[0, 0])
    if not own > 0.0:
        raise ValueError(f"sa_g: record {motion.name!r} has no response at T = {t:g} s to "
                         "scale")
    return motion.scaled(target / own)


SAAVG_N = 10
"""Periods of the geometric mean of :func:`sa_avg` unless told otherwise (Eads et al. 2015
used ten, equally spaced, from 0.2 T1 to 3 T1)."""


def saavg_periods(period_range: Sequence[float], n: int = SAAVG_N) -> FloatArray:
    """``n`` periods equally spaced from the lower to the upper period of ``period_range``
    [s], both included: where :func:`sa_avg` takes the spectrum."""
    if len(period_range) != 2:
        raise ValueError(f"saavg_periods: two periods, the ends of the range [s] (got "
                         f"{list(period_range)!r})")
    lo, hi = (_period("saavg_periods", x) for x in period_range)
    if not lo < hi:
        raise ValueError(f"saavg_periods: the lower period must be below the upper (got "
                         f"{lo:g}, {hi:g} s)")
    return np.linspace(lo, hi, _count("saavg_n", n, 2))


def sa_avg(motion: GroundMotion, period_range: Sequence[float], damping: float = 0.05,
           n: int = SAAVG_N) -> float:
    """Average spectral acceleration [g]: the geometric mean of the record's
    pseudo-acceleration at ``n`` periods equally spaced over ``period_range`` [s],

        Sa_avg = (Π_i PSA(T_i, ζ))^(1/n)   (Bianchini, Diotallevi & Baker 2009; Eads,
        Miranda & Lignos 2015, *Earthq. Eng. Struct. Dyn.* 44(12), 2057–2073, who take
        0.2 T1 to 3 T1),

    an intensity measure that follows the spectral shape over the periods that matter to a
    structure whose period lengthens, or, for pounding, to two buildings of different
    periods. Exact spectra (:func:`pounding.spectra.response_spectrum`)."""
    from pounding.spectra.response import response_spectrum

    periods = saavg_periods(period_range, n)
    psa = response_spectrum(motion, periods, damping).psa_g[0]
    if not np.all(psa > 0.0):
        raise ValueError(f"saavg_g: record {motion.name!r} has no response at some period "
                         f"of {periods[0]:g}-{periods[-1]:g} s")
    return float(np.exp(np.mean(np.log(psa))))


def scale_to_saavg(motion: GroundMotion, saavg_g: float, period_range: Sequence[float],
                   damping: float = 0.05, n: int = SAAVG_N) -> GroundMotion:
    """The record scaled so that its :func:`sa_avg` over ``period_range`` is ``saavg_g`` [g]
    (a geometric mean of spectra scales with the record: one factor)."""
    target = _positive("saavg_g", saavg_g)
    return motion.scaled(target / sa_avg(motion, period_range, damping, n))


def _target_on(target: DesignSpectrum, periods: FloatArray) -> FloatArray:
    """The target's Sa [g] at ``periods``, or one line saying which periods it lacks."""
    lo, hi = float(target.periods[0]), float(target.periods[-1])
    if periods.min() < lo - 1e-12 or periods.max() > hi + 1e-12:
        raise ValueError(f"target: spectrum {target.name!r} covers {lo:g}–{hi:g} s, not the "
                         f"periods {periods.min():g}–{periods.max():g} s the scaling needs")
    sa = np.atleast_1d(np.asarray(target.sa_g(periods), dtype=float))
    if np.any(~(sa > 0.0)):
        raise ValueError(f"target: spectrum {target.name!r} is not positive at every period "
                         f"in {periods.min():g}–{periods.max():g} s")
    return sa


def _positive(name: str, value: float) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: must be a positive number (got {value!r})") from None
    if not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"{name}: must be a positive number (got {value!r})")
    return x


def _period(name: str, value: float) -> float:
    """A period [s]: positive and within :data:`pounding.spectra.response.PERIOD_RANGE`."""
    from pounding.spectra.response import check_periods

    return float(check_periods([_positive(name, value)], name)[0])


_MAX_PERIODS = 100_000
"""Most periods a scaling computes the spectrum at (``n_periods``, ``saavg_n``)."""


def _count(name: str, n: int, low: int) -> int:
    """A number of periods: an integer from ``low`` to :data:`_MAX_PERIODS`."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not \
            low <= int(n) <= _MAX_PERIODS:
        raise ValueError(f"{name}: an integer from {low} to {_MAX_PERIODS} (got {n!r})")
    return int(n)


def _check_code(code: str) -> None:
    if code in RENAMED_CODES:
        raise ValueError(f"code: {code!r} is now spelled {RENAMED_CODES[code]!r}, as "
                         "`pounding code-check` spells it (one of "
                         f"{', '.join(CODES)})")
    if code not in CODES:
        raise ValueError(f"code: pounding scales a suite by the rule of asce7-22 (ASCE 7-22 "
                         f"§16.2.3) or en1998-1 (EN 1998-1 §3.2.3.1.2) (got {code!r})")
