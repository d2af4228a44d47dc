"""The seed paper's derivation of its proposed damping formula (seed eqs 21–39), step by step.

Naderpour, Khatami & Barros (2015), COMPDYN, section "Proposed non-linear viscoelastic model".
Each function computes one equation *exactly as the paper states it* and cites it, so that
every step can be evaluated, compared with the step before, and held against a simulated
collision. Where a step does not follow from the one before, the function for the stated
equation is kept and a second function gives what the preceding step actually implies; the
docstrings and ``docs/seed_paper.md`` say which is which.

Notation (SI): ``k`` spring stiffness [N/m], ``m = m1 m2 / (m1 + m2)`` effective mass [kg]
(text after eq 24), ``ζ`` damping ratio, ``δ`` penetration [m], ``δ̇`` its rate [m/s],
``δ̇_final`` (``v_final``), ``δ̇_0`` (``v0``) and ``δ̇_imp`` (``v_imp``) the three velocities the
paper names without defining [m/s], ``e`` = CR, the coefficient of restitution.

Reading of the undefined velocities (the paper never defines δ̇_0, δ̇_final and δ̇_imp)
------------------------------------------------------------------------------------
* ``δ̇_imp`` is the relative velocity at impact (eq 36: the kinetic energy lost is
  ``½ m (1 − CR²) δ̇_imp²``).
* ``δ̇_0 = δ̇_imp``: the δ̇ > 0 branch of eq 29 starts at ``δ = 0`` with velocity ``δ̇_0``
  (its linear term makes ``δ̇(0) = |δ̇_final| + δ̇_0 − |δ̇_final|``) and falls to 0 at δmax;
  that is the approach (compression) phase of an impact at ``δ̇_imp``.
* ``|δ̇_final| = CR · δ̇_imp``: the δ̇ < 0 branch of eq 29 ends at ``δ = 0`` with speed
  ``|δ̇_final|``, the separation speed; CR = v_after / v_before (eq 16 read the right way round;
  the paper prints it inverted). This is the only reading that gives eq 39 its factor
  ``CR · (… CR …)`` in the denominator.

What holds and what does not (all shown by functions here; tests in
``tests/contact/test_seed_derivation.py``)
------------------------------------------------------------------------------------
* Eq 25 follows from eqs 23–24 (with ω = ω_n): ``2 π ζ k δmax² = ½ m δ̇_final²``.
* Eqs 26–28 treat the per-cycle dissipation ``2 π ζ k δ²`` as if it were stored energy: the
  velocity profile is that of a spring of stiffness ``4 π ζ k``, not ``k``. For the linear
  spring that unloads elastically (the law the derivation describes: a dashpot acting only on
  approach, eq 31), ``½ k δmax² = ½ m δ̇_final²``; together with eq 25 this forces
  ``ζ = 1/(4π) ≈ 0.0796`` whatever CR is (:func:`zeta_consistent_with_eq25`).
* Eqs 31–35 follow from eqs 29–30 and 25 (the integral of eq 34 is ``π δmax²/4``).
* Eq 36 = eq 35 with δmax from eq 25 — it follows. Eq 37 = eq 36 with δmax² from eq 25 —
  it follows.
* Eq 38 does **not** follow from eq 37: dividing eq 37 by m gives a second term
  ``ζ^0.5 (δ̇_0 − |δ̇_final|) δ̇_final / (2 sqrt(π))``; eq 38 prints
  ``ζ^0.5 (sqrt(π)/π) (…)`` — twice that (:func:`eq37_rhs_per_mass` vs :func:`eq38_rhs`).
* Eq 39 follows from neither eq 38 nor eq 37 under the reading above
  (:func:`zeta_from_eq38`): solving eq 37 gives
  ``ζ = ((1 − CR²) / (CR (sqrt(π) (0.5 CR + 1/π) − CR/sqrt(π))))²``; eq 39 has ``− CR`` where
  this has ``− CR/sqrt(π)``. At CR = 0.5 eq 39 gives 8.74 (Table 1), eq 38 as printed 2.22,
  eq 37 4.28.
* Eq 24 (ΔE = ½ m δ̇_final²) and eq 36 (ΔE = ½ m (1 − CR²) δ̇_imp²) use the same symbol ΔE;
  with ``|δ̇_final| = CR δ̇_imp`` they agree only at CR = 1/sqrt(2).
* The derivation uses a constant ``c = 2 ζ sqrt(k m)`` (eq 30) and a linear spring (eq 23);
  the formula is then proposed for the nonlinear viscoelastic law of eqs 17–18, whose
  ``c_h = 2 ζ sqrt(k_h sqrt(δ) m)`` and spring ``k_h δ^1.5`` appear nowhere in it.
"""

