"""`pounding report`: one self-contained HTML page for a run or a sweep folder, rendered in
a real headless browser (chromium; install it with ``bash ci/install_browser.sh``).

Set ``POUNDING_SKIP_BROWSER=1`` to skip the browser tests where no browser can be
installed; without it a missing chromium is a failure, not a skip.
"""

from __future__ import annotations

import base64
import json
import os
import re
import shutil
import struct
import subprocess
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pounding.cli import main
from pounding.config import dump_toml, load_config
from pounding.plot.registry import RUN_FIGURES, figures_for
from pounding.report import DEFAULT_NAME, detect_kind, render_report, write_report

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
# the figures of a run of the seed example (linear storeys: no storey hysteresis figure)
FIGURE_TITLES = {f.file: f.caption for f in figures_for(load_config(SEED).build().model).values()}
INSTALL = "bash ci/install_browser.sh"
IMG_SRC = re.compile(r"<img\b[^>]*?\bsrc=\"([^\"]*)\"", re.S)


# ------------------------------------------------------------------------ fixtures
@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """`pounding run` of the seed example, simulated for 5 s only (7 impacts)."""
    base = tmp_path_factory.mktemp("run")
    data = tomllib.loads(SEED.read_text(encoding="utf-8"))
    data["solver"]["duration"] = 5.0
    model = base / "seed_short.toml"
    model.write_text(dump_toml(data), encoding="utf-8")
    out = base / "out"
    assert main(["run", str(model), "--out", str(out)]) == 0
    return out


@pytest.fixture(scope="module")
def report(run_dir: Path) -> Path:
    assert main(["report", str(run_dir)]) == 0
    return run_dir / DEFAULT_NAME


def sweep_folder(folder: Path, with_error: bool = True) -> Path:
    """A results.parquet shaped like `pounding sweep`'s: case columns, parameters, status,
    measures, per-floor measures; the parameters named in the schema metadata."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    folder.mkdir(parents=True, exist_ok=True)
    gaps, es = [0.0, 0.01, 0.02, 0.04], [0.5, 0.8]
    rows = []
    for i, (g, e) in enumerate((g, e) for g in gaps for e in es):
        ok = not (with_error and i == 3)
        rows.append({
            "case_index": i, "case_id": f"{i:016x}", "contact.gap": g, "contact.e": e,
            "status": "ok" if ok else "error",
            "error": None if ok else "contact.e: <bad> & worse",
            "n_impacts": 10 - int(100 * g) if ok else None,
            "peak_contact_force_N": 4e6 * (1 - 10 * g) * (1.2 - 0.4 * e) if ok else np.nan,
            "contact_dissipated_J": 3e4 * (1 - 10 * g) if ok else np.nan,
            "peak_drift_ratio": 0.02 if ok else np.nan,
            "impact_overflow": False,
            "peak_displacement_m_B1F1": 0.05 if ok else np.nan,
            "wall_time_s": 0.5,
        })
    table = pa.Table.from_pandas(pd.DataFrame(rows), preserve_index=False)
    meta = {**(table.schema.metadata or {}),
            b"pounding.sweep": json.dumps({"name": "gap <&> e sweep",
                                           "params": ["contact.gap", "contact.e"]}).encode()}
    pq.write_table(table.replace_schema_metadata(meta), folder / "results.parquet")
    return folder


# ------------------------------------------------------------------------ the browser
def chromium() -> str:
    """The chromium executable; fail (or skip with POUNDING_SKIP_BROWSER=1) without one."""
    for name in (os.environ.get("POUNDING_CHROMIUM", ""), "chromium", "chromium-browser"):
        if name and (path := shutil.which(name)):
            return path
    if os.environ.get("POUNDING_SKIP_BROWSER") == "1":
        pytest.skip("no chromium; POUNDING_SKIP_BROWSER=1 set")
    pytest.fail(f"chromium not found: the report test renders the HTML in a headless browser. "
                f"Run `{INSTALL}` (Debian: apt-get install chromium), or set "
                "POUNDING_SKIP_BROWSER=1 to skip this test.", pytrace=False)


def browse(html_file: Path, work: Path, *mode: str) -> subprocess.CompletedProcess[str]:
    """Run headless chromium on ``html_file`` with ``mode`` (--dump-dom / --screenshot)."""
    exe = chromium()
    profile = work / f"profile-{len(list(work.glob('profile-*')))}"
    cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--no-first-run",
           f"--user-data-dir={profile}", "--window-size=1200,3000", *mode,
           html_file.resolve().as_uri()]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=180,
                          env={**os.environ, "HOME": str(work)})
    assert proc.returncode == 0, f"chromium failed ({proc.returncode}): {proc.stderr[-2000:]}"
    return proc


def png_size(data: bytes) -> tuple[int, int]:
    """Width and height [px] from a PNG's IHDR chunk."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    return struct.unpack(">II", data[16:24])


