"""The one compiled time stepper (numba) for buildings that pound.

Two regimes, one kernel:

1. **All gaps open.** The structure is linear and the ground acceleration is linear between
   grid points, so each grid step is taken with the exact propagator
   (:mod:`pounding.integrate.exact_steps`), block by block, with the input and viscous
   energies of the step exact. After each step every gap is checked for closing at the step
   end and inside it, so no touch is missed.
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
    IMP_COLUMNS,
    PK_COLUMNS,
    WS_F_SIZE,
    WS_I_SIZE,
)
from pounding.integrate.rhs import (
    G_NOW,
    INLINE,
    deriv_call,
    first_unknown_law,
    gap_row,
    set_ground,
)

__all__ = ["ENERGY_COLUMNS", "IMP_COLUMNS", "PK_COLUMNS", "WS_F_SIZE", "WS_I_SIZE",
           "integrate_chunk"]


@njit(cache=True, error_model="numpy", nogil=True, fastmath={"contract"}, _nrt=False)
def integrate_chunk(k0, k1, dt, ag, exact_free, blk, fops, g0, g1, faa, bw, k_band, c_band,
                    m_diag, mr, r, cdof, cw, cgap, ccode, cparams, s_lo, s_hi, s_code, s_par,
                    s_zi, below, rtol, atol, h_max, x, committed, sstate, wc, w_start, imp_row,
                    last_f, ws_f, ws_i, u_out, v_out, acc_out, pen_out, f_out, vs_out, e_out,
                    imp, cpeak, cpeak_t, ccount, pk, ks, ps, ks_b, ps_b, kx, px, ytmp, y1, yb,
                    x1, acc, lin, work, gd, gr, gd1, gr1, arel0, arel1, jk, jk1, aabs0, aabs1,
                    m_inv, gnd):
    """Advance grid steps ``k0 … k1−1`` (times ``k·dt``), writing outputs at ``k+1``; stop
    early at the first grid point after ``ws_i[I_CALL_STEPS]`` RK steps in all. The grid
    point reached is left in ``ws_i[I_REACHED]`` (the next call starts there).

    Parameters (all arrays are updated in place)
    ----------
    dt : float
        Grid step [s]. ``ag`` (nt, G): the G ground acceleration components at grid points
        [m/s²] (along the columns of R).
    exact_free : bool
        Take steps without contact with the exact propagator (cost O(N²) a step, cheapest
        for small models); otherwise with the adaptive RK (O(N·bw) a stage).
    blk, fops, g0, g1, faa
        The exact step over dt (:class:`pounding.integrate.propagator.FreeStep`: blocks,
        block operators, Γ0 and Γ1 (2N, G), input-energy coefficients of the products of
        the ground components (3, G, G); unused unless ``exact_free``).
    bw, k_band, c_band, m_diag, mr, r
        Half-bandwidth of K and C; K of the linear storeys [N/m] and C [N·s/m] in band
        storage (``(2 bw + 1, N)``, :func:`pounding.integrate.band_storage`); lumped floor
        masses [kg], M R [kg] and the influence matrix R, both (N, G).
    cdof, cw, cgap, ccode, cparams
        Contacts: DOFs and signed weights of the two contact points (n_c, W: any width),
        gap [m], law code, law constants.
    s_lo, s_hi, s_code, s_par, s_zi
        Yielding storeys: DOF below (−1 ground) and above, storey-law code and constants,
        index of the storey's ``z`` among the extra states (−1: none). Empty for linear
        buildings (then ``exact_free`` may be true).
    below : (N,) int
        The DOF of the floor below each floor (−1: the ground), for storey drifts.
    rtol : float; atol : (2N + n_z,)
        RK tolerances (the displacement entries equal). ``h_max`` caps RK steps [s].
    x : (2N + n_z,)
        State [u, u̇, z] at grid point k0 (relative to the ground; z of Bouc–Wen storeys).
    committed : (n_c, STATE_SIZE)
        Committed contact states.
    sstate : (n_s, 2)
        Committed drift [m] and shear [N] of every yielding storey.
    wc, w_start : (n_c,)
        Cumulative contact work [J], and its value at each open impact's start.
    imp_row : (n_c,) int
        Row of each contact's open impact in ``imp`` (−1 if none).
    last_f : (n_c, 5)
        Per contact: time, force and force rate at the start of the current step (for the
        peak force inside each step); the first step accepted after its last onset [s] (0:
        none yet), where the next onset's steps start; 1 while an open gap found not to
        touch has not receded yet.
    ws_f, ws_i
        Workspace scalars (proposed RK step, cumulative input, viscous and storey work) and
        counters (:mod:`pounding.integrate.layout`).
    u_out, v_out, acc_out : (nt, N); pen_out, f_out : (nt, n_c) (f_out zero on entry);
    vs_out : (nt, n_s);
    e_out : (nt, 7); imp : (cap, IMP_COLUMNS)
        Outputs (vs_out: shear of every yielding storey).
    cpeak, cpeak_t, ccount : (n_c,)
        Peak force [N], its time [s] and number of impacts of every contact (kept even if
        the impact table overflows).
    pk : (N, PK_COLUMNS)
        Located peaks of every floor with their times (:mod:`pounding.integrate.peaks`).
    ks, ps, ks_b, ps_b, kx, px, ytmp, y1, yb, x1, acc, lin, work, gd, gr, gd1, gr1, arel0,
    arel1, jk, jk1, aabs0, aabs1, m_inv, gnd
        Scratch (:func:`pounding.integrate.kernel_scratch`): RK stages and powers of the
        main and the bracketing steps (7, 2N + n_z) and (7, 4 + n_c); f and the powers at
        the current state (1, …); trial states (2N + n_z,) ×4; the exact step's sweep
        (4N + 4); K u and C u̇ (2, N); (2N,); every contact's δ and δ̇ now and at the end of
        a trial exact step (n_c,) ×4; every floor's relative acceleration ×2, jerk ×2 and
        absolute acceleration ×2 (N,); 1 / floor mass (N,); the ground components at the
        step's ends, their slope, at the RK step's end and now (5, G). Allocated by the caller, once a
        run, so that this function compiles quickly (each allocation inside it cost
        compile time).
    """
    n = r.shape[0]
    # a law code no compiled law implements: stop before using it (its trial is NaN)
    bad = first_unknown_law(ccode, s_code, s_par)
    if bad >= 0:
        ws_i[I_FAILED] = FAIL_UNKNOWN_LAW
        ws_i[I_FAIL_STEP] = k0
        ws_i[I_FAIL_ROW] = bad
        return
    graze_tol = EVENT_TOL * atol[0]
    # the state at grid point k0: f, every gap's δ and δ̇, the accelerations
    set_ground(gnd, G_NOW, ag, k0)
    deriv_call(x, x, gnd, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap, ccode,
               cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin, kx, px, 0)
    _gaps_now(x, n, cdof, cw, cgap, gd, gr)
    for i in range(n):
        arel0[i] = kx[0, n + i]
    k = k0
    while k < k1:
        if ws_i[I_MODE] == 0:
            # exact steps while every gap stays open; stops at the step in which one could
            # close (x, gd and gr are then those of grid point k)
            k = free_run(k, k1, dt, ag, blk, fops, g0, g1, faa, bw, k_band, c_band, m_diag,
                         m_inv, r, cdof, cw, cgap, graze_tol, below, x, x1, acc, lin, gd, gr,
                         gd1, gr1, wc, ws_f, u_out, v_out, acc_out, pen_out, e_out, pk)
            if k < 0:
                ws_i[I_FAILED] = FAIL_NONFINITE
                ws_i[I_FAIL_STEP] = -k - 1
                return
            if k >= k1:
                break
            ws_i[I_MODE] = 1
            # a gap found not to touch at an earlier peak has receded since (the exact
            # steps do not clear its flag): search every gap afresh
            for c in range(cgap.shape[0]):
                last_f[c, LF_GRAZED] = 0.0
            set_ground(gnd, G_NOW, ag, k)
            deriv_call(x, x, gnd, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap,
                       ccode, cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate,
                       lin, kx, px, 0)
        # (else kx holds f at grid point k: the last stage of the grid step before, or
        # evaluated again after a contact opened or closed there)
        k = adaptive_run(k, k1, dt, ag, exact_free, bw, k_band, c_band, m_diag, m_inv, mr, r,
                         cdof, cw, cgap, ccode, cparams, s_lo, s_hi, s_code, s_par, s_zi,
                         below, rtol, atol, h_max, graze_tol, x, committed, sstate, wc,
                         w_start, imp_row, last_f, ws_f, ws_i, u_out, v_out, acc_out, pen_out,
                         f_out, vs_out, e_out, imp, cpeak, cpeak_t, ccount, pk, kx, px, ks, ps,
                         ks_b, ps_b, ytmp, y1, yb, lin, work, arel0, jk, jk1, aabs0, aabs1, gd,
                         gr, gnd)
        if k < 0:
            return
        if exact_free and not any_closed(committed):
            ws_i[I_MODE] = 0
        if ws_i[I_NSTEPS] >= ws_i[I_CALL_STEPS]:
            break  # the call's share of RK steps is done: return at grid point k
    ws_i[I_REACHED] = k


@njit(**INLINE)
def _gaps_now(x, n, cdof, cw, cgap, gd, gr):
    """Every contact's δ and δ̇ at state x."""
    for c in range(cgap.shape[0]):
        dsum, gr[c] = gap_row(c, x, n, cdof, cw)
        gd[c] = dsum - cgap[c]