from __future__ import annotations

from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import quad

from pounding.validation import finite, non_negative, positive, restitution

FloatArray = NDArray[np.float64]

SQRT_PI: float = float(np.sqrt(np.pi))

__all__ = [
    "DissipatedEnergy",
    "SeedPrediction",
    "damping_coefficient_eq30",
    "delta_max_eq25",
    "dissipated_energy_eq23",
    "dissipated_energy_eq24",
    "dissipated_energy_eq31",
    "dissipated_energy_eq35",
    "eq36_rhs",
    "eq37_rhs",
    "eq37_rhs_per_mass",
    "eq38_rhs",
    "kinetic_energy_loss_eq36",
    "residual_eq36",
    "residual_eq38",
    "seed_prediction",
    "velocity_eq28",
    "velocity_eq29",
    "zeta_consistent_with_eq25",
    "zeta_eq39",
    "zeta_from_eq38",
]


def _out(x: FloatArray) -> FloatArray | float:
    return float(x) if np.ndim(x) == 0 else x


def _zeta(zeta: float) -> float:
    return positive("zeta", zeta)


# --------------------------------------------------------------------------- eqs 21-25
def dissipated_energy_eq23(zeta: float, k: float, delta: ArrayLike,
                           omega_ratio: float = 1.0) -> FloatArray | float:
    """Energy dissipated per cycle of steady harmonic motion: ``ΔE = 2 π ζ (ω/ω_n) k δ²`` [J]
    (seed eq 23; the same as eq 11).

    ``omega_ratio`` is ω/ω_n; the paper sets it to 1 ("the equation between w and w_n could be
    assumed to be 1") before eq 24. Eqs 21–22 are the definition ``ΔE = ∫ c δ̇ dδ`` of which
    this is the closed form over a cycle of amplitude δ (see
    :func:`pounding.contact.link_element.ellipse_area`).
    """
    z = non_negative("zeta", zeta)
    kk = positive("k", k)
    r = positive("omega_ratio", omega_ratio)
    d = np.asarray(delta, dtype=float)
    return _out(2.0 * np.pi * z * r * kk * d * d)


def dissipated_energy_eq24(m: float, v_final: ArrayLike) -> FloatArray | float:
    """Right side of seed eq 24: ``ΔE = 0.5 m δ̇_final²`` [J].

    The paper equates the energy dissipated over one cycle of harmonic motion with the
    kinetic energy at the *final* velocity. Eq 36 later equates the same ΔE with
    ``½ m (1 − CR²) δ̇_imp²``; with ``|δ̇_final| = CR δ̇_imp`` the two agree only at
    ``CR = 1/sqrt(2)``.
    """
    mm = positive("m", m)
    v = np.asarray(v_final, dtype=float)
    return _out(0.5 * mm * v * v)


def delta_max_eq25(m: float, zeta: float, k: float, v_final: ArrayLike) -> FloatArray | float:
    """Maximum penetration ``δmax = sqrt(m / (4 π ζ k)) δ̇_final`` [m] (seed eq 25).

    Follows from eq 24 = eq 23 (ω = ω_n): ``2 π ζ k δmax² = ½ m δ̇_final²``.

    **What it implies.** δmax grows without bound as ζ → 0 and is set by the final
    (rebound) velocity, not the impact velocity. An elastic linear spring stopping a mass gives
    ``δmax = sqrt(m/k) v``; eq 25 agrees with that only when ``4 π ζ = 1``
    (:func:`zeta_consistent_with_eq25`).
    """
    mm = positive("m", m)
    z = _zeta(zeta)
    kk = positive("k", k)
    v = np.abs(np.asarray(v_final, dtype=float))
    return _out(np.sqrt(mm / (4.0 * np.pi * z * kk)) * v)


