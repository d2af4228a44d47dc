"""The one compiled time stepper (numba) for buildings that pound.

Two regimes, one kernel:

1. **All gaps open.** The structure is linear and the ground acceleration is linear between
   grid points, so each grid step is taken with the exact propagator
   (:mod:`pounding.integrate.exact_steps`), block by block, with the input and viscous
   energies of the step exact. After each step every gap is checked for closing at the step
   end and inside it, so no touch is missed — and every cable restrainer, slack in this
   regime, for its slack being taken up, likewise.
2. **Any contact closed (or about to close).** The step is re-taken with an adaptive
   Dormand–Prince 5(4) integrator (:mod:`pounding.integrate.dormand_prince`) whose steps land
   exactly on grid points (:mod:`pounding.integrate.adaptive`). Events are located on actual
   RK steps by the Illinois method (:mod:`pounding.integrate.events`): a gap closing
   (contact onset, where ``v0`` is committed — contract step 3), reopening (separation),
   the rate ``δ̇`` changing sign inside a contact (approach ↔ restitution, where laws switch
   branch), a yielding storey's drift reversing, and an open gap peaking within the event
   tolerance of closing. Contact and storey states are committed only at accepted step
   ends and events (:mod:`pounding.integrate.commit`). Energies (input, viscous, contact
   work per contact) are integrated with the same RK weights, so they are as accurate as
   the motion.

In both regimes the peaks of every floor's displacement, storey drift and absolute
acceleration are located inside steps with their times (:mod:`pounding.integrate.peaks`), as
the peak contact force is.

The equations of motion are in :mod:`pounding.integrate.rhs`, the data layout (table
columns, workspace slots) in :mod:`pounding.integrate.layout`. Floating point: no
reassociation (``fastmath`` allows only fused multiply-add), so results do not depend on how
arrays happen to be aligned in memory — a sweep's cases are bit-identical whichever process
runs them.

The kernel advances a chunk of grid steps ``[k0, k1)`` — returning early once a call's share
of RK steps is done — and keeps everything it needs between chunks in a workspace, so the
caller regains control often (Python handles Ctrl-C and SIGTERM only between calls) and can
show progress; the answer does not depend on how the run is cut into chunks.
"""

from __future__ import annotations

from numba import njit

from pounding.integrate.adaptive import LF_GRAZED, adaptive_run, any_closed
from pounding.integrate.exact_links import rows_allow_exact
from pounding.integrate.exact_steps import free_run
from pounding.integrate.layout import (
    ENERGY_COLUMNS,
    EVENT_TOL,
    FAIL_NONFINITE,
    FAIL_UNKNOWN_LAW,
    I_CALL_STEPS,
    I_FAIL_ROW,
    I_FAIL_STEP,
    I_FAILED,
    I_MODE,
    I_NSTEPS,
    I_REACHED,
    I_STOP,
    IMP_COLUMNS,
    PK_COLUMNS,
    W_RESUME_S,
    WS_F_SIZE,
    WS_I_SIZE,
)
from pounding.integrate.rhs import (
    ENTRY,
    G_A0,
    G_A1,
    G_NOW,
    G_SLOPE,
    INLINE,
    deriv_call,
    first_unknown_law,
    gap_row,
    ground_at,
    set_ground,
)

__all__ = ["ENERGY_COLUMNS", "IMP_COLUMNS", "PK_COLUMNS", "WS_F_SIZE", "WS_I_SIZE",
           "integrate_chunk"]


