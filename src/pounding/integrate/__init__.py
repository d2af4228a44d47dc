"""Time-history simulation of buildings that pound: ``simulate(model, motion)``.

Problem (:class:`pounding.model.PoundingModel`), excitation
(:class:`pounding.ground_motion.GroundMotion`) and solver options are separate; the solver
is the one compiled kernel of :mod:`pounding.integrate.kernel`; the answer is a
:class:`pounding.result.Result`. The slow SciPy reference used to verify it is
:func:`pounding.integrate.reference.simulate_reference`.
"""

from __future__ import annotations

import math
import os
import sys
import time
import warnings
import weakref
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from pounding.contact.base import STATE_SIZE
from pounding.ground_motion import GroundMotion
from pounding.hysteresis.dispatch import storey_recoverable as _recoverable
from pounding.integrate.kernel import integrate_chunk
from pounding.integrate.kernel_cache import KERNEL_MODULES, invalidate_if_stale
from pounding.integrate.layout import (
    ENERGY_COLUMNS,
    FAIL_BUDGET,
    I_FAIL_STEP,
    I_FAILED,
    I_NEVENTS,
    I_NIMP,
    I_NREJECT,
    I_NSTEPS,
    I_ONSET_C,
    I_OVERFLOW,
    I_STEP_BUDGET,
    IMP_COLUMNS,
    PK_COLUMNS,
    W_ERR_OLD,
    W_H,
    W_PEAK_MARGIN,
    WS_F_SIZE,
    WS_I_SIZE,
)
from pounding.integrate.propagator import FreeStep, free_step
from pounding.model import PoundingModel
from pounding.result import Result, SolverStats
from pounding.validation import positive

__all__ = ["simulate", "grid_step", "DEFAULT_RTOL", "IntegrationError"]

invalidate_if_stale([sys.modules[name] for name in KERNEL_MODULES])


class IntegrationError(ValueError):
    """A run that cannot be integrated: the adaptive step fell below 10⁻¹⁴ of the grid
    step, or the run used up its budget of adaptive steps. The message names the time, the
    contacts closed then, and what to check. (A ``ValueError``: it comes from input the
    solver cannot resolve — masses, stiffnesses or damping far outside a building's range —
    and the command line reports it in one line with exit status 2.)"""


def default_step_budget(n_grid: int) -> int:
    """Most adaptive steps a run may take: 100 a grid step, and at least 10⁵.

    Measured needs (2026-11-24): 0.04–0.11 a grid step for the pounding examples (El Centro,
    1 ms), about 1–3 for yielding storeys stepped adaptively throughout. A run that needs
    more is resolving a contact millions of times faster than the building moves (a
    contact far too stiff, or damped far beyond critical, for the floor masses): it would
    take hours, so it is stopped and reported instead.
    """
    return 100 * n_grid + 100_000

DEFAULT_RTOL: float = 1e-8
"""Default relative tolerance of the RK steps taken through contacts."""

DEFAULT_OUTPUT_STEP: float = 1e-3
"""Default largest output (grid) step [s]."""


EXACT_FREE_MAX_DOF: int = 400
"""``free_stepping="auto"`` uses the exact propagator up to this many floors in all.

Measured on 2 cores (shear pair of ``benchmarks/bench_opensees.py``, El Centro 20 s, gap
0.02 m; ``free_stepping="exact"`` against ``"rk"``): 100 floors 0.14 s against 0.22 s,
300 floors 1.2 s against 1.5 s, 500 floors 2.7 s against 6.1 s. Exact stepping was the
faster at every size tried; the limit bounds its O(N²) products and (2N)² memory for
models far beyond that.
"""


def half_bandwidth(*mats: np.ndarray) -> int:
    """Largest ``|i − j|`` with a non-zero entry in any of the matrices."""
    bw = 0
    for a in mats:
        i, j = np.nonzero(a)
        if i.size:
            bw = max(bw, int(np.max(np.abs(i - j))))
    return bw


