"""Buildings given as matrices in model files: the example, ``pounding run``, and bad fields
(one line naming the field and the value, exit status 2, nothing written)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import load_config
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import MatrixBuilding, ShearBuilding

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "integrate"))
from test_matrix_building import frame_matrices  # noqa: E402

K2 = np.array([[6.0e7, -2.0e7], [-2.0e7, 2.0e7]])
M2 = np.diag([2.0e5, 1.0e5])
TAIL = ('[[building]]\nmass = 3e5\nperiod = 0.6\nheight = 3.0\n'
        '[contact]\nlaw = "kelvin-voigt"\nk = 9.3e8\ne = 0.65\ngap = 0.01\n'
        '[solver]\nduration = 3.0\n')


def write_matrices(folder: Path, M: np.ndarray = M2, K: np.ndarray = K2) -> None:
    np.savetxt(folder / "m.csv", M, delimiter=",")
    np.savetxt(folder / "k.csv", K, delimiter=",")


def model_text(building: str) -> str:
    return '[record]\nbundled = "el_centro"\n[[building]]\nname = "mx"\n' + building + TAIL


MATRIX = 'matrices = { M = "m.csv", K = "k.csv" }\nelevations = [3.0, 6.0]\n'


def run_file(tmp_path: Path, text: str, capsys: pytest.CaptureFixture[str]
             ) -> tuple[int, list[str]]:
    model = tmp_path / "model.toml"
    model.write_text(text)
    capsys.readouterr()
    code = main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"])
    return code, capsys.readouterr().err.strip().splitlines()


# ------------------------------------------------------------------ the example
def test_the_example_matrices_are_the_frame_they_say():
    K = np.loadtxt(ROOT / "examples" / "matrix_building_K.csv", delimiter=",")
    M = np.loadtxt(ROOT / "examples" / "matrix_building_M.csv", delimiter=",")
    kc, _ = frame_matrices(10, 3.2, 6.0, 7.8e9, 3.9e9)
    # the file holds kc to 17 significant digits, but kc is condensed through LAPACK
    # (np.linalg.solve), whose last bit depends on the BLAS kernel the machine picks
    # (OPENBLAS_CORETYPE=SkylakeX vs Haswell: 4e-16): equal to round-off, not bit for bit
    np.testing.assert_allclose(K, kc, rtol=1e-13, atol=1e-13 * np.abs(kc).max())
    np.testing.assert_array_equal(M, np.diag(np.full(10, 6e5)))
    model, _, _ = load_config(ROOT / "examples" / "matrix_building.toml").build()
    frame, shear = model.buildings
    assert isinstance(frame, MatrixBuilding) and isinstance(shear, ShearBuilding)
    assert not frame.is_shear_building()
    assert frame.fundamental_period == pytest.approx(1.149, abs=1e-3)


def test_pounding_run_on_a_building_given_as_npz(tmp_path, capsys):
    """M, K and C in one archive, labels and floors named, through the command line: the
    same run as the API's, and every output written."""
    sb = ShearBuilding.uniform(2, 2e5, 4e7, 3.0)
    np.savez(tmp_path / "b.npz", M=sb.mass_matrix(), K=sb.stiffness_matrix(),
             C=sb.damping_matrix())
    text = model_text('npz = "b.npz"\nelevations = [3.0, 6.0]\nlabels = ["low", "roof"]\n'
                      'floors = ["low", "roof"]\n')
    model = tmp_path / "model.toml"
    model.write_text(text)
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(tmp_path / "out")]) == 0
    out = tmp_path / "out"
    assert {"summary.json", "timehistories.nc", "impacts.csv", "envelopes.png"} <= {
        p.name for p in out.iterdir()}
    s = json.loads((out / "summary.json").read_text())
    b1 = s["buildings"][0]
    assert b1["given_as"] == "matrices" and [r["label"] for r in b1["storeys"]] == ["low", "roof"]
    assert b1["storeys"][0]["peak_storey_shear_N"] is None  # no storey stiffness in K
    assert s["buildings"][1]["storeys"][0]["peak_storey_shear_N"] > 0
    # the API run of the same model
    api = PoundingModel([MatrixBuilding(M=sb.mass_matrix(), K=sb.stiffness_matrix(),
                                        C=sb.damping_matrix(), labels=["low", "roof"],
                                        elevations=[3.0, 6.0], name="mx"),
                         ShearBuilding.sdof(3e5, period=0.6, height=3.0)], [0.01],
                        load_config(model).build().model.contact)
    from pounding.ground_motion import el_centro

    r = simulate(api, el_centro(), duration=3.0)
    assert s["n_impacts"] == r.n_impacts > 0
    assert s["peak_contact_force_N"] == pytest.approx(float(r.peak_contact_force.max()),
                                                      rel=1e-12)
    # the model.toml a run writes names the archive in full and runs from anywhere
    copy = load_config(out / "model.toml")
    assert Path(copy.building[0].npz).is_absolute()  # type: ignore[arg-type]
    # the NetCDF file names the building's own labels; its storey shear is NaN
    import xarray as xr

    with xr.open_dataset(out / "timehistories.nc", engine="h5netcdf") as ds:
        assert list(ds["dof_name"].values) == ["low", "roof", "F1"]
        assert np.isnan(ds["storey_shear"].values[:, :2]).all()
        assert np.isfinite(ds["storey_shear"].values[:, 2]).all()
        np.testing.assert_allclose(ds["storey_height"].values, [3.0, 3.0, 3.0])
    # and the report reads the folder
    assert main(["report", str(out), "--html", str(tmp_path / "report.html")]) == 0
    assert (tmp_path / "report.html").stat().st_size > 10_000


