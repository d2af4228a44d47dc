"""`pounding animate` of buildings in plan and of bridges: what is drawn against what the run
computed independently of the drawing.

* buildings in plan (examples/torsional_pair.toml, 7.4 s: its first impacts at 7.23 s): a
  slab corner moves × the factor by what the building's own kinematics give
  (``PlanBuilding.point_displacement``), and at every contact the drawn faces are
  ``factor × (−penetration)`` apart (the kernel's penetration from the NetCDF file);
* a bridge along its axis (examples/bridge_two_frames.toml, 2.3 s: a backwall impact at
  1.98 s, the joint at 2.16 s): the joint and the backwall gaps drawn are ``factor ×
  (−penetration)``;
* across it (examples/bridge_transverse.toml, 1.8 s): the deck ends stand
  ``factor × (−penetration)`` from the shear keys;
and the pages: the plan page's slider moves the frame in a real browser (as
tests/test_animate.py; POUNDING_SKIP_BROWSER=1 skips it)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import dump_toml

from test_report import browse

ROOT = Path(__file__).resolve().parents[1]


def _run(tmp: pytest.TempPathFactory, example: str, duration: float) -> Path:
    base = tmp.mktemp(example)
    data = tomllib.loads((ROOT / "examples" / f"{example}.toml").read_text(encoding="utf-8"))
    data.setdefault("solver", {})["duration"] = duration
    data.setdefault("output", {})["figures"] = False
    model = base / f"{example}.toml"
    model.write_text(dump_toml(data), encoding="utf-8")
    out = base / "run"
    assert main(["run", str(model), "--out", str(out)]) == 0
    return out


def _frames(folder: Path, **options: float):
    from pounding.report.animate import run_frames
    from pounding.report.run_folder import read_run

    run = read_run(folder)
    return run, run_frames(run, **options)


def _drawn(frames, vertex) -> np.ndarray:
    """(frames, 2): where ``vertex`` is drawn at every frame."""
    return np.array([vertex.at(frames.channels[i], frames.exaggeration)
                     for i in range(len(frames.time))])


def _at_frames(run, frames, name: str) -> np.ndarray:
    t = run.ds["time"].values
    k = np.searchsorted(t, frames.time - 1e-12)
    return np.asarray(run.ds[name].values, dtype=float)[k]


@pytest.fixture(scope="module")
def plan_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _run(tmp_path_factory, "torsional_pair", 7.4)


def test_plan_slabs_move_by_their_kinematics_and_touch_when_the_contact_closes(plan_run
                                                                               ) -> None:
    run, frames = _frames(plan_run, fps=25.0, start=6.0)
    model = run.built.model
    assert frames.view == "plan" and frames.equal_scales
    f = frames.exaggeration
    u = _at_frames(run, frames, "displacement")
    # the top slab of each building: its corners against PlanBuilding.point_displacement
    slabs = [s for s in frames.shapes if s.kind == "slab"]
    assert len(slabs) == 2
    for b, slab in enumerate(slabs):
        plan = model.buildings[b].plan
        off = int(model.system.offsets[b])
        local = u[:, off:off + 3 * plan.n_floors]
        for v, (x, y) in zip(slab.vertices, ((0, 0), (plan.width, 0), (plan.width, plan.depth),
                                             (0, plan.depth)), strict=True):
            drawn = _drawn(frames, v) - [v.x, v.y]
            for comp, direction in ((0, "x"), (1, "y")):
                want = np.array([plan.point_displacement(row, plan.n_floors - 1, x, y, direction)
                                 for row in local])
                np.testing.assert_allclose(drawn[:, comp], f * want, rtol=0, atol=1e-9)
    # at the top floor's contacts: the faces drawn f × (−penetration) apart, at every frame
    pen = _at_frames(run, frames, "penetration")
    labels = [c.label for c in frames.contacts]
    b1, b2 = slabs
    for y_site in (6.0, 12.0):
        k = labels.index(f"B1F3@y={y_site:g}-B2F3@y={y_site:g}")
        p1, p2 = model.buildings[0].plan, model.buildings[1].plan
        s1 = (y_site - p1.site_y) / p1.depth  # along B1's right edge (corner 1 → 2)
        s2 = (y_site - p2.site_y) / p2.depth  # along B2's left edge (corner 0 → 3)
        right1 = (1 - s1) * _drawn(frames, b1.vertices[1])[:, 0] + s1 * _drawn(
            frames, b1.vertices[2])[:, 0]
        left2 = (1 - s2) * _drawn(frames, b2.vertices[0])[:, 0] + s2 * _drawn(
            frames, b2.vertices[3])[:, 0]
        np.testing.assert_allclose(left2 - right1, -f * pen[:, k], rtol=0, atol=1e-9)
    struck = [i for i in range(len(frames.time)) if frames.struck(i)]
    assert struck and frames.time[struck[0]] == pytest.approx(7.24, abs=0.021)
    assert all(c.mark is not None for c in frames.contacts)


def test_the_plan_page_slider_moves_the_frame_in_a_browser(plan_run, tmp_path: Path) -> None:
    out = tmp_path / "page"
    assert main(["animate", str(plan_run), "--out", str(out), "--no-video", "--start", "7",
                 "--fps", "25"]) == 0
    html = (out / "animation.html").read_text(encoding="utf-8")
    assert '"view": "plan"' in html and '"equal": true' in html
    probe = """<script>
