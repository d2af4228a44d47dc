"""A bridge run element by element (:attr:`pounding.result.Result.bridge`, summary.json's
``bridge`` block): the piers' and bearings' forces against the equations of motion of the
deck and the caps, the seats' envelopes against the contacts' penetrations, the
restrainers' yielding against their law, the impacts and energies against the run's
totals."""

from __future__ import annotations

import json

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.result.files import json_ready
from pounding.structure.bridge import (
    Abutment,
    Bearing,
    Bridge,
    BridgeFrame,
    Pier,
    Restrainer,
)

KV = ContactSpec("kelvin-voigt", k=1.0e9, e=0.6)
CABLES = {"kind": "restrainer", "k": 2.0e7, "slack": 0.01, "yield_force": 6.0e5,
          "hardening": 0.02}


def _bridge(restrainer: dict | None = None) -> PoundingModel:
    """Two one-pier frames: frame 1 linear (elastomeric bearing with a dashpot), frame 2 on
    a yielding pier; a 20 mm joint and 40 mm abutment gaps."""
    f1 = BridgeFrame(1.2e6, [Pier(9.0, 1.0e8, 1.2e5)], Bearing.elastomeric(4.0e7, 2.0e5))
    f2 = BridgeFrame(1.0e6, [Pier(9.0, 3.0e8, 1.0e5, Bilinear(yield_force=1.5e6,
                                                                hardening=0.02))],
                     Bearing.elastomeric(1.5e8, 1.0e5))
    rs = () if restrainer is None else (Restrainer(0, restrainer),)
    return PoundingModel.from_bridge(Bridge([f1, f2], [0.02], abutments=(Abutment(0.04),
                                                                          Abutment(0.04)),
                                            restrainers=rs), KV)


@pytest.fixture(scope="module")
def run():
    return simulate(_bridge(), el_centro().scaled(1.5), duration=6.0)


@pytest.fixture(scope="module")
def run_restrained():
    return simulate(_bridge(CABLES), el_centro().scaled(1.5), duration=6.0)


def _deck_contact_force(res, p: int) -> np.ndarray:
    """Net contact force on frame ``p``'s deck [N] (nt,): a contact pushes its left body
    back (−x) and its right body on (+x), compression positive."""
    out = np.zeros(res.time.size)
    for c in res.model.contacts:
        if c.right.building == p:
            out += res.contact_force[:, c.index]
        if c.left.building == p:
            out -= res.contact_force[:, c.index]
    return out


def test_element_forces_balance_the_deck_and_the_caps(run) -> None:
    """Each frame's bearing force is what balances its deck — ``F_b = F_contact − m_d ü_abs
    − (a₀M + a₁K_lin)v`` at the deck — and its pier's shear what balances its cap,
    ``F_p = F_b − m_c ü_abs − (a₀M + a₁K_lin)v`` at the cap: the equations of motion the
    kernel integrated, assembled here from the frame's matrices, not from the element
    table. The histories agree to 1.4e-15 of the peak (asserted: 1e-9); a linear pier's
    shear is k × its drift, the drift ratio its drift over its height, the yielding pier's
    ductility over 1."""
    res = run
    bp = res.bridge
    assert [f.label for f in bp.frames] == ["B1", "B2"]
    u, v, acc = res.displacement, res.velocity, res.abs_acceleration
    for p, (frame, fp) in enumerate(zip(res.model.buildings, bp.frames)):
        off = int(res.model.system.offsets[p])
        a0, a1 = frame.rayleigh
        c_rayleigh = a0 * frame.M + a1 * frame.linear_stiffness_matrix()
        dofs = slice(off, off + frame.n)
        damping = v[:, dofs] @ c_rayleigh.T
        inertia = acc[:, dofs] * np.diag(frame.M)
        bearing = _deck_contact_force(res, p) - inertia[:, 0] - damping[:, 0]
        pier = bearing - inertia[:, 1] - damping[:, 1]
        (b,), (q,) = fp.bearings, fp.piers
        scale = np.abs(bearing).max()
        assert b.peak_force == pytest.approx(np.abs(bearing).max(), abs=1e-9 * scale)
        assert q.peak_shear == pytest.approx(np.abs(pier).max(), abs=1e-9 * scale)
        assert b.peak_displacement == pytest.approx(np.abs(u[:, off] - u[:, off + 1]).max(),
                                                    rel=1e-12)
        assert q.peak_drift == pytest.approx(np.abs(u[:, off + 1]).max(), rel=1e-12)
        assert q.peak_drift_ratio == pytest.approx(q.peak_drift / 9.0, rel=1e-12)
    linear, yielding = bp.piers
    assert linear.peak_shear == pytest.approx(1.0e8 * linear.peak_drift, rel=1e-12)
    assert np.isnan(linear.ductility) and linear.law == "linear"
    assert yielding.ductility == pytest.approx(yielding.peak_drift / (1.5e6 / 3.0e8))
    assert yielding.ductility > 1.0  # (it yielded)
    assert yielding.peak_shear <= 1.5e6 + 0.02 * 3.0e8 * yielding.peak_drift + 1e-6
    assert bp.frames[0].peak_deck_displacement == pytest.approx(
        res.peak_displacement[0], rel=1e-12)


