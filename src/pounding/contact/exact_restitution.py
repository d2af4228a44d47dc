"""The restitution each contact law really achieves, exactly: ``e`` as a function of the
law's damping parameter, in closed form where the law has one (Kelvin–Voigt without tension,
modified Kelvin–Voigt, Hunt–Crossley) or reduced to a one-dimensional integration
(Jankowski's nonlinear viscoelastic law), and the exact inverse of the default Kelvin–Voigt
law's. Every ``e`` here depends on the damping parameter alone, not on the masses, the
stiffness or the impact velocity.

These are what :func:`pounding.contact.calibration.calibrate` inverts, and what the damping
formulas of :mod:`pounding.contact.restitution` approximate; the simulated collision
(:func:`pounding.contact.collision.simulate_collision`) agrees with each (tests).

The four exact inverses (:func:`zeta_kelvin_voigt_clipped`,
:func:`zeta_modified_kelvin_voigt_exact`, :func:`chi_hunt_crossley_exact`,
:func:`zeta_nonlinear_viscoelastic_exact`) are tabulated at ``e`` = 0.01, 0.02, … 0.99
(:mod:`pounding.contact.exact_table`, made by these functions): a model file's ``e`` of two
decimals takes its value from there, without loading SciPy's root finder and integrator
(0.3 s of a run's start-up); any other ``e`` is solved for here.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.contact import exact_table
from pounding.memo import Memo
from pounding.validation import restitution as _check_e

FloatArray = NDArray[np.float64]


def _by_damping_regime(zeta: ArrayLike, under: Callable[[FloatArray], FloatArray],
                       critical: float, over: Callable[[FloatArray], FloatArray]
                       ) -> FloatArray | float:
    """``under(ζ)`` for ζ < 1, ``critical`` at ζ = 1 (within 1e-9) and ``over(ζ)`` for
    ζ > 1, elementwise; ζ must be finite and ≥ 0."""
    z = np.asarray(zeta, dtype=float)
    if np.any(~np.isfinite(z) | (z < 0.0)):
        raise ValueError(f"zeta must be finite and >= 0 (got {z})")
    out = np.empty_like(z)
    is_under = z < 1.0 - 1e-9
    is_over = z > 1.0 + 1e-9
    out[is_under] = under(z[is_under])
    out[is_over] = over(z[is_over])
    out[~(is_under | is_over)] = critical
    return float(out) if out.ndim == 0 else out


def restitution_kelvin_voigt_clipped(zeta: ArrayLike) -> FloatArray | float:
    """Exact ``e`` of the Kelvin–Voigt law whose force is clipped at zero (no tension).

    The bodies separate when ``k δ + c δ̇`` returns to zero, with the spring still
    compressed (Schwager & Pöschel 2007, *Coefficient of restitution and linear–dashpot
    model revisited*, Granular Matter 9:465–469, eqs 20–22; derived again in
    ``docs/laws/kelvin-voigt.md`` from the damped free vibration):

    * ζ < 1: ``e = exp(−ζ (π − 2 arcsin ζ) / sqrt(1 − ζ²))``
    * ζ = 1: ``e = exp(−2)``
    * ζ > 1: ``e = exp(−2 ζ arccosh(ζ) / sqrt(ζ² − 1))``
    """
    return _by_damping_regime(
        zeta,
        lambda z: np.exp(-z * (np.pi - 2.0 * np.arcsin(z)) / np.sqrt(1.0 - z**2)),
        math.exp(-2.0),
        lambda z: np.exp(-2.0 * z * np.arccosh(z) / np.sqrt(z**2 - 1.0)))


def zeta_kelvin_voigt_clipped(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio with which the Kelvin–Voigt law *without tension* achieves
    exactly ``e``: the inverse of :func:`restitution_kelvin_voigt_clipped` (Schwager &
    Pöschel 2007, Granular Matter 9:465–469), found to round-off by Brent's method (``e``
    falls monotonically with ζ). ``c = 2 ζ sqrt(k m_eff)``.

    This is the default for the Kelvin–Voigt law: the force clipped at zero, so the dashpot
    never pulls the buildings together, and the restitution exactly the target.
    Anagnostopoulos' ζ (:func:`~pounding.contact.restitution.zeta_anagnostopoulos`) is exact for the law whose dashpot
    may pull (``tension = true``); used with the clipped law it gives a larger e (0.675 for
    a target of 0.65).
    """
    return _invert(e, lambda ei: _tabulated(exact_table.ZETA_KELVIN_VOIGT_CLIPPED, ei,
                                            _zeta_kelvin_voigt_clipped))