def band_storage(a: np.ndarray, bw: int) -> np.ndarray:
    """``(2 bw + 1, N)`` band storage of a square matrix: ``out[d, i] = a[i, i + d − bw]``
    (zero outside the matrix), the layout the kernel's O(N·bw) products read."""
    n = a.shape[0]
    out = np.zeros((2 * bw + 1, n))
    for d in range(2 * bw + 1):
        off = d - bw
        i = np.arange(max(0, -off), min(n, n - off))
        out[d, i] = a[i, i + off]
    return out


def choose_free_stepping(mode: str, n_dof: int, bw: int) -> bool:
    """True to step contact-free intervals with the exact propagator (see :func:`simulate`)."""
    from pounding.validation import choice

    mode = choice("free_stepping", mode, ("auto", "exact", "rk"))
    if mode == "auto":
        return n_dof <= EXACT_FREE_MAX_DOF
    return mode == "exact"


HISTORY_MEMORY_FRACTION: float = 0.5
"""A run whose histories would take more than this fraction of the machine's memory is
refused before anything is allocated."""


def history_bytes(model: PoundingModel, nt: int) -> int:
    """Bytes of the histories a run of ``nt`` output times writes: displacement, velocity,
    acceleration of every floor, penetration and force of every contact, shear of every
    yielding storey, seven energies and the ground acceleration, 8 bytes each."""
    n, nc = model.n_dof, len(model.contacts)
    ns = len(model.yielding_storeys)
    return 8 * nt * (3 * n + 2 * nc + ns + ENERGY_COLUMNS + 1)