def check_images(dom: str, expected: int) -> None:
    srcs = IMG_SRC.findall(dom)
    assert len(srcs) == expected, f"{len(srcs)} <img> in the DOM, expected {expected}"
    for src in srcs:
        assert src.startswith("data:image/png;base64,"), src[:60]
        data = base64.b64decode(src.split(",", 1)[1])
        w, h = png_size(data)
        assert len(data) > 1000 and w > 0 and h > 0


def check_screenshot(png: Path) -> None:
    import matplotlib.image as mpimg

    assert png.is_file() and png.stat().st_size > 10_000, "no screenshot"
    px = mpimg.imread(png)[..., :3]
    assert px.shape[:2] == (3000, 1200)
    assert float(px.std()) > 0.05, f"blank screenshot (pixel std {px.std():.4f})"
    dark = float((px.mean(axis=2) < 0.5).mean())
    assert 0.005 < dark < 0.5, f"fraction of dark pixels {dark:.4f}: not a rendered page"


def test_run_report_renders_in_headless_chromium(report: Path, tmp_path: Path) -> None:
    dom = browse(report, tmp_path, "--dump-dom").stdout
    assert "<title>seed SDOF pair: pounding run report</title>" in dom
    assert "<h1>seed SDOF pair: pounding run report</h1>" in dom
    for heading in ("Headline numbers", "Model", "Record", "Figures", "Animation",
                    "Impact table", "Energy balance", "Gap check"):
        assert f"<h2>{heading}</h2>" in dom, heading
    # the impact table: 7 rows of contact B1F1-B2F1, headers with units
    table = dom[dom.index('<table class="impacts">'):]
    table = table[: table.index("</table>")]
    assert len(re.findall(r"<tr><td[^>]*>\d+</td><td>B1F1-B2F1</td>", table)) == 7
    for header in ("start [s]", "impact velocity v0 [m/s]", "peak force [N]",
                   "max penetration [m]", "energy dissipated by the contact [J]"):
        assert f"<th>{header}</th>" in table
    check_images(dom, expected=1 + len(FIGURE_TITLES))  # ground motion + 4 figures

    shot = tmp_path / "report.png"
    browse(report, tmp_path, f"--screenshot={shot}")
    check_screenshot(shot)


def test_sweep_report_renders_in_headless_chromium(tmp_path: Path) -> None:
    folder = sweep_folder(tmp_path / "sweep")
    assert main(["report", str(folder)]) == 0
    dom = browse(folder / DEFAULT_NAME, tmp_path, "--dump-dom").stdout
    assert "gap &lt;&amp;&gt; e sweep: pounding sweep report" in dom
    check_images(dom, expected=2)  # one plot per swept parameter
    shot = tmp_path / "sweep.png"
    browse(folder / DEFAULT_NAME, tmp_path, f"--screenshot={shot}")
    check_screenshot(shot)


# ------------------------------------------------------------------------ run report content
def test_run_report_is_self_contained_with_units(report: Path) -> None:
    text = report.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>")
    # nothing fetched from elsewhere: no stylesheet link, remote or file URL, and no script
    # but the embedded animation's own two (its frames as JSON, and the code drawing them)
    assert text.count("<script") == 2 and text.count('<div class="anim">') == 1
    view = text[text.index('<div class="anim">'):]
    assert view.index("</script></div>") > view.rindex("<script")
    assert "<link" not in text and "<iframe" not in text
    assert not re.search(r"(src|href)=\"(?!data:|#)", text)
    assert "http://" not in text and "https://" not in text
    for unit_header in ("peak contact force [N]", "peak roof displacement [m]",
                        "peak storey drift [m]", "total mass [kg]", "T1 [s]",
                        "final value [J]", "PGA [g]", "record duration [s]",
                        "max(u_left − u_right) in this run [m]", "gap [m]",
                        "integration wall time [s]"):
        assert unit_header in text, unit_header
    for name in FIGURE_TITLES:
        assert f"{name} of the run" in text
    assert "El Centro 1940" in text and "nonlinear-viscoelastic" in text


