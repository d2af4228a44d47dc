"""Spatially varying ground motion in time histories: each building on its own ground, the
contacts seeing the grounds' relative displacement; against the shifted record, the uniform
run, a SciPy solution written here in absolute coordinates, and the energy balance."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotion, el_centro
from pounding.ground_motion.spatial import SpatialMotion, delayed, wave_passage
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.wall import MoatWall

A = ShearBuilding.sdof(2e5, period=0.5)
B = ShearBuilding.sdof(3e5, period=1.0)
KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


def test_a_delay_of_whole_samples_shifts_the_record_exactly() -> None:
    ec = el_centro()
    d = delayed(ec, 7 * ec.dt)
    assert d.npts == ec.npts + 7 and np.array_equal(d.accel[7:], ec.accel)
    assert not np.any(d.accel[:7])
    w = wave_passage(ec, [0.0, 30.0, 45.0], apparent_velocity=-1500.0)  # toward −x
    assert w.delays == pytest.approx((0.03, 0.01, 0.0))
    assert np.array_equal(w.records[2].accel[: ec.npts], ec.accel)
    assert np.array_equal(w.records[0].accel[3: 3 + ec.npts], ec.accel)


def test_one_record_for_all_is_the_uniform_run() -> None:
    model = PoundingModel([A, B], [0.02], KV)
    ec = el_centro()
    r0 = simulate(model, ec, duration=15.0)
    r1 = simulate(model, SpatialMotion([ec, ec]), duration=15.0)
    assert r0.n_impacts == r1.n_impacts > 0
    assert np.array_equal(r0.displacement, r1.displacement)


def test_apart_each_building_responds_to_its_own_shifted_record() -> None:
    """Never touching (a 10 m gap): building 2 under the record 0.3 s later moves as it does
    alone under the record, 0.3 s later — the exact steps on the same inputs. (The record
    starts from rest: a first sample that is not zero is a jump at t = 0, and after zeros
    a ramp over one step.)"""
    raw = el_centro()
    ec = GroundMotion(raw.dt, np.concatenate([[0.0], raw.accel[:1200]]), "El Centro")
    model = PoundingModel([A, B], [10.0], KV)
    w = wave_passage(ec, [0.0, 60.0], apparent_velocity=200.0)  # τ = 0.3 s = 30 samples
    res = simulate(model, w, dt=ec.dt, duration=12.0)
    alone = simulate(PoundingModel([B], [], KV), ec, dt=ec.dt, duration=12.0)
    u2 = res.displacement[:, 1]
    peak = np.max(np.abs(alone.displacement))
    assert np.max(np.abs(u2[30:] - alone.displacement[:-30, 0])) < 1e-12 * peak
    assert not np.any(u2[:30])
    first = simulate(PoundingModel([A], [], KV), ec, dt=ec.dt, duration=12.0)
    assert np.max(np.abs(res.displacement[:, 0] - first.displacement[:, 0])) < 1e-12 * peak


def _absolute_reference(m: tuple[float, float], k: tuple[float, float],
                        c: tuple[float, float], k_contact: float, gap: float,
                        grounds: list[GroundMotion], t_end: float,
                        t_out: np.ndarray) -> np.ndarray:
    """Two SDOF buildings in absolute coordinates X_i on grounds u_g,i (integrated here from
    their records, linear between samples), a linear spring k_contact in compression across
    δ = X_1 − X_2 − gap: solve_ivp, restarted at every δ = 0; the state (8, len(t_out)) at
    the times ``t_out`` from each piece's dense output."""
    times = [g.time for g in grounds]
    acc = [g.accel for g in grounds]

    def ag(i: int, t: float) -> float:
        return float(np.interp(t, times[i], acc[i], right=0.0))

    def rhs(t: float, y: np.ndarray, closed: bool) -> list[float]:
        X1, X2, V1, V2, u1, u2, w1, w2 = y
        f = k_contact * (X1 - X2 - gap) if closed else 0.0
        a1 = (-k[0] * (X1 - u1) - c[0] * (V1 - w1) - f) / m[0]
        a2 = (-k[1] * (X2 - u2) - c[1] * (V2 - w2) + f) / m[1]
        return [V1, V2, a1, a2, w1, w2, ag(0, t), ag(1, t)]

    def closing(t: float, y: np.ndarray, closed: bool) -> float:
        return y[0] - y[1] - gap

    def opening(t: float, y: np.ndarray, closed: bool) -> float:
        return y[0] - y[1] - gap

    closing.terminal = opening.terminal = True  # type: ignore[attr-defined]
    closing.direction, opening.direction = 1.0, -1.0  # type: ignore[attr-defined]
    t, y = 0.0, np.zeros(8)
    out = np.zeros((8, t_out.size))
    closed = False
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), y, args=(closed,),
                        events=opening if closed else closing, rtol=1e-11, atol=1e-14,
                        method="DOP853", max_step=float(grounds[0].dt), dense_output=True)
        t_new = float(sol.t[-1])
        inside = (t_out >= t) & (t_out <= t_new)
        out[:, inside] = sol.sol(t_out[inside])
        t, y = t_new, sol.y[:, -1].copy()
        if sol.status == 1:
            closed = not closed
    return out