def _zeta_kelvin_voigt_clipped(ei: float) -> float:
    """:func:`zeta_kelvin_voigt_clipped` of one ``e`` (solved, not tabulated)."""
    from scipy.optimize import brentq

    if ei >= 1.0:
        return 0.0
    hi = 1.0
    while restitution_kelvin_voigt_clipped(hi) > ei:
        hi *= 2.0
    return float(brentq(lambda z: restitution_kelvin_voigt_clipped(z) - ei, 0.0, hi,
                        xtol=1e-300, rtol=8.9e-16, maxiter=200))


def restitution_modified_kelvin_voigt(zeta: ArrayLike) -> FloatArray | float:
    """Exact ``e`` achieved by the modified Kelvin–Voigt law with damping ratio ζ.

    Approach is a damped oscillator from ``δ = 0, δ̇ = v0`` to maximum compression; restitution
    is undamped, so ``e = ω δmax / v0``. With ``θ = arctan(sqrt(1 − ζ²)/ζ)``:

    * ζ < 1: ``e = exp(−ζ θ / sqrt(1 − ζ²))``
    * ζ = 1: ``e = exp(−1)``
    * ζ > 1: ``e = exp(−ζ artanh(sqrt(ζ² − 1)/ζ) / sqrt(ζ² − 1))``, computed as
      ``exp(−ζ arcosh(ζ) / s)`` with ``s = sqrt((ζ − 1)(ζ + 1))`` and
      ``arcosh(ζ) = log1p(ζ − 1 + s)`` (the same number: ``artanh(s/ζ) = ln(ζ + s)`` since
      ``ζ² − s² = 1``); the ``artanh`` form loses digits as ``s/ζ → 1`` (2.7e-14 relative at
      ζ = 25, 7e-9 at ζ = 10⁴, and different on different CPUs), this one keeps them (tests:
      against 40-digit mpmath).

    Derived here (Chopra's free-vibration solutions); the approximate inverse is Mahmoud &
    Jankowski's eq 20 (:func:`~pounding.contact.restitution.zeta_mahmoud`).
    """
    def under(z: FloatArray) -> FloatArray:
        s = np.sqrt(1.0 - z**2)
        return np.where(z == 0.0, 1.0, np.exp(-z * np.arctan2(s, z) / np.where(s > 0, s, 1.0)))

    def over(z: FloatArray) -> FloatArray:
        s = np.sqrt((z - 1.0) * (z + 1.0))
        return np.exp(-z * np.log1p((z - 1.0) + s) / s)

    return _by_damping_regime(zeta, under, math.exp(-1.0), over)


_BERNOULLI_SERIES = (1.0 / 12.0, -1.0 / 720.0, 1.0 / 30240.0, -1.0 / 1209600.0,
                     1.0 / 47900160.0, -691.0 / 1307674368000.0)
"""Coefficients of y², y⁴, … y¹² in ``y / (1 − e^−y) = 1 + y/2 + Σ`` (the Bernoulli numbers
B_2k / (2k)!)."""


def _bernoulli_excess(y: float) -> float:
    """``y / (1 − e^−y) − 1`` to round-off for every y > 0: by its series below y = 0.5
    (where the direct form loses digits to cancellation), directly above."""
    if y < 0.5:
        y2 = y * y
        acc = 0.0
        for c in reversed(_BERNOULLI_SERIES):
            acc = acc * y2 + c
        return 0.5 * y + y2 * acc
    return y / -np.expm1(-y) - 1.0


