"""The output grid of a run: its step, the ground acceleration on it, and whether its
histories fit in memory."""

from __future__ import annotations

import math
import os
import weakref

import numpy as np

from pounding.ground_motion import GroundMotion, GroundMotionComponents
from pounding.integrate.layout import ENERGY_COLUMNS
from pounding.model import PoundingModel
from pounding.validation import positive

DEFAULT_OUTPUT_STEP: float = 1e-3
"""Default largest output (grid) step [s]."""


HISTORY_MEMORY_FRACTION: float = 0.5
"""A run whose histories would take more than this fraction of the machine's memory is
refused before anything is allocated."""


def history_bytes(model: PoundingModel, nt: int) -> int:
    """Bytes of the histories a run of ``nt`` output times writes: displacement, velocity,
    acceleration of every floor, penetration and force of every contact, force of every
    element row (yielding storey, a bridge's pier or bearing), rotation and moment of every
    hinge of a yielding frame, the energies and the ground acceleration (each of its G
    components), 8 bytes each."""
    n, nc = model.n_dof, len(model.contacts)
    ns = len(model.element_rows)
    nh = len(model.hinge_labels())
    r = np.asarray(model.system.r)
    g = 1 if r.ndim == 1 else r.shape[1]
    return 8 * nt * (3 * n + 2 * nc + ns + 2 * nh + ENERGY_COLUMNS + g)


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


def ground_on_grid(motion: GroundMotion | GroundMotionComponents, dt: float,
                   t_end: float) -> np.ndarray:
    """Ground acceleration [m/s²] at ``k·dt`` for k = 0 … ⌈t_end/dt⌉: (nt,) for a
    :class:`GroundMotion`, (nt, G) for :class:`GroundMotionComponents` (each component as
    one record).

    The record is linear between its samples; after its last sample it returns linearly to
    zero over one record step and stays there — a rule that does not depend on ``dt``.
    """
    nt = int(math.ceil(t_end / dt - 1e-9)) + 1
    if nt < 2:
        raise ValueError(f"duration: {t_end:g} s is shorter than one output step ({dt:g} s)")
    if isinstance(motion, GroundMotionComponents):
        return np.ascontiguousarray(np.column_stack(
            [ground_on_grid(c, dt, t_end) for c in motion.components]))
    t = np.arange(nt) * dt
    t_rec = np.append(motion.time, motion.time[-1] + motion.dt)
    a_rec = np.append(motion.accel, 0.0)
    return np.interp(t, t_rec, a_rec, right=0.0)


_GRID_MEMO: "weakref.WeakKeyDictionary[object, dict[tuple[float, float], np.ndarray]]" = (
    weakref.WeakKeyDictionary())


def ground_displacement_on_grid(record: GroundMotion, dt: float, nt: int
                                ) -> tuple[np.ndarray, np.ndarray]:
    """The ground's displacement [m] and velocity [m/s] at ``nt`` grid points ``dt`` apart,
    from rest: the record (as :func:`ground_on_grid` puts it on the grid, linear between
    the points) integrated exactly — as the time stepper integrates a ground station's
    motion (:mod:`pounding.integrate.stations`)."""
    a = ground_on_grid(record, dt, (nt - 1) * dt)[:nt]
    v = np.concatenate([[0.0], np.cumsum(0.5 * dt * (a[:-1] + a[1:]))])
    u = np.concatenate([[0.0], np.cumsum(dt * v[:-1] + dt * dt * (2 * a[:-1] + a[1:]) / 6)])
    return u, v


def n_ground_components(motion: GroundMotion | GroundMotionComponents) -> int:
    """G of a motion: 1 for a :class:`GroundMotion`."""
    return motion.n_components if isinstance(motion, GroundMotionComponents) else 1


def check_ground_components(model: PoundingModel,
                            motion: GroundMotion | GroundMotionComponents) -> None:
    """One line if the motion's components do not match the columns of the model's
    influence matrix R (an (N,) influence vector is one column)."""
    r = np.asarray(model.system.r)
    n_r = 1 if r.ndim == 1 else r.shape[1]
    n_m = n_ground_components(motion)
    if n_m != n_r:
        raise ValueError(f"motion: {n_m} ground component{'s' if n_m != 1 else ''} for a "
                         f"model whose influence matrix R has {n_r} column"
                         f"{'s' if n_r != 1 else ''} (one component per column)")


def ground_on_grid_memo(motion: GroundMotion | GroundMotionComponents, dt: float,
                        t_end: float) -> np.ndarray:
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
