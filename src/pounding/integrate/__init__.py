"""Time-history simulation of buildings that pound: ``simulate(model, motion)``.

Problem (:class:`pounding.model.PoundingModel`), excitation
(:class:`pounding.ground_motion.GroundMotion`, or
:class:`~pounding.ground_motion.GroundMotionComponents` for a model whose influence matrix R
has several columns) and solver options are separate; the solver
is the one compiled kernel of :mod:`pounding.integrate.kernel`; the answer is a
:class:`pounding.result.Result`. The slow SciPy reference used to verify it is
:func:`pounding.integrate.reference.simulate_reference`.

Around the kernel: the output grid (:mod:`~pounding.integrate.grid`), the model as the
kernel reads it (:mod:`~pounding.integrate.kernel_model`), the starting state
(:mod:`~pounding.integrate.start`), the exact step between impacts
(:mod:`~pounding.integrate.propagator`) and the cache guard
(:mod:`~pounding.integrate.kernel_cache`).
"""

from __future__ import annotations

import contextlib
import sys
import time
import warnings
from collections.abc import Callable, Iterator
from typing import NamedTuple

import numpy as np

from pounding.allocator import keep_freed_memory
from pounding.ground_motion import GroundMotion, GroundMotionComponents
from pounding.ground_motion.spatial import SpatialMotion
from pounding.integrate.failure_text import failure_text, nonfinite_text
from pounding.integrate.grid import (
    DEFAULT_OUTPUT_STEP,
    HISTORY_MEMORY_FRACTION,
    check_ground_components,
    check_history_size,
    grid_step,
    ground_on_grid,
    ground_on_grid_memo,
    history_bytes,
    physical_memory,
)
from pounding.integrate.kernel import integrate_chunk
from pounding.integrate.kernel_cache import (
    COLD_COMPILE_S,
    KERNEL_MODULES,
    cached_here,
    invalidate_if_stale,
)
from pounding.integrate.kernel_model import (
    EXACT_FREE_MAX_DOF,
    NO_FREE_STEP,
    KernelModel,
    band_storage,
    choose_free_stepping,
    exact_stepping,
    floor_below,
    half_bandwidth,
    kernel_model,
    maxwell_exact_rows,
    maxwell_free_step,
    peak_margin,
    remembered_for,
)
from pounding.integrate.layout import (
    I_CALL_STEPS,
    I_FAILED,
    I_NEVENTS,
    I_NIMP,
    I_NREJECT,
    I_NSTEPS,
    I_OVERFLOW,
    I_REACHED,
    I_STOP,
    I_STOP_ROW,
    PK_COLUMNS,
    W_RESUME_S,
)
from pounding.integrate.periods import (
    RK_STABILITY,
    check_building_periods,
    check_contact_periods,
    check_link_periods,
    stiff_frame_rate,
)
from pounding.integrate.propagator import FreeStep, free_step
from pounding.integrate.start import (
    final_peaks,
    initial_peaks,
    initial_state,
    initial_storeys,
    write_initial_row,
)
from pounding.integrate.stations import link_stations, station_kernel_model
from pounding.integrate.workspace import (
    RunInputs,
    kernel_scratch,
    new_outputs,
    new_state,
)
from pounding.model import PoundingModel
from pounding.result import Result, SolverStats
from pounding.validation import positive

__all__ = [
    "CALL_WORK_NS",
    "DEFAULT_OUTPUT_STEP",
    "DEFAULT_RTOL",
    "EXACT_FREE_MAX_DOF",
    "HISTORY_MEMORY_FRACTION",
    "IntegrationError",
    "KernelModel",
    "band_storage",
    "call_sizes",
    "check_building_periods",
    "check_contact_periods",
    "check_ground_components",
    "check_history_size",
    "check_link_periods",
    "choose_free_stepping",
    "default_step_budget",
    "floor_below",
    "grid_step",
    "ground_on_grid",
    "half_bandwidth",
    "history_bytes",
    "initial_state",
    "initial_storeys",
    "kernel_model",
    "kernel_scratch",
    "peak_margin",
    "physical_memory",
    "simulate",
    "solver_compile_seconds",
]