def test_pounding_on_different_grounds_against_an_absolute_reference() -> None:
    """A sine reaching the right building 0.1 s later: the relative displacements, the
    impacts and the contact forces of pounding's run against the reference's."""
    dt = 0.005
    t = np.arange(0, 4.0 + dt / 2, dt)
    sine = GroundMotion(dt, 3.0 * np.sin(2 * np.pi * 1.5 * t) * np.exp(-0.2 * t), "sine")
    w = wave_passage(sine, [0.0, 40.0], apparent_velocity=400.0)  # τ = 0.1 s
    k_c = 5e8
    spec = ContactSpec("linear-spring", k=k_c)
    model = PoundingModel([A, B], [0.01], spec)
    res = simulate(model, w, dt=dt, duration=4.0, rtol=1e-10)
    assert res.n_impacts > 2
    m = (2e5, 3e5)
    k = (A.stiffness_matrix()[0, 0], B.stiffness_matrix()[0, 0])
    c = (A.damping_matrix()[0, 0], B.damping_matrix()[0, 0])
    yy = _absolute_reference(m, k, c, k_c, 0.01, list(w.records), 4.0, res.time)
    # relative to each building's own ground, at pounding's output steps
    rel = [yy[0] - yy[4], yy[1] - yy[5]]
    peak = np.max(np.abs(rel))
    for i in range(2):
        assert np.max(np.abs(res.displacement[:, i] - rel[i])) < 1e-6 * peak, i
    # the penetration seen by the contact includes the grounds' relative displacement
    delta = yy[0] - yy[1] - 0.01
    f_ref = k_c * np.maximum(delta, 0.0)
    assert np.max(np.abs(res.contact_force[:, 0] - f_ref)) < 1e-5 * f_ref.max()


def test_the_energy_balance_closes_with_the_grounds_work() -> None:
    ec = el_centro().trimmed(15.0)
    model = PoundingModel([A, B, ShearBuilding.sdof(2.5e5, period=0.7)], [0.02, 0.015], KV)
    res = simulate(model, wave_passage(ec, [0.0, 25.0, 45.0], 250.0), duration=15.0)
    assert res.n_impacts > 5
    assert res.energy_balance_error < 1e-7


def test_refusals() -> None:
    ec = el_centro()
    with pytest.raises(ValueError, match="one record per building"):
        simulate(PoundingModel([A, B], [0.02], KV), SpatialMotion([ec, delayed(ec, 0.1),
                                                                   ec]))
    with pytest.raises(ValueError, match="one step"):
        SpatialMotion([ec, GroundMotion(0.02, ec.accel[::2])])
    with pytest.raises(ValueError, match="apparent_velocity"):
        wave_passage(ec, [0.0, 1.0], 0.0)