def physical_memory() -> int:
    """This machine's physical memory [bytes] (8 GiB if the system does not say)."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):
        return 8 * 2**30


def check_history_size(model: PoundingModel, t_end: float, step: float) -> None:
    """Refuse, before allocating, a run whose histories would not fit in memory
    (:data:`HISTORY_MEMORY_FRACTION` of it): one line naming the output step and duration
    and what it would take."""
    nt = t_end / step + 1.0
    need = 8.0 * nt * (history_bytes(model, 1) / 8.0)
    have = physical_memory()
    if need > HISTORY_MEMORY_FRACTION * have:
        raise ValueError(
            f"solver: {t_end:g} s at an output step of {step:g} s is {nt:.3g} output times; "
            f"the histories would take {need / 2**30:.3g} GiB (this machine has "
            f"{have / 2**30:.3g} GiB): use a larger dt (the accuracy does not depend on it) "
            "or a shorter duration")


def grid_step(record_dt: float, dt: float | None = None) -> float:
    """The grid step actually used: the largest ``record_dt / m`` (m integer) ≤ ``dt``.

    The ground acceleration is then exactly linear on every grid step, which the exact
    propagator between impacts requires.
    """
    want = DEFAULT_OUTPUT_STEP if dt is None else positive("dt", dt)
    m = max(1, math.ceil(record_dt / want - 1e-9))
    return record_dt / m


def ground_on_grid(motion: GroundMotion, dt: float, t_end: float) -> np.ndarray:
    """Ground acceleration [m/s²] at ``k·dt`` for k = 0 … ⌈t_end/dt⌉.

    The record is linear between its samples; after its last sample it returns linearly to
    zero over one record step and stays there — a rule that does not depend on ``dt``.
    """
    nt = int(math.ceil(t_end / dt - 1e-9)) + 1
    if nt < 2:
        raise ValueError(f"duration: {t_end:g} s is shorter than one output step ({dt:g} s)")
    t = np.arange(nt) * dt
    t_rec = np.append(motion.time, motion.time[-1] + motion.dt)
    a_rec = np.append(motion.accel, 0.0)
    return np.interp(t, t_rec, a_rec, right=0.0)


_GRID_MEMO: "weakref.WeakKeyDictionary[GroundMotion, dict[tuple[float, float], np.ndarray]]" = (
    weakref.WeakKeyDictionary())


def _ground_on_grid_memo(motion: GroundMotion, dt: float, t_end: float) -> np.ndarray:
    """:func:`ground_on_grid`, remembered per record (records are read-only) for a few
    (step, duration) pairs: repeated runs and sweeps on one record interpolate it once.
    The array is read-only."""
    per = _GRID_MEMO.setdefault(motion, {})
    key = (float(dt), float(t_end))
    ag = per.get(key)
    if ag is None:
        ag = ground_on_grid(motion, dt, t_end)
        ag.setflags(write=False)
        if len(per) >= 8:
            per.clear()
        per[key] = ag
    return ag


class KernelModel(NamedTuple):
    """A :class:`~pounding.model.PoundingModel` as the kernel reads it: every array
    :func:`simulate` passes that depends on the model alone (see
    :func:`pounding.integrate.kernel.integrate_chunk` for their meaning).

    Assembled once per model by :func:`kernel_model` and reused by every later run of it, so
    a repeated run (a record sweep, a benchmark) pays only for its own outputs. The kernel
    only reads these arrays; they are left writeable because numba compiles a separate
    signature for read-only ones. Do not modify them.
    """

    n: int  #: floors (degrees of freedom)
    nz: int  #: internal variables of the yielding storeys (Bouc–Wen z)
    bw: int  #: half-bandwidth of K and C
    K: np.ndarray  #: stiffness of the linear storeys [N/m], (N, N)
    k_band: np.ndarray  #: K in band storage
    c_band: np.ndarray  #: C [N·s/m] in band storage
    m_diag: np.ndarray  #: lumped floor masses [kg]
    mr: np.ndarray  #: M r [kg]
    r: np.ndarray  #: influence vector
    cdof: np.ndarray  #: contact DOFs (n_c, 4)
    cw: np.ndarray  #: contact weights (n_c, 4)
    cgap: np.ndarray  #: gaps [m]
    ccode: np.ndarray  #: contact-law codes
    cparams: np.ndarray  #: contact-law constants
    s_lo: np.ndarray  #: yielding storeys: DOF below (−1 ground)
    s_hi: np.ndarray  #: yielding storeys: DOF above
    s_code: np.ndarray  #: storey-law codes
    s_par: np.ndarray  #: storey-law constants
    s_zi: np.ndarray  #: index of each storey's z (−1 none)
    below: np.ndarray  #: DOF of the floor below each floor (−1: the ground)
    free_steps: dict[float, FreeStep]  #: exact grid steps already built, by step [s]


_KERNEL_MODELS: dict[int, KernelModel] = {}


def _read_only_free_step(fs: FreeStep) -> FreeStep:
    for a in fs:
        a.setflags(write=False)
    return fs


_NO_FREE_STEP = _read_only_free_step(FreeStep(np.array([0, 1], dtype=np.int64), np.zeros((2, 4)),
                                              np.zeros(2), np.zeros(2), np.zeros(3)))
"""The exact-step arguments of an RK-stepped run, which the kernel never reads: read-only
like a real :class:`FreeStep`'s arrays, so that numba compiles the kernel for one signature
only (not a second one, 37–56 s on 2 cores, for yielding or very large models)."""


def kernel_model(model: PoundingModel) -> KernelModel:
    """The model's :class:`KernelModel`, assembled on its first run and remembered until the
    model is garbage-collected (models are frozen; they hold NumPy arrays, so they are
    remembered by identity, not by value)."""
    key = id(model)
    km = _KERNEL_MODELS.get(key)
    if km is None:
        km = _assemble_kernel_model(model)
        try:
            # the entry must go when the model does (before its id can be reused)
            weakref.finalize(model, _KERNEL_MODELS.pop, key, None)
        except TypeError:
            return km  # a model that cannot be weakly referenced is not remembered
        _KERNEL_MODELS[key] = km
    return km


def _assemble_kernel_model(model: PoundingModel) -> KernelModel:
    sys_ = model.system
    M, C, r = sys_.M, sys_.C, sys_.r
    K = model.linear_stiffness()
    m_diag = np.diag(M).copy()
    if np.any(M != np.diag(m_diag)):
        raise ValueError("model: the mass matrix must be diagonal (lumped floor masses)")
    bw = half_bandwidth(K, C)
    s_lo, s_hi, s_code, s_par, s_zi = model.storey_arrays()
    cdof, cw, cgap, ccode, cparams = model.contact_arrays()
    return KernelModel(n=r.size, nz=int(np.sum(s_zi >= 0)), bw=bw, K=K,
                       k_band=band_storage(K, bw), c_band=band_storage(C, bw), m_diag=m_diag,
                       mr=np.ascontiguousarray(M @ r), r=np.ascontiguousarray(r, dtype=float),
                       cdof=cdof, cw=cw, cgap=cgap, ccode=ccode,
                       cparams=np.ascontiguousarray(cparams), s_lo=s_lo, s_hi=s_hi,
                       s_code=s_code, s_par=np.ascontiguousarray(s_par), s_zi=s_zi,
                       below=floor_below(model), free_steps={})


def floor_below(model: PoundingModel) -> np.ndarray:
    """The DOF of the floor below each floor (−1 for a first floor: the ground), so that
    the drift of storey j is ``u[j] − u[below[j]]``."""
    below = np.arange(model.n_dof, dtype=np.int64) - 1
    for off in model.system.offsets[: len(model.buildings)]:
        below[int(off)] = -1
    return below


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


def initial_storeys(model: PoundingModel, u0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Committed ``(drift, shear)`` of every yielding storey at t = 0, and their ``z``.

    A storey given an initial drift is taken as loaded monotonically to it from rest (its
    law followed from zero), so a drift beyond yield starts on the yield branch.
    """
    from pounding.hysteresis.dispatch import drive_path

    lo, hi, code, par, zi = model.storey_arrays()
    state = np.zeros((lo.size, 2))
    z = np.zeros(int(np.sum(zi >= 0)))
    for s in range(lo.size):
        d = u0[hi[s]] - (u0[lo[s]] if lo[s] >= 0 else 0.0)
        if d != 0.0:
            v, zz = drive_path(int(code[s]), par[s: s + 1], np.array([0.0, d]), 200)
            state[s] = (d, v[-1])
            if zi[s] >= 0:
                z[zi[s]] = zz[-1]
    return state, z


