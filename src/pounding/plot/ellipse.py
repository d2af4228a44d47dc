"""The seed paper's Fig 2: hysteresis loop of a spring and a dashpot in parallel."""

from __future__ import annotations

from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from pounding.contact.link_element import ellipse_area, harmonic_loop
from pounding.plot import new_figure
from pounding.plot.layout import MM, display_scale, place_legend, plain_ticks


def plot_hysteresis_ellipse(k: float, c: float, omega: float, delta0: float,
                            n: int = 721) -> Figure:
    """Seed Fig 2 for ``δ = δ0 sin(ω t)``: spring line, dashpot ellipse, combined loop.

    * blue: ``f_S = k δ`` (eq 3) — a line, no dissipated energy;
    * green: ``f_D = c δ̇`` against δ — the ellipse of eq 9, area ``π c ω δ0²`` (eq 10);
    * red: ``f = f_S + f_D`` (eqs 4–5) — the same ellipse sheared ("rotated") by the spring,
      enclosing the same area.

    Parameters
    ----------
    k : float
        Spring stiffness [N/m].
    c : float
        Dashpot coefficient [N·s/m].
    omega : float
        Circular frequency [rad/s].
    delta0 : float
        Amplitude [m].
    n : int
        Samples over the cycle.

    Returns
    -------
    matplotlib.figure.Figure
        Write it with :func:`pounding.plot.save_figure`.
    """
    loop = harmonic_loop(k, c, omega, delta0, n=n)
    e_d = ellipse_area(c, omega, delta0)
    force = display_scale("N", float(abs(loop.f_total).max()))
    joules, stiff, dash = (display_scale(u, v) for u, v in (("J", e_d), ("N/m", k),
                                                             ("N·s/m", c)))
    fig = new_figure(6.4, 4.8, laid_out=False)
    ax = fig.add_subplot(1, 1, 1)
    d = loop.delta * MM.factor
    ax.plot(d, loop.f_spring * force.factor, color="tab:blue", lw=1.6,
            label=r"spring $f_S = k\delta$")
    ax.plot(d, loop.f_dashpot * force.factor, color="tab:green", lw=1.6,
            label=r"dashpot $f_D = c\dot\delta$ (eq 9)")
    ax.plot(d, loop.f_total * force.factor, color="tab:red", lw=1.8,
            label=r"link $f = k\delta + c\dot\delta$ (eq 5)")
    ax.plot([], [], " ", label=rf"$E_D = \pi c \omega \delta_0^2$ = "
            f"{e_d * joules.factor:.4g} {joules.unit} (eq 10)")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.axvline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel(f"penetration δ [{MM.unit}]")
    ax.set_ylabel(f"force [{force.unit}]")
    ax.set_title(f"Hysteresis loop of the link element (seed Fig 2)\n"
                 f"k = {k * stiff.factor:.3g} {stiff.unit}, c = {c * dash.factor:.3g} "
                 f"{dash.unit}, ω = {omega:.3g} rad/s, δ0 = {delta0 * MM.factor:.3g} {MM.unit}",
                 fontsize=10, pad=14)
    ax.xaxis.set_major_locator(MaxNLocator(6))
    ax.grid(True, lw=0.4, alpha=0.5)
    plain_ticks(fig)
    place_legend(ax, fontsize=8, framealpha=0.9)
    return fig
