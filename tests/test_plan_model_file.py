"""Buildings in plan and two ground components from a model file (issue 18): the example
``torsional_pair.toml`` run through the CLI equals the Python API's run of the same model
(``torsional_pair()`` of tests/integrate/test_plan_pounding.py, itself checked against the
SciPy reference) to the last bit; one component at an incidence and the scaling of both
components against :func:`at_incidence` by hand; bad fields one line each, exit 2."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from pounding import PoundingModel, simulate
from pounding.cli import main
from pounding.config import load_config, parse_config
from pounding.example_files import example_path
from pounding.ground_motion import GroundMotionComponents, load_bundled
from pounding.ground_motion.incidence import at_incidence
from pounding.model import ContactSpec
from pounding.units import G

sys.path.insert(0, str(Path(__file__).parent / "integrate"))
from test_plan_pounding import torsional_pair  # noqa: E402

FIRST, SECOND = "kocaeli_1999_duzce_180_RSN1158", "kocaeli_1999_duzce_270_RSN1158"
EXAMPLE = example_path("torsional_pair.toml")


def api_model() -> PoundingModel:
    left, right, gap = torsional_pair()
    return PoundingModel([left, right], gaps=[gap],
                         contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))


def test_the_example_through_the_cli_is_the_api_run(tmp_path, capsys) -> None:
    """Same buildings, contact and motion from the file as from Python: every history in the
    NetCDF file and every peak in summary.json equal; both corners of the roof strike."""
    out = tmp_path / "out"
    assert main(["run", str(EXAMPLE), "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    motion = GroundMotionComponents(at_incidence(load_bundled(FIRST), load_bundled(SECOND),
                                                 60.0))
    r = simulate(api_model(), motion, dt=0.001)
    import xarray as xr

    with xr.open_dataset(out / "timehistories.nc", engine="h5netcdf") as ds:
        assert np.array_equal(ds["displacement"].values, np.asarray(r.displacement))
        assert np.array_equal(ds["contact_force"].values, np.asarray(r.contact_force))
        assert np.array_equal(ds["ground_acceleration"].values, np.asarray(r.ground))
        assert ds["ground_acceleration"].dims == ("time", "ground_component")
        assert [str(c)[-3:] for c in ds["ground_component"].values] == ["(x)", "(y)"]
        assert list(ds["dof_name"].values[:3]) == ["F1x", "F1y", "F1θ"]
    s = json.loads((out / "summary.json").read_text())
    assert s["impacts_by_contact"] == {lb: p.impacts for lb, p in r.contact_peaks.items()}
    assert s["peak_contact_force_by_contact_N"] == {lb: p.force
                                                    for lb, p in r.contact_peaks.items()}
    struck = {lb for lb, k in s["impacts_by_contact"].items() if k}
    assert {"B1F3@y=6-B2F3@y=6", "B1F3@y=12-B2F3@y=12"} <= struck
    # floor rotations: the θ DOFs' peaks, in mrad
    peak = np.abs(np.asarray(r.displacement)).max(axis=0)
    theta = s["peak_floor_rotation_mrad"]
    assert list(theta) == [f"B{b}F{j}θ" for b in (1, 2) for j in (1, 2, 3)]
    for (label, v), dof in zip(theta.items(), [2, 5, 8, 11, 14, 17]):
        assert v == 1e3 * r.peak_displacement[dof], label  # located inside the steps
        assert peak[dof] <= r.peak_displacement[dof] < 1.001 * peak[dof]  # the grid's peak
    assert s["buildings"][1]["storeys"][2]["peak_rotation_mrad"] == theta["B2F3θ"]
    assert s["buildings"][1]["given_as"] == "plan"
    assert "rotation" in printed and "[mrad]" in printed
    assert s["record"] == f"{FIRST} + {SECOND} at 60°"
    assert s["record_pga_g"] == pytest.approx(motion.pga_g, rel=1e-15)
    # the figures are written; the copy of the model states its defaults and builds the same
    assert {"displacements.png", "envelopes.png", "contact_forces.png"} <= {
        p.name for p in out.iterdir()}
    # the report reads the folder (the record section: both components, x and y)
    assert main(["report", str(out), "--html", str(tmp_path / "report.html")]) == 0
    html = (tmp_path / "report.html").read_text()
    assert "PGA of x, y [g]" in html and "record.incidence in model.toml" in html
    copy = load_config(out / "model.toml")
    assert copy.record.incidence == 60.0
    assert copy.building[0].damping is not None
    built = copy.build()
    for a, b in zip(built.model.buildings, api_model().buildings):
        assert np.array_equal(a.damping_matrix(), b.damping_matrix())
        assert np.array_equal(a.stiffness_matrix(), b.stiffness_matrix())


def _plan_text(record: str) -> str:
    text = EXAMPLE.read_text()
    start, end = text.index("[record]"), text.index("[[building]]")
    return text[:start] + record + "\n" + text[end:]


def test_one_component_shakes_along_the_incidence(tmp_path) -> None:
    """No second component: the record alone at the incidence, at_incidence(first, None, α)."""
    cfg = parse_config(__import__("tomllib").loads(_plan_text(
        f'[record]\nbundled = "{FIRST}"\nincidence = 30.0\nduration = 10.0\n')))
    model, motion, solver = cfg.build()
    ax, ay = at_incidence(load_bundled(FIRST).trimmed(10.0), None, 30.0)
    assert isinstance(motion, GroundMotionComponents)
    assert np.array_equal(motion.accel, np.column_stack([ax.accel, ay.accel]))
    assert "alone (one component) at 30°" in motion.name
    r = simulate(model, motion, **solver)
    ref = simulate(api_model(), GroundMotionComponents((ax, ay)), **solver)
    assert np.array_equal(np.asarray(r.displacement), np.asarray(ref.displacement))


@pytest.mark.parametrize("scaling", ["pga_g = 0.5", "scale = 1.7"])
def test_scaling_multiplies_both_components_alike(scaling: str) -> None:
    """The factor is the first component's; the second takes the same."""
    cfg = parse_config(__import__("tomllib").loads(_plan_text(
        f'[record]\nbundled = "{FIRST}"\nsecond = "{SECOND}"\nincidence = 60.0\n'
        f'duration = 12.0\n{scaling}\n')))
    motion = cfg.build().motion
    h1, h2 = load_bundled(FIRST).trimmed(12.0), load_bundled(SECOND).trimmed(12.0)
    factor = 0.5 * G / h1.pga if scaling.startswith("pga") else 1.7
    ax, ay = at_incidence(h1.scaled(factor), h2.scaled(factor), 60.0)
    np.testing.assert_allclose(motion.accel, np.column_stack([ax.accel, ay.accel]),
                               rtol=1e-14, atol=1e-14 * h1.pga * factor)


