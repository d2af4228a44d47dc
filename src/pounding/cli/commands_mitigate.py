"""`pounding mitigate`."""

from pounding.cli.app import app, console  # noqa: F401

from pathlib import Path  # noqa: E402
from typing import Annotated, Any  # noqa: E402

import typer  # noqa: E402
from rich.table import Table  # noqa: E402
from rich.text import Text  # noqa: E402


@app.command("mitigate")
def mitigate_cmd(
    study_file: Annotated[Path, typer.Argument(
        help="TOML study file: base model, records, options (see docs/mitigation.md).",
        show_default=False)],
    out: Annotated[Path | None, typer.Option(
        "--out", "-o", help="Output folder (default: out of the study file, else "
                            "<name>-results beside it).", show_default=False)] = None,
    overwrite: Annotated[bool, typer.Option(
        "--overwrite", help="Replace the output folder of an earlier study (only one holding "
                            "nothing but the files of its manifest).")] = False,
    figures: Annotated[bool, typer.Option(
        "--figures/--no-figures", help="Draw the trade-off figure.")] = True,
) -> None:
    """Compare retrofit options for a pair of buildings: bare gap, bumpers, links.

    Every option (a list of devices added to the base model) runs under every record;
    prints and writes, per option, the impacts, the peak impact force, drift ratio,
    storey shear and floor acceleration, and the energy the devices dissipated.

    Examples:

      pounding mitigate examples/mitigation_two_10_storey.toml

      pounding mitigate study.toml --out retrofit --overwrite --no-figures
    """
    from pounding.cli.commands_run import _progress_bar, _sigterm_as_interrupt
    from pounding.studies.mitigation import run_mitigation

    with _sigterm_as_interrupt(), _progress_bar("mitigation runs") as progress:
        res = run_mitigation(study_file, out=out, overwrite=overwrite, figures=figures,
                             progress=progress)
    _print(res)


def _print(res: Any) -> None:
    s = res.summary
    t = Table(title=f"retrofit options (mean over {int(s['records'].iloc[0])} record(s))")
    heads = ("option", "impacts", "peak impact force [MN]", "pad impacts",
             "peak pad force [MN]", "peak drift ratio [%]", "peak storey shear [MN]",
             "peak floor accel. [g]", "dissipated: contacts / pads / links [MJ]")
    for h in heads:
        t.add_column(Text(h), justify="left" if h == "option" else "right")
    for name, r in s.iterrows():
        t.add_row(str(name), f"{r['n_impacts']:.1f}", f"{r['peak_impact_force_N'] / 1e6:.3g}",
                  f"{r['n_pad_impacts']:.1f}", f"{r['peak_pad_force_N'] / 1e6:.3g}",
                  f"{100 * r['peak_drift_ratio']:.3g}", f"{r['peak_storey_shear_N'] / 1e6:.3g}",
                  f"{r['peak_abs_accel_m_s2'] / 9.80665:.3g}",
                  f"{r['contact_dissipated_J'] / 1e6:.3g} / {r['pads_dissipated_J'] / 1e6:.3g}"
                  f" / {r['links_dissipated_J'] / 1e6:.3g}")
    console.print(t)
    console.print(Text.assemble("results in ", (str(res.out_dir), "bold"), ": "
                                + ", ".join(sorted(p.name for p in res.files.values()))))
