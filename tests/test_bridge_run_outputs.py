"""`pounding run` and `pounding report` of a bridge (examples/bridge_two_frames.toml): tables
that speak bridge (frames, piers, bearings, joints and abutments; mm, kN) in place of the
storey tables, summary.json's ``bridge`` block, the bridge's figures, and the report's
Bridge section with the seat margins of summary.json's ``seats``."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from pounding.cli import main
from pounding.cli.tables import number
from pounding.example_files import example_path
from pounding.report import write_report

EXAMPLE = example_path("bridge_two_frames.toml")


@pytest.fixture(scope="module")
def printed(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Path]:
    """What `pounding run` of the example printed (a console 200 wide, so no table is
    split) and its output folder."""
    from pounding.cli.app import console

    out = tmp_path_factory.mktemp("bridge") / "out"
    width = console.width
    console.width = 200
    with console.capture() as capture:
        try:
            assert main(["run", str(EXAMPLE), "--out", str(out)]) == 0
        finally:
            console.width = width
    return capture.get(), out


def _row(text: str, key: str) -> list[str]:
    """The cells of the first table row whose first cell is ``key``."""
    for line in text.splitlines():
        cells = [c.strip() for c in re.split(r"[│┃]", line)[1:-1]]
        if cells and cells[0] == key:
            return cells
    raise AssertionError(f"no row {key!r}")


def test_run_prints_the_bridge_in_its_own_terms(printed) -> None:
    """Frames, piers, bearings, joints and abutments with their units; the numbers those of
    summary.json's ``bridge`` block; no storey table."""
    text, out = printed
    for title in ("Bridge frames: decks", "Piers: drift", "Bearings: deck relative",
                  "Joints and abutments: impacts"):
        assert title in text, title
    for absent in ("Storeys: peaks", "Buildings (peaks", "peak roof displacement"):
        assert absent not in text, absent
    for header in ("peak deck displacement [mm]", "peak drift [mm]", "drift ratio [%]",
                   "peak shear [kN]", "stiffness [kN/mm]", "peak displacement [mm]",
                   "peak force [kN]", "gap [mm]", "peak impact force [kN]",
                   "max opening [mm]", "max closing [mm]"):
        assert header in text, header
    assert _row(text, "frames / joints / abutments / restrainers")[1] == "2 / 1 / 2 / 0"
    bridge = json.loads((out / "summary.json").read_text(encoding="utf-8"))["bridge"]
    pier = bridge["frames"][0]["piers"][0]
    cells = _row(text, "B1P1")
    assert cells[1] == "bilinear, F_y 2000 kN"
    assert cells[4] == number(1e3 * pier["peak_drift_m"])
    assert cells[5] == number(100 * pier["peak_drift_ratio"], 3)
    assert cells[7] == number(1e-3 * pier["peak_shear_N"])
    assert cells[9] == number(pier["ductility"], 3) and pier["ductility"] > 1
    slider = bridge["frames"][1]["bearings"][0]
    cells = _row(text, "B2Br1")
    assert cells[1:3] == ["sliding", "friction μW 600.2 kN"]
    assert cells[3] == number(1e3 * slider["peak_displacement_m"])
    assert cells[5] == number(1e-3 * slider["peak_force_N"])
    joint = bridge["joints"][0]
    cells = _row(text, "J1")
    assert cells[1:4] == ["B1 – B2", "25.00", str(joint["impacts"])]
    assert cells[7] == number(1e3 * joint["peak_opening_m"])
    assert cells[9] == number(1e3 * joint["peak_closing_m"])
    assert [a["abutment"] for a in bridge["abutments"]] == ["A1", "A2"]
    assert _row(text, "A2")[1] == "B2 – abutment"
    assert sum(s["impacts"] for s in [*bridge["joints"], *bridge["abutments"]]) == 20


def test_summary_gives_a_deck_no_storey(printed) -> None:
    """A deck stands on piers and bearings: summary.json lists no drift, drift ratio, storey
    shear, ductility or residual drift for it at the top level (the deck's displacement
    over its elevation read as a drift ratio, and a residual drift of 0 beside a pier
    that kept one); the piers' are in the ``bridge`` block."""
    _, out = printed
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    for key in ("peak_drift_m", "peak_drift_ratio", "peak_storey_shear_N"):
        assert summary[key] == {}, key
    for key in ("ductility_demand", "residual_drift_m"):
        assert key not in summary, key
    assert set(summary["peak_displacement_m"]) == {"B1F1", "B2F1"}  # the decks' own peaks
    pier = summary["bridge"]["frames"][0]["piers"][0]
    assert pier["ductility"] > 1 and abs(pier["residual_drift_m"]) > 0
    for frame in summary["buildings"]:  # nor frame by frame
        for row in frame["storeys"]:
            assert "peak_displacement_m" in row and not {
                "peak_drift_m", "peak_drift_ratio", "peak_storey_shear_N"} & set(row), row


