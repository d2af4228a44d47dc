"""Frames whose masses are not only on rigid floors, in time histories: frames without rigid
floors (a lateral mass at every node, beams axially flexible), vertical and rotational masses
(a rotational mass at a hinged joint keeps the hinge's joint rotation among the dynamic DOFs),
a neighbour striking the frame's outer column line, and a slab striking a node of the
frame's column between its floors (floor to column at a node, with the column's bending).

Checked against the plain SciPy frame reference (:mod:`pounding.integrate.frame_reference`:
its own condensation over the DOFs with mass, ``solve_ivp`` at rtol 1e-10), against the
model's SciPy reference with the contacts (:func:`pounding.integrate.reference.simulate_reference`),
and against rigid floors as the beams' axial stiffness grows."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from frame_kernel_models import KV  # (this folder)

from pounding.contact.spec import ContactSpec
from pounding.devices import Link
from pounding.ground_motion import el_centro
from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
from pounding.integrate import simulate
from pounding.integrate.frame_reference import simulate_frame_reference
from pounding.integrate.reference import simulate_reference
from pounding.model import PoundingModel
from pounding.structure import MatrixBuilding, ShearBuilding
from pounding.structure.damping import RayleighDamping
from pounding.structure.frame import Frame, FrameHinge, regular_frame
from pounding.structure.frame_linear import frame_matrix_building


def _three(diaphragm: bool, beam_EA: float = 5e9, hinges: bool = True) -> Frame:
    """A 3-storey, 2-bay frame with bilinear hinges (3 % hardening), gravity on its beams, a
    leaning column and P-Delta; its floor masses shared by the floor's three nodes."""
    law = [BilinearHinge(k0=1e11, m_y=0.6 * m, hardening=0.03) for m in (4e5, 3.5e5, 3e5)]
    return regular_frame([6.0, 6.0], [4.0, 3.5, 3.5], column_EI=[3e8, 2.5e8, 2e8],
                         beam_EI=[2.5e8, 2e8, 1.5e8], column_hinge=law if hinges else None,
                         beam_hinge=law[::-1] if hinges else None,
                         floor_mass=[8e4, 8e4, 6e4], beam_load=2e4, beam_EA=beam_EA,
                         column_EA=2e10, leaning_load=5e5, geometry="p-delta",
                         diaphragm=diaphragm, name="three")


def _close(a: np.ndarray, b: np.ndarray, rel: float) -> None:
    assert np.max(np.abs(a - b)) <= rel * np.max(np.abs(b))


def _follows_the_reference(frame: Frame, floor_columns: list[list[int]]) -> None:
    """The kernel against the SciPy frame reference, 3 s of El Centro × 1.5; the reference's
    floor displacement is the mean of the floor's nodes, the kernel's the mean of the
    columns ``floor_columns[j]`` of its displacements."""
    motion = el_centro().scaled(1.5)
    ref = simulate_frame_reference(frame, motion.accel, motion.dt, duration=3.0)
    got = simulate(PoundingModel([frame_matrix_building(frame)], [], KV), motion,
                   duration=3.0, dt=motion.dt)
    floors = np.stack([got.displacement[:, c].mean(axis=1) for c in floor_columns], axis=1)
    # measured 2026-11-27: 1.7e-9 / 1.1e-10 (floors), 1.1e-8 / 7.7e-9 (hinge rotations),
    # 9.6e-9 / 7.0e-9 (moments), 2e-9 / 5e-10 (hysteretic energy)
    _close(floors, ref.floor_displacements - ref.gravity_floor_displacements, 1e-7)
    _close(got.hinge_rotation, ref.hinge_rotations, 1e-6)
    _close(got.hinge_moment, ref.hinge_moments, 1e-6)
    assert np.sum(got.hinge_dissipated) == pytest.approx(np.sum(ref.hinge_hysteretic[-1]),
                                                         rel=1e-6)
    assert np.max(ref.peak_hinge_rotation) > 10 * min(h.law.theta_y for h in frame.hinges)


