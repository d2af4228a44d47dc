"""Several buildings as one block-diagonal system; floors at a shared elevation."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.structure import ModalDamping, ShearBuilding, assemble, shared_levels


def test_assemble_is_block_diagonal_with_offsets() -> None:
    a = ShearBuilding.uniform(3, 1.0e5, 1.0e8, name="A")
    b = ShearBuilding.sdof(5.0e4, period=0.3)
    c = ShearBuilding.uniform(2, 2.0e5, 3.0e8, damping=ModalDamping(0.02))
    M, C, K, r, offsets = assemble([a, b, c])
    np.testing.assert_array_equal(offsets, [0, 3, 4])
    assert offsets.dtype == np.int64
    assert M.shape == C.shape == K.shape == (6, 6) and r.shape == (6,)
    np.testing.assert_array_equal(r, np.ones(6))
    for bld, o in zip((a, b, c), offsets, strict=True):
        s = slice(o, o + bld.n)
        np.testing.assert_array_equal(M[s, s], bld.mass_matrix())
        np.testing.assert_array_equal(K[s, s], bld.stiffness_matrix())
        np.testing.assert_array_equal(C[s, s], bld.damping_matrix())
    # no coupling between buildings before contact
    mask = np.zeros((6, 6), dtype=bool)
    for bld, o in zip((a, b, c), offsets, strict=True):
        mask[o:o + bld.n, o:o + bld.n] = True
    for A in (M, C, K):
        assert np.all(A[~mask] == 0.0)
        assert A.dtype == np.float64 and A.flags.c_contiguous


def test_assembled_dof_lookup() -> None:
    sys = assemble([ShearBuilding.uniform(3, 1.0, 1.0), ShearBuilding.uniform(2, 1.0, 1.0)])
    assert sys.n_dof == 5
    assert sys.dof(1, 0) == 3 and sys.dof(0, 2) == 2
    with pytest.raises(ValueError, match="floor_index"):
        sys.dof(1, 2)
    with pytest.raises(ValueError, match="building"):
        sys.dof(2, 0)


def test_assemble_bad_input() -> None:
    with pytest.raises(ValueError, match="buildings"):
        assemble([])
    with pytest.raises(ValueError, match=r"buildings\[1\]"):
        assemble([ShearBuilding.uniform(2, 1.0, 1.0), "B"])  # type: ignore[list-item]


def test_shared_levels_equal_buildings() -> None:
    a = ShearBuilding.uniform(4, 1.0, 1.0, height=3.0)
    assert shared_levels(a, a) == [(0, 0), (1, 1), (2, 2), (3, 3)]


def test_shared_levels_different_heights_stop_at_lower_roof() -> None:
    tall = ShearBuilding.uniform(5, 1.0, 1.0, height=3.0)
    short = ShearBuilding.uniform(3, 1.0, 1.0, height=3.0)
    assert shared_levels(tall, short) == [(0, 0), (1, 1), (2, 2)]
    assert shared_levels(short, tall) == [(0, 0), (1, 1), (2, 2)]


def test_shared_levels_mismatched_storey_heights() -> None:
    # 3.0 m and 3.5 m storeys line up only at common multiples of both: 21 m, 42 m, ...
    a = ShearBuilding.uniform(5, 1.0, 1.0, height=3.0)
    b = ShearBuilding.uniform(5, 1.0, 1.0, height=3.5)
    assert shared_levels(a, b) == []
    a = ShearBuilding.uniform(15, 1.0, 1.0, height=3.0)   # levels 3 … 45
    b = ShearBuilding.uniform(12, 1.0, 1.0, height=3.5)   # levels 3.5 … 42
    assert shared_levels(a, b) == [(6, 5), (13, 11)]      # 21 m and 42 m


def test_shared_levels_irregular_storeys_and_tolerance() -> None:
    a = ShearBuilding(masses=[1.0] * 3, stiffnesses=[1.0] * 3, heights=[4.5, 3.0, 3.0])
    b = ShearBuilding(masses=[1.0] * 3, stiffnesses=[1.0] * 3, heights=[3.0, 4.5, 3.0 + 2e-7])
    # a: 4.5, 7.5, 10.5   b: 3.0, 7.5, 10.5000002
    assert shared_levels(a, b) == [(1, 1), (2, 2)]
    assert shared_levels(a, b, tol=1e-8) == [(1, 1)]
    with pytest.raises(ValueError, match=r"tol.*-1"):
        shared_levels(a, b, tol=-1.0)
    with pytest.raises(ValueError, match="b must be a ShearBuilding"):
        shared_levels(a, 3.0)  # type: ignore[arg-type]
