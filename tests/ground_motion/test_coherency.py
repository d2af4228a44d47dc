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
    assert w.records[1].npts == EC.npts + 5 and w.delays == pytest.approx((0.0, 0.05))
    assert np.max(np.abs(w.records[1].accel[5:] - EC.accel)) < 1e-12 * EC.pga
    assert np.max(np.abs(w.records[1].accel[:5])) < 1e-12 * EC.pga
    # recorded downstream: the upstream station 0.05 s earlier, nothing wrapped around —
    # every motion on one axis, the record after 5 leading zeros
    u = coherent_motions(EC, [0.0, 50.0], coherency="luco-wong", beta=0.0,
                         apparent_velocity=1000.0, recorded_at=1, seed=1)
    assert u.delays == pytest.approx((0.0, 0.05))
    assert np.array_equal(u.records[1].accel[5:], EC.accel) and not np.any(u.records[1].accel[:5])
    assert np.max(np.abs(u.records[0].accel[: EC.npts] - EC.accel)) < 1e-12 * EC.pga
    assert np.max(np.abs(u.records[0].accel[EC.npts:])) < 1e-12 * EC.pga
    # reproducible, and another seed another motion
    again = coherent_motions(EC, [0.0, 40.0, 0.0], seed=3)
    assert np.array_equal(again.records[1].accel, s.records[1].accel)
    other = coherent_motions(EC, [0.0, 40.0, 0.0], seed=4)
    assert not np.allclose(other.records[1].accel, s.records[1].accel)


X = [0.0, 60.0, 150.0]
N_SEEDS = 300


def _spectra(model: str) -> np.ndarray:
    """The DFTs of every station's motion over N_SEEDS seeds (seeds, stations, lines)."""
    return np.array([[np.fft.rfft(r.accel) for r in
                      coherent_motions(EC, X, coherency=model, apparent_velocity=800.0,
                                       seed=seed).records]
                     for seed in range(N_SEEDS)])


def _coherency_checks(A: np.ndarray) -> list[bool]:
    """Per band (1–2, 2–4, 4–8 Hz, the lines pooled) and pair: is the estimated complex
    coherency within 2.5 standard errors (1 − |γ|²)/√N of Harichandran–Vanmarcke's with
    waves at 800 m/s?"""
    f = np.fft.rfftfreq(EC.npts + 19, EC.dt)  # (the record and 150/800 s of zeros)
    out = []
    for lo, hi in ((1.0, 2.0), (2.0, 4.0), (4.0, 8.0)):
        band = (f >= lo) & (f < hi)
        for j, k in ((1, 0), (2, 0), (2, 1)):
            cross = np.mean(A[:, j, band] * A[:, k, band].conj(), axis=0)
            pj = np.mean(np.abs(A[:, j, band]) ** 2, axis=0)
            pk = np.mean(np.abs(A[:, k, band]) ** 2, axis=0)
            est = cross / np.sqrt(pj * pk)  # per line
            w = 2 * np.pi * f[band]
            target = (harichandran_vanmarcke(X[j] - X[k], f[band])
                      * np.exp(-1j * w * (X[j] - X[k]) / 800.0))
            g2 = np.abs(target) ** 2
            # the error of a coherency estimate from N independent pairs ~ (1 − |γ|²)/√N
            err = np.mean(np.abs(est - target))
            out.append(bool(err < 2.5 * np.mean((1 - g2) / np.sqrt(N_SEEDS)) + 1e-3))
    return out


def test_coherency_and_amplitudes_over_many_seeds() -> None:
    """300 seeds, stations at 0 (the record), 60 and 150 m, Harichandran–Vanmarcke with
    waves at 800 m/s: every pair's estimated coherency in three bands within 2.5 standard
    errors of the target — and Luco & Wong's motions fail the same checks (so they can
    fail); each station's mean power per band, and its whole energy Σ a², the record's."""
    A = _spectra("harichandran-vanmarcke")
    assert A.shape[2] == (EC.npts + 19) // 2 + 1  # (the record and 150/800 s of zeros)
    assert all(_coherency_checks(A))
    assert sum(_coherency_checks(_spectra("luco-wong"))) <= 4
    f = np.fft.rfftfreq(EC.npts + 19, EC.dt)
    for lo, hi in ((1.0, 2.0), (2.0, 4.0), (4.0, 8.0)):
        band = (f >= lo) & (f < hi)
        p0 = np.abs(A[0, 0, band]) ** 2
        for j in (1, 2):
            ratio = np.mean(np.abs(A[:, j, band]) ** 2, axis=0) / p0
            assert np.mean(ratio) == pytest.approx(1.0, abs=4 / np.sqrt(N_SEEDS * band.sum()))
    # the whole motion's energy (∝ Σ|A|², Parseval), over the seeds: the record's
    energy = np.sum(np.abs(A) ** 2, axis=2)
    for j in (1, 2):
        assert np.mean(energy[:, j]) / energy[0, 0] == pytest.approx(1.0, abs=0.03)


def test_refusals() -> None:
    with pytest.raises(ValueError, match="coherency"):
        coherent_motions(EC, [0.0, 10.0], coherency="abrahamson")
    with pytest.raises(ValueError, match="recorded_at"):
        coherent_motions(EC, [0.0, 10.0], recorded_at=2)
    with pytest.raises(ValueError, match="apparent_velocity"):
        coherent_motions(EC, [0.0, 10.0], apparent_velocity=0.0)