def test_a_frame_without_rigid_floors_follows_the_scipy_frame_reference() -> None:
    frame = _three(diaphragm=False)
    b = frame_matrix_building(frame)
    # its floors are the left column line (nodes 4, 7, 10), struck there from the left and
    # at the right column line (nodes 6, 9, 12) from the right; the middle line after
    assert b.labels == ("F1", "F2", "F3", "N6x", "N9x", "N12x", "N5x", "N8x", "N11x")
    assert b.floors == (0, 1, 2)
    assert dict(b.faces) == {"left": (0, 1, 2), "right": (3, 4, 5)}
    assert np.array_equal(b.r, np.ones(9))
    _follows_the_reference(frame, [[0, 6, 3], [1, 7, 4], [2, 8, 5]])


def test_vertical_and_rotational_masses_follow_the_scipy_frame_reference() -> None:
    # rigid floors, 20 t vertical mass and 5 t·m² rotational inertia at every joint: the
    # joints' rotations (where the hinges are) are dynamic DOFs, not condensed out
    frame = _three(diaphragm=True)
    m = np.array(frame.masses)
    standing = frame.node_level >= 0
    m[:, 1] = np.where(standing, 2e4, 0.0)
    m[:, 2] = np.where(standing, 5e3, 0.0)
    frame = dataclasses.replace(frame, masses=m)
    b = frame_matrix_building(frame)
    assert b.n == 3 + 2 * 9 and b.labels[3:5] == ("N4y", "N4r") and not b.faces
    assert np.array_equal(b.r, [1.0] * 3 + [0.0] * 18)  # (the ground shakes sideways)
    _follows_the_reference(frame, [[0], [1], [2]])


def test_stiff_beams_without_rigid_floors_pound_as_rigid_floors() -> None:
    # elastic frames beside a shear building: as the beams' EA grows the frame without rigid
    # floors approaches the frame with them, impacts and all. (The contact's dashpot is
    # given, c: the one made from e and the colliding masses would see a node's third of
    # the floor mass where the rigid floor has all of it.)
    other = ShearBuilding([1.5e5] * 3, [1.2e8] * 3, [4.0, 3.5, 3.5])
    contact = ContactSpec("kelvin-voigt", k=2e9, c=2e6)
    motion = el_centro()
    rigid = simulate(PoundingModel([frame_matrix_building(_three(True, hinges=False)), other],
                                   [0.01], contact), motion, duration=6.0)
    errors, impacts = [], []
    for ea in (1e11, 1e12):
        b = frame_matrix_building(_three(False, beam_EA=ea, hinges=False))
        model = PoundingModel([b, other], [0.01], contact)
        # struck at its right column line: the contacts' left points are N6x, N9x, N12x,
        # labelled by floor
        assert [b.labels[c.left.upper] for c in model.contacts] == ["N6x", "N9x", "N12x"]
        assert [c.label for c in model.contacts] == ["B1F1-B2F1", "B1F2-B2F2", "B1F3-B2F3"]
        got = simulate(model, motion, duration=6.0)
        impacts.append(got.n_impacts)
        errors.append(np.max(np.abs(got.displacement[:, [3, 4, 5]]
                                    - rigid.displacement[:, [0, 1, 2]]))
                      / np.max(np.abs(rigid.displacement[:, :3])))
    # measured 2026-11-27: 1.9e-3 at EA 1e11, 1.7e-4 at 1e12 (∝ 1/EA); 12 impacts
    assert errors[1] < 5e-4 and errors[1] < errors[0] / 5, errors
    assert impacts[1] == rigid.n_impacts > 0, (impacts, rigid.n_impacts)


def _column_node_frame(hinges: bool) -> Frame:
    """A one-bay, two-storey frame (4 m, 3.5 m; span 6 m) whose right column has a node at
    2.0 m with 2 t of lateral mass (the column's own, lumped there); EPP hinges at the
    column bases and the beams' ends when ``hinges``."""
    nodes = [[0, 0], [6, 0], [0, 4], [6, 4], [0, 7.5], [6, 7.5], [6, 2.0]]
    elements = [[0, 2], [1, 6], [6, 3], [2, 3], [2, 4], [3, 5], [4, 5]]
    EI = [3e8, 3e8, 3e8, 2.5e8, 2.5e8, 2.5e8, 2e8]
    supports = np.zeros((7, 3), dtype=bool)
    supports[[0, 1]] = True
    masses = np.zeros((7, 3))
    masses[[2, 3], 0] = 4e4
    masses[[4, 5], 0] = 3e4
    masses[6, 0] = 2e3
    law = ElasticPlastic(k0=1e11, m_y=2.5e5)
    hinge_list = ((FrameHinge(0, 0, law), FrameHinge(1, 0, law), FrameHinge(3, 0, law),
                   FrameHinge(3, 1, law), FrameHinge(6, 0, law), FrameHinge(6, 1, law))
                  if hinges else ())
    return Frame(nodes=nodes, elements=elements, EA=np.full(7, 1e11), EI=EI,
                 supports=supports, hinges=hinge_list, masses=masses,
                 damping=RayleighDamping(0.05, 0.05), name="split column")


