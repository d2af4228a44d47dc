"""Model files (`pounding.config`): the examples, round trips, and errors that name the key."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from pounding.config import RunConfig, dump_toml, load_config, parse_config
from pounding.example_files import example_kind
from pounding.structure.assembly import floor_dofs
from pounding.model import PoundingModel
from pounding.structure import ModalDamping, RayleighDamping

ROOT = Path(__file__).resolve().parents[1]
# model files (sweep files, sweep_*.toml, are tested in tests/studies/test_sweep.py, spectrum
# files, spectrum_*.toml, in tests/spectra/, pushover files, *_pushover.toml, in
# tests/structure/test_pushover_cli.py)
EXAMPLES = sorted(p for p in (ROOT / "examples").glob("*.toml") if example_kind(p.name) == "model")
DEMO = ROOT / "src" / "pounding" / "examples" / "two_10_storey.toml"


def base() -> dict[str, Any]:
    """The seed SDOF pair as plain data."""
    return {
        "name": "pair",
        "record": {"bundled": "el_centro"},
        "building": [{"mass": 2e5, "period": 0.5}, {"mass": 3e5, "period": 1.0}],
        "contact": {"law": "nonlinear-viscoelastic", "k_h": 2.75e9, "e": 0.65, "gap": 0.02},
    }


def error_of(data: dict[str, Any], tmp_path: Path | None = None) -> str:
    """The message of the ValueError a model file with ``data`` raises."""
    if tmp_path is None:
        with pytest.raises(ValueError) as info:
            parse_config(data, where="m.toml")
    else:
        f = tmp_path / "m.toml"
        f.write_text(dump_toml(data), encoding="utf-8")
        with pytest.raises(ValueError) as info:
            load_config(f)
    return str(info.value)


# ------------------------------------------------------------------------ examples
def test_there_are_the_four_examples() -> None:
    names = {p.name for p in EXAMPLES}
    assert {"seed_sdof_pair.toml", "two_10_storey.toml", "different_heights.toml",
            "row_of_three.toml"} <= names


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_parses_and_builds(path: Path) -> None:
    cfg = load_config(path)
    model, motion, solver = cfg.build()
    assert isinstance(model, PoundingModel)
    assert len(model.buildings) + len(model.walls) >= 2 and len(model.contacts) >= 1
    # every pair of neighbours can meet somewhere
    assert {c.pair for c in model.contacts if not c.on_wall} == set(
        range(len(model.buildings) - 1))
    for b in model.buildings:
        assert 0.1 < b.fundamental_period < 2.5
        floor_masses = b.masses[floor_dofs(b)]  # a plan's θ DOFs carry inertias [kg·m²]
        assert np.all((floor_masses >= 1e4) & (floor_masses <= 1e7))
    assert motion.pga_g > 0.1
    assert set(solver) == {"dt", "duration", "rtol", "h_max"}


def test_seed_example_is_the_seed_pair() -> None:
    model, motion, _ = load_config(ROOT / "examples" / "seed_sdof_pair.toml").build()
    left, right = model.buildings
    assert left.masses[0] == 2e5 and right.masses[0] == 3e5
    assert left.fundamental_period == pytest.approx(0.5, rel=1e-12)
    assert right.fundamental_period == pytest.approx(1.0, rel=1e-12)
    assert model.gaps == (0.02,)
    law = model.contacts[0].law
    assert type(law).__name__ == "NonlinearViscoelastic" and law.k_h == 2.75e9
    assert motion.npts == 4000 and motion.pga_g == pytest.approx(0.3129, abs=1e-4)


def test_different_heights_meet_up_to_the_lower_roof() -> None:
    model, _, _ = load_config(ROOT / "examples" / "different_heights.toml").build()
    assert [b.n for b in model.buildings] == [8, 5]
    assert [c.label for c in model.contacts] == [f"B1F{j}-B2F{j}" for j in range(1, 6)]
    assert model.buildings[0].fundamental_period == pytest.approx(0.93, rel=1e-9)


def test_row_of_three_has_two_gaps() -> None:
    model, motion, _ = load_config(ROOT / "examples" / "row_of_three.toml").build()
    assert model.gaps == (0.03, 0.02)
    assert {c.pair for c in model.contacts} == {0, 1}
    assert motion.pga_g == pytest.approx(0.4, rel=1e-12)
    assert isinstance(model.buildings[0].damping, RayleighDamping)
    assert model.buildings[0].damping.by_periods


def test_the_examples_ship_inside_the_package_and_copy_out(tmp_path: Path) -> None:
    from pounding.example_files import DEMO as DEMO_NAME
    from pounding.example_files import KINDS, copy_examples, example_path, examples

    # the repository's examples/ is the package's folder (a link), so a wheel has them all
    assert (ROOT / "examples").resolve() == example_path(DEMO_NAME).parent.resolve()
    assert example_path(DEMO_NAME).resolve() == DEMO.resolve()
    listed = {e.name: e.kind for e in examples()}
    assert KINDS == ("sweep", "spectrum", "fragility", "mitigation")
    assert listed == {p.name: next((k for k in KINDS if p.name.startswith(f"{k}_")),
                                   "pushover" if p.stem.endswith("_pushover") else "model")
                      for p in (ROOT / "examples").glob("*.toml")}
    assert all(e.description for e in examples())
    assert listed["fragility_two_10_storey.toml"] == "fragility"
    copied = copy_examples(tmp_path / "mine")
    data = {"matrix_building_M.csv", "matrix_building_K.csv"}  # the matrices an example reads
    assert {p.name for p in copied} == set(listed) | {"README.md"} | data
    for p in copied:
        if p.suffix == ".toml" and listed.get(p.name) == "model":
            load_config(p)  # every copied model file runs from its new folder
    with pytest.raises(ValueError, match="already has"):
        copy_examples(tmp_path / "mine")
    with pytest.raises(ValueError, match="no bundled example 'nope'"):
        example_path("nope")


def test_an_interrupted_copy_of_the_examples_leaves_whole_files_only(tmp_path: Path,
                                                                      monkeypatch) -> None:
    """A full disk (or Ctrl-C) on the third file: the two before it are whole, nothing is
    half-written, and a folder the copy made is gone if it is empty."""
    import pounding.example_files as ex
    from pounding.io import files

    real = files.write_bytes
    calls = []

    def failing(target, data):
        calls.append(target)
        if len(calls) == 3:
            raise OSError(28, "No space left on device", str(target))
        return real(target, data)

    monkeypatch.setattr(ex, "write_bytes", failing)
    with pytest.raises(OSError, match="No space"):
        ex.copy_examples(tmp_path / "mine")
    written = sorted(p.name for p in (tmp_path / "mine").iterdir())
    assert written == sorted(Path(c).name for c in calls[:2])
    for name in written:
        assert (tmp_path / "mine" / name).read_bytes() == (ex._folder() / name).read_bytes()
    monkeypatch.setattr(ex, "write_bytes", lambda target, data: (_ for _ in ()).throw(
        KeyboardInterrupt()))
    with pytest.raises(KeyboardInterrupt):
        ex.copy_examples(tmp_path / "new" / "deeper")
    assert not (tmp_path / "new").exists()


# ------------------------------------------------------------------------ round trip
@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_round_trip_through_toml(path: Path, tmp_path: Path) -> None:
    cfg = load_config(path)
    text = cfg.to_toml(resolve_paths=True, header="copy\nof a file")
    assert text.startswith("# copy\n# of a file\n")
    copy = tmp_path / "copy.toml"
    copy.write_text(text, encoding="utf-8")
    again = load_config(copy)
    assert again.model_dump() == cfg.model_dump()
    m1, g1, s1 = cfg.build()
    m2, g2, s2 = again.build()
    assert s1 == s2 and m1.gaps == m2.gaps
    assert all(a == b for a, b in zip(m1.buildings, m2.buildings))
    assert np.array_equal(g1.accel, g2.accel)


def test_record_file_relative_to_the_model_file_and_scaled(tmp_path: Path) -> None:
    rec = tmp_path / "records" / "pulse.txt"
    rec.parent.mkdir()
    t = np.arange(0, 2.0, 0.01)
    np.savetxt(rec, np.column_stack([t, 0.5 * np.sin(2 * np.pi * t)]))
    data = base()
    data["record"] = {"file": "records/pulse.txt", "units": "g", "pga_g": 0.3,
                      "duration": 1.0}
    sub = tmp_path / "models"
    sub.mkdir()
    (sub / "m.toml").write_text(dump_toml(data).replace('"records/', '"../records/'),
                                encoding="utf-8")
    cfg = load_config(sub / "m.toml")
    _, motion, _ = cfg.build()
    assert motion.pga_g == pytest.approx(0.3, rel=1e-12)
    assert motion.duration == pytest.approx(1.0)
    # the copy written with a run points at the file wherever it is read from
    moved = tmp_path / "elsewhere.toml"
    moved.write_text(cfg.to_toml(resolve_paths=True), encoding="utf-8")
    assert tomllib.loads(moved.read_text())["record"]["file"] == str(rec.resolve())
    assert load_config(moved).build().motion.npts == motion.npts


def test_building_forms_and_damping() -> None:
    data = base()
    data["building"] = [
        {"mass": 2e5, "stiffness": 4e7, "damping": {"rayleigh": [0.05]}},
        {"n_storeys": 3, "mass": 1e5, "period": 0.6, "height": 3.0,
         "damping": {"ratio": 0.02}},
        {"masses": [1e5, 1e5, 8e4], "stiffnesses": [2e8, 2e8, 1e8], "height": 3.0,
         "damping": {"rayleigh": [0.05, 0.03], "modes": [1, 3]}},
    ]
    data["contact"]["gap"] = 0.01
    model, _, _ = parse_config(data).build()
    a, b, c = model.buildings
    assert a.stiffnesses[0] == 4e7 and a.n == 1
    assert b.fundamental_period == pytest.approx(0.6, rel=1e-9)
    assert b.damping == ModalDamping(0.02)
    assert c.damping == RayleighDamping(zeta_i=0.05, zeta_j=0.03, mode_i=1, mode_j=3)
    assert list(c.floor_levels) == [3.0, 6.0, 9.0]
    assert [x.name for x in model.buildings] == ["B1", "B2", "B3"]
    sdof = parse_config(base()).build().model.buildings[0]
    assert sdof.stiffnesses[0] == pytest.approx(2e5 * (2 * math.pi / 0.5) ** 2, rel=1e-14)


# ------------------------------------------------------------------------ errors
def test_negative_mass_names_path_and_value() -> None:
    data = base()
    data["building"][0]["mass"] = -2e5
    assert error_of(data) == "m.toml: building[0].mass: must be in (0, 1e+12] kg (got -200000)"


def test_negative_period_of_second_building() -> None:
    data = base()
    data["building"][1]["period"] = -0.5
    assert error_of(data) == "m.toml: building[1].period: must be in (0, 100] s (got -0.5)"


def test_unknown_law() -> None:
    data = base()
    data["contact"]["law"] = "kelvin-voight"
    msg = error_of(data)
    assert msg.startswith("m.toml: contact.law: unknown law 'kelvin-voight'")
    assert "did you mean 'kelvin-voigt'" in msg and "\n" not in msg


def test_misspelt_key_is_an_error_with_a_suggestion() -> None:
    data = base()
    data["building"][1]["perod"] = data["building"][1].pop("period")
    msg = error_of(data)
    assert "building[1].perod: unknown key (got 1); did you mean 'period'?" in msg
    data = base()
    data["solvr"] = {"dt": 0.001}
    assert "solvr: unknown key" in error_of(data) and "did you mean 'solver'" in error_of(data)


def test_gaps_count_wrong() -> None:
    data = base()
    del data["contact"]["gap"]
    data["contact"]["gaps"] = [0.02, 0.03]
    assert error_of(data) == ("m.toml: contact.gaps: need 1 value(s) for 2 buildings "
                              "(got 2: [0.02, 0.03])")


def test_missing_record_file(tmp_path: Path) -> None:
    data = base()
    data["record"] = {"file": "nowhere.at2"}
    msg = error_of(data, tmp_path)
    assert msg.startswith(f"{tmp_path / 'm.toml'}: record.file: no such file")
    assert "nowhere.at2" in msg


def test_wrong_types_and_several_problems_one_line_each() -> None:
    data = base()
    data["building"][0]["mass"] = "2e5"
    data["building"][1]["period"] = 0
    data["contact"]["e"] = 1.5
    lines = error_of(data).splitlines()
    assert lines == [
        "m.toml: building[0].mass: must be a number (got '2e5')",
        "m.toml: building[1].period: must be in (0, 100] s (got 0)",
        "m.toml: contact.e: must be in (0, 1] (got 1.5)",
    ]


def test_key_not_read_by_the_law() -> None:
    data = base()
    data["contact"]["k"] = 9.3e8
    msg = error_of(data)
    assert msg.startswith("m.toml: contact.k: not used by the nonlinear-viscoelastic law "
                          "(got 9.3e+08)")


def test_domain_errors_carry_the_section_path() -> None:
    data = base()
    data["building"][0] = {"n_storeys": 2, "mass": 1e5, "stiffness": 1e8,
                           "damping": {"rayleigh": [0.05], "modes": [1, 3]}}
    msg = error_of(data)
    assert msg == ("m.toml: building[0].damping.modes[1]: must be in [1, 2]: the building has 2 "
                   "mode(s) (got 3)")
    data = base()
    data["contact"] = {"law": "kelvin-voigt", "e": 0.65, "gap": 0.02}
    assert error_of(data) == "m.toml: contact.k: required for the kelvin-voigt law"


def test_structural_problems() -> None:
    data = base()
    data["building"][0] = {"masses": [1e5, 1e5], "stiffnesses": [1e8]}
    assert error_of(data) == ("m.toml: building[0].stiffnesses: need 2 values, one per floor "
                              "like masses (got 1)")
    data = base()
    data["building"][0]["n_storeys"] = 0
    assert "building[0].n_storeys: must be in [1, 10000] (got 0)" in error_of(data)
    data = base()
    del data["contact"]
    assert error_of(data).startswith("m.toml: contact: required with 2 buildings")
    data = base()
    data["building"][1]["height"] = 3.5
    data["contact"]["floor_to_column"] = False
    assert "no floor at the same elevation" in error_of(data)
    data = base()
    data["record"] = {"bundled": "el_centro", "scale": 2.0, "pga_g": 0.5}
    assert ("record.pga_g: give one of scale, pga_g, sa_g and saavg_g (got scale=2, "
            "pga_g=0.5)") in error_of(data)
    data = base()
    data["building"] = []
    assert "building: must hold at least 1 value(s)" in error_of(data)


def test_file_level_errors(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="no such model file"):
        load_config(tmp_path / "absent.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("name = \n", encoding="utf-8")
    with pytest.raises(ValueError, match="not valid TOML"):
        load_config(bad)


def test_a_single_building_needs_no_contact() -> None:
    data = base()
    data["building"] = data["building"][:1]
    del data["contact"]
    model, _, _ = parse_config(data).build()
    assert model.contacts == () and model.gaps == ()
    assert isinstance(parse_config(data), RunConfig)
