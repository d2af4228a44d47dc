"""What an import or a command's help loads: reading a sweep's table loads neither the model
nor SciPy nor numba, and ``pounding --help`` / ``pounding run --help`` load no NumPy (each
checked in a fresh interpreter, so nothing another test imported counts)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

HEAVY = ("numpy", "scipy", "numba", "pandas", "xarray", "matplotlib", "dask", "distributed",
         "pyarrow", "pounding.model", "pounding.integrate", "pounding.studies.gap")


def loaded_by(code: str, watched: tuple[str, ...] = HEAVY) -> set[str]:
    """The modules of ``watched`` (default :data:`HEAVY`) that a fresh interpreter has
    loaded after ``code``."""
    probe = (f"{code}\nimport json, sys\n"
             f"print(json.dumps([m for m in {list(watched)!r} if m in sys.modules]))")
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
    return set(json.loads(proc.stdout.strip().splitlines()[-1]))


def test_reading_a_sweep_table_loads_no_model_scipy_or_numba() -> None:
    loaded = loaded_by("import pounding.studies.sweep.table")
    assert not loaded & {"scipy", "numba", "pounding.model", "pounding.integrate",
                         "pounding.studies.gap", "dask", "distributed"}, loaded


def test_the_studies_package_loads_a_study_only_when_named() -> None:
    assert not loaded_by("import pounding.studies") & {"numpy", "scipy", "numba"}
    loaded = loaded_by("from pounding.studies import critical_gaps")
    assert "pounding.studies.gap" in loaded
    # a code rule is a formula: it needs neither the gap study nor the model
    loaded = loaded_by("from pounding.studies import srss")
    assert not loaded & {"pounding.studies.gap", "pounding.model", "scipy", "numba"}, loaded


@pytest.mark.parametrize("argv", [["--help"], ["--version"], ["run", "--help"],
                                  ["sweep", "--help"], ["ellipse", "--help"],
                                  ["collide", "--help"]])
def test_help_loads_no_numpy(argv: list[str]) -> None:
    code = ("from pounding.cli import main\n"
            f"try:\n    main({argv!r})\nexcept SystemExit:\n    pass\n"
            "import sys; sys.stdout.flush()")
    # the help goes to stdout before the probe's line: take the last line only
    assert loaded_by(code) == set(), argv


def test_the_output_foundations_load_nothing_heavy() -> None:
    """Writing files and keeping output folders (``pounding.io``) is needed by every command
    at start-up: it loads nothing of :data:`HEAVY`, NumPy included."""
    assert loaded_by("import pounding.io.files, pounding.io.manifest, "
                     "pounding.io.output_folder") == set()


def test_a_fragility_module_loads_only_what_it_needs() -> None:
    """Fitting a fragility curve loads neither the study's runner nor what it runs (the
    sweep machinery, the model, the time stepper, Dask); the package names it all."""
    runner_side = ("pounding.studies.fragility.runner", "pounding.studies.fragility.analysis",
                   "pounding.studies.fragility.cases", "pounding.studies.fragility.study",
                   "pounding.studies.sweep", "pounding.config", "pydantic")
    watched = HEAVY + runner_side
    loaded = loaded_by("import pounding.studies.fragility.fitting", watched)
    assert not loaded & {"scipy", "numba", "dask", "pounding.model", "pounding.integrate",
                         *runner_side}, loaded
    assert not loaded_by("import pounding.studies.fragility", watched) - {"numpy"}
    loaded = loaded_by("from pounding.studies.fragility import run_study", watched)
    assert "pounding.studies.fragility.runner" in loaded


def test_the_seed_link_element_loads_no_compiled_law() -> None:
    """``pounding ellipse`` (the seed paper's link element) needs NumPy and SciPy only: the
    contact package loads its laws' compiled kernels (numba) on first use of a law."""
    assert "numba" not in loaded_by("import pounding.contact.link_element")
    assert "numba" in loaded_by("from pounding.contact import LAWS")


@pytest.mark.parametrize("package", ["pounding.config", "pounding.contact", "pounding.result",
                                     "pounding.structure",
                                     "pounding.studies",
                                     "pounding.studies.sweep", "pounding.studies.fragility"])
def test_every_public_name_of_a_lazy_package_is_there(package: str) -> None:
    """Each name a package lists is what its module defines (imported on first use), and
    a name it does not have is an AttributeError naming the package."""
    import importlib

    module = importlib.import_module(package)
    for name in module.__all__:
        value = getattr(module, name)
        source = importlib.import_module(module._EXPORTS[name])
        assert value is getattr(source, name), name
        assert name in dir(module)
    with pytest.raises(AttributeError, match=f"module '{package}' has no attribute 'nope'"):
        getattr(module, "nope")
    # a public name that is also a submodule's would become the module once anything
    # imports that submodule (``pounding.run`` was the function until ``pounding.run`` the
    # module was imported)
    import pkgutil

    submodules = {m.name for m in pkgutil.iter_modules(module.__path__)}
    assert not submodules & set(module.__all__)


def test_a_run_of_two_shear_buildings_loads_only_what_its_model_needs(tmp_path) -> None:
    """``pounding run examples/seed_sdof_pair.toml --no-figures`` (two SDOF buildings,
    Jankowski's law with e = 0.65) loads none of the machinery of the models it does not
    hold — buildings in plan's foundations, bridges, frames — nor what only other commands
    need: SciPy's optimizers and integrators (the exact ζ of e = 0.65 is tabulated), the
    contact calibration, pandas, xarray, matplotlib, Dask. (``scipy.linalg`` it does load:
    the exact propagator is a matrix exponential.)"""
    from pathlib import Path

    seed = Path(__file__).resolve().parents[1] / "examples" / "seed_sdof_pair.toml"
    not_needed = ("scipy.optimize", "scipy.integrate", "scipy.sparse", "scipy.special",
                  "pandas", "xarray", "matplotlib", "dask", "pounding.structure.plan",
                  "pounding.structure.bridge", "pounding.structure.foundation",
                  "pounding.structure.frame", "pounding.structure.frame_linear",
                  "pounding.contact.calibration", "pounding.contact.collision",
                  "pounding.plot.response", "pounding.studies")
    code = ("from pounding.cli import main\n"
            f"assert main(['run', {str(seed)!r}, '--out', {str(tmp_path / 'out')!r}, "
            "'--no-figures']) == 0\n"
            "import sys; sys.stdout.flush()")
    loaded = loaded_by(code, not_needed + ("pounding.integrate", "scipy.linalg"))
    assert (tmp_path / "out" / "timehistories.nc").is_file()
    assert {"pounding.integrate", "scipy.linalg"} <= loaded  # (it did run)
    assert not loaded & set(not_needed), sorted(loaded & set(not_needed))
