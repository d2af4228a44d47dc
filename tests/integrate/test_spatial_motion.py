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
from pounding.devices import Link

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


def _ground_motion_exact(record: GroundMotion):
    """The ground's displacement [m] and velocity [m/s] at any time, from rest, for the
    record linear between its samples (zero after it): the exact double integral, so the
    reference below integrates only the buildings, whose forcing is smooth."""
    dt, a = record.dt, np.append(record.accel, 0.0)
    v = np.concatenate([[0.0], np.cumsum(0.5 * dt * (a[:-1] + a[1:]))])
    u = np.concatenate([[0.0], np.cumsum(dt * v[:-1] + dt * dt * (2 * a[:-1] + a[1:]) / 6)])

    def at(t: float) -> tuple[float, float]:
        k = min(int(t / dt), a.size - 2)
        s, slope = t - k * dt, (a[k + 1] - a[k]) / dt
        return (u[k] + v[k] * s + a[k] * s * s / 2 + slope * s ** 3 / 6,
                v[k] + a[k] * s + slope * s * s / 2)

    return at


def _absolute_reference(m: tuple[float, float], k: tuple[float, float],
                        c: tuple[float, float], k_contact: float, gap: float,
                        grounds: list[GroundMotion], t_end: float,
                        t_out: np.ndarray) -> np.ndarray:
    """Two SDOF buildings in absolute coordinates X_i on grounds u_g,i (their exact motion,
    :func:`_ground_motion_exact`), a linear spring k_contact in compression across
    δ = X_1 − X_2 − gap: solve_ivp, restarted at every δ = 0; the state
    [X_1, X_2, V_1, V_2, u_1, u_2, w_1, w_2] at the times ``t_out``."""
    ground = [_ground_motion_exact(g) for g in grounds]

    def rhs(t: float, y: np.ndarray, closed: bool) -> list[float]:
        X1, X2, V1, V2 = y
        (u1, w1), (u2, w2) = ground[0](t), ground[1](t)
        f = k_contact * (X1 - X2 - gap) if closed else 0.0
        a1 = (-k[0] * (X1 - u1) - c[0] * (V1 - w1) - f) / m[0]
        a2 = (-k[1] * (X2 - u2) - c[1] * (V2 - w2) + f) / m[1]
        return [V1, V2, a1, a2]

    def closing(t: float, y: np.ndarray, closed: bool) -> float:
        return y[0] - y[1] - gap

    def opening(t: float, y: np.ndarray, closed: bool) -> float:
        return y[0] - y[1] - gap

    closing.terminal = opening.terminal = True  # type: ignore[attr-defined]
    closing.direction, opening.direction = 1.0, -1.0  # type: ignore[attr-defined]
    t, y = 0.0, np.zeros(4)
    out = np.zeros((8, t_out.size))
    closed = False
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), y, args=(closed,),
                        events=opening if closed else closing, rtol=1e-11, atol=1e-14,
                        method="DOP853", max_step=float(grounds[0].dt), dense_output=True)
        t_new = float(sol.t[-1])
        inside = (t_out >= t) & (t_out <= t_new)
        if inside.any():
            out[:4, inside] = sol.sol(t_out[inside])
        t, y = t_new, sol.y[:, -1].copy()
        if sol.status == 1:
            closed = not closed
    for q, tq in enumerate(t_out):
        (out[4, q], out[6, q]), (out[5, q], out[7, q]) = ground[0](tq), ground[1](tq)
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
    for i in range(2):  # (measured 3.8e-9)
        assert np.max(np.abs(res.displacement[:, i] - rel[i])) < 1e-7 * peak, i
    # the penetration seen by the contact includes the grounds' relative displacement
    delta = yy[0] - yy[1] - 0.01
    f_ref = k_c * np.maximum(delta, 0.0)  # (measured 6.5e-9)
    assert np.max(np.abs(res.contact_force[:, 0] - f_ref)) < 1e-7 * f_ref.max()


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
    on its own ground (their exact motion, :func:`_ground_motion_exact`), in absolute
    coordinates (the building X on u_g, the walls at u_l and u_r): linear springs
    k_contact in compression across δ_l = u_l − X − gap_l and δ_r = X − u_r − gap_r;
    solve_ivp restarted at every contact event; [X, V, u_g, v_g, u_l, v_l, u_r, v_r] at
    ``t_out``."""
    m = 2e5
    k, c = A.stiffness_matrix()[0, 0], A.damping_matrix()[0, 0]
    ground = [_ground_motion_exact(g) for g in grounds]

    def rhs(t: float, y: np.ndarray, closed: tuple[bool, bool]) -> list[float]:
        X, V = y
        (u, w), (ul, _), (ur, _) = (g(t) for g in ground)
        f_l = k_contact * (ul - X - gaps[0]) if closed[0] else 0.0
        f_r = k_contact * (X - ur - gaps[1]) if closed[1] else 0.0
        return [V, (-k * (X - u) - c * (V - w) + f_l - f_r) / m]

    def left(t: float, y: np.ndarray, closed: tuple[bool, bool]) -> float:
        return ground[1](t)[0] - y[0] - gaps[0]

    def right(t: float, y: np.ndarray, closed: tuple[bool, bool]) -> float:
        return y[0] - ground[2](t)[0] - gaps[1]

    def watch(g, is_closed: bool):  # type: ignore[no-untyped-def]
        """δ of a contact, crossing down if it is closed, up if open."""
        def event(t: float, y: np.ndarray, closed: tuple[bool, bool]) -> float:
            return g(t, y, closed)
        event.terminal = True  # type: ignore[attr-defined]
        event.direction = -1.0 if is_closed else 1.0  # type: ignore[attr-defined]
        return event

    t, y, closed = 0.0, np.zeros(2), (False, False)
    out = np.zeros((8, t_out.size))
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), y, args=(closed,),
                        events=[watch(left, closed[0]), watch(right, closed[1])],
                        rtol=1e-11, atol=1e-14, method="DOP853",
                        max_step=float(grounds[0].dt), dense_output=True)
        t_new = float(sol.t[-1])
        inside = (t_out >= t) & (t_out <= t_new)
        if inside.any():
            out[:2, inside] = sol.sol(t_out[inside])
        y = sol.y[:, -1].copy()
        if sol.status == 1:
            hit = 0 if sol.t_events[0].size else 1
            closed = (not closed[0], closed[1]) if hit == 0 else (closed[0], not closed[1])
        t = t_new
    for q, tq in enumerate(t_out):
        (out[2, q], out[3, q]), (out[4, q], out[5, q]), (out[6, q], out[7, q]) = (
            g(tq) for g in ground)
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
    # (measured 4.4e-9 and 9.5e-9)
    assert np.max(np.abs(res.displacement[:, 0] - rel)) < 1e-7 * np.max(np.abs(rel))
    f_l = k_c * np.maximum(yy[4] - yy[0] - gaps[0], 0.0)
    f_r = k_c * np.maximum(yy[0] - yy[6] - gaps[1], 0.0)
    assert f_l.max() > 0 and f_r.max() > 0  # (both walls struck)
    for col, f_ref in ((0, f_l), (1, f_r)):
        assert np.max(np.abs(res.contact_force[:, col] - f_ref)) < 1e-7 * f_ref.max(), col
    assert res.energy_balance_error < 1e-9
    # on the building's ground (no walls' own): a different run
    same = simulate(model, SpatialMotion([w.records[0]]), dt=dt, duration=4.0, rtol=1e-10)
    assert np.max(np.abs(same.displacement[:, 0] - res.displacement[:, 0])) > 1e-3 * np.max(
        np.abs(rel))
    with pytest.raises(ValueError, match="no wall on its right"):
        simulate(PoundingModel([A], [], ContactSpec("linear-spring", k=k_c), walls=walls[:1]),
                 w, dt=dt, duration=1.0)


def _linked_reference(link: tuple[float, float, float], grounds: list[GroundMotion],
                      t_end: float, t_out: np.ndarray) -> np.ndarray:
    """Buildings A and B (SDOF) in absolute coordinates X on their own grounds (each
    ground's motion exact, :func:`_ground_motion_exact`), joined by a link of stiffness k
    and dashpot c (slack s = 0: a Kelvin link; s > 0 and c = 0: an elastic cable that pulls
    only, F = k (Δ − s) for Δ = X_B − X_A > s); solve_ivp restarted where the cable
    tightens or slackens; [X_A, X_B, V_A, V_B, u_A, u_B, w_A, w_B] at ``t_out``."""
    k_l, c_l, slack = link
    m = (2e5, 3e5)
    k = (A.stiffness_matrix()[0, 0], B.stiffness_matrix()[0, 0])
    c = (A.damping_matrix()[0, 0], B.damping_matrix()[0, 0])
    ground = [_ground_motion_exact(g) for g in grounds]
    cable = slack > 0.0

    def rhs(t: float, y: np.ndarray, taut: bool) -> list[float]:
        X1, X2, V1, V2 = y
        (u1, w1), (u2, w2) = ground[0](t), ground[1](t)
        d, dd = X2 - X1, V2 - V1
        f = (k_l * (d - slack) if taut else 0.0) if cable else k_l * d + c_l * dd
        a1 = (-k[0] * (X1 - u1) - c[0] * (V1 - w1) + f) / m[0]
        a2 = (-k[1] * (X2 - u2) - c[1] * (V2 - w2) - f) / m[1]
        return [V1, V2, a1, a2]

    def tightens(t: float, y: np.ndarray, taut: bool) -> float:
        return y[1] - y[0] - slack

    def slackens(t: float, y: np.ndarray, taut: bool) -> float:
        return y[1] - y[0] - slack

    tightens.terminal = slackens.terminal = True  # type: ignore[attr-defined]
    tightens.direction, slackens.direction = 1.0, -1.0  # type: ignore[attr-defined]
    t, y, taut = 0.0, np.zeros(4), False
    out = np.zeros((8, t_out.size))
    while t < t_end:
        event = (slackens if taut else tightens) if cable else None
        sol = solve_ivp(rhs, (t, t_end), y, args=(taut,), events=event, rtol=1e-10,
                        atol=1e-13, method="DOP853", dense_output=True,
                        max_step=float(grounds[0].dt))
        t_new = float(sol.t[-1])
        inside = (t_out >= t) & (t_out <= t_new)
        if inside.any():
            out[:4, inside] = sol.sol(t_out[inside])
        t, y = t_new, sol.y[:, -1].copy()
        if sol.status == 1:
            taut = not taut
    for q, tq in enumerate(t_out):
        (out[4, q], out[6, q]), (out[5, q], out[7, q]) = ground[0](tq), ground[1](tq)
    return out


@pytest.mark.parametrize("kind", ["kelvin", "restrainer"])
def test_a_link_between_buildings_on_different_grounds(kind: str) -> None:
    """A Kelvin link and a cable restrainer (slack, elastic) joining two buildings whose
    grounds differ by 0.1 s of wave passage, no pounding (a wide gap): the buildings' motion,
    the link's elongation (with the grounds' offset) and force against the absolute
    reference, and the energy balance with the grounds' work through the link."""
    dt = 0.005
    t = np.arange(0, 4.0 + dt / 2, dt)
    sine = GroundMotion(dt, 3.0 * np.sin(2 * np.pi * 1.5 * t) * np.exp(-0.2 * t), "sine")
    w = wave_passage(sine, [0.0, 40.0], apparent_velocity=400.0)  # τ = 0.1 s
    if kind == "kelvin":
        link, params = Link(("B1F1", "B2F1"), "kelvin", k=2e6, c=1e5), (2e6, 1e5, 0.0)
    else:
        link = Link(("B1F1", "B2F1"), "restrainer", k=5e6, slack=0.01, yield_force=1e9)
        params = (5e6, 0.0, 0.01)
    model = PoundingModel([A, B], [1.0], KV, devices=[link])
    res = simulate(model, w, dt=dt, duration=4.0, rtol=1e-10)
    yy = _linked_reference(params, list(w.records), 4.0, res.time)
    rel = [yy[0] - yy[4], yy[1] - yy[5]]
    peak = np.max(np.abs(rel))
    for i in range(2):  # (measured 3e-11 of the peak)
        assert np.max(np.abs(res.displacement[:, i] - rel[i])) < 1e-8 * peak, i
    elongation = yy[1] - yy[0]
    assert np.max(np.abs(res.link_displacement[:, 0] - elongation)) < 1e-8 * np.max(
        np.abs(elongation))
    # (the grounds' offset is a part of it the relative motion alone would miss)
    assert np.max(np.abs(elongation - (rel[1] - rel[0]))) > 0.1 * np.max(np.abs(elongation))
    k_l, c_l, slack = params
    f_ref = (k_l * np.maximum(elongation - slack, 0.0) if slack > 0
             else k_l * elongation + c_l * (yy[3] - yy[2]))
    assert np.max(np.abs(res.link_force[:, 0] - f_ref)) < 1e-7 * np.max(np.abs(f_ref))
    if slack > 0:
        assert f_ref.max() > 0 and np.any(elongation < slack)  # (taut and slack in turn)
    assert res.energy_balance_error < 1e-8