# ------------------------------------------------------------------ bad fields
@pytest.mark.parametrize("building, expected", [
    ('matrices = { M = "m.csv", K = "nope.csv" }\nelevations = [3.0, 6.0]\n',
     "building[0].matrices.K: no such file"),
    ('matrices = { M = "m.csv", K = "k.csv" }\n', "building[0].elevations: required for a "
                                                  "building given as matrices"),
    (MATRIX.replace("[3.0, 6.0]", "[3.0, 6.0, 9.0]"),
     "building[0]: building 'mx': elevations has 3 values but the matrices have 2 degrees"),
    (MATRIX + 'labels = ["a"]\n', "building[0].labels: need 2 values, one per degree of "
                                   "freedom like elevations (got 1: ['a'])"),
    (MATRIX + 'floors = ["F1", "F9"]\n', "building[0].floors[1]: must be one of the labels "
                                         "(F1, F2) or an index in [0, 1] (got 'F9')"),
    (MATRIX + 'r = [1.0, 0.0, 1.0]\n', "r has 3 values but the matrices have 2"),
    (MATRIX + 'storey_law = { type = "bilinear", yield_force = 1e6 }\n',
     "building[0].storey_law: not a key of a building given as matrices (a matrix building "
     "is linear"),
    (MATRIX + 'mass = 2e5\n', "building[0].mass: not a key of a building given as matrices "
                              "(got 200000)"),
    (MATRIX + 'npz = "b.npz"\n', "building[0].npz: give matrices or npz, not both"),
    ('matrices = { M = "m.csv", K = "k.csv", C = "k.csv" }\nelevations = [3.0, 6.0]\n'
     'damping = { ratio = 0.05 }\n', "building[0].damping: give a damping matrix (matrices.C) "
                                     "or damping, not both"),
    (MATRIX.replace("[3.0, 6.0]", "[3.0, 3.0]"),
     "building[0].elevations[1]: must be above elevations[0] = 3 m: each floor its own "
     "elevation, the lowest first (got 3)"),
    ('n_storeys = 2\nmass = 2e5\nstiffness = 4e7\nelevations = [3.0, 6.0]\n',
     "building[0].elevations: only for a building given as matrices"),
])
def test_bad_matrix_building_fields_are_named(tmp_path, capsys, building, expected):
    write_matrices(tmp_path)
    code, err = run_file(tmp_path, model_text(building), capsys)
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith("error: ") and expected in err[0], err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("M, K, expected", [
    (np.array([[2e5, 1e3], [1e3, 1e5]]), K2,
     "M must be diagonal (lumped floor masses); got off-diagonal entry M[0,1] = 1000; "
     "the time stepper takes lumped masses"),
    (M2, K2 + np.array([[0.0, 1e6], [0.0, 0.0]]), "K must be symmetric: K[0,1] = -19000000 "
                                                  "but K[1,0] = -20000000"),
    (M2, -K2, "K must be positive definite"),
])
def test_bad_matrices_are_named_with_their_file(tmp_path, capsys, M, K, expected):
    write_matrices(tmp_path, M, K)
    code, err = run_file(tmp_path, model_text(MATRIX), capsys)
    assert code == 2 and len(err) == 1, err
    # "error: <model file>: building[0]: <matrix file>: …" (long paths shortened)
    assert err[0].startswith("error: ") and "building[0]: " in err[0], err
    assert expected in err[0], err
    assert not (tmp_path / "out").exists()
