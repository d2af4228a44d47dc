"""Contract 7 of the hinge laws (:mod:`pounding.hysteresis.hinges`): on a branch a law calls
two-way, a hinge moved back and forth along it and committed at its last point is in the state
one move there gives — what lets a yielding frame's time stepper leave such hinges alone
between events (:mod:`pounding.structure.frame_configuration`). Checked on the states of a
cyclic path through every law, against the law's own single move (independent of how the
frame uses it), with the points between chosen at random inside the branch."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.hysteresis.hinges import (
    BilinearHinge,
    ElasticPlastic,
    HingeLaw,
    HingeState,
)
from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented

K0, MY = 1.0e8, 3.0e5
IMK = {"k0": K0, "m_y": MY, "theta_p": 0.025, "theta_pc": 0.15, "theta_u": 0.2,
       "mc_my": 1.1, "kappa": 0.4, "c": 1.0, "lambda_": 0.8}
LAWS = [ElasticPlastic(k0=K0, m_y=MY), BilinearHinge(k0=K0, m_y=MY, hardening=0.05),
        IMKBilinear(**IMK), IMKPeakOriented(**IMK)]
PATH = [0.0, 0.005, -0.004, 0.012, -0.01, 0.03, -0.02, 0.001, 0.05, -0.045, 0.08, 0.0]


def _states(law: HingeLaw) -> list[HingeState]:
    """Every breakpoint of the path and three points inside each branch on the way."""
    state, out = law.start(), [law.start()]
    for target in PATH[1:]:
        d = 1 if target > state.theta else -1
        while state.theta != target:
            end = law.branch(state, d).theta_end
            stop = end if (end - target) * d < 0 else target
            for f in (0.25, 0.5, 0.75):
                out.append(law.moved(state, state.theta + f * (stop - state.theta)))
            state = law.moved(state, stop)
            out.append(state)
    return out


def _close(a: HingeState, b: HingeState) -> bool:
    mem_a, mem_b = np.asarray(a.memory, float), np.asarray(b.memory, float)
    return (math.isclose(a.theta, b.theta, rel_tol=1e-12, abs_tol=1e-15)
            and math.isclose(a.moment, b.moment, rel_tol=1e-9, abs_tol=1e-9 * MY)
            and mem_a.shape == mem_b.shape
            and bool(np.allclose(mem_a, mem_b, rtol=1e-9, atol=1e-9 * MY)))


@pytest.mark.parametrize("law", LAWS, ids=lambda law: law.label)
def test_a_hinge_moved_back_and_forth_on_a_two_way_branch_is_where_one_move_puts_it(
        law: HingeLaw) -> None:
    rng = np.random.default_rng(7)
    two_way = one_way = 0
    for state in _states(law):
        up, down = law.branch(state, 1), law.branch(state, -1)
        if not law.two_way(state):
            one_way += 1
            continue
        two_way += 1
        assert up.k_t == down.k_t
        lo = max(down.theta_end, state.theta - 0.01)
        hi = min(up.theta_end, state.theta + 0.01)
        points = rng.uniform(lo, hi, size=6)
        walked = state
        for p in points:
            walked = law.moved(walked, float(p))
        direct = law.moved(state, float(points[-1]))
        assert _close(walked, direct), (state, points)
        # and the branch ahead either way is the one the state had
        for d, br in ((1, up), (-1, down)):
            again = law.branch(walked, d)
            assert again.k_t == br.k_t and again.theta_end == pytest.approx(
                br.theta_end, rel=1e-12, abs=1e-15)
    # the path visits both kinds (the check is not empty): elastic stretches are two-way,
    # yielding and post-capping ones are not
    assert two_way >= 10 and one_way >= 5


@pytest.mark.parametrize("law", LAWS, ids=lambda law: law.label)
def test_a_hinge_on_its_backbone_is_not_two_way(law: HingeLaw) -> None:
    on_backbone = law.moved(law.start(), 3 * MY / K0)  # three times its yield rotation
    assert not law.two_way(on_backbone)
    assert law.two_way(law.moved(on_backbone, 2 * MY / K0))  # unloaded part way: elastic


@pytest.mark.parametrize("law", LAWS, ids=lambda law: law.label)
def test_branches_at_once_are_the_branches_one_by_one(law: HingeLaw) -> None:
    # (the IMK laws prepare each direction once for the three answers)
    for state in _states(law):
        up, down, two_way = law.branches(state)
        assert up == law.branch(state, 1) and down == law.branch(state, -1)
        assert two_way == law.two_way(state)
