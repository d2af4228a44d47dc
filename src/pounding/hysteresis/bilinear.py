"""Bilinear storey with kinematic hardening (OpenSees ``Steel01`` without isotropic
hardening; Chopra, *Dynamics of Structures*, §7.1 for the elastic–perfectly-plastic case).

The shear moves with slope ``k`` inside a band of width ``2(1 − b)F_y`` that slides along the
hardening line ``b k d``:

    V_trial = V_c + k (d − d_c)                         (elastic predictor)
    V = min(max(V_trial, b k d − (1 − b) F_y), b k d + (1 − b) F_y)   (return to the band)

so the skeleton is ``±F_y`` at ``±F_y/k`` followed by slope ``b k``, unloading is elastic
with ``k``, and the Bauschinger effect of kinematic hardening (reverse yield after a
``2F_y`` change in shear) follows. ``b = 0`` is elastic–perfectly plastic.
"""

from __future__ import annotations

from dataclasses import dataclass

from numba import njit

from pounding.hysteresis.base import BILINEAR, StoreyLaw


@njit(cache=True, inline="always", error_model="numpy")
def bilinear_trial(k, fy, b, p3, p4, p5, d, rate, z, d_c, v_c):
    """Trial shear of the bilinear storey (contract step 3): ``(V, ∂V/∂d, ż = 0)``."""
    v = v_c + k * (d - d_c)
    hard = b * k * d
    band = (1.0 - b) * fy
    if v > hard + band:
        return hard + band, b * k, 0.0
    if v < hard - band:
        return hard - band, b * k, 0.0
    return v, k, 0.0


@dataclass(frozen=True)
class Bilinear(StoreyLaw):
    """Bilinear storey with kinematic hardening.

    Parameters
    ----------
    yield_force : float or sequence, optional
        Storey yield shear ``F_y`` [N] (one value, or one per storey).
    yield_drift : float or sequence, optional
        Yield drift ``F_y / k`` [m] instead of ``yield_force``.
    hardening : float
        Post-yield stiffness ratio ``b`` (0 ≤ b < 1): slope ``b k`` after yield.

    Examples
    --------
    >>> from pounding.hysteresis import Bilinear, respond_drift_path
    >>> law = Bilinear(yield_force=1e5, hardening=0.05)
    >>> [round(v) for v in respond_drift_path(law, 1e7, [0.0, 0.005, 0.02, 0.0])]
    [0, 50000, 105000, -95000]
    """

    hardening: float = 0.0

    code = BILINEAR
    label = "bilinear"

    def _check(self) -> None:
        b = float(self.hardening)
        if not (0.0 <= b < 1.0):
            raise ValueError(f"hardening: the post-yield stiffness ratio must be in [0, 1) "
                             f"(got {self.hardening!r})")
        object.__setattr__(self, "hardening", b)

    def _extra(self) -> tuple[float, ...]:
        return (self.hardening,)

    def _describe(self) -> str:
        return f"{super()._describe()}, hardening={self.hardening!r}"
