"""The exact steps of uncoupled floors (:mod:`pounding.integrate.exact_uncoupled`): their own
loop gives the generic loop's bits (:func:`pounding.integrate.exact_steps.free_run`).

A cable restrainer that never takes up its slack changes nothing in the exact steps (no
force, K and C as they were) but gives the model an element row, which sends it down the
generic loop: the two runs must agree bit for bit in every output they share — the
histories, the energies and the located peaks (with their times), over El Centro's 40 s,
whose ~2,000 peak searches the uncoupled loop batches several times over."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from pounding import simulate
from pounding.config import load_config
from pounding.devices.link import Link
from pounding.integrate.exact_uncoupled import is_uncoupled
from pounding.integrate.kernel_model import kernel_model
from pounding.integrate.propagator import free_step
from pounding.model import PoundingModel

SEED = Path(__file__).resolve().parents[2] / "examples" / "seed_sdof_pair.toml"


def _shape_is_uncoupled(model: PoundingModel, dt: float) -> bool:
    km = kernel_model(model)
    fl = km.floors
    fs = free_step(np.diag(fl.m_diag), km.C, km.K, fl.r, dt, km.C_links)
    return bool(is_uncoupled(fs.blk, fs.modal, fs.maxwell, fs.rows, km.n, fl.bw,
                             fl.r.shape[1], km.elements.lo.size))


def test_uncoupled_loop_gives_the_generic_loops_bits():
    model, motion, solver = load_config(SEED).build()
    plain = PoundingModel(model.buildings, [10.0], model.contact)
    slack = PoundingModel(model.buildings, [10.0], model.contact, devices=[
        Link(("B1F1", "B2F1"), "restrainer", k=5e6, slack=100.0)])
    assert _shape_is_uncoupled(plain, solver["dt"])
    assert not _shape_is_uncoupled(slack, solver["dt"])
    a = simulate(plain, motion, **solver)
    b = simulate(slack, motion, **solver)
    assert a.stats.rk_steps == 0 and b.stats.rk_steps == 0  # every step exact
    da, db = a.to_xarray(), b.to_xarray()
    shared = [name for name in da.data_vars if name in db.data_vars]
    assert {"displacement", "velocity", "absolute_acceleration", "penetration",
            "energy"} <= set(shared)
    for name in shared:
        assert np.array_equal(da[name].values, db[name].values), name
    # the located peaks and their times
    assert a.located_peaks is not None
    assert np.array_equal(a.located_peaks, b.located_peaks)
