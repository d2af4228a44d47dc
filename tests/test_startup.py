"""Start-up: what ``import pounding`` and the CLI load, the public API at the top level,
``--version`` and ``python -m pounding``, and the run's files written without xarray/pandas
read back identical to what xarray/pandas give."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr

import pounding
from pounding.cli import main
from pounding.config import load_config
from pounding.integrate import simulate
from pounding.result import IMPACTS_CSV_COLUMNS, save_result

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
HEAVY = ("numba", "scipy", "pandas", "xarray", "matplotlib", "dask", "pydantic")


def _modules_after(code: str) -> set[str]:
    out = subprocess.run([sys.executable, "-c", code + "\nimport sys\n"
                          "print(' '.join(sorted({m.split('.')[0] for m in sys.modules})))"],
                         capture_output=True, text=True, check=True)
    return set(out.stdout.split())


@pytest.mark.parametrize("code", ["import pounding", "import pounding.cli",
                                  "from pounding.cli import app"])
def test_start_up_imports_no_heavy_library(code: str) -> None:
    loaded = _modules_after(code)
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))


def test_every_public_name_resolves_from_the_top_level() -> None:
    """Each public name is the very object its module defines (a class or function, never
    a module)."""
    import importlib
    import types

    for name, module in pounding._EXPORTS.items():
        value = getattr(pounding, name)
        assert not isinstance(value, types.ModuleType), name
        assert value is getattr(importlib.import_module(module), name), name
    assert {"PoundingModel", "ContactSpec", "ShearBuilding", "simulate", "Result",
            "el_centro", "KelvinVoigt", "run"} <= set(pounding.__all__)
    assert set(pounding.__all__) == set(pounding._EXPORTS) | {"__version__"}
    assert pounding.simulate is simulate
    assert callable(pounding.run)
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        pounding.nope  # noqa: B018


def test_no_module_takes_the_name_of_a_public_object() -> None:
    """Importing a submodule binds it as an attribute of its package: a module
    ``pounding/run.py`` made ``pounding.run`` the module, not the function, once anything had
    imported it (``TypeError: 'module' object is not callable``). Here every module of
    pounding is imported first, in a fresh process, and every public name must still be its
    object."""
    code = ("import importlib, pkgutil, types, pounding\n"
            "for m in pkgutil.walk_packages(pounding.__path__, 'pounding.'):\n"
            "    if not m.name.endswith('__main__'):\n"
            "        importlib.import_module(m.name)\n"
            "bad = [n for n, mod in pounding._EXPORTS.items()\n"
            "       if isinstance(getattr(pounding, n), types.ModuleType)\n"
            "       or getattr(pounding, n) is not getattr(importlib.import_module(mod), n)]\n"
            "print(' '.join(bad))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.split() == []


def test_top_level_docstring_example_runs() -> None:
    import doctest

    failures, tried = doctest.testmod(pounding, verbose=False)
    assert tried >= 4 and failures == 0


@pytest.mark.parametrize("argv", [["-m", "pounding", "--version"],
                                  ["-c", "from pounding.cli import main; main(['--version'])"]])
def test_version(argv: list[str]) -> None:
    out = subprocess.run([sys.executable, *argv], capture_output=True, text=True)
    assert out.returncode == 0
    assert out.stdout.strip() == f"pounding {pounding.__version__}"


def test_usage_error_is_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", str(SEED), "--no-such-option"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: pounding run: ")
    assert "--no-such-option" in err[0]


def test_files_written_without_xarray_read_back_as_xarray_and_pandas_give(
        tmp_path: Path) -> None:
    model, motion, solver = load_config(SEED).build()
    res = simulate(model, motion, **solver)
    files = save_result(res, tmp_path)
    with xr.open_dataset(files["timehistories"], engine="h5netcdf") as ds:
        ds.load()
        xr.testing.assert_identical(ds, res.to_dataset())
        assert list(ds["building"].values) == ["B1", "B2"]
        assert ds["building"].dims == ("floor",)
    assert files["impacts"].read_text().startswith(",".join(IMPACTS_CSV_COLUMNS.values()))
    back = pd.read_csv(files["impacts"])  # plain: no comment line, units in the names
    pd.testing.assert_frame_equal(back, res.impacts.rename(columns=IMPACTS_CSV_COLUMNS),
                                  check_dtype=False)
    assert len(back) == res.n_impacts == int(res.impacts_per_contact.sum())
    np.testing.assert_allclose(res.dissipated_per_contact,
                               [np.nansum(res.impacts["energy_dissipated"])])


def test_every_command_shows_examples_in_its_help(capsys: pytest.CaptureFixture[str]) -> None:
    from typer.main import get_command

    from pounding.cli import app

    names = sorted(get_command(app).commands)  # type: ignore[attr-defined]
    assert {"run", "demo", "examples", "record", "sweep", "report", "gap"} <= set(names)
    for name in names:
        assert main([name, "--help"]) == 0
        text = capsys.readouterr().out
        assert "Examples:" in text, name
        after = text.split("Examples:", 1)[1]
        shown = [ln.strip(" │") for ln in after.splitlines() if ln.strip().startswith("pounding ")]
        assert shown and all(ln.split()[1] == name for ln in shown), (name, shown)


def test_peak_forces_come_with_their_contact_labels() -> None:
    model, motion, solver = load_config(SEED).build()
    res = simulate(model, motion, **solver)
    peaks = res.contact_peaks
    assert list(peaks) == [c.label for c in model.contacts] == ["B1F1-B2F1"]
    p = peaks["B1F1-B2F1"]
    imp = res.impacts
    assert p.force == imp["peak_force"].max() == res.peak_contact_force[0]
    assert p.time == imp.loc[imp["peak_force"].idxmax(), "peak_force_time"]
    assert p.impacts == len(imp) == 26
    assert p.dissipated == pytest.approx(imp["energy_dissipated"].sum(), rel=1e-12)