def test_a_slab_strikes_the_node_of_the_frames_column_between_its_floors() -> None:
    frame = frame_matrix_building(_column_node_frame(hinges=False))
    # 2 m is not a floor (no beam there): the floors stay at 4 and 7.5 m, with their drifts
    assert frame.labels == ("F1", "F2", "N7x") and frame.floors == (0, 1)
    assert dict(frame.faces) == {"left": (0, 1), "right": (0, 1, 2)}
    assert list(frame.face_dofs("right")) == [2, 0, 1]  # (by elevation)
    low = ShearBuilding.uniform(1, 6e4, 6e7, height=2.0)  # its roof at the node's level
    model = PoundingModel([frame, low], [0.005], KV)
    (c,) = model.contacts
    assert (c.left.upper, c.left.xi, c.label) == (2, 1.0, "B1S1@0.50-B2F1")
    motion = el_centro().scaled(1.5)
    got = simulate(model, motion, duration=5.0)
    ref = simulate_reference(model, motion, duration=5.0, rtol=1e-10)
    assert got.n_impacts == ref.n_impacts > 0
    # measured 2026-11-27: 2.0e-10, 6 impacts
    scale = np.max(np.abs(ref.displacement))
    err = np.max(np.abs(got.displacement - ref.displacement)) / scale
    assert err < 1e-7, err
    # the column bends at the node: it moves unlike the storey's linear interpolation
    node, floor1 = got.displacement[:, 2], got.displacement[:, 0]
    assert np.max(np.abs(node - 0.5 * floor1)) > 0.05 * np.max(np.abs(node))


def test_a_yielding_frame_struck_at_its_column_node_balances_its_energy() -> None:
    frame = frame_matrix_building(_column_node_frame(hinges=True))
    low = ShearBuilding.uniform(1, 6e4, 6e7, height=2.0)
    got = simulate(PoundingModel([frame, low], [0.005], KV), el_centro().scaled(3.0),
                   duration=8.0)
    # measured 2026-11-27: 6 impacts, peak hinge rotations 0.033-0.034 rad, 1.4e-10
    assert got.n_impacts > 0
    assert np.min(got.hinge_peak_rotation) > 10 * 2.5e5 / 1e11  # (every hinge yielded)
    assert got.energy_balance_error < 1e-8


def test_a_floor_without_lateral_mass_where_it_is_struck_is_refused() -> None:
    frame = _three(diaphragm=False, hinges=False)
    m = np.array(frame.masses)
    m[8, 0] = 0.0  # node 9: the right end of floor 2
    with pytest.raises(ValueError, match=r"three: masses: node 9 \(nodes\[8\], floor 2, "
                                         r"y = 7\.5 m\) has no lateral mass"):
        frame_matrix_building(dataclasses.replace(frame, masses=m))


