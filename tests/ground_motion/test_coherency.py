"""Incoherent motions simulated from a record: the record kept where it was recorded, full
coherence giving the record (shifted by wave passage), and over many seeds the target
coherency and the record's Fourier amplitudes within their sampling error (estimated here
from the simulations, not by the simulator)."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.ground_motion import el_centro
from pounding.ground_motion.coherency import (
    coherent_motions,
    harichandran_vanmarcke,
    lagged_coherency,
    luco_wong,
)

EC = el_centro().trimmed(10.0)


def test_coherency_models_closed_forms() -> None:
    """The formulas at hand-computed points."""
    A, al, k, f0, b = 0.736, 0.147, 5210.0, 1.09, 2.78
    xi, f = 100.0, 1.09
    theta = k / np.sqrt(1.0 + (f / f0) ** b)  # (= k/√2 at f = f0)
    c = 2 * xi * (1 - A + al * A)
    expected = A * np.exp(-c / (al * theta)) + (1 - A) * np.exp(-c / theta)
    assert harichandran_vanmarcke(xi, f) == pytest.approx(expected, rel=1e-14)
    assert harichandran_vanmarcke(0.0, 7.0) == 1.0
    assert luco_wong(100.0, 10.0, beta=2e-4) == pytest.approx(np.exp(-0.04), rel=1e-14)
    w = np.linspace(0.1, 60.0, 50)
    assert np.all(np.diff(lagged_coherency("harichandran-vanmarcke", 50.0, w)) < 0)


def test_the_record_stays_and_full_coherence_is_the_record() -> None:
    s = coherent_motions(EC, [0.0, 40.0, 0.0], seed=3)
    assert np.array_equal(s.records[0].accel, EC.accel)  # (no wave passage: no longer)
    # a station at the recorded one's place, no wave passage: the record itself
    assert np.max(np.abs(s.records[2].accel[: EC.npts] - EC.accel)) < 1e-12 * EC.pga
    # full coherence (β = 0) with waves at 1000 m/s over 50 m: the record 0.05 s later
    w = coherent_motions(EC, [0.0, 50.0], coherency="luco-wong", beta=0.0,
                         apparent_velocity=1000.0, seed=1)
    assert w.records[1].npts == EC.npts + 5
    assert np.max(np.abs(w.records[1].accel[5:] - EC.accel)) < 1e-12 * EC.pga
    assert np.max(np.abs(w.records[1].accel[:5])) < 1e-12 * EC.pga
    # reproducible, and another seed another motion
    again = coherent_motions(EC, [0.0, 40.0, 0.0], seed=3)
    assert np.array_equal(again.records[1].accel, s.records[1].accel)
    other = coherent_motions(EC, [0.0, 40.0, 0.0], seed=4)
    assert not np.allclose(other.records[1].accel, s.records[1].accel)


def test_coherency_and_amplitudes_over_many_seeds() -> None:
    """300 seeds, stations at 0 (the record), 60 and 150 m, Harichandran–Vanmarcke with
    waves at 800 m/s: per frequency band (1–2, 2–4, 4–8 Hz, the lines of each band
    pooled), the estimated complex coherency of every pair against γ_jk, and each
    simulated station's mean power against the record's: the coherency within 2.5 times
    its standard error (1 − |γ|²)/√N (Luco & Wong's motions fail it), the power within 4."""
    x = [0.0, 60.0, 150.0]
    n_seeds = 300
    specs = []
    for seed in range(n_seeds):
        s = coherent_motions(EC, x, apparent_velocity=800.0, seed=seed, trim=False)
        specs.append(np.array([np.fft.rfft(r.accel) for r in s.records]))
    A = np.array(specs)  # (seeds, stations, F)
    n = 2 * EC.npts
    f = np.fft.rfftfreq(n, EC.dt)
    for lo, hi in ((1.0, 2.0), (2.0, 4.0), (4.0, 8.0)):
        band = (f >= lo) & (f < hi)
        for j, k in ((1, 0), (2, 0), (2, 1)):
            cross = np.mean(A[:, j, band] * A[:, k, band].conj(), axis=0)
            pj = np.mean(np.abs(A[:, j, band]) ** 2, axis=0)
            pk = np.mean(np.abs(A[:, k, band]) ** 2, axis=0)
            est = cross / np.sqrt(pj * pk)  # per line
            w = 2 * np.pi * f[band]
            target = (harichandran_vanmarcke(x[j] - x[k], f[band])
                      * np.exp(-1j * w * (x[j] - x[k]) / 800.0))
            g2 = np.abs(target) ** 2
            # the error of a coherency estimate from N independent pairs ~ (1 − |γ|²)/√N
            err = np.abs(est - target)
            assert np.mean(err) < 2.5 * np.mean((1 - g2) / np.sqrt(n_seeds)) + 1e-3, (lo, j, k)
        p0 = np.abs(A[0, 0, band]) ** 2
        for j in (1, 2):
            ratio = np.mean(np.abs(A[:, j, band]) ** 2, axis=0) / p0
            assert np.mean(ratio) == pytest.approx(1.0, abs=4 / np.sqrt(n_seeds * band.sum()))


def test_refusals() -> None:
    with pytest.raises(ValueError, match="coherency"):
        coherent_motions(EC, [0.0, 10.0], coherency="abrahamson")
    with pytest.raises(ValueError, match="recorded_at"):
        coherent_motions(EC, [0.0, 10.0], recorded_at=2)
    with pytest.raises(ValueError, match="apparent_velocity"):
        coherent_motions(EC, [0.0, 10.0], apparent_velocity=0.0)
