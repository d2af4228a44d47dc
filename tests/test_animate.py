"""`pounding animate`: the frames against the NetCDF they come from, the video, the page
driven in a real headless browser (chromium, as tests/test_report.py; POUNDING_SKIP_BROWSER=1
skips it where none can be installed), and bad input."""

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
SEED = ROOT / "examples" / "seed_sdof_pair.toml"


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """`pounding run` of the seed SDOF pair for 2 s (one impact, at 1.98 s)."""
    base = tmp_path_factory.mktemp("animate")
    data = tomllib.loads(SEED.read_text(encoding="utf-8"))
    data["solver"]["duration"] = 2.0
    data.setdefault("output", {})["figures"] = False
    model = base / "seed_2s.toml"
    model.write_text(dump_toml(data), encoding="utf-8")
    out = base / "run"
    assert main(["run", str(model), "--out", str(out)]) == 0
    return out


@pytest.fixture(scope="module")
def animated(run_dir: Path) -> Path:
    assert main(["animate", str(run_dir)]) == 0
    return run_dir


def test_frames_follow_the_histories(run_dir: Path) -> None:
    import xarray as xr

    from pounding.plot.animate import animation_frames

    with xr.open_dataset(run_dir / "timehistories.nc", engine="h5netcdf") as ds:
        ds = ds.load()
    frames = animation_frames(ds, fps=25.0)
    t = ds["time"].values
    assert len(frames.time) == 51  # 2 s at 25 frames/s, both ends
    np.testing.assert_allclose(frames.time, np.arange(51) / 25.0, atol=1e-9)
    u = ds["displacement"].values
    for b, j in zip(frames.buildings, (0, 1), strict=True):
        k = np.searchsorted(t, frames.time - 1e-12)
        np.testing.assert_allclose(b.displacement[:, 0], u[k, j], rtol=0, atol=1e-15)
    # the gap drawn is the model's 20 mm times the factor: faces touch when the contact closes
    gap_drawn = frames.buildings[1].left - frames.buildings[0].left - frames.buildings[0].width
    assert gap_drawn == pytest.approx(0.02 * frames.exaggeration, rel=1e-9)
    # an impact is marked on a frame iff the contact carried force at a step since the last
    force = ds["contact_force"].values[:, 0]
    for i in range(1, 51):
        between = (t > frames.time[i - 1]) & (t <= frames.time[i] + 1e-12)
        assert (frames.contacts[0].force[i] > 0) == bool((force[between] > 0).any()), i
    struck = [i for i in range(51) if frames.struck(i)]
    assert struck and frames.time[struck[0]] == pytest.approx(2.0)  # impact at 1.98 s
    assert frames.contacts[0].force.max() == pytest.approx(force.max(), rel=1e-12)
    # options: fps, window, exaggeration
    part = animation_frames(ds, fps=10.0, start=0.5, end=1.5, exaggeration=20.0)
    np.testing.assert_allclose(part.time, 0.5 + np.arange(11) / 10.0, atol=1e-9)
    assert part.exaggeration == 20.0


def test_animate_writes_a_gif_and_a_self_contained_page(animated: Path) -> None:
    from PIL import Image

    from pounding.io.manifest import Manifest

    html = (animated / "animation.html").read_text(encoding="utf-8")
    assert "http://" not in html and "https://" not in html and "<link" not in html
    assert not re.search(r"\bsrc=", html)  # nothing fetched: the data and the code inline
    assert "[m/s²]" in html and "[kN]" in html
    video = next(animated.glob("animation.*[!l]"))  # .gif here (no ffmpeg) or .mp4
    if video.suffix == ".gif":
        with Image.open(video) as im:
            assert im.n_frames == 51
    manifest = Manifest(animated)
    assert manifest.is_ours(animated / "animation.html") and manifest.is_ours(video)
    # again: pounding's own files are replaced
    assert main(["animate", str(animated), "--fps", "10", "--no-video"]) == 0
    assert 'max="20"' in (animated / "animation.html").read_text(encoding="utf-8")


