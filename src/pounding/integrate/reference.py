"""The slow, plain, obviously-correct reference solution (SciPy ``solve_ivp``).

Used by the tests and benchmarks to hold the compiled kernel to account; never by users for
production runs. It integrates the full first-order system ``[u, u̇, h, E_in, E_visc,
W_storey, W_c]`` with ``DOP853`` at tight tolerance, one record interval at a time (the
ground acceleration is linear on each), and stops at every located event — a gap closing
or opening, the penetration rate changing sign inside a contact, a clipped contact force
returning to zero or rising from it, a storey yielding or unloading, a cable restrainer
going taut, slack, yielding or unloading — to commit the state there (contract steps 3–4) and restart. Peak forces are
found on the dense output of each segment and refined with a bounded scalar search.

Nothing here comes from the compiled kernel's side: the contact, storey and link laws are
written out afresh from their equations (:mod:`pounding.integrate.reference_laws`), and so
are the output grid, the ground acceleration between record samples, the starting state and
the floors' order (:mod:`pounding.integrate.reference_inputs`); what it shares with the
kernel is the model (its matrices, contacts and their kinematics) and the record. Yielding
storeys each have one state ``h`` integrated with the motion: for the bilinear storey ``h``
is the shear itself, in *rate form* — ``V̇ = k ḋ`` while elastic, ``V̇ = b k ḋ`` on the yield
branch — switching at located events (the shear reaching ``b k d ± (1 − b) F_y``, and the
drift rate changing sign on the yield branch), instead of the kernel's return mapping; for
Bouc–Wen ``h = z``.
"""

from __future__ import annotations

import math

import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

from pounding.contact.codes import V0_MIN
from pounding.devices import Link
from pounding.ground_motion import GroundMotion, GroundMotionComponents
from pounding.integrate.reference_inputs import (
    check_components,
    floor_below,
    ground_at,
    influence,
    initial_state,
    knots,
    output_step,
    output_times,
)
from pounding.integrate.reference_laws import (
    RESTRAINER_SLACK,
    RESTRAINER_TAUT,
    RESTRAINER_YIELDING,
    Storey,
    contact_force,
    fracture_penetration,
    keeps_set,
    link_force,
    link_recoverable,
    maxwell_spring_rate,
    release_function,
    restrainer_force,
    restrainer_switches,
    spring_stiffness,
    stored_energy,
    storey_load,
    storey_recoverable,
    storey_shear,
)
from pounding.integrate.reference_laws import (
    storeys as yielding_storeys,
)
from pounding.model import PoundingModel
from pounding.result import ENERGY_NAMES, IMPACT_COLUMNS, Result, SolverStats

REFERENCE_RTOL: float = 1e-10


@dataclass(frozen=True)
class StopEvent:
    """A terminal event function for ``solve_ivp``, which reads ``terminal`` and
    ``direction`` off the callable: ``function(t, y)`` crosses zero (in ``direction``: +1
    rising, −1 falling) where the state changes branch; ``tag`` is (kind, index, sign), the
    sign ±1 for a storey yielding one way or the other, 0 for the other kinds."""

    function: Callable[[float, NDArray[np.float64]], float]
    direction: float
    tag: tuple[str, int, int]
    terminal: bool = True

    def __call__(self, t: float, y: NDArray[np.float64]) -> float:
        return self.function(t, y)