def zeta_consistent_with_eq25() -> float:
    """The one damping ratio at which eq 25 agrees with a linear spring: ``ζ = 1/(4π)``.

    The derivation's law (linear spring ``k``, dashpot on approach only — eq 31 integrates
    the approach branch) unloads elastically, so the separation speed satisfies
    ``½ k δmax² = ½ m δ̇_final²``. Eq 25 states ``2 π ζ k δmax² = ½ m δ̇_final²``. Both hold
    only if ``2 π ζ = ½``, whatever CR is.
    """
    return float(1.0 / (4.0 * np.pi))


# --------------------------------------------------------------------------- eqs 26-29
def velocity_eq28(delta: ArrayLike, m: float, zeta: float, k: float,
                  v_final: float) -> FloatArray | float:
    """Relative velocity during impact, ``δ̇ = sqrt(δ̇_final² − 4 k ζ π δ² / m)`` [m/s]
    (seed eq 28, from the energy balance of eqs 26–27).

    Eq 26, ``2 π ζ k δ² + ½ m δ̇² = ½ m δ̇_final²``, treats the per-cycle dissipation
    ``2 π ζ k δ²`` as a stored (potential) energy: the profile is that of an undamped spring of
    stiffness ``4 π ζ k``. Valid for ``|δ| ≤ δmax`` of eq 25 (zero there).
    """
    mm = positive("m", m)
    z = _zeta(zeta)
    kk = positive("k", k)
    vf = finite("v_final", v_final)
    d = np.asarray(delta, dtype=float)
    arg = vf * vf - 4.0 * kk * z * np.pi * d * d / mm
    if np.any(arg < -1e-12 * vf * vf):
        dmax = float(delta_max_eq25(mm, z, kk, vf))
        raise ValueError(f"delta must satisfy |delta| <= delta_max = {dmax:g} m of eq 25 "
                         f"(got {float(np.max(np.abs(d))):g})")
    return _out(np.sqrt(np.clip(arg, 0.0, None)))


def velocity_eq29(delta: ArrayLike, m: float, zeta: float, k: float, v_final: float,
                  v0: float, branch: Literal["approach", "rebound"] = "approach"
                  ) -> FloatArray | float:
    """Velocity profile during impact, both branches of seed eq 29 [m/s].

    * ``branch="rebound"`` (the paper's "for δ̇ < 0"):
      ``δ̇ = −sqrt(δ̇_final² − 4 k ζ π δ² / m)`` — from ``−|δ̇_final|`` at ``δ = 0`` to 0 at δmax.
    * ``branch="approach"`` (the paper's "for δ̇ > 0"):
      ``δ̇ = sqrt(δ̇_final² − 4 k ζ π δ² / m) + (δ̇_0 − |δ̇_final|)(δmax − δ)/δmax`` — from
      ``δ̇_0`` at ``δ = 0`` (if δ̇_final ≥ 0) to 0 at δmax, with δmax from eq 25.

    The added linear term makes the approach branch violate the energy balance of eq 26
    unless ``δ̇_0 = |δ̇_final|``; the paper offers it as an assumption.

    Parameters
    ----------
    delta : array_like
        Penetration(s), ``0 ≤ δ ≤ δmax`` [m].
    m, zeta, k : float
        Effective mass [kg], damping ratio, stiffness [N/m].
    v_final : float
        δ̇_final [m/s] (this module reads it as the separation speed ``CR · δ̇_imp``).
    v0 : float
        δ̇_0 [m/s] (read as the impact velocity δ̇_imp).
    branch : {"approach", "rebound"}
    """
    v0f = finite("v0", v0)
    root = np.asarray(velocity_eq28(delta, m, zeta, k, v_final), dtype=float)
    if branch == "rebound":
        return _out(-root)
    if branch != "approach":
        raise ValueError(f"branch must be 'approach' or 'rebound' (got {branch!r})")
    vf = float(v_final)
    dmax = float(delta_max_eq25(m, zeta, k, vf))
    d = np.asarray(delta, dtype=float)
    return _out(root + (v0f - abs(vf)) * (dmax - d) / dmax)


