"""`pounding ellipse`: energy per cycle of the seed's link element and its Fig 2."""

from pathlib import Path
from typing import Optional

import typer
from rich.table import Table

from pounding.cli.app import app, console  # noqa: F401


@app.command("ellipse")
def ellipse(
    k: float = typer.Option(1e8, "--k", help="Spring stiffness k (N/m)."),
    c: Optional[float] = typer.Option(None, "--c", help="Dashpot coefficient c (N·s/m) "
                                      "(default: from --zeta by eq 12)."),
    zeta: Optional[float] = typer.Option(None, "--zeta", help="Damping ratio ζ; c = 2kζ/ω_n "
                                         "(eq 12). Default 0.05 when --c is not given."),
    mass: float = typer.Option(1e6, "--mass", help="Mass m (kg); ω_n = sqrt(k/m)."),
    omega: Optional[float] = typer.Option(None, "--omega", help="Circular frequency ω (rad/s) "
                                          "of δ = δ0 sin ωt (default ω_n)."),
    period: Optional[float] = typer.Option(None, "--period", help="Period T (s); ω = 2π/T."),
    delta0: float = typer.Option(0.01, "--delta0", help="Amplitude δ0 (m)."),
    n: int = typer.Option(2001, "--n", help="Samples over the cycle."),
    plot: Optional[Path] = typer.Option(None, "--plot", metavar="FILE",
                                        help="Draw the seed's Fig 2 to FILE."),
) -> None:
    """Energy dissipated per cycle by a spring + dashpot link element (seed eqs 1-12, Fig 2).

    Examples:

      pounding ellipse

      pounding ellipse --zeta 0.1 --period 0.5 --plot fig2.png
    """
    from pounding.io import check_output_file

    check_output_file(plot, "--plot", figure=True)
    import numpy as np

    from pounding.link_element import (
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

    info = Table(title="Link element under δ = δ0 sin ωt", show_header=True)
    info.add_column("input")
    info.add_column("value", justify="right")
    info.add_column("unit")
    for name, val, unit in [("k", kk, "N/m"), ("m", mm, "kg"), ("ω_n = sqrt(k/m)", omega_n, "rad/s"),
                            ("ω", w, "rad/s"), ("c", cc, "N·s/m"),
                            ("ζ = c ω_n / 2k (eqs 11-12)", zeta_from_eq11(cc, kk, w, omega_n), "-"),
                            ("δ0", d0, "m")]:
        info.add_row(name, f"{val:.6g}", unit)
    console.print(info)

    table = Table(title="Energy per cycle", show_header=True)
    table.add_column("quantity")
    table.add_column("value [J]", justify="right")
    table.add_column("rel. diff. from eq 10", justify="right")

    def rel(x: float) -> str:
        return f"{(x - e10) / e10:+.2e}" if e10 > 0 else "-"

    table.add_row("E_D = π c ω δ0² (eq 10)", f"{e10:.6g}", "0")
    table.add_row("E_D = ∫ c δ̇² dt, trapezoid (eq 1)", f"{e1:.6g}", rel(e1))
    table.add_row("loop f = kδ + cδ̇, shoelace (eq 5)", f"{a_total:.6g}", rel(a_total))
    table.add_row("ellipse f_D, shoelace (eq 9)", f"{a_dash:.6g}", rel(a_dash))
    table.add_row("E_S = ∫ k δ δ̇ dt, one cycle (eq 2)", f"{e2:.3g}", "-")
    console.print(table)

    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.ellipse import plot_hysteresis_ellipse

        fig = plot_hysteresis_ellipse(kk, cc, w, d0)
        out = save_figure(fig, plot)
        console.print(f"figure written: {out}")