def test_a_transverse_bridge_gives_its_decks_no_storey_either() -> None:
    """Across the axis the frames are no less bridge frames (the model has no ``bridge``:
    keys are stops): no deck drift ratio, no residual drift of 0 for a deck."""
    from pounding.config import load_config
    from pounding.integrate import simulate
    from pounding.result.summary import summarize

    model, motion, solver = load_config(EXAMPLE.parent / "bridge_transverse.toml").build()
    summary = summarize(simulate(model, motion, **{**solver, "duration": 3.0}))
    assert summary["peak_drift_ratio"] == {} and summary["peak_storey_shear_N"] == {}
    assert not summary.get("residual_drift_m") and not summary.get("ductility_demand")
    assert summary["peak_displacement_m"]  # the decks' own peaks stay


def test_run_writes_the_bridge_figures(printed) -> None:
    _, out = printed
    names = {p.name for p in out.iterdir()}
    assert {"bridge.png", "bridge_elements.png"} <= names
    assert not {"envelopes.png", "storeys.png"} & names
    assert (out / "bridge.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


SEATS = [  # as summary.json's ``seats`` (fields of the seat checks), made up for the test
    {"name": "A1", "width_m": 0.45, "required_m": 0.4117, "clause": "AASHTO LRFD 4.7.4.4",
     "peak_opening_m": 0.0806, "margin_m": 0.3694, "unseated": False},
    {"name": "J1", "width_m": 0.06, "required_m": 0.4117, "clause": "AASHTO LRFD 4.7.4.4",
     "peak_opening_m": 0.0824, "margin_m": -0.0224, "unseated": True},
]


def _section(html: str, anchor: str, following: str) -> str:
    return html[html.index(f'id="{anchor}"'):html.index(f'id="{following}"')]


def test_report_has_a_bridge_section(printed, tmp_path: Path) -> None:
    """The report's Bridge section: the elevation drawn with the seat widths of
    summary.json's ``seats``, the element tables in mm and kN, the seat margins with the
    unseated seat warned; the Figures section leaves the elevation to it; no storey table
    in the headline numbers, frames (not buildings of storeys) in the Model section."""
    import shutil

    _, out = printed
    folder = tmp_path / "run"
    shutil.copytree(out, folder)
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    summary["seats"] = SEATS
    (folder / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    html = write_report(folder, tmp_path / "report.html").read_text(encoding="utf-8")
    bridge = _section(html, "bridge", "model")
    assert "<h2" in bridge and ">Bridge<" in bridge
    assert bridge.count("<img ") == 1
    assert "drawn with the seat widths of summary.json&#x27;s seats" in bridge
    for header in ("peak drift [mm]", "peak shear [kN]", "peak displacement [mm]",
                   "largest opening [mm]", "seat width [mm]", "margin [mm]"):
        assert f"<th>{header}</th>" in bridge, header
    drift = 1e3 * summary["bridge"]["frames"][0]["piers"][0]["peak_drift_m"]
    assert "<td>B1P1</td><td>bilinear, F_y 2000 kN</td>" in bridge
    assert f'<td class="n">{drift:.4g}</td>' in bridge
    assert ("<tr><td>J1</td><td class=\"n\">60</td><td class=\"n\">411.7</td>"
            "<td>AASHTO LRFD 4.7.4.4</td><td class=\"n\">82.4</td>"
            "<td class=\"n\">-22.4</td><td>yes</td></tr>") in bridge
    assert "Unseated: J1" in bridge and "Narrower than the clause&#x27;s minimum: J1" in bridge
    figures = _section(html, "figures", "impacts")
    assert "bridge_elements.png of the run" in figures and "bridge.png" not in figures
    model = _section(html, "model", "record")
    assert "Frames, left to right" in model and "Buildings, left to right" not in model
    assert "<td>B1Br1 (elastomeric)</td>" in model
    headline = _section(html, "summary", "bridge")
    assert "largest deck displacement [m]" in headline
    assert "Peak response of each building" not in headline


def test_report_without_seats_says_they_were_not_checked(printed, tmp_path: Path) -> None:
    import shutil

    from pounding.report import render_report

    _, out = printed
    folder = tmp_path / "run"
    shutil.copytree(out, folder)
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    summary.pop("seats", None)  # (a run whose model gives no seat widths)
    (folder / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    html = render_report(folder)
    bridge = _section(html, "bridge", "model")
    assert "Seat margins: not checked in this run" in bridge
    assert "bridge.png of the run" in bridge


def test_report_of_a_bridge_folder_without_its_model(printed, tmp_path: Path) -> None:
    """Without model.toml the page still knows a bridge's figures from summary.json's
    ``bridge`` block: a missing bridge_elements.png is warned about, the storeys' figures
    are not asked for, the elevation comes from the folder."""
    import shutil

    from pounding.report import render_report

    _, out = printed
    folder = tmp_path / "run"
    shutil.copytree(out, folder)
    (folder / "model.toml").unlink()
    (folder / "bridge_elements.png").unlink()
    html = render_report(folder)
    assert "bridge_elements.png is not in the folder and could not be regenerated" in html
    assert "envelopes.png" not in html and "storeys.png" not in html
    assert "bridge.png of the run" in _section(html, "bridge", "model")
