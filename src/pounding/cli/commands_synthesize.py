"""`pounding synthesize`: a suite of stochastic records for an earthquake scenario and site
(Rezaeian & Der Kiureghian 2010), written as PEER .AT2 files with their median spectrum
beside the NGA-West1 median of Boore & Atkinson (2008)."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, print_table


class Mechanism(str, Enum):
    """The mechanisms of the predictive equations."""

    strike_slip = "strike-slip"
    reverse = "reverse"


@app.command("synthesize")
def synthesize_cmd(
    magnitude: Annotated[float, typer.Option(
        "--magnitude", "-m", metavar="M", help="Moment magnitude.",
        show_default=False)] = ...,  # type: ignore[assignment]
    distance: Annotated[float, typer.Option(
        "--distance", "-r", metavar="KM", help="Rupture distance R_rup \\[km].",
        show_default=False)] = ...,  # type: ignore[assignment]
    vs30: Annotated[float, typer.Option(
        "--vs30", metavar="M/S", help="Vs30 of the site \\[m/s].",
        show_default=False)] = ...,  # type: ignore[assignment]
    mechanism: Annotated[Mechanism, typer.Option(
        "--mechanism", help="Faulting mechanism (F = 0 strike-slip, 1 reverse).")]
        = Mechanism.strike_slip,
    count: Annotated[int, typer.Option(
        "--count", "-n", metavar="N", help="Records in the suite.")] = 10,
    seed: Annotated[int, typer.Option(
        "--seed", metavar="SEED", help="Seed: the same seed gives the same records, record "
        "i the same whatever --count.")] = 0,
    dt: Annotated[float, typer.Option(
        "--time-step", metavar="SECONDS", help="Time step of the records written \\[s] "
        "(at most 0.02).")] = 0.01,
    out: Annotated[Path, typer.Option(
        "--out", "-o", metavar="DIR", help=f"{opt.OUT_HELP} Default: synthetic-records in "
        "the current folder.", show_default=False)] = Path("synthetic-records"),
    overwrite: opt.Overwrite = False,
) -> None:
    """Stochastic records for a scenario: the model of Rezaeian & Der Kiureghian (2010).

    Its six parameters are drawn, correlated, from the paper's predictive equations for
    the magnitude, distance, Vs30 and mechanism; the records are written as .AT2 files
    with parameters.csv and spectrum.csv (the suite's median PSA beside Boore & Atkinson
    2008's median); see docs/records.md.

    Examples:

      pounding synthesize -m 7 -r 25 --vs30 750 --count 20 --seed 1 --out m7-site

      pounding synthesize -m 6.5 -r 15 --vs30 400 --mechanism reverse -n 11
    """
    from pounding.studies.stochastic_suite import write_stochastic_suite

    for name, value, lo, hi in (("--magnitude", magnitude, 4.0, 9.0),
                                ("--distance", distance, 0.0, 500.0),
                                ("--vs30", vs30, 100.0, 3000.0),
                                ("--count", count, 1, 100_000),
                                ("--time-step", dt, 0.0, 0.02)):
        open_low = name in ("--distance", "--time-step")
        if not (lo < value <= hi if open_low else lo <= value <= hi):
            bracket = "(" if open_low else "["
            raise ValueError(f"{name}: must be in {bracket}{lo:g}, {hi:g}] (got {value:g})")
    if seed < 0:
        raise ValueError(f"--seed: a whole number ≥ 0 (got {seed})")
    res = write_stochastic_suite(out, magnitude, distance, vs30, mechanism.value, count,
                                 seed, dt=dt, overwrite=overwrite)
    rows = [(str(r[0]), f"{r[7]:.3f}", f"{r[1]:.3g}", f"{r[2]:.1f}", f"{r[3]:.1f}",
             f"{r[4]:.2f}", f"{r[5]:+.3f}", f"{r[6]:.2f}", f"{r[8]:.1f}") for r in res.rows]
    print_table(console, f"{count} stochastic records: M {magnitude:g}, R_rup {distance:g} km, "
                f"Vs30 {vs30:g} m/s, {mechanism.value}, seed {seed}",
                [Col("record", "left", wrap=True), Col("PGA [g]"), Col("I_a [m/s]"),
                 Col("D5-95 [s]"), Col("t_mid [s]"), Col("f_mid [Hz]"), Col("f' [Hz/s]"),
                 Col("ζ_f [-]"), Col("length [s]")], rows)
    print_table(console, "median 5 %-damped PSA of the suite and of Boore & Atkinson (2008) "
                         "at R_JB = R_rup",
                [Col("T [s]"), Col("suite [g]"), Col("BA08 [g]"), Col("ratio")],
                [(f"{t:g}", f"{a:.4g}", f"{b:.4g}", f"{a / b:.2f}")
                 for t, a, b in zip(res.periods, res.median_g, res.ba08_g)])
    console.print(f"records, parameters.csv and spectrum.csv in {res.out_dir}",
                  highlight=False)
