"""frame_from_opensees: a frame built in OpenSeesPy, imported, analysed in pounding.

* Round trip: a pounding frame built in OpenSeesPy (``opensees_frames.build``) and imported
  back is the same frame — nodes, supports, masses, loads, rigid floors, leaning loads,
  geometry exactly; ``EA``, ``EI`` and the hinge laws' constants to 1e-12 (read from the
  elements' basic stiffness and by probing the materials, not from the 6-digit printout).
* The imported frame's pushover in pounding against OpenSees' pushover of the same domain
  (within OpenSees' own convergence, as in ``test_frame_opensees.py``).
* A portal frame written by hand the way OpenSees users write it (their own tags, hinge node
  order, ``-dir 3``, base member ends fixed instead of tied): its sway mechanism carries
  ``4 M_p / h = 300 kN``.
* What the import refuses: one line naming the element, node or material.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import opensees_frames as osf  # tests/structure (pytest puts a test's folder on sys.path)
import pytest

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
from pounding.structure.frame import Frame, regular_frame
from pounding.structure.frame_analysis import pushover
from pounding.structure.frame_opensees import frame_from_opensees, read_opensees_frame


@pytest.fixture
def ops(opensees: Any) -> Any:
    return opensees  # (conftest.py: skipped, saying why, where OpenSeesPy cannot load)


def three_by_two(**kw: Any) -> Frame:
    args: dict[str, Any] = dict(
        column_EI=[2.0123456789e8, 1.5e8, 1e8], beam_EI=[3e8, 2.5e8, 2.0987654321e8],
        column_EA=[2e10, 1.5e10, 1.0123456789e10], beam_EA=1e10,
        column_hinge=BilinearHinge(k0=1.23456789e11, m_y=5.0123456789e5, hardening=0.0312345),
        beam_hinge=ElasticPlastic(k0=0.987654321e11, m_y=4.0123456789e5),
        floor_mass=[2e5, 2.0123456789e5, 1.5e5], beam_load=[3e4, 3.0123456789e4, 2.5e4],
        name="3x2")
    args.update(kw)
    return regular_frame([6.0, 5.0], [4.0, 3.5, 3.5], **args)


CASES = {
    "gravity": {},
    "leaning": {"leaning_load": [2e6, 2e6, 1.5e6]},
    "p-delta": {"geometry": "p-delta", "leaning_load": 1e6},
    "flexible floors": {"diaphragm": False, "beam_load": 0.0},
}


@pytest.mark.parametrize("case", list(CASES))
def test_round_trip_gives_the_same_frame(ops: Any, case: str) -> None:
    frame = three_by_two(**CASES[case])
    built = osf.build(ops, frame)
    got = read_opensees_frame(ops, name="imported")
    g = got.frame
    order = [built.node.index(t) for t in got.node_tags]
    assert order == list(range(frame.n_nodes))
    assert got.element_tags == tuple(range(1, frame.n_elements + 1))
    assert got.hinge_tags == tuple(10001 + h for h in range(len(frame.hinges)))
    np.testing.assert_array_equal(g.nodes, frame.nodes)
    np.testing.assert_array_equal(g.elements, frame.elements)
    np.testing.assert_array_equal(g.supports, frame.supports)
    np.testing.assert_array_equal(g.masses, frame.masses)
    np.testing.assert_array_equal(g.nodal_loads, frame.nodal_loads)
    np.testing.assert_allclose(g.member_loads, frame.member_loads, rtol=1e-12)
    np.testing.assert_array_equal(g.leaning_loads, frame.leaning_loads)
    np.testing.assert_allclose(g.EA, frame.EA, rtol=1e-12)
    np.testing.assert_allclose(g.EI, frame.EI, rtol=1e-12)
    assert (g.diaphragm, g.geometry, g.name) == (frame.diaphragm, frame.geometry, "imported")
    assert len(g.hinges) == len(frame.hinges)
    for mine, theirs in zip(g.hinges, frame.hinges, strict=True):
        assert (mine.element, mine.end, type(mine.law)) == (
            theirs.element, theirs.end, type(theirs.law))
        for attr in ("k0", "m_y", "hardening"):
            assert getattr(mine.law, attr) == pytest.approx(getattr(theirs.law, attr),
                                                            rel=1e-12, abs=0.0)


@pytest.mark.parametrize("case", ["gravity", "leaning", "p-delta"])
def test_imported_frame_pushes_over_as_opensees_does(ops: Any, case: str) -> None:
    frame = three_by_two(**CASES[case])
    built = osf.build(ops, frame)
    imported = frame_from_opensees(ops)
    mine = pushover(imported, 0.4)
    assert mine.stopped == "target"
    original = pushover(frame, 0.4)
    same = np.interp(original.roof_displacement, mine.roof_displacement, mine.base_shear)
    assert np.max(np.abs(same - original.base_shear)) <= 1e-9 * original.peak_base_shear
    osf.gravity(ops)
    theirs = osf.pushover(ops, built, mine.load_shape, 0.4, 0.000625)
    assert theirs.complete
    at = np.interp(theirs.roof, mine.roof_displacement, mine.base_shear)
    assert np.max(np.abs(theirs.base_shear - at)) <= 1e-6 * mine.peak_base_shear


def hand_portal(ops: Any, *, hinge_mat: Callable[[Any], None] | None = None,
                extra: Callable[[Any], None] | None = None, tie_floor: bool = True) -> None:
    """The issue's portal frame (span 6 m, height 4 m, EI = 2e8 N·m², M_p 300 / 600 kN·m),
    written as an OpenSees user writes it: joints 1-4, member ends 11-18; base hinges with
    their member-end nodes fixed in translation, the others tied by equalDOF; rotation as
    -dir 3; a Steel01 material with b = 0 for the columns, ElasticPP for the beam."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0, 0), (2, 6, 0), (3, 0, 4), (4, 6, 4), (11, 0, 0), (12, 0, 4),
                      (13, 6, 0), (14, 6, 4), (15, 0, 4), (16, 6, 4)):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.fix(11, 1, 1, 0)
    ops.fix(13, 1, 1, 0)
    for joint, end in ((3, 12), (4, 14), (3, 15), (4, 16)):
        ops.equalDOF(joint, end, 1, 2)
    if tie_floor:
        ops.equalDOF(3, 4, 1)
    ops.mass(3, 5e4, 0.0, 0.0)
    ops.mass(4, 5e4, 0.0, 0.0)
    ops.geomTransf("Linear", 1)
    E, A, I = 2e11, 1e-2, 1e-3  # EI = 2e8 N·m²
    ops.element("elasticBeamColumn", 1, 11, 12, A, E, I, 1)
    ops.element("elasticBeamColumn", 2, 13, 14, A, E, I, 1)
    ops.element("elasticBeamColumn", 3, 15, 16, A, E, I, 1)
    if hinge_mat is None:
        ops.uniaxialMaterial("Steel01", 1, 3e5, 1e11, 0.0)
    else:
        hinge_mat(ops)
    ops.uniaxialMaterial("ElasticPP", 2, 1e11, 6e5 / 1e11)
    for z, a, b, mat in ((101, 11, 1, 1), (102, 12, 3, 1), (103, 13, 2, 1), (104, 14, 4, 1),
                         (105, 3, 15, 2), (106, 4, 16, 2)):
        ops.element("zeroLength", z, a, b, "-mat", mat, "-dir", 3)
    if extra is not None:
        extra(ops)