def test_a_second_component_from_a_file(tmp_path) -> None:
    """``second_file`` reads the orthogonal component from a file (dt stated)."""
    h2 = load_bundled(SECOND).trimmed(8.0)
    np.savetxt(tmp_path / "h2.txt", h2.accel / G)
    text = _plan_text(f'[record]\nbundled = "{FIRST}"\nsecond_file = "h2.txt"\n'
                      f'dt = {h2.dt!r}\nunits = "g"\nincidence = 90.0\nduration = 8.0\n')
    (tmp_path / "m.toml").write_text(text)
    motion = load_config(tmp_path / "m.toml").build().motion
    ax, ay = at_incidence(load_bundled(FIRST).trimmed(8.0), h2, 90.0)
    np.testing.assert_allclose(motion.accel, np.column_stack([ax.accel, ay.accel]),
                               rtol=1e-12, atol=1e-12)


PLANAR = ('[record]\nbundled = "el_centro"\n[[building]]\nmass = 2e5\nperiod = 0.5\n'
          '[[building]]\nmass = 3e5\nperiod = 1.0\n[contact]\nlaw = "kelvin-voigt"\n'
          'k = 9.3e8\ne = 0.65\ngap = 0.02\n')
ONE = ('[record]\nbundled = "el_centro"\n[[building]]\nplan = { width = 10.0, depth = 8.0 }\n'
       'masses = [2e5, 2e5]\nheight = 3.0\nelements = [\n'
       '  { x = 0.0, y = 4.0, direction = "y", stiffnesses = 1e8 },\n'
       '  { x = 10.0, y = 4.0, direction = "y", stiffnesses = [1e8, 1e8] },\n'
       '  { x = 5.0, y = 0.0, direction = "x", stiffnesses = 1e8 },\n'
       '  { x = 5.0, y = 8.0, direction = "x", stiffnesses = 1e8 },\n]\n')