def restitution_hunt_crossley(chi: ArrayLike) -> FloatArray | float:
    """Exact ``e`` of the Hunt–Crossley law ``F = k δⁿ (1 + χ δ̇/v0)``, any ``n``.

    Dividing the equation of motion by ``δ̇`` and integrating over approach and restitution
    eliminates ``k`` and ``n``: ``χ (1 + e) = ln((1 + χ) / (1 − χ e))`` (Hunt & Crossley
    1975). Lankarani–Nikravesh's ``χ = 3(1 − e²)/4`` is its small-dissipation limit.

    Evaluated stably: with ``y = χ (1 + e)`` the relation reads
    ``y / (1 − e^−y) − 1 = χ``, whose left side is computed without cancellation
    (:func:`_bernoulli_excess`) and grows monotonically from 0; so ``y`` is found to
    round-off by Brent's method and ``e = y/χ − 1``, accurate for any χ (the direct form lost
    ``1 − e`` to cancellation: 9 % wrong at χ = 1e-5). The force never returns to zero before
    the bodies separate (``1 − χ e > 0`` always), so ``e < 1/χ``.
    """
    from scipy.optimize import brentq

    x = np.atleast_1d(np.asarray(chi, dtype=float))
    bad = ~np.isfinite(x) | (x < 0.0)
    if np.any(bad):
        raise ValueError(f"chi must be finite and >= 0 (got {x[bad][0]})")
    out = np.empty_like(x)
    for i, c in enumerate(x):
        if c == 0.0:
            out[i] = 1.0
            continue
        # χ < y < 2χ + 2: the excess is below y and above y/2
        y = brentq(lambda yy, c=c: _bernoulli_excess(yy) - c, c, 2.0 * c + 2.0,
                   xtol=1e-300, rtol=8.9e-16, maxiter=200)
        out[i] = y / c - 1.0
    return float(out[0]) if np.ndim(chi) == 0 else out