@njit(**ENTRY)
def integrate_chunk(k0, k1, run, km, fs, st, out, sc):
    """Advance grid steps ``k0 … k1−1`` (times ``k·dt``), writing outputs at ``k+1``; stop
    early at the first grid point after ``ws_i[I_CALL_STEPS]`` RK steps in all, or right
    after a hinge event of a yielding frame (``ws_i[I_STOP]``; the grid step in progress in
    ``ws_i[I_REACHED]`` and the local time reached in it in ``ws_f[W_RESUME_S]``, where the
    next call resumes). The grid point reached is left in ``ws_i[I_REACHED]`` (the next
    call starts there).

    Parameters (named tuples of arrays; those of ``st``, ``out`` and ``sc`` are updated in
    place)
    ----------
    run : :class:`pounding.integrate.workspace.RunInputs`
        The grid step ``dt`` [s] and the G ground components at the grid points ``ag``
        (nt, G) [m/s²] (along the columns of R); ``exact``: take steps without contact with
        the exact propagator (cost O(N²) a step, cheapest for small models), otherwise with
        the adaptive RK (O(N·bw) a stage); the RK tolerances ``rtol`` and ``atol``
        (2N + n_z,: the displacement entries equal, and the velocity entries), and the
        largest RK step ``h_max`` [s].
    km : :class:`pounding.integrate.kernel_model.KernelArrays`
        The model: its floors (half-bandwidth of K and C; K of the linear storeys [N/m] and
        C [N·s/m] in band storage, ``(2 bw + 1, N)``; lumped floor masses [kg] and their
        inverses; M R [kg] and the influence matrix R, both (N, G); the DOF of the floor
        below each floor, −1 the ground), its contacts (DOFs and signed weights of every
        contact row (n_c, W: any width), gaps [m], law codes and constants) and its element
        rows (yielding storeys and links: DOF below, −1 the ground, and above, law code and
        constants, index of the row's ``z`` among the extra states, −1 none; ``exact`` may
        be true only if every row is a linear link folded into K and C, a linear Maxwell
        link (its z in the exact step's state, ``fs.maxwell``) or a cable restrainer, whose
        slack taken up hands the step to RK as a gap closing does).
    fs : :class:`pounding.integrate.propagator.FreeStep`
        The exact step over dt (blocks, block operators, Γ0 and Γ1 (2N + n_z, G), input-energy
        coefficients of the products of the ground components (3, G, G); unused unless
        ``exact``).
    st : :class:`pounding.integrate.workspace.KernelState`
        The state at grid point k0 — ``x`` = [u, u̇, z] relative to the ground, the
        committed contact and element-row states, cumulative contact work and its value at
        each open impact's start, each contact's open impact row and last force — and the
        workspace scalars and counters (:mod:`pounding.integrate.layout`).
    out : :class:`pounding.integrate.workspace.KernelOutputs`
        Histories (displacement, velocity, absolute acceleration (nt, N); penetration and
        force (nt, n_c), the force zero on entry; element-row forces (nt, n_s); energies
        (nt, ENERGY_COLUMNS)), the impact table, per-contact peak force, its time and
        number of impacts (kept even if the table overflows), and the located peaks of
        every floor with their times (N, PK_COLUMNS, :mod:`pounding.integrate.peaks`).
    sc : :class:`pounding.integrate.workspace.KernelScratch`
        Scratch, allocated by the caller once a run, so that this function compiles
        quickly (each allocation inside it cost compile time).
    """
    fl, ct, el = km.floors, km.contacts, km.elements
    x = st.x
    ws_i = st.ws_i
    committed = st.committed
    kx = sc.kx
    gnd = sc.gnd
    n = fl.m_diag.shape[0]
    # a law code no compiled law implements: stop before using it (its trial is NaN)
    bad = first_unknown_law(ct, el)
    if bad >= 0:
        ws_i[I_FAILED] = FAIL_UNKNOWN_LAW
        ws_i[I_FAIL_STEP] = k0
        ws_i[I_FAIL_ROW] = bad
        return
    graze_tol = EVENT_TOL * run.atol[0]
    # the state at grid point k0 (or, after a hinge event, at the local time
    # ws_f[W_RESUME_S] inside grid step k0): f, every gap's δ and δ̇, the accelerations
    s_resume = st.ws_f[W_RESUME_S]
    if s_resume > 0.0:
        for g in range(gnd.shape[1]):
            gnd[G_A0, g] = run.ag[k0, g]
            gnd[G_A1, g] = run.ag[k0 + 1, g]
            gnd[G_SLOPE, g] = (gnd[G_A1, g] - gnd[G_A0, g]) / run.dt
        ground_at(gnd, G_NOW, s_resume)
    else:
        set_ground(gnd, G_NOW, run.ag, k0)
    deriv_call(x, x, gnd, fl, ct, el, committed, st.storeys, sc.lin, kx, sc.px, 0)
    _gaps_now(x, n, ct, sc.gd, sc.gr)
    for i in range(n):
        sc.arel0[i] = kx[0, n + i]
    k = k0
    while k < k1:
        if ws_i[I_MODE] == 0:
            # exact steps while every gap stays open; stops at the step in which one could
            # close (x, gd and gr are then those of grid point k)
            k = free_run(k, k1, run, fl, ct, el, fs, graze_tol, st, out, sc)
            if k < 0:
                ws_i[I_FAILED] = FAIL_NONFINITE
                ws_i[I_FAIL_STEP] = -k - 1
                return
            if k >= k1:
                break
            ws_i[I_MODE] = 1
            # a gap found not to touch at an earlier peak has receded since (the exact
            # steps do not clear its flag): search every gap afresh
            for c in range(ct.gap.shape[0]):
                st.last_force[c, LF_GRAZED] = 0.0
            set_ground(gnd, G_NOW, run.ag, k)
            deriv_call(x, x, gnd, fl, ct, el, committed, st.storeys, sc.lin, kx, sc.px, 0)
        # (else kx holds f at grid point k: the last stage of the grid step before, or
        # evaluated again after a contact opened or closed there)
        k = adaptive_run(k, k1, run, km, graze_tol, st, out, sc)
        if k < 0:
            return
        if ws_i[I_STOP] != 0:
            break  # a hinge event: Python gives its frame the next configuration
        if run.exact and not any_closed(committed) and rows_allow_exact(x, n, el):
            ws_i[I_MODE] = 0
        if ws_i[I_NSTEPS] >= ws_i[I_CALL_STEPS]:
            break  # the call's share of RK steps is done: return at grid point k
    ws_i[I_REACHED] = k


@njit(**INLINE)
def _gaps_now(x, n, ct, gd, gr):
    """Every contact's δ and δ̇ at state x."""
    for c in range(ct.gap.shape[0]):
        dsum, gr[c] = gap_row(c, x, n, ct.dof, ct.weight)
        gd[c] = dsum - ct.gap[c]