invalidate_if_stale([sys.modules[name] for name in KERNEL_MODULES])


class IntegrationError(ValueError):
    """A run that cannot be integrated: the adaptive step fell below 10⁻¹⁴ of the grid
    step, the run used up its budget of adaptive steps, or the state stopped being finite
    numbers (an overflow: no result is returned with NaN or infinity in it). The message
    names the time, the contacts closed then (or the record's PGA and the fastest DOF), and
    what to check. (A ``ValueError``: it comes from input the
    solver cannot resolve — masses, stiffnesses or damping far outside a building's range —
    and the command line reports it in one line with exit status 2.)"""


SIDESWAY_CHECK_S: float = 0.1
"""How often a run with yielding frames looks for a frame swayed past a storey's height [s
of the record] (between calls of the kernel; :meth:`FrameRun.check_sidesway`)."""

CALL_WORK_NS: float = 1e8
"""Work of one call of the compiled kernel, as :func:`call_sizes` estimates it [ns]. Python
handles a signal (Ctrl-C, SIGTERM turned into an interrupt by the command line) only
between calls, so this bounds how long one is held: 0.1 s estimated; measured 80–110 ms a
call (median) and 0.13–0.18 s at most for 1000 storeys beside an SDOF (RK), 300 + 100
storeys (exact) and a yielding SDOF at h_max = 10 µs, on a loaded 2-core machine
(2026-11-27). A call costs 3–6 µs of its own, so the run is cut into calls at no measurable
cost (a run shorter than this is one call)."""


def call_sizes(km: KernelModel, exact: bool, fs: FreeStep) -> tuple[int, int]:
    """How much of a run one call of the kernel takes: ``(grid steps, RK steps)``, each
    estimated to cost :data:`CALL_WORK_NS`. A call returns at the first grid point after
    either; both are fixed by the model alone, so where a run is cut does not depend on
    the machine's speed (nor does the answer: the kernel's state carries over).

    Estimated costs (2026-11-27, 2 cores under load; measured 0.5–2× these): an exact grid
    step ``0.4 Σ_b (2 n_b + m_b)² + 300 N + 100`` ns for blocks of ``n_b`` floors and
    ``m_b`` linear Maxwell links (whose springs' deformations are in the block's state),
    N floors in all (the propagator's sweep, the outputs and peak tests); an RK step
    ``2000 + 140 N (2 bw + 1) + 100 n_c + 200 n_s`` ns (six right-hand sides of the banded
    K and C of half-bandwidth bw, n_c contacts, n_s yielding storeys and links).
    """
    n, bw, nc, ns = km.n, km.floors.bw, km.contacts.gap.size, km.elements.lo.size
    rk_ns = 2000.0 + 140.0 * n * (2 * bw + 1) + 100.0 * nc + 200.0 * ns
    rk_per_call = max(1, int(CALL_WORK_NS / rk_ns))
    if not exact:
        # every grid step takes an RK step at least: the RK steps bound the call
        return rk_per_call, rk_per_call
    blocks = np.diff(fs.blk) + 0.5 * fs.maxwell[:, 0]  # (2 n_b + m_b: the block's state)
    exact_ns = 0.4 * float(np.sum((2.0 * blocks) ** 2)) + 300.0 * n + 100.0
    return max(1, int(CALL_WORK_NS / exact_ns)), rk_per_call


def default_step_budget(n_grid: int) -> int:
    """Most adaptive steps a run may take: ``100 · n_grid + 100,000`` (100 a grid step, plus 10⁵).

    Measured needs (2026-11-24): 0.04–0.11 a grid step for the pounding examples (El Centro,
    1 ms), about 1–3 for yielding storeys stepped adaptively throughout. A run that needs
    more is resolving a contact millions of times faster than the building moves (a
    contact far too stiff, or damped far beyond critical, for the floor masses): it would
    take hours, so it is stopped and reported instead.
    """
    return 100 * n_grid + 100_000


