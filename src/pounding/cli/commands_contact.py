"""`pounding zeta | audit | collide | calibrate | fit`: the contact core on the command line."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, energy_scale, force_scale, literal, number, print_table

SHORT = {"anagnostopoulos": "ζ Anag.", "schwager-poschel": "ζ S&P", "jankowski": "ζ Jank.(19)",
         "mahmoud": "ζ Mahm.(20)", "naderpour": "ζ eq 39", "hunt-crossley": "χ H-C",
         "lankarani-nikravesh": "χ L-N", "flores": "χ Flores", "gonthier": "χ Gonth.",
         "exact-modified-kelvin-voigt": "ζ mod. K-V", "exact-hunt-crossley": "χ Hunt-Crossley",
         "exact-nonlinear-viscoelastic": "ζ nonlin. visc."}
"""Column titles of `pounding zeta` (full names and sources: `pounding.contact.FORMULAS`)."""

LAW_CHOICES = ", ".join(law.value for law in opt.Law)

LawOption = Annotated[opt.Law, typer.Option(
    "--law", metavar="LAW", case_sensitive=False, help=f"{opt.LAW_HELP} One of "
    f"{LAW_CHOICES}.", show_default=False)]
"""``--law`` of ``collide`` and ``calibrate`` (required)."""

FitLaw = Annotated[opt.Law, typer.Option(
    "--law", metavar="LAW", case_sensitive=False, help=f"{opt.LAW_HELP} One with a "
    "stiffness and at most one damping parameter to fit: linear-spring, kelvin-voigt, "
    "modified-kelvin-voigt, hertz, hunt-crossley, nonlinear-viscoelastic.",
    show_default=False)]
"""``--law`` of ``fit`` (required)."""

ETargets = Annotated[str | None, typer.Option(
    "--e", metavar="LIST", help=opt.E_HELP + " One impact for each; required for a damped "
    "law (none for linear-spring or hertz).", show_default=False)]
"""``--e`` of ``collide``."""

ERequired = Annotated[str, typer.Option(
    "--e", metavar="LIST", help=opt.E_HELP + " The targets to calibrate for.",
    show_default=False)]
"""``--e`` of ``calibrate`` (required)."""

PlotOption = Annotated[Path | None, typer.Option(
    "--plot", metavar="FILE", help=opt.PLOT_HELP, show_default=False)]


def _restitutions(text: str | None, default: tuple[float, ...]) -> list[float]:
    """The coefficients of ``--e`` (``default`` when not given), each checked."""
    from pounding.validation import restitution

    values = opt.split_floats(text, "--e")
    return [float(restitution(x, "--e")) for x in (default if values is None else values)]


@app.command("zeta")
def zeta_cmd(
    e: opt.ETable = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: the seed's Fig 4, every "
        "formula against e.", show_default=False)] = None,
) -> None:
    """Print the seed's Table 1 beside every damping formula (zeta and chi against e).

    Examples:

      pounding zeta

      pounding zeta --e 0.3,0.5,0.7 --plot fig4.png
    """
    from pounding.contact.restitution import FORMULAS, PUBLISHED, TABLE1_E, TABLE1_ZETA
    from pounding.io.files import check_output_file

    check_output_file(plot, "--plot", figure=True)

    values = _restitutions(e, TABLE1_E)
    published = [FORMULAS[key] for key in PUBLISHED]
    table1 = dict(zip(TABLE1_E, TABLE1_ZETA))
    rows = [(f"{x:.3g}", next((f"{v:.2f}" for k, v in table1.items() if abs(k - x) < 1e-12),
                              ""), *(f"{float(f(x)):.4g}" for f in published))
            for x in values]
    print_table(console, "Impact damping from the coefficient of restitution e (all "
                         "dimensionless)",
                [Col("e"), Col("Table 1"), *(Col(SHORT[f.key]) for f in published)], rows,
                caption="Anag. = Anagnostopoulos 1988 (Kelvin-Voigt with tension); S&P = "
                        "Schwager & Pöschel 2007 (Kelvin-Voigt without tension, the "
                        "default); Jank. = Jankowski 2006 (seed eq 19); Mahm. = Mahmoud & "
                        "Jankowski 2011 (seed eq 20); eq 39 = Naderpour et al. 2015; H-C = "
                        "Hunt & Crossley 1975; L-N = Lankarani & Nikravesh 1990 (Hertzdamp); "
                        "Flores = Ye et al. 2009 / Flores et al. 2011; Gonth. = Gonthier et "
                        "al. 2004")
    exact = [f for f in FORMULAS.values() if f.key not in PUBLISHED]
    print_table(console, "Exact damping for e: each law's own e inverted (the laws' "
                         "defaults; Kelvin-Voigt's is S&P above)",
                [Col("e"), *(Col(SHORT[f.key]) for f in exact)],
                [(f"{x:.3g}", *(f"{float(f(x)):.4g}" for f in exact)) for x in values])
    console.print(Text("ζ: damping ratio of the viscoelastic laws (c = 2ζ sqrt(k m_eff) or "
                       "seed eq 18); χ: factor of F = k δⁿ (1 + χ δ̇/v0). Table 1 = eq 39 as "
                       "printed."))
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.contact import plot_damping_formulas

        console.print(Text(f"figure: {save_figure(plot_damping_formulas(), plot)}"))


@app.command("audit")
def audit_cmd(
    e: opt.ETable = None,
    m1: opt.Mass1 = 2.0e5,
    m2: opt.Mass2 = 3.0e5,
    v0: opt.ImpactVelocity = 0.5,
    k_h: opt.HertzStiffness = 2.75e9,
    k: opt.LinearStiffness = 9.3e8,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: achieved against target "
        "e.", show_default=False)] = None,
    csv: Annotated[Path | None, typer.Option(
        "--csv", metavar="FILE", help=opt.CSV_HELP + " One row per formula, law and target "
        "e: formula, law, intended, target_e, damping, achieved_e, error, separated, "
        "energy_error, peak_force_N, duration_s.", show_default=False)] = None,
) -> None:
    """Restitution audit: the e each formula really achieves, with each law, in a simulated impact.

    Examples:

      pounding audit

      pounding audit --e 0.5,0.7 --csv audit.csv --plot audit.png
    """
    from pounding.contact.audit import PAIRINGS, AuditCase, restitution_audit
    from pounding.contact.restitution import TABLE1_E
    from pounding.io.files import check_output_file

    check_output_file(plot, "--plot", figure=True)
    check_output_file(csv, "--csv")

    targets = _restitutions(e, TABLE1_E)
    case = AuditCase(m1=m1, m2=m2, v0=v0, k_h=k_h, k=k)
    with console.status(f"simulating {len(PAIRINGS) * len(targets)} impacts ..."):
        df = restitution_audit(targets, case)
    rows = []
    for (formula, law), g in df.groupby(["formula", "law"], sort=False):
        mark = "" if bool(g["intended"].iloc[0]) else " *"
        cells = [f"{v:.4f}" if s else "stuck" for v, s in zip(g["achieved_e"], g["separated"])]
        rows.append((literal(formula), literal(f"{law}{mark}"), *cells,
                     f"{g['error'].abs().max():.4f}"))
    print_table(console, f"Restitution audit: achieved e for target e (m1 = {m1:g} kg, m2 = "
                         f"{m2:g} kg, v0 = {v0:g} m/s)",
                [Col("formula", "left", wrap=True), Col("law", "left", wrap=True),
                 *(Col(f"{x:.3g}") for x in targets), Col("max |err|")], rows, keys=2)
    console.print(Text("* the formula was not derived for this law. 'stuck': the bodies never "
                       "separate (e = 0). Energy check: max |W - ½m(1-e²)v0²| / ½mv0² = "
                       f"{df['energy_error'].max():.1e}."))
    if csv is not None:
        from pounding.io.files import write_text

        write_text(csv, df.rename(columns={"peak_force": "peak_force_N",
                                           "duration": "duration_s"}).to_csv(index=False))
        console.print(Text(f"table: {csv}"))
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.contact import plot_audit

        console.print(Text(f"figure: {save_figure(plot_audit(df), plot)}"))


@app.command("collide")
def collide_cmd(
    law: LawOption,
    e: ETargets = None,
    formula: Annotated[opt.Formula | None, typer.Option(
        "--formula", metavar="FORMULA", case_sensitive=False, help="Damping formula for e. "
        "Default: the one exact for the law, so the impact achieves e; or one of " + ", ".join(
            f.value for f in opt.Formula) + " (`pounding zeta` tabulates them).",
        show_default=False)] = None,
    m1: opt.Mass1 = 2.0e5,
    m2: opt.Mass2 = 3.0e5,
    v0: opt.ImpactVelocity = 0.5,
    k_h: opt.HertzStiffness = 2.75e9,
    k: opt.LinearStiffness = 9.3e8,
    tension: opt.Tension = False,
    delta_m: Annotated[float | None, typer.Option(
        "--delta-m", metavar="M", help=opt.escape(
            "Bilinear: assumed max penetration [m]. Default: the penetration this impact "
            "reaches (exact formula) or the elastic Hertz one (--formula muthukumar)."),
        show_default=False)] = None,
) -> None:
    """Simulate one impact of two free masses and report what the law really does.

    Examples:

      pounding collide --law nonlinear-viscoelastic --e 0.65

      pounding collide --law kelvin-voigt --e 0.5,0.8 --m1 1e5 --m2 1e5 --tension
    """
    from pounding.contact.base import m_effective
    from pounding.contact.bilinear import exact_delta_m
    from pounding.contact.calibration import hertz_delta_max
    from pounding.contact.collision import simulate_collision
    from pounding.contact.factory import is_exact, make_law, resolve_formula

    name = str(law)
    form = None if formula is None else str(formula)
    if e is None and name not in ("linear-spring", "hertz"):
        raise ValueError(f"--e: required for the {name} law (its coefficient of restitution, "
                         "e.g. --e 0.65)")
    targets: list[float | None] = list(_restitutions(e, ())) if e is not None else [None]
    impacts = []
    for target in targets:
        dm = delta_m
        if name == "bilinear-impact" and dm is None and target is not None:
            # the penetration the element reaches in this impact (exact sizing), or
            # Muthukumar's elastic Hertz one
            dm = (hertz_delta_max(k_h, m_effective(m1, m2), v0)
                  if resolve_formula(name, form) == "muthukumar"
                  else exact_delta_m(k_h, target, m_effective(m1, m2), v0))
        obj = make_law(name, k=k, k_h=k_h, e=target, formula=form, m1=m1, m2=m2,
                       tension=tension, delta_m=dm)
        used = resolve_formula(name, form, tension) if target is not None else None
        impacts.append((target, used, obj, simulate_collision(obj, m1, m2, v0)))
    f_scale, f_unit = force_scale(max(r.peak_force for *_, r in impacts))
    # energies in the unit of the impact's kinetic energy ½ m_eff v0², and round-off
    # (below 1e-9 of it: an undamped law's ∫F dδ) shown as 0
    kinetic = 0.5 * m_effective(m1, m2) * v0**2
    e_scale, e_unit = energy_scale(kinetic)

    def energy(value: float) -> str:
        return number(value * e_scale, 6) if abs(value) > 1e-9 * kinetic else "0"

    def column(target: float | None, used: str | None, r: Any) -> list[str]:
        """One impact's cells, in the order of ``quantities``."""
        exact = (" (exact for this law)" if is_exact(name, form, tension)
                 else " (published; not exact for this law)")
        return [f"{target:.6g}" if target is not None else "–",
                "–" if used is None else used + exact,
                f"{r.e:.6f}" if r.separated else "0 (stuck: the bodies never separate)",
                number(1e3 * r.duration, 6) if r.separated else "stuck",
                number(1e3 * r.time_to_max, 6), number(1e3 * r.delta_max, 6),
                number(r.peak_force * f_scale, 6), energy(r.energy_dissipated),
                energy(r.energy_expected)]

    quantities = ["target e", "damping formula for e", "achieved e", "contact duration [ms]",
                  "time to max compression [ms]", "max penetration [mm]",
                  f"peak force [{f_unit}]", f"energy dissipated ∫F dδ [{e_unit}]",
                  f"½ m_eff v0² (1 − e²) [{e_unit}]"]
    cells = [column(t, u, r) for t, u, _, r in impacts]
    rows = [(literal(q), *(c[j] for c in cells)) for j, q in enumerate(quantities)]
    heads = [Col("quantity", "left", wrap=True)]
    heads += [Col("value" if len(impacts) == 1 else f"e = {t:g}", wrap=True)
              for t, *_ in impacts]
    title = impacts[0][2].readable() if len(impacts) == 1 else (
        f"{name}: one impact of m1 = {m1:g} kg and m2 = {m2:g} kg at v0 = {v0:g} m/s")
    print_table(console, title, heads, rows)


