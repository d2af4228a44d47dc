"""`pounding mitigate`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.running import progress_bar, sigterm_as_interrupt
from pounding.cli.tables import Col, energy_scale, force_scale, literal, number, print_table


@app.command("mitigate")
def mitigate_cmd(
    study_file: Annotated[Path, typer.Argument(
        help="TOML study file: base model, records, options (see docs/mitigation.md).",
        show_default=False)],
    out: opt.Out = None,
    overwrite: opt.Overwrite = False,
    figures: opt.FiguresStudy = None,
    workers: opt.WorkersFew = None,
    scheduler: opt.SchedulerFew = None,
) -> None:
    """Compare retrofit options for a pair of buildings: bare gap, bumpers, links.

    Every option (a list of devices added to the base model) runs under every record;
    prints and writes, per option, the impacts, the peak impact force, drift ratio,
    storey shear and floor acceleration, and the energy the devices dissipated.

    Examples:

      pounding mitigate examples/mitigation_two_10_storey.toml

      pounding mitigate study.toml --out retrofit --overwrite --no-figures -j 2
    """
    from pounding.studies.mitigation import run_mitigation

    with sigterm_as_interrupt(), progress_bar("mitigation", "runs") as progress:
        res = run_mitigation(study_file, out, overwrite=overwrite, figures=figures,
                             progress=progress, scheduler=scheduler, n_workers=workers)
    _print(res)


def _print(res: Any) -> None:
    """The summary per option: forces and shears in one unit (kN or MN), energies in one
    (kJ or MJ)."""
    from pounding.units import G

    s = res.summary
    bridge = "peak_seat_opening_m" in s.columns  # a bridge: its piers carry the shear
    shear = "peak_pier_shear_N" if bridge else "peak_storey_shear_N"
    forces = [s[c].abs().max() for c in ("peak_impact_force_N", "peak_pad_force_N", shear)]
    f_scale, f_unit = force_scale(max(forces))
    energies = [s[c].abs().max() for c in ("contact_dissipated_J", "pads_dissipated_J",
                                           "links_dissipated_J")]
    e_scale, e_unit = energy_scale(max(energies))
    cols = [Col("option", "left", wrap=True), Col("impacts"),
            Col(f"peak impact force [{f_unit}]"), Col("pad impacts"),
            Col(f"peak pad force [{f_unit}]"), Col("peak drift ratio [%]"),
            Col(f"peak {'pier' if bridge else 'storey'} shear [{f_unit}]"),
            Col("peak floor accel. [g]"),
            Col(f"dissipated in contacts [{e_unit}]"), Col(f"dissipated by pads [{e_unit}]"),
            Col(f"dissipated by links [{e_unit}]")]
    if bridge:
        cols[5:5] = [Col("peak seat opening [mm]")]
    rows = []
    for name, r in s.iterrows():
        row = [literal(name), f"{r['n_impacts']:.1f}",
               number(r["peak_impact_force_N"] * f_scale), f"{r['n_pad_impacts']:.1f}",
               number(r["peak_pad_force_N"] * f_scale), number(100 * r["peak_drift_ratio"], 3),
               number(r[shear] * f_scale), number(r["peak_abs_accel_m_s2"] / G, 3),
               number(r["contact_dissipated_J"] * e_scale),
               number(r["pads_dissipated_J"] * e_scale),
               number(r["links_dissipated_J"] * e_scale)]
        if bridge:
            row[5:5] = [number(1000 * r["peak_seat_opening_m"], 4)]
        rows.append(tuple(row))
    print_table(console, f"retrofit options (mean over {int(s['records'].iloc[0])} "
                         "record(s))", cols, rows)
    console.print(Text.assemble("results in ", (str(res.out_dir), "bold"), ": "
                                + ", ".join(sorted(p.name for p in res.files.values()))))
