"""The exact step's sweep of a linked block two floors a pass
(:func:`pounding.integrate.exact_links.sweep_floor_pairs`, also the Maxwell block's four
links a pass in :func:`pounding.integrate.exact_maxwell.maxwell_block_step`) gives the very
numbers of one column a pass: each row takes the same products in the same order. Checked
against a plain loop compiled with the kernel's options, bit for bit, for blocks of odd and
even size, and on whole runs against the linked models' adaptive and reference answers
elsewhere (tests/devices/test_links.py, tests/integrate/test_exact_maxwell.py)."""

from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
from pounding.devices import Link
from pounding.integrate.exact_links import sweep_floor_pairs

OPTS = dict(cache=False, error_model="numpy", fastmath={"contract"}, _nrt=False)


@njit(**OPTS)
def _one_floor_a_pass(p, nb, n, rows, x, acc, fops):
    for j in range(nb):
        xu = x[p + j]
        xv = x[n + p + j]
        for ir in range(rows):
            acc[ir] = acc[ir] + fops[p + j, ir] * xu + fops[n + p + j, ir] * xv


@njit(**OPTS)
def _pairs(p, nb, n, rows, x, acc, fops):
    sweep_floor_pairs(p, nb, n, rows, x, acc, fops)


@pytest.mark.parametrize("nb, rows", [(1, 6), (2, 12), (5, 24), (10, 44), (11, 49), (20, 84)])
def test_two_floors_a_pass_are_one_floor_a_pass_bit_for_bit(nb, rows):
    rng = np.random.default_rng(nb)
    n = nb + 3  # the block starts at floor p = 2 of n floors
    p = 2
    fops = rng.standard_normal((2 * n, rows + 3)) * np.exp(rng.uniform(-20, 20, (2 * n, 1)))
    x = rng.standard_normal(2 * n) * np.exp(rng.uniform(-10, 10, 2 * n))
    start = rng.standard_normal(rows + 3)
    a, b = start.copy(), start.copy()
    _one_floor_a_pass(p, nb, n, rows, x, a, fops)
    _pairs(p, nb, n, rows, x, b, fops)
    assert np.array_equal(a, b)
    assert np.array_equal(a[rows:], start[rows:])  # nothing past the block's rows


@pytest.mark.parametrize("kind", ["viscous", "maxwell"])
def test_a_linked_block_of_odd_size_steps_exactly_like_the_adaptive_run(kind):
    """A 3-storey and a 2-storey building tied at two levels (a block of five floors: a
    pair of floors a pass and one left over), without contact: the exact steps agree with
    the adaptive ones to the latter's tolerance, energy included."""
    kw = dict(c=3e5) if kind == "viscous" else dict(c=3e5, k=1.5e7)
    blds = [ShearBuilding.uniform(3, 3e5, 4e8), ShearBuilding.uniform(2, 2e5, 3e8)]
    links = [Link((f"B1F{i}", f"B2F{i}"), kind, **kw) for i in (1, 2)]
    model = PoundingModel(blds, [5.0], ContactSpec("kelvin-voigt", k=1e9, e=0.65),
                          devices=links)
    gm = el_centro().trimmed(3.0)
    res = simulate(model, gm)
    rk = simulate(model, gm, free_stepping="rk", rtol=1e-10)
    assert res.stats.rk_steps == 0 < rk.stats.rk_steps
    for name in ("displacement", "velocity", "link_force"):
        ours, theirs = getattr(res, name), getattr(rk, name)
        assert np.abs(ours - theirs).max() < 1e-7 * np.abs(theirs).max(), name
    e = np.s_[:, [0, 1, 2, 3, 7]]
    assert np.abs(res.energy[e] - rk.energy[e]).max() < 1e-7 * np.abs(rk.energy[e]).max()
    assert res.energy[-1, 7] > 0.0
    assert res.energy_balance_error < 1e-10