def test_seats_read_the_contacts_and_the_energy_closes(run) -> None:
    """A seat's closing is the gap plus its contact's penetration (sample for sample); its
    impacts and peak forces are its contacts'; they add up to the run's; the finished
    impacts' energy is the run's contact-dissipated energy (all impacts finished) and the
    run's energy balance closes."""
    res = run
    seats = {s.name: s for s in res.bridge.seats}
    assert list(seats) == ["A1", "J1", "A2"]
    labels = {c.label: c for c in res.model.contacts}
    for s in seats.values():
        (label,) = s.contacts
        c = labels[label]
        pen = res.penetration[:, c.index]
        assert s.peak_closing == pytest.approx(c.gap + pen.max(), abs=1e-12)
        assert s.impacts == res.impacts_per_contact[c.index] > 0
        assert s.peak_force == res.peak_contact_force[c.index]
    u = res.displacement
    assert seats["J1"].peak_opening == pytest.approx((u[:, 2] - u[:, 0]).max(), rel=1e-12)
    assert seats["A2"].peak_opening == pytest.approx((-u[:, 2]).max(), rel=1e-12)
    assert sum(s.impacts for s in seats.values()) == res.n_impacts
    open_at_end = np.isnan(res.impact_array[:, 2]).sum()
    assert open_at_end == 0
    total = sum(s.dissipated for s in seats.values())
    assert total == pytest.approx(res.contact_dissipated[-1], rel=1e-6)
    assert res.energy_balance_error < 1e-8


def test_cable_restrainer_yields_by_its_law(run_restrained) -> None:
    """The cables (k = 20 MN/m, slack 10 mm, F_y = 600 kN, b = 0.02) yield: the joint opened
    past slack + F_y/k = 40 mm (read from the decks' displacements), the plastic elongation
    is > 0, and the peak force lies between F_y and F_y + H z (H = b k/(1 − b))."""
    res = run_restrained
    (r,) = res.bridge.restrainers
    assert (r.name, r.joint, r.kind) == ("R1", "J1", "restrainer")
    opening = res.displacement[:, 2] - res.displacement[:, 0]
    assert r.peak_opening == pytest.approx(opening.max(), rel=1e-12)
    assert r.yield_opening == pytest.approx(0.01 + 6.0e5 / 2.0e7)
    assert r.yielded and opening.max() > 0.04 and r.plastic_elongation > 0
    h = 0.02 * 2.0e7 / 0.98
    assert 6.0e5 < r.peak_force <= (6.0e5 + h * r.plastic_elongation) * (1 + 1e-9)
    assert r.peak_force == pytest.approx(np.abs(res.link_force[:, 0]).max(), rel=1e-12)
    block = res.summary()["bridge"]["restrainers"][0]
    assert block["yielded"] is True and block["peak_force_N"] == r.peak_force


def test_summary_bridge_block_names_its_units(run) -> None:
    """summary.json's ``bridge`` block: frames with their piers and bearings, joints,
    abutments; every number's key ends in its unit (or is a ratio, count or name); JSON
    without NaN; a model of buildings has none."""
    s = run.summary()
    block = json.loads(json.dumps(json_ready(s["bridge"]), allow_nan=False))
    assert [f["frame"] for f in block["frames"]] == ["B1", "B2"]
    pier = block["frames"][1]["piers"][0]
    assert pier["pier"] == "B2P1" and pier["ductility"] > 1
    assert pier["peak_shear_N"] == run.bridge.piers[1].peak_shear
    assert [j["joint"] for j in block["joints"]] == ["J1"]
    assert [a["abutment"] for a in block["abutments"]] == ["A1", "A2"]
    assert block["restrainers"] == []
    unitless = {"frame", "name", "deck", "pier", "bearing", "law", "kind", "joint",
                "abutment", "contacts", "impacts", "ductility", "peak_drift_ratio",
                "piers", "bearings", "restrainer", "yielded"}

    def keys(obj):
        if isinstance(obj, dict):
            for k, val in obj.items():
                yield k
                yield from keys(val)
        elif isinstance(obj, list):
            for val in obj:
                yield from keys(val)

    units = ("_m", "_s", "_N", "_J", "_kg", "_m_s2", "_N_m")
    for key in set(keys({k: v for k, v in block.items() if k != "notes"})):
        assert key in unitless or key.endswith(units) or key in (
            "frames", "joints", "abutments", "restrainers"), key


def test_a_row_of_buildings_has_no_bridge_view() -> None:
    from pounding.structure import ShearBuilding

    model = PoundingModel([ShearBuilding.uniform(1, 2e5, 3.2e7),
                           ShearBuilding.uniform(1, 3e5, 1.2e7)], [0.02], KV)
    res = simulate(model, el_centro(), duration=1.0)
    assert res.bridge is None and "bridge" not in res.summary()
    from pounding.plot.bridge import plot_bridge_elevation
    from pounding.plot.registry import figures_for

    assert not {"bridge_figure", "bridge_element_figure"} & set(figures_for(res))
    with pytest.raises(ValueError, match="not a bridge"):
        plot_bridge_elevation(res)


