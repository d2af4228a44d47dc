"""`pounding code-check`: a code's required separation beside the model's gaps."""

from __future__ import annotations

from enum import StrEnum
from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import code_check_time_history as th  # (issue 29, wt-codesth29)
from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, literal, print_table


# issue 29 (wt-codesth29): one list of codes for every --code (options.Code)
SeparationCode = opt.Code
"""The codes of ``pounding code-check --code`` (:data:`pounding.studies.codes.CODES`)."""


class Combination(StrEnum):
    """Modal combination rules (:data:`pounding.studies.codes.COMBINATIONS`)."""

    cqc = "cqc"
    srss = "srss"


@app.command("code-check", context_settings=opt.CODE_CONTEXT)  # (issue 29: old --code)
def code_check_cmd(
    model: Annotated[Path, typer.Argument(
        help="TOML model file, as for `pounding run` (its buildings and gaps are checked; "
             "its record and contact law are not used).", show_default=False)],
    code: Annotated[SeparationCode, typer.Option(
        "--code", help=f"{opt.CODE_HELP} Its separation rule is checked.",  # (issue 29)
        show_default=False)],
    sds: Annotated[float | None, typer.Option(
        "--sds", metavar="G", help="asce7-22: S_DS \\[g] (§11.4.5).", show_default=False)]
        = None,
    sd1: Annotated[float | None, typer.Option(
        "--sd1", metavar="G", help="asce7-22: S_D1 \\[g] (§11.4.5).", show_default=False)]
        = None,
    tl: Annotated[float | None, typer.Option(
        "--tl", metavar="SECONDS", help="asce7-22: T_L \\[s] (§11.4.6).", show_default=False)]
        = None,
    cd: Annotated[float | None, typer.Option(
        "--cd", metavar="VALUE", help="asce7-22: deflection amplification factor C_d (Table "
        "12.2-1).", show_default=False)] = None,
    r: Annotated[float | None, typer.Option(
        "--r", metavar="VALUE", help="asce7-22: response modification coefficient R (Table "
        "12.2-1).", show_default=False)] = None,
    ie: Annotated[float | None, typer.Option(
        "--ie", metavar="VALUE", help="asce7-22: importance factor I_e (Table 1.5-2).",
        show_default=False)] = None,
    agr: Annotated[float | None, typer.Option(
        "--agr", metavar="G", help="en1998-1: reference peak ground acceleration a_gR \\[g] on "
        "ground A.", show_default=False)] = None,
    ground_type: Annotated[str | None, typer.Option(
        "--ground-type", metavar="A-E", help="en1998-1: ground type (Table 3.1).",
        show_default=False)] = None,
    spectrum_type: Annotated[int | None, typer.Option(
        "--spectrum-type", metavar="1|2", help="en1998-1: spectrum type 1 or 2 "
        "(§3.2.2.2(2)).", show_default=False)] = None,
    q: Annotated[float | None, typer.Option(
        "--q", metavar="VALUE", help="en1998-1: behaviour factor q (§3.2.2.5).",
        show_default=False)] = None,
    qd: Annotated[float | None, typer.Option(
        "--qd", metavar="VALUE", help="en1998-1: displacement behaviour factor q_d (§4.3.4). "
        "Default: q.", show_default=False)] = None,
    importance: Annotated[float | None, typer.Option(
        "--importance", metavar="VALUE", help="en1998-1: importance factor γ_I (§4.2.5). "
        "Default: 1.", show_default=False)] = None,
    beta: Annotated[float | None, typer.Option(
        "--beta", metavar="VALUE", help="en1998-1: lower bound factor β of the design "
        "spectrum (§3.2.2.5(4)). Default: 0.2.", show_default=False)] = None,
    property_line: Annotated[bool, typer.Option(
        "--property-line", help="The two buildings stand on two properties with the line "
        "between them: each is set back its own displacement (their sum), instead of the "
        "SRSS of buildings on one property.")] = False,
    combination: Annotated[Combination, typer.Option(
        "--combination", help="Modal combination rule.")] = Combination.cqc,
    out: Annotated[Path | None, typer.Option(
        "--out", "-o", metavar="DIR", help=f"{opt.OUT_HELP} Writes code_check.json there; "
        "without it nothing is written.", show_default=False)] = None,
    overwrite: opt.Overwrite = False,
    time_history: th.TimeHistory = False,  # the time histories beside the check (issue 29,
    suite: th.Suite = None,                # wt-codesth29: cli/code_check_time_history.py)
    design: th.Design = None,
    duration: th.Duration = None,
) -> int:
    """The separation a seismic code asks for between neighbouring buildings, beside the
    model's gaps, floor by floor, each number with its clause.

    The code's displacements come from the model's own buildings: a modal response spectrum
    analysis on the code's design spectrum (linear, every mode). Exit status 0 whether or
    not the gaps meet the code (the table says OK / not OK).

    Examples:

      pounding code-check examples/two_10_storey.toml --code asce7-22 --sds 1.0 --sd1 0.6 --tl 8 --cd 5.5 --r 8 --ie 1

      pounding code-check examples/two_10_storey.toml --code en1998-1 --agr 0.25 --ground-type C --spectrum-type 1 --q 4 --out check

      pounding code-check examples/two_10_storey.toml --code asce7-22 --sds 1.0 --sd1 0.6 --tl 8 --cd 5.5 --r 8 --ie 1 --time-history
    """
    from pounding.config import load_config
    from pounding.studies.codes import code_check, write_code_check

    if out is not None:  # refuse a bad --out before any computation
        from pounding.io.manifest import check_out_folder

        check_out_folder(out, overwrite, "code-check")
    asce = {"sds": sds, "sd1": sd1, "tl": tl, "cd": cd, "r": r, "ie": ie}
    ec8 = {"agr": agr, "ground_type": ground_type, "spectrum_type": spectrum_type, "q": q,
           "qd": qd, "importance": importance, "beta": beta}
    mine, others = (asce, ec8) if code is SeparationCode.asce7_22 else (ec8, asce)
    foreign = next((k for k, v in others.items() if v is not None), None)
    if foreign is not None:
        raise ValueError(f"--{foreign.replace('_', '-')}: not a parameter of --code "
                         f"{code.value} (got {others[foreign]!r})")
    for name, value in mine.items():
        if value is None and name in ("sds", "sd1", "tl", "cd", "r", "ie", "agr",
                                      "ground_type", "spectrum_type", "q"):
            raise ValueError(f"--{name.replace('_', '-')}: --code {code.value} needs it "
                             "(got none)")
    histories = th.wanted(time_history, suite, design, duration)  # (issue 29, wt-codesth29)
    records, target = th.read_inputs(suite, design, duration) if histories else (None, None)
    cfg = load_config(model)
    pounding_model, _, solver = cfg.build()
    check = code_check(pounding_model, code.value, same_property=not property_line,
                       combination=combination.value, **mine)

    head = [("code", check.title), ("displacement", check.displacement),
            ("parameters", ", ".join(f"{k} = {v}" for k, v in check.parameters.items())),
            *((f"T [s] {name}", ", ".join(f"{t:.4g}" for t in periods[:3])
               + (", …" if len(periods) > 3 else ""))
              for name, periods in check.periods.items()),
            *(("assumes", a) for a in check.assumptions)]
    print_table(console, f"{pounding_model.name}: code check", [
        Col("quantity", "left", wrap=True), Col("value", "left", wrap=True)], head,
        show_header=False)
    symbol = "δ_M" if code is SeparationCode.asce7_22 else "d_s"
    for pair in dict.fromkeys(row.pair for row in check.rows):
        rows = [[literal(row.contact), f"{row.elevation:.3g}", f"{1e3 * row.left:.1f}",
                 f"{1e3 * row.right:.1f}", f"{1e3 * row.required:.1f}", f"{1e3 * row.gap:.1f}",
                 "OK" if row.ok else "not OK", row.clause]
                for row in check.rows if row.pair == pair]
        left, right = pair.split("-")
        print_table(console, f"{pair}: separation by {check.title} [mm]", [
            Col("floor", "left"), Col("elevation [m]"), Col(f"{symbol} {left} [mm]"),
            Col(f"{symbol} {right} [mm]"), Col("required [mm]"), Col("gap [mm]"),
            Col("check", "left"), Col("clause", "left", wrap=True)], rows, keys=1,
            caption="; ".join(f"{k}: {v}" for k, v in check.clauses.items()))
    bad = [row for row in check.rows if not row.ok]
    console.print(Text(f"{len(check.rows) - len(bad)} of {len(check.rows)} level(s) meet "
                       f"{check.title}" + (f"; largest shortfall {1e3 * max(r.required - r.gap for r in bad):.1f} mm"
                                          if bad else "")))
    if histories:  # (issue 29, wt-codesth29) code_check.json gets a time_history block
        check = th.beside(pounding_model, check, records, target, solver, duration)
    if out is not None:
        path = write_code_check(check, out, overwrite=overwrite, source=str(model))
        console.print(Text(f"written: {path}"))
    return 0