# --------------------------------------------------------------------------- eqs 30-35
def damping_coefficient_eq30(k: float, m: float, zeta: float) -> float:
    """Dashpot coefficient of eq 30, ``c = 2 ζ sqrt(k m)`` [N·s/m].

    Eq 30 writes ``ΔE = 2 ζ sqrt(k m) ∫ δ̇ dδ``: eq 22 with this constant c — eq 12 with
    ``ω_n = sqrt(k/m)``, *not* the paper's own eq 15 (which has ``1/sqrt(1 − ζ)``), and not the
    δ-dependent ``c_h`` of eq 18.
    """
    kk = positive("k", k)
    mm = positive("m", m)
    z = non_negative("zeta", zeta)
    return float(2.0 * z * np.sqrt(kk * mm))


class DissipatedEnergy(NamedTuple):
    """Energy dissipated by the dashpot over the approach, split as in seed eqs 33–35 [J].

    Attributes
    ----------
    ellipse : first term, ``4 k sqrt(π) ζ^1.5 ∫_0^δmax sqrt(δmax² − δ²) dδ``
        ``= 4 k sqrt(π) ζ^1.5 (0.25 π δmax²)`` (eq 35).
    wedge : second term, ``2 ζ sqrt(k m) (δ̇_0 − |δ̇_final|)/2 · δmax`` (from the linear term
        of eq 29).
    total : their sum, ΔE of eq 35.
    delta_max : δmax of eq 25 used [m].
    """

    ellipse: float
    wedge: float
    total: float
    delta_max: float


def dissipated_energy_eq35(k: float, m: float, zeta: float, v0: float,
                           v_final: float) -> DissipatedEnergy:
    """Dissipated energy over the approach, closed form of seed eq 35 (parts: eqs 33–34).

    ``ΔE = 4 k sqrt(π) ζ^1.5 (0.25 π δmax²) + 2 ζ sqrt(k m) (δ̇_0 − |δ̇_final|)/2 · δmax``
    with ``δmax = sqrt(m/(4 π ζ k)) δ̇_final`` (eq 25). Eqs 31 → 35 are correct algebra:
    eq 33 factors ``sqrt(4 ζ π k / m)`` out of the root, eq 34 multiplies it by
    ``2 ζ sqrt(k m)`` to get ``4 k sqrt(π) ζ^1.5``, and ``∫_0^δmax sqrt(δmax² − δ²) dδ =
    π δmax²/4`` gives eq 35. Compare :func:`dissipated_energy_eq31` (quadrature).
    """
    kk = positive("k", k)
    mm = positive("m", m)
    z = _zeta(zeta)
    v0f = finite("v0", v0)
    vf = finite("v_final", v_final)
    dmax = float(delta_max_eq25(mm, z, kk, vf))
    ellipse = 4.0 * kk * SQRT_PI * z**1.5 * (0.25 * np.pi * dmax * dmax)
    wedge = 2.0 * z * np.sqrt(kk * mm) * (v0f - abs(vf)) / 2.0 * dmax
    return DissipatedEnergy(float(ellipse), float(wedge), float(ellipse + wedge), dmax)