# ------------------------------------------------------------------------ figures
def test_bridge_figures_replace_the_storey_figures(run_restrained) -> None:
    """A bridge's run draws its elevation and element figures in place of the storeys'
    envelope and hysteresis figures (a blank page before); a row of buildings never
    draws them."""
    from pounding.plot.registry import RUN_FIGURES, figures_for

    assert list(figures_for(run_restrained)) == [
        "bridge_figure", "displacement_figure", "force_figure", "hysteresis_figure",
        "bridge_element_figure", "energy_figure"]
    assert RUN_FIGURES["bridge_figure"].file == "bridge.png"
    assert RUN_FIGURES["bridge_element_figure"].file == "bridge_elements.png"


def test_elevation_draws_the_seats_envelope_to_scale(run_restrained) -> None:
    """The elevation to scale from the spans (frame 1: 2 × 30 m, frame 2: 2 × 25 m): piers
    at the supports between spans (30 m, 85 m), seats at 0, 60 and 110 m. Below, each
    seat's largest opening (up) and closing (down) in mm, the gap dashed at −gap, the seat
    width at +width, and J1 (72 mm open against a 60 mm seat) marked unseated."""
    from pounding.plot.bridge import bridge_layout, plot_bridge_elevation

    res = run_restrained
    spans = [[30.0, 30.0], [25.0, 25.0]]
    layout = bridge_layout(res, spans)
    assert layout.to_scale and layout.piers == ((30.0,), (85.0,))
    assert layout.seats == (0.0, 60.0, 110.0)
    assert not bridge_layout(res).to_scale  # (the frames carry no spans)
    fig = plot_bridge_elevation(res, seat_widths={"J1": 0.06}, spans=spans)
    top, bottom = fig.axes
    assert sorted({round(float(ln.get_xdata()[0]), 9) for ln in top.get_lines()
                   if ln.get_linewidth() == 3.5}) == [30.0, 85.0]
    seats = {s.name: s for s in res.bridge.seats}
    bars = {}
    for ln in bottom.get_lines():
        x, y = ln.get_xdata(), ln.get_ydata()
        if ln.get_color() in ("tab:blue", "tab:orange"):
            bars[(float(x[0]), ln.get_color())] = float(y[1])
    for s, x in zip(seats.values(), layout.seats):
        assert bars[(x, "tab:blue")] == pytest.approx(1e3 * s.peak_opening, rel=1e-12)
        assert bars[(x, "tab:orange")] == pytest.approx(-1e3 * s.peak_closing, rel=1e-12)
    gaps = sorted(float(ln.get_ydata()[0]) for ln in bottom.get_lines()
                  if ln.get_linestyle() == "--")
    assert gaps == pytest.approx([-40.0, -40.0, -20.0])
    widths = [float(ln.get_ydata()[0]) for ln in bottom.get_lines() if ln.get_color() == "k"]
    assert widths == pytest.approx([60.0])
    assert seats["J1"].peak_opening > 0.06
    assert "unseated" in [t.get_text() for t in bottom.texts]
    assert bottom.get_ylabel().startswith("relative displacement [mm]")
    assert bottom.get_xlabel() == "along the bridge [m]"
    texts = " ".join(t.get_text() for t in top.texts)
    assert "J1\ngap 20 mm, 10 impacts" in texts and "R1 612.8 kN (yielded)" in texts


def test_element_figure_draws_each_element_in_mm_and_kn(run_restrained) -> None:
    """One panel per pier and bearing (a row per frame), one per restrainer: the deformation
    in mm against the force in kN, sample for sample; the yield forces dashed."""
    from pounding.plot.bridge import plot_bridge_elements
    from pounding.result.storey_peaks import bridge_element_histories

    res = run_restrained
    fig = plot_bridge_elements(res)
    drawn = [ax for ax in fig.axes if ax.axison]
    assert [ax.get_title().split(":")[0].split(" ")[0] for ax in drawn] == [
        "B1P1", "B1Br1", "B2P1", "B2Br1", "R1"]
    histories = {label: (d, f) for _, label, d, f in bridge_element_histories(res)}
    for ax in drawn[:4]:
        d, f = histories[ax.get_title().split(":")[0].split(" ")[0]]
        loop = ax.get_lines()[0]
        np.testing.assert_allclose(loop.get_xdata(), 1e3 * d, rtol=1e-14)
        np.testing.assert_allclose(loop.get_ydata(), 1e-3 * f, rtol=1e-14)
        assert ax.get_ylabel() in ("force [kN]", "")
    dashed = sorted(float(ln.get_ydata()[0]) for ln in drawn[2].get_lines()
                    if ln.get_linestyle() == "--")
    assert dashed == pytest.approx([-1500.0, 1500.0])
    restrainer = drawn[4].get_lines()[0]
    np.testing.assert_allclose(restrainer.get_ydata(), 1e-3 * res.link_force[:, 0], rtol=1e-14)
