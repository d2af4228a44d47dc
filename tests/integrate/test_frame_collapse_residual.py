"""A yielding frame's residual drift (unloaded along its hinges' unloading stiffness), checked
against where the frame comes to rest when the shaking stops and the run goes on; and a frame
that collapses sideways stops the run with one line (:class:`FrameCollapse`) instead of being
integrated on to any drift."""

from __future__ import annotations

import numpy as np
import pytest
from frame_kernel_models import KV, _portal  # (this folder)

from pounding.ground_motion import GroundMotion, el_centro
from pounding.hysteresis.hinges import ElasticPlastic
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure.damping import RayleighDamping
from pounding.structure.frame import regular_frame
from pounding.structure.frame_configuration import FrameCollapse
from pounding.structure.frame_linear import frame_matrix_building


def test_the_residual_drift_is_where_the_frame_comes_to_rest_after_the_shaking() -> None:
    model = PoundingModel([frame_matrix_building(_portal())], [], KV)
    record = el_centro().scaled(3.0)
    shaken = simulate(model, record, duration=8.0)
    # the same 8 s of shaking, then 40 s of still ground: the 5 %-damped portal comes to
    # rest (its hinges do not yield again: the same peaks), and where it rests is its
    # residual displacement
    n = int(round(8.0 / record.dt)) + 1
    still = np.concatenate([record.accel[:n], np.zeros(int(round(40.0 / record.dt)))])
    rested = simulate(model, GroundMotion(record.dt, still, name="then still"), duration=48.0)
    np.testing.assert_allclose(rested.hinge_peak_rotation, shaken.hinge_peak_rotation,
                               rtol=1e-9)
    assert abs(rested.velocity[-1, 0]) < 1e-9  # at rest
    rest = rested.displacement[-1, 0]
    assert abs(rest) > 0.01  # a permanent offset of the mechanism, 20 mm
    assert shaken.residual_drift[0] == pytest.approx(rest, rel=1e-6)
    assert rested.residual_drift[0] == pytest.approx(rest, rel=1e-6)
    # and the summary says it (it used to say 0 for frames)
    from pounding.result.summary import inelastic_summary

    label = model.dof_labels()[0]
    assert inelastic_summary(shaken)["residual_drift_m"][label] == pytest.approx(rest,
                                                                                 rel=1e-6)


def test_a_frame_that_collapses_sideways_stops_the_run_in_one_line() -> None:
    # the portal under a leaning load whose P-Delta (P/h = 3.75 MN/m) overwhelms its
    # mechanism's strength once it sways 80 mm: a negative stiffness, no strength left
    portal = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                           column_hinge=ElasticPlastic(k0=1e11, m_y=3e5),
                           beam_hinge=ElasticPlastic(k0=1e11, m_y=6e5), floor_mass=5e4,
                           leaning_load=1.5e7, geometry="p-delta",
                           damping=RayleighDamping(0.05, 0.05), name="portal")
    model = PoundingModel([frame_matrix_building(portal)], [], KV)
    with pytest.raises(FrameCollapse, match=r"^portal \(building B1\): collapsed sideways: "
                       r"storey 1 drifted -?[0-9.]+ m, more than its height 4 m, at t = "
                       r"[0-9.]+ s \(the run stops there\)$") as caught:
        simulate(model, el_centro().scaled(3.0), duration=20.0)
    drifted = float(str(caught.value).split("drifted ")[1].split(" m")[0])
    # looked at every 0.1 s of the record: caught within a few metres of the limit, not at
    # 10⁴⁷ m as when the whole run was one call of the kernel
    assert 4.0 < abs(drifted) < 20.0
    assert isinstance(caught.value, ValueError)  # (reported like bad input by the CLI)


@pytest.mark.parametrize("speed", [0.6, 1.0])
def test_a_hinge_is_capped_when_its_first_excursion_passes_its_capping_rotation(
        speed: float) -> None:
    # the portal set swinging (no ground motion): its first excursion is monotonic, on the
    # IMK backbone not yet deteriorated, so a hinge reaches its cap exactly when its peak
    # rotation passes θ_y + θ_p of that backbone (Lignos & Krawinkler 2011) — the law's
    # constants, not the branch the kernel saw
    from pounding.hysteresis.imk import IMKBilinear

    def law(m_y: float) -> IMKBilinear:
        return IMKBilinear(k0=1e11, m_y=m_y, theta_p=0.01, theta_pc=0.08, theta_u=0.2,
                           mc_my=1.1, kappa=0.4, lambda_=0.5)

    portal = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                           column_hinge=law(3e5), beam_hinge=law(6e5), floor_mass=5e4,
                           damping=RayleighDamping(0.05, 0.05), name="portal")
    model = PoundingModel([frame_matrix_building(portal)], [], KV)
    r = simulate(model, GroundMotion(0.01, np.zeros(200), name="still"), duration=1.5,
                 initial_velocity=[speed])
    cap = np.array([fh.law.theta_y + fh.law.theta_p for fh in portal.hinges])
    np.testing.assert_array_equal(r.hinge_capped, r.hinge_peak_rotation > cap)
    assert r.hinge_capped.sum() == (4 if speed == 1.0 else 0)  # the columns' ends, or none


def test_hinges_without_a_capping_point_are_never_capped() -> None:
    r = simulate(PoundingModel([frame_matrix_building(_portal())], [], KV),
                 el_centro().scaled(3.0), duration=8.0)
    assert r.hinge_peak_rotation.max() > 0.005 and not r.hinge_capped.any()


def test_pounding_run_of_a_collapsing_frame_says_so_in_one_line_with_status_1(
        tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    from pounding.cli import main

    model = tmp_path / "collapse.toml"
    model.write_text('name = "collapse"\n[record]\nbundled = "el_centro"\nscale = 3.0\n'
                     'duration = 10.0\n[[building]]\nname = "portal"\n'
                     'damping = { ratio = 0.05 }\n[building.frame]\nbays = [6.0]\n'
                     'storey_heights = [4.0]\ncolumn_EI = 2.0e8\nbeam_EI = 2.0e8\n'
                     'floor_mass = 5.0e4\nleaning_load = 1.5e7\ngeometry = "p-delta"\n'
                     'column_hinge = { type = "elastic-plastic", k0 = 1.0e11, m_y = 3.0e5 }\n'
                     'beam_hinge = { type = "elastic-plastic", k0 = 1.0e11, m_y = 6.0e5 }\n')
    assert main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "collapsed sideways: storey 1 drifted" in err[0], err
    assert not (tmp_path / "out").exists()
