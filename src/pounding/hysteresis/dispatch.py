"""The one compiled entry point to every storey law (like :mod:`pounding.contact.dispatch`).

:func:`storey_trial` switches on the law code; the time-history kernel calls it for every
yielding storey at every stage, and :func:`respond_drift_path` drives it along a drift
history (cyclic push tests, plots). One implementation of each law; a code no branch
implements gives NaN (no law stands in for an unknown one), and :func:`check_storey_law`
refuses such a law in Python, in one line naming its class and code.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from pounding.devices.laws import DEVICE_MIN, device_stored, device_trial
from pounding.hysteresis.base import (
    BILINEAR,
    BOUC_WEN,
    ELASTIC,
    P_FY,
    P_K,
    STATE_SIZE,
    StoreyLaw,
)
from pounding.hysteresis.bilinear import bilinear_trial
from pounding.hysteresis.bouc_wen import bouc_wen_trial

STOREY_LAW_CODES: dict[int, str] = {ELASTIC: "elastic", BILINEAR: "bilinear",
                                    BOUC_WEN: "Bouc-Wen"}
"""The storey-law codes :func:`storey_trial` implements (links between buildings have
theirs from :data:`pounding.devices.laws.DEVICE_MIN` up)."""


def check_storey_law(law: object) -> None:
    """Refuse a storey law whose code the compiled dispatcher does not implement: a
    ``ValueError`` naming the law's class and code."""
    code = getattr(law, "code", None)
    if not isinstance(code, (int, np.integer)) or int(code) not in STOREY_LAW_CODES:
        known = ", ".join(f"{k} {name}" for k, name in STOREY_LAW_CODES.items())
        raise ValueError(f"storey law {type(law).__name__} has code {code}, which no compiled "
                         f"storey law implements (codes: {known}); a new law needs its own "
                         "code and branch")


@njit(cache=True, inline="always", error_model="numpy")
def storey_trial(code, sp, s, d, rate, z, d_c, v_c):
    """Trial of storey ``s`` (constants ``sp[s]``, law ``code``): ``(V, ∂V/∂d, ż)``.

    Code 0 (elastic) returns ``(k d, k, 0)``. Codes from ``DEVICE_MIN`` up are the links
    between buildings (:mod:`pounding.devices.laws`), which use the same element rows. Any
    other code returns NaN.
    """
    if code >= DEVICE_MIN:
        return device_trial(code, sp[s, 0], sp[s, 1], sp[s, 2], sp[s, 3], d, rate, z)
    if code == BILINEAR:
        return bilinear_trial(sp[s, 0], sp[s, 1], sp[s, 2], sp[s, 3], sp[s, 4], sp[s, 5],
                              d, rate, z, d_c, v_c)
    if code == BOUC_WEN:
        return bouc_wen_trial(sp[s, 0], sp[s, 1], sp[s, 2], sp[s, 3], sp[s, 4], sp[s, 5],
                              d, rate, z, d_c, v_c)
    if code == ELASTIC:
        return sp[s, 0] * d, sp[s, 0], 0.0
    return np.nan, np.nan, np.nan


@njit(cache=True, inline="always", error_model="numpy")
def storey_recoverable(code, sp, s, d, z, v):
    """Elastic energy [J] storey ``s`` gives back when unloaded to zero shear (contract 5)."""
    if code >= DEVICE_MIN:
        return device_stored(code, sp[s, 0], sp[s, 1], sp[s, 2], sp[s, 3], d, z)
    k = sp[s, 0]
    if code == BILINEAR:
        return 0.5 * v * v / k
    if code == BOUC_WEN:
        alpha = sp[s, 2]
        fy = sp[s, 1]
        return 0.5 * alpha * k * d * d + 0.5 * (1.0 - alpha) * fy * (fy / k) * z * z
    if code == ELASTIC:
        return 0.5 * k * d * d
    return np.nan


@njit(cache=True, error_model="numpy")
def drive_path(code, sp, drift, substeps):
    """Shear along a drift path, committing at every sample; ``z`` of Bouc–Wen integrated
    in drift (rate-independent: ``dz/dd = ż/ḋ``) by classical RK4 with ``substeps`` steps per
    sample interval."""
    n = drift.shape[0]
    v_out = np.zeros(n)
    z_out = np.zeros(n)
    d_c = 0.0
    v_c = 0.0
    z = 0.0
    for i in range(n):
        d = drift[i]
        if i > 0:
            dd = d - drift[i - 1]
            sgn = 1.0 if dd > 0.0 else (-1.0 if dd < 0.0 else 0.0)
            h = dd / substeps
            dprev = drift[i - 1]
            # dz/dd = ż / ḋ: evaluate ż at a unit rate of the increment's sign, times that sign
            for q in range(substeps):
                d0 = dprev + q * h
                k1 = sgn * storey_trial(code, sp, 0, d0, sgn, z, d_c, v_c)[2]
                k2 = sgn * storey_trial(code, sp, 0, d0 + 0.5 * h, sgn, z + 0.5 * h * k1,
                                        d_c, v_c)[2]
                k3 = sgn * storey_trial(code, sp, 0, d0 + 0.5 * h, sgn, z + 0.5 * h * k2,
                                        d_c, v_c)[2]
                k4 = sgn * storey_trial(code, sp, 0, d0 + h, sgn, z + h * k3, d_c, v_c)[2]
                z += h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0
        v = storey_trial(code, sp, 0, d, 0.0, z, d_c, v_c)[0]
        v_out[i] = v
        z_out[i] = z
        d_c = d
        v_c = v
    return v_out, z_out


def respond_drift_path(law: StoreyLaw | None, stiffness: float, drift: ArrayLike,
                       substeps: int = 200) -> NDArray[np.float64]:
    """Storey shear [N] along a drift history [m] (a cyclic push test), starting unloaded.

    Parameters
    ----------
    law : StoreyLaw or None
        The storey law (None: linear elastic).
    stiffness : float
        Elastic storey stiffness ``k`` [N/m].
    drift : array_like, shape (n,)
        Drift at successive samples [m]; between samples it is taken to move linearly.
    substeps : int
        RK4 steps per sample interval for laws with an internal variable (Bouc–Wen).

    Returns
    -------
    numpy.ndarray, shape (n,)
    """
    d = np.ascontiguousarray(drift, dtype=float)
    if d.ndim != 1 or not np.all(np.isfinite(d)):
        raise ValueError("drift: need a 1-D array of finite values [m]")
    k = float(stiffness)
    if not (math.isfinite(k) and k > 0.0):
        raise ValueError(f"stiffness: must be finite and > 0 (got {stiffness!r})")
    if law is None:
        return k * d
    check_storey_law(law)
    sp = law.params(np.array([k]))
    v, _ = drive_path(law.code, sp, d, int(substeps))
    return v


__all__ = [
    "P_FY",
    "P_K",
    "STATE_SIZE",
    "STOREY_LAW_CODES",
    "check_storey_law",
    "drive_path",
    "respond_drift_path",
    "storey_recoverable",
    "storey_trial",
]
