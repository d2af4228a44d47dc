"""Storey laws against closed forms: cyclic push tests (drift-controlled)."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.hysteresis import Bilinear, BoucWen, respond_drift_path
from pounding.structure import ShearBuilding

K = 2.0e7        # N/m
FY = 1.0e5       # N
DY = FY / K      # 5 mm


def cycles(amplitudes, per_leg=400):
    """Drift path 0 → +a1 → −a1 → +a2 → … → 0, sampled finely."""
    pts = [0.0]
    for a in amplitudes:
        pts += [a, -a]
    pts.append(0.0)
    out = [np.linspace(p, q, per_leg, endpoint=False) for p, q in zip(pts[:-1], pts[1:])]
    return np.concatenate(out + [np.array([0.0])])


def loop_area(d, v):
    """Work ∮ V dd along the path (trapezoids)."""
    return float(np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(d)))


@pytest.mark.parametrize("b", [0.0, 0.05, 0.3])
def test_bilinear_skeleton_and_unloading(b):
    law = Bilinear(yield_force=FY, hardening=b)
    d = np.array([0.0, 0.5 * DY, DY, 4 * DY, 3 * DY, 4 * DY - 2 * DY * 1.0, -6 * DY])
    v = respond_drift_path(law, K, d)
    tol = 1e-9 * FY
    assert v[1] == pytest.approx(0.5 * FY, abs=tol)             # elastic
    assert v[2] == pytest.approx(FY, abs=tol)                   # yield point
    assert v[3] == pytest.approx(FY + b * K * 3 * DY, abs=tol)  # hardening branch
    assert v[4] == pytest.approx(v[3] - K * DY, abs=tol)        # elastic unloading, slope k
    # unloading stays elastic over a shear change of 2 F_y: down to the lower band line
    assert v[5] == pytest.approx(v[3] - K * 2 * DY, abs=tol)
    assert v[6] == pytest.approx(b * K * (-6 * DY) - (1 - b) * FY, abs=tol)


@pytest.mark.parametrize("b", [0.0, 0.05, 0.3])
@pytest.mark.parametrize("mu", [2.0, 5.0])
def test_bilinear_loop_area_closed_form(b, mu):
    """A stable symmetric cycle ±D encloses 4 (1 − b) F_y (D − d_y)."""
    D = mu * DY
    path = cycles([D, D], per_leg=4000)
    v = respond_drift_path(Bilinear(yield_force=FY, hardening=b), K, path)
    half = path.size // 2                    # the second cycle only
    area = loop_area(path[half - 1:], v[half - 1:])
    assert area == pytest.approx(4 * (1 - b) * FY * (D - DY), rel=5e-4)


def test_bilinear_elastic_inside_yield():
    law = Bilinear(yield_drift=DY, hardening=0.1)
    path = cycles([0.9 * DY, 0.5 * DY])
    np.testing.assert_allclose(respond_drift_path(law, K, path), K * path, rtol=0,
                               atol=1e-9 * FY)


@pytest.mark.parametrize("beta,gamma", [(0.5, 0.5), (0.75, 0.25), (0.25, 0.75)])
def test_bouc_wen_n1_monotonic_closed_form(beta, gamma):
    """n = 1: z(d) = (1 − exp(−(β+γ) d/d_y)) / (β+γ) on first loading."""
    alpha = 0.1
    law = BoucWen(yield_force=FY, alpha=alpha, n=1.0, beta=beta, gamma=gamma)
    d = np.linspace(0.0, 8 * DY, 81)
    v = respond_drift_path(law, K, d, substeps=50)
    s = beta + gamma
    z = (1.0 - np.exp(-s * d / DY)) / s
    np.testing.assert_allclose(v, alpha * K * d + (1 - alpha) * FY * z, rtol=1e-10, atol=1e-6)


@pytest.mark.parametrize("n", [1.0, 2.0, 8.0])
def test_bouc_wen_skeleton_limits(n):
    """Initial tangent k; V − αkd → (1 − α) F_y z_u on monotonic loading; unloading from
    saturation with tangent k[α + (1 − α)(1 − (γ − β) z_u^n)]."""
    alpha, beta, gamma = 0.05, 0.6, 0.4
    law = BoucWen(yield_force=FY, alpha=alpha, n=n, beta=beta, gamma=gamma)
    zu = law.z_ultimate
    assert zu == pytest.approx(1.0)
    eps = 1e-6 * DY
    v0 = respond_drift_path(law, K, [0.0, eps])
    assert v0[1] / eps == pytest.approx(K, rel=1e-5)
    D = 30 * DY
    up = np.linspace(0.0, D, 3001)
    v = respond_drift_path(law, K, up)
    assert v[-1] - alpha * K * D == pytest.approx((1 - alpha) * FY * zu, rel=1e-6)
    back = np.concatenate([up, [D - eps]])
    vb = respond_drift_path(law, K, back)
    k_unload = (vb[-2] - vb[-1]) / eps
    assert k_unload == pytest.approx(K * (alpha + (1 - alpha) * (1 - (gamma - beta) * zu**n)),
                                     rel=1e-4)


def test_bouc_wen_large_n_approaches_bilinear():
    bw = BoucWen(yield_force=FY, alpha=0.05, n=40.0)
    bl = Bilinear(yield_force=FY, hardening=0.05)
    path = cycles([4 * DY, 6 * DY])
    vbw = respond_drift_path(bw, K, path)
    vbl = respond_drift_path(bl, K, path)
    assert np.max(np.abs(vbw - vbl)) < 0.03 * FY


def test_bouc_wen_loop_dissipates():
    law = BoucWen(yield_force=FY, alpha=0.05, n=2.0)
    path = cycles([5 * DY])
    v = respond_drift_path(law, K, path)
    area = loop_area(path, v)
    # between the elastic (0) and the bilinear limit 4(1 − α)F_y(D − d_y)
    assert 0.5 * 4 * 0.95 * FY * 4 * DY < area < 4 * 0.95 * FY * 4 * DY


@pytest.mark.parametrize("kwargs,field", [
    ({}, "yield_force"),
    ({"yield_force": 1.0, "yield_drift": 1.0}, "yield_force"),
    ({"yield_force": -1.0}, "yield_force"),
    ({"yield_force": 1.0, "hardening": 1.0}, "hardening"),
    ({"yield_force": 1.0, "hardening": -0.1}, "hardening"),
])
def test_bilinear_bad_input_names_field(kwargs, field):
    with pytest.raises(ValueError, match=field):
        Bilinear(**kwargs)


@pytest.mark.parametrize("kwargs,field", [
    ({"yield_force": 1.0, "alpha": 1.0}, "alpha"),
    ({"yield_force": 1.0, "n": 0.5}, "n"),
    ({"yield_force": 1.0, "beta": -0.5, "gamma": 0.4}, "beta"),
    ({"yield_force": 1.0, "beta": float("nan")}, "beta"),
])
def test_bouc_wen_bad_input_names_field(kwargs, field):
    with pytest.raises(ValueError, match=field):
        BoucWen(**kwargs)


def test_building_takes_a_law_per_storey():
    b = ShearBuilding.uniform(3, 1e5, K, height=3.0)
    law = Bilinear(yield_force=[3e5, 2e5, 1e5], hardening=0.02)
    bb = b.with_storey_law(law)
    np.testing.assert_array_equal(bb.yield_forces, [3e5, 2e5, 1e5])
    assert bb.storey_law_params()[:, 0].tolist() == [K] * 3
    assert bb.fundamental_period == b.fundamental_period      # elastic stiffness unchanged
    with pytest.raises(ValueError, match="yield_force: need one value or 3"):
        b.with_storey_law(Bilinear(yield_force=[1e5, 1e5], hardening=0.0))
    with pytest.raises(ValueError, match="storey_law"):
        ShearBuilding(masses=[1.0], stiffnesses=[1.0], heights=[1.0], storey_law="bilinear")


def test_isolator_base_is_abstract():
    """The isolator base is not a bearing: instantiating it fails (before, it built an
    object whose stiffness and law raised NotImplementedError when first used), and a
    subclass that leaves out its stiffness or its law cannot be instantiated either."""
    from pounding.hysteresis.isolators import BilinearIsolator, Isolator

    with pytest.raises(TypeError, match="abstract"):
        Isolator()

    class NoLaw(Isolator):
        @property
        def stiffness(self) -> float:
            return 1.0

    with pytest.raises(TypeError, match="law"):
        NoLaw()
    iso = BilinearIsolator(2e8, 2e7, yield_force=1e6)
    assert isinstance(iso, Isolator) and iso.stiffness == 2e8