def test_hand_written_portal_carries_its_sway_mechanism_load(ops: Any) -> None:
    hand_portal(ops)
    got = read_opensees_frame(ops, name="portal")
    f = got.frame
    assert got.node_tags == (1, 2, 3, 4)
    assert (f.n_nodes, f.n_elements, len(f.hinges), f.diaphragm) == (4, 3, 6, True)
    assert f.EI == pytest.approx([2e8] * 3, rel=1e-12)
    columns = [h.law for h in f.hinges if h.element < 2]
    assert all(isinstance(law, ElasticPlastic) and law.m_y == pytest.approx(3e5, rel=1e-12)
               for law in columns)
    assert f.floor_masses == pytest.approx([1e5])
    r = pushover(f, 0.2)
    assert r.peak_base_shear == pytest.approx(4 * 3e5 / 4.0, rel=1e-9)


def _steel01_isotropic(o: Any) -> None:
    o.uniaxialMaterial("Steel01", 1, 3e5, 1e11, 0.01, 0.01, 1.0, 0.0, 1.0)


def _imk(o: Any) -> None:
    o.uniaxialMaterial("IMKBilin", 1, 1e11, 0.03, 0.02, 0.2, 3e5, 1.1, 0.1, 0.03, 0.02, 0.2,
                       3e5, 1.1, 0.1, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0)