def test_gap_check_and_energy_agree_with_the_run(run_dir: Path, report: Path) -> None:
    import xarray as xr

    text = report.read_text(encoding="utf-8")
    summary = json.loads((run_dir / "summary.json").read_text())
    with xr.open_dataset(run_dir / "timehistories.nc", engine="h5netcdf") as ds:
        u = ds["displacement"].values
        pen = ds["penetration"].values[:, 0]
    rel = u[:, 0] - u[:, 1]
    np.testing.assert_allclose(rel - pen, 0.02, atol=1e-12)  # δ = u_left − u_right − gap
    gap = text[text.index('id="gap-check"'):]
    row = re.search(r"<tr><td>B1F1-B2F1</td>(.*?)</tr>", gap).group(1)  # type: ignore[union-attr]
    cells = re.findall(r"<td[^>]*>(.*?)</td>", row)
    assert cells[0] == "3" and cells[1] == "0.02" and cells[2] == "yes" and cells[3] == "7"
    assert float(cells[5]) == pytest.approx(rel.max(), rel=1e-3)
    assert float(cells[6]) == pytest.approx(0.02 - rel.max(), rel=1e-3)
    assert "not read from this run where anything touched" in gap
    energy = text[text.index('id="energy"'):text.index('id="gap-check"')]
    fin = summary["energy_final_J"]
    for term in ("input", "damping", "contact_work"):
        m = re.search(rf"<tr><td>{term}</td><td class=\"n\">([^<]+)</td>", energy)
        assert m and float(m.group(1)) == pytest.approx(fin[term], rel=1e-3), term


def test_missing_figures_are_regenerated_from_the_netcdf(run_dir: Path, tmp_path: Path) -> None:
    copy = tmp_path / "nofig"
    shutil.copytree(run_dir, copy)
    for fig in RUN_FIGURES.values():
        (copy / fig.file).unlink(missing_ok=True)
    (copy / DEFAULT_NAME).unlink(missing_ok=True)
    out = write_report(copy, tmp_path / "r.html")
    text = out.read_text(encoding="utf-8")
    assert text.count("regenerated from timehistories.nc") == len(FIGURE_TITLES)
    assert len(IMG_SRC.findall(text)) == 1 + len(FIGURE_TITLES)
    assert sorted(p.name for p in copy.iterdir()) == sorted(
        p.name for p in run_dir.iterdir() if p.suffix != ".png" and p.name != DEFAULT_NAME)


def test_text_from_the_files_is_escaped(run_dir: Path, tmp_path: Path) -> None:
    copy = tmp_path / "evil"
    shutil.copytree(run_dir, copy)
    evil = '<script>alert("x")</script> & co'
    summary = json.loads((copy / "summary.json").read_text())
    summary["model"] = evil
    (copy / "summary.json").write_text(json.dumps(summary))
    toml = (copy / "model.toml").read_text().replace('name = "seed SDOF pair"',
                                                     f"name = {json.dumps(evil)}")
    (copy / "model.toml").write_text(toml)
    text = render_report(copy)
    assert text.count("<script") == 2  # the animation's own (test above); none from the files
    assert "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; co" in text


def test_report_out_option_and_atomic_write(run_dir: Path, tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "sub" / "page.html"
    assert main(["report", str(run_dir), "--html", str(target)]) == 0
    assert target.is_file() and str(target) in capsys.readouterr().out
    assert [p.name for p in target.parent.iterdir()] == ["page.html"]  # no temporary left
    assert main(["report", str(run_dir), "--html", str(tmp_path)]) == 2  # a folder
    assert "is a folder" in capsys.readouterr().err


# ------------------------------------------------------------------------ sweep and errors
def test_sweep_report_content(tmp_path: Path) -> None:
    folder = sweep_folder(tmp_path / "sweep")
    assert detect_kind(folder) == "sweep"
    text = write_report(folder).read_text(encoding="utf-8")
    assert "<title>gap &lt;&amp;&gt; e sweep: pounding sweep report</title>" in text
    assert "contact.gap [m]" in text and "contact.e [-]" in text
    assert "peak_contact_force_N [N]" in text and "peak_displacement_m_B1F1 [m]" in text
    assert "main measure (plotted)" in text
    assert "8 case(s); the full grid of these values has 8 (a full grid)." in text
    assert "1 case(s) failed." in text and "contact.e: &lt;bad&gt; &amp; worse" in text
    assert "Summary statistics over all cases" in text and "median" in text
    assert len(IMG_SRC.findall(text)) == 2


def test_neither_run_nor_sweep_is_an_error(tmp_path: Path,
                                           capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "summary.json").write_text("{}")
    with pytest.raises(ValueError, match=r"missing timehistories\.nc.*missing results\.parquet"):
        write_report(tmp_path)
    assert main(["report", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert str(tmp_path.name) in err and "neither a run output" in err
    assert main(["report", str(tmp_path / "nope")]) == 2
    assert "does not exist" in capsys.readouterr().err
    assert not (tmp_path / DEFAULT_NAME).exists()


def test_run_report_shows_laws_and_damping_in_words(report: Path) -> None:
    """The model section gives each contact element's law and each building's damping in
    words with units and a few digits, not as Python reprs."""
    text = report.read_text(encoding="utf-8")
    assert ("nonlinear viscoelastic (Jankowski): k_h = 2.75e9 N/m^1.5, ζ = 0.368, "
            "m_eff = 1.20e5 kg") in text
    assert "modal, ζ = 0.05 in every mode" in text
    for raw in ("NonlinearViscoelastic(", "ModalDamping(", "0.3681616135670679"):
        assert raw not in text, raw
