"""Frames in pounding against the same frames in OpenSeesPy: periods and pushover curves.

The OpenSees models are built from the pounding :class:`~pounding.structure.frame.Frame` by
``opensees_frames.build`` (elasticBeamColumn members, zeroLength hinges with ElasticPP or
Steel01 materials, equalDOF rigid floors, a pin-ended PDelta leaning column), so both
programs analyse one model. Skipped, saying why, where OpenSeesPy cannot load (a failure
under CI: ``tests/conftest.py``).

* Elastic periods agree to 1e-8 (both are exact eigenvalues of the same matrices).
* Pushover: pounding goes event to event (exact, piecewise linear); OpenSees takes
  displacement-controlled Newton steps. Its base shear at its own roof displacements is
  compared with pounding's curve there. Where no hinge reverses inside a step, OpenSees is
  exact too (errors ~1e-14); where one does, OpenSees' step misses the reversal point and
  carries the error on, so the error falls as the step shrinks (measured on the 3-storey,
  2-bay frame with gravity: 3.5e-6 of the peak base shear at 10 mm steps, 4.5e-7 at 2.5 mm,
  2.9e-7 at 0.625 mm, 5.5e-8 at 0.156 mm; the Newton tolerance does not change them).
* P-Delta: OpenSees' ``PDelta`` transformation uses the columns' current axial forces,
  pounding holds those of the gravity analysis. With rigid floors the storey's geometric
  stiffness depends only on the sum of its columns' axial forces, which lateral load does
  not change (overturning adds and removes equal amounts), so the two agree within
  OpenSees' convergence — measured, not assumed, by ``test_pushover_converges``'s p-delta
  case; the leaning column carries a constant load in both.
* Where OpenSees fails: the portal frame with elastic-perfectly-plastic hinges once its sway
  mechanism forms (the tangent is singular; ``DisplacementControl`` solves with it, and no
  fallback algorithm helps); the 3-storey frame in 20 mm steps (Newton oscillates between
  hinge states). pounding runs both.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
from pounding.structure import frame_analysis
from pounding.structure.frame import Frame, regular_frame
from pounding.structure.frame_analysis import frame_modes, pushover

import opensees_frames as osf  # tests/structure (pytest puts a test's folder on sys.path)

K_HINGE = 1e11  # N·m/rad: hinges rigid until they yield (θ_y = M_p / K ~ 3e-6 rad)


@pytest.fixture
def ops(opensees: Any) -> Any:
    return opensees  # (conftest.py: skipped, saying why, where OpenSeesPy cannot load)


def portal(law: type[BilinearHinge] = ElasticPlastic, hardening: float = 0.0) -> Frame:
    """The portal frame of examples/portal_pushover.toml (issue 26): span 6 m, height 4 m,
    EI = 2.0e8 N·m², hinges M_p = 300 kN·m (columns), 600 kN·m (beam)."""
    kw = {} if law is ElasticPlastic else {"hardening": hardening}
    return regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                         column_hinge=law(k0=K_HINGE, m_y=3e5, **kw),
                         beam_hinge=law(k0=K_HINGE, m_y=6e5, **kw), name="portal")


def three_by_two(**kw: Any) -> Frame:
    """A 3-storey, 2-bay frame (bays 6 and 5 m, storeys 4, 3.5, 3.5 m) with bilinear column
    hinges, elastic-plastic beam hinges, floor masses and gravity loads on the beams."""
    args: dict[str, Any] = dict(
        column_EI=[2e8, 1.5e8, 1e8], beam_EI=[3e8, 2.5e8, 2e8],
        column_EA=[2e10, 1.5e10, 1e10], beam_EA=1e10,
        column_hinge=BilinearHinge(k0=K_HINGE, m_y=5e5, hardening=0.03),
        beam_hinge=ElasticPlastic(k0=K_HINGE, m_y=4e5),
        floor_mass=[2e5, 2e5, 1.5e5], beam_load=[3e4, 3e4, 2.5e4], name="3x2")
    args.update(kw)
    return regular_frame([6.0, 5.0], [4.0, 3.5, 3.5], **args)


def opensees_errors(ops: Any, frame: Frame, target: float, steps: list[float],
                    pattern: str = "uniform") -> tuple[list[float], list[osf.PushoverCurve],
                                                       frame_analysis.PushoverResult]:
    """pounding's pushover, and OpenSees' at each step size: the largest difference of base
    shear at OpenSees' roof displacements, relative to pounding's peak."""
    exact = pushover(frame, target, pattern=pattern)
    errors, curves = [], []
    for step in steps:
        built = osf.build(ops, frame)
        if np.any(frame.member_loads) or np.any(frame.nodal_loads) or np.any(
                frame.leaning_loads):
            osf.gravity(ops)
        curve = osf.pushover(ops, built, exact.load_shape, target, step)
        at = np.interp(curve.roof, exact.roof_displacement, exact.base_shear)
        errors.append(float(np.max(np.abs(curve.base_shear - at))) / exact.peak_base_shear)
        curves.append(curve)
    return errors, curves, exact


def test_periods_of_a_three_storey_two_bay_frame_agree(ops: Any) -> None:
    frame = three_by_two(beam_load=0.0)
    osf.build(ops, frame)
    expected = osf.periods(ops, 3)
    assert frame_modes(frame)[0][:3] == pytest.approx(expected, rel=1e-8)


def test_periods_without_rigid_floors_agree(ops: Any) -> None:
    frame = three_by_two(beam_load=0.0, diaphragm=False)
    osf.build(ops, frame)
    assert frame_modes(frame)[0][:3] == pytest.approx(osf.periods(ops, 3), rel=1e-8)


def test_portal_pushover_matches_opensees_until_opensees_fails(ops: Any) -> None:
    errors, curves, exact = opensees_errors(ops, portal(), 0.2, [0.0025, 0.000625])
    assert exact.peak_base_shear == pytest.approx(4 * 3e5 / 4.0, rel=1e-9)
    assert exact.stopped == "target"
    for err, curve in zip(errors, curves, strict=True):
        assert curve.roof.size > 2  # OpenSees took some steps …
        assert err <= 1e-9  # … and agrees on every one (no hinge reverses)


def test_portal_with_hardening_hinges_matches_opensees_all_the_way(ops: Any) -> None:
    b = 1e-6  # post-yield stiffness b·K = 1e5 N·m/rad
    errors, curves, exact = opensees_errors(ops, portal(BilinearHinge, b), 0.2, [0.01, 0.0025])
    assert all(c.complete for c in curves)
    assert max(errors) <= 1e-9
    # the sway mechanism's 4 M_p / h, plus at most the four column hinges' hardening over
    # the drift ratio 0.2 / 4 (the chord rotation bounds their plastic rotation)
    assert 3e5 < exact.peak_base_shear < 3e5 + 4 * b * K_HINGE * (0.2 / 4.0) / 4.0


STEPS = [0.01, 0.0025, 0.000625, 0.00015625]  # m


@pytest.mark.parametrize(("case", "pattern"), [
    ("gravity", "uniform"), ("gravity", "triangular"), ("leaning", "uniform"),
    ("p-delta", "uniform")])
def test_pushover_converges_to_pounding_as_the_step_shrinks(ops: Any, case: str,
                                                            pattern: str) -> None:
    kw: dict[str, Any] = {"leaning": {"leaning_load": 2e6},
                          "p-delta": {"geometry": "p-delta"}}.get(case, {})
    frame = three_by_two(**kw)
    errors, curves, exact = opensees_errors(ops, frame, 0.4, STEPS, pattern)
    assert exact.stopped == "target"
    assert all(c.complete for c in curves), [c.roof[-1] for c in curves]
    assert errors[-1] <= 2e-7, errors
    assert errors[-1] <= errors[0] / 10, errors


def test_pounding_and_opensees_see_the_same_leaning_column_p_delta(ops: Any) -> None:
    """The leaning column lowers the frame's strength by P·Δ/h: both programs agree on the
    curve with it, and it differs from the curve without it by more than they differ."""
    errors, _, with_lean = opensees_errors(ops, three_by_two(leaning_load=2e6), 0.4,
                                           [0.000625])
    without = pushover(three_by_two(), 0.4)
    at = np.interp(with_lean.roof_displacement, without.roof_displacement,
                   without.base_shear)
    effect = float(np.max(np.abs(at - with_lean.base_shear))) / with_lean.peak_base_shear
    assert effect > 0.05
    assert errors[0] < 1e-5 * effect


def test_pushover_with_unequal_leaning_loads_reaches_its_target(
        ops: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    """A hinge turning at a rounding-level rate against its branch's direction (-2.8e-17)
    once landed on its breakpoint in a zero step, and the event loop cycled to MAX_EVENTS
    (fixed in frame_analysis._advance: such a hinge reaches no breakpoint)."""
    monkeypatch.setattr(frame_analysis, "MAX_EVENTS", 2000)  # fail fast, not after 200 000
    frame = three_by_two(leaning_load=[2e6, 2e6, 1.5e6])
    errors, curves, exact = opensees_errors(ops, frame, 0.4, [0.000625])
    assert exact.stopped == "target"
    assert curves[0].complete
    assert errors[0] <= 1e-6
