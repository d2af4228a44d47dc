"""`pounding ellipse`: energy per cycle of the seed's link element and its Fig 2."""

from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, energy_scale, literal, number, print_table


@app.command("ellipse")
def ellipse(
    k: Annotated[float, typer.Option("--k", metavar="N/M", help=opt.K_HELP + " Of the link "
                                     "element's spring.")] = 1e8,
    c: Annotated[float | None, typer.Option("--c", metavar="N·S/M", help=opt.escape(
        "Dashpot coefficient c [N·s/m]. Default: from --zeta by eq 12."),
        show_default=False)] = None,
    zeta: Annotated[float | None, typer.Option("--zeta", metavar="RATIO", help=(
        "Damping ratio ζ; c = 2kζ/ω_n (eq 12). Default: 0.05 when --c is not given."),
        show_default=False)] = None,
    mass: Annotated[float, typer.Option("--mass", metavar="KG", help=opt.escape(
        "Mass m [kg]; ω_n = sqrt(k/m)."))] = 1e6,
    omega: Annotated[float | None, typer.Option("--omega", metavar="RAD/S", help=opt.escape(
        "Circular frequency ω [rad/s] of δ = δ0 sin ωt. Default: ω_n."),
        show_default=False)] = None,
    period: Annotated[float | None, typer.Option("--period", metavar="SECONDS", help=opt.escape(
        "Period T [s] of δ = δ0 sin ωt; ω = 2π/T."), show_default=False)] = None,
    delta0: Annotated[float, typer.Option("--delta0", metavar="M", help=opt.escape(
        "Amplitude δ0 [m]."))] = 0.01,
    n: Annotated[int, typer.Option("--n", metavar="N", min=3, help="Samples over the "
                                   "cycle.")] = 2001,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: the seed's Fig 2.",
        show_default=False)] = None,
) -> None:
    """Energy dissipated per cycle by a spring + dashpot link element (seed eqs 1-12, Fig 2).

    Examples:

      pounding ellipse

      pounding ellipse --zeta 0.1 --period 0.5 --plot fig2.png
    """
    import numpy as np

    from pounding.io.files import check_output_file

    check_output_file(plot, "--plot", figure=True)

    from pounding.contact.link_element import (
        damping_coefficient_viscous,
        dissipated_energy,
        ellipse_area,
        harmonic_loop,
        loop_area,
        spring_work,
        zeta_from_eq11,
    )
    from pounding.validation import non_negative, positive

    kk = positive("k", k)
    mm = positive("mass", mass)
    omega_n = float(np.sqrt(kk / mm))
    if c is not None and zeta is not None:
        raise ValueError(f"c and zeta: give one, not both (got c={c:g}, zeta={zeta:g})")
    if omega is not None and period is not None:
        raise ValueError(f"omega and period: give one, not both "
                         f"(got omega={omega:g}, period={period:g})")
    if c is None:
        z = non_negative("zeta", 0.05 if zeta is None else zeta)
        cc = damping_coefficient_viscous(kk, z, omega_n)
    else:
        cc = non_negative("c", c)
    w = (positive("omega", omega) if omega is not None
         else 2.0 * np.pi / positive("period", period) if period is not None else omega_n)
    d0 = positive("delta0", delta0)

    loop = harmonic_loop(kk, cc, w, d0, n=n)
    e10 = ellipse_area(cc, w, d0)
    e1 = dissipated_energy(loop.t, loop.delta, cc)
    a_total = loop_area(loop.delta, loop.f_total)
    a_dash = loop_area(loop.delta, loop.f_dashpot)
    e2 = spring_work(loop.t, loop.delta, kk)

    print_table(console, "Link element under δ = δ0 sin ωt",
                [Col("input", "left", wrap=True), Col("value"), Col("unit", "left")],
                [(literal(name), f"{val:.6g}", unit) for name, val, unit in [
                    ("k", kk, "N/m"), ("m", mm, "kg"), ("ω_n = sqrt(k/m)", omega_n, "rad/s"),
                    ("ω", w, "rad/s"), ("c", cc, "N·s/m"),
                    ("ζ = c ω_n / 2k (eqs 11-12)", zeta_from_eq11(cc, kk, w, omega_n), "-"),
                    ("δ0", d0, "m")]])

    def rel(x: float) -> str:
        return f"{(x - e10) / e10:+.2e}" if e10 > 0 else "-"

    scale, unit = energy_scale(max(abs(e10), abs(e1), abs(a_total), abs(a_dash)))
    if max(abs(e10), abs(e1)) < 1e3:  # below a kJ: in J
        scale, unit = 1.0, "J"
    print_table(console, "Energy per cycle",
                [Col("quantity", "left", wrap=True), Col(f"value [{unit}]"),
                 Col("rel. diff. from eq 10")],
                [("E_D = π c ω δ0² (eq 10)", number(e10 * scale, 6), "0"),
                 ("E_D = ∫ c δ̇² dt, trapezoid (eq 1)", number(e1 * scale, 6), rel(e1)),
                 ("loop f = kδ + cδ̇, shoelace (eq 5)", number(a_total * scale, 6),
                  rel(a_total)),
                 ("ellipse f_D, shoelace (eq 9)", number(a_dash * scale, 6), rel(a_dash)),
                 ("E_S = ∫ k δ δ̇ dt, one cycle (eq 2)", f"{e2 * scale:.3g}", "-")])

    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.ellipse import plot_hysteresis_ellipse

        fig = plot_hysteresis_ellipse(kk, cc, w, d0)
        out = save_figure(fig, plot)
        console.print(Text(f"figure: {out}"))
