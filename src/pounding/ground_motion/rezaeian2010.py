"""The predictive equations of Rezaeian & Der Kiureghian (2010) for the six parameters of
their stochastic ground-motion model (:mod:`pounding.ground_motion.stochastic`), from the
moment magnitude ``M``, the rupture distance ``R_rup`` [km], ``Vs30`` [m/s] and the
mechanism ``F`` (0 strike-slip, 1 reverse), and suites of motions simulated from them.

Rezaeian, S. & Der Kiureghian, A. (2010), "Simulation of synthetic ground motions for
specified earthquake and site characteristics", *Earthquake Engng Struct. Dyn.*
39:1155–1180, doi:10.1002/eqe.997. Each parameter ``θ_i`` is mapped to the standard normal
space, ``ν_i = Φ⁻¹(F_i(θ_i))`` with ``F_i`` its fitted marginal distribution, and
``ν_i = μ_i(F, M, R, V) + η_i + ε_i`` (random-effects regression: ``η`` between events,
``ε`` within an event), each error normal with its own correlation matrix across the six.

Source of the numbers: the paper itself could not be read here. The coefficients, the
marginal distributions, the standard deviations and the three correlation matrices are
those of the SCEC Broadband Platform's implementation of these equations
(``SCECcode/bbp``, ``bbp/comps/rzz2015_gmpe.py``, "GMPEs for the six parameters in
Rezaeian (2010)"), which states them with ``M``, ``R`` and ``V`` in their own units:
``μ_1 = β0 + β1 M/7 + β2 F + β3 ln(R/25) + β4 ln(V/750)`` for the Arias intensity and
``μ_i = β0 + β1 M + β2 F + β3 R + β4 V`` for the other five (the paper's ``M/7``, ``R/25``,
``V/750`` terms multiplied out, to four decimals). See ``docs/records.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.stochastic import (
    ModelParameters,
    modulating_shape,
    simulate,
)
from pounding.units import G
from pounding.validation import in_range

__all__ = ["MECHANISMS", "Scenario", "median_parameters", "sample_parameters",
           "stochastic_suite"]

MECHANISMS = {"strike-slip": 0, "reverse": 1}
"""The mechanisms of the equations and their ``F``."""

BETA = np.array([
    [-2.2962, 2.9440, -0.0707, -1.3564, -0.2654],   # ν1: Arias intensity (M/7, ln R/25, ln V/750)
    [-6.1946, 0.9703, -0.7034, 0.0087, -0.0007],    # ν2: D5-95
    [-5.0105, 0.6625, -0.3450, 0.0139, -0.0002],    # ν3: t_mid
    [2.2525, -0.2586, -0.0808, -0.0084, 0.0000],    # ν4: ω_mid / 2π
    [-2.4886, 0.3440, 0.0441, 0.0026, -0.0001],     # ν5: ω' / 2π
    [-0.2583, 0.1293, -0.4772, -0.0115, 0.0004],    # ν6: ζ_f
])
"""Regression coefficients ``[β0, β_M, β_F, β_R, β_V]`` of each ``ν_i`` (module docstring)."""

SIGMA_WITHIN = np.array([0.5937, 0.5688, 0.4145, 0.7228, 0.9529, 0.7601])
"""Standard deviations of the within-event errors ``ε_i``."""
TAU_BETWEEN = np.array([0.2738, 0.4574, 0.5114, 0.6918, 0.1286, 0.6815])
"""Standard deviations of the between-event errors ``η_i``."""

RHO_BETWEEN = np.array([
    [1.0000, 0.0323, 0.3603, -0.2583, 0.4515, 0.4272],
    [0.0323, 1.0000, 0.6982, -0.1200, -0.2291, -0.2902],
    [0.3603, 0.6982, 1.0000, -0.2973, -0.2542, -0.1387],
    [-0.2583, -0.1200, -0.2973, 1.0000, 0.0973, 0.3336],
    [0.4515, -0.2291, -0.2542, 0.0973, 1.0000, 0.1105],
    [0.4272, -0.2902, -0.1387, 0.3336, 0.1105, 1.0000]])
"""Correlation of the between-event errors ``η``."""
RHO_WITHIN = np.array([
    [1.0000, -0.4682, -0.1486, -0.0994, 0.0951, -0.1673],
    [-0.4682, 1.0000, 0.6420, -0.0411, -0.1323, -0.0249],
    [-0.1486, 0.6420, 1.0000, -0.0188, -0.2400, 0.0649],
    [-0.0994, -0.0411, -0.0188, 1.0000, -0.3118, 0.1555],
    [0.0951, -0.1323, -0.2400, -0.3118, 1.0000, -0.0522],
    [-0.1673, -0.0249, 0.0649, 0.1555, -0.0522, 1.0000]])
"""Correlation of the within-event errors ``ε``."""
RHO_TOTAL = np.array([
    [1.0000, -0.3555, 0.0066, -0.1545, 0.1341, -0.0078],
    [-0.3555, 1.0000, 0.6729, -0.1303, -0.1576, -0.1958],
    [0.0066, 0.6729, 1.0000, -0.2761, -0.1977, -0.2188],
    [-0.1545, -0.1303, -0.2761, 1.0000, -0.2034, 0.2814],
    [0.1341, -0.1576, -0.1977, -0.2034, 1.0000, -0.0137],
    [-0.0078, -0.1958, -0.2188, 0.2814, -0.0137, 1.0000]])
"""Correlation of the total errors ``η + ε`` as stated beside the other two (the samples
use the sum of the two covariances; ``docs/records.md`` compares them)."""

SLOPE_CDF = (17.095, 6.7729, 4.8512, -2.0, 0.5)
"""``a, b, c, x_min, x_max`` of the two-sided exponential distribution of ``ω'/2π``
[Hz/s]: density ``c e^{b x}`` on ``[x_min, 0]`` and ``c e^{−a x}`` on ``[0, x_max]``."""


@dataclass(frozen=True)
class Scenario:
    """An earthquake and a site: ``magnitude`` (moment), ``distance`` R_rup [km], ``vs30``
    [m/s] and ``mechanism`` (``"strike-slip"`` or ``"reverse"``)."""

    magnitude: float
    distance: float
    vs30: float
    mechanism: str = "strike-slip"

    def __post_init__(self) -> None:
        in_range("magnitude", self.magnitude, 4.0, 9.0)
        in_range("distance [km]", self.distance, 0.0, 500.0, low_open=True)
        in_range("vs30 [m/s]", self.vs30, 100.0, 3000.0)
        if self.mechanism not in MECHANISMS:
            raise ValueError(f"mechanism must be one of {', '.join(MECHANISMS)} (got "
                             f"{self.mechanism!r})")

    def mean_normal(self) -> np.ndarray:
        """``μ_i``, the means of the six ``ν_i``."""
        f = MECHANISMS[self.mechanism]
        m, r, v = self.magnitude, self.distance, self.vs30
        x1 = np.array([1.0, m / 7.0, f, math.log(r / 25.0), math.log(v / 750.0)])
        x = np.array([1.0, m, f, r, v])
        return np.concatenate([[BETA[0] @ x1], BETA[1:] @ x])


def covariance() -> np.ndarray:
    """Covariance of ``η + ε``: ``D_τ R_η D_τ + D_σ R_ε D_σ``."""
    between = RHO_BETWEEN * np.outer(TAU_BETWEEN, TAU_BETWEEN)
    within = RHO_WITHIN * np.outer(SIGMA_WITHIN, SIGMA_WITHIN)
    return between + within


def _slope_ppf(p: np.ndarray) -> np.ndarray:
    a, b, c, lo, hi = SLOPE_CDF
    p0 = c / b * (1.0 - math.exp(b * lo))  # the probability below 0
    neg = np.log(np.minimum(p, p0) * b / c + math.exp(b * lo)) / b
    pos = -np.log(1.0 - (np.maximum(p, p0) - p0) * a / c) / a
    return np.clip(np.where(p < p0, neg, pos), lo, hi)


def to_parameters(nu: np.ndarray) -> list[ModelParameters]:
    """The model parameters of points ``nu`` (shape ``(n, 6)``) of the standard normal space,
    through the inverse marginal distributions of the paper (Table of the marginals as the
    BBP states them): ``ln I_a`` [s·g] normal (−4.8255, 1.4318); ``D_5-95`` beta (1.1314,
    2.4474) on [5, 45] s; ``t_mid`` beta (1.5792, 3.6405) on [0.5, 40] s; ``ω_mid/2π``
    gamma (4.0982, scale 1.4330) Hz; ``ω'/2π`` two-sided exponential on [−2, 0.5] Hz/s;
    ``ζ_f`` beta (1.4250, 5.7208) on [0.02, 1]."""
    from scipy import stats

    p = stats.norm.cdf(np.atleast_2d(nu))
    arias_sg = np.exp(stats.norm.ppf(p[:, 0], -4.8255, 1.4318))
    d595 = 5.0 + 40.0 * stats.beta.ppf(p[:, 1], 1.1314, 2.4474)
    t_mid = 0.5 + 39.5 * stats.beta.ppf(p[:, 2], 1.5792, 3.6405)
    f_mid = stats.gamma.ppf(p[:, 3], 4.0982, scale=1.4330)
    f_slope = _slope_ppf(p[:, 4])
    zeta = 0.02 + 0.98 * stats.beta.ppf(p[:, 5], 1.4250, 5.7208)
    return [ModelParameters(arias=float(a * G), d595=float(d), t_mid=float(t),
                            f_mid=float(f), f_slope=float(s), zeta_f=float(min(z, 0.99)))
            for a, d, t, f, s, z in zip(arias_sg, d595, t_mid, f_mid, f_slope, zeta)]


def median_parameters(scenario: Scenario) -> ModelParameters:
    """The parameters at ``ν = μ`` (each the median of its predictive distribution)."""
    return to_parameters(scenario.mean_normal()[None, :])[0]


def sample_parameters(scenario: Scenario, count: int,
                      rng: np.random.Generator) -> list[ModelParameters]:
    """``count`` correlated sets of parameters: ``ν ~ N(μ, Σ)`` (:func:`covariance`),
    mapped to the parameters (:func:`to_parameters`)."""
    n = int(in_range("count", count, 1, 100_000))
    chol = np.linalg.cholesky(covariance())
    nu = scenario.mean_normal() + rng.standard_normal((n, 6)) @ chol.T
    return to_parameters(nu)


def record_duration(params: ModelParameters) -> float:
    """Time [s] by which 99.9 % of the Arias intensity has arrived, plus 5 s for the
    filter's ring-down."""
    from scipy.special import gammaincinv

    k, rate = modulating_shape(params.d595, params.t_mid)
    return float(gammaincinv(k, 0.999) / rate + 5.0)


