"""Bridge frames (a deck on piers through bearings): their matrices and periods against a
hand-assembled eigenproblem, their element rows (a law each), the row they make, and the
element rows of every existing kind of building unchanged by the generalisation to a law
per row (checked against the per-building API the model read before)."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.devices import Link
from pounding.hysteresis import Bilinear, BoucWen
from pounding.hysteresis.isolators import FrictionPendulum
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.bridge import (
    Abutment,
    Bearing,
    Bridge,
    BridgeFrame,
    Pier,
    Restrainer,
    pier_stiffness,
)
from pounding.structure.foundation import Footing, Soil, flexible_base

KV = ContactSpec("kelvin-voigt", k=1.0e9, e=0.6)


def test_one_pier_frame_periods_match_the_closed_form() -> None:
    """Deck m_d on a bearing k_b on a cap m_c on a pier k_p: ω² are the roots of
    m_d m_c ω⁴ − (m_d (k_b + k_p) + m_c k_b) ω² + k_b k_p = 0 (hand-assembled 2×2
    eigenproblem), and with a vanishing cap mass the deck's period is that of the pier and
    bearing in series, 2π √(m_d (k_b + k_p) / (k_b k_p))."""
    md, mc, kb, kp = 2.0e6, 1.0e5, 2.0e7, 5.0e7
    frame = BridgeFrame(md, [Pier(8.0, kp, mc)], Bearing.elastomeric(kb))
    a, b, c = md * mc, -(md * (kb + kp) + mc * kb), kb * kp
    w2 = np.sort(np.roots([a, b, c]).real)
    np.testing.assert_allclose(frame.modes().periods, 2 * np.pi / np.sqrt(w2), rtol=1e-12)
    light = BridgeFrame(md, [Pier(8.0, kp, md * 1e-9)], Bearing.elastomeric(kb))
    series = 2 * np.pi * np.sqrt(md * (kb + kp) / (kb * kp))
    assert light.modes().periods[0] == pytest.approx(series, rel=1e-8)


def test_two_pier_frame_matrices_and_damping() -> None:
    """K from the elements by hand; C = a₀ M + a₁ K_lin + the bearings' dashpots, with
    ζ = 5 % at modes 1 and 2 when every element is linear (Rayleigh's own check)."""
    piers = [Pier(8.0, 5e7, 1e5), Pier(6.0, 9e7, 8e4)]
    bearings = [Bearing.elastomeric(2e7, 3e5), Bearing.elastomeric(3e7)]
    f = BridgeFrame(3e6, piers, bearings, deck_elevation=8.0, zeta=0.05)
    K = np.array([[5e7, -2e7, -3e7], [-2e7, 7e7, 0.0], [-3e7, 0.0, 12e7]])
    np.testing.assert_array_equal(f.stiffness_matrix(), K)
    np.testing.assert_array_equal(f.linear_stiffness_matrix(), K)
    a0, a1 = f.rayleigh
    dash = np.zeros((3, 3))
    dash[np.ix_([0, 1], [0, 1])] = 3e5 * np.array([[1, -1], [-1, 1]])
    np.testing.assert_allclose(f.damping_matrix(), a0 * f.mass_matrix() + a1 * K + dash,
                               rtol=1e-12)
    w = 2 * np.pi / f.modes().periods[:2]
    np.testing.assert_allclose(a0 / (2 * w) + a1 * w / 2, [0.05, 0.05], rtol=1e-10)
    assert f.floors == (0,) and dict(f.faces) == {"left": (0,), "right": (0,)}
    assert f.element_rows() == [] and not f.is_inelastic


def test_nonlinear_elements_are_rows_with_their_own_laws() -> None:
    """A yielding pier and a sliding bearing are element rows with their own law and
    constants; their initial stiffness stays in K (periods, damping) and leaves the
    linear stiffness the time stepper takes."""
    law = Bilinear(yield_force=1.5e6, hardening=0.05)
    slider = Bearing.sliding(mu=0.08, weight=2e7, yield_displacement=1e-3)
    f = BridgeFrame(2e6, [Pier(8.0, 5e7, 1e5, law), Pier(8.0, 6e7, 1e5)],
                    [Bearing.elastomeric(2e7), slider])
    rows = f.element_rows()
    assert [(r.label, r.lower, r.upper, r.storey) for r in rows] == [("P1", -1, 1, -1),
                                                                      ("Br2", 2, 0, -1)]
    assert rows[0].law is law and list(rows[0].params[:3]) == [5e7, 1.5e6, 0.05]
    assert isinstance(rows[1].law, BoucWen) and rows[1].law.alpha == 0.0
    assert rows[1].params[0] == pytest.approx(0.08 * 2e7 / 1e-3)
    assert rows[1].params[1] == pytest.approx(0.08 * 2e7)
    k_nl = np.zeros((3, 3))
    k_nl[1, 1] += 5e7
    k_nl[np.ix_([2, 0], [2, 0])] += 1.6e9 * np.array([[1, -1], [-1, 1]])
    np.testing.assert_allclose(f.stiffness_matrix() - f.linear_stiffness_matrix(), k_nl)
    assert f.is_inelastic


def test_bridge_row_joints_abutments_restrainers() -> None:
    """The frames' decks meet across the joint and strike the abutments; the caps strike
    nothing; a restrainer is a link between the decks; element rows are numbered by frame."""
    f1 = BridgeFrame(2e6, [Pier(8.0, 5e7, 1e5, Bilinear(yield_force=1e6))],
                     Bearing.elastomeric(2e7), name="F1")
    f2 = BridgeFrame(3e6, [Pier(8.0, 8e7, 1e5), Pier(6.0, 1e8, 1e5)],
                     Bearing.sliding(0.06, 1.5e7), deck_elevation=8.0, name="F2")
    bridge = Bridge([f1, f2], [0.02], abutments=(Abutment(0.04), Abutment(0.05)),
                    restrainers=[Restrainer(0, {"kind": "kelvin", "k": 1e7, "c": 1e4})])
    model = PoundingModel.from_bridge(bridge, KV)
    assert [(c.label, c.gap) for c in model.contacts] == [("B1F1-B2F1", 0.02),
                                                          ("A1-B1F1", 0.04), ("B2F1-A2", 0.05)]
    assert model.element_labels() == ["B1P1", "B2Br1", "B2Br2"]
    assert model.yielding_storeys == () and model.is_inelastic
    assert model.link_dofs == ((0, 2),) and model.links[0].name == "R1"
    lo, hi, _, _, zi = model.storey_arrays()
    assert list(lo) == [-1, 3, 4, 0] and list(hi) == [1, 2, 2, 2]
    assert list(zi) == [-1, 0, 1, -1]
    assert model.dof_units() == ["m"] * 5


@pytest.mark.parametrize("bad, message", [
    (lambda: Bridge([BridgeFrame(1e6, [Pier(8.0, 1e7, 1e4)], Bearing.elastomeric(1e7)),
                     BridgeFrame(1e6, [Pier(6.0, 1e7, 1e4)], Bearing.elastomeric(1e7))],
                    [0.02]), "frames[1]: deck at 6 m"),
    (lambda: Bridge([BridgeFrame(1e6, [Pier(8.0, 1e7, 1e4)], Bearing.elastomeric(1e7))],
                    [0.02]), "joint_gaps: need 0 value(s)"),
    (lambda: BridgeFrame(1e6, [Pier(8.0, 1e7, 1e4)], [Bearing.elastomeric(1e7)] * 2),
     "bearings: need one Bearing per pier"),
    (lambda: Abutment(0.05, law="backfill"), "law: expected a ContactSpec or None (got str)"),
    (lambda: pier_stiffness(1e9, 8.0, "pinned"), "fixity: 'pinned'"),
])
def test_bad_bridges_are_refused_in_one_line(bad, message) -> None:
    with pytest.raises(ValueError) as info:
        bad()
    assert message in str(info.value) and "\n" not in str(info.value)


def _rows_as_before(model: PoundingModel) -> tuple[np.ndarray, ...]:
    """The element rows the model listed before a law per row: every building's yielding
    storeys with its one storey law (``yielding_storey_dofs``, ``storey_law_params``),
    then the links (the old :meth:`PoundingModel.storey_arrays` and ``storey_rocking``)."""
    offsets = model.system.offsets
    lo, hi, code, prm, zi, rock, lever = [], [], [], [], [], [], []
    nz = 0
    for p, b in enumerate(model.buildings):
        law = b.storey_law
        if law is None:
            continue
        par = b.storey_law_params()
        for r, (a, u, rk, arm) in enumerate(b.yielding_storey_dofs()):
            lo.append(int(offsets[p] + a) if a >= 0 else -1)
            hi.append(int(offsets[p] + u))
            code.append(law.code)
            prm.append(par[r])
            zi.append(nz if law.has_internal_variable else -1)
            nz += law.has_internal_variable
            rock.append(int(offsets[p] + rk) if rk >= 0 else -1)
            lever.append(float(arm))
    width = prm[0].size if prm else 6
    for link, (a, u) in zip(model.links, model.link_dofs):
        lo.append(a)
        hi.append(u)
        code.append(link.code)
        prm.append(link.params(width))
        zi.append(nz if link.has_internal_variable else -1)
        nz += link.has_internal_variable
        rock.append(-1)
        lever.append(0.0)
    return (np.array(lo, dtype=np.int64), np.array(hi, dtype=np.int64),
            np.array(code, dtype=np.int64), np.array(prm, dtype=float).reshape(len(prm), width),
            np.array(zi, dtype=np.int64), np.array(rock, dtype=np.int64),
            np.array(lever, dtype=float))


def test_existing_buildings_rows_are_bit_identical() -> None:
    """Shear buildings (bilinear, Bouc–Wen on some storeys), one on a flexible base, a
    base-isolated one, and links of the three kinds: the kernel's element arrays equal,
    bit for bit, those of the per-building API the model read before."""
    a = ShearBuilding.uniform(3, 3e5, 3.5e8, height=3.2).with_storey_law(
        Bilinear(yield_drift=0.004 * 3.2, hardening=0.05))
    b = ShearBuilding.uniform(3, 2.5e5, 1.5e8, height=3.2).with_storey_law(
        BoucWen(yield_drift=0.006 * 3.2, alpha=0.05, n=1.5))
    c = ShearBuilding(masses=[2e5] * 4, stiffnesses=[2e8] * 4, heights=[3.0] * 4,
                      storey_law=BoucWen(yield_force=3e5, alpha=0.1), yielding_storeys=(0, 2))
    iso = ShearBuilding.base_isolated(ShearBuilding.uniform(3, 3e5, 3.5e8, height=3.2), 3e5,
                                      FrictionPendulum(radius=2.0, mu=0.06))
    soil = flexible_base(a, Footing(radius=4.0, mass=3e5, inertia=2e6), Soil(150.0, 1800.0, 0.33))
    model = PoundingModel([soil, b, c, iso], [0.01, 0.02, 0.03], KV, devices=[
        Link(("B1F2", "B2F2"), "maxwell", c=1e6, k=1e7, alpha=0.5),
        Link(("B3F1", "B4F1"), "kelvin", c=1e5, k=1e6),
        Link(("B2F3", "B3F3"), "viscous", c=1e5)])
    now = (*model.storey_arrays(), *model.storey_rocking())
    before = _rows_as_before(model)
    assert len(now) == len(before)
    for x, y in zip(now, before):
        assert x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes()
    assert model.yielding_storeys == ((0, 0), (0, 1), (0, 2), (1, 0), (1, 1), (1, 2),
                                      (2, 0), (2, 2), (3, 0))
