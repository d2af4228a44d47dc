"""benchmarks/opensees_plan.py: the OpenSees model of buildings in plan, checked against the
PlanBuilding's own matrices with solvers written here (not against pounding's engine); then
pounding's engine checked against it (issue 18).

* Periods: ``ops.eigen`` of the OpenSees model against ``PlanBuilding.modes().periods``.
* No contact (gaps so large nothing touches): the OpenSees histories against
  ``M ü + C u̇ + K u = −M R a_g`` (M, K, C from the PlanBuilding, R its influence matrix)
  solved (a) exactly at the record samples by ``scipy.signal.lsim`` (first-order hold: exact
  for the ground acceleration linear between samples, as OpenSees' ``Path`` series), with
  the error falling as dt² as dt is refined (Newmark average acceleration is second order),
  and (b) by the trapezoidal rule on the first-order form written out here, which *is*
  Newmark average acceleration for a linear system — equal to OpenSees at the same dt up
  to its Newton tolerance.
* Contact kinematics: with an undamped contact (c = 0) the contact force equals
  ``k (δ − gap)⁺`` with ``δ`` the x displacements of the two façade points computed from
  the floor histories by rigid-floor kinematics written out here.
* Against pounding: the torsional pair striking at its corners (El Centro along x; the Düzce
  pair at 60°), the same impacts per contact, peak forces and floor histories within
  OpenSees' first-order accuracy (it does not locate contact onsets), the error shrinking
  from dt = 1 ms to 0.25 ms.

Skipped where OpenSeesPy is not importable; run with a venv that has it, e.g.
``PYTHONPATH=src:benchmarks /work/bench-venv/bin/python -m pytest -q
tests/structure/test_opensees_plan.py``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from scipy import signal

pytestmark = pytest.mark.usefixtures("opensees")  # conftest.py: skip or, under CI, fail
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))

import opensees_models as osm  # noqa: E402
import opensees_plan as osp  # noqa: E402
from pounding.ground_motion import el_centro  # noqa: E402
from pounding.structure.damping import RayleighDamping  # noqa: E402
from pounding.structure.plan import LateralElement, PlanBuilding  # noqa: E402

FAR = 10.0  # m: a gap no floor closes in these records (peaks are a few cm)


def eccentric_building(site_y: float = 0.0) -> PlanBuilding:
    """Three storeys, 18 m × 10 m, centres of mass that move floor to floor, given floor
    inertias, an inclined (30°) brace line, an element missing in one storey, stiffness
    eccentricity in both directions, Rayleigh damping anchored at two periods."""
    return PlanBuilding(
        masses=[3e5, 2.5e5, 2e5], heights=[4.0, 3.2, 3.2], width=18.0, depth=10.0,
        mass_centres=[(9.0, 5.0), (9.8, 4.6), (8.5, 5.5)],
        inertias=[1.0e7, 8.0e6, 6.0e6], site_y=site_y, name="eccentric",
        damping=RayleighDamping.from_periods(0.5, 0.12, 0.05, 0.03),
        elements=[LateralElement(9.0, 0.0, "x", [2.0e8, 1.5e8, 1.0e8]),
                  LateralElement(9.0, 10.0, "x", [0.8e8, 0.6e8, 0.5e8]),
                  LateralElement(0.0, 5.0, "y", [1.0e8, 0.8e8, 0.6e8]),
                  LateralElement(18.0, 5.0, "y", [2.5e8, 2.0e8, 1.5e8]),
                  LateralElement(12.0, 3.0, 30.0, [6e7, 5e7, 0.0])])


def record(seconds: float) -> tuple[np.ndarray, np.ndarray, float]:
    """El Centro (x) and, as a y component, the same record reversed in time and scaled by
    0.7 (any second signal will do for the check), both starting from a zero sample (at
    rest: OpenSees' Newmark starts from zero acceleration), and one second longer than
    asked (at the record's last sample OpenSees' accumulated time may round past the end of
    the ``Path`` series, where it gives zero)."""
    gm = el_centro()
    n = int(round(seconds / gm.dt)) + 100
    ax = np.concatenate([[0.0], gm.accel[:n]])
    ay = np.concatenate([[0.0], -0.7 * gm.accel[::-1][:n]])
    return ax, ay, gm.dt


def state_space(b: PlanBuilding, components: int) -> tuple[np.ndarray, np.ndarray]:
    """``ẋ = A x + B a_g``, ``x = (u, u̇)``: ``A = [[0, I], [−M⁻¹K, −M⁻¹C]]``,
    ``B = [[0], [−R]]``."""
    M, K, C = b.mass_matrix(), b.stiffness_matrix(), b.damping_matrix()
    R = b.influence_matrix()[:, :components]
    n = b.n
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    B = np.vstack([np.zeros((n, components)), -R])
    return A, B


def exact(b: PlanBuilding, accel: np.ndarray, dt: float) -> np.ndarray:
    """u at the record samples, exact for a ground acceleration linear between samples."""
    A, B = state_space(b, accel.shape[1])
    sys_ = signal.StateSpace(A, B, np.hstack([np.eye(b.n), np.zeros((b.n, b.n))]),
                             np.zeros((b.n, accel.shape[1])))
    t = np.arange(accel.shape[0]) * dt
    _, y, _ = signal.lsim(sys_, accel, t, interp=True)
    return y


def trapezoid(b: PlanBuilding, accel: np.ndarray, record_dt: float, dt: float,
              n_steps: int) -> np.ndarray:
    """The trapezoidal rule on ``ẋ = A x + B a_g`` at step dt, a_g linear between samples:
    ``(I − dt/2 A) x₊ = (I + dt/2 A) x + dt/2 B (a_g + a_g₊)``."""
    A, B = state_space(b, accel.shape[1])
    t = np.arange(n_steps + 1) * dt
    tr = np.arange(accel.shape[0]) * record_dt
    ag = np.column_stack([np.interp(t, tr, a, right=0.0) for a in accel.T])
    eye = np.eye(A.shape[0])
    lhs = np.linalg.inv(eye - 0.5 * dt * A)
    step = lhs @ (eye + 0.5 * dt * A)
    force = 0.5 * dt * lhs @ B
    x = np.zeros(A.shape[0])
    u = np.zeros((n_steps + 1, b.n))
    for s in range(n_steps):
        x = step @ x + force @ (ag[s] + ag[s + 1])
        u[s + 1] = x[:b.n]
    return u


def run(buildings: list[PlanBuilding], ax: np.ndarray, ay: np.ndarray | None, rdt: float,
        dt: float, duration: float, gaps: list[float] | None = None,
        contact: dict | None = None) -> dict:
    return osp.run_opensees_plan(
        buildings, [FAR] * (len(buildings) - 1) if gaps is None else gaps,
        contact or {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65}, ax, ay, rdt, dt, duration)


# --------------------------------------------------------------------------- periods
@pytest.mark.parametrize("which", ["eccentric", "torsional pair"])
def test_opensees_periods_equal_the_plan_buildings(which: str) -> None:
    """Every natural period of the OpenSees model (all modes, LAPACK) is a period of one of
    the PlanBuildings (``modes()``: M, K from pounding's plan module), to 1e-6 relative."""
    if which == "eccentric":
        buildings, gaps = [eccentric_building()], []
    else:
        left, right, gap = osp.torsional_pair()
        buildings, gaps = [left, right], [gap]
    ours = np.sort(np.concatenate([b.modes().periods for b in buildings]))[::-1]
    theirs = osp.opensees_plan_periods(buildings, gaps)
    assert theirs.shape == ours.shape
    np.testing.assert_allclose(theirs, ours, rtol=1e-6, atol=0.0)


def test_example_pair_has_the_documented_periods_and_eccentricity() -> None:
    left, right, gap = osp.torsional_pair()
    assert gap == 0.02
    assert 0.3 <= left.fundamental_period <= 0.8 and 0.3 <= right.fundamental_period <= 0.8
    assert np.allclose(left.stiffness_eccentricity(), 0.0)
    assert right.stiffness_eccentricity()[0, 1] == pytest.approx(3.6, abs=1e-12)
    assert [c[3] for c in osp.plan_contacts([left, right])] == [6.0, 12.0] * 3


# --------------------------------------------------------------------------- histories
def test_without_contact_opensees_is_newmark_of_the_plan_matrices() -> None:
    """Newmark average acceleration on a linear system is the trapezoidal rule on its
    first-order form: at the same dt the OpenSees histories of an eccentric building (x and
    y ground components) and of a row of three (x only; contact elements between the first two,
never closed) equal the trapezoidal rule on (M, C, K, R)
    of the PlanBuildings, to 1e-9 of the peak (Newton's tolerance is 1e-10 m)."""
    ax, ay, rdt = record(4.0)
    dt, duration = 0.005, 4.0
    n_steps = int(round(duration / dt))
    b = eccentric_building()
    r = run([b], ax, ay, rdt, dt, duration)
    ref = trapezoid(b, np.column_stack([ax, ay]), rdt, dt, n_steps)
    assert np.abs(ref[:, 0::3]).max() > 1e-2 and np.abs(ref[:, 2::3]).max() > 1e-4
    np.testing.assert_allclose(r["u"], ref, rtol=0, atol=1e-9 * np.abs(ref).max())

    left, right, _ = osp.torsional_pair()
    pair = [left, right, eccentric_building(site_y=4.0)]
    r = run(pair, ax, None, rdt, dt, duration)
    assert r["force"].shape[1] > 0 and not r["force"].any()
    for i, bld in enumerate(pair):
        ref = trapezoid(bld, ax[:, None], rdt, dt, n_steps)
        got = r["u"][:, r["dof_start"][i]:r["dof_start"][i + 1]]
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-9 * np.abs(ref).max())


def test_without_contact_opensees_converges_to_the_exact_response_as_dt_squared() -> None:
    """The exact response at the record samples (lsim) against OpenSees at dt = record dt
    / 1, 2, 4, 8: the largest error over all DOFs, relative to the peak, falls by 4 (3.6 to
    4.4) each halving, and is below 1e-3 at dt = 1.25 ms."""
    ax, ay, rdt = record(5.0)
    duration = 5.0
    ns = int(round(duration / rdt))
    b = eccentric_building()
    left, right, _ = osp.torsional_pair()
    cases = [([b], np.column_stack([ax, ay]), ay), ([left, right], ax[:, None], None)]
    for buildings, accel, accel_y in cases:
        refs = [exact(bld, accel, rdt)[:ns + 1] for bld in buildings]
        errors = []
        for sub in (1, 2, 4, 8):
            r = run(buildings, ax, accel_y, rdt, rdt / sub, duration)
            err = 0.0
            for i, ref in enumerate(refs):
                got = r["u"][::sub, r["dof_start"][i]:r["dof_start"][i + 1]]
                err = max(err, np.abs(got - ref).max() / np.abs(ref).max())
            errors.append(err)
        ratios = np.array(errors[:-1]) / np.array(errors[1:])
        assert np.all((ratios > 3.6) & (ratios < 4.4)), (errors, ratios)
        assert errors[-1] < 1e-3, errors


# --------------------------------------------------------------------------- contacts
def test_contact_force_is_the_penetration_of_the_facade_points() -> None:
    """An undamped contact (c = 0): the force at each contact equals k (δ − gap)⁺ with
    δ = u_x(left point) − u_x(right point), each from its floor's (u_x, θ) and the point's
    lever arm about that floor's centre of mass, y_site − (site_y + y_c) — the torsional
    pair under El Centro, so that the floors twist and strike."""
    left, right, gap = osp.torsional_pair()
    ax, _, rdt = record(8.0)
    k = 9.3e8
    r = run([left, right], ax, None, rdt, 0.002, 8.0, gaps=[gap],
            contact={"law": "kelvin-voigt", "k": k, "c": 0.0})
    assert r["n_impacts"] > 0 and r["peak_force"].max() > 1e5
    s = r["dof_start"]
    ul, ur = r["u"][:, s[0]:s[1]], r["u"][:, s[1]:s[2]]
    corner = False
    for (b, i, j, y), f in zip(r["contacts"], r["force"].T):
        i, j = int(i), int(j)
        arm_l = y - (left.site_y + left.mass_centres[i, 1])
        arm_r = y - (right.site_y + right.mass_centres[j, 1])
        corner |= bool(f.max() > 0 and arm_r != 0.0)
        x_left = ul[:, 3 * i] - arm_l * ul[:, 3 * i + 2]
        x_right = ur[:, 3 * j] - arm_r * ur[:, 3 * j + 2]
        delta = x_left - x_right
        expected = k * np.maximum(delta - gap, 0.0)
        np.testing.assert_allclose(f, expected, rtol=0, atol=1e-9 * r["peak_force"].max())
    assert corner  # some impact away from the right building's centre of mass line


def test_dashpot_from_e_is_pounding_contact_specs() -> None:
    """Kelvin–Voigt given by ``e``: each contact's dashpot is the one pounding's ContactSpec
    builds for the two floor masses that meet (Anagnostopoulos, the dashpot may pull), and
    the Rayleigh coefficients are each building's own."""
    from pounding.model import ContactSpec

    left, right, gap = osp.torsional_pair()
    heavier = PlanBuilding(masses=[4e5, 3e5, 2e5], heights=right.heights, width=right.width,
                           depth=right.depth, elements=right.elements, site_y=right.site_y)
    ax, _, rdt = record(0.1)
    r = run([left, heavier], ax, None, rdt, 0.01, 0.05, gaps=[gap],
            contact={"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65})
    spec = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65, formula="anagnostopoulos",
                       tension=True)
    for (_, i, j, _), law in zip(r["contacts"], r["params"]["contact_laws"]):
        ours = spec.build(float(left.masses[int(i)]), float(heavier.masses[int(j)]))
        assert (law["k"], law["gap"]) == (9.3e8, gap)
        assert law["c"] == pytest.approx(ours.c, rel=1e-12)
    assert len({law["c"] for law in r["params"]["contact_laws"]}) == 3
    for bld, a in zip((left, heavier), r["params"]["rayleigh"]):
        assert a == bld.damping.coefficients(bld.mass_matrix(), bld.stiffness_matrix())


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("kwargs, match", [
    (dict(gaps=[]), "gaps must have one value per neighbouring pair"),
    (dict(gaps=[0.0]), r"gaps\[0\] must be a finite number > 0"),
    (dict(contact={"law": "hertz", "k": 1e9}), r"contact\['law'\] must be one of"),
    (dict(contact={"law": "kelvin-voigt", "k": 1e9}), "as 'c' .* or as 'e'"),
    (dict(contact={"law": "kelvin-voigt", "k": 1e9, "e": 0.6, "tension": False}),
     r"contact\['tension'\] must be True"),
    (dict(contact={"law": "kelvin-voigt", "k": -1.0, "c": 0.0}), r"contact\['k'\]"),
    (dict(contact={"law": "kelvin-voigt", "k": 1e9, "c": 0.0, "zeta": 0.1}),
     r"contact\['zeta'\] is not a field"),
    (dict(dt=0.0), "dt must be a finite number > 0"),
    (dict(accel_y=np.array([np.nan, 0.0])), "accel_y must be a 1-D array"),
])
def test_bad_input_is_named(kwargs: dict, match: str) -> None:
    left, right, gap = osp.torsional_pair()
    args = dict(buildings=[left, right], gaps=[gap],
                contact={"law": "kelvin-voigt", "k": 1e9, "e": 0.65},
                accel_x=np.zeros(10), accel_y=None, record_dt=0.01, dt=0.01, duration=0.05)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        osp.run_opensees_plan(**args)


def test_script_prints_the_example_and_refuses_a_bad_step(capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    assert osp.main(["--duration", "0.5", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "y component: none" in out and "500 steps" in out
    assert sum(line.startswith("  floor ") for line in out.splitlines()) == 6
    with pytest.raises(SystemExit) as exc:
        osp.main(["--dt", "0"])
    assert exc.value.code == 2
    assert "--dt must be a finite number > 0 [s] (got 0.0)" in capsys.readouterr().err


def test_modal_damping_is_refused() -> None:
    from pounding.structure.damping import ModalDamping

    b = PlanBuilding(masses=[1e5], heights=[3.0], width=10.0, depth=8.0,
                     damping=ModalDamping(0.05),
                     elements=[LateralElement(5.0, 0.0, "x", 1e8),
                               LateralElement(5.0, 8.0, "x", 1e8),
                               LateralElement(0.0, 4.0, "y", 1e8),
                               LateralElement(10.0, 4.0, "y", 1e8)])
    with pytest.raises(ValueError, match=r"buildings\[0\]\.damping must be RayleighDamping"):
        osp.opensees_plan_periods([b], [])


# ------------------------------------------------------------------ against pounding
def _pounding_on_the_same_model(buildings: list[PlanBuilding], gap: float, law: dict,
                                contact_laws: list[dict]):
    """pounding's model of the OpenSees run: the same PlanBuildings and gap, Kelvin–Voigt
    with the dashpot pulling until the gap reopens (``ViscoelasticGap``) and the c OpenSees
    used — one explicit c for all contacts, as the floor masses that meet are the same at
    every contact of the pair (checked)."""
    from pounding import PoundingModel
    from pounding.model import ContactSpec

    cs = {cl["c"] for cl in contact_laws}
    assert len(cs) == 1, cs
    return PoundingModel(buildings, gaps=[gap], contact=ContactSpec(
        "kelvin-voigt", k=law["k"], c=cs.pop(), tension=True))


def _records() -> dict[str, tuple]:
    """El Centro along x, its first 6 s; the Düzce pair (Kocaeli 1999, 180 and 270) at 60°,
    the window 8.0–10.4 s of the kernel's reference test. Each with a zero sample in front
    (both tools start at rest from zero ground acceleration)."""
    from pounding.ground_motion import GroundMotion, load_bundled

    def window(g: GroundMotion, t0: float, t1: float) -> GroundMotion:
        k0, k1 = round(t0 / g.dt), round(t1 / g.dt)
        return GroundMotion(g.dt, np.concatenate([[0.0], g.accel[k0: k1 + 1]]), name=g.name)

    h1 = load_bundled("kocaeli_1999_duzce_180_RSN1158")
    h2 = load_bundled("kocaeli_1999_duzce_270_RSN1158")
    return {"el centro x": (window(el_centro(), 0.0, 6.0), None, 0.0),
            "duzce 60°": (window(h1, 8.0, 10.4), window(h2, 8.0, 10.4), 60.0)}


@pytest.mark.parametrize("which", ["el centro x", "duzce 60°"])
def test_pounding_and_opensees_agree_on_the_torsional_pair(which: str) -> None:
    """pounding (event-located contacts, exact free steps) and OpenSees (Newmark average
    acceleration, contact felt from the first step end after its onset) on the same torsional
    pair, same contact law and c:

    * the same impacts at every contact, corner contacts among them (Düzce: both corners,
      the right building's at y = 6 m and the left's at y = 12 m);
    * OpenSees does not locate contact onsets, so its error is first order in dt: before the
      first contact only Newmark's (dt², 3e-5 of the peak at 1 ms, measured), after it an
      error in the momentum each impact transfers of the order of the part of a step
      missed. Measured: floor u_x 4.1e-3 (El Centro) / 2.2e-3 (Düzce) of the peak at 1 ms,
      9.4e-4 / 7.1e-4 at 0.25 ms; θ 7.9e-3 / 5.6e-3 → 1.2e-3 / 1.6e-3 of its peak; peak
      contact forces 4.9e-3 / 1.1e-2 → 2.0e-3 / 6.5e-3 (largest over contacts; the force
      errors are not monotone contact by contact, as the onset falls anywhere in a step).
      Asserted: u_x within 1 %, θ within 1.5 %, u_y within 0.1 % of their peaks (Düzce; no
      y motion under x shaking), peak forces within 1.5 % at 1 ms; at 0.25 ms the largest
      displacement error at most half that at 1 ms (first order: a quarter) and the largest
      force error smaller, each below 1 %."""
    from pounding import simulate
    from pounding.ground_motion import GroundMotionComponents
    from pounding.ground_motion.incidence import at_incidence

    first, second, angle = _records()[which]
    gx, gy = at_incidence(first, second, angle)
    duration = (gx.accel.size - 1) * gx.dt
    left, right, gap = osp.torsional_pair()
    law = osp.EXAMPLE_CONTACT
    errors = {}
    for dt in (1e-3, 2.5e-4):
        r = osp.run_opensees_plan([left, right], [gap], law, gx.accel,
                                  None if second is None else gy.accel, gx.dt, dt, duration)
        assert r["failed"] == 0
        if dt == 1e-3:
            model = _pounding_on_the_same_model([left, right], gap, law,
                                                r["params"]["contact_laws"])
            ours = simulate(model, GroundMotionComponents((gx, gy)), dt=1e-3,
                            duration=duration, rtol=1e-10)
            u = np.asarray(ours.displacement)
            peaks = list(ours.contact_peaks.items())
            # the contacts in the same order on both sides
            assert [lab for lab, _ in peaks] == [
                f"B1F{int(i) + 1}@y={y:g}-B2F{int(j) + 1}@y={y:g}"
                for _, i, j, y in r["contacts"]]
            struck = {lab for lab, p in peaks if p.impacts}
            assert "B1F3@y=6-B2F3@y=6" in struck
            if second is not None:
                assert "B1F3@y=12-B2F3@y=12" in struck
        for (lab, p), col in zip(peaks, r["force"].T):
            assert osm.count_impacts(col) == p.impacts, (dt, lab)
        ref_force = np.array([p.force for _, p in peaks])
        hit = ref_force > 0
        force_err = np.max(np.abs(r["peak_force"][hit] - ref_force[hit]) / ref_force[hit])
        got = r["u"][::round(1e-3 / dt)]
        assert got.shape == u.shape
        d = np.abs(got - u)
        ex = d[:, 0::3].max() / np.abs(u[:, 0::3]).max()
        eth = d[:, 2::3].max() / np.abs(u[:, 2::3]).max()
        if second is None:
            assert np.abs(u[:, 1::3]).max() < 1e-12 and np.abs(got[:, 1::3]).max() < 1e-12
            ey = 0.0
        else:
            ey = d[:, 1::3].max() / np.abs(u[:, 1::3]).max()
        errors[dt] = (ex, eth, ey, force_err)
    (ex1, eth1, ey1, ef1), (ex4, eth4, ey4, ef4) = errors[1e-3], errors[2.5e-4]
    assert ex1 < 1e-2 and eth1 < 1.5e-2 and ey1 < 1e-3 and ef1 < 1.5e-2, errors
    assert max(ex4, eth4) <= 0.5 * max(ex1, eth1), errors
    assert ef4 < ef1 and ef4 < 1e-2, errors