def _elastic_hinge(o: Any) -> None:
    o.uniaxialMaterial("Elastic", 1, 1e11)


def _truss(o: Any) -> None:
    o.uniaxialMaterial("Elastic", 9, 2e11)
    o.element("Truss", 99, 3, 2, 1e-3, 9)


def _inclined_load(o: Any) -> None:
    o.timeSeries("Linear", 1)
    o.pattern("Plain", 1, 1)
    o.eleLoad("-ele", 3, "-type", "-beamUniform", -1e4, 5e3)


def _corotational(o: Any) -> None:
    o.geomTransf("Corotational", 7)
    o.node(20, 3.0, 8.0)
    o.element("elasticBeamColumn", 7, 3, 20, 1e-2, 2e11, 1e-3, 7)


def _rigid_link(o: Any) -> None:
    o.equalDOF(3, 4, 2)  # with the floor's tie in x: the beam rigid in x and y


def _one_end_released(o: Any) -> None:
    o.node(20, 3.0, 8.0)
    o.element("elasticBeamColumn", 7, 3, 20, 1e-2, 2e11, 1e-3, 1, "-release", 1)


@pytest.mark.parametrize(("mat", "extra", "tie", "expected"), [
    (_steel01_isotropic, None, True, "material 1 (Steel01): isotropic hardening"),
    (_elastic_hinge, None, True, "material 1 (ElasticMaterial): not supported as a hinge"),
    (None, _truss, True, "element 99 (Truss): not supported"),
    (None, _inclined_load, True, "element 3 (ElasticBeam2d): its -beamUniform load"),
    (None, _corotational, True, "geometric transformation CorotCrdTransf2d: not supported"),
    (None, _rigid_link, True, "equalDOF 3 4 (DOFs [1, 2]): pounding reads equalDOF as"),
    (None, _one_end_released, True, "element 7 (ElasticBeam2d): -release 1"),
])
def test_what_it_cannot_read_is_refused_in_one_line(ops: Any, mat: Any, extra: Any, tie: bool,
                                                    expected: str) -> None:
    hand_portal(ops, hinge_mat=mat, extra=extra, tie_floor=tie)
    with pytest.raises(ValueError) as info:
        frame_from_opensees(ops)
    message = str(info.value)
    assert expected in message
    assert "\n" not in message


def test_a_floor_tied_in_part_is_refused(ops: Any) -> None:
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x in ((1, 0.0), (2, 6.0), (3, 11.0)):
        ops.node(tag, x, 0.0)
        ops.fix(tag, 1, 1, 1)
        ops.node(tag + 10, x, 4.0)
    ops.geomTransf("Linear", 1)
    for tag in (1, 2, 3):
        ops.element("elasticBeamColumn", tag, tag, tag + 10, 1e-2, 2e11, 1e-3, 1)
    ops.element("elasticBeamColumn", 4, 11, 12, 1e-2, 2e11, 1e-3, 1)
    ops.element("elasticBeamColumn", 5, 12, 13, 1e-2, 2e11, 1e-3, 1)
    ops.equalDOF(11, 12, 1)
    with pytest.raises(ValueError, match=r"floor at y = 4 m does not tie nodes \[13\]"):
        frame_from_opensees(ops)


def _imk_peak(o: Any) -> None:
    o.uniaxialMaterial("IMKPeakOriented", 1, 1e11, 0.03, 0.02, 0.2, 3e5, 1.1, 0.1, 0.025,
                       0.02, 1e10, 2.5e5, 1.15, 0.2, 1.0, 0.8, 1.2, 1.0, 1.0, 1.0, 1.0, 1.0,
                       1.0, 0.9)


