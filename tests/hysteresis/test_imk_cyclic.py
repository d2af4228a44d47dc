"""The modified IMK hinge laws on cyclic paths, against the published deterioration equations
worked by hand for the first excursions; their hysteretic energy; and the hinge contract.

Ibarra, Medina & Krawinkler (2005), EESD 34(12), with E_t = Λ M_y (Lignos & Krawinkler 2011):

* Eq. (1) ``β_i = (E_i / (E_t − Σ_{j=1..i} E_j))^c``;
* Eqs. (3), (4) ``M_y,i = (1 − β_s,i D) M_y,i−1``, ``K_s,i = (1 − β_s,i D) K_s,i−1``;
* Eq. (5) ``M_ref,i = (1 − β_c,i D) M_ref,i−1`` (the post-capping line's moment at θ = 0);
* Eq. (6) ``K_u,i = (1 − β_k,i) K_u,i−1`` at each reversal;
* Eq. (7) ``θ_t,i = (1 + β_a,i D) θ_t,i−1`` (the peak-oriented target rotation).

Each excursion's energy ``E_i`` is the area under the hand-built path between two zero-moment
crossings (the trapezoid rule on its corners, exact for straight segments). The hand-worked
tests call the laws only for the moments they compare.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from pounding.hysteresis.hinges import HingeLaw, HingeState, moment_path
from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented
from pounding.structure.frame import Frame, FrameHinge
from pounding.structure.frame_analysis import pushover

K0, MY, THETA_P, THETA_PC, MC_MY = 1.0e8, 3.0e5, 0.03, 0.2, 1.1
THETA_Y = MY / K0  # 0.003 rad
MC = MC_MY * MY
KS = (MC - MY) / THETA_P  # post-yield slope, 1e6 N·m/rad
THETA_C = THETA_Y + THETA_P
E_T = 1.0 * MY  # Λ = 1 rad


def work(corners: list[tuple[float, float]]) -> float:
    """∫M dθ along straight segments through the corners (θ, M)."""
    return sum(0.5 * (m0 + m1) * (t1 - t0)
               for (t0, m0), (t1, m1) in itertools.pairwise(corners))


def test_basic_strength_deterioration_over_three_excursions() -> None:
    """Eqs. (1), (3), (4) with D+ = 1, D− = 0.6, on the bilinear law, for 0 → a1 → −a1 → a2 → −a2."""
    d_neg, a1, a2, e_t = 0.6, 0.01, 0.02, 0.25 * MY
    law = IMKBilinear(k0=K0, m_y=MY, theta_p=THETA_P, theta_pc=THETA_PC, mc_my=MC_MY,
                      lambda_s=0.25, d_neg=d_neg)  # Λ_C, Λ_K off (λ = 0)

    def line(my: float, ks: float, x: float) -> float:
        """The post-yield line through the yield point (my/K0, my), slope ks, at x."""
        return my + ks * (x - my / K0)

    def reload(x0: float, my: float, ks: float) -> tuple[float, float]:
        """Where the elastic line K0 (x − x0) meets that line (side coordinates)."""
        x = (my - ks * my / K0 + K0 * x0) / (K0 - ks)
        return x, K0 * (x - x0)

    # excursion 1: loading to +a1, unloading to zero
    m_a1 = line(MY, KS, a1)
    z1 = a1 - m_a1 / K0
    e1 = work([(0.0, 0.0), (THETA_Y, MY), (a1, m_a1), (z1, 0.0)])
    beta1 = e1 / (e_t - e1)
    # excursion 2: towards the negative side, deteriorated by β1 (rate D−)
    my_n, ks_n = (1 - beta1 * d_neg) * MY, (1 - beta1 * d_neg) * KS
    x_hit, m_hit = reload(-z1, my_n, ks_n)
    m_na1 = line(my_n, ks_n, a1)
    z2 = -a1 + m_na1 / K0
    e2 = work([(z1, 0.0), (-x_hit, -m_hit), (-a1, -m_na1), (z2, 0.0)])
    beta2 = e2 / (e_t - e1 - e2)
    # excursion 3: towards the positive side, deteriorated by β2
    my_p, ks_p = (1 - beta2) * MY, (1 - beta2) * KS
    x_hit3, m_hit3 = reload(z2, my_p, ks_p)
    m_a2 = line(my_p, ks_p, a2)
    z3 = a2 - m_a2 / K0
    e3 = work([(z2, 0.0), (x_hit3, m_hit3), (a2, m_a2), (z3, 0.0)])
    beta3 = e3 / (e_t - e1 - e2 - e3)
    # excursion 4: the negative side again, by β3 on top of β1
    my_n2, ks_n2 = (1 - beta3 * d_neg) * my_n, (1 - beta3 * d_neg) * ks_n
    m_na2 = line(my_n2, ks_n2, a2)
    x_hit4, _ = reload(-z3, my_n2, ks_n2)

    # the regime the hand calculation assumes: reloading meets the post-yield line before the
    # peak, the peaks stay before the capping point and far above the residual strength
    assert x_hit < a1 and x_hit3 < a2 and x_hit4 < a2 < THETA_C
    assert 0.0 < beta1 < beta2 < 0.2 and 0.0 < beta3 < 0.3

    moments = moment_path(law, [0.0, a1, -a1, a2, -a2])
    expected = [0.0, m_a1, -m_na1, m_a2, -m_na2]
    np.testing.assert_allclose(moments, expected, rtol=1e-10, atol=1e-6)
    # the published strengths are visibly deteriorated: not the undeteriorated backbone
    assert abs(moments[2]) < line(MY, KS, a1) - 0.005 * MY
    assert abs(moments[3]) < line(MY, KS, a2) - 0.02 * MY
    assert abs(moments[4]) < line(MY, KS, a2) - 0.02 * MY


def test_unloading_stiffness_deterioration_at_two_reversals() -> None:
    """Eq. (6) with E_i and Σ E_j taken without the elastic energy M²/(2 K_u)."""
    a, step = 0.012, 0.0005
    law = IMKBilinear(k0=K0, m_y=MY, theta_p=THETA_P, theta_pc=THETA_PC, mc_my=MC_MY,
                      lambda_k=1.0, c_k=1.0)
    m_a = MY + KS * (a - THETA_Y)
    w1 = work([(0.0, 0.0), (THETA_Y, MY), (a, m_a)])
    stored = 0.5 * m_a**2 / K0
    beta_k1 = (w1 - stored) / (E_T - (w1 - stored))  # no excursion yet: E_i = Σ E_j
    k1 = (1 - beta_k1) * K0
    # to the negative side with K1: the backbone there is undeteriorated (Λ_S, Λ_C off)
    z1 = a - m_a / k1
    x_hit = (MY - KS * THETA_Y - k1 * z1) / (k1 - KS)
    m_hit = k1 * (x_hit + z1)
    corners = [(0.0, 0.0), (THETA_Y, MY), (a, m_a), (z1, 0.0), (-x_hit, -m_hit), (-a, -m_a)]
    w2, w_exc = work(corners), work(corners[:4])
    stored2 = 0.5 * m_a**2 / k1
    beta_k2 = (w2 - w_exc - stored2) / (E_T - (w2 - stored2))
    k2 = (1 - beta_k2) * k1
    assert x_hit < a and 0.0 < beta_k1 < beta_k2 < 0.5

    moments = moment_path(law, [0.0, a, a - step, -a, -a + step])
    np.testing.assert_allclose(moments, [0.0, m_a, m_a - k1 * step, -m_a, -m_a + k2 * step],
                               rtol=1e-10, atol=1e-6)


def test_post_capping_strength_deterioration() -> None:
    """Eq. (5): the post-capping line moves towards the origin by (1 − β_c)."""
    a, past, e_t = 0.01, 0.02, 0.25 * MY
    law = IMKBilinear(k0=K0, m_y=MY, theta_p=THETA_P, theta_pc=THETA_PC, mc_my=MC_MY,
                      lambda_c=0.25)
    k_pc = -MC / THETA_PC
    m_a = MY + KS * (a - THETA_Y)
    z1 = -a + m_a / K0
    e1 = work([(0.0, 0.0), (-THETA_Y, -MY), (-a, -m_a), (z1, 0.0)])
    beta_c = e1 / (e_t - e1)
    m_ref = (1 - beta_c) * (MC - k_pc * THETA_C)  # Eq. (5)
    # the new capping point: the (unchanged) post-yield line meets the moved post-capping line;
    # the strength and so K_pc are unchanged (the paper's and OpenSees' rule coincide here)
    theta_cap = (m_ref - (MY - KS * THETA_Y)) / (KS - k_pc)
    m_cap = MY + KS * (theta_cap - THETA_Y)
    theta = theta_cap + past
    assert theta_cap < THETA_C and m_ref + k_pc * theta > 0.4 * MY
    moments = moment_path(law, [0.0, -a, theta_cap, theta])
    np.testing.assert_allclose(moments[2:], [m_cap, m_ref + k_pc * theta], rtol=1e-10)
    assert moments[3] < MC + k_pc * (theta - THETA_C) - 0.01 * MY  # below the original branch


def test_peak_oriented_target_grows_by_eq7() -> None:
    """Eq. (7) on the peak-oriented law: 0 → b (past the cap) → −a → back to b and beyond."""
    b, a = 0.06, 0.01
    law = IMKPeakOriented(k0=K0, m_y=MY, theta_p=THETA_P, theta_pc=THETA_PC, mc_my=MC_MY,
                          lambda_a=1.0)  # only accelerated reloading stiffness deterioration
    k_pc = -MC / THETA_PC
    m_b = MC + k_pc * (b - THETA_C)
    z1 = b - m_b / K0
    e1 = work([(0.0, 0.0), (THETA_Y, MY), (THETA_C, MC), (b, m_b), (z1, 0.0)])
    beta_a1 = e1 / (E_T - e1)
    # towards the negative side: target θ_y (1 + β_a1) on the backbone; the last reversal
    # point there (the yield point) is the steeper aim, then the post-yield line to −a
    m_a = MY + KS * (a - THETA_Y)
    assert THETA_Y * (1 + beta_a1) < a and MY / (THETA_Y + z1) > (MY + KS * THETA_Y * beta_a1) / (
        THETA_Y * (1 + beta_a1) + z1)
    z2 = -a + m_a / K0
    e2 = work([(z1, 0.0), (-THETA_Y, -MY), (-a, -m_a), (z2, 0.0)])
    beta_a2 = e2 / (E_T - e1 - e2)
    target = b * (1 + beta_a2)  # Eq. (7), from the largest positive rotation b
    m_target = MC + k_pc * (target - THETA_C)
    k_reload = m_target / (target - z2)  # straight to the target (it is below M at b)
    assert m_target < m_b and target < 0.1
    moments = moment_path(law, [0.0, b, -a, b, target, target + 0.01])
    np.testing.assert_allclose(
        moments, [0.0, m_b, -m_a, k_reload * (b - z2), m_target, m_target + 0.01 * k_pc],
        rtol=1e-10)


# ------------------------------------------------------------------------------- energy
def protocol(amplitudes: list[float], cycles: int = 2) -> list[float]:
    path = [0.0]
    for amp in amplitudes:
        path += [amp, -amp] * cycles
    return path


def corners_along(law: HingeLaw, path: list[float]) -> list[HingeState]:
    """The committed state at every breakpoint along the path (through the contract)."""
    state, out = law.start(), [law.start()]
    for target in path[1:]:
        d = 1 if target > state.theta else -1
        while state.theta != target:
            end = law.branch(state, d).theta_end
            stop = end if (end - target) * d < 0 else target
            state = law.moved(state, stop)
            out.append(state)
    return out


LK_STEEL = {"k0": K0, "m_y": MY, "theta_p": 0.025, "theta_pc": 0.15, "theta_u": 0.2,
            "mc_my": 1.1, "kappa": 0.4, "c": 1.0}


@pytest.mark.parametrize("lam", [0.5, 1.0, 3.0])
@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
def test_hysteretic_energy_never_negative_nor_decreasing(cls: type, lam: float) -> None:
    law = cls(**LK_STEEL, lambda_=lam)
    path = protocol([0.00375, 0.005, 0.0075, 0.01, 0.015, 0.02, 0.03, 0.04, 0.05, 0.06])
    states = corners_along(law, path)
    # the work on each straight piece is its length times the moment at its middle (exact,
    # and blind to the jumps a failure makes at a piece's ends)
    work_done = np.cumsum([0.0] + [
        law.moved(s0, 0.5 * (s0.theta + s1.theta)).moment * (s1.theta - s0.theta)
        for s0, s1 in itertools.pairwise(states)])
    hysteretic = work_done - np.array([law.recoverable(s) for s in states])
    tol = 1e-9 * MY * THETA_Y
    assert hysteretic.min() >= -tol
    assert np.diff(hysteretic).min() >= -tol
    assert hysteretic[-1] > 10 * MY * THETA_Y  # it did dissipate


# ------------------------------------------------------------------------------- contract
@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
def test_one_move_equals_many_small_moves_and_tangents_are_exact(cls: type) -> None:
    law = cls(**LK_STEEL, lambda_=0.6)
    path = protocol([0.004, 0.012, 0.03, 0.06, 0.1], cycles=1) + [0.07, 0.09, -0.05, 0.25]
    fine = [0.0]
    for t0, t1 in itertools.pairwise(path):
        fine += list(np.linspace(t0, t1, 37)[1:])
    coarse_moments = moment_path(law, path)
    fine_moments = moment_path(law, fine)[36::36]
    np.testing.assert_allclose(fine_moments, coarse_moments[1:], rtol=1e-9, atol=1e-6 * MY)
    # the tangent each branch reports is the slope of the moment along it
    state = law.start()
    for target in path[1:]:
        d = 1 if target > state.theta else -1
        while state.theta != target:
            br = law.branch(state, d)
            stop = br.theta_end if (br.theta_end - target) * d < 0 else target
            h = 0.25 * (stop - state.theta)
            inside = law.moved(law.moved(state, state.theta + h), state.theta + 2 * h)
            assert inside.moment - law.moved(state, state.theta + h).moment == pytest.approx(
                br.k_t * h, rel=1e-7, abs=1e-7 * MY)
            state = law.moved(state, stop)
    assert state.moment == 0.0  # fractured: 0.25 rad is past θ_u = 0.2


def test_memory_is_a_tuple_of_floats() -> None:
    for cls in (IMKBilinear, IMKPeakOriented):
        law = cls(**LK_STEEL, lambda_=1.0)
        state = law.moved(law.moved(law.start(), 0.03), -0.02)
        assert isinstance(state.memory, tuple)
        assert all(isinstance(v, float) for v in state.memory)
        assert "lambda=1 rad" in law.describe()


@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
def test_event_to_event_pushover_stops_at_the_backbone_points(cls: type) -> None:
    """A cantilever column on an IMK hinge, pushed to 0.15 rad (short of θ_u): the
    event-to-event pushover lands on yield, capping and residual points exactly, and its base
    shear is M/h there (statically determinate)."""
    h, law = 4.0, cls(**LK_STEEL, lambda_=1.0)
    column = Frame(nodes=[[0.0, 0.0], [0.0, h]], elements=[[0, 1]], EA=1e12, EI=1e10,
                   supports=[[True, True, True], [False, False, False]],
                   hinges=(FrameHinge(0, 0, law),), diaphragm=False, name="column")
    result = pushover(column, 0.15 * h)
    theta = result.hinge_rotations[:, 0]
    theta_y, theta_c = MY / K0, MY / K0 + 0.025
    theta_r = theta_c + 0.15 * (1 - 0.4 / 1.1)
    for point in (theta_y, theta_c, theta_r):
        assert np.min(np.abs(theta - point)) < 1e-12
    np.testing.assert_allclose(result.base_shear, result.hinge_moments[:, 0] / h, rtol=1e-9,
                               atol=1e-6)
    assert result.peak_base_shear == pytest.approx(1.1 * MY / h, rel=1e-12)
    assert result.base_shear[-1] == pytest.approx(0.4 * MY / h, rel=1e-9)


@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
def test_pushover_past_the_ultimate_rotation_sheds_the_moment(cls: type) -> None:
    """Pushed past θ_u the hinge fractures: its moment drops to 0 at θ_u and the event-to-event
    pushover releases it at that roof displacement (the base shear falls from κ M_y / h to 0
    there) instead of carrying the old shear on; ``stop_below`` then ends the push."""
    h, theta_u = 4.0, 0.2
    law = cls(**{**LK_STEEL, "theta_u": theta_u})
    column = Frame(nodes=[[0.0, 0.0], [0.0, h]], elements=[[0, 1]], EA=1e12, EI=1e10,
                   supports=[[True, True, True], [False, False, False]],
                   hinges=(FrameHinge(0, 0, law),), diaphragm=False, name="column")
    result = pushover(column, 0.3 * h)
    at_u = np.flatnonzero(np.abs(result.hinge_rotations[:, 0] - theta_u) < 1e-12)
    assert at_u.size == 1  # reached θ_u; released at the same roof displacement next
    i = int(at_u[0])
    assert result.base_shear[i] == pytest.approx(0.4 * MY / h, rel=1e-9)
    assert result.roof_displacement[i + 1] == pytest.approx(result.roof_displacement[i],
                                                            rel=1e-12)
    assert np.all(np.abs(result.base_shear[i + 1:]) < 1e-9 * MY / h)
    assert np.all(np.abs(result.hinge_moments[i + 1:, 0]) < 1e-9 * MY)
    stopped = pushover(column, 0.3 * h, stop_below=0.05)
    assert stopped.stopped == "strength"


def test_reloading_beyond_the_ultimate_rotation_after_a_fracture_is_continuous() -> None:
    """Fractured at θ_u = 0.08, turned back by 0.001 rad (unloading at K_e/2 after the
    residual: M = −K_e/2 · 0.001), then outward again: the moment climbs back along K_e/2 to
    zero and stays there (OpenSees drops it to zero at once; the module docstring)."""
    law = IMKBilinear(**{**LK_STEEL, "theta_u": 0.08})
    state = law.moved(law.start(), 0.08)
    assert state.moment == 0.0
    back = law.moved(state, 0.079)
    assert back.moment == pytest.approx(-0.5 * K0 * 0.001, rel=1e-9)
    half = law.moved(back, 0.0795)
    assert half.moment == pytest.approx(-0.5 * K0 * 0.0005, rel=1e-9)
    br = law.branch(back, 1)
    assert br.k_t == pytest.approx(0.5 * K0) and br.theta_end == pytest.approx(0.08)
    assert law.moved(back, 0.1).moment == 0.0