def _write_initial_row(model: PoundingModel, km: KernelModel, x: np.ndarray,
                       sstate: np.ndarray, u_out: np.ndarray, v_out: np.ndarray,
                       acc_out: np.ndarray, pen_out: np.ndarray, vs_out: np.ndarray,
                       e_out: np.ndarray, at_rest: bool) -> None:
    """Row 0 of the histories: the state at t = 0 (the kernel writes the rows after it)."""
    n, ns = km.n, km.s_lo.size
    e_out[0] = 0.0
    vs_out[0] = sstate[:, 1]
    if at_rest:
        u_out[0] = 0.0
        v_out[0] = 0.0
        acc_out[0] = 0.0
        pen_out[0] = 0.0 - km.cgap  # (+0.0, not −0.0, for a zero gap)
        return
    u, v = x[:n], x[n:2 * n]
    u_out[0] = u
    v_out[0] = v
    pen_out[0] = model.contact_penetration(u)
    storey_force = np.zeros(n)
    np.add.at(storey_force, km.s_hi, sstate[:, 1])
    lower = km.s_lo >= 0
    np.add.at(storey_force, km.s_lo[lower], -sstate[lower, 1])
    acc_out[0] = -(km.K @ u + model.system.C @ v + storey_force) / km.m_diag
    e_out[0, 1] = 0.5 * v @ (km.m_diag * v)
    e_out[0, 2] = 0.5 * u @ km.K @ u + sum(
        _recoverable(int(km.s_code[s]), km.s_par, s, sstate[s, 0],
                     x[2 * n + km.s_zi[s]] if km.s_zi[s] >= 0 else 0.0, sstate[s, 1])
        for s in range(ns))


