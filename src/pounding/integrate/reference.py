"""The slow, plain, obviously-correct reference solution (SciPy ``solve_ivp``).

Used by the tests and benchmarks to hold the compiled kernel to account; never by users for
production runs. It integrates the full first-order system ``[u, u̇, E_in, E_visc, W_c]``
with ``DOP853`` at tight tolerance, one record interval at a time (the ground acceleration
is linear on each), and stops at every located event — a gap closing or opening, and the
penetration rate changing sign inside a contact — to commit the contact state there
(contract steps 3–4) and restart. Peak forces are found on the dense output of each
segment and refined with a bounded scalar search.
"""

from __future__ import annotations

import time

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

from pounding.contact.base import STATE_SIZE, V0, V0_MIN
from pounding.contact.dispatch import contact_stored_energy, contact_trial
from pounding.ground_motion import GroundMotion
from pounding.integrate import ground_on_grid, grid_step, initial_state
from pounding.integrate.kernel import ENERGY_COLUMNS, IMP_COLUMNS
from pounding.model import PoundingModel
from pounding.result import Result, SolverStats

REFERENCE_RTOL: float = 1e-10


def simulate_reference(model: PoundingModel, motion: GroundMotion, *, dt: float | None = None,
                       duration: float | None = None, rtol: float = REFERENCE_RTOL,
                       initial_displacement: np.ndarray | None = None,
                       initial_velocity: np.ndarray | None = None) -> Result:
    """Reference solution of :func:`pounding.integrate.simulate` (same arguments, same Result).

    Slow: minutes for a long record. Outputs at the same grid as :func:`simulate`.
    """
    step = grid_step(motion.dt, dt)
    t_end = motion.duration if duration is None else float(duration)
    ag = ground_on_grid(motion, step, t_end)
    nt = ag.size
    t_grid = np.arange(nt) * step
    sys_ = model.system
    M, C, K, r = sys_.M, sys_.C, sys_.K, sys_.r
    n = r.size
    minv = np.linalg.inv(M)
    minv_k, minv_c, mr = minv @ K, minv @ C, M @ r
    contacts = model.contacts
    nc = len(contacts)
    cl = np.array([c.dof_left for c in contacts], dtype=int)
    cr = np.array([c.dof_right for c in contacts], dtype=int)
    gap = np.array([c.gap for c in contacts])
    codes = [c.law.code for c in contacts]
    params = [c.law.params() for c in contacts]
    committed = np.zeros((nc, STATE_SIZE))
    scratch = np.zeros(STATE_SIZE)
    phase = np.zeros(nc, dtype=int)  # +1 approaching, −1 restitution (closed contacts)
    u_scale = max(min(gap) if nc else 0.0, 1e-3)
    v_scale = max(motion.pgv, 1e-3)
    e_scale = max(float(np.sum(M)) * v_scale**2, 1.0)
    atol = np.concatenate([np.full(n, 1e-3 * rtol * u_scale), np.full(n, 1e-3 * rtol * v_scale),
                           np.full(2 + nc, 1e-3 * rtol * e_scale)])

    def forces(y: NDArray[np.float64]) -> NDArray[np.float64]:
        f = np.zeros(nc)
        for c in range(nc):
            # between events a contact keeps its committed status (see the kernel)
            if committed[c, V0] > 0.0:
                d = max(y[cl[c]] - y[cr[c]] - gap[c], 1e-300)
                f[c] = contact_trial(codes[c], params[c], d, y[n + cl[c]] - y[n + cr[c]],
                                     committed[c], scratch)[0]
        return f

    def rhs_factory(t0: float, a0: float, slope: float):
        def rhs(t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
            u, v = y[:n], y[n:2 * n]
            a_g = a0 + slope * (t - t0)
            f = forces(y)
            p = np.zeros(n)
            np.add.at(p, cl, -f)
            np.add.at(p, cr, f)
            acc = -minv_k @ u - minv_c @ v + minv @ p - r * a_g
            rate = v[cl] - v[cr]
            return np.concatenate([v, acc, [-(v @ mr) * a_g, v @ (C @ v)], f * rate])
        return rhs

    def make_events() -> list:
        evs = []
        for c in range(nc):
            if committed[c, V0] == 0.0:
                def ev(t, y, c=c):
                    return y[cl[c]] - y[cr[c]] - gap[c]
                ev.direction = 1.0
            else:
                def ev(t, y, c=c):
                    return y[cl[c]] - y[cr[c]] - gap[c]
                ev.direction = -1.0
            ev.terminal = True
            evs.append(ev)
            if committed[c, V0] > 0.0:
                def evr(t, y, c=c):
                    return y[n + cl[c]] - y[n + cr[c]]
                evr.direction = -1.0 if phase[c] > 0 else 1.0
                evr.terminal = True
                evs.append(evr)
        return evs

    y = np.zeros(2 * n + 2 + nc)
    y[: 2 * n] = initial_state(model, initial_displacement, initial_velocity)
    out = np.zeros((nt, 2 * n + 2 + nc))
    out[0] = y
    f_out = np.zeros((nt, nc))
    stored = np.zeros(nt)
    impacts: list[list[float]] = []
    open_row = [-1] * nc
    w_start = np.zeros(nc)
    events = 0
    start = time.perf_counter()
    # record intervals on the grid: integrate [t_i, t_{i+1}] where a_g is linear
    rec_step = motion.dt
    per = int(round(rec_step / step))
    for i in range(0, nt - 1, per):
        j = min(i + per, nt - 1)
        t0, t1 = t_grid[i], t_grid[j]
        a0 = ag[i]
        slope = (ag[j] - ag[i]) / (t1 - t0)
        rhs = rhs_factory(t0, a0, slope)
        t = t0
        while True:
            evs = make_events()
            sol = solve_ivp(rhs, (t, t1), y, method="DOP853", rtol=rtol, atol=atol, events=evs,
                            dense_output=True)
            t_stop = float(sol.t[-1])
            # outputs on the grid inside this segment
            k_lo = int(np.ceil((t - t0) / step - 1e-9)) + i
            k_hi = int(np.floor((t_stop - t0) / step + 1e-9)) + i
            for k in range(max(k_lo, i), min(k_hi, j) + 1):
                yk = sol.sol(t_grid[k])
                out[k] = yk
                f_out[k] = forces(yk)
                stored[k] = sum(contact_stored_energy(codes[c], params[c],
                                                      yk[cl[c]] - yk[cr[c]] - gap[c], committed[c])
                                for c in range(nc) if committed[c, V0] > 0.0)
            # peak force over the segment for every closed contact
            for c in range(nc):
                if committed[c, V0] > 0.0 and open_row[c] >= 0 and t_stop > t:
                    def neg_f(s: float, c: int = c) -> float:
                        ys = sol.sol(s)
                        return -forces(ys)[c]
                    ts = np.linspace(t, t_stop, 64)
                    fs = np.array([-neg_f(s) for s in ts])
                    kmax = int(np.argmax(fs))
                    best = fs[kmax]
                    if 0 < kmax < len(ts) - 1:
                        res = minimize_scalar(neg_f, bounds=(ts[kmax - 1], ts[kmax + 1]),
                                              method="bounded", options={"xatol": 1e-12})
                        best = max(best, -res.fun)
                    row = impacts[open_row[c]]
                    row[4] = max(row[4], best)
            y = sol.y[:, -1].copy()
            t = t_stop
            if sol.status != 1:
                break
            # which event fired first?
            fired = [(float(te[0]), k) for k, te in enumerate(sol.t_events) if len(te)]
            _, kev = min(fired)
            y = sol.y_events[kev][0].copy()
            events += 1
            # map event index back to (contact, kind)
            idx = 0
            for c in range(nc):
                if idx == kev:
                    kind = "gap"
                    break
                idx += 1
                if committed[c, V0] > 0.0:
                    if idx == kev:
                        kind = "rate"
                        break
                    idx += 1
            d = y[cl[c]] - y[cr[c]] - gap[c]
            rate = y[n + cl[c]] - y[n + cr[c]]
            if kind == "gap" and committed[c, V0] == 0.0:
                committed[c] = 0.0
                committed[c, V0] = max(rate, V0_MIN)
                phase[c] = 1
                f0 = contact_trial(codes[c], params[c], max(d, 1e-300), rate, committed[c],
                                   scratch)[0]
                impacts.append([c, t, np.nan, committed[c, V0], f0, 0.0, np.nan, np.nan])
                open_row[c] = len(impacts) - 1
                w_start[c] = y[2 * n + 2 + c]
            elif kind == "gap":
                row = impacts[open_row[c]]
                row[2] = t
                row[6] = max(-rate, 0.0) / committed[c, V0]
                row[7] = y[2 * n + 2 + c] - w_start[c]
                open_row[c] = -1
                committed[c] = 0.0
                phase[c] = 0
            else:
                contact_trial(codes[c], params[c], d, rate,
                              committed[c], scratch)
                committed[c] = scratch
                impacts[open_row[c]][5] = max(impacts[open_row[c]][5], d)
                phase[c] = -phase[c]
            if t >= t1:
                break
        # commit states of closed contacts at the interval end (contract step 4)
        for c in range(nc):
            if committed[c, V0] > 0.0:
                d = y[cl[c]] - y[cr[c]] - gap[c]
                contact_trial(codes[c], params[c], d, y[n + cl[c]] - y[n + cr[c]],
                              committed[c], scratch)
                committed[c] = scratch
                impacts[open_row[c]][5] = max(impacts[open_row[c]][5], d)
    wall = time.perf_counter() - start
    u_out = out[:, :n]
    v_out = out[:, n:2 * n]
    acc = np.empty((nt, n))
    for k in range(nt):
        p = np.zeros(n)
        np.add.at(p, cl, -f_out[k])
        np.add.at(p, cr, f_out[k])
        acc[k] = -minv_k @ u_out[k] - minv_c @ v_out[k] + minv @ p
    energy = np.zeros((nt, ENERGY_COLUMNS))
    energy[:, 0] = out[:, 2 * n]
    energy[:, 1] = 0.5 * np.einsum("ki,ij,kj->k", v_out, M, v_out)
    energy[:, 2] = 0.5 * np.einsum("ki,ij,kj->k", u_out, K, u_out)
    energy[:, 3] = out[:, 2 * n + 1]
    energy[:, 4] = out[:, 2 * n + 2:].sum(axis=1)
    energy[:, 5] = stored
    pen = u_out[:, cl] - u_out[:, cr] - gap
    imp = np.array(impacts, dtype=float).reshape(-1, IMP_COLUMNS)
    stats = SolverStats(solver="scipy-reference", rtol=rtol, events=events, wall_time=wall)
    return Result(model=model, motion=motion, dt=step, ground=ag, displacement=u_out,
                  velocity=v_out, abs_acceleration=acc, penetration=pen, contact_force=f_out,
                  energy=energy, impact_array=imp, stats=stats)