class _ModelNotes(NamedTuple):
    """What :func:`simulate` found of a model, for its next runs."""

    checked: set[tuple[float, float]]
    """(output step, duration) pairs whose checks the model passed."""
    margin: dict[float, float]
    """The peak margin (:func:`peak_margin`) of each output step."""
    stiff_rate: list[object]
    """The yielding frames' fastest over-damped decay rate and its text
    (:func:`pounding.integrate.periods.stiff_frame_rate`), once found (empty before)."""


_NOTES: dict[int, _ModelNotes] = {}
"""The notes of every model alive, by its identity (an entry goes with its model): the
cases of a sweep that share a model (:mod:`pounding.studies.sweep.builder`) check it once."""


def _model_notes(model: PoundingModel) -> _ModelNotes:
    """The notes of a model (fresh ones, not kept, for a model that cannot be weakly
    referenced)."""
    return remembered_for(model, _NOTES, id(model), lambda: _ModelNotes(set(), {}, []))


_kernel_loaded: list[bool] = []
"""Non-empty once this process has called the compiled kernel (loaded it)."""


def solver_compile_seconds() -> float:
    """Seconds of compiling the next :func:`simulate` in this process will spend first:
    about :data:`~pounding.integrate.kernel_cache.COLD_COMPILE_S` where numba's cache holds
    no compiled kernel for this machine (a fresh install, an empty ``NUMBA_CACHE_DIR``, a
    kernel source changed), else 0 (loaded already, or loads from the cache). Reads numba's
    cache index only (:func:`~pounding.integrate.kernel_cache.cached_here`)."""
    if _kernel_loaded or cached_here(integrate_chunk):
        return 0.0
    return COLD_COMPILE_S

DEFAULT_RTOL: float = 1e-8
"""Default relative tolerance of the RK steps taken through contacts."""


@contextlib.contextmanager
def _blas_threads(limit: int | None) -> Iterator[None]:
    """Limit the BLAS library's threads to ``limit`` inside (None: no limit), as
    ``threadpoolctl.threadpool_limits`` does."""
    if limit is None:
        yield
        return
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=limit, user_api="blas"):
        yield


