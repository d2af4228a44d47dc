"""`pounding code-check`: a code's required separation beside the model's gaps."""

from __future__ import annotations

from enum import StrEnum
from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import code_check_time_history as th
from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, literal, print_table

# one list of codes for every --code (options.Code)
SeparationCode = opt.Code
"""The codes of ``pounding code-check --code`` (:data:`pounding.studies.codes.CODES`)."""


class Procedure(StrEnum):
    """ASCE 7-22's analyses for δ_max (:data:`pounding.studies.codes.asce7_22.PROCEDURES`)."""

    modal = "modal"
    elf = "elf"


SYMBOLS: dict[str, str] = {"asce7-22": "δ_M", "en1998-1": "d_s", "nzs1170.5": "d",
                           "nbcc2020": "Δ", "is1893": "RΔ"}
"""The symbol of each code's displacement in the table's headers."""


class Combination(StrEnum):
    """Modal combination rules (:data:`pounding.studies.codes.COMBINATIONS`)."""

    cqc = "cqc"
    srss = "srss"


@app.command("code-check", context_settings=opt.CODE_CONTEXT)  # (the old --code spelling)
def code_check_cmd(
    model: Annotated[Path, typer.Argument(
        help="TOML model file, as for `pounding run` (its buildings and gaps are checked; "
             "its record and contact law are not used).", show_default=False)],
    code: Annotated[SeparationCode, typer.Option(
        "--code", metavar="CODE", help=f"{opt.CODE_HELP} Its separation rule is checked: "
        "asce7-22, en1998-1, nzs1170.5, nbcc2020 or is1893.",
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
        "12.2-1); is1893: response reduction factor R (Table 9).", show_default=False)]
        = None,
    ie: Annotated[float | None, typer.Option(
        "--ie", metavar="VALUE", help="asce7-22: importance factor I_e (Table 1.5-2); "
        "nbcc2020: earthquake importance factor I_E (Table 4.1.8.5).",
        show_default=False)] = None,
    # ASCE 7-22's ELF route and the codes nzs1170.5, nbcc2020, is1893 (their parameters;
    # each refused with the other codes)
    procedure: Annotated[Procedure | None, typer.Option(
        "--procedure", help="asce7-22: δ_max by the modal response spectrum analysis "
        "(§12.9.1) or the equivalent lateral force procedure (§12.8). Default: modal.",
        show_default=False)] = None,
    s1: Annotated[float | None, typer.Option(
        "--s1", metavar="G", help="asce7-22: mapped S1 \\[g] (§11.4.2), for eq. 12.8-6 "
        "(C_s ≥ 0.5 S1/(R/I_e) where S1 ≥ 0.6 g). Default: eq. 12.8-6 not checked.",
        show_default=False)] = None,
    z: Annotated[float | None, typer.Option(
        "--z", metavar="VALUE", help="nzs1170.5: hazard factor Z (§3.1.4); is1893: zone "
        "factor Z (Table 3).", show_default=False)] = None,
    ru: Annotated[float | None, typer.Option(
        "--ru", metavar="VALUE", help="nzs1170.5: return period factor R_u (Table 3.5).",
        show_default=False)] = None,
    site_class: Annotated[str | None, typer.Option(
        "--site-class", metavar="A-E", help="nzs1170.5: site subsoil class (§3.1.3).",
        show_default=False)] = None,
    mu: Annotated[float | None, typer.Option(
        "--mu", metavar="VALUE", help="nzs1170.5: structural ductility factor μ (§4.3).",
        show_default=False)] = None,
    s_table: Annotated[str | None, typer.Option(
        "--s-table", metavar="S0.2,S0.5,S1,S2,S5,S10", help="nbcc2020: the site's design "
        "S(T) \\[g] at 0.2, 0.5, 1, 2, 5 and 10 s (Sentence 4.1.8.4).",
        show_default=False)] = None,
    rd: Annotated[float | None, typer.Option(
        "--rd", metavar="VALUE", help="nbcc2020: ductility-related force modification "
        "factor R_d (Table 4.1.8.9).", show_default=False)] = None,
    ro: Annotated[float | None, typer.Option(
        "--ro", metavar="VALUE", help="nbcc2020: overstrength-related force modification "
        "factor R_o (Table 4.1.8.9).", show_default=False)] = None,
    soil_type: Annotated[str | None, typer.Option(
        "--soil-type", metavar="I|II|III", help="is1893: soil type (Table 4).",
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
        "--importance", metavar="VALUE", help="en1998-1: importance factor γ_I (§4.2.5), "
        "default 1; is1893: importance factor I (Table 8).", show_default=False)] = None,
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
    # the time histories beside the check (cli/code_check_time_history.py)
    time_history: th.TimeHistory = False,
    suite: th.Suite = None,
    design: th.Design = None,
    duration: th.Duration = None,
) -> int:
    """The separation a seismic code asks for between neighbouring buildings, beside the
    model's gaps, floor by floor, each number with its clause.

    Codes: asce7-22 (§12.12), en1998-1 (§4.4.2.7), nzs1170.5 (§7.4), nbcc2020 (Sentence
    4.1.8.14), is1893 (§7.11.3). The code's displacements come from the model's own
    buildings: a modal response spectrum analysis on the code's design spectrum (linear,
    every mode), or for asce7-22 with --procedure elf its equivalent lateral force
    procedure. Each code's options are refused with another code. Exit status 0 whether
    or not the gaps meet the code (the table says OK / not OK).

    Examples:

      pounding code-check examples/two_10_storey.toml --code asce7-22 --sds 1.0 --sd1 0.6 --tl 8 --cd 5.5 --r 8 --ie 1

      pounding code-check examples/two_10_storey.toml --code asce7-22 --procedure elf --s1 0.75 --sds 1.0 --sd1 0.6 --tl 8 --cd 5.5 --r 8 --ie 1

      pounding code-check examples/two_10_storey.toml --code en1998-1 --agr 0.25 --ground-type C --spectrum-type 1 --q 4 --out check

      pounding code-check examples/two_10_storey.toml --code nzs1170.5 --z 0.4 --ru 1 --site-class C --mu 4

      pounding code-check examples/two_10_storey.toml --code nbcc2020 --s-table 0.85,0.75,0.42,0.26,0.085,0.03 --rd 5 --ro 1.5 --ie 1

      pounding code-check examples/two_10_storey.toml --code is1893 --z 0.36 --importance 1.2 --r 5 --soil-type II

      pounding code-check examples/two_10_storey.toml --code asce7-22 --sds 1.0 --sd1 0.6 --tl 8 --cd 5.5 --r 8 --ie 1 --time-history
    """
    from pounding.config import load_config
    from pounding.studies.codes import code_check, write_code_check

    if out is not None:  # refuse a bad --out before any computation
        from pounding.io.manifest import check_out_folder

        check_out_folder(out, overwrite, "code-check")
    # every code's options: those of another code refused, a missing one named
    from pounding.studies.codes import code_parameters

    given = {"sds": sds, "sd1": sd1, "tl": tl, "cd": cd, "r": r, "ie": ie,
             "procedure": None if procedure is None else procedure.value, "s1": s1,
             "agr": agr, "ground_type": ground_type, "spectrum_type": spectrum_type, "q": q,
             "qd": qd, "importance": importance, "beta": beta, "z": z, "ru": ru,
             "site_class": site_class, "mu": mu, "s_table": s_table, "rd": rd, "ro": ro,
             "soil_type": soil_type}
    accepted = code_parameters(code.value)
    foreign = next((k for k, v in given.items() if v is not None and k not in accepted), None)
    if foreign is not None:
        raise ValueError(f"--{foreign.replace('_', '-')}: not a parameter of --code "
                         f"{code.value} (got {given[foreign]!r})")
    if property_line and code is SeparationCode.is1893:
        raise ValueError("--property-line: --code is1893 has one rule (§7.11.3: "
                         "R (Δ1 + Δ2), already the sum of the two)")
    mine = {k: v for k, v in given.items() if k in accepted}
    for name, value in mine.items():
        if value is None and accepted[name]:
            raise ValueError(f"--{name.replace('_', '-')}: --code {code.value} needs it "
                             "(got none)")
    histories = th.wanted(time_history, suite, design, duration)
    records, target = th.read_inputs(suite, design, duration) if histories else (None, None)
    cfg = load_config(model)
    pounding_model, _, solver = cfg.build()
    if histories:  # refused before any table is printed
        from pounding.studies.codes.time_history import refuse_linked

        refuse_linked(pounding_model)
    check = code_check(pounding_model, code.value, same_property=not property_line,
                       combination=combination.value, **mine)

    head = [("code", check.title), ("displacement", check.displacement),
            ("parameters", ", ".join(f"{k} = {v}" for k, v in check.parameters.items()
                                     if not isinstance(v, dict))),
            *((name, ", ".join(f"{k} = {v:.4g}" if isinstance(v, float) else f"{k} = {v}"
                               for k, v in values.items()))
              for name, values in check.parameters.get("buildings", {}).items()),
            *((f"T [s] {name}", ", ".join(f"{t:.4g}" for t in periods[:3])
               + (", …" if len(periods) > 3 else ""))
              for name, periods in check.periods.items()),
            *(("assumes", a) for a in check.assumptions)]
    print_table(console, f"{pounding_model.name}: code check", [
        Col("quantity", "left", wrap=True), Col("value", "left", wrap=True)], head,
        show_header=False)
    symbol = SYMBOLS[code.value]
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
    if histories:  # code_check.json gets a time_history block
        check = th.beside(pounding_model, check, records, target, solver, duration)
    if out is not None:
        path = write_code_check(check, out, overwrite=overwrite, source=str(model))
        console.print(Text(f"written: {path}"))
    return 0