def dissipated_energy_eq31(k: float, m: float, zeta: float, v0: float, v_final: float) -> float:
    """Seed eq 31 evaluated by quadrature: ``ΔE = 2 ζ sqrt(k m) ∫_0^δmax δ̇(δ) dδ`` [J],
    with δ̇ the approach branch of eq 29 and δmax from eq 25 (adaptive Gauss–Kronrod,
    :func:`scipy.integrate.quad`). Equal to :func:`dissipated_energy_eq35` — the step holds.
    """
    c = damping_coefficient_eq30(k, m, zeta)
    dmax = float(delta_max_eq25(m, zeta, k, v_final))

    def integrand(d: float) -> float:
        return float(velocity_eq29(min(d, dmax), m, zeta, k, v_final, v0, "approach"))

    val, _ = quad(integrand, 0.0, dmax, epsabs=0.0, epsrel=1e-12, limit=200)
    return float(c * val)


# --------------------------------------------------------------------------- eqs 36-39
def kinetic_energy_loss_eq36(m: float, e: ArrayLike, v_imp: float) -> FloatArray | float:
    """Left side of seed eqs 36–37: ``½ m (1 − CR²) δ̇_imp²`` [J] (m = m1 m2/(m1 + m2)).

    The kinetic energy lost in a collision with coefficient of restitution CR (defined the
    usual way, v_after/v_before — eq 16 prints it inverted).
    """
    mm = positive("m", m)
    x = restitution(e, "e")
    v = finite("v_imp", v_imp)
    return _out(0.5 * mm * (1.0 - x * x) * v * v)


def eq36_rhs(k: float, m: float, zeta: float, v0: float, v_final: float) -> float:
    """Right side of seed eq 36 [J], as stated:
    ``4 k sqrt(π) ζ^1.5 (0.25 π δmax²) + 2 ζ sqrt(k m) (δ̇_0 − |δ̇_final|)/2 ·
    sqrt(m/(4 π ζ k)) · δ̇_final`` (eq 35 with δmax of eq 25 in its second term; the first
    term still holds δmax², computed here from eq 25)."""
    kk = positive("k", k)
    mm = positive("m", m)
    z = _zeta(zeta)
    v0f = finite("v0", v0)
    vf = finite("v_final", v_final)
    dmax = float(delta_max_eq25(mm, z, kk, vf))
    first = 4.0 * kk * SQRT_PI * z**1.5 * (0.25 * np.pi * dmax**2)
    second = (2.0 * z * np.sqrt(kk * mm) * (v0f - abs(vf)) / 2.0
              * np.sqrt(mm / (4.0 * np.pi * z * kk)) * vf)
    return float(first + second)


def eq37_rhs(k: float, m: float, zeta: float, v0: float, v_final: float) -> float:
    """Right side of seed eq 37 [J], as stated:
    ``4 k sqrt(π) ζ^1.5 (0.25 π m/(4 π ζ k) δ̇_final²) + ζ sqrt(k m) (δ̇_0 − |δ̇_final|)
    sqrt(m/(4 π ζ k)) δ̇_final``. Eq 36 with δmax² from eq 25 — this step holds."""
    kk = positive("k", k)
    mm = positive("m", m)
    z = _zeta(zeta)
    v0f = finite("v0", v0)
    vf = finite("v_final", v_final)
    first = 4.0 * kk * SQRT_PI * z**1.5 * (0.25 * np.pi * mm / (4.0 * np.pi * z * kk) * vf**2)
    second = z * np.sqrt(kk * mm) * (v0f - abs(vf)) * np.sqrt(mm / (4.0 * np.pi * z * kk)) * vf
    return float(first + second)


def eq37_rhs_per_mass(zeta: float, v0: float, v_final: float) -> float:
    """Eq 37's right side divided by m, simplified correctly [J/kg]:
    ``0.25 sqrt(π) ζ^0.5 δ̇_final² + ζ^0.5 (δ̇_0 − |δ̇_final|) δ̇_final / (2 sqrt(π))``.

    This is what eq 38 should read. (k cancels.) Compare :func:`eq38_rhs`, whose second term is
    twice this one's.
    """
    z = _zeta(zeta)
    v0f = finite("v0", v0)
    vf = finite("v_final", v_final)
    return float(0.25 * SQRT_PI * np.sqrt(z) * vf**2
                 + np.sqrt(z) * (v0f - abs(vf)) * vf / (2.0 * SQRT_PI))


