"""`pounding zeta | audit | collide | calibrate | fit`: the contact core on the command line."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich import box
from rich.table import Table
from rich.text import Text

from pounding.cli.app import app, console

if TYPE_CHECKING:
    import numpy as np

SHORT = {"anagnostopoulos": "ζ Anag.", "schwager-poschel": "ζ S&P", "jankowski": "ζ Jank.(19)", "mahmoud": "ζ Mahm.(20)",
         "naderpour": "ζ eq 39", "hunt-crossley": "χ H-C", "lankarani-nikravesh": "χ L-N",
         "flores": "χ Flores", "gonthier": "χ Gonth.",
         "exact-modified-kelvin-voigt": "ζ mod. K-V", "exact-hunt-crossley": "χ Hunt-Crossley",
         "exact-nonlinear-viscoelastic": "ζ nonlin. visc."}
"""Column titles of `pounding zeta` (full names and sources: `pounding.contact.FORMULAS`)."""

E_HELP = "Coefficients of restitution, comma-separated (default: the seed's Table 1, 0.1 ... 0.9)."


def _parse_floats(text: str | None, name: str, default: tuple[float, ...]) -> np.ndarray:
    import numpy as np

    if text is None:
        return np.asarray(default, dtype=float)
    try:
        return np.asarray([float(x) for x in text.split(",") if x.strip()], dtype=float)
    except ValueError:
        raise ValueError(f"{name}: expected comma-separated numbers (got {text!r})") from None


def _col(table: Table, title: str, **kw) -> None:
    table.add_column(Text(title), **kw)


# options shared by the impact commands (each command sets its own default)
Mass1 = Annotated[float, typer.Option(help="Mass of body 1 (kg).")]
Mass2 = Annotated[float, typer.Option(help="Mass of body 2 (kg).")]
ImpactVelocity = Annotated[float, typer.Option(help="Impact velocity (m/s).")]
HertzStiffness = Annotated[float, typer.Option("--k-h", help="Hertz stiffness (N/m^1.5).")]
LinearStiffness = Annotated[float, typer.Option("--k", help="Linear stiffness (N/m).")]
Tension = Annotated[bool, typer.Option(
    "--tension/--no-tension",
    help="Kelvin-Voigt: may the dashpot pull before separation (model-file key tension; "
         "default no: the force is clipped at zero, as buildings cannot pull each other; "
         "--tension is OpenSees' ViscoelasticGap).")]

LawName = Annotated[str, typer.Argument(help="linear-spring, kelvin-voigt, modified-kelvin-voigt, "
                                        "hertz, hunt-crossley, hertzdamp, nonlinear-viscoelastic, "
                                        "naderpour, bilinear-impact.")]


@app.command("zeta")
def zeta_cmd(
    e: Annotated[str | None, typer.Option("--e", help=E_HELP)] = None,
    plot: Annotated[Path | None, typer.Option("--plot", metavar="FILE",
                    help="Draw the seed's Fig 4 (every formula against e) to FILE.")] = None,
) -> None:
    """Print the seed's Table 1 beside every damping formula (zeta and chi against e).

    Examples:

      pounding zeta

      pounding zeta --e 0.3,0.5,0.7 --plot fig4.png
    """
    from pounding.contact.restitution import FORMULAS, PUBLISHED, TABLE1_E, TABLE1_ZETA
    from pounding.io import check_output_file
    from pounding.validation import restitution

    check_output_file(plot, "--plot", figure=True)

    values = restitution(_parse_floats(e, "--e", TABLE1_E), "--e")
    table = Table(title="Impact damping from the coefficient of restitution e (all dimensionless)",
                  box=box.SIMPLE_HEAD)
    _col(table, "e", justify="right")
    _col(table, "Table 1", justify="right", no_wrap=True)
    published = [FORMULAS[key] for key in PUBLISHED]
    for f in published:
        _col(table, SHORT[f.key], justify="right", no_wrap=True)
    table1 = dict(zip(TABLE1_E, TABLE1_ZETA))
    for x in values:
        printed = next((f"{v:.2f}" for k, v in table1.items() if abs(k - x) < 1e-12), "")
        table.add_row(f"{x:.3g}", printed, *(f"{float(f(x)):.4g}" for f in published))
    table.caption = ("Anag. = Anagnostopoulos 1988 (Kelvin-Voigt with tension); S&P = Schwager & "
                     "Pöschel 2007 (Kelvin-Voigt without tension, the default); Jank. = Jankowski 2006 (seed eq 19); Mahm. = "
                     "Mahmoud & Jankowski 2011 (seed eq 20); eq 39 = Naderpour et al. 2015; H-C = "
                     "Hunt & Crossley 1975; L-N = Lankarani & Nikravesh 1990 (Hertzdamp); Flores = "
                     "Ye et al. 2009 / Flores et al. 2011; Gonth. = Gonthier et al. 2004")
    console.print(table)
    exact = [f for f in FORMULAS.values() if f.key not in PUBLISHED]
    ex = Table(title="Exact damping for e: each law's own e inverted (the laws' defaults; "
                     "Kelvin-Voigt's is S&P above)", box=box.SIMPLE_HEAD)
    _col(ex, "e", justify="right")
    for f in exact:
        _col(ex, SHORT[f.key], justify="right", no_wrap=True)
    for x in values:
        ex.add_row(f"{x:.3g}", *(f"{float(f(x)):.4g}" for f in exact))
    console.print(ex)
    console.print("ζ: damping ratio of the viscoelastic laws (c = 2ζ sqrt(k m_eff) or seed "
                  "eq 18); χ: factor of F = k δⁿ (1 + χ δ̇/v0). Table 1 = eq 39 as printed.")
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.contact import plot_damping_formulas

        console.print(f"figure: {save_figure(plot_damping_formulas(), plot)}", highlight=False)


@app.command("audit")
def audit_cmd(
    e: Annotated[str | None, typer.Option("--e", help=E_HELP)] = None,
    m1: Mass1 = 2.0e5,
    m2: Mass2 = 3.0e5,
    v0: ImpactVelocity = 0.5,
    k_h: HertzStiffness = 2.75e9,
    k: LinearStiffness = 9.3e8,
    plot: Annotated[Path | None, typer.Option("--plot", metavar="FILE",
                    help="Draw achieved against target e to FILE.")] = None,
    csv: Annotated[Path | None, typer.Option("--csv", metavar="FILE",
                   help="Write the full audit table to FILE (CSV).")] = None,
) -> None:
    """Restitution audit: the e each formula really achieves, with each law, in a simulated impact.

    Examples:

      pounding audit

      pounding audit --e 0.5,0.7 --csv audit.csv --plot audit.png
    """
    from pounding.contact.audit import PAIRINGS, AuditCase, restitution_audit
    from pounding.contact.restitution import TABLE1_E
    from pounding.io import check_output_file
    from pounding.validation import restitution

    check_output_file(plot, "--plot", figure=True)
    check_output_file(csv, "--csv")

    targets = restitution(_parse_floats(e, "--e", TABLE1_E), "--e")
    case = AuditCase(m1=m1, m2=m2, v0=v0, k_h=k_h, k=k)
    with console.status(f"simulating {len(PAIRINGS) * targets.size} impacts ..."):
        df = restitution_audit(targets, case)
    table = Table(title=f"Restitution audit: achieved e for target e (m1={m1:g} kg, m2={m2:g} kg, "
                        f"v0={v0:g} m/s)")
    _col(table, "formula")
    _col(table, "law")
    for x in targets:
        _col(table, f"{x:.3g}", justify="right")
    _col(table, "max |err|", justify="right")
    for (formula, law), g in df.groupby(["formula", "law"], sort=False):
        mark = "" if bool(g["intended"].iloc[0]) else " *"
        cells = [f"{v:.4f}" if s else "stuck" for v, s in zip(g["achieved_e"], g["separated"])]
        table.add_row(formula, law + mark, *cells, f"{g['error'].abs().max():.4f}")
    console.print(table)
    console.print("* the formula was not derived for this law. 'stuck': the bodies never separate "
                  f"(e = 0). Energy check: max |W - ½m(1-e²)v0²| / ½mv0² = "
                  f"{df['energy_error'].max():.1e}.", highlight=False)
    if csv is not None:
        from pounding.io import write_text

        write_text(csv, df.to_csv(index=False))
        console.print(f"table: {csv}", highlight=False)
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.contact import plot_audit

        console.print(f"figure: {save_figure(plot_audit(df), plot)}", highlight=False)


@app.command("collide")
def collide_cmd(
    law: LawName,
    e: Annotated[float | None, typer.Option("--e", help="Target coefficient of restitution.")] = None,
    formula: Annotated[str | None, typer.Option(help="Damping formula for e (default: the one exact for the law, so the impact achieves e; or a published one by name, as `pounding zeta` lists).")] = None,
    m1: Mass1 = 2.0e5,
    m2: Mass2 = 3.0e5,
    v0: ImpactVelocity = 0.5,
    k_h: HertzStiffness = 2.75e9,
    k: LinearStiffness = 9.3e8,
    tension: Tension = False,
    delta_m: Annotated[float | None, typer.Option("--delta-m", help="Bilinear: assumed max penetration (m); default the penetration this impact reaches (exact formula) or the elastic Hertz one (--formula muthukumar).")] = None,
) -> None:
    """Simulate one impact of two free masses and report what the law really does.

    Examples:

      pounding collide nonlinear-viscoelastic --e 0.65

      pounding collide kelvin-voigt --e 0.5 --m1 1e5 --m2 1e5 --tension
    """
    from pounding.contact.base import m_effective
    from pounding.contact.bilinear import exact_delta_m
    from pounding.contact.calibration import hertz_delta_max
    from pounding.contact.collision import simulate_collision
    from pounding.contact.factory import LAW_NAMES, is_exact, make_law, resolve_formula
    from pounding.validation import choice

    name = choice("law", law, LAW_NAMES)
    if name == "bilinear-impact" and delta_m is None and e is not None:
        # the penetration the element reaches in this impact (exact sizing), or Muthukumar's
        # elastic Hertz one
        delta_m = (hertz_delta_max(k_h, m_effective(m1, m2), v0)
                   if resolve_formula(name, formula) == "muthukumar"
                   else exact_delta_m(k_h, e, m_effective(m1, m2), v0))
    obj = make_law(name, k=k, k_h=k_h, e=e, formula=formula, m1=m1, m2=m2,
                   tension=tension, delta_m=delta_m)
    used = resolve_formula(name, formula, tension) if e is not None else None
    r = simulate_collision(obj, m1, m2, v0)
    table = Table(title=obj.readable())
    _col(table, "quantity")
    _col(table, "value", justify="right")
    rows = [("target e", f"{e:.6g}" if e is not None else "-"),
            ("damping formula for e", "-" if used is None else used + (
                " (exact for this law)" if is_exact(name, formula, tension)
                else " (published; not exact for this law)")),
            ("achieved e", f"{r.e:.6f}" if r.separated else "0 (stuck: the bodies never "
                                                             "separate)"),
            ("contact duration [s]", f"{r.duration:.6e}" if r.separated else "stuck"),
            ("time to max compression [s]", f"{r.time_to_max:.6e}"),
            ("max penetration [m]", f"{r.delta_max:.6e}"),
            ("peak force [N]", f"{r.peak_force:.6e}"),
            ("energy dissipated ∫F dδ [J]", f"{r.energy_dissipated:.6e}"),
            ("½ m_eff v0² (1 − e²) [J]", f"{r.energy_expected:.6e}")]
    for name, value in rows:
        table.add_row(Text(name), value)
    console.print(table)


@app.command("calibrate")
def calibrate_cmd(
    law: LawName,
    e: Annotated[float, typer.Option("--e", help="Target coefficient of restitution.")],
    m1: Mass1 = 2.0e5,
    m2: Mass2 = 3.0e5,
    v0: ImpactVelocity = 0.5,
    k_h: HertzStiffness = 2.75e9,
    k: LinearStiffness = 9.3e8,
    tension: Tension = False,
) -> None:
    """Find the damping that makes a law achieve exactly the target e.

    Examples:

      pounding calibrate hunt-crossley --e 0.6

      pounding calibrate nonlinear-viscoelastic --e 0.3 --v0 1.0
    """
    from pounding.contact.calibration import calibrate, calibrate_bilinear
    from pounding.contact.factory import make_law

    name = law.strip().lower()
    if name == "bilinear-impact":
        cal = calibrate_bilinear(k_h, e, m1, m2, v0)
    else:
        start = make_law(name, k=k, k_h=k_h, e=e, m1=m1, m2=m2, tension=tension) \
            if name not in ("linear-spring", "hertz") else make_law(name, k=k, k_h=k_h)
        cal = calibrate(start, e, m1, m2, v0)
    unit = cal.law.field_unit(cal.parameter)
    console.print(f"{cal.law.readable()}\n{cal.parameter} = {cal.value:.10g}"
                  + (f" {unit}" if unit not in ("", "-") else "") + f" ({cal.method}); "
                  f"achieved e = {cal.achieved_e:.8f} for target {cal.target_e:g}",
                  highlight=False)


@app.command("fit")
def fit_cmd(
    force_file: Annotated[Path, typer.Argument(help="Two columns: time after first contact (s), contact force (N); '#' comments, comma or space separated.")],
    m1: Mass1,
    m2: Mass2,
    v0: Annotated[float, typer.Option(help="Measured impact velocity (m/s).")],
    law: Annotated[str, typer.Option(help="Law to fit: linear-spring, kelvin-voigt, modified-kelvin-voigt, hertz, hunt-crossley, nonlinear-viscoelastic.")] = "hunt-crossley",
) -> None:
    """Fit a law's stiffness and damping to a measured impact-force history (least squares).

    Examples:

      pounding fit force.csv --m1 2e5 --m2 3e5 --v0 0.5 --law hunt-crossley
    """
    from dataclasses import fields

    import numpy as np

    from pounding.contact.base import SYMBOLS
    from pounding.contact.calibration import fit_impact

    try:
        data = np.loadtxt(force_file, comments="#", delimiter="," if force_file.suffix == ".csv" else None, ndmin=2)
    except ValueError as exc:
        raise ValueError(f"{force_file}: cannot read two numeric columns ({exc})") from None
    if data.shape[1] < 2:
        raise ValueError(f"{force_file}: expected two columns (time, force), found {data.shape[1]}")
    fit = fit_impact(data[:, 0], data[:, 1], m1, m2, v0, law=law)
    table = Table(title=f"Fit of {fit.law.label} to {force_file.name}")
    _col(table, "parameter")
    _col(table, "value", justify="right")
    stiffness = fields(fit.law)[0].name  # k, k_h: the first field of every fitted law
    for name, value in fit.parameters.items():
        field = stiffness if name == "stiffness" else name
        label = (f"stiffness {field}" if name == "stiffness"
                 else f"damping {SYMBOLS.get(name, name)}")
        table.add_row(f"{label} [{fit.law.field_unit(field)}]", f"{value:.6g}")
    table.add_row("RMS residual [N]", f"{fit.residual_rms:.4g}")
    table.add_row("RMS residual / peak force [%]", f"{100 * fit.relative_residual:.3f}")
    table.add_row("achieved e [-]", f"{fit.achieved_e:.4f}")
    console.print(table)