@pytest.mark.parametrize(("mat", "expected"), [
    (_imk, dict(k0=1e11, theta_p=0.03, theta_pc=0.02, theta_u=0.2, m_y=3e5, mc_my=1.1,
                kappa=0.1, lambda_s=1.0, lambda_c=1.0, lambda_k=1.0)),
    (_imk_peak, dict(k0=1e11, theta_p=0.03, theta_p_neg=0.025, theta_u_neg=float("inf"),
                     m_y_neg=2.5e5, mc_my_neg=1.15, kappa_neg=0.2, lambda_s=1.0,
                     lambda_c=0.8, lambda_a=1.2, lambda_k=1.0, d_neg=0.9)),
])
def test_imk_materials_become_imk_laws(ops: Any, mat: Any, expected: dict[str, float]) -> None:
    """IMKBilin and IMKPeakOriented import as the IMK laws with the constants typed (the
    arguments in OpenSees' order: Ke, then each side's dp, dpc, du, Fy, FmaxFy, FresFy, then
    the Λ and c of each mode, D+ and D−; du = 1e10 is no ultimate rotation)."""
    from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented

    hand_portal(ops, hinge_mat=mat)
    f = frame_from_opensees(ops)
    law = next(h.law for h in f.hinges if h.element == 0)
    assert isinstance(law, IMKPeakOriented if mat is _imk_peak else IMKBilinear)
    for key, value in expected.items():
        assert getattr(law, key) == pytest.approx(value, rel=1e-12), key


def test_an_imk_material_is_read_through_the_materials_argument(ops: Any) -> None:
    hand_portal(ops, hinge_mat=_imk)
    law = ElasticPlastic(k0=1e11, m_y=3e5)
    f = frame_from_opensees(ops, materials={1: law})
    assert [h.law for h in f.hinges if h.element < 2] == [law] * 4
    assert pushover(f, 0.2).peak_base_shear == pytest.approx(3e5, rel=1e-9)


def test_a_three_dimensional_model_is_refused(ops: Any) -> None:
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    with pytest.raises(ValueError, match=r"^node 1: 3-D with 6 DOFs; pounding imports planar"):
        frame_from_opensees(ops)


def test_load_patterns_choose_the_gravity_loads(ops: Any) -> None:
    def loads(o: Any) -> None:
        o.timeSeries("Linear", 1)
        o.pattern("Plain", 1, 1)
        o.load(3, 0.0, -1e5, 0.0)
        o.pattern("Plain", 2, 1)
        o.load(3, 1e3, 0.0, 0.0)  # a lateral pattern the user pushes with

    hand_portal(ops, extra=loads)
    gravity_only = frame_from_opensees(ops, load_patterns=[1])
    assert gravity_only.nodal_loads[2].tolist() == [0.0, -1e5, 0.0]
    both = frame_from_opensees(ops)
    assert both.nodal_loads[2].tolist() == [1e3, -1e5, 0.0]
    with pytest.raises(ValueError, match=r"load_patterns: pattern 7 is not in the domain"):
        frame_from_opensees(ops, load_patterns=[7])


def test_importing_leaves_the_domain_as_it_was(ops: Any) -> None:
    """The materials are read through parameters that are removed again, not by straining
    them: a second import reads the same laws, and no parameter is left behind."""
    hand_portal(ops)
    first = frame_from_opensees(ops)
    second = frame_from_opensees(ops)
    assert [h.law for h in first.hinges] == [h.law for h in second.hinges]
    assert list(ops.getParamTags()) == []


def test_a_material_that_is_not_a_hinge_law_is_refused(ops: Any) -> None:
    hand_portal(ops)
    with pytest.raises(ValueError, match=r"^materials\[1\]: need a hinge law \(got 3\.0\)$"):
        frame_from_opensees(ops, materials={1: 3.0})  # type: ignore[dict-item]