def simulate(model: PoundingModel, motion: GroundMotion, *, dt: float | None = None,
             duration: float | None = None, rtol: float = DEFAULT_RTOL,
             h_max: float | None = None, impact_capacity: int | None = None,
             initial_displacement: np.ndarray | None = None,
             initial_velocity: np.ndarray | None = None,
             free_stepping: str = "auto", max_rk_steps: int | None = None,
             progress: Callable[[float], None] | None = None) -> Result:
    """Simulate the model under a ground motion.

    Parameters
    ----------
    model : PoundingModel
        Buildings, gaps, contact law.
    motion : GroundMotion
        Ground acceleration [m/s²], linear between its samples.
    dt : float, optional
        Output (grid) step [s]; rounded down to a divisor of the record step
        (:func:`grid_step`). Default 1 ms. Accuracy does not depend on it: steps without
        contact are exact and contacts are sub-stepped adaptively.
    duration : float, optional
        Time simulated [s]; default the record's duration (after it, free vibration).
    rtol : float
        Relative tolerance of the adaptive steps through contacts.
    h_max : float, optional
        Largest adaptive step [s] (default: the grid step).
    impact_capacity : int, optional
        Rows reserved for the impact table (default generous; overflow is reported).
    initial_displacement, initial_velocity : ndarray (N,), optional
        Floor displacements [m] and velocities [m/s] at t = 0 relative to the ground
        (default at rest). Every gap must be open at t = 0.
    free_stepping : {"auto", "exact", "rk"}
        How steps without contact are taken: ``"exact"`` propagator (O(N²) a step, exact),
        adaptive ``"rk"`` (O(N·bandwidth) a step), or ``"auto"``: exact up to
        ``EXACT_FREE_MAX_DOF`` (400) floors in all, where it was measured the faster, RK
        beyond. A model with yielding storeys is not linear between impacts, so it is always
        stepped by RK (``"exact"`` is refused).
    max_rk_steps : int, optional
        Most adaptive steps the run may take (default :func:`default_step_budget`: 100 a
        grid step); a run that needs more stops with an :class:`IntegrationError`.
    progress : callable, optional
        Called with the fraction done (0 … 1) after each chunk of steps.

    Returns
    -------
    Result

    Raises
    ------
    IntegrationError
        The run cannot be integrated (step-size underflow, or the step budget used up); one
        line says when, at which contacts, and what to check.
    """
    step = grid_step(motion.dt, dt)
    t_end = motion.duration if duration is None else positive("duration", duration)
    check_history_size(model, t_end, step)
    rtol = positive("rtol", rtol)
    h_max = step if h_max is None else positive("h_max", h_max)
    ag = _ground_on_grid_memo(motion, step, t_end)
    nt = ag.size
    km = kernel_model(model)
    n, nz, bw = km.n, km.nz, km.bw
    ns = km.s_lo.size
    if ns and free_stepping == "exact":
        raise ValueError("free_stepping: 'exact' needs linear storeys; this model has "
                         "yielding storeys (use 'auto' or 'rk')")
    exact = choose_free_stepping(free_stepping, n, bw) and ns == 0
    if exact:
        fs = km.free_steps.get(step)
        if fs is None:
            sys_ = model.system
            fs = km.free_steps[step] = free_step(sys_.M, sys_.C, km.K, sys_.r, step)
    else:
        fs = _NO_FREE_STEP
    nc = km.cgap.size
    # absolute tolerances: displacement scale from the gaps and the record, velocity from PGV
    u_scale = max(float(km.cgap.min()) if nc else 0.0, 1e-3)
    v_scale = max(motion.pgv, 1e-3)
    atol = np.empty(2 * n + nz)
    atol[:n] = rtol * 1e-3 * u_scale
    atol[n:2 * n] = rtol * 1e-3 * v_scale
    atol[2 * n:] = rtol * 1e-3  # z is dimensionless, |z| ≲ 1

    at_rest = initial_displacement is None and initial_velocity is None
    if at_rest:
        # (every gap is open: the model's gaps are ≥ 0; storeys unloaded, z = 0)
        x = np.zeros(2 * n + nz)
        sstate = np.zeros((ns, 2))
    else:
        x0 = initial_state(model, initial_displacement, initial_velocity)
        sstate, z0 = initial_storeys(model, x0[:n])
        x = np.concatenate([x0, z0])
    committed = np.zeros((max(nc, 1), STATE_SIZE))[:nc]
    wc = np.zeros(nc)
    w_start = np.zeros(nc)
    imp_row = np.full(nc, -1, dtype=np.int64)
    last_f = np.zeros((nc, 5))
    ws_f = np.zeros(WS_F_SIZE)
    ws_f[W_ERR_OLD] = 1e-4
    ws_f[W_H] = step * 0.1
    ws_f[W_PEAK_MARGIN] = peak_margin(km, step)
    ws_i = np.zeros(WS_I_SIZE, dtype=np.int64)
    ws_i[0] = 0 if exact else 1  # I_MODE: 0 exact stepping, 1 adaptive RK
    ws_i[I_ONSET_C] = -1
    ws_i[I_STEP_BUDGET] = (default_step_budget(nt) if max_rk_steps is None
                           else int(positive("max_rk_steps", max_rk_steps)))
    cap = impact_capacity or max(1000, 20 * nc * int(t_end) + 1000)
    # The kernel writes every row after the first of these, so they are not zeroed first
    # (zeroing ~5 MB costs as much as a tenth of an SDOF pair's run when the memory is
    # reused); f_out is: exact steps leave its zero rows untouched.
    u_out = np.empty((nt, n))
    v_out = np.empty((nt, n))
    acc_out = np.empty((nt, n))
    pen_out = np.empty((nt, nc))
    f_out = np.zeros((nt, nc))
    vs_out = np.empty((nt, ns))
    e_out = np.empty((nt, ENERGY_COLUMNS))
    imp = np.full((cap, IMP_COLUMNS), np.nan)
    cpeak = np.zeros(nc)
    cpeak_t = np.zeros(nc)
    ccount = np.zeros(nc, dtype=np.int64)
    _write_initial_row(model, km, x, sstate, u_out, v_out, acc_out, pen_out, vs_out, e_out,
                       at_rest)

    chunk = max(1000, (nt - 1) // 50) if progress is not None else nt
    pk = _initial_peaks(u_out[0], acc_out[0], km.below)
    args = (step, ag, exact, fs.blk, fs.ops, fs.gamma0, fs.gamma1, fs.aa, bw, km.k_band,
            km.c_band, km.m_diag, km.mr, km.r, km.cdof, km.cw, km.cgap, km.ccode, km.cparams,
            km.s_lo, km.s_hi, km.s_code, km.s_par, km.s_zi, km.below, rtol, atol, h_max, x,
            committed, sstate, wc, w_start, imp_row, last_f, ws_f, ws_i, u_out, v_out, acc_out,
            pen_out, f_out, vs_out, e_out, imp, cpeak, cpeak_t, ccount, pk,
            *kernel_scratch(km, x.size))
    # An empty chunk first: the process's first call loads the compiled kernel from numba's
    # cache (~0.3 s), which is not integrating and is kept out of stats.wall_time (a few µs
    # once loaded).
    integrate_chunk(0, 0, *args)
    start = time.perf_counter()
    for k0 in range(0, nt - 1, chunk):
        k1 = min(nt - 1, k0 + chunk)
        integrate_chunk(k0, k1, *args)
        if ws_i[I_FAILED]:
            raise IntegrationError(_failure_text(model, ws_i, committed, step, rtol))
        if progress is not None:
            progress(k1 / (nt - 1))
    wall = time.perf_counter() - start
    _final_peaks(pk, u_out[-1], acc_out[-1], km.below, (nt - 1) * step)
    n_imp = int(ws_i[I_NIMP])
    if n_imp > cap:
        warnings.warn(f"impact table full: {n_imp} impacts, {cap} rows kept (raise "
                      f"impact_capacity); peak forces and counts per contact are complete",
                      RuntimeWarning, stacklevel=2)
    stats = SolverStats(solver="kernel", rtol=rtol, rk_steps=int(ws_i[I_NSTEPS]),
                        rejected=int(ws_i[I_NREJECT]), events=int(ws_i[I_NEVENTS]),
                        impact_overflow=bool(ws_i[I_OVERFLOW] == 1), wall_time=wall)
    return Result(model=model, motion=motion, dt=step, ground=ag,
                  displacement=u_out, velocity=v_out, abs_acceleration=acc_out,
                  penetration=pen_out, contact_force=f_out, energy=e_out,
                  yielding_shear=vs_out, final_z=x[2 * n:].copy(),
                  impact_array=imp[: min(n_imp, cap)].copy(), stats=stats,
                  contact_peak=cpeak, contact_peak_time=cpeak_t, contact_impacts=ccount,
                  located_peaks=pk)


def peak_margin(km: KernelModel, step: float) -> float:
    """How much larger (relative) an acceleration peak between two samples an exact step
    apart can be than the larger sample: 4 (ω_max h)²/8, with ω_max² bounded by the largest
    Gershgorin row sum of M⁻¹K (a sinusoid at ω sampled every h misses its crest by at most
    (ω h)²/8; the factor 4 covers what a bound on the modes and the ground's linear pieces
    leave). Floors whose sampled peak is further below their peak so far are not searched
    between samples: no peak there can beat it."""
    w2 = float(np.max(np.sum(np.abs(km.K), axis=1) / km.m_diag)) if km.n else 0.0
    return min(1.0, 0.5 * w2 * step * step)


def kernel_scratch(km: KernelModel, m: int) -> tuple[np.ndarray, ...]:
    """The kernel's scratch arrays for a model (see
    :func:`pounding.integrate.kernel.integrate_chunk`), ``m`` the length of the state."""
    n, nc = km.n, km.cgap.size
    npw = 3 + nc
    stages = np.zeros((2, 7, m))
    powers = np.zeros((2, 7, npw))
    states = np.zeros((4, m))
    gaps = np.zeros((4, nc))
    floors = np.zeros((6, n))
    return (stages[0], powers[0], stages[1], powers[1], np.zeros((1, m)), np.zeros((1, npw)),
            *states, np.zeros(2 * m + 4), np.zeros((2, n)), np.zeros(2 * n), *gaps, *floors,
            1.0 / km.m_diag)


def _initial_peaks(u0: np.ndarray, a0: np.ndarray, below: np.ndarray) -> np.ndarray:
    """The peaks table at t = 0: every floor's |u|, |drift| and |absolute acceleration|."""
    pk = np.zeros((u0.size, PK_COLUMNS))
    pk[:, 0] = np.abs(u0)
    lower = np.where(below >= 0, u0[np.maximum(below, 0)], 0.0)
    pk[:, 2] = np.abs(u0 - lower)
    pk[:, 4] = np.abs(a0)
    return pk


def _final_peaks(pk: np.ndarray, u: np.ndarray, a: np.ndarray, below: np.ndarray,
                 t: float) -> None:
    """Compare the values at the end of the run with the peaks (the kernel examines only
    steps in which a rate changes sign: pounding.integrate.peaks)."""
    lower = np.where(below >= 0, u[np.maximum(below, 0)], 0.0)
    for col, v in ((0, np.abs(u)), (2, np.abs(u - lower)), (4, np.abs(a))):
        more = v > pk[:, col]
        pk[more, col] = v[more]
        pk[more, col + 1] = t


def _failure_text(model: PoundingModel, ws_i: np.ndarray, committed: np.ndarray, step: float,
                  rtol: float) -> str:
    """One line: why and when the integration stopped, the contacts closed then, and what
    to check."""
    t = int(ws_i[I_FAIL_STEP]) * step
    closed = [c.label for c, st in zip(model.contacts, committed) if st[0] > 0.0]
    where = (f" with contact {', '.join(closed[:4])}{' …' if len(closed) > 4 else ''} closed"
             if closed else "")
    if ws_i[I_FAILED] == FAIL_BUDGET:
        why = (f"solver: stopped after {int(ws_i[I_STEP_BUDGET]):,} adaptive steps at "
               f"t = {t:.4f} s{where}")
    else:
        why = (f"solver: the adaptive step fell below 1e-14 of the {step:g} s output step at "
               f"t = {t:.4f} s{where} (rtol = {rtol:g})")
    return (why + ": the model moves millions of times faster than a building does there; "
            "check the masses, storey and contact stiffnesses and the contact damping "
            "(e.g. e far below 0.1), or raise max_rk_steps")