const first = canvas.toDataURL();
slider.value = "6"; slider.dispatchEvent(new Event("input"));
document.body.setAttribute("data-slid", canvas.dataset.frame + "|" + clock.textContent
                           + "|" + (first !== canvas.toDataURL()));
</script></body>"""
    page = tmp_path / "probe.html"
    page.write_text(html.replace("</body>", probe), encoding="utf-8")
    dom = browse(page, tmp_path, "--virtual-time-budget=2000", "--dump-dom").stdout
    slid = re.search(r'data-slid="([^"]*)"', dom)
    assert slid, dom[-2000:]
    frame, clock, changed = slid.group(1).split("|")
    assert frame == "6" and clock.startswith("t = 7.240 s") and changed == "true"
    assert "impact" in clock


def test_a_bridge_along_its_axis_opens_and_closes_its_joints(
        tmp_path_factory: pytest.TempPathFactory, tmp_path: Path) -> None:
    run, frames = _frames(_run(tmp_path_factory, "bridge_two_frames", 2.3), fps=50.0)
    assert frames.view == "elevation"
    f = frames.exaggeration
    pen = _at_frames(run, frames, "penetration")
    labels = [c.label for c in frames.contacts]
    d1, d2 = [s for s in frames.shapes if s.kind == "deck"]
    walls = [s for s in frames.shapes if s.kind == "wall"]
    x_a1 = walls[0].vertices[0].x
    x_a2 = walls[1].vertices[0].x
    joint = _drawn(frames, d2.vertices[0])[:, 0] - _drawn(frames, d1.vertices[1])[:, 0]
    np.testing.assert_allclose(joint, -f * pen[:, labels.index("B1F1-B2F1")], atol=1e-9, rtol=0)
    a1 = _drawn(frames, d1.vertices[0])[:, 0] - x_a1
    np.testing.assert_allclose(a1, -f * pen[:, labels.index("A1-B1F1")], atol=1e-9, rtol=0)
    a2 = x_a2 - _drawn(frames, d2.vertices[1])[:, 0]
    np.testing.assert_allclose(a2, -f * pen[:, labels.index("B2F1-A2")], atol=1e-9, rtol=0)
    assert joint.min() < 0.0 < joint.max() and a1.min() < 0.0  # closed (struck) and open
    for k, label in enumerate(labels):
        hit = [i for i in range(len(frames.time)) if k in frames.struck(i)]
        assert hit, label  # each of the three struck within the 2.3 s
    assert main(["animate", str(run.folder), "--out", str(tmp_path / "p"), "--no-video"]) == 0
    assert '"kind": "deck"' in (tmp_path / "p" / "animation.html").read_text(encoding="utf-8")


def test_a_bridge_across_its_axis_sways_between_its_keys(
        tmp_path_factory: pytest.TempPathFactory) -> None:
    run, frames = _frames(_run(tmp_path_factory, "bridge_transverse", 1.8), fps=50.0)
    assert frames.view == "plan" and not frames.equal_scales
    f = frames.exaggeration
    pen = _at_frames(run, frames, "penetration")
    labels = [c.label for c in frames.contacts]
    d1, d2 = [s for s in frames.shapes if s.kind == "deck"]
    keys = {}
    for s in frames.shapes:
        if s.kind == "wall":
            keys[(s.vertices[0].x + s.vertices[1].x) / 2 > d1.vertices[1].x,
                 s.vertices[0].y > 0] = s.vertices[0].y
    y1 = _drawn(frames, d1.vertices[0])[:, 1]
    y2 = _drawn(frames, d2.vertices[1])[:, 1]
    np.testing.assert_allclose(keys[False, True] - y1, -f * pen[:, labels.index("B1F1-A1+y/key")],
                               atol=1e-9, rtol=0)
    np.testing.assert_allclose(y1 - keys[False, False],
                               -f * pen[:, labels.index("A1-y-B1F1/key")], atol=1e-9, rtol=0)
    np.testing.assert_allclose(keys[True, True] - y2, -f * pen[:, labels.index("B2F1-A2+y/key")],
                               atol=1e-9, rtol=0)
    struck = [i for i in range(len(frames.time)) if frames.struck(i)]
    assert struck and frames.time[struck[0]] == pytest.approx(1.62, abs=0.021)
