"""Jupyter: ``Result``, a sweep and a fragility study display as an HTML summary with their
key figure (``_repr_html_``), and ``Result.to_xarray()`` is the dataset the NetCDF file holds.

The HTML's numbers are read back and compared with the object's own summary
(``Result.summary()``, the sweep's outcome and table); the figure is a decodable PNG; showing
writes nothing. The fragility study's view is tested beside its study
(tests/studies/test_fragility_study.py)."""

from __future__ import annotations

import base64
import html
import io
import re
from pathlib import Path

import numpy as np
import pytest

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate

ROOT = Path(__file__).resolve().parents[1]
CELL = re.compile(r"<t[dh][^>]*>(.*?)</t[dh]>")


def rows(text: str) -> dict[str, str]:
    """The two-column rows of the HTML tables: first cell → second cell (unescaped)."""
    out = {}
    for row in re.findall(r"<tr>(.*?)</tr>", text):
        cells = [html.unescape(c) for c in CELL.findall(row)]
        if len(cells) >= 2:
            out[cells[0]] = cells[1]
    return out


def png_of(text: str) -> tuple[int, int]:
    """The size of the one inline PNG of ``text`` (it decodes)."""
    from PIL import Image

    uris = re.findall(r'<img [^>]*src="data:image/png;base64,([^"]+)"', text)
    assert len(uris) == 1
    with Image.open(io.BytesIO(base64.b64decode(uris[0]))) as im:
        im.load()
        return im.size


@pytest.fixture(scope="module")
def result():  # the seed pair (docs/seed_paper.md) for 6 s of El Centro: several impacts
    model = PoundingModel([ShearBuilding.sdof(2e5, period=0.5),
                           ShearBuilding.sdof(3e5, period=1.0)], gaps=[0.02],
                          contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    return simulate(model, el_centro(), duration=6.0)


def test_a_result_shows_its_summary_numbers_with_units_and_a_figure(
        result, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    text = result._repr_html_()
    assert list(tmp_path.iterdir()) == []  # nothing written where it was shown
    s = result.summary()
    got = rows(text)
    assert s["n_impacts"] > 2 and got["impacts"] == str(s["n_impacts"])
    for label, value in (("peak contact force [kN]", s["peak_contact_force_N"] / 1e3),
                         ("at t [s]", s["peak_contact_force_time_s"]),
                         ("energy dissipated in the contacts [kJ]",
                          s["contact_dissipated_J"] / 1e3),
                         ("simulated duration [s]", s["duration_s"])):
        assert float(got[label]) == pytest.approx(value, rel=5e-4), label  # 4 digits shown
    for b, floor in (("B1", "B1F1"), ("B2", "B2F1")):
        assert float(got[b]) == pytest.approx(s["peak_displacement_m"][floor] * 1e3, rel=5e-4)
    contact = re.search(r"<tr><td[^>]*>B1F1-B2F1</td><td[^>]*>(\d+)</td><td[^>]*>([^<]+)<",
                        text)
    assert contact and int(contact.group(1)) == s["impacts_by_contact"]["B1F1-B2F1"]
    assert float(contact.group(2)) == pytest.approx(
        s["peak_contact_force_by_contact_N"]["B1F1-B2F1"] / 1e3, rel=5e-4)
    for unit in ("[kN]", "[mm]", "[%]", "[s]", "[kJ]", " g"):
        assert unit in text, unit
    assert png_of(text)[0] >= 400
    assert "<script" not in text


def test_to_xarray_is_the_dataset_the_netcdf_holds(result, tmp_path: Path) -> None:
    import xarray as xr

    ds = result.to_xarray()
    result.save(tmp_path)
    with xr.open_dataset(tmp_path / "timehistories.nc", engine="h5netcdf") as f:
        nc = f.load()
    assert set(ds.variables) == set(nc.variables) and set(ds.coords) == set(nc.coords)
    assert ds.attrs == nc.attrs and ds.attrs["units"].startswith("SI")
    for name in ds.variables:
        a, b = ds[name], nc[name]
        assert a.dims == b.dims and a.attrs == b.attrs, name
        if a.dtype.kind in "OUS":
            assert [str(x) for x in a.values.ravel()] == [str(x) for x in b.values.ravel()]
        else:
            assert a.dtype == b.dtype, name
            np.testing.assert_array_equal(a.values, b.values, err_msg=name)
    for name in ("displacement", "contact_force", "ground_acceleration", "energy"):
        assert ds[name].attrs["units"] == nc[name].attrs["units"] != ""
    xr.testing.assert_identical(ds, nc)
    xr.testing.assert_identical(ds, result.to_dataset())  # the older name


def test_a_sweep_shows_its_counts_forces_and_figure(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    from pounding.studies.sweep import load_results, load_sweep, run_sweep

    path = tmp_path / "sweep.toml"
    path.write_text(f'base = "{ROOT / "examples" / "seed_sdof_pair.toml"}"\nname = "t"\n'
                    'out = "out"\n[grid]\n"contact.gap" = [0.0, 0.05]\n'
                    '"record.duration" = [2.0]\n', encoding="utf-8")
    outcome = run_sweep(load_sweep(path), scheduler="synchronous", figures=False)
    before = sorted(p.name for p in outcome.out_dir.iterdir())
    monkeypatch.chdir(tmp_path)
    text = outcome._repr_html_()
    assert sorted(p.name for p in outcome.out_dir.iterdir()) == before
    got = rows(text)
    assert int(got["cases"]) == outcome.n_cases == 2
    assert int(got["failed cases"]) == outcome.n_errors
    force = load_results(outcome.results)["peak_contact_force_N"].to_numpy() / 1e3
    assert force.max() > 0
    assert float(got["peak contact force, largest over the cases [kN]"]) == pytest.approx(
        force.max(), rel=5e-4)
    assert float(got["peak contact force, least over the cases [kN]"]) == pytest.approx(
        force.min(), rel=5e-4, abs=1e-9)
    assert int(got["cases with an impact"]) == int((force > 0).sum())
    assert "[s]" in text and "[kN]" in text
    png_of(text)
