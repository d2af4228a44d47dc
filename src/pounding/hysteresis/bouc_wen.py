"""Bouc–Wen storey (Bouc 1967; Wen 1976, J. Eng. Mech. Div. ASCE 102(2):249–263), in the
normalised form of Ismail, Ikhouane & Rodellar (2009), Arch. Comput. Methods Eng.
16:161–188, eqs (1)–(2):

    V = α k d + (1 − α) F_y z
    ż = (1 / d_y) [ A ḋ − β |ḋ| |z|^(n−1) z − γ ḋ |z|^n ],   d_y = F_y / k

with ``A = 1`` (A, β, γ and F_y are redundant: fixing A loses nothing; Ma, Zhang & Xu 2004).
``z`` is dimensionless; the caller integrates it with the motion (contract step 4).

Closed-form limits (used by the tests):

* initial stiffness ``∂V/∂d = k`` at ``z = 0``;
* on monotonic loading ``z → z_u = (1/(β + γ))^(1/n)``, so the skeleton tends to the
  straight lines ``V = α k d ± (1 − α) F_y z_u`` (= ``α k d ± (1 − α) F_y`` for the usual
  ``β + γ = 1``);
* the tangent on loading is ``k [α + (1 − α)(1 − (β + γ)|z|^n)]`` and on unloading
  ``k [α + (1 − α)(1 − (γ − β)|z|^n)]`` (``= k`` for ``β = γ``).

Recoverable energy (contract step 5): ``½ α k d² + ½ (1 − α) F_y d_y z²``.
"""

from __future__ import annotations

from dataclasses import dataclass

from numba import njit

from pounding.hysteresis.base import BOUC_WEN, P_K, StoreyLaw


@njit(cache=True, inline="always", error_model="numpy")
def bouc_wen_trial(k, fy, alpha, n, beta, gamma, d, rate, z, d_c, v_c):
    """Shear, tangent and ``ż`` of the Bouc–Wen storey: ``(V, ∂V/∂d, ż)``."""
    dy = fy / k
    az = abs(z)
    zn = az if n == 1.0 else az ** n
    s = rate * z
    psi = gamma + beta if s > 0.0 else (gamma - beta if s < 0.0 else gamma)
    dz_dd = (1.0 - zn * psi) / dy
    return alpha * k * d + (1.0 - alpha) * fy * z, alpha * k + (1.0 - alpha) * fy * dz_dd, \
        rate * dz_dd


@dataclass(frozen=True)
class BoucWen(StoreyLaw):
    """Smooth hysteretic storey of Bouc and Wen.

    Parameters
    ----------
    yield_force, yield_drift : float or sequence
        Give one: ``F_y`` [N] or ``d_y = F_y / k`` [m] (one value, or one per storey).
    alpha : float
        Post-yield stiffness ratio (0 ≤ α < 1).
    n : float
        Smoothness of the elastic–plastic transition (≥ 1; large n approaches bilinear).
    beta, gamma : float
        Loop shape; ``β + γ > 0`` bounds ``z``. The usual choice β = γ = 0.5 unloads with the
        initial stiffness and saturates at ``|z| = 1``.

    Examples
    --------
    >>> from pounding.hysteresis import BoucWen, respond_drift_path
    >>> law = BoucWen(yield_force=1e5, alpha=0.05, n=2.0)
    >>> import numpy as np
    >>> v = respond_drift_path(law, 1e7, np.linspace(0.0, 0.1, 2001))
    >>> round(float(v[-1] - 0.05 * 1e7 * 0.1), 1)   # → (1 − α) F_y
    95000.0
    """

    alpha: float = 0.05
    n: float = 1.0
    beta: float = 0.5
    gamma: float = 0.5

    code = BOUC_WEN
    label = "Bouc-Wen"

    def _check(self) -> None:
        for name, lo in (("alpha", 0.0), ("n", 1.0)):
            v = float(getattr(self, name))
            if not (v >= lo) or (name == "alpha" and v >= 1.0) or v != v or v == float("inf"):
                raise ValueError(f"{name}: must be in "
                                 f"{'[0, 1)' if name == 'alpha' else '[1, inf)'} "
                                 f"(got {getattr(self, name)!r})")
            object.__setattr__(self, name, v)
        b, g = float(self.beta), float(self.gamma)
        if not (b == b and g == g) or b + g <= 0.0 or abs(b) == float("inf") \
                or abs(g) == float("inf"):
            raise ValueError(f"beta, gamma: need finite values with beta + gamma > 0 so z "
                             f"stays bounded (got beta={self.beta!r}, gamma={self.gamma!r})")
        if g - b > b + g:
            raise ValueError(f"beta: must be >= 0 (got {self.beta!r})")
        object.__setattr__(self, "beta", b)
        object.__setattr__(self, "gamma", g)

    def _extra(self) -> tuple[float, ...]:
        return (self.alpha, self.n, self.beta, self.gamma)

    @property
    def has_internal_variable(self) -> bool:
        return True

    @property
    def z_ultimate(self) -> float:
        """Limit of ``z`` on monotonic loading, ``(1/(β + γ))^(1/n)``."""
        return (1.0 / (self.beta + self.gamma)) ** (1.0 / self.n)

    def unloading_stiffness(self, params, z):  # noqa: D102 (see base)
        k = float(params[P_K])
        return k * (self.alpha + (1.0 - self.alpha)
                    * (1.0 - abs(z) ** self.n * (self.gamma - self.beta)))

    def _describe(self) -> str:
        return (f"{super()._describe()}, alpha={self.alpha!r}, n={self.n!r}, "
                f"beta={self.beta!r}, gamma={self.gamma!r}")