def eq38_rhs(zeta: float, v0: float, v_final: float) -> float:
    """Right side of seed eq 38 as printed [J/kg]:
    ``0.25 sqrt(π) ζ^0.5 δ̇_final² + ζ^0.5 (sqrt(π)/π) (δ̇_0 − |δ̇_final|) δ̇_final``.

    **Does not follow from eq 37.** Eq 37 divided by m has ``1/(2 sqrt(π))`` where this has
    ``sqrt(π)/π = 1/sqrt(π)`` (:func:`eq37_rhs_per_mass`); the first terms agree.
    """
    z = _zeta(zeta)
    v0f = finite("v0", v0)
    vf = finite("v_final", v_final)
    return float(0.25 * SQRT_PI * np.sqrt(z) * vf**2
                 + np.sqrt(z) * (SQRT_PI / np.pi) * (v0f - abs(vf)) * vf)


def residual_eq36(k: float, m: float, zeta: float, e: float, v_imp: float, v0: float,
                  v_final: float) -> float:
    """Seed eq 36, left minus right [J]: zero when the stated energy balance holds."""
    return float(kinetic_energy_loss_eq36(m, e, v_imp)) - eq36_rhs(k, m, zeta, v0, v_final)


def residual_eq38(zeta: float, e: float, v_imp: float, v0: float, v_final: float,
                  form: Literal["stated", "from_eq37"] = "stated") -> float:
    """Seed eq 38, left minus right [J/kg]: ``½ (1 − CR²) δ̇_imp² − RHS``.

    ``form="stated"`` uses eq 38 as printed (:func:`eq38_rhs`); ``"from_eq37"`` uses eq 37
    divided by m (:func:`eq37_rhs_per_mass`).
    """
    x = float(restitution(e, "e"))
    v = finite("v_imp", v_imp)
    if form == "stated":
        rhs = eq38_rhs(zeta, v0, v_final)
    elif form == "from_eq37":
        rhs = eq37_rhs_per_mass(zeta, v0, v_final)
    else:
        raise ValueError(f"form must be 'stated' or 'from_eq37' (got {form!r})")
    return float(0.5 * (1.0 - x * x) * v * v - rhs)


def zeta_from_eq38(e: ArrayLike, form: Literal["stated", "from_eq37"] = "stated",
                   v0_ratio: float = 1.0, final_ratio: float | None = None
                   ) -> FloatArray | float:
    """Solve seed eq 38 (or eq 37 / m) for ζ, given CR — the step the paper takes to eq 39.

    Reading (the paper defines none of the velocities; see the module docstring):
    ``δ̇_imp = 1`` (the equation is homogeneous of degree 2 in the velocities),
    ``δ̇_0 = v0_ratio · δ̇_imp`` (default 1: δ̇_0 is the impact velocity) and
    ``δ̇_final = final_ratio · δ̇_imp`` (default ``CR``: the separation speed).
    Eq 38 is linear in ``sqrt(ζ)``: ``½ (1 − CR²) = sqrt(ζ) B`` with
    ``B = 0.25 sqrt(π) f² + a (v0 − f) f``, ``a = 1/sqrt(π)`` as printed (``form="stated"``)
    or ``1/(2 sqrt(π))`` from eq 37 (``form="from_eq37"``); so ``ζ = (½ (1 − CR²) / B)²``.
    With the default reading:

    * stated:    ``ζ = ((1 − CR²) / (CR (0.5 sqrt(π) CR + 2 (1 − CR)/sqrt(π))))²``
    * from_eq37: ``ζ = ((1 − CR²) / (CR (0.5 sqrt(π) CR + (1 − CR)/sqrt(π))))²``

    Neither is eq 39 (:func:`zeta_eq39`), which reads
    ``((1 − CR²) / (CR (0.5 sqrt(π) CR + 1/sqrt(π) − CR)))²``.

    Raises
    ------
    ValueError
        If ``B ≤ 0`` for some CR (no real ζ solves the equation there).
    """
    x = restitution(e, "e")
    r0 = finite("v0_ratio", v0_ratio)
    f = x if final_ratio is None else np.full_like(x, finite("final_ratio", final_ratio))
    if form == "stated":
        a = 1.0 / SQRT_PI
    elif form == "from_eq37":
        a = 1.0 / (2.0 * SQRT_PI)
    else:
        raise ValueError(f"form must be 'stated' or 'from_eq37' (got {form!r})")
    b = 0.25 * SQRT_PI * f * f + a * (r0 - np.abs(f)) * f
    if np.any(b <= 0.0):
        bad = float(np.asarray(x)[b <= 0.0].flat[0]) if np.ndim(x) else float(x)
        raise ValueError(f"e: eq 38 has no real solution for zeta at e = {bad:g} "
                         f"with v0_ratio = {r0:g}")
    return _out((0.5 * (1.0 - x * x) / b) ** 2)