@app.command("calibrate")
def calibrate_cmd(
    law: LawOption,
    e: ERequired,
    m1: opt.Mass1 = 2.0e5,
    m2: opt.Mass2 = 3.0e5,
    v0: opt.ImpactVelocity = 0.5,
    k_h: opt.HertzStiffness = 2.75e9,
    k: opt.LinearStiffness = 9.3e8,
    tension: opt.Tension = False,
) -> None:
    """Find the damping that makes a law achieve exactly the target e.

    Examples:

      pounding calibrate --law hunt-crossley --e 0.6

      pounding calibrate --law nonlinear-viscoelastic --e 0.3,0.5 --v0 1.0
    """
    from pounding.contact.calibration import calibrate, calibrate_bilinear
    from pounding.contact.factory import make_law

    name = str(law)
    for target in _restitutions(e, ()):
        if name == "bilinear-impact":
            cal = calibrate_bilinear(k_h, target, m1, m2, v0)
        else:
            start = make_law(name, k=k, k_h=k_h, e=target, m1=m1, m2=m2, tension=tension) \
                if name not in ("linear-spring", "hertz") else make_law(name, k=k, k_h=k_h)
            cal = calibrate(start, target, m1, m2, v0)
        unit = cal.law.field_unit(cal.parameter)
        console.print(Text(f"{cal.law.readable()}\n{cal.parameter} = {cal.value:.10g}"
                           + (f" {unit}" if unit not in ("", "-") else "")
                           + f" ({cal.method}); achieved e = {cal.achieved_e:.8f} for target "
                             f"{cal.target_e:g}"))