def simulate_reference(model: PoundingModel, motion: GroundMotion | GroundMotionComponents, *,
                       dt: float | None = None, duration: float | None = None,
                       rtol: float = REFERENCE_RTOL,
                       initial_displacement: np.ndarray | None = None,
                       initial_velocity: np.ndarray | None = None) -> Result:
    """Reference solution of :func:`pounding.integrate.simulate` (same arguments, same Result).

    Slow: minutes for a long record. Outputs at the same grid as :func:`simulate`.
    """
    check_components(model, motion)
    step = output_step(motion.dt, dt)
    t_end = motion.duration if duration is None else float(duration)
    t_grid = output_times(step, t_end)
    nt = t_grid.size
    rec_dt, ground_knots = knots(motion, float(t_grid[-1]))
    ag = ground_at(t_grid, rec_dt, ground_knots)  # (nt, G)
    ground = ag[:, 0].copy() if ag.shape[1] == 1 else ag
    sys_ = model.system
    M, C = sys_.M, sys_.C
    r = influence(model)  # R (N, G): M ü + … = −M R a_g
    K = model.linear_stiffness()
    n = r.shape[0]
    minv = np.linalg.inv(M)
    minv_k, minv_c, mr = minv @ K, minv @ C, M @ r
    contacts = model.contacts
    nc = len(contacts)
    cdof, cw = model.contact_kinematics()
    gap = np.array([c.gap for c in contacts])
    laws = [c.law for c in contacts]
    v0s = np.zeros(nc)  # closing velocity of each contact's impact (0: open)
    slips = np.zeros(nc)  # the bilinear element's plastic offset; the backfill's set
    phase = np.zeros(nc, dtype=int)  # +1 approaching, −1 restitution (closed contacts)
    # laws clipped at F = 0 before δ = 0 (Kelvin–Voigt without tension): where the clip
    # bites, an event; released[c] while the clipped force is zero
    release = [release_function(law) for law in laws]
    released = np.zeros(nc, dtype=bool)
    # shear keys: the penetration at which each breaks off (None: never); a broken key's
    # set is +inf (reference_laws._key)
    fracture = [fracture_penetration(law) for law in laws]
    storeys = yielding_storeys(model)
    ns = len(storeys)
    yld = np.zeros(ns, dtype=int)  # bilinear: 0 elastic, ±1 on the yield branch
    u_scale = max(min(gap) if nc else 0.0, 1e-3)
    v_scale = max(motion.pgv, 1e-3)
    e_scale = max(float(np.sum(M)) * v_scale**2, 1.0)
    # links between buildings (reference_laws.link_force); a Maxwell link's spring
    # deformation is a state
    links = model.links
    l_lo = [lo for lo, _ in model.link_dofs]
    l_hi = [hi for _, hi in model.link_dofs]
    l_zi = list(np.cumsum([lk.kind == "maxwell" for lk in links]) - 1)
    nzl = sum(lk.kind == "maxwell" for lk in links)
    # a cable restrainer's branch and plastic elongation [m] change only at its events
    rst_branch = np.full(len(links), RESTRAINER_SLACK)
    rst_plastic = np.zeros(len(links))
    i_h = 2 * n                 # hysteretic states
    i_z = 2 * n + ns            # Maxwell links' spring deformations
    i_e = 2 * n + ns + nzl      # E_in, E_visc, W_storey, W_links, W_c...
    h_scale = [st.fy if st.kind == "bilinear" else 1.0 for st in storeys]
    atol = np.concatenate([np.full(n, 1e-3 * rtol * u_scale), np.full(n, 1e-3 * rtol * v_scale),
                           1e-3 * rtol * np.array(h_scale, dtype=float),
                           np.full(nzl, 1e-3 * rtol * u_scale),
                           np.full(4 + nc, 1e-3 * rtol * e_scale)])

    def kin(y: NDArray[np.float64], c: int) -> tuple[float, float]:
        return (float(cw[c] @ y[cdof[c]] - gap[c]), float(cw[c] @ y[n + cdof[c]]))

    def forces(y: NDArray[np.float64]) -> NDArray[np.float64]:
        f = np.zeros(nc)
        for c in range(nc):
            # between events a contact keeps its committed status (see the kernel)
            if v0s[c] > 0.0:
                f[c] = contact_force(laws[c], *kin(y, c), v0s[c], slips[c])[0]
        return f

    def drift(y: NDArray[np.float64], s: int) -> tuple[float, float]:
        st = storeys[s]
        lo_u = y[st.lower] if st.lower >= 0 else 0.0
        lo_v = y[n + st.lower] if st.lower >= 0 else 0.0
        if st.rock >= 0:  # a storey over a rocking footing: its lever times the rocking
            lo_u += st.lever * y[st.rock]
            lo_v += st.lever * y[n + st.rock]
        return y[st.upper] - lo_u, y[n + st.upper] - lo_v

    def storey_shears(y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Shear of every yielding storey and the rate of its state h."""
        v = np.zeros(ns)
        hdot = np.zeros(ns)
        for s, st in enumerate(storeys):
            v[s], hdot[s] = storey_shear(st, *drift(y, s), y[i_h + s], yld[s])
        return v, hdot

    def link_forces(y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64],
                                                      NDArray[np.float64]]:
        """Force, relative velocity and ż (Maxwell) of every link."""
        f, rate, zdot = np.zeros(len(links)), np.zeros(len(links)), np.zeros(nzl)
        for q, lk in enumerate(links):
            d = y[l_hi[q]] - y[l_lo[q]]
            rate[q] = y[n + l_hi[q]] - y[n + l_lo[q]]
            z = y[i_z + l_zi[q]] if lk.kind == "maxwell" else 0.0
            if lk.kind == "restrainer":
                f[q] = restrainer_force(lk, d, rst_plastic[q], rst_branch[q])
                continue
            f[q] = link_force(lk, d, rate[q], z)
            if lk.kind == "maxwell":
                zdot[l_zi[q]] = maxwell_spring_rate(lk, rate[q], z)
        return f, rate, zdot

    def add_link_loads(p: NDArray[np.float64], f: NDArray[np.float64]) -> None:
        for q in range(len(links)):
            p[l_hi[q]] -= f[q]
            p[l_lo[q]] += f[q]

    def rhs_factory(t0: float, a0: NDArray[np.float64], slope: NDArray[np.float64]
                    ) -> Callable[[float, NDArray[np.float64]], NDArray[np.float64]]:
        def rhs(t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
            u, v = y[:n], y[n:2 * n]
            a_g = a0 + slope * (t - t0)  # the G components
            f = forces(y)
            p = np.zeros(n)
            for c in range(nc):
                np.add.at(p, cdof[c], -cw[c] * f[c])
            vs, hdot = storey_shears(y)
            p_storey = 0.0
            for s, st in enumerate(storeys):
                storey_load(p, st, vs[s])
                p_storey += vs[s] * drift(y, s)[1]
            fl, rl, zdot = link_forces(y)
            add_link_loads(p, fl)
            acc = -minv_k @ u - minv_c @ v + minv @ p - r[:, 0] * a_g[0]
            p_in = -(v @ mr[:, 0]) * a_g[0]  # input power −u̇ᵀ M R a_g
            for g in range(1, a_g.size):
                acc -= r[:, g] * a_g[g]
                p_in -= (v @ mr[:, g]) * a_g[g]
            rate = np.array([kin(y, c)[1] for c in range(nc)])
            return np.concatenate([v, acc, hdot, zdot, [p_in, v @ (C @ v), p_storey,
                                                        fl @ rl], f * rate])
        return rhs

    def make_events() -> list[StopEvent]:
        """Terminal events, each tagged (kind, index)."""
        evs = []
        for c in range(nc):
            def ev(t: float, y: NDArray[np.float64], c: int = c) -> float:
                return kin(y, c)[0]
            broken = slips[c] == np.inf
            if not (broken and v0s[c] == 0.0):  # (a broken-off key closing is no impact)
                evs.append(StopEvent(ev, 1.0 if v0s[c] == 0.0 else -1.0, ("gap", c, 0)))
            if v0s[c] > 0.0 and fracture[c] is not None and not broken:
                def evf(t: float, y: NDArray[np.float64], c: int = c,
                        du: float = fracture[c]) -> float:  # type: ignore[assignment]
                    return kin(y, c)[0] - du
                evs.append(StopEvent(evf, 1.0, ("fracture", c, 0)))
            if v0s[c] > 0.0:
                def evr(t: float, y: NDArray[np.float64], c: int = c) -> float:
                    return kin(y, c)[1]
                evs.append(StopEvent(evr, -1.0 if phase[c] > 0 else 1.0, ("rate", c, 0)))
                release_c = release[c]
                if release_c is not None:
                    def evc(t: float, y: NDArray[np.float64], c: int = c,
                            release_c: Callable[[float, float], float] = release_c) -> float:
                        return release_c(*kin(y, c))
                    evs.append(StopEvent(evc, 1.0 if released[c] else -1.0, ("release", c, 0)))
        for s, st in enumerate(storeys):
            if st.kind == "bilinear" and yld[s] == 0:
                for sign in (1.0, -1.0):
                    def evy(t: float, y: NDArray[np.float64], s: int = s, sign: float = sign,
                            st: Storey = st) -> float:
                        d = drift(y, s)[0]
                        return sign * (y[i_h + s] - st.b * st.k * d) - (1.0 - st.b) * st.fy
                    evs.append(StopEvent(evy, 1.0, ("yield", s, int(sign))))
            elif st.kind == "bilinear":
                # leaving the yield branch: the drift rate changes sign
                def evu(t: float, y: NDArray[np.float64], s: int = s) -> float:
                    return drift(y, s)[1]
                evs.append(StopEvent(evu, -1.0 if yld[s] > 0 else 1.0, ("unload", s, 0)))
            # (Bouc–Wen: ż is continuous where ḋ changes sign, only its slope jumps; the
            # tight-tolerance steps go through it without an event)
        for q, lk in enumerate(links):
            if lk.kind == "viscous" and lk.alpha != 1.0:
                # a fluid damper's force has an unbounded slope where its rate changes sign:
                # an event where it next does (the way it is going now, or, at a rate of
                # ~0 — at rest, or just after such an event — the way it is accelerating)
                going = float(np.sign(y[n + l_hi[q]] - y[n + l_lo[q]]))
                if abs(y[n + l_hi[q]] - y[n + l_lo[q]]) < 1e-9 * v_scale:
                    dy = rhs(t, y)
                    going = float(np.sign(dy[n + l_hi[q]] - dy[n + l_lo[q]]))
                if going == 0:
                    continue

                def evl(t: float, y: NDArray[np.float64], q: int = q) -> float:
                    return y[n + l_hi[q]] - y[n + l_lo[q]]
                evs.append(StopEvent(evl, -going, ("link", q, 0)))
            if lk.kind == "restrainer":
                for w, (after, _, way) in enumerate(restrainer_switches(
                        lk, 0.0, rst_plastic[q], rst_branch[q])):
                    def evs_r(t: float, y: NDArray[np.float64], q: int = q, w: int = w,
                              lk: Link = lk) -> float:
                        d = y[l_hi[q]] - y[l_lo[q]]
                        return restrainer_switches(lk, d, rst_plastic[q], rst_branch[q])[w][1]
                    evs.append(StopEvent(evs_r, float(way), ("restrainer", q, after)))
                if rst_branch[q] == RESTRAINER_YIELDING:
                    def evu_r(t: float, y: NDArray[np.float64], q: int = q) -> float:
                        return y[n + l_hi[q]] - y[n + l_lo[q]]
                    evs.append(StopEvent(evu_r, -1.0, ("rst_unload", q, 0)))
        return evs

    y = np.zeros(i_e + 4 + nc)
    y[: 2 * n] = initial_state(model, initial_displacement, initial_velocity)
    for q, lk in enumerate(links):
        if lk.kind == "restrainer":
            opening = y[l_hi[q]] - y[l_lo[q]]
            if opening > lk.yield_elongation:
                raise ValueError("initial_displacement: the reference starts restrainers "
                                 "within their elastic range")
            rst_branch[q] = RESTRAINER_TAUT if opening > lk.slack else RESTRAINER_SLACK
    if ns and np.any(y[:n] != 0.0):
        raise ValueError("initial_displacement: the reference starts yielding storeys at rest "
                         "only")
    out = np.zeros((nt, y.size))
    out[0] = y
    below = floor_below(model)

    def floor_values(yt: NDArray[np.float64]) -> NDArray[np.float64]:
        """|u|, |drift| and |absolute acceleration| of every floor at the states ``yt``
        (columns): an array (3, N, n_times)."""
        u, v = yt[:n], yt[n:2 * n]
        lower = np.where(below[:, None] >= 0, u[np.maximum(below, 0)], 0.0)
        p = np.zeros_like(u)
        for k in range(yt.shape[1]):
            f = forces(yt[:, k])
            for c in range(nc):
                np.add.at(p[:, k], cdof[c], -cw[c] * f[c])
            vs = storey_shears(yt[:, k])[0]
            for s, st in enumerate(storeys):
                storey_load(p[:, k], st, vs[s])
            add_link_loads(p[:, k], link_forces(yt[:, k])[0])
        a_abs = -minv_k @ u - minv_c @ v + minv @ p
        return np.abs(np.stack([u, u - lower, a_abs]))

    peaks = np.zeros((n, 6))  # |u|, |drift|, |absolute acceleration|, each with its time
    peaks[:, 0::2] = floor_values(y[:, None])[:, :, 0].T
    f_out = np.zeros((nt, nc))
    vs_out = np.zeros((nt, ns))
    lf_out = np.zeros((nt, len(links)))
    stored = np.zeros(nt)
    impacts: list[list[float]] = []
    open_row = [-1] * nc
    w_start = np.zeros(nc)
    events = 0
    start = time.perf_counter()
    # record intervals: integrate [t_i, t_{i+1}] where a_g is linear (its samples at the ends)
    t_last = float(t_grid[-1])
    i = 0
    while i * rec_dt < t_last - 1e-9 * step:
        t0, t1 = i * rec_dt, min((i + 1) * rec_dt, t_last)
        a0 = ground_knots[i]
        slope = (ground_knots[i + 1] - ground_knots[i]) / rec_dt
        i += 1
        rhs = rhs_factory(t0, a0, slope)
        t = t0
        while True:
            evs = make_events()
            sol = solve_ivp(rhs, (t, t1), y, method="DOP853", rtol=rtol, atol=atol, events=evs,
                            dense_output=True)
            t_stop = float(sol.t[-1])
            # outputs on the grid inside this segment
            k_lo = int(np.ceil(t / step - 1e-9))
            k_hi = min(int(np.floor(t_stop / step + 1e-9)), nt - 1)
            for k in range(k_lo, k_hi + 1):
                yk = sol.sol(t_grid[k])
                out[k] = yk
                f_out[k] = forces(yk)
                vs_out[k] = storey_shears(yk)[0]
                lf_out[k] = link_forces(yk)[0]
                stored[k] = sum(stored_energy(laws[c], kin(yk, c)[0], slips[c])
                                for c in range(nc) if v0s[c] > 0.0)
            # peak force over the segment for every closed contact
            for c in range(nc):
                if v0s[c] > 0.0 and open_row[c] >= 0 and t_stop > t:
                    def neg_f(s: float, c: int = c) -> float:
                        ys = sol.sol(s)
                        return -forces(ys)[c]
                    ts = np.linspace(t, t_stop, 64)
                    fs = np.array([-neg_f(s) for s in ts])
                    kmax = int(np.argmax(fs))
                    best, t_best = fs[kmax], ts[kmax]
                    if len(ts) > 1:
                        res = minimize_scalar(neg_f, bounds=_around(ts, kmax),
                                              method="bounded", options={"xatol": 1e-12})
                        if -res.fun > best:
                            best, t_best = -res.fun, float(res.x)
                    row = impacts[open_row[c]]
                    if best > row[4]:
                        row[4], row[5] = best, t_best
            if t_stop > t:
                _update_peaks(peaks, sol.sol, t, t_stop, floor_values)
            y = sol.y[:, -1].copy()
            t = t_stop
            if sol.status != 1:
                break
            # which event fired first?
            fired = [(float(te[0]), k) for k, te in enumerate(sol.t_events) if len(te)]
            _, first = min(fired)
            y_before = sol.y[:, 0]
            y = sol.y_events[first][0].copy()
            # A velocity that changes sign can end two things at one instant: the rate of a
            # contact with a wall and the drift rate of the storey below the floor that
            # strikes it are one velocity. solve_ivp stops at the first of two coincident
            # events only, and at the restart the other's function is 0 ± round-off: on the
            # wrong side of 0 its crossing would be missed (an isolator left on its yield
            # branch while it unloads). So every rate event that was on its way to 0 and is
            # there now (to 1e-12 of the velocity scale) is handled here too.
            handled = [first] + [
                k for k, ev in enumerate(evs)
                if k != first and ev.tag[0] in ("rate", "unload", "link", "rst_unload")
                and abs(ev(t, y)) <= 1e-12 * v_scale
                and np.sign(ev(t, y_before)) == -ev.direction]
            for kev in handled:
                events += 1
                tag = evs[kev].tag
                if tag[0] == "link":
                    pass  # (a fluid damper's rate changed sign: the step restarts there)
                elif tag[0] == "restrainer":
                    rst_branch[tag[1]] = tag[2]
                elif tag[0] == "rst_unload":
                    # off the backbone: the cable is longer by what it yielded
                    q = tag[1]
                    lk = links[q]
                    d = y[l_hi[q]] - y[l_lo[q]]
                    f = restrainer_force(lk, d, 0.0, RESTRAINER_YIELDING)
                    rst_plastic[q] = d - float(lk.slack) - f / spring_stiffness(lk)  # type: ignore[arg-type]
                    rst_branch[q] = RESTRAINER_TAUT
                elif tag[0] == "yield":
                    yld[tag[1]] = tag[2]
                elif tag[0] == "unload":
                    yld[tag[1]] = 0
                elif tag[0] == "release":
                    # the clipped force reaches zero (the impact ends there: end time and
                    # restitution) or rises from it again (the impact goes on)
                    c = tag[1]
                    released[c] = not released[c]
                    row = impacts[open_row[c]]
                    row[2] = t if released[c] else np.nan
                    row[7] = max(-kin(y, c)[1], 0.0) / v0s[c] if released[c] else np.nan
                elif tag[0] == "fracture":
                    # the key breaks off: its force drops to zero for good, its impact ends
                    c = tag[1]
                    d, rate = kin(y, c)
                    row = impacts[open_row[c]]
                    row[6] = max(row[6], d)
                    if np.isnan(row[2]):
                        row[2] = t
                    slips[c] = np.inf
                elif tag[0] == "gap" and v0s[tag[1]] == 0.0:
                    c = tag[1]
                    d, rate = kin(y, c)
                    v0s[c] = max(rate, V0_MIN)  # contract step 3: the closing velocity
                    slips[c] = slips[c] if keeps_set(laws[c]) else 0.0
                    phase[c] = 1
                    f0 = contact_force(laws[c], d, rate, v0s[c], slips[c])[0]
                    impacts.append([c, t, np.nan, v0s[c], f0, t, 0.0, np.nan, np.nan])
                    open_row[c] = len(impacts) - 1
                    w_start[c] = y[i_e + 4 + c]
                elif tag[0] == "gap":
                    c = tag[1]
                    d, rate = kin(y, c)
                    row = impacts[open_row[c]]
                    if np.isnan(row[2]):  # (not already ended by a release)
                        row[2] = t
                        row[7] = max(-rate, 0.0) / v0s[c]
                    row[8] = y[i_e + 4 + c] - w_start[c]
                    open_row[c] = -1
                    v0s[c] = 0.0
                    slips[c] = slips[c] if keeps_set(laws[c]) else 0.0
                    phase[c] = 0
                    released[c] = False
                else:
                    c = tag[1]
                    d, rate = kin(y, c)
                    intact = not math.isinf(slips[c])  # (past its break a key's impact is over)
                    slips[c] = contact_force(laws[c], d, rate, v0s[c], slips[c])[1]
                    if intact:
                        impacts[open_row[c]][6] = max(impacts[open_row[c]][6], d)
                    phase[c] = -phase[c]
            if t >= t1:
                break
        # commit states of closed contacts at the interval end (contract step 4)
        for c in range(nc):
            if v0s[c] > 0.0:
                d, rate = kin(y, c)
                intact = not math.isinf(slips[c])
                slips[c] = contact_force(laws[c], d, rate, v0s[c], slips[c])[1]
                if intact:
                    impacts[open_row[c]][6] = max(impacts[open_row[c]][6], d)
    wall = time.perf_counter() - start
    for q, lk in enumerate(links):
        if lk.kind == "restrainer" and rst_branch[q] == RESTRAINER_YIELDING:
            # (still on the backbone: its plastic elongation so far, as if it unloaded now)
            opening = y[l_hi[q]] - y[l_lo[q]]
            rst_plastic[q] = (opening - float(lk.slack)  # type: ignore[arg-type]
                              - restrainer_force(lk, opening, 0.0, RESTRAINER_YIELDING)
                              / spring_stiffness(lk))
    u_out = out[:, :n]
    v_out = out[:, n:2 * n]
    acc = np.empty((nt, n))
    for k in range(nt):
        p = np.zeros(n)
        for c in range(nc):
            np.add.at(p, cdof[c], -cw[c] * f_out[k, c])
        for s, st in enumerate(storeys):
            storey_load(p, st, vs_out[k, s])
        add_link_loads(p, lf_out[k])
        acc[k] = -minv_k @ u_out[k] - minv_c @ v_out[k] + minv @ p
    recov = np.zeros(nt)
    for s, st in enumerate(storeys):
        storey_drift = (u_out[:, st.upper] - (u_out[:, st.lower] if st.lower >= 0 else 0.0)
                        - (st.lever * u_out[:, st.rock] if st.rock >= 0 else 0.0))
        recov += storey_recoverable(st, storey_drift, out[:, i_h + s])
    recov_links = np.zeros(nt)
    for q, lk in enumerate(links):
        if lk.kind == "restrainer":
            recov_links += lf_out[:, q] ** 2 / (2.0 * spring_stiffness(lk))  # F²/(2k)
            continue
        z = out[:, i_z + l_zi[q]] if lk.kind == "maxwell" else np.zeros(nt)
        recov_links += link_recoverable(lk, u_out[:, l_hi[q]] - u_out[:, l_lo[q]], z)
    energy = np.zeros((nt, len(ENERGY_NAMES)))
    energy[:, 0] = out[:, i_e]
    energy[:, 1] = 0.5 * np.einsum("ki,ij,kj->k", v_out, M, v_out)
    energy[:, 2] = 0.5 * np.einsum("ki,ij,kj->k", u_out, K, u_out) + recov + recov_links
    energy[:, 3] = out[:, i_e + 1]
    energy[:, 4] = out[:, i_e + 4:].sum(axis=1)
    energy[:, 5] = stored
    energy[:, 6] = out[:, i_e + 2] - recov
    energy[:, 7] = out[:, i_e + 3] - recov_links
    pen = model.contact_penetration(u_out)
    imp = np.array(impacts, dtype=float).reshape(-1, len(IMPACT_COLUMNS))
    stats = SolverStats(solver="scipy-reference", rtol=rtol, events=events, wall_time=wall)
    return Result(model=model, motion=motion, dt=step, ground=ground, displacement=u_out,
                  velocity=v_out, abs_acceleration=acc, penetration=pen, contact_force=f_out,
                  energy=energy, impact_array=imp, stats=stats, yielding_shear=vs_out,
                  final_z=np.array([out[-1, i_h + s] for s, st in enumerate(storeys)
                                    if st.kind != "bilinear"]
                                   + [out[-1, i_z + l_zi[q]] if lk.kind == "maxwell"
                                      else rst_plastic[q] for q, lk in enumerate(links)
                                      if lk.has_internal_variable]),
                  link_force=lf_out,
                  located_peaks=peaks)


def _around(ts: NDArray[np.float64], k: int) -> tuple[float, float]:
    """The samples either side of sample k, within the segment (a bracket for a search)."""
    return float(ts[max(k - 1, 0)]), float(ts[min(k + 1, ts.size - 1)])


def _update_peaks(peaks: NDArray[np.float64],
                  dense: Callable[[NDArray[np.float64]], NDArray[np.float64]], t0: float,
                  t1: float, values: Callable[[NDArray[np.float64]], NDArray[np.float64]]
                  ) -> None:
    """Largest |u|, |drift|, |absolute acceleration| of every floor over ``[t0, t1]`` from
    the dense output ``dense``: 64 samples, then a bounded scalar search (to 10⁻¹² s) around
    the largest, as for the peak contact forces."""
    ts = np.linspace(t0, t1, 64)
    vals = values(dense(ts))  # (3, N, 64)
    for q in range(3):
        for i in range(vals.shape[1]):
            kmax = int(np.argmax(vals[q, i]))
            best, t_best = float(vals[q, i, kmax]), float(ts[kmax])
            # refine only where the samples come within 1 % of the peak so far (64 samples of
            # a step under the record's sample interval miss a smooth peak by far less); a
            # largest sample at an end of the segment too (the peak may lie just inside it)
            if t1 > t0 and best >= 0.99 * peaks[i, 2 * q]:
                res = minimize_scalar(lambda s, q=q, i=i: -values(dense(np.array([s])))[q, i, 0],
                                      bounds=_around(ts, kmax), method="bounded",
                                      options={"xatol": 1e-12})
                if -res.fun > best:
                    best, t_best = float(-res.fun), float(res.x)
            if best > peaks[i, 2 * q]:
                peaks[i, 2 * q] = best
                peaks[i, 2 * q + 1] = t_best