def zeta_eq39(e: ArrayLike) -> FloatArray | float:
    """The paper's proposed damping ratio, seed eq 39 as printed:
    ``ζ = ((1 − CR²) / (CR (sqrt(π)(0.5 CR + 1/π) − CR)))²``.

    Same formula as :func:`pounding.contact.restitution.zeta_naderpour` (the law-facing one);
    here so the derivation can be compared end to end. It does not follow from eq 38 or
    eq 37 (:func:`zeta_from_eq38`).
    """
    from pounding.contact.restitution import zeta_naderpour

    return zeta_naderpour(e)


# --------------------------------------------------------------------------- vs simulation
class SeedPrediction(NamedTuple):
    """What the seed's derivation predicts for one collision, to hold against a simulation.

    Attributes
    ----------
    zeta : damping ratio used.
    c : dashpot coefficient ``2 ζ sqrt(k m)`` of eq 30 [N·s/m].
    v_final : separation speed assumed, ``CR · δ̇_imp`` [m/s].
    delta_max : eq 25 [m].
    delta_max_elastic : ``sqrt(m/k) δ̇_imp`` — the undamped linear spring, for scale [m].
    energy_dissipated : eq 35 total (approach only) [J].
    energy_lost : eq 36 left side ``½ m (1 − CR²) δ̇_imp²`` [J].
    residual_eq36 : ``energy_lost − energy_dissipated`` [J]: zero only if ζ solves eq 36.
    """

    zeta: float
    c: float
    v_final: float
    delta_max: float
    delta_max_elastic: float
    energy_dissipated: float
    energy_lost: float
    residual_eq36: float


def seed_prediction(k: float, m: float, e: float, v_imp: float,
                    zeta: float | None = None) -> SeedPrediction:
    """The derivation's predictions for a linear-spring collision at ``δ̇_imp = v_imp``.

    Uses the module's reading (``δ̇_0 = δ̇_imp``, ``|δ̇_final| = CR δ̇_imp``). ``zeta``
    defaults to eq 39's value for ``e``. Simulate the modified Kelvin–Voigt law
    (``pounding.contact.ModifiedKelvinVoigt(k, c)``, the law eqs 30–31 describe) at the same
    k, m, c and impact speed, and compare its δmax, the energy it dissipates and its CR with
    these numbers.
    """
    kk = positive("k", k)
    mm = positive("m", m)
    x = float(restitution(e, "e"))
    v = positive("v_imp", v_imp)
    z = float(zeta_eq39(x)) if zeta is None else _zeta(zeta)
    vf = x * v
    parts = dissipated_energy_eq35(kk, mm, z, v, vf)
    lost = float(kinetic_energy_loss_eq36(mm, x, v))
    return SeedPrediction(
        zeta=z,
        c=damping_coefficient_eq30(kk, mm, z),
        v_final=vf,
        delta_max=parts.delta_max,
        delta_max_elastic=float(np.sqrt(mm / kk) * v),
        energy_dissipated=parts.total,
        energy_lost=lost,
        residual_eq36=lost - parts.total,
    )