@app.command("fit")
def fit_cmd(
    force_file: Annotated[Path, typer.Argument(
        help="Two columns: time after first contact [s], contact force [N]; '#' comments, "
             "comma or space separated.".replace("[", "\\["), show_default=False)],
    law: FitLaw,
    m1: Annotated[float, typer.Option("--m1", metavar="KG", help=opt.escape(
        "Mass of body 1 [kg]."), show_default=False)],
    m2: Annotated[float, typer.Option("--m2", metavar="KG", help=opt.escape(
        "Mass of body 2 [kg]."), show_default=False)],
    v0: Annotated[float, typer.Option("--v0", metavar="M/S", help=opt.escape(
        "Impact velocity [m/s]. As measured."), show_default=False)],
) -> None:
    """Fit a law's stiffness and damping to a measured impact-force history (least squares).

    Examples:

      pounding fit force.csv --law hunt-crossley --m1 2e5 --m2 3e5 --v0 0.5
    """
    import numpy as np

    from pounding.contact.base import SYMBOLS
    from pounding.contact.calibration import fit_impact

    try:
        data = np.loadtxt(force_file, comments="#",
                          delimiter="," if force_file.suffix == ".csv" else None, ndmin=2)
    except ValueError as exc:
        raise ValueError(f"{force_file}: cannot read two numeric columns ({exc})") from None
    if data.shape[1] < 2:
        raise ValueError(f"{force_file}: expected two columns (time, force), found "
                         f"{data.shape[1]}")
    fit = fit_impact(data[:, 0], data[:, 1], m1, m2, v0, law=str(law))
    from dataclasses import fields

    stiffness = fields(fit.law)[0].name  # k, k_h: the first field of every fitted law
    rows: list[tuple[str | Text, str]] = []
    for key, value in fit.parameters.items():
        field = stiffness if key == "stiffness" else key
        label = (f"stiffness {field}" if key == "stiffness"
                 else f"damping {SYMBOLS.get(key, key)}")
        rows.append((literal(f"{label} [{fit.law.field_unit(field)}]"), f"{value:.6g}"))
    f_scale, f_unit = force_scale(float(np.max(np.abs(data[:, 1]))))
    rows += [(f"RMS residual [{f_unit}]", number(fit.residual_rms * f_scale)),
             ("RMS residual / peak force [%]", f"{100 * fit.relative_residual:.3f}"),
             ("achieved e [-]", f"{fit.achieved_e:.4f}")]
    print_table(console, f"Fit of {fit.law.label} to {force_file.name}",
                [Col("parameter", "left", wrap=True), Col("value")], rows)
