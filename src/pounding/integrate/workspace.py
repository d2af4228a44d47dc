"""A run's workspace, as the compiled kernel (:func:`pounding.integrate.kernel.integrate_chunk`)
takes it beside the model's arrays (:class:`pounding.integrate.kernel_model.KernelArrays`)
and the exact step (:class:`pounding.integrate.propagator.FreeStep`): what the run adds to
the model (:class:`RunInputs`), the state carried from one call of the kernel to the next
(:class:`KernelState`), the outputs it writes (:class:`KernelOutputs`) and its scratch
(:class:`KernelScratch`). Each is a named tuple of arrays, which numba passes by value and
reads by field name; all are allocated here, once a run, so the compiled functions allocate
nothing."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from pounding.contact.codes import STATE_SIZE
from pounding.integrate.kernel_model import KernelModel
from pounding.integrate.layout import (
    E_DEVICE,
    ENERGY_COLUMNS,
    I_MODE,
    I_ONSET_C,
    I_STEP_BUDGET,
    IMP_COLUMNS,
    P_CONTACT,
    W_ERR_OLD,
    W_H,
    W_PEAK_MARGIN,
    WS_F_SIZE,
    WS_I_SIZE,
)
from pounding.integrate.rhs import G_ROWS


class RunInputs(NamedTuple):
    """What a run adds to the model: the ground on the output grid and how to step."""

    dt: float  #: grid (output) step [s]
    ag: np.ndarray  #: the G ground components at the grid points [m/s²], (nt, G)
    exact: bool  #: take steps without contact with the exact propagator
    rtol: float  #: relative tolerance of the adaptive steps
    atol: np.ndarray  #: their absolute tolerances, (2N + n_z,) (displacements alike)
    h_max: float  #: largest adaptive step [s]


class KernelState(NamedTuple):
    """Everything the kernel carries from one call to the next (updated in place)."""

    x: np.ndarray  #: state [u, u̇, z] at the grid point reached (2N + n_z,)
    committed: np.ndarray  #: committed contact states (n_c, STATE_SIZE)
    storeys: np.ndarray  #: committed drift [m] and force [N] of every element row (n_s, 2)
    contact_work: np.ndarray  #: cumulative contact work [J] (n_c,)
    work_at_onset: np.ndarray  #: its value at each open impact's start [J] (n_c,)
    impact_row: np.ndarray  #: row of each contact's open impact in the table (−1: none)
    #: per contact: time, force and force rate at the start of the current step, the first
    #: step accepted after its last onset [s], and the graze flag (n_c, 5)
    #: (:data:`pounding.integrate.adaptive.LF_TIME` …)
    last_force: np.ndarray
    ws_f: np.ndarray  #: workspace scalars (:data:`pounding.integrate.layout.W_H` …)
    ws_i: np.ndarray  #: counters (:data:`pounding.integrate.layout.I_MODE` …)


class KernelOutputs(NamedTuple):
    """What the kernel writes: histories at the grid points, the impact table, per-contact
    peaks and counts, and the located peaks of every floor."""

    u: np.ndarray  #: displacements [m] (nt, N)
    v: np.ndarray  #: velocities [m/s] (nt, N)
    acc: np.ndarray  #: absolute accelerations [m/s²] (nt, N)
    pen: np.ndarray  #: penetrations [m] (nt, n_c)
    force: np.ndarray  #: contact forces [N] (nt, n_c), zero on entry
    element_force: np.ndarray  #: force of every element row [N] (nt, n_s)
    energy: np.ndarray  #: energies [J] (nt, ENERGY_COLUMNS)
    impacts: np.ndarray  #: impact table (capacity, IMP_COLUMNS)
    peak_force: np.ndarray  #: peak force of every contact [N] (n_c,)
    peak_force_time: np.ndarray  #: its time [s]
    impact_count: np.ndarray  #: impacts of every contact (kept past the table's capacity)
    peaks: np.ndarray  #: located peaks of every floor (N, PK_COLUMNS)
    hinge_rotation: np.ndarray  #: rotation of every hinge of the yielding frames [rad] (nt, n_h)
    hinge_moment: np.ndarray  #: and its moment [N·m] (nt, n_h)


def new_state(km: KernelModel, x: np.ndarray, storeys: np.ndarray, step: float,
              margin: float, exact: bool, step_budget: int) -> KernelState:
    """The state a run starts from: ``x`` and the element rows' ``storeys`` at t = 0, every
    contact open, the first RK step a tenth of the grid step ``step``, the peak margin
    (:func:`pounding.integrate.kernel_model.peak_margin`), the stepping mode and the budget
    of RK steps."""
    nc = km.contacts.gap.size
    ws_f = np.zeros(WS_F_SIZE)
    ws_f[W_ERR_OLD] = 1e-4
    ws_f[W_H] = step * 0.1
    ws_f[W_PEAK_MARGIN] = margin
    ws_i = np.zeros(WS_I_SIZE, dtype=np.int64)
    ws_i[I_MODE] = 0 if exact else 1  # 0 exact stepping, 1 adaptive RK
    ws_i[I_ONSET_C] = -1
    ws_i[I_STEP_BUDGET] = step_budget
    return KernelState(x, np.zeros((max(nc, 1), STATE_SIZE))[:nc], storeys, np.zeros(nc),
                       np.zeros(nc), np.full(nc, -1, dtype=np.int64), np.zeros((nc, 5)),
                       ws_f, ws_i)


def new_outputs(km: KernelModel, nt: int, capacity: int, peaks: np.ndarray,
                n_hinges: int = 0) -> KernelOutputs:
    """The outputs of a run of ``nt`` grid points with ``capacity`` rows of impacts (and
    ``n_hinges`` hinges of yielding frames).

    The kernel writes every row after the first of the histories, so they are not zeroed
    first (zeroing ~5 MB costs as much as a tenth of an SDOF pair's run when the memory is
    reused); the contact forces are: exact steps leave their zero rows untouched. Nor is the
    impact table: the kernel writes every column of a row when the impact starts, and only
    the rows written are kept."""
    n, nc, ns = km.n, km.contacts.gap.size, km.elements.lo.size
    energy = np.empty((nt, ENERGY_COLUMNS), order="F")  # (each energy's history contiguous)
    energy[:, E_DEVICE] = 0.0  # (exact steps write it only for a model with links)
    return KernelOutputs(np.empty((nt, n)), np.empty((nt, n)), np.empty((nt, n)),
                         np.empty((nt, nc)), np.zeros((nt, nc)), np.empty((nt, ns)), energy,
                         np.empty((capacity, IMP_COLUMNS)), np.zeros(nc), np.zeros(nc),
                         np.zeros(nc, dtype=np.int64), peaks, np.empty((nt, n_hinges)),
                         np.empty((nt, n_hinges)))


class KernelScratch(NamedTuple):
    """The kernel's scratch (:func:`kernel_scratch`): allocated by the caller once a run, so
    that the compiled functions allocate nothing (each allocation inside them cost compile
    time, and they run without numba's reference counting)."""

    ks: np.ndarray  #: stages of the main RK step (7, m)
    ps: np.ndarray  #: their powers (7, 4 + n_c)
    ks_b: np.ndarray  #: stages of a bracketing RK step (7, m)
    ps_b: np.ndarray  #: their powers (7, 4 + n_c)
    kx: np.ndarray  #: f at the current state (1, m)
    px: np.ndarray  #: its powers (1, 4 + n_c)
    ytmp: np.ndarray  #: a stage's state (m,)
    y1: np.ndarray  #: the state at a step's end (m,)
    yb: np.ndarray  #: the state at a bracketing step's end (m,)
    x1: np.ndarray  #: the state after an exact step (m,)
    acc: np.ndarray  #: the exact step's sweep (2 m + 4 G)
    lin: np.ndarray  #: K u and C u̇ (2, N)
    work: np.ndarray  #: (2N,)
    gd: np.ndarray  #: every contact's δ now (n_c,)
    gr: np.ndarray  #: and δ̇
    gd1: np.ndarray  #: δ at the end of a trial exact step
    gr1: np.ndarray  #: and δ̇
    arel0: np.ndarray  #: every floor's relative acceleration at a step's start (N,)
    arel1: np.ndarray  #: and end
    jk: np.ndarray  #: every floor's jerk at a step's start (N,)
    jk1: np.ndarray  #: and end
    aabs0: np.ndarray  #: every floor's absolute acceleration at a step's start (N,)
    aabs1: np.ndarray  #: and end
    #: the ground components at the grid step's ends, their slope, at the RK step's end and
    #: now, (G_ROWS, G) (:data:`pounding.integrate.rhs.G_A0` …)
    gnd: np.ndarray
    #: the modal state of the exact steps' modal blocks at a step's start and end, their
    #: sums, and the grid point the first is at (−1: none) (QM_ROWS, N + 1)
    #: (:mod:`pounding.integrate.modal_steps`)
    modal: np.ndarray


def kernel_scratch(km: KernelModel, m: int) -> KernelScratch:
    """The kernel's scratch arrays for a model, ``m`` the length of the state."""
    n, nc = km.n, km.contacts.gap.size
    npw = P_CONTACT + nc  # the power rows (layout.P_INPUT … P_CONTACT + c)
    stages = np.zeros((2, 7, m))
    powers = np.zeros((2, 7, npw))
    states = np.zeros((4, m))
    gaps = np.zeros((4, nc))
    floors = np.zeros((6, n))
    return KernelScratch(stages[0], powers[0], stages[1], powers[1], np.zeros((1, m)),
                         np.zeros((1, npw)), states[0], states[1], states[2], states[3],
                         np.zeros(2 * m + 4 * km.floors.r.shape[1]), np.zeros((2, n)),
                         np.zeros(2 * n),
                         gaps[0], gaps[1], gaps[2], gaps[3],
                         floors[0], floors[1], floors[2], floors[3], floors[4], floors[5],
                         np.zeros((G_ROWS, km.floors.r.shape[1])), modal_scratch(n))


def modal_scratch(n: int) -> np.ndarray:
    """:attr:`KernelScratch.modal` of N floors: no modal state yet (grid point −1)."""
    from pounding.integrate.modal_steps import QM_ROWS

    qm = np.zeros((QM_ROWS, n + 1))
    qm[0, n] = -1.0
    return qm