def restitution_nonlinear_viscoelastic(zeta: float) -> float:
    """Exact ``e`` of Jankowski's nonlinear viscoelastic law (seed eqs 17–18) for impact
    damping ratio ζ, from the approach alone.

    The law damps only while approaching (``c = 2 ζ sqrt(k_h sqrt(δ) m_eff)``) and is
    elastic while restoring, so the restitution returns all the energy stored at maximum
    compression: ``e = sqrt(0.8 x_max^2.5)`` in the variables ``δ = δ* x``, ``t = (δ*/v0) s``,
    ``δ* = (m_eff v0² / k_h)^0.4``, where the approach is ``x'' = −x^1.5 − 2 ζ x^0.25 x'``
    from ``x = 0, x' = 1`` to ``x' = 0`` — so e depends on ζ alone (Jankowski 2006, EESD
    35(4):517–524, who fitted eq 19 to it). Solved here with SciPy's DOP853 at rtol 1e-12;
    the full two-body collision (:func:`pounding.contact.collision.simulate_collision`)
    agrees to 1e-10 (tests).
    """
    from scipy.integrate import solve_ivp

    z = float(zeta)
    if not (math.isfinite(z) and z >= 0.0):
        raise ValueError(f"zeta must be finite and >= 0 (got {zeta!r})")

    def rhs(_s: float, y: NDArray[np.float64]) -> list[float]:
        x = max(y[0], 0.0)
        return [y[1], -x**1.5 - 2.0 * z * x**0.25 * y[1]]

    def at_max(_s: float, y: NDArray[np.float64]) -> float:
        return y[1]

    at_max.terminal = True  # type: ignore[attr-defined]
    at_max.direction = -1.0  # type: ignore[attr-defined]
    sol = solve_ivp(rhs, (0.0, 1e4), [0.0, 1.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=at_max)
    x_max = float(sol.y_events[0][0][0])
    return math.sqrt(0.8 * x_max**2.5)


# --------------------------------------------------------------------------- exact inverses
def _invert(e: ArrayLike, one: Callable[[float], float]) -> FloatArray | float:
    """``one(e)`` elementwise over a checked ``e`` (0 < e ≤ 1), scalar in, scalar out."""
    x = np.atleast_1d(_check_e(e)).astype(float)
    out = np.array([one(float(ei)) for ei in x.ravel()]).reshape(x.shape)
    return float(out.ravel()[0]) if np.ndim(e) == 0 else out


def _tabulated(table: Mapping[float, float], e: float, solve: Callable[[float], float]
               ) -> float:
    """The value of ``e`` in ``table`` (:mod:`pounding.contact.exact_table`), or
    ``solve(e)`` for an ``e`` it does not hold."""
    value = table.get(e)
    return solve(e) if value is None else value


def _brent_decreasing(fun: Callable[[float], FloatArray | float], target: float, hi: float,
                      xtol: float = 1e-300) -> float:
    """The x ≥ 0 with ``fun(x) = target`` for ``fun`` falling from ``fun(0) = 1``:
    ``hi`` doubled until it brackets, then Brent's method to round-off."""
    from scipy.optimize import brentq

    while float(fun(hi)) > target:
        hi *= 2.0
    return float(brentq(lambda z: float(fun(z)) - target, 0.0, hi, xtol=xtol, rtol=8.9e-16,
                        maxiter=200))


def zeta_modified_kelvin_voigt_exact(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio with which the modified Kelvin–Voigt law achieves exactly ``e``:
    the inverse of :func:`restitution_modified_kelvin_voigt` (Brent's method to round-off;
    ``e`` falls monotonically with ζ). ``c = 2 ζ sqrt(k m_eff)``.

    The default of the modified Kelvin–Voigt law. Mahmoud & Jankowski's eq 20
    (:func:`~pounding.contact.restitution.zeta_mahmoud`) approximates it (0.6538 achieved for
    a target of 0.65).
    """
    return _invert(e, lambda ei: _tabulated(exact_table.ZETA_MODIFIED_KELVIN_VOIGT, ei,
                                            _zeta_modified_kelvin_voigt_exact))


def _zeta_modified_kelvin_voigt_exact(ei: float) -> float:
    """:func:`zeta_modified_kelvin_voigt_exact` of one ``e`` (solved, not tabulated)."""
    return 0.0 if ei >= 1.0 else _brent_decreasing(restitution_modified_kelvin_voigt, ei, 1.0)


def chi_hunt_crossley_exact(e: ArrayLike) -> FloatArray | float:
    """Damping factor χ with which the Hunt–Crossley law ``F = k δⁿ (1 + χ δ̇/v0)`` achieves
    exactly ``e``, any ``n``: the inverse of :func:`restitution_hunt_crossley`, i.e. the root
    of ``χ (1 + e) = ln((1 + χ) / (1 − χ e))`` (Brent's method to round-off).

    The default of the Hunt–Crossley family (``hunt-crossley``, ``hertzdamp``). The
    published closed forms approximate it: Lankarani & Nikravesh's ``3(1 − e²)/4`` is its
    limit for e → 1 (it gives 0.775 for a target of 0.65), Flores' and Gonthier's are
    within a few hundredths.
    """
    return _invert(e, lambda ei: _tabulated(exact_table.CHI_HUNT_CROSSLEY, ei,
                                            _chi_hunt_crossley_exact))


def _chi_hunt_crossley_exact(ei: float) -> float:
    """:func:`chi_hunt_crossley_exact` of one ``e`` (solved, not tabulated)."""
    if ei >= 1.0:
        return 0.0
    # 3(1 − e²)/4 is within a factor of 3 of it: a bracket to start from
    return _brent_decreasing(restitution_hunt_crossley, ei, max(1.0 - ei * ei, 1e-300))


def _zeta_nonlinear_viscoelastic_exact(e: float) -> float:
    """:func:`zeta_nonlinear_viscoelastic_exact` of one ``e`` (solved: neither tabulated nor
    remembered)."""
    from scipy.optimize import brentq

    if e >= 1.0:
        return 0.0
    # Jankowski's eq 19 (restitution.zeta_jankowski) is within a few per cent of it:
    # bracket about it
    guess = 4.5 * math.sqrt(5.0) * (1.0 - e * e) / (e * (e * (9.0 * math.pi - 16.0) + 16.0))
    lo, hi = 0.5 * guess, 2.0 * guess
    while restitution_nonlinear_viscoelastic(hi) > e:
        lo, hi = hi, hi * 2.0
    while lo > 0.0 and restitution_nonlinear_viscoelastic(lo) < e:
        lo, hi = 0.0 if lo < 1e-12 else lo / 4.0, lo
    return float(brentq(lambda z: restitution_nonlinear_viscoelastic(z) - e, lo, hi,
                        xtol=1e-14, rtol=1e-13, maxiter=100))


def zeta_nonlinear_viscoelastic_exact(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio with which Jankowski's nonlinear viscoelastic law (seed eqs
    17–18) achieves exactly ``e``: the inverse of :func:`restitution_nonlinear_viscoelastic`
    (Brent's method on the one-dimensional approach, to 1e-13 relative in ζ).

    The default of the ``nonlinear-viscoelastic`` law. Jankowski's eq 19
    (:func:`~pounding.contact.restitution.zeta_jankowski`) is a fit to it (0.6470 achieved
    for a target of 0.65). Each ``e`` costs about a dozen integrations of the approach
    (≈ 0.1 s); its ζ is remembered (:data:`EXACT_ZETA_NONLINEAR_VISCOELASTIC`), so a sweep
    or a model with many contacts of one ``e`` pays once. An ``e`` of two decimals is
    tabulated (:mod:`pounding.contact.exact_table`) and costs nothing.
    """
    return _invert(e, lambda ei: _tabulated(
        exact_table.ZETA_NONLINEAR_VISCOELASTIC, ei,
        lambda ej: EXACT_ZETA_NONLINEAR_VISCOELASTIC.get(
            ej, lambda: _zeta_nonlinear_viscoelastic_exact(ej))))


EXACT_ZETA_NONLINEAR_VISCOELASTIC = Memo(max_items=1024)
"""ζ of :func:`zeta_nonlinear_viscoelastic_exact`, keyed by ``e``."""


# --------------------------------------------------------------------------- the table
TABULATED_E: tuple[float, ...] = tuple(k / 100 for k in range(1, 100))
"""The ``e`` of :mod:`pounding.contact.exact_table`: 0.01, 0.02, … 0.99 (each the double
nearest to its two decimals, as a model file's ``e = 0.65`` reads)."""

_SOLVERS: dict[str, Callable[[float], float]] = {
    "ZETA_KELVIN_VOIGT_CLIPPED": _zeta_kelvin_voigt_clipped,
    "ZETA_MODIFIED_KELVIN_VOIGT": _zeta_modified_kelvin_voigt_exact,
    "CHI_HUNT_CROSSLEY": _chi_hunt_crossley_exact,
    "ZETA_NONLINEAR_VISCOELASTIC": _zeta_nonlinear_viscoelastic_exact,
}
"""The table's names and the solver that makes each."""


def table_source() -> str:
    """The source of :mod:`pounding.contact.exact_table`, solved afresh (each value by the
    solver of its inverse at each of :data:`TABULATED_E`; about 5 s). Regenerate the module
    with ``python -c "from pounding.contact.exact_restitution import table_source;
    print(table_source(), end='')" > src/pounding/contact/exact_table.py``."""
    header = ('"""The exact inverses of :mod:`pounding.contact.exact_restitution` at e = 0.01, '
              "0.02, …\n0.99, as its solvers give them (made by\n"
              ":func:`pounding.contact.exact_restitution.table_source`; "
              "``tests/contact/test_exact_table.py``\nsolves them again). A model file's "
              "``e`` of two decimals reads its damping from here,\nwithout loading SciPy's "
              'root finder and integrator."""')
    lines = [*header.split("\n"), "",
             "from __future__ import annotations"]
    for name, solve in _SOLVERS.items():
        lines += ["", f"{name}: dict[float, float] = {{"]
        lines += [f"    {e!r}: {solve(e)!r}," for e in TABULATED_E]
        lines += ["}"]
    return "\n".join(lines) + "\n"
