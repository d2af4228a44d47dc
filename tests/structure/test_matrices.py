"""Buildings given as matrices: readers, validation, modes, and the way back to ShearBuilding.

Checked against hand-written arrays (every file is written here, by hand, to tmp_path),
closed forms (the 2-DOF generalised eigenproblem solved by the quadratic formula; Chopra's
two-storey frame) and ShearBuilding's own matrices.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import scipy.io
import scipy.sparse

from pounding.hysteresis import Bilinear
from pounding.structure import ModalDamping, RayleighDamping, ShearBuilding
from pounding.structure.matrices import MatrixBuilding
from pounding.structure.matrix_checks import check_matrix, lumped_masses
from pounding.structure.matrix_files import read_matrix, read_matrix_building

K3 = np.array([[5.0e7, -2.0e7, 0.0],
               [-2.0e7, 3.0e7, -1.0e7],
               [0.0, -1.0e7, 1.0e7]])          # shear building k = 3e7, 2e7, 1e7
M3 = np.diag([3.0e5, 2.0e5, 1.0e5])
LABELS3 = ("F1", "F2", "F3")
Z3 = [4.0, 7.0, 10.0]


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def _building(**kw: object) -> MatrixBuilding:
    args: dict[str, object] = {"M": M3, "K": K3, "labels": LABELS3, "elevations": Z3}
    args.update(kw)
    return MatrixBuilding(**args)  # type: ignore[arg-type]


# --------------------------------------------------------------------------- text files
def test_csv_comma_separated(tmp_path: Path) -> None:
    p = _write(tmp_path / "k.csv", "5e7,-2e7,0\n-2e7,3e7,-1e7\n0,-1e7,1e7\n")
    np.testing.assert_array_equal(read_matrix(p, "K"), K3)


def test_csv_whitespace_comments_blank_lines_bom_and_spaces_after_commas(tmp_path: Path) -> None:
    p = tmp_path / "k.txt"
    p.write_bytes("\ufeff# stiffness [N/m]\n\n 5e7  -2e7\t0   \n-2e7 3e7 -1e7  # row 2\n\n"
                  "0 -1e7 1e7\n".encode())
    np.testing.assert_array_equal(read_matrix(p, "K"), K3)
    q = _write(tmp_path / "m.dat", "3e5, 0, 0\n0, 2e5, 0\n0, 0, 1e5\n")
    np.testing.assert_array_equal(read_matrix(q, "M"), M3)


def test_csv_one_by_one(tmp_path: Path) -> None:
    np.testing.assert_array_equal(read_matrix(_write(tmp_path / "k.csv", "7.5\n"), "K"), [[7.5]])


@pytest.mark.parametrize("text, message", [
    ("1,2\n3,x\n", r"k\.csv: line 2: item 2 of 2 on the line is not a number \(the file must hold "
                    r"plain numbers"),
    ("a,b\n1,2\n2,1\n", r"k\.csv: line 1: item 1 of 2 on the line is not a number"),
    ("1,,2\n", r"k\.csv: line 1 has an empty field between commas"),
    ("1,2\n", r"k\.csv: K must be square \(got 1×2\)"),
    ("1 2\n3\n", r"k\.csv: line 2 has 1 numbers but line 1 has 2: every row of a matrix"),
    ("# nothing\n\n", r"k\.csv: holds no numbers"),
    ("", r"k\.csv: holds no numbers"),
    ("1,2\n2,nan\n", r"k\.csv: K\[1,1\] = nan is not finite"),
    ("1,2\n2,inf\n", r"k\.csv: K\[1,1\] = inf is not finite"),
    ("1;2\n2;1\n", r"k\.csv: line 1: the line is not a number"),
])
def test_csv_errors_name_file_and_line(tmp_path: Path, text: str, message: str) -> None:
    p = _write(tmp_path / "k.csv", text)
    with pytest.raises(ValueError, match=message) as err:
        read_matrix(p, "K")
    assert "\n" not in str(err.value)


def test_csv_that_is_not_text(tmp_path: Path) -> None:
    p = tmp_path / "k.csv"
    p.write_bytes(b"\xff\xfe\x00\x81\x9f")
    with pytest.raises(ValueError, match=r"k\.csv: not a text file"):
        read_matrix(p, "K")


def test_missing_file_and_unknown_suffix(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"nope\.csv: no such file"):
        read_matrix(tmp_path / "nope.csv")
    p = _write(tmp_path / "k.xlsx", "1")
    with pytest.raises(ValueError, match=r"k\.xlsx: unknown matrix file type '\.xlsx'; read are "
                                         r"\.csv, \.txt, \.dat, \.npy, \.npz, \.mtx"):
        read_matrix(p)


# --------------------------------------------------------------------------- numpy files
def test_npy(tmp_path: Path) -> None:
    np.save(tmp_path / "k.npy", K3)
    np.testing.assert_array_equal(read_matrix(tmp_path / "k.npy", "K"), K3)
    np.save(tmp_path / "ki.npy", np.array([[2, -1], [-1, 1]], dtype=np.int32))
    got = read_matrix(tmp_path / "ki.npy", "K")
    assert got.dtype == np.float64
    np.testing.assert_array_equal(got, [[2.0, -1.0], [-1.0, 1.0]])


@pytest.mark.parametrize("array, message", [
    (np.ones(3), r"K must be a 2-D matrix \(got 3\)"),
    (np.array(5.0), r"K must be a 2-D matrix \(got a scalar\)"),
    (np.ones((2, 2, 2)), r"K must be a 2-D matrix \(got 2×2×2\)"),
    (np.zeros((0, 0)), r"K is empty \(0×0\)"),
    (np.eye(2, dtype=complex), r"the array holds complex128 values; expected real numbers"),
    (np.eye(2, dtype=bool), r"the array holds bool values; expected real numbers"),
])
def test_npy_errors(tmp_path: Path, array: np.ndarray, message: str) -> None:
    np.save(tmp_path / "k.npy", array)
    with pytest.raises(ValueError, match=r"k\.npy: " + message):
        read_matrix(tmp_path / "k.npy", "K")


def test_npy_that_is_not_npy(tmp_path: Path) -> None:
    p = _write(tmp_path / "k.npy", "1,2\n2,1\n")
    with pytest.raises(ValueError, match=r"k\.npy: not a NumPy \.npy file"):
        read_matrix(p, "K")
    np.savez(tmp_path / "a.npz", K=K3)
    (tmp_path / "a.npz").rename(tmp_path / "b.npy")
    with pytest.raises(ValueError, match=r"b\.npy: is an \.npz archive, not an \.npy array"):
        read_matrix(tmp_path / "b.npy", "K")
    np.save(tmp_path / "o.npy", np.array([[None]], dtype=object), allow_pickle=True)
    with pytest.raises(ValueError, match=r"o\.npy: not a NumPy \.npy file"):
        read_matrix(tmp_path / "o.npy", "K")


def test_npz_building_with_and_without_c(tmp_path: Path) -> None:
    C = 0.01 * K3 + 0.2 * M3
    np.savez(tmp_path / "b.npz", M=M3, K=K3, C=C)
    b = read_matrix_building(tmp_path / "b.npz", labels=LABELS3, elevations=Z3, name="B")
    np.testing.assert_array_equal(b.mass_matrix(), M3)
    np.testing.assert_array_equal(b.stiffness_matrix(), K3)
    np.testing.assert_array_equal(b.damping_matrix(), C)
    assert b.damping is None and b.C is not None
    assert dict(b.sources) == {"M": str(tmp_path / "b.npz"), "K": str(tmp_path / "b.npz"),
                               "C": str(tmp_path / "b.npz")}
    np.savez(tmp_path / "d.npz", M=M3, K=K3)
    d = read_matrix_building(tmp_path / "d.npz", labels=LABELS3, elevations=Z3)
    assert d.damping == RayleighDamping() and d.C is None
    with pytest.raises(ValueError, match=r"b\.npz: holds a damping matrix C and a damping model "
                                         r"was given too; give one"):
        read_matrix_building(tmp_path / "b.npz", labels=LABELS3, elevations=Z3,
                             damping=ModalDamping(0.05))


def test_npz_c_read_when_k_comes_from_another_file(tmp_path: Path) -> None:
    C = 0.01 * K3
    np.savez(tmp_path / "mc.npz", M=M3, C=C)
    np.save(tmp_path / "k.npy", K3)
    b = read_matrix_building(tmp_path / "mc.npz", tmp_path / "k.npy", labels=LABELS3,
                             elevations=Z3)
    np.testing.assert_array_equal(b.damping_matrix(), C)
    assert b.sources["K"] == str(tmp_path / "k.npy") and b.sources["C"] == str(tmp_path / "mc.npz")


def test_npz_missing_array_and_wrong_kind(tmp_path: Path) -> None:
    np.savez(tmp_path / "b.npz", M=M3, C=M3)
    with pytest.raises(ValueError, match=r"b\.npz: has no array 'K' \(it holds M, C\); a "
                                         r"building's \.npz holds M, K and optionally C"):
        read_matrix_building(tmp_path / "b.npz", labels=LABELS3, elevations=Z3)
    np.save(tmp_path / "single.npy", K3)
    (tmp_path / "single.npy").rename(tmp_path / "single.npz")
    with pytest.raises(ValueError, match=r"single\.npz: is a single \.npy array, not an \.npz"):
        read_matrix(tmp_path / "single.npz", "K")
    _write(tmp_path / "junk.npz", "not a zip")
    with pytest.raises(ValueError, match=r"junk\.npz: not a NumPy \.npz archive"):
        read_matrix(tmp_path / "junk.npz", "K")


# --------------------------------------------------------------------------- matrix market
def test_mtx_symmetric_coordinate_by_hand(tmp_path: Path) -> None:
    """Symmetric storage keeps the lower triangle; the reader must return the full matrix."""
    p = _write(tmp_path / "k.mtx",
               "%%MatrixMarket matrix coordinate real symmetric\n% K of a 3-storey frame\n"
               "3 3 5\n1 1 5e7\n2 1 -2e7\n2 2 3e7\n3 2 -1e7\n3 3 1e7\n")
    np.testing.assert_array_equal(read_matrix(p, "K"), K3)


def test_mtx_general_array_by_hand_and_integer_field(tmp_path: Path) -> None:
    p = _write(tmp_path / "m.mtx", "%%MatrixMarket matrix array real general\n2 2\n"
                                   "3e5\n0\n0\n1e5\n")        # column-major
    np.testing.assert_array_equal(read_matrix(p, "M"), np.diag([3e5, 1e5]))
    q = _write(tmp_path / "i.mtx", "%%MatrixMarket matrix coordinate integer general\n2 2 2\n"
                                   "1 1 4\n2 2 9\n")
    np.testing.assert_array_equal(read_matrix(q, "M"), np.diag([4.0, 9.0]))


def test_mtx_written_by_scipy_dense_and_sparse(tmp_path: Path) -> None:
    scipy.io.mmwrite(tmp_path / "dense.mtx", K3)
    scipy.io.mmwrite(tmp_path / "sparse.mtx", scipy.sparse.coo_matrix(K3))
    for name in ("dense.mtx", "sparse.mtx"):
        np.testing.assert_array_equal(read_matrix(tmp_path / name, "K"), K3)


@pytest.mark.parametrize("text, message", [
    ("%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1.0 2.0\n",
     r"Matrix Market field is 'complex'; expected real or integer"),
    ("%%MatrixMarket matrix coordinate pattern general\n2 2 2\n1 1\n2 2\n",
     r"Matrix Market field is 'pattern'; expected real or integer"),
    ("1 2\n3 4\n", r"not a Matrix Market file"),
    ("%%MatrixMarket matrix coordinate real general\n2 3 1\n1 1 1.0\n",
     r"K must be square \(got 2×3\)"),
])
def test_mtx_errors(tmp_path: Path, text: str, message: str) -> None:
    p = _write(tmp_path / "k.mtx", text)
    with pytest.raises(ValueError, match=r"k\.mtx: " + message):
        read_matrix(p, "K")


# --------------------------------------------------------------------------- validation
def test_symmetry_reports_the_worst_entry(tmp_path: Path) -> None:
    K = K3.copy()
    K[0, 1] = -2.0e7 + 1.0            # off by 1: 2e-8 of the largest entry
    K[2, 1] = -1.0e7 + 50.0           # off by 50: the worst
    np.savetxt(tmp_path / "k.csv", K, delimiter=",")
    with pytest.raises(ValueError, match=r"k\.csv: K must be symmetric: K\[1,2\] = -10000000 "
                                         r"but K\[2,1\] = -9999950 \(difference 50 > 1e-10 × "
                                         r"largest entry 5e\+07\)"):
        read_matrix(tmp_path / "k.csv", "K")


def test_symmetry_within_tolerance_is_symmetrised() -> None:
    K = K3.copy()
    K[0, 1] += 1.0e-4                 # 2e-12 of the largest entry
    got = check_matrix(K, "K")
    np.testing.assert_array_equal(got, got.T)
    assert got[0, 1] == pytest.approx(-2.0e7 + 0.5e-4, rel=1e-15)


@pytest.mark.parametrize("files, message", [
    ({"M": "2x2", "K": "3x3"}, r"k\.csv: K is 3×3 but M \(from \S*m\.csv\) is 2×2; they must be "
                               r"the same size"),
    ({"M": "3x3", "K": "3x3", "C": "2x2"}, r"c\.csv: C is 2×2 but M \(from \S*m\.csv\) is 3×3"),
])
def test_sizes_must_agree_between_files(tmp_path: Path, files: dict[str, str],
                                        message: str) -> None:
    mats = {"2x2": np.diag([1.0, 2.0]), "3x3": np.diag([1.0, 2.0, 3.0])}
    paths = {}
    for key, size in files.items():
        paths[key] = tmp_path / f"{key.lower()}.csv"
        np.savetxt(paths[key], mats[size] if key != "K" else K3, delimiter=",")
    with pytest.raises(ValueError, match=message):
        read_matrix_building(paths["M"], paths["K"], paths.get("C"), labels=LABELS3,
                             elevations=Z3)


def test_k_file_needed_unless_npz(tmp_path: Path) -> None:
    np.savetxt(tmp_path / "m.csv", M3, delimiter=",")
    with pytest.raises(ValueError, match=r"m\.csv: give K's file too \(only an \.npz archive "
                                         r"holds both\)"):
        read_matrix_building(tmp_path / "m.csv", labels=LABELS3, elevations=Z3)


@pytest.mark.parametrize("kw, message", [
    ({"labels": ("F1", "F2")}, r"labels has 2 entries but the matrices have 3 degrees of "
                                r"freedom"),
    ({"labels": "F1F2F3"}, r"labels must be a sequence of strings"),
    ({"labels": ("F1", "F1", "F3")}, r"labels\[1\] = 'F1' repeats labels\[0\]"),
    ({"labels": ("F1", " ", "F3")}, r"labels\[1\] must be a non-empty string"),
    ({"labels": ("F1", 2, "F3")}, r"labels\[1\] must be a non-empty string \(got 2\)"),
    ({"elevations": [4.0, 7.0]}, r"elevations has 2 values but the matrices have 3 degrees"),
    ({"elevations": [4.0, math.nan, 10.0]}, r"elevations\[1\] = nan is not finite"),
    ({"elevations": [[4.0, 7.0, 10.0]]}, r"elevations must be one-dimensional"),
    ({"r": [1.0, 1.0]}, r"r has 2 values but the matrices have 3 degrees of freedom"),
    ({"r": [0.0, 0.0, 0.0]}, r"r is all zero: the ground motion would not move the building"),
    ({"r": ["a", 1, 1]}, r"r must be numbers, one per degree of freedom"),
    ({"name": 3}, r"name must be a string"),
])
def test_labels_elevations_r_are_checked(kw: dict[str, object], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        _building(**kw)


def test_messages_name_the_building_when_not_from_files() -> None:
    with pytest.raises(ValueError, match=r"^building 'A': labels has 2 entries"):
        _building(labels=("a", "b"), name="A")
    with pytest.raises(ValueError, match=r"^matrix building: K is 2×2 but M is 3×3"):
        _building(K=np.eye(2))


@pytest.mark.parametrize("K, lam", [
    (np.array([[1.0e7, -1.0e7], [-1.0e7, 1.0e7]]), r"(?:-?\d(?:\.\d+)?e-\d\d|-?0)"),  # free-free: 0
    (np.diag([1.0e7, -2.0e6]), r"-2e\+06"),
])
def test_k_must_be_positive_definite(tmp_path: Path, K: np.ndarray, lam: str) -> None:
    np.savetxt(tmp_path / "k.csv", K, delimiter=",")
    np.savetxt(tmp_path / "m.csv", np.diag([1.0, 1.0]), delimiter=",")
    with pytest.raises(ValueError, match=r"k\.csv: K must be positive definite \(the building "
                                         r"must be restrained against the ground, with no "
                                         r"mechanism\); its smallest eigenvalue is " + lam
                                         + "$"):
        read_matrix_building(tmp_path / "m.csv", tmp_path / "k.csv", labels=("a", "b"),
                             elevations=[3.0, 6.0])


def test_m_must_be_positive_definite(tmp_path: Path) -> None:
    np.savetxt(tmp_path / "m.csv", np.diag([1.0e5, 0.0, 2.0e5]), delimiter=",")
    np.savetxt(tmp_path / "k.csv", K3, delimiter=",")
    with pytest.raises(ValueError, match=r"m\.csv: M\[1,1\] = 0 must be > 0: every degree of "
                                         r"freedom needs a positive mass"):
        read_matrix_building(tmp_path / "m.csv", tmp_path / "k.csv", labels=LABELS3,
                             elevations=Z3)
    M = np.array([[1.0, 2.0, 0.0], [2.0, 1.0, 0.0], [0.0, 0.0, 1.0]])   # eigenvalues -1, 1, 3
    with pytest.raises(ValueError, match=r"^matrix building: M must be positive definite "
                                         r"\(every degree of freedom needs mass; .*\); its "
                                         r"smallest eigenvalue is -1$"):
        _building(M=M)


def test_damping_matrix_checks() -> None:
    C = 0.02 * K3
    b = _building(C=C)
    np.testing.assert_array_equal(b.damping_matrix(), C)
    with pytest.raises(ValueError, match=r"C must be positive semi-definite \(damping cannot add "
                                         r"energy\); its smallest eigenvalue is -1000"):
        _building(C=np.diag([1.0e3, -1.0e3, 1.0e3]))
    with pytest.raises(ValueError, match=r"give a damping matrix C or a damping model, not both"):
        _building(C=C, damping=RayleighDamping())
    with pytest.raises(ValueError, match=r"C must be symmetric"):
        _building(C=np.triu(C))
    with pytest.raises(ValueError, match=r"damping must be a DampingModel"):
        _building(damping="rayleigh")
    with pytest.raises(ValueError, match=r"mode_j must be <= the number of modes, 3"):
        _building(damping=RayleighDamping(0.05, mode_j=4))


def test_c_from_file_named_in_errors(tmp_path: Path) -> None:
    np.savetxt(tmp_path / "m.csv", M3, delimiter=",")
    np.savetxt(tmp_path / "k.csv", K3, delimiter=",")
    np.savetxt(tmp_path / "c.csv", -np.eye(3), delimiter=",")
    with pytest.raises(ValueError, match=r"^.*c\.csv: C must be positive semi-definite"):
        read_matrix_building(tmp_path / "m.csv", tmp_path / "k.csv", tmp_path / "c.csv",
                             labels=LABELS3, elevations=Z3)


def test_lumped_masses() -> None:
    np.testing.assert_array_equal(lumped_masses(M3), [3.0e5, 2.0e5, 1.0e5])
    M = M3.copy()
    M[0, 2] = M[2, 0] = 1.5e3
    M[0, 1] = M[1, 0] = 2.0e2
    with pytest.raises(ValueError, match=r"^m\.csv: M must be diagonal \(lumped floor masses\); "
                                         r"got off-diagonal entry M\[0,2\] = 1500$"):
        lumped_masses(M, "m.csv")
    tiny = M3.copy()
    tiny[0, 1] = tiny[1, 0] = 1.0e-8          # 3e-14 of the largest mass: taken as zero
    np.testing.assert_array_equal(lumped_masses(tiny), [3.0e5, 2.0e5, 1.0e5])
    with pytest.raises(ValueError, match=r"M\[1,1\] = -1 must be > 0"):
        lumped_masses(np.diag([1.0, -1.0]))
    b = _building(M=M)
    assert not b.is_lumped
    with pytest.raises(ValueError, match=r"matrix building: M must be diagonal"):
        b.lumped_masses()
    assert _building().is_lumped


# --------------------------------------------------------------------------- modes
@pytest.mark.parametrize("M, K", [
    (np.diag([2.0e5, 1.0e5]), np.array([[6.0e7, -2.5e7], [-2.5e7, 4.0e7]])),
    (np.array([[3.0, 0.4], [0.4, 2.0]]), np.array([[9.0, 1.5], [1.5, 4.0]])),
])
def test_two_dof_eigenvalues_by_the_quadratic_formula(M: np.ndarray, K: np.ndarray) -> None:
    """det(K − λM) = 0 ⇔ (m11 m22 − m12²) λ² − (k11 m22 + k22 m11 − 2 k12 m12) λ
    + (k11 k22 − k12²) = 0."""
    a = M[0, 0] * M[1, 1] - M[0, 1] ** 2
    b = -(K[0, 0] * M[1, 1] + K[1, 1] * M[0, 0] - 2 * K[0, 1] * M[0, 1])
    c = K[0, 0] * K[1, 1] - K[0, 1] ** 2
    disc = math.sqrt(b * b - 4 * a * c)
    lam = sorted([(-b - disc) / (2 * a), (-b + disc) / (2 * a)])
    r = MatrixBuilding(M=M, K=K, labels=["x1", "x2"], elevations=[3.0, 6.0]).modes()
    np.testing.assert_allclose(r.omegas**2, lam, rtol=1e-12)
    np.testing.assert_allclose(r.periods, [2 * math.pi / math.sqrt(x) for x in lam], rtol=1e-12)
    np.testing.assert_allclose(r.shapes.T @ M @ r.shapes, np.eye(2), atol=1e-12)
    np.testing.assert_allclose(K @ r.shapes, M @ r.shapes * r.omegas**2, rtol=1e-10, atol=1e-12)


def test_chopra_two_storey_frame() -> None:
    m, k = 1.0e5, 5.0e7
    b = MatrixBuilding(M=np.diag([2 * m, m]), K=[[3 * k, -k], [-k, k]], labels=["F1", "F2"],
                       elevations=[3.0, 6.0])
    r = b.modes()
    np.testing.assert_allclose(r.omegas**2, [k / (2 * m), 2 * k / m], rtol=1e-12)
    np.testing.assert_allclose(r.effective_masses, [8 * m / 3, m / 3], rtol=1e-12)
    assert b.fundamental_period == pytest.approx(2 * math.pi / math.sqrt(k / (2 * m)), rel=1e-12)


def test_default_damping_is_rayleigh_five_percent_at_modes_one_and_two() -> None:
    r = _building().modes()
    np.testing.assert_allclose(r.damping_ratios[:2], [0.05, 0.05], rtol=1e-10)
    assert r.damping_ratios[2] > 0.05


def test_influence_vector_enters_participation() -> None:
    r = np.array([1.0, 0.5, 0.0])
    got = _building(r=r).modes()
    np.testing.assert_allclose(got.modal_contributions.sum(axis=1), r, atol=1e-12)


# --------------------------------------------------------------------------- shear building
SHEAR_BUILDINGS = [
    ShearBuilding(masses=[3.0e5, 2.5e5, 2.0e5], stiffnesses=[4.0e8, 3.0e8, 2.0e8],
                  heights=[4.0, 3.0, 3.0], name="A"),
    ShearBuilding.uniform(8, mass=2.0e5, stiffness=3.0e8, height=3.2,
                          damping=RayleighDamping(0.05, 0.03, mode_i=1, mode_j=3), name="tower"),
    ShearBuilding.sdof(2.0e5, period=0.5),
    ShearBuilding(masses=[1.234567e5, 9.87654e4], stiffnesses=[1.1e8, 7.7e7], heights=[3.3, 2.9],
                  damping=ModalDamping(0.02)),
]


@pytest.mark.parametrize("sb", SHEAR_BUILDINGS, ids=lambda b: f"n{b.n}")
def test_round_trip_to_shear_building(sb: ShearBuilding) -> None:
    mb = MatrixBuilding.from_shear_building(sb)
    assert mb.is_shear_building() and mb.shear_building_mismatch() is None
    back = mb.to_shear_building()
    for got, want in ((back.mass_matrix(), sb.mass_matrix()),
                      (back.stiffness_matrix(), sb.stiffness_matrix()),
                      (back.damping_matrix(), sb.damping_matrix())):
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * np.abs(want).max())
    np.testing.assert_allclose(back.heights, sb.heights, rtol=1e-12)
    np.testing.assert_allclose(back.stiffnesses, sb.stiffnesses, rtol=1e-12)
    assert back.damping == sb.damping and back.name == sb.name
    np.testing.assert_allclose(mb.damping_matrix(), sb.damping_matrix(), rtol=1e-12,
                               atol=1e-12 * np.abs(sb.damping_matrix()).max())
    np.testing.assert_allclose(mb.modes().periods, sb.modes().periods, rtol=1e-12)
    assert mb.labels == tuple(f"F{j}" for j in range(1, sb.n + 1))


def test_round_trip_through_csv_files(tmp_path: Path) -> None:
    sb = SHEAR_BUILDINGS[0]
    np.savetxt(tmp_path / "m.csv", sb.mass_matrix(), delimiter=",", fmt="%.17g")
    np.savetxt(tmp_path / "k.txt", sb.stiffness_matrix(), fmt="%.17g")
    mb = read_matrix_building(tmp_path / "m.csv", tmp_path / "k.txt", labels=LABELS3,
                              elevations=sb.floor_levels, damping=sb.damping, name="A")
    back = mb.to_shear_building()
    np.testing.assert_allclose(back.stiffness_matrix(), sb.stiffness_matrix(), rtol=1e-12)
    np.testing.assert_allclose(back.mass_matrix(), sb.mass_matrix(), rtol=1e-12)
    np.testing.assert_allclose(back.heights, sb.heights, rtol=1e-12)


def test_storey_stiffnesses_by_hand() -> None:
    np.testing.assert_array_equal(_building().storey_stiffnesses(), [3.0e7, 2.0e7, 1.0e7])
    one = MatrixBuilding(M=[[5.0]], K=[[7.0]], labels=["F1"], elevations=[3.0])
    np.testing.assert_array_equal(one.storey_stiffnesses(), [7.0])


def _k_with(i: int, j: int, v: float) -> np.ndarray:
    K = K3.copy()
    K[i, j] = K[j, i] = v
    return K


@pytest.mark.parametrize("kw, why", [
    ({"M": np.array([[3e5, 1e3, 0], [1e3, 2e5, 0], [0, 0, 1e5]])},
     "M is not diagonal (lumped floor masses)"),
    ({"r": [1.0, 1.0, 0.5]}, "r is not all ones"),
    ({"elevations": [4.0, 4.0, 10.0]}, "elevations do not rise strictly"),
    ({"elevations": [0.0, 3.0, 6.0]}, "elevations do not rise strictly from above the ground"),
    ({"K": _k_with(0, 2, -1.0e6)}, "K is not tridiagonal: K[0,2] = -1e+06"),
    ({"K": np.array([[5e7, 2e7, 0], [2e7, 3e7, -1e7], [0, -1e7, 1e7]])},
     "K[0,1] = 2e+07 is not negative"),
    ({"K": K3 + np.diag([0.0, 1.0e6, 0.0])}, "row 1 of K sums to 1e+06, not 0"),
    ({"K": K3 + np.diag([0.0, 0.0, 2.0e6])}, "row 2 of K sums to 2e+06, not 0"),
])
def test_not_a_shear_building_says_why(kw: dict[str, object], why: str) -> None:
    b = _building(**kw)
    assert not b.is_shear_building()
    mismatch = b.shear_building_mismatch()
    assert mismatch is not None and mismatch.startswith(why)
    with pytest.raises(ValueError, match=r"is not a shear building: " + why.replace("(", r"\(")
                       .replace(")", r"\)").replace("[", r"\[").replace("]", r"\]")
                       .replace("+", r"\+")):
        b.to_shear_building()


def test_to_shear_building_damping_and_storey_law() -> None:
    b = _building(C=0.01 * K3)
    with pytest.raises(ValueError, match=r"was given a damping matrix C; a ShearBuilding takes "
                                         r"a damping model: pass damping=\.\.\."):
        b.to_shear_building()
    sb = b.to_shear_building(damping=ModalDamping(0.03))
    assert sb.damping == ModalDamping(0.03)
    law = Bilinear(yield_drift=0.01, hardening=0.05)
    yielding = _building().to_shear_building(storey_law=law)
    assert yielding.storey_law == law
    with pytest.raises(ValueError, match=r"has a storey law; a matrix building is linear"):
        MatrixBuilding.from_shear_building(yielding)


# --------------------------------------------------------------------------- value semantics
def test_arrays_read_only_and_copies_handed_out() -> None:
    b = _building()
    with pytest.raises(ValueError):
        b.M[0, 0] = 1.0
    with pytest.raises(ValueError):
        b.elevations[0] = 1.0
    K = b.stiffness_matrix()
    K[0, 0] = -1.0
    assert b.stiffness_matrix()[0, 0] == 5.0e7
    for A in (b.mass_matrix(), b.stiffness_matrix(), b.damping_matrix()):
        assert A.dtype == np.float64 and A.flags.c_contiguous and A.flags.writeable
    np.testing.assert_array_equal(b.influence_vector(), np.ones(3))
    assert b.n == 3 and b.labels == LABELS3


def test_equality() -> None:
    assert _building() == _building()
    assert _building() != _building(name="other")
    assert _building(C=0.01 * K3) == _building(C=0.01 * K3)
    assert _building(C=0.01 * K3) != _building()
    assert _building().__eq__(3) is NotImplemented


# ------------------------------------------------------------------ sizes declared by a header
def _npy_header_only(path: Path, shape: tuple[int, ...]) -> Path:
    """An .npy file whose header declares ``shape`` (float64) and that holds no data."""
    from numpy.lib import format as npy_format

    with path.open("wb") as f:
        npy_format.write_array_header_1_0(f, {"descr": "<f8", "fortran_order": False,
                                              "shape": shape})
    return path


@pytest.mark.parametrize("shape, message", [
    ((10**6, 10**6), r"big\.npy: the file's \.npy header declares a 1000000×1000000 array; a "
                     r"building's matrix is at most 10000×10000 \(one row and column per "
                     r"degree of freedom\)$"),
    ((10**12,), r"big\.npy: the file's \.npy header declares a 1000000000000 array"),
    ((3, 3), r"big\.npy: the file is cut short: its header declares a 3×3 float64 array "
             r"\(72 bytes\) but 0 bytes follow it$"),
])
def test_npy_sizes_are_checked_from_the_header(tmp_path: Path, shape, message) -> None:
    path = _npy_header_only(tmp_path / "big.npy", shape)
    with pytest.raises(ValueError, match=message):
        read_matrix(path, "K")


def test_npz_member_sizes_are_checked_from_their_headers(tmp_path: Path) -> None:
    import zipfile

    header = _npy_header_only(tmp_path / "h.npy", (10**6, 10**6)).read_bytes()
    with zipfile.ZipFile(tmp_path / "b.npz", "w") as z:
        z.writestr("M.npy", header)
    with pytest.raises(ValueError, match=r"b\.npz: array 'M''s \.npy header declares a "
                                         r"1000000×1000000 array; a building's matrix is at "
                                         r"most 10000×10000"):
        read_matrix(tmp_path / "b.npz", "M")


@pytest.mark.parametrize("text, message", [
    ("%%MatrixMarket matrix array real general\n1000000000 1000000000\n1\n",
     r"big\.mtx: its Matrix Market size line declares a 1000000000×1000000000 array; a "
     r"building's matrix is at most 10000×10000"),
    ("%%MatrixMarket matrix coordinate real general\n1000000000 1000000000 3\n1 1 1\n",
     r"big\.mtx: its Matrix Market size line declares a 1000000000×1000000000 array"),
    ("%%MatrixMarket matrix coordinate real general\n3 3 1000000000000\n1 1 1\n",
     r"big\.mtx: its Matrix Market size line declares 1000000000000 entries, more than a "
     r"3×3 matrix has"),
    ("%%MatrixMarket matrix coordinate real general\n3000 3000 9000000\n1 1 1\n",
     r"big\.mtx: its Matrix Market size line declares 9000000 entries but the file is only "
     r"\d+ bytes long"),
])
def test_matrix_market_sizes_are_checked_from_the_size_line(tmp_path: Path, text,
                                                            message) -> None:
    with pytest.raises(ValueError, match=message):
        read_matrix(_write(tmp_path / "big.mtx", text), "K")


def test_a_text_matrix_too_large_for_a_building_is_refused_while_reading(tmp_path) -> None:
    rows = _write(tmp_path / "rows.csv", "1\n" * 10_001)
    with pytest.raises(ValueError, match=r"rows\.csv: more than 10000 rows \(line 10001\); a "
                                         r"building's matrix is at most 10000×10000"):
        read_matrix(rows, "K")
    line = _write(tmp_path / "line.csv", "1," * 400_000 + "1\n")
    with pytest.raises(ValueError, match=r"line\.csv: line 1 is longer than 640000 characters"):
        read_matrix(line, "K")


def test_a_header_declaring_a_huge_matrix_is_one_line_from_the_command_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from pounding.cli import main

    _npy_header_only(tmp_path / "K.npy", (10**6, 10**6))
    np.save(tmp_path / "M.npy", np.eye(2))
    model = _write(tmp_path / "m.toml",
                   '[record]\nbundled = "el_centro"\n[[building]]\nmatrices = { M = "M.npy", '
                   'K = "K.npy" }\nelevations = [3.0, 6.0]\n[[building]]\nmass = 2e5\n'
                   'period = 0.5\n[contact]\nlaw = "kelvin-voigt"\nk = 9.3e8\ne = 0.65\n'
                   'gap = 0.02\n')
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "1000000×1000000" in err[0] and "K.npy" in err[0], err
    assert not (tmp_path / "out").exists()


def test_a_matrix_building_and_a_model_of_one_pickle_and_deep_copy() -> None:
    """``sources`` is a read-only mapping proxy, which pickle refused: a matrix building, a
    building in plan's row building and any model holding one could not go to another
    process (multiprocessing) nor through ``copy.deepcopy`` (TypeError: cannot pickle
    'mappingproxy' object). They travel whole, and ``sources`` stays read-only."""
    import copy
    import pickle

    from pounding.model import ContactSpec, PoundingModel
    from pounding.structure.plan import LateralElement, PlanBuilding

    b = _building(sources={"M": "m.csv", "K": "k.csv"}, name="A")
    plan = PlanBuilding(masses=[4e5], heights=[4.0], width=20.0, depth=10.0, elements=[
        LateralElement(0.0, 0.0, "x", 5e7), LateralElement(0.0, 10.0, "x", 5e7),
        LateralElement(0.0, 5.0, "y", 5e7), LateralElement(20.0, 5.0, "y", 1e8)])
    model = PoundingModel([b, plan], [0.05], ContactSpec("linear-spring", k=1e8))
    for copied in (pickle.loads(pickle.dumps(b)), copy.deepcopy(b)):
        assert copied == b and dict(copied.sources) == {"M": "m.csv", "K": "k.csv"}
        with pytest.raises(TypeError):
            copied.sources["M"] = "other.csv"  # type: ignore[index]
    again = pickle.loads(pickle.dumps(model))
    assert again.buildings == model.buildings
    assert [c.label for c in again.contacts] == [c.label for c in model.contacts] != []