@pytest.mark.parametrize("order", ["frame left", "frame right"])
def test_a_link_holds_the_frame_at_its_column_line_toward_the_other(order: str) -> None:
    # a viscous damper across the gap at floor 3: on the frame without rigid floors it
    # acts at the column line facing the neighbour (N12x on the right, F3 = N10x on the
    # left), checked against the model's SciPy reference
    frame = frame_matrix_building(_three(diaphragm=False, hinges=False))
    other = ShearBuilding([1.5e5] * 3, [1.2e8] * 3, [4.0, 3.5, 3.5])
    row, (lo, hi) = ([frame, other], ("B1F3", "B2F3")) if order == "frame left" else \
        ([other, frame], ("B1F3", "B2F3"))
    model = PoundingModel(row, [0.01], KV, devices=[Link((lo, hi), "viscous", c=3e6)])
    names = model.dof_names()
    assert [names[d] for d in model.link_dofs[0]] == (["N12x", "F3"] if order == "frame left"
                                                      else ["F3", "F3"])
    motion = el_centro()
    got = simulate(model, motion, duration=1.5)
    if order == "frame right":  # (the same pair mirrored: the DOFs above are the point)
        assert np.max(np.abs(got.link_force)) > 1e4
        return
    ref = simulate_reference(model, motion, duration=1.5, rtol=1e-10)
    scale = np.max(np.abs(ref.displacement))
    # measured 2026-11-27: 2.8e-10 (4 s; 0.14 MN in the damper)
    err = np.max(np.abs(got.displacement - ref.displacement)) / scale
    assert err < 1e-6, err
    assert np.max(np.abs(got.link_force)) > 1e4
    np.testing.assert_allclose(got.link_displacement[:, 0],
                               got.displacement[:, model.link_dofs[0][1]]
                               - got.displacement[:, model.link_dofs[0][0]])


def test_faces_of_a_matrix_building_are_checked_and_kept() -> None:
    import pickle

    kw = dict(M=np.diag([2e5, 2e5, 1e5]), K=[[6e7, -2e7, 0], [-2e7, 4e7, -2e7], [0, -2e7, 2e7]],
              labels=["F1", "R1", "F2"], elevations=[3.5, 3.5, 6.5], floors=["F1", "F2"],
              r=[1.0, 1.0, 1.0])
    b = MatrixBuilding(**kw, faces={"right": ["R1", "F2"]})
    assert np.array_equal(b.face_dofs("right"), [1, 2])
    assert np.array_equal(b.face_dofs("left"), [0, 2])  # (the floors)
    assert list(b.face_below("right")) == [-2, -1, 1]
    assert pickle.loads(pickle.dumps(b)) == b
    assert b != MatrixBuilding(**kw)
    with pytest.raises(ValueError, match=r"faces: 'top' is not a side \(left or right\)"):
        MatrixBuilding(**kw, faces={"top": [0]})
    with pytest.raises(ValueError, match=r"faces\.right\[0\] = 'X' is not one of the labels"):
        MatrixBuilding(**kw, faces={"right": ["X"]})
    assert not MatrixBuilding(**kw, faces={"right": None}).faces  # (the floors)
    # a rotation is not struck (it once was taken for a displacement, interpolated)
    rot = {**kw, "r": [1.0, 0.0, 1.0]}
    with pytest.raises(ValueError, match=r"faces\.right: 'R1' is not a translation along the "
                                         r"row \(its r is 0, not 1\)"):
        MatrixBuilding(**rot, faces={"right": ["R1", "F2"]})
    with pytest.raises(ValueError, match=r"faces\.right: 'F1' and 'R1' are both at "
                                         r"elevation 3\.5 m"):
        MatrixBuilding(**kw, faces={"right": ["F1", "R1", "F2"]})



