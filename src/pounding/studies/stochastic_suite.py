"""A folder of stochastic records (``pounding synthesize``): ``count`` records of the model
of Rezaeian & Der Kiureghian (2010) for one scenario and seed, written as PEER ``.AT2``
files, with their parameters and their median spectrum beside the NGA-West1 median of
Boore & Atkinson (2008). See ``docs/records.md``.

Layout::

    <out>/<stem>_01.AT2 ...   the records, in g (pounding record reads them back)
    <out>/parameters.csv      one row per record: its six parameters, PGA and length
    <out>/spectrum.csv        damping, period, the suite's median PSA, BA08's median, ratio
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = ["MARK", "SPECTRUM_PERIODS", "SuiteOutput", "write_stochastic_suite"]

MARK = "pounding synthesize: stochastic record"
"""First line of every record written."""

SPECTRUM_PERIODS = (0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0)
"""Periods of ``spectrum.csv`` [s]."""

SPECTRUM_DAMPING = 0.05
"""Damping ratio of ``spectrum.csv``'s spectra (a fraction of critical; BA08's medians are
5 %-damped), written in its ``damping`` column as the spectra's CSVs do."""

PARAMETER_COLUMNS = ("record", "arias_m_s", "d595_s", "t_mid_s", "f_mid_hz",
                     "f_slope_hz_s", "zeta_f", "pga_g", "length_s")


@dataclass(frozen=True)
class SuiteOutput:
    """What :func:`write_stochastic_suite` wrote: the folder, the record files, the
    median spectrum [g] of the suite and BA08's at :data:`SPECTRUM_PERIODS` (BA08 at
    ``R_JB = R_rup``), and the parameters of each record (rows of ``parameters.csv``)."""

    out_dir: Path
    records: list[Path]
    periods: np.ndarray
    median_g: np.ndarray
    ba08_g: np.ndarray
    rows: list[tuple[object, ...]]


def write_stochastic_suite(out: str | os.PathLike[str], magnitude: float, distance: float,
                           vs30: float, mechanism: str = "strike-slip", count: int = 10,
                           seed: int = 0, *, dt: float = 0.01, overwrite: bool = False
                           ) -> SuiteOutput:
    """Simulate the suite and write its folder whole (built aside, then put in place).

    Raises
    ------
    ValueError
        One line: a bad scenario value (naming it), or an ``out`` that cannot be used
        (exists without ``overwrite``, or holds files pounding did not write).
    """
    from pounding.ground_motion.ba08 import ba08_median
    from pounding.ground_motion.rezaeian2010 import Scenario, stochastic_suite
    from pounding.ground_motion.writers import at2_text
    from pounding.io.files import check_writable, write_text
    from pounding.io.manifest import check_out_folder
    from pounding.io.output_folder import new_output_folder
    from pounding.spectra.response import csv_text, response_spectrum
    from pounding.units import G

    scenario = Scenario(magnitude, distance, vs30, mechanism)
    target = Path(out)
    check_writable(target)
    check_out_folder(target, overwrite, "synthesize")
    motions = stochastic_suite(scenario, count, seed, dt=dt)
    width = len(str(count))
    stem = f"M{magnitude:g}_R{distance:g}_V{vs30:g}_{mechanism}_seed{seed}"
    names = [f"{stem}_{i + 1:0{width}d}.AT2" for i in range(count)]
    t = np.array(SPECTRUM_PERIODS)
    psa = np.array([response_spectrum(gm, t, SPECTRUM_DAMPING).psa[0] / G for gm in motions])
    median = np.exp(np.log(psa).mean(axis=0))
    ba08 = ba08_median(t, magnitude, distance, vs30, mechanism)
    rows: list[tuple[object, ...]] = []
    for name, gm in zip(names, motions):
        p = gm.metadata
        rows.append((name, p["arias"], p["d595"], p["t_mid"], p["f_mid"], p["f_slope"],
                     p["zeta_f"], gm.pga_g, gm.duration))
    with new_output_folder(target, "synthesize", [*names, "parameters.csv", "spectrum.csv"],
                           check=lambda: check_out_folder(target, overwrite, "synthesize")
                           ) as tmp:
        for name, gm in zip(names, motions):
            p = gm.metadata
            write_text(tmp / name, at2_text(gm, MARK, (
                f"{gm.name}: Rezaeian & Der Kiureghian (2010), Ia {p['arias']:.4g} m/s, "
                f"D5-95 {p['d595']:.4g} s, tmid {p['t_mid']:.4g} s, fmid {p['f_mid']:.4g} Hz, "
                f"f' {p['f_slope']:.4g} Hz/s, zeta_f {p['zeta_f']:.4g}")))
        write_text(tmp / "parameters.csv", csv_text(PARAMETER_COLUMNS, rows))
        write_text(tmp / "spectrum.csv", csv_text(
            ("damping", "period_s", "median_psa_g", "ba08_median_g", "ratio"),
            [(SPECTRUM_DAMPING, float(a), float(b), float(c), float(b / c))
             for a, b, c in zip(t, median, ba08)]))
    return SuiteOutput(target, [target / n for n in names], t, median, ba08, rows)
