"""Make a contact law do what it is meant to: exact calibration to a target restitution, and
least-squares fitting to a measured impact force history.

* :func:`calibrate` finds the damping parameter of any law that reproduces a target ``e``:
  by inverting a closed form of ``e`` to round-off where one exists (Kelvin–Voigt with and
  without tension, modified Kelvin–Voigt, Hunt–Crossley), by root finding on the
  one-dimensional approach for Jankowski's law, and otherwise by a bracketing root-finder
  on the simulated collision (:func:`pounding.contact.collision.simulate_collision`).
* :func:`fit_impact` fits the stiffness and damping of a chosen law to a measured
  contact-force history of one collision.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq, least_squares

from pounding.contact.base import ContactLaw, m_effective
from pounding.contact.bilinear import BilinearImpact
from pounding.contact.collision import simulate_collision
from pounding.contact.hertz import Hertz, HuntCrossley, NonlinearViscoelastic
from pounding.contact.linear import KelvinVoigt, LinearSpring, ModifiedKelvinVoigt
from pounding.contact.exact_restitution import (  # noqa: F401  (the exact e's, re-exported)
    chi_hunt_crossley_exact,
    restitution_hunt_crossley,
    restitution_kelvin_voigt_clipped,
    restitution_modified_kelvin_voigt,
    restitution_nonlinear_viscoelastic,
    zeta_kelvin_voigt_clipped,
    zeta_modified_kelvin_voigt_exact,
    zeta_nonlinear_viscoelastic_exact,
)
from pounding.contact.restitution import zeta_anagnostopoulos
from pounding.validation import choice, positive, restitution


# --------------------------------------------------------------------------- closed forms
def hertz_delta_max(k_h: float, m_eff: float, v0: float, n: float = 1.5) -> float:
    """Maximum penetration [m] of an elastic Hertz impact: ``((n+1) m_eff v0² / (2 k_h))^(1/(n+1))``.

    For ``n = 1.5`` this is ``(5 m_eff v0² / (4 k_h))^(2/5)`` (energy balance).
    """
    return ((n + 1.0) * positive("m_eff", m_eff) * positive("v0", v0) ** 2
            / (2.0 * positive("k_h", k_h))) ** (1.0 / (n + 1.0))


def restitution_of(law: ContactLaw, m1: float, m2: float) -> float | None:
    """The ``e`` that ``law`` achieves in an impact of two free bodies of masses ``m1``,
    ``m2`` [kg] (any impact velocity), from its exact ``e`` of the damping parameter
    (:mod:`pounding.contact.exact_restitution`); 1 for the elastic laws; None for the
    bilinear element, whose ``e`` depends on the impact velocity. 0 where the bodies never
    separate (Kelvin–Voigt with tension and ζ ≥ 1)."""
    if isinstance(law, (LinearSpring, Hertz)):
        return 1.0
    if isinstance(law, HuntCrossley):
        return float(restitution_hunt_crossley(law.chi))
    if isinstance(law, NonlinearViscoelastic):
        return restitution_nonlinear_viscoelastic(law.zeta)
    if isinstance(law, (KelvinVoigt, ModifiedKelvinVoigt)):
        zeta = law.c / (2.0 * np.sqrt(law.k * m_effective(m1, m2)))
        if isinstance(law, ModifiedKelvinVoigt):
            return float(restitution_modified_kelvin_voigt(zeta))
        if not law.tension:
            return float(restitution_kelvin_voigt_clipped(zeta))
        # with tension: the damped half period (Anagnostopoulos 1988); overdamped never
        # returns to δ = 0
        return float(np.exp(-np.pi * zeta / np.sqrt(1.0 - zeta**2))) if zeta < 1.0 else 0.0
    return None


# --------------------------------------------------------------------------- calibration
@dataclass(frozen=True)
class Calibration:
    """Outcome of :func:`calibrate`.

    Attributes
    ----------
    law : ContactLaw
        The law with its damping parameter set.
    parameter : str
        Name of the calibrated field.
    value : float
        Its calibrated value.
    target_e, achieved_e : float
        Requested and simulated coefficient of restitution.
    method : str
        ``"closed form"``, ``"approach integrated alone"`` (Jankowski's law) or ``"root finding"``.
    """

    law: ContactLaw
    parameter: str
    value: float
    target_e: float
    achieved_e: float
    method: str


def _root(fun: Callable[[float], float], target: float, lo: float, hi: float, xtol: float) -> float:
    """Find x with fun(x) = target for fun decreasing; expand ``hi`` until it brackets."""
    f_lo = fun(lo) - target
    if f_lo < 0.0:
        raise ValueError(f"target e={target:g} is above what the law achieves with no damping "
                         f"({fun(lo):.6f})")
    for _ in range(80):
        if fun(hi) - target < 0.0:
            break
        lo, hi = hi, hi * 2.0
    else:
        raise ValueError(f"target e={target:g} is below what the law can achieve")
    return brentq(lambda x: fun(x) - target, lo, hi, xtol=xtol, rtol=1e-14, maxiter=200)


def calibrate(law: ContactLaw, target_e: float, m1: float, m2: float, v0: float = 1.0,
              tol: float = 1e-6) -> Calibration:
    """Set the damping parameter of ``law`` so an impact achieves exactly ``target_e``.

    Parameters
    ----------
    law : ContactLaw
        A damped law (its stiffness is kept; its damping value is only a starting point).
    target_e : float
        Target coefficient of restitution, 0 < e < 1.
    m1, m2 : float
        Masses of the colliding bodies [kg].
    v0 : float
        Impact velocity [m/s]; irrelevant for laws whose e is velocity-independent
        (all but the bilinear element), kept for generality.
    tol : float
        Absolute tolerance on the achieved e.

    Returns
    -------
    Calibration

    Notes
    -----
    Closed forms, inverted to round-off: Kelvin–Voigt with tension (ζ of Anagnostopoulos),
    clipped Kelvin–Voigt (:func:`~pounding.contact.restitution.
    restitution_kelvin_voigt_clipped`, Schwager & Pöschel 2007), modified Kelvin–Voigt
    (:func:`restitution_modified_kelvin_voigt`), Hunt–Crossley
    (:func:`restitution_hunt_crossley`). Jankowski's law (and the seed's eq 39 law, the
    same law): its e depends on ζ alone, through the approach
    (:func:`restitution_nonlinear_viscoelastic`), so Brent's method runs on that
    one-dimensional integration (about 6 ms each). Others: Brent's method on the simulated
    collision, whose e decreases monotonically with the damping parameter. In every case the
    returned ``achieved_e`` is measured on the full simulated collision.
    """
    e = float(restitution(target_e, "target_e"))
    if e >= 1.0:
        raise ValueError("target_e must be < 1 to calibrate damping (got 1)")
    m_eff = m_effective(m1, m2)
    if law.damping_field is None:
        raise ValueError(f"law: {law.label} has no damping parameter to calibrate"
                         + ("; use calibrate_bilinear" if isinstance(law, BilinearImpact) else ""))

    def achieved(x: float) -> float:
        return simulate_collision(law.with_damping(x), m1, m2, v0).e

    if isinstance(law, KelvinVoigt) and law.tension:
        zeta = float(zeta_anagnostopoulos(e))
        value, method = 2.0 * zeta * np.sqrt(law.k * m_eff), "closed form"
    elif isinstance(law, ModifiedKelvinVoigt):
        zeta = float(zeta_modified_kelvin_voigt_exact(e))
        value, method = 2.0 * zeta * np.sqrt(law.k * m_eff), "closed form"
    elif isinstance(law, KelvinVoigt):
        zeta = float(zeta_kelvin_voigt_clipped(e))
        value, method = 2.0 * zeta * np.sqrt(law.k * m_eff), "closed form"
    elif isinstance(law, HuntCrossley):
        value, method = float(chi_hunt_crossley_exact(e)), "closed form"
    elif isinstance(law, NonlinearViscoelastic):
        # e depends on ζ alone (restitution_nonlinear_viscoelastic): Brent's method on that
        # one-dimensional approach
        value = float(zeta_nonlinear_viscoelastic_exact(e))
        method = "approach integrated alone"
    else:
        scale = {"c": 2.0 * np.sqrt(getattr(law, "k", 1.0) * m_eff)}.get(law.damping_field, 1.0)
        value = _root(achieved, e, 0.0, 0.1 * scale, xtol=tol * 1e-3 * scale)
        method = "root finding"
    calibrated = law.with_damping(value)
    got = simulate_collision(calibrated, m1, m2, v0).e
    return Calibration(calibrated, law.damping_field, float(value), e, got, method)


def calibrate_bilinear(k_h: float, target_e: float, m1: float, m2: float, v0: float,
                       delta_m: float | None = None, a: float = 0.1,
                       n: float = 1.5) -> Calibration:
    """Bilinear impact element that achieves ``target_e`` at impact velocity ``v0``.

    The loop is sized at ``delta_m`` (default: the elastic Hertz maximum penetration at
    ``v0``, Muthukumar 2003); the restitution it is sized for (``e`` of
    :meth:`BilinearImpact.from_hertz`) is found by root finding so the simulated impact
    achieves ``target_e``.

    Raises
    ------
    ValueError
        If no design e reaches the target: an element sized at ``delta_m`` penetrates less
        than ``delta_m`` and so dissipates less than designed; the message gives the
        smallest e it can reach.
    """
    e = float(restitution(target_e, "target_e"))
    dm = hertz_delta_max(k_h, m_effective(m1, m2), v0, n) if delta_m is None \
        else positive("delta_m", delta_m)

    def achieved(x: float) -> float:
        return simulate_collision(BilinearImpact.from_hertz(k_h, x, dm, a, n), m1, m2, v0).e

    lo, hi = 1e-6, 1.0 - 1e-9  # e = 1 is the elastic limit, not a bilinear loop
    e_min = achieved(lo)
    if e < e_min:
        raise ValueError(f"target_e={e:g} is out of reach of a bilinear element sized at "
                         f"delta_m={dm:.4g} m (it reaches e >= {e_min:.4f}): its own penetration "
                         f"stays below delta_m, so it dissipates less than designed")
    x = brentq(lambda s: achieved(s) - e, lo, hi, xtol=1e-12)
    law = BilinearImpact.from_hertz(k_h, x, dm, a, n)
    return Calibration(law, "e_design", float(x), e, simulate_collision(law, m1, m2, v0).e,
                       "root finding")


# --------------------------------------------------------------------------- fitting
FIT_LAWS: tuple[str, ...] = ("linear-spring", "kelvin-voigt", "modified-kelvin-voigt", "hertz",
                             "hunt-crossley", "nonlinear-viscoelastic")
"""Laws :func:`fit_impact` can fit (stiffness and, where the law has one, damping)."""


@dataclass(frozen=True)
class ImpactFit:
    """Outcome of :func:`fit_impact`.

    Attributes
    ----------
    law : ContactLaw
        The fitted law.
    parameters : dict[str, float]
        Fitted values by field name (SI units of each field).
    residual_rms : float
        Root-mean-square force residual [N].
    relative_residual : float
        ``residual_rms`` over the measured peak force.
    achieved_e : float
        Coefficient of restitution the fitted law achieves at the given ``v0``.
    """

    law: ContactLaw
    parameters: dict[str, float]
    residual_rms: float
    relative_residual: float
    achieved_e: float


def _build(name: str, stiffness: float, damping: float, m_eff: float, n: float) -> ContactLaw:
    if name == "linear-spring":
        return LinearSpring(stiffness)
    if name == "kelvin-voigt":
        return KelvinVoigt(stiffness, damping, tension=True)
    if name == "modified-kelvin-voigt":
        return ModifiedKelvinVoigt(stiffness, damping)
    if name == "hertz":
        return Hertz(stiffness, n)
    if name == "hunt-crossley":
        return HuntCrossley(stiffness, damping, n)
    return NonlinearViscoelastic(stiffness, damping, m_eff)


def fit_impact(t: ArrayLike, force: ArrayLike, m1: float, m2: float, v0: float,
               law: str = "hunt-crossley", n: float = 1.5) -> ImpactFit:
    """Fit a law's stiffness and damping to a measured contact-force history.

    Parameters
    ----------
    t : array_like, shape (k,)
        Sample times [s], with ``t = 0`` at first contact.
    force : array_like, shape (k,)
        Measured contact force [N] (noise allowed; samples after separation should be ~0).
    m1, m2 : float
        Masses of the colliding bodies [kg].
    v0 : float
        Measured impact velocity [m/s].
    law : str
        One of :data:`FIT_LAWS`.
    n : float
        Hertz exponent, held fixed for the Hertz-type laws.

    Returns
    -------
    ImpactFit

    Notes
    -----
    Least squares (SciPy ``least_squares``, trust-region reflective) in the logarithms of
    the parameters, each residual the difference of the simulated and measured force at a
    sample time. The start comes from the measured contact duration (stiffness) and
    impulse (restitution).
    """
    name = choice("law", law, FIT_LAWS)
    tt = np.asarray(t, dtype=float)
    ff = np.asarray(force, dtype=float)
    if tt.ndim != 1 or tt.shape != ff.shape or tt.size < 5:
        raise ValueError(f"t and force must be 1-D arrays of one length >= 5 "
                         f"(got shapes {tt.shape} and {ff.shape})")
    if not (np.all(np.isfinite(tt)) and np.all(np.isfinite(ff))):
        raise ValueError("t and force must be finite")
    m_eff = m_effective(m1, m2)
    v0 = positive("v0", v0)
    peak = float(np.max(np.abs(ff)))
    if peak <= 0.0:
        raise ValueError("force: the measured history is zero everywhere")
    # starting point: duration and impulse of the measured pulse
    above = tt[ff > 0.05 * peak]
    duration = float(above[-1] - above[0]) if above.size > 1 else float(tt[-1] - tt[0])
    impulse = float(np.trapezoid(np.clip(ff, 0.0, None), tt))
    e0 = float(np.clip(impulse / (m_eff * v0) - 1.0, 0.05, 0.95))
    hertzian = name in ("hertz", "hunt-crossley", "nonlinear-viscoelastic")
    if hertzian:  # elastic Hertz duration ≈ 3.2181 (m²/(k² v0))^(1/5) (Goldsmith: 2.94 δm/v0)
        k0 = np.sqrt((3.2181**5) * m_eff**2 / (duration**5 * v0))
    else:
        k0 = m_eff * (np.pi / duration) ** 2
    damped = name not in ("linear-spring", "hertz")
    if name in ("kelvin-voigt", "modified-kelvin-voigt"):
        d0 = 2.0 * float(zeta_anagnostopoulos(e0)) * np.sqrt(k0 * m_eff)
    elif name == "hunt-crossley":
        d0 = 0.75 * (1.0 - e0**2)
    else:
        d0 = 0.5 * (1.0 - e0)
    x0 = np.log([k0, d0]) if damped else np.log([k0])

    def model(x: NDArray[np.float64]) -> ContactLaw:
        return _build(name, float(np.exp(x[0])), float(np.exp(x[1])) if damped else 0.0, m_eff, n)

    def residual(x: NDArray[np.float64]) -> NDArray[np.float64]:
        r = simulate_collision(model(x), m1, m2, v0, rtol=1e-9, samples=200)
        return (r.force_at(tt) - ff) / peak

    sol = least_squares(residual, x0, method="trf", x_scale=1.0, xtol=1e-10, ftol=1e-12)
    fitted = model(sol.x)
    rms = float(np.sqrt(np.mean((sol.fun * peak) ** 2)))
    params = {"stiffness": float(np.exp(sol.x[0]))}
    if damped:
        params[fitted.damping_field or "damping"] = float(np.exp(sol.x[1]))
    e_fit = simulate_collision(fitted, m1, m2, v0).e
    return ImpactFit(fitted, params, rms, rms / peak, e_fit)
