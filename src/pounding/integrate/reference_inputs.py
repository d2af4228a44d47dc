"""The SciPy reference's own reading of a run's inputs: the output grid, the ground
acceleration between record samples, the starting state and the floor below each floor.

Written here from the physics, apart from the compiled kernel's helpers
(:mod:`pounding.integrate.grid`, :mod:`pounding.integrate.start`,
:mod:`pounding.integrate.kernel_model`), so that a kernel-versus-reference test also checks
those: a record is linear between its samples (each component along its column of the
influence matrix R), and after its last sample it returns linearly to zero over one record
step and stays there; outputs are at multiples of the largest divisor of the record step
not above the output step asked for.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from pounding.ground_motion import GroundMotion, GroundMotionComponents
from pounding.model import PoundingModel
from pounding.structure.assembly import floor_dofs

DEFAULT_STEP: float = 1e-3
"""Output step [s] when none is asked for (as :func:`pounding.integrate.simulate`)."""


def records(motion: GroundMotion | GroundMotionComponents) -> list[GroundMotion]:
    """The motion's records, one per ground component."""
    if isinstance(motion, GroundMotionComponents):
        return list(motion.components)
    return [motion]


def influence(model: PoundingModel) -> NDArray[np.float64]:
    """The influence matrix R (N, G) of the model (an (N,) vector is its one column)."""
    r = np.asarray(model.system.r, dtype=float)
    return r.reshape(r.shape[0], -1)


def check_components(model: PoundingModel, motion: GroundMotion | GroundMotionComponents
                     ) -> None:
    """One component per column of R, or a one-line ``ValueError``."""
    g, n_r = len(records(motion)), influence(model).shape[1]
    if g != n_r:
        raise ValueError(f"motion: {g} ground component{'s' * (g != 1)} for a model whose "
                         f"influence matrix R has {n_r} column{'s' * (n_r != 1)}")


def output_step(record_dt: float, dt: float | None) -> float:
    """The output step: ``record_dt / m`` for the smallest whole ``m`` with
    ``record_dt / m ≤ dt`` (within a relative 10⁻⁹), so that every record interval holds a
    whole number of output steps."""
    want = DEFAULT_STEP if dt is None else float(dt)
    if not (math.isfinite(want) and want > 0.0):
        raise ValueError(f"dt: must be finite and > 0 (got {dt!r})")
    m = max(1, math.ceil(record_dt / (want * (1.0 + 1e-9))))
    return record_dt / m


def output_times(step: float, t_end: float) -> NDArray[np.float64]:
    """``0, step, 2 step, …`` up to the first multiple of the step at or past ``t_end``
    (within a relative 10⁻⁹ of a step)."""
    count = math.ceil(t_end / step - 1e-9) + 1
    if count < 2:
        raise ValueError(f"duration: {t_end:g} s is shorter than one output step "
                         f"({step:g} s)")
    return np.arange(count, dtype=np.float64) * step


def knots(motion: GroundMotion | GroundMotionComponents, t_end: float
          ) -> tuple[float, NDArray[np.float64]]:
    """The record step and the ground components at every record sample time ``i·dt`` from
    0 to past ``t_end`` (K, G): each record's samples, then zero (a record returns linearly
    to zero over the step after its last sample, and stays there)."""
    recs = records(motion)
    dt = recs[0].dt
    count = max(max(rec.accel.size for rec in recs) + 1, int(math.ceil(t_end / dt)) + 2)
    values = np.zeros((count, len(recs)))
    for g, rec in enumerate(recs):
        values[: rec.accel.size, g] = rec.accel
    return dt, values


def ground_at(times: NDArray[np.float64], dt: float, values: NDArray[np.float64]
              ) -> NDArray[np.float64]:
    """The ground components (len(times), G) at ``times``, linear between the knots
    ``values`` (at ``i·dt``)."""
    t = np.asarray(times, dtype=float)
    i = np.minimum(np.floor(t / dt + 1e-9).astype(int), values.shape[0] - 2)
    frac = (t - i * dt) / dt
    return values[i] + (values[i + 1] - values[i]) * frac[:, None]


def floor_below(model: PoundingModel) -> NDArray[np.int64]:
    """For every DOF the DOF of the floor below it (−1: the ground), the floors of each
    building taken in order of elevation (a matrix building's floor DOFs need not be); a
    DOF that is not a floor is given itself (no storey drift)."""
    below = np.arange(model.n_dof, dtype=np.int64)
    for off, b in zip(model.system.offsets, model.buildings):
        floors = [int(off) + int(f) for f in floor_dofs(b)]
        for k, f in enumerate(floors):
            below[f] = floors[k - 1] if k > 0 else -1
    return below


def initial_state(model: PoundingModel, u0: NDArray[np.float64] | None,
                  v0: NDArray[np.float64] | None) -> NDArray[np.float64]:
    """``[u, u̇]`` at t = 0: zeros, or the values given (one finite value per DOF); every
    gap must be open."""
    n = model.n_dof
    x = np.zeros(2 * n)
    for name, given, at in (("initial_displacement", u0, 0), ("initial_velocity", v0, n)):
        if given is not None:
            arr = np.asarray(given, dtype=float)
            if arr.shape != (n,) or not np.all(np.isfinite(arr)):
                raise ValueError(f"{name}: need {n} finite values (got {given!r})")
            x[at: at + n] = arr
    dof, w = model.contact_kinematics()
    for c in model.contacts:
        delta = float(w[c.index] @ x[dof[c.index]]) - c.gap
        if delta > 0.0:
            raise ValueError(f"initial_displacement: contact {c.label} starts closed "
                             f"(penetration {delta:g} m)")
    return x