def stochastic_motion(scenario: Scenario, seed: int, index: int, *, dt: float = 0.01,
                      duration: float | None = None) -> GroundMotion:
    """Record ``index`` (0-based) of the suite of ``scenario`` and ``seed``: its own stream
    ``numpy.random.default_rng([seed, index])`` draws the six parameters, then the pulses,
    so a record is the same whatever the size of the suite and on any machine."""
    s = int(in_range("seed", seed, 0, 2**63 - 1))
    i = int(in_range("index", index, 0, 10**9))
    rng = np.random.default_rng([s, i])
    params = sample_parameters(scenario, 1, rng)[0]
    end = record_duration(params) if duration is None else duration
    end = max(end, params.t_mid)
    f = scenario
    name = (f"M{f.magnitude:g} R{f.distance:g}km Vs{f.vs30:g} {f.mechanism} "
            f"seed {s} #{i + 1}")
    return simulate(params, end, dt, rng, name=name)


def stochastic_suite(scenario: Scenario, count: int, seed: int, *, dt: float = 0.01,
                     duration: float | None = None) -> list[GroundMotion]:
    """``count`` records of ``scenario``: :func:`stochastic_motion` for ``index = 0 …
    count − 1``."""
    n = int(in_range("count", count, 1, 100_000))
    return [stochastic_motion(scenario, seed, i, dt=dt, duration=duration) for i in range(n)]