@pytest.mark.parametrize("text, expected", [
    (PLANAR.replace('"el_centro"', f'"{FIRST}"\nsecond = "{SECOND}"', 1),
     f"record.second: a second horizontal component and its incidence are for a model with "
     f"buildings in plan (plan = {{ … }}); these buildings are planar, shaken along x by "
     f"the record alone (got second = '{SECOND}')"),
    (PLANAR.replace('"el_centro"', '"el_centro"\nincidence = 30.0', 1),
     "record.incidence: a second horizontal component and its incidence are for a model "
     "with buildings in plan"),
    (ONE.replace('"el_centro"', '"el_centro"\nsecond = "nope"', 1),
     "record.second: unknown bundled record 'nope'"),
    (ONE.replace('"el_centro"', f'"el_centro"\nsecond = "{SECOND}"\nsecond_file = "x.txt"',
                 1), "record.second_file: give second (bundled) or second_file, not both"),
    (ONE.replace('"el_centro"', '"el_centro"\nsecond_file = "missing.txt"', 1),
     "record.second_file: no such file"),
    (ONE.replace('"el_centro"', '"el_centro"\nincidence = "north"', 1),
     "record.incidence: must be a number (got 'north')"),
    (ONE[:ONE.index("elements = [")], "building[0].elements: required for a "
                                                     "building in plan"),
    (ONE.replace("masses = [2e5, 2e5]\n", ""), "building[0].masses: required for a building "
                                                 "in plan"),
    (ONE.replace("stiffnesses = [1e8, 1e8]", "stiffnesses = [1e8, 1e8, 1e8]"),
     "building[0].elements[1].stiffnesses: need 2 values, one per storey like masses, or one "
     "value for every storey (got 3: [100000000.0, 100000000.0, 100000000.0])"),
    (ONE.replace('direction = "y", stiffnesses = 1e8', 'direction = "z", stiffnesses = 1e8'),
     "building[0].elements[0].direction: must be \"x\", \"y\" or a number in [-360, 360] "
     "degrees (got 'z')"),
    (ONE.replace("stiffnesses = 1e8 },\n  { x = 10.0", "stiffnesses = -1e8 },\n  { x = 10.0"),
     "building[0].elements[0].stiffnesses: must be in [0, 1e+15] N/m (got -1e+08)"),
    (ONE.replace("depth = 8.0 }", "depth = 8.0, inertias = [1e6, 0.0] }"),
     "building[0].plan.inertias[1]: must be > 0 kg·m² (got 0)"),
    (ONE.replace("width = 10.0", "width = -10.0"),
     "building[0].plan.width: must be in (0, 10000] m (got -10)"),
    (ONE.replace("depth = 8.0 }", "depth = 8.0, inertias = [1e6, 1e6, 1e6] }"),
     "building[0].plan.inertias: need one value or 2, one a floor (got 3"),
    (ONE.replace("depth = 8.0 }", "depth = 8.0, mass_centres = [[5.0, 4.0]] }"),
     "building[0].plan.mass_centres: need one [x, y] for every floor or 2, one a floor"),
    (ONE.replace("height = 3.0", "heights = [3.0]"),
     "building[0].heights: need 2 values, one per floor like masses (got 1: [3.0])"),
    (ONE.replace("height = 3.0", 'height = 3.0\nstorey_law = { type = "bilinear", '
                                 'yield_force = 1e6 }'),
     "building[0].storey_law: not a key of a building in plan (a building in plan is "
     "linear)"),
    (ONE.replace("height = 3.0", "height = 3.0\nstiffnesses = [1e8, 1e8]"),
     "building[0].stiffnesses: not a key of a building in plan (each element of elements "
     "has its own stiffnesses)"),
    (ONE.replace('direction = "x"', 'direction = "y"'),
     "building[0].elements: they do not restrain floor 1 in x"),
    (PLANAR.replace("period = 0.5\n", 'period = 0.5\nelements = [{ x = 0.0, y = 0.0, '
                                      'direction = "x", stiffnesses = 1e8 }]\n', 1),
     "building[0].elements: only for a building in plan (plan = { width = …, depth = … } "
     "with elements = [ … ])"),
])
def test_bad_fields_are_one_line_naming_field_and_value(tmp_path, capsys, text,
                                                        expected) -> None:
    model = tmp_path / "model.toml"
    model.write_text(text)
    capsys.readouterr()
    code = main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith("error: ") and expected in err[0], err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.toml"]


def test_the_ground_panel_draws_both_components_labelled_x_and_y() -> None:
    """The bottom panel of a time-history figure: one line a component, legend x and y, each
    line's peak that component's (the display decimation keeps every peak)."""
    from pounding.plot.response import plot_displacements

    cfg = parse_config(__import__("tomllib").loads(_plan_text(
        f'[record]\nbundled = "{FIRST}"\nsecond = "{SECOND}"\nincidence = 60.0\n'
        'duration = 10.0\n')))
    model, motion, solver = cfg.build()
    r = simulate(model, motion, **solver)
    fig = plot_displacements(r)
    ground = fig.axes[len(model.buildings)]
    assert ground.get_ylabel() == "ground acc. [g]"
    assert [t.get_text() for t in ground.get_legend().get_texts()] == ["x", "y"]
    lines = [ln for ln in ground.get_lines() if ln.get_label() in ("x", "y")]
    for g, ln in enumerate(lines):
        assert np.abs(ln.get_ydata()).max() == np.abs(np.asarray(r.ground)[:, g]).max() / G
    title = ground.get_title(loc="left")
    assert title.startswith("ground acceleration, peak x ") and ", y " in title, title
