"""The state a run starts from: checked initial displacements and velocities, yielding
storeys loaded to them, the first row of every history and of the peaks table; and the
peaks at the end."""

from __future__ import annotations

import numpy as np

from pounding.hysteresis.dispatch import storey_recoverable as _recoverable
from pounding.integrate.kernel_model import KernelModel
from pounding.integrate.layout import EL_FOLDED, EL_LEVER, EL_ROCK, PK_COLUMNS
from pounding.integrate.workspace import KernelOutputs
from pounding.model import PoundingModel


def initial_state(model: PoundingModel, u0: np.ndarray | None,
                  v0: np.ndarray | None) -> np.ndarray:
    """State ``[u, u̇]`` at t = 0, checked: right length, finite, every gap open.

    (Yielding storeys start unloaded at these drifts: see :func:`initial_storeys`.)"""
    n = model.n_dof
    x = np.zeros(2 * n)
    for name, val, sl in (("initial_displacement", u0, slice(0, n)),
                          ("initial_velocity", v0, slice(n, 2 * n))):
        if val is not None:
            arr = np.asarray(val, dtype=float)
            if arr.shape != (n,) or not np.all(np.isfinite(arr)):
                raise ValueError(f"{name}: need {n} finite values, one per floor (got {val!r})")
            x[sl] = arr
    for c, d in zip(model.contacts, model.contact_penetration(x[:n])):
        if d > 0.0:
            raise ValueError(f"initial_displacement: contact {c.label} starts closed "
                             f"(penetration {d:g} m); start with every gap open")
    return x


def initial_storeys(km: KernelModel, u0: np.ndarray,
                    v0: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Committed ``(drift, shear)`` of every yielding storey and link at t = 0, and their
    ``z`` (the element rows of the model's :class:`KernelModel`).

    A storey given an initial drift is taken as loaded monotonically to it from rest (its
    law followed from zero), so a drift beyond yield starts on the yield branch. A link
    starts with its force at the initial displacement and velocity, a Maxwell link with its
    spring unstretched (``z = 0``).
    """
    from pounding.devices.laws import DEVICE_MIN
    from pounding.hysteresis.dispatch import drive_path, storey_trial

    el = km.elements
    lo, hi, code, par, zi = el.lo, el.hi, el.code, el.params, el.z_index
    state = np.zeros((lo.size, 2))
    z = np.zeros(int(np.sum(zi >= 0)))
    v = np.zeros_like(u0) if v0 is None else v0
    for s in range(lo.size):
        d = u0[hi[s]] - (u0[lo[s]] if lo[s] >= 0 else 0.0)
        if par[s, EL_ROCK] >= 0.0:  # a storey over a rocking footing
            d -= par[s, EL_LEVER] * u0[int(par[s, EL_ROCK])]
        if code[s] >= DEVICE_MIN:
            rate = v[hi[s]] - v[lo[s]]
            state[s] = (d, storey_trial(int(code[s]), par, s, d, rate, 0.0, d, 0.0)[0])
            continue
        if d != 0.0:
            v, zz = drive_path(int(code[s]), par[s: s + 1], np.array([0.0, d]), 200)
            state[s] = (d, v[-1])
            if zi[s] >= 0:
                z[zi[s]] = zz[-1]
    return state, z


def write_initial_row(model: PoundingModel, km: KernelModel, x: np.ndarray,
                      sstate: np.ndarray, out: KernelOutputs, at_rest: bool) -> None:
    """Row 0 of the histories ``out``: the state at t = 0 (the kernel writes the rows after
    it)."""
    u_out, v_out, acc_out, pen_out, e_out = out.u, out.v, out.acc, out.pen, out.energy
    vs_out = out.element_force
    el, m_diag = km.elements, km.floors.m_diag
    n, ns = km.n, el.lo.size
    e_out[0] = 0.0
    vs_out[0] = sstate[:, 1]
    if at_rest:
        u_out[0] = 0.0
        v_out[0] = 0.0
        acc_out[0] = 0.0
        pen_out[0] = 0.0 - km.contacts.gap  # (+0.0, not −0.0, for a zero gap)
        return
    u, v = x[:n], x[n:2 * n]
    u_out[0] = u
    v_out[0] = v
    pen_out[0] = model.contact_penetration(u[:model.n_dof])  # (ground stations: at rest)
    storey_force = np.zeros(n)
    applied = el.params[:, EL_FOLDED] == 0.0  # (the linear links folded into K and C are there)
    np.add.at(storey_force, el.hi[applied], sstate[applied, 1])
    lower = (el.lo >= 0) & applied
    np.add.at(storey_force, el.lo[lower], -sstate[lower, 1])
    rocking = el.params[:, EL_ROCK] >= 0.0  # the storeys' moments on rocking footings
    np.add.at(storey_force, el.params[rocking, EL_ROCK].astype(np.int64),
              -el.params[rocking, EL_LEVER] * sstate[rocking, 1])
    acc_out[0] = -(km.K @ u + km.C @ v + storey_force) / m_diag
    e_out[0, 1] = 0.5 * v @ (m_diag * v)
    e_out[0, 2] = 0.5 * u @ km.K @ u + sum(
        _recoverable(int(el.code[s]), el.params, s, sstate[s, 0],
                     x[2 * n + el.z_index[s]] if el.z_index[s] >= 0 else 0.0, sstate[s, 1])
        for s in range(ns) if applied[s])


def initial_peaks(u0: np.ndarray, a0: np.ndarray, below: np.ndarray) -> np.ndarray:
    """The peaks table at t = 0: every floor's |u|, |drift| and |absolute acceleration|."""
    pk = np.zeros((u0.size, PK_COLUMNS))
    pk[:, 0] = np.abs(u0)
    lower = np.where(below >= 0, u0[np.maximum(below, 0)], 0.0)
    pk[:, 2] = np.abs(u0 - lower)
    pk[:, 4] = np.abs(a0)
    return pk


def final_peaks(pk: np.ndarray, u: np.ndarray, a: np.ndarray, below: np.ndarray,
                 t: float) -> None:
    """Compare the values at the end of the run with the peaks (the kernel examines only
    steps in which a rate changes sign: pounding.integrate.peaks)."""
    lower = np.where(below >= 0, u[np.maximum(below, 0)], 0.0)
    for col, v in ((0, np.abs(u)), (2, np.abs(u - lower)), (4, np.abs(a))):
        more = v > pk[:, col]
        pk[more, col] = v[more]
        pk[more, col + 1] = t