def simulate(model: PoundingModel, motion: GroundMotion | GroundMotionComponents, *,
             dt: float | None = None, duration: float | None = None, rtol: float = DEFAULT_RTOL,
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
    motion : GroundMotion or GroundMotionComponents
        Ground acceleration [m/s²], linear between its samples: one record for a model
        whose influence ``system.r`` is a vector (N,), or one record per column of an
        influence matrix (N, G), in the order of the columns (the equations are
        ``M ü + C u̇ + K u + … = −M R a_g(t)``).
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
        beyond (and beyond ``EXACT_LINKED_BLOCK_MAX`` (120) floors tied by linear links).
        Linear links without internal variable (Kelvin, a dashpot with α = 1) are part of
        the linear structure stepped exactly, as are linear Maxwell links (α = 1; their
        springs' deformations in the exact step's state, under one ground component), and
        slack cable restrainers exert no force there; a model with yielding storeys or
        other links between buildings is always stepped by RK (``"exact"`` is refused).
    max_rk_steps : int, optional
        Most adaptive steps the run may take (default :func:`default_step_budget`: 100 a
        grid step plus 10⁵); a run that needs more stops with an :class:`IntegrationError`.
    progress : callable, optional
        Called with the fraction done (0 … 1) after each chunk of steps. With or without it
        the run is cut into calls of the compiled kernel of about 0.1 s each
        (:func:`call_sizes`), so Ctrl-C takes effect within about a second.

    Returns
    -------
    Result

    Raises
    ------
    ValueError
        Input the solver refuses before the run, in one line naming it: among others a
        building, contact or link that moves millions of times faster than the output step
        (:mod:`pounding.integrate.periods`).
    IntegrationError
        The run cannot be integrated (step-size underflow, the step budget used up, or the
        state overflowing to numbers that are not finite); one line says when, at which
        contacts, and what to check (for an overflow: the record's PGA and the stiffness,
        mass and damping of the fastest DOF).
    """
    keep_freed_memory()  # once per process: outputs reuse what the last run freed
    check_ground_components(model, motion)
    step = grid_step(motion.dt, dt)
    t_end = motion.duration if duration is None else positive("duration", duration)
    notes = _model_notes(model)
    # spatially varying ground: each building on its station's ground (one station: the
    # plain model under that record)
    stations, station_records, wall_stations = _stations(model, motion)
    km = (kernel_model(model) if stations is None
          else station_kernel_model(model, stations, wall_stations))
    n_model = model.n_dof
    if (step, t_end) not in notes.checked:
        check_history_size(model, t_end, step)
        if step not in km.periods_checked:  # (the buildings' and links': once for a sweep)
            check_building_periods(model, step)
            check_link_periods(model, step)
            km.periods_checked.add(step)
        check_contact_periods(model, step)
        notes.checked.add((step, t_end))
    rtol = positive("rtol", rtol)
    h_max = step if h_max is None else positive("h_max", h_max)
    ground = ground_on_grid_memo(motion, step, t_end)  # (nt,) or (nt, G)
    nt = ground.shape[0]
    ag = ground.reshape(nt, -1)  # (nt, G), read-only like ground
    if stations is not None:
        ag = np.ascontiguousarray(np.column_stack(
            [ground_on_grid_memo(rec, step, t_end) for rec in station_records]))
        ag.flags.writeable = False  # (read-only like one record's: one compiled kernel)
    if km.floors.r.shape[1] != ag.shape[1]:  # (checked above; the kernel reads ag[k, g]
        raise ValueError(f"motion: {ag.shape[1]} ground components for "  # unchecked)
                         f"{km.floors.r.shape[1]}")
    n, nz = km.n, km.nz
    fl, ct, el = km.floors, km.contacts, km.elements
    ns = el.lo.size
    yielding_frames = bool(model.yielding_frames)
    exact = exact_stepping(km, free_stepping, yielding_frames)
    if exact:
        fs = km.free_steps.get(step)
        if fs is None:
            with warnings.catch_warnings():  # (an overflow is said below, in one line)
                warnings.simplefilter("ignore", RuntimeWarning)
                fs = (free_step(np.diag(fl.m_diag), km.C, km.K, fl.r, step, km.C_links)
                      if maxwell_exact_rows(km) is None else maxwell_free_step(km, step))
            if not all(np.all(np.isfinite(a)) for a in (fs.ops, fs.gamma0, fs.gamma1, fs.aa)):
                raise IntegrationError(nonfinite_text(model, motion, None, step))
            km.free_steps[step] = fs
    else:
        fs = NO_FREE_STEP
    nc = ct.gap.size
    # absolute tolerances: displacement scale from the gaps and the record, velocity from PGV
    u_scale = max(float(ct.gap.min()) if nc else 0.0, 1e-3)
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
        if stations is not None:  # (the grounds start at rest, where they are)
            x0 = np.concatenate([x0[:n_model], np.zeros(n - n_model), x0[n_model:],
                                 np.zeros(n - n_model)])
        sstate, z0 = initial_storeys(km, x0[:n], x0[n:])
        x = np.concatenate([x0, z0])
    margin = notes.margin.get(step)
    if margin is None:
        margin = notes.margin[step] = peak_margin(km, step)
    budget = (default_step_budget(nt) if max_rk_steps is None
              else int(positive("max_rk_steps", max_rk_steps)))
    if yielding_frames:
        # (a mode a yielding frame's damping over-damps holds its explicit steps short:
        # refused before the run where even stable steps would overrun the budget)
        rate = notes.stiff_rate
        if not rate:
            rate[:] = stiff_frame_rate(model)
        least = t_end * float(rate[0]) / RK_STABILITY  # type: ignore[arg-type]
        if least > budget:
            raise IntegrationError(
                f"solver: a yielding frame's damping over-damps a stiff mode{rate[1]}; the run "
                f"would take at least {least:,.0f} adaptive steps, beyond its budget of "
                f"{budget:,} (max_rk_steps)")
    st = new_state(km, x, sstate, step, margin, exact, budget)
    ws_i = st.ws_i
    cap = impact_capacity or max(1000, 20 * nc * int(t_end) + 1000)
    arrays = km.arrays
    frames = None
    if yielding_frames:
        from pounding.integrate.frame_run import FrameRun

        frames = FrameRun(model, km, atol)
        moving = np.flatnonzero(np.any(ag != 0.0, axis=1))
        frames.start(x, ag[0], ag[moving[0]] if moving.size else ag[0])
        arrays = frames.arrays
    out = new_outputs(km, nt, cap, np.empty((n, PK_COLUMNS)),
                      frames.n_hinges if frames is not None else 0)
    write_initial_row(model, km, x, sstate, out, at_rest)
    if frames is not None:
        frames.initial_row(x, out.hinge_rotation[0], out.hinge_moment[0])
    out.peaks[:] = initial_peaks(out.u[0], out.acc[0], fl.below)

    # the run in calls of bounded work, so that Ctrl-C and SIGTERM (which Python handles
    # only between calls) take effect within a fraction of a second, whatever the model
    grid_per_call, rk_per_call = call_sizes(km, exact, fs)
    if progress is not None:
        grid_per_call = min(grid_per_call, max(1000, (nt - 1) // 50))
    if frames is not None:
        # a frame that has lost its strength sways away exponentially: look every
        # SIDESWAY_CHECK_S of the record (FrameRun.check_sidesway)
        grid_per_call = min(grid_per_call, max(1, int(SIDESWAY_CHECK_S / step)))
    scratch = kernel_scratch(km, x.size)
    args = (RunInputs(step, ag, exact, rtol, atol, h_max), arrays, fs, st, out, scratch)
    # An empty chunk first, in a process that has not loaded the compiled kernel yet: that
    # call loads it from numba's cache (~0.3 s), which is not integrating and is kept out of
    # stats.wall_time.
    if not _kernel_loaded:
        ws_i[I_CALL_STEPS] = 0
        integrate_chunk(0, 0, *args)
        _kernel_loaded.append(True)
    start = time.perf_counter()
    k0 = 0
    # (a yielding frame's events do small dense products between the kernel's calls,
    # which a multithreaded BLAS runs slower on a busy machine: one thread there)
    with _blas_threads(1 if frames is not None else None):
        while k0 < nt - 1:
            ws_i[I_CALL_STEPS] = ws_i[I_NSTEPS] + rk_per_call
            integrate_chunk(k0, min(nt - 1, k0 + grid_per_call), *args)
            if ws_i[I_FAILED]:
                raise IntegrationError(failure_text(model, km, motion, ws_i, st.committed, step,
                                                     rtol))
            k0 = int(ws_i[I_REACHED])
            if frames is not None:
                frames.check_sidesway(st.x, k0 * step)
            if ws_i[I_STOP]:
                # a hinge event: the frame's next configuration, then on from the same instant
                ws_i[I_STOP] = 0
                assert frames is not None
                frames.on_event(st.x, scratch.kx[0], k0 * step + st.ws_f[W_RESUME_S],
                                int(ws_i[I_STOP_ROW]))
            elif progress is not None:
                progress(k0 / (nt - 1))
    wall = time.perf_counter() - start
    hinges = frames.finish(st.x, (nt - 1) * step, out.hinge_rotation, out.u) if frames else None
    pk = out.peaks
    final_peaks(pk, out.u[-1], out.acc[-1], fl.below, (nt - 1) * step)
    n_imp = int(ws_i[I_NIMP])
    if n_imp > cap:
        warnings.warn(f"impact table full: {n_imp} impacts, {cap} rows kept (raise "
                      f"impact_capacity); peak forces and counts per contact are complete",
                      RuntimeWarning, stacklevel=2)
    stats = SolverStats(solver="kernel", rtol=rtol, rk_steps=int(ws_i[I_NSTEPS]),
                        rejected=int(ws_i[I_NREJECT]), events=int(ws_i[I_NEVENTS]),
                        impact_overflow=bool(ws_i[I_OVERFLOW] == 1), wall_time=wall)
    n_storey_rows = len(model.element_rows)
    u_out, v_out, acc_out = out.u, out.v, out.acc
    link_ground = None
    ground_motion = None
    wall_motion: dict[str, np.ndarray] = {}
    if stations is not None:  # (the buildings' DOFs; the grounds' are not reported)
        u_out, v_out, acc_out = (np.ascontiguousarray(a[:, :n_model])
                                 for a in (out.u, out.v, out.acc))
        pk = np.ascontiguousarray(pk[:n_model])
        # each building's ground and each wall's on its own, as the kernel stepped them
        ground_motion = np.stack([out.u[:, n_model + np.array(stations)],
                                  out.v[:, n_model + np.array(stations)]])
        wall_motion = {side: np.stack([out.u[:, n_model + s], out.v[:, n_model + s]])
                       for side, s in wall_stations}
        crossing = link_stations(model, stations)
        if crossing:  # (each link's grounds' offset: the DOFs after the stations)
            link_ground = np.zeros((2, out.u.shape[0], len(model.links)))
            first = n - len(crossing)
            for q, (i, _, _) in enumerate(crossing):
                link_ground[0, :, i] = out.u[:, first + q]
                link_ground[1, :, i] = out.v[:, first + q]
    return Result(model=model, motion=motion, dt=step, ground=ground,
                  displacement=u_out, velocity=v_out, abs_acceleration=acc_out,
                  penetration=out.pen, contact_force=out.force, energy=out.energy,
                  yielding_shear=out.element_force[:, :n_storey_rows],
                  link_force=out.element_force[:, n_storey_rows:], final_z=x[2 * n:].copy(),
                  link_ground=link_ground, building_ground=ground_motion,
                  wall_ground=wall_motion or None,
                  impact_array=out.impacts[: min(n_imp, cap)].copy(), stats=stats,
                  contact_peak=out.peak_force, contact_peak_time=out.peak_force_time,
                  contact_impacts=out.impact_count, located_peaks=pk,
                  hinge_rotation=out.hinge_rotation if frames else None,
                  hinge_moment=out.hinge_moment if frames else None,
                  hinge_peak_rotation=hinges.peak_rotation if hinges else None,
                  hinge_peak_rotation_time=hinges.peak_rotation_time if hinges else None,
                  hinge_residual_rotation=hinges.residual_rotation if hinges else None,
                  hinge_dissipated=hinges.dissipated if hinges else None,
                  frame_residual_displacement=hinges.residual_floors if hinges else None,
                  member_end_moment=hinges.member_end_moment if hinges else None,
                  hinge_capped=hinges.capped if hinges else None,
                  frame_restoring_force=hinges.restoring if hinges else None)


def _stations(model: PoundingModel, motion: GroundMotion | GroundMotionComponents
              ) -> tuple[tuple[int, ...] | None, list[GroundMotion], tuple[tuple[str, int], ...]]:
    """The station of each building, the stations' records and the walls' own stations
    ((side, station) pairs) under a :class:`~pounding.ground_motion.spatial.SpatialMotion`
    with more than one distinct record (:mod:`pounding.integrate.stations`);
    ``(None, [], ())`` otherwise."""
    if not isinstance(motion, SpatialMotion):
        return None, [], ()
    index, records = motion.stations()
    if len(index) != len(model.buildings):
        raise ValueError(f"motion: a spatially varying motion needs one record per building "
                         f"({len(model.buildings)}; got {len(index)})")
    if len(records) == 1:
        return None, [], ()
    return tuple(index), records, tuple(motion.wall_stations().items())