def test_a_floor_fixed_in_x_beside_tied_floors_is_accepted(ops: Any) -> None:
    """A two-storey column pair whose first floor is held in x (fix … 1 0 0) and whose roof is
    tied: the held floor has nothing to tie (it raised an IndexError before)."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for k, x in enumerate((0.0, 6.0)):
        for level, y in enumerate((0.0, 4.0, 8.0)):
            ops.node(10 * level + k + 1, x, y)
        ops.fix(k + 1, 1, 1, 1)
        ops.fix(10 + k + 1, 1, 0, 0)
    ops.geomTransf("Linear", 1)
    for k in (1, 2):
        ops.element("elasticBeamColumn", k, k, 10 + k, 1e-2, 2e11, 1e-3, 1)
        ops.element("elasticBeamColumn", 10 + k, 10 + k, 20 + k, 1e-2, 2e11, 1e-3, 1)
    ops.element("elasticBeamColumn", 30, 11, 12, 1e-2, 2e11, 1e-3, 1)
    ops.element("elasticBeamColumn", 31, 21, 22, 1e-2, 2e11, 1e-3, 1)
    ops.equalDOF(21, 22, 1)
    f = frame_from_opensees(ops)
    assert f.diaphragm
    assert f.levels.tolist() == [4.0, 8.0]


def _bilin(lam: float) -> Any:
    """A ``Bilin`` material (K_e 1e8; M_y 3e5 / 2.5e5; a_s 0.003 / 0.002; θ_p 0.03 / 0.025;
    θ_pc 0.2 / 0.15; residual 0.4 / 0.3; θ_u 0.25 / 0.2), cyclic deterioration Λ = ``lam``."""
    def make(o: Any) -> None:
        o.uniaxialMaterial("Bilin", 1, 1e8, 0.003, 0.002, 3e5, -2.5e5, lam, lam, lam, lam,
                           1.0, 1.0, 1.0, 1.0, 0.03, 0.025, 0.2, 0.15, 0.4, 0.3, 0.25, 0.2,
                           1.0, 1.0)
    return make


def test_a_bilin_material_without_deterioration_moves_as_opensees_does(ops: Any) -> None:
    """OpenSees' older ``Bilin`` (which it says to replace by IMKBilin) imports as the
    bilinear IMK law, M_c/M_y = 1 + a_s K_e θ_p / M_y, and follows OpenSees' Bilin along a
    cyclic path of growing amplitude into the post-capping branch on both sides."""
    import math

    from pounding.hysteresis.hinges import moment_path
    from pounding.hysteresis.imk import IMKBilinear

    hand_portal(ops, hinge_mat=_bilin(0.0))
    f = frame_from_opensees(ops)
    law = next(h.law for h in f.hinges if h.element == 0)
    assert isinstance(law, IMKBilinear)
    assert law.mc_my == pytest.approx(1 + 0.003 * 1e8 * 0.03 / 3e5, rel=1e-12)
    assert law.mc_my_neg == pytest.approx(1 + 0.002 * 1e8 * 0.025 / 2.5e5, rel=1e-12)
    assert (law.m_y, law.m_y_neg, law.kappa_neg) == (3e5, 2.5e5, 0.3)
    path = [0.0]
    for amp in (0.005, 0.02, 0.06, 0.1):
        path += [amp, -amp, amp]
    ops.wipe()
    _bilin(0.0)(ops)
    ops.testUniaxialMaterial(1)
    theirs, previous = [0.0], 0.0
    for target in path[1:]:
        n = max(1, math.ceil(abs(target - previous) / 1e-5))
        for j in range(1, n + 1):
            ops.setStrain(previous + (target - previous) * j / n)
        theirs.append(ops.getStress())
        previous = target
    ours = moment_path(law, path)
    # measured 2026-11-27: 1.9e-16 of M_y (constants typed with 6 digits or fewer)
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=1e-9 * 3e5)
    assert min(ours) < -2.5e5 and max(ours) > 3e5  # (past yield both ways)


def test_a_bilin_material_with_cyclic_deterioration_is_refused(ops: Any) -> None:
    hand_portal(ops, hinge_mat=_bilin(1.0))
    with pytest.raises(ValueError, match=r"material 1 \(Bilin\): cyclic deterioration \(LamdaS "
                                         r"= 1, LamdaK = 1, LamdaA = 1, LamdaD = 1\) is not "
                                         r"read: OpenSees replaced Bilin by IMKBilin"):
        frame_from_opensees(ops)
