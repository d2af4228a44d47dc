"""A bad sweep file is refused as a bad model file is: one line naming the key path and the
value (the same validation sections and the same formatter,
:mod:`pounding.studies.sweep.sections`), exit status 2, nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest

from pounding.cli import main
from pounding.studies.sweep import parse_sweep

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "seed_sdof_pair.toml"
GRID = '[grid]\n"contact.gap" = [0.01]\n'


@pytest.mark.parametrize("body, expected", [
    ("", "grid: give exactly one of [grid], [list] and [random] (got none)"),
    (GRID + '[list]\n"contact.e" = [0.5]\n',
     "list: give exactly one of [grid], [list] and [random] (got grid, list)"),
    ("[grid]\n", 'grid: give at least one parameter, e.g. "contact.gap" = [0.01, 0.02]'),
    ('[grid]\n"contact.gap" = []\n', "grid.contact.gap: must hold at least 1 value(s) (got 0: [])"),
    ('[grid]\n"contact.gap" = 0.01\n', "grid.contact.gap: must be a list [ ... ] (got 0.01)"),
    ('[grid]\n"contact.gap" = [nan]\n', "grid.contact.gap: values must be finite (got nan)"),
    ("batch_size = 0\n" + GRID, "batch_size: must be >= 1 (got 0)"),
    ("batch_size = 2.5\n" + GRID, "batch_size: must be an integer (got 2.5)"),
    ('histories = "hdf5"\n' + GRID,
     "histories: must be false, \"netcdf\", \"zarr\" or \"none\" (got 'hdf5')"),
    ('nmae = "x"\n' + GRID, "nmae: unknown key (got 'x'); did you mean 'name'? (keys here: "
                            "base, batch_size, grid, histories, list, name, out, random)"),
    ('[random]\nn = 2\nseed = -1\n"contact.gap" = [0.0, 0.05]\n',
     "random.seed: must be >= 0 (got -1)"),
    ('[random]\nseed = 1\n"contact.gap" = [0.0, 0.05]\n', "random.n: required"),
    ('[random]\nn = 2\nseed = 1\n"contact.gap" = [0.05, 0.0]\n',
     "random.contact.gap.uniform: must be [low, high], two numbers with low < high "
     "(got [0.05, 0.0])"),
    ('[random]\nn = 2\nseed = 1\n"contact.gap" = { unifrom = [0.0, 0.05] }\n',
     "random.contact.gap.unifrom: unknown distribution (got [0.0, 0.05]); did you mean "
     "'uniform'? (distributions: uniform, log, int, choice)"),
    ('[random]\nn = 2\nseed = 1\n"contact.gap" = { log = [0.0, 0.05] }\n',
     "random.contact.gap.log: needs low > 0 (got [0.0, 0.05])"),
    ('[grid]\n"contact.gapp" = [0.01]\n', "grid.contact.gapp: unknown key 'gapp'; did you mean "
                                         "'gap'? (keys here: a, backbone, backwall_height, "
                                         "backwall_width, c, capacity, chi, delta_m, "
                                         "delta_ult, e, floor_to_column, formula, "
                                         "fracture_displacement, gap, gaps, k, k_h, law, "
                                         "level_tolerance, n, tension, zeta)"),
    ('[list]\n"building.5.period" = [0.5]\n',
     "list.building.5.period: building.5: need an index 0 … 1 or * (every one)"),
    ('[random]\nn = 2\nseed = 1\n"building.0.n_storeys" = { int = [1.5, 3] }\n',
     "random.building.0.n_storeys.int: must be [low, high], two integers with low < high "
     "(got [1.5, 3])"),
])
def test_a_bad_sweep_file_is_one_line_naming_the_key_and_value(tmp_path, capsys, body,
                                                               expected):
    path = tmp_path / "sweep.toml"
    path.write_text(f'base = "{BASE}"\nout = "out"\n' + body, encoding="utf-8")
    capsys.readouterr()
    assert main(["sweep", str(path), "--scheduler", "synchronous"]) == 2
    captured = capsys.readouterr()
    assert captured.err.strip().splitlines() == [f"error: {path}: {expected}"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.toml"]


@pytest.mark.parametrize("data, expected", [
    ({"grid": {"contact.gap": [0.01]}}, "s.toml: base: required"),
    ({"base": 3, "grid": {"contact.gap": [0.01]}},
     's.toml: base: the model file (base = "model.toml", relative to the sweep file) or an '
     "inline [base] table (got 3)"),
    ({"base": str(BASE), "grid": {"contact.gap": [0.01]}, "batch_size": True},
     "s.toml: batch_size: must be an integer (got true)"),
    ({"base": str(BASE), "random": {"n": 2, "seed": 1, "contact.gap": 0.5}},
     "s.toml: random.contact.gap: give [low, high] (uniform) or one of { uniform = [a, b] }, "
     "{ log = [a, b] }, { int = [a, b] }, { choice = [...] } (got 0.5)"),
    # several problems: one line each
    ({"base": str(BASE), "grid": {"contact.gap": []}, "batch_size": 0},
     "s.toml: batch_size: must be >= 1 (got 0)\n"
     "s.toml: grid.contact.gap: must hold at least 1 value(s) (got 0: [])"),
])
def test_the_api_refuses_with_the_same_lines(data, expected):
    with pytest.raises(ValueError) as info:
        parse_sweep(data, where="s.toml")
    assert str(info.value) == expected


def test_a_good_random_table_still_draws_the_same_cases():
    """The same seed gives the same cases as before the sweep file was a pydantic model
    (values of numpy's PCG64 with seed 7)."""
    import math

    import numpy as np

    sweep = parse_sweep({"base": str(BASE), "random": {
        "n": 3, "seed": 7, "contact.gap": [0.0, 0.05], "contact.e": {"choice": [0.5, 0.7]},
        "record.scale": {"log": [0.5, 2.0]}, "building.0.n_storeys": {"int": [1, 3]}}},
        where="s.toml")
    gen = np.random.Generator(np.random.PCG64(7))
    expected = []
    for _ in range(3):
        gap = float(gen.uniform(0.0, 0.05))
        e = [0.5, 0.7][int(gen.integers(2))]
        scale = float(math.exp(gen.uniform(math.log(0.5), math.log(2.0))))
        n = int(gen.integers(1, 3, endpoint=True))
        expected.append((gap, e, scale, n))
    assert [c.values for c in sweep.cases] == expected


@pytest.mark.parametrize("missing, scheduler, words", [
    ({"distributed"}, [], "a sweep needs distributed (Dask), which comes"),
    ({"pyarrow", "distributed"}, [], "a sweep needs pyarrow and distributed (Dask), which come"),
    ({"pyarrow"}, ["--scheduler", "synchronous"], "a sweep needs pyarrow, which comes"),
])
def test_without_the_sweep_extra_a_sweep_is_one_line_naming_it(tmp_path, capsys, monkeypatch,
                                                                missing, scheduler, words):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name in missing else real(name, *a))
    path = tmp_path / "sweep.toml"
    path.write_text(f'base = "{BASE}"\nout = "out"\n' + GRID, encoding="utf-8")
    capsys.readouterr()
    assert main(["sweep", str(path), *scheduler]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f'error: {words} with the sweep extra: pip install "pounding[sweep]"']
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.toml"]


def test_without_pyarrow_the_report_of_a_sweep_is_one_line_naming_the_extra(tmp_path, capsys,
                                                                             monkeypatch):
    import importlib.util

    folder = tmp_path / "sweep-results"
    folder.mkdir()
    (folder / "results.parquet").write_bytes(b"PAR1")  # (never read: refused before)
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "pyarrow" else real(name, *a))
    capsys.readouterr()
    assert main(["report", str(folder)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ['error: the report of a sweep needs pyarrow, which comes with the sweep '
                   'extra: pip install "pounding[sweep]"']
    assert sorted(p.name for p in folder.iterdir()) == ["results.parquet"]