def _walls_reference(k_contact: float, gaps: tuple[float, float],
                     grounds: list[GroundMotion], t_end: float,
                     t_out: np.ndarray) -> np.ndarray:
    """Building A (SDOF) between a wall on each side, the building and the two walls each
    on its own ground, in absolute coordinates (the building X on u_g, the walls at u_l and
    u_r): linear springs k_contact in compression across δ_l = u_l − X − gap_l and
    δ_r = X − u_r − gap_r; solve_ivp restarted at every contact event; the state
    [X, V, u_g, v_g, u_l, v_l, u_r, v_r] at ``t_out``."""
    m = 2e5
    k, c = A.stiffness_matrix()[0, 0], A.damping_matrix()[0, 0]
    times = [g.time for g in grounds]
    acc = [g.accel for g in grounds]

    def ag(i: int, t: float) -> float:
        return float(np.interp(t, times[i], acc[i], right=0.0))

    def rhs(t: float, y: np.ndarray) -> list[float]:
        X, V, u, w, ul, wl, ur, wr = y
        f_l = k_contact * max(ul - X - gaps[0], 0.0)
        f_r = k_contact * max(X - ur - gaps[1], 0.0)
        a = (-k * (X - u) - c * (V - w) + f_l - f_r) / m
        return [V, a, w, ag(0, t), wl, ag(1, t), wr, ag(2, t)]

    def left(t: float, y: np.ndarray) -> float:
        return y[4] - y[0] - gaps[0]

    def right(t: float, y: np.ndarray) -> float:
        return y[0] - y[6] - gaps[1]

    left.terminal = right.terminal = True  # type: ignore[attr-defined]
    t, y = 0.0, np.zeros(8)
    out = np.zeros((8, t_out.size))
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), y, events=[left, right], rtol=1e-11, atol=1e-14,
                        method="DOP853", max_step=float(grounds[0].dt), dense_output=True)
        t_new, y_new = float(sol.t[-1]), sol.y[:, -1].copy()
        if t_new <= t + 1e-12:  # (stopped by the event it started on: step past it)
            sol = solve_ivp(rhs, (t, min(t + 1e-6, t_end)), y, rtol=1e-11, atol=1e-14,
                            method="DOP853", dense_output=True)
            t_new, y_new = float(sol.t[-1]), sol.y[:, -1].copy()
        inside = (t_out >= t) & (t_out <= t_new)
        if inside.any():
            out[:, inside] = sol.sol(t_out[inside])
        t, y = t_new, y_new
    return out


def test_walls_on_their_own_grounds_against_an_absolute_reference() -> None:
    """A building between two walls (an abutment at each end of a bridge), the waves
    reaching the left wall 0.02 s and the right wall 0.04 s after the building: its motion,
    both walls' contact forces and the energy balance against the absolute reference."""
    dt = 0.005
    t = np.arange(0, 4.0 + dt / 2, dt)
    sine = GroundMotion(dt, 3.0 * np.sin(2 * np.pi * 1.5 * t) * np.exp(-0.2 * t), "sine")
    k_c, gaps = 1e8, (0.01, 0.012)
    walls = [MoatWall(height=3.0, gap=gaps[0], side="left"),
             MoatWall(height=3.0, gap=gaps[1], side="right")]
    model = PoundingModel([A], [], ContactSpec("linear-spring", k=k_c), walls=walls)
    w = wave_passage(sine, [0.0, 20.0, 40.0], apparent_velocity=1000.0).with_walls(
        ["left", "right"])
    assert w.delays == (0.0,) and dict(w.wall_delays) == pytest.approx(
        {"left": 0.02, "right": 0.04})
    res = simulate(model, w, dt=dt, duration=4.0, rtol=1e-10)
    yy = _walls_reference(k_c, gaps, [w.records[0], w.walls["left"], w.walls["right"]],
                          4.0, res.time)
    rel = yy[0] - yy[2]
    assert np.max(np.abs(res.displacement[:, 0] - rel)) < 1e-6 * np.max(np.abs(rel))
    f_l = k_c * np.maximum(yy[4] - yy[0] - gaps[0], 0.0)
    f_r = k_c * np.maximum(yy[0] - yy[6] - gaps[1], 0.0)
    assert f_l.max() > 0 and f_r.max() > 0  # (both walls struck)
    for col, f_ref in ((0, f_l), (1, f_r)):
        assert np.max(np.abs(res.contact_force[:, col] - f_ref)) < 2e-6 * f_ref.max(), col
    assert res.energy_balance_error < 1e-9
    # on the building's ground (no walls' own): a different run
    same = simulate(model, SpatialMotion([w.records[0]]), dt=dt, duration=4.0, rtol=1e-10)
    assert np.max(np.abs(same.displacement[:, 0] - res.displacement[:, 0])) > 1e-3 * np.max(
        np.abs(rel))
    with pytest.raises(ValueError, match="no wall on its right"):
        simulate(PoundingModel([A], [], ContactSpec("linear-spring", k=k_c), walls=walls[:1]),
                 w, dt=dt, duration=1.0)