def test_the_slider_and_play_move_the_frame_in_a_browser(run_dir: Path, tmp_path: Path
                                                        ) -> None:
    assert main(["animate", str(run_dir), "--out", str(tmp_path / "page"), "--no-video"]) == 0
    html = (tmp_path / "page" / "animation.html").read_text(encoding="utf-8")
    probe = """<script>
const first = canvas.toDataURL();
slider.value = "50"; slider.dispatchEvent(new Event("input"));
const moved = canvas.toDataURL();
document.body.setAttribute("data-slid", canvas.dataset.frame + "|" + clock.textContent
                           + "|" + (first !== moved));
slider.value = "0"; slider.dispatchEvent(new Event("input"));
button.click();
setTimeout(() => document.body.setAttribute("data-played", slider.value + "|" +
           canvas.dataset.frame), 1000);
</script></body>"""
    page = tmp_path / "probe.html"
    page.write_text(html.replace("</body>", probe), encoding="utf-8")
    dom = browse(page, tmp_path, "--virtual-time-budget=3000", "--dump-dom").stdout
    slid = re.search(r'data-slid="([^"]*)"', dom)
    assert slid, dom[-2000:]
    frame, clock, changed = slid.group(1).split("|")
    assert frame == "50" and changed == "true"
    assert clock.startswith("t = 2.000 s") and "impact" in clock
    played = re.search(r'data-played="(\d+)\|(\d+)"', dom)
    assert played, dom[-2000:]
    assert 10 <= int(played.group(1)) == int(played.group(2))  # ~25 frames in 1 s of play


def test_bad_input_exits_2_and_writes_nothing(run_dir: Path, tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "nowhere"
    assert main(["animate", str(missing)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(missing) in err[0] and err[0].startswith("error:")

    half = tmp_path / "half"
    half.mkdir()
    (half / "summary.json").write_text("{}", encoding="utf-8")
    assert main(["animate", str(half)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(half) in err[0] and "timehistories.nc" in err[0]
    assert sorted(p.name for p in half.iterdir()) == ["summary.json"]

    # a file pounding did not write is never replaced
    out = tmp_path / "mine"
    out.mkdir()
    (out / "animation.html").write_text("my notes", encoding="utf-8")
    assert main(["animate", str(run_dir), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "animation.html" in err[0]
    assert (out / "animation.html").read_text(encoding="utf-8") == "my notes"
    assert sorted(p.name for p in out.iterdir()) == ["animation.html"]

    for option, value in (("--fps", "0"), ("--exaggeration", "-1"), ("--end", "9")):
        assert main(["animate", str(run_dir), "--out", str(tmp_path / "o"), option, value]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and option in err[0] and value in err[0]
    assert not (tmp_path / "o").exists()


def test_out_folder_gets_a_manifest(run_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "movies"
    assert main(["animate", str(run_dir), "--out", str(out), "--no-video"]) == 0
    assert (out / "animation.html").is_file() and not list(out.glob("animation.gif"))
    assert main(["animate", str(run_dir), "--out", str(out), "--no-video"]) == 0


def test_the_run_report_embeds_the_view_and_its_slider_moves_the_frame(run_dir: Path,
                                                                      tmp_path: Path) -> None:
    """The run report holds the animation page's view, its frames embedded once (as in the
    page `pounding animate` writes), and its slider moves the frame in a real browser."""
    report = tmp_path / "report.html"
    assert main(["report", str(run_dir), "--html", str(report)]) == 0
    text = report.read_text(encoding="utf-8")
    assert text.count('<script id="anim-data"') == 1 and 'max="50"' in text  # 2 s at 25 /s
    assert main(["animate", str(run_dir), "--out", str(tmp_path / "page"), "--no-video"]) == 0
    page = (tmp_path / "page" / "animation.html").read_text(encoding="utf-8")
    data = re.compile(r'<script id="anim-data" type="application/json">(.*?)</script>', re.S)
    assert data.search(text).group(1) == data.search(page).group(1)  # type: ignore[union-attr]
    probe = """<script>
slider.value = "50"; slider.dispatchEvent(new Event("input"));
document.body.setAttribute("data-slid", canvas.dataset.frame + "|" + clock.textContent);
</script></body>"""
    probed = tmp_path / "probe.html"
    probed.write_text(text.replace("</body>", probe), encoding="utf-8")
    dom = browse(probed, tmp_path, "--virtual-time-budget=2000", "--dump-dom").stdout
    slid = re.search(r'data-slid="([^"]*)"', dom)
    assert slid, dom[-2000:]
    frame, clock = slid.group(1).split("|")
    assert frame == "50" and clock.startswith("t = 2.000 s") and "impact" in clock