def _opensees_frames() -> Any:
    """tests/structure/opensees_frames.py (the frames built in OpenSeesPy node for node)."""
    import importlib.util
    import sys
    from pathlib import Path

    path = Path(__file__).parents[1] / "structure" / "opensees_frames.py"
    spec = importlib.util.spec_from_file_location("opensees_frames", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("opensees_frames", module)
    spec.loader.exec_module(module)
    return sys.modules["opensees_frames"]


def test_opensees_converges_toward_the_kernel_on_a_frame_without_rigid_floors() -> None:
    # the 3-storey frame without rigid floors, Steel01 hinges, vertical masses at the joints,
    # mass-proportional damping (the same C in both: 5 % at 1 s), no gravity; OpenSees'
    # Newmark (average acceleration, Newton) at three steps against every lateral DOF
    ops = pytest.importorskip("openseespy.opensees")
    osf = _opensees_frames()
    zeta, w1 = 0.05, 2 * np.pi
    law = [BilinearHinge(k0=1e11, m_y=0.6 * m, hardening=0.03) for m in (4e5, 3.5e5, 3e5)]
    frame = regular_frame([6.0, 6.0], [4.0, 3.5, 3.5], column_EI=[3e8, 2.5e8, 2e8],
                          beam_EI=[2.5e8, 2e8, 1.5e8], column_hinge=law, beam_hinge=law[::-1],
                          floor_mass=[8e4, 8e4, 6e4], beam_EA=5e9, column_EA=2e10,
                          diaphragm=False, name="no rigid floors",
                          damping=RayleighDamping(zeta, zeta / 2, period_i=1.0, period_j=0.5))
    m = np.array(frame.masses)
    m[:, 1] = np.where(frame.node_level >= 0, 2e4, 0.0)
    frame = dataclasses.replace(frame, masses=m)
    b = frame_matrix_building(frame)
    assert np.allclose(b.damping_matrix(), 2 * zeta * w1 * b.M, rtol=0, atol=1e-9 * b.M.max())
    motion, duration = el_centro().scaled(1.5), 3.0
    got = simulate(PoundingModel([b], [], KV), motion, duration=duration, dt=motion.dt)
    assert np.max(got.hinge_dissipated) > 0.0
    dofs = b.gravity_state.dofs
    node_of = {int(dofs.node[i, 0]): i for i in range(frame.n_nodes) if dofs.node[i, 0] >= 0}
    lateral = [k for k in range(b.n) if b.r[k] == 1.0]
    tags = [node_of[int(b.kept[k])] + 1 for k in lateral]  # (OpenSees node i + 1)
    ours = got.displacement[:, lateral]
    errors = []
    for dt in (1e-3, 5e-4, 2.5e-4):
        osf.build(ops, frame)
        samples = int(round(duration / motion.dt))
        ops.timeSeries("Path", 2, "-dt", motion.dt, "-values", *motion.accel[:samples + 2])
        ops.pattern("UniformExcitation", 2, 1, "-accel", 2)
        ops.rayleigh(2 * zeta * w1, 0.0, 0.0, 0.0)
        ops.constraints("Plain")
        ops.numberer("RCM")
        ops.system("BandGeneral")
        ops.test("NormDispIncr", 1e-12, 50)
        ops.algorithm("Newton")
        ops.integrator("Newmark", 0.5, 0.25)
        ops.analysis("Transient")
        every = int(round(motion.dt / dt))
        theirs = np.zeros_like(ours)
        for k in range(samples * every):
            assert ops.analyze(1, dt) == 0, (dt, k)
            if (k + 1) % every == 0:
                theirs[(k + 1) // every] = [ops.nodeDisp(t, 1) for t in tags]
        ops.wipe()
        errors.append(np.max(np.abs(theirs - ours)) / np.max(np.abs(ours)))
    # measured 2026-11-27: 1.7e-4, 4.1e-5, 1.6e-5
    assert errors[0] > errors[1] > errors[2] and errors[2] < 5e-5, errors


def test_outputs_of_a_frame_without_rigid_floors_name_its_dofs(tmp_path: Any) -> None:
    # its node DOFs keep their own names (not "B1F4" … made up from their index), the
    # residual drift is its floors' only, and the report's gap check reads the column
    # line that is struck (once: the floor's left node, 0.56 mm off)
    from pounding.cli import main

    path = tmp_path / "m.toml"
    text = (Path(__file__).parents[2] / "src" / "pounding" / "examples" /
            "frames_pounding.toml").read_text()
    text = text.replace('geometry = "p-delta"', 'geometry = "p-delta"\ndiaphragm = false\n'
                        'beam_EA = 5.0e9').replace("scale = 1.5", "scale = 1.5\nduration = 3.0")
    path.write_text(text)
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--no-figures"]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert set(summary["residual_drift_m"]) == {"B1F1", "B1F2", "B1F3", "B2F1", "B2F2"}
    from pounding.report.run_checks import gap_check_section
    from pounding.report.run_folder import read_run

    run = read_run(out)
    table = gap_check_section(run)[0]
    for row in table.rows:
        label, max_rel = row[0], row[6]
        c = next(c for c in run.built.model.contacts if c.label == label)
        pen = run.ds["penetration"].sel(contact=label).values
        assert max_rel == pytest.approx(float(np.max(pen)) + c.gap, abs=1e-12)
    names = [str(x) for x in run.ds["floor"].values]
    assert "B1N6x" in names and "B1F4" not in names
