"""The figures of a fragility study (``pounding fragility``): IDA curves with their
fractiles, fragility curves with the observed fractions and bootstrap bands, the
probability of pounding against the gap, and its surface over gap and intensity."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure

from pounding.plot import new_figure
from pounding.result.demands import DEMANDS

__all__ = ["plot_fragility", "plot_gap_probability", "plot_gap_surface", "plot_ida"]

RULE_STYLE = {"ABS": "tab:red", "SRSS": "tab:green", "DDC": "tab:purple"}
_FRACTILE_STYLE = (("16 %", "--"), ("50 %", "-"), ("84 %", "--"))


def _gap_text(g: float | None) -> str:
    return "base model's gap" if g is None else f"gap {1000 * g:g} mm"


def _panels(n: int, width: float, height: float) -> tuple[Figure, list[Any]]:
    """A figure of ``n`` panels, at most three a row, each ``width`` × ``height`` inches."""
    ncol = min(3, n)
    nrow = -(-n // ncol)
    fig = new_figure(width * ncol + 0.6, height * nrow + 0.7, laid_out=False)
    return fig, [fig.add_subplot(nrow, ncol, i + 1) for i in range(n)]


def plot_ida(a: Any, gap_index: int = 0) -> Figure:
    """IDA curves: intensity (vertical) against each demand (horizontal), one thin grey line
    per record, and the 16/50/84 % fractiles over the records at each level (Vamvatsikos &
    Cornell 2002), for the runs at one gap."""
    keys = [k for k in a.demands if k != "pounding"]
    fig, axes = _panels(len(keys), 4.0, 3.5)
    x = a.levels
    for i, (k, ax) in enumerate(zip(keys, axes)):
        d = DEMANDS[k]
        v = a.demands[k][gap_index] * d.factor
        for r in range(v.shape[0]):
            ok = np.isfinite(v[r])
            ax.plot(np.r_[0.0, v[r][ok]], np.r_[0.0, x[ok]], color="0.6", lw=0.8,
                    label="each record" if r == 0 else None)
        f = a.fractiles[k][gap_index] * d.factor
        for (name, ls), row in zip(_FRACTILE_STYLE, f):
            ax.plot(np.r_[0.0, row], np.r_[0.0, x], color="k", ls=ls,
                    lw=2.2 if name == "50 %" else 1.4, label=f"{name} fractile")
        ax.set_xlabel(f"{d.label} [{d.unit}]")
        ax.set_ylabel(a.cases.im_label)
        ax.set_xlim(left=0.0)
        ax.set_ylim(0.0, x.max() * 1.03)
        ax.grid(True, alpha=0.3)
        if i == 0:
            ax.legend(fontsize=7, loc="lower right")
    fig.suptitle(f"{a.cases.config.name}: IDA curves of {len(a.records)} records "
                 f"({_gap_text(a.gaps[gap_index])})", fontsize=10)
    fig.tight_layout()
    return fig


def plot_fragility(a: Any) -> Figure:
    """One panel per limit state: the observed fraction of runs exceeding it at each stripe
    (markers), the maximum-likelihood fit to the stripes (Baker 2015, solid) with its
    bootstrap band, and the fit to the IDA capacities (dashed); one colour per gap."""
    specs = list(dict.fromkeys(r.spec.label for r in a.limit_states))
    fig, axes = _panels(len(specs), 4.2, 3.4)
    x = a.levels
    grid = np.linspace(0.0, x.max() * 1.05, 300)[1:]
    conf = a.cases.config.bootstrap.confidence
    for name, ax in zip(specs, axes):
        for gi, r in enumerate([r for r in a.limit_states if r.spec.label == name]):
            c = f"C{gi}"
            tag = "" if len(a.gaps) == 1 else f", {_gap_text(r.gap)}"
            frac = np.where(r.n_runs > 0, r.n_exceed / np.maximum(r.n_runs, 1), np.nan)
            ax.plot(x, frac, "o", color=c, ms=4, label=f"observed fraction{tag}")
            if r.msa.medians.size:
                lo, hi = r.msa.band(grid)
                ax.fill_between(grid, lo, hi, color=c, alpha=0.15, lw=0,
                                label=f"{100 * conf:g} % band (bootstrap)" if gi == 0 else None)
            ax.plot(grid, r.msa.probability(grid), color=c, lw=1.8,
                    label=f"MLE on stripes: θ = {r.msa.median:.3g} g, β = {r.msa.beta:.2f}")
            ax.plot(grid, r.ida.probability(grid), color=c, lw=1.3, ls="--",
                    label=f"IDA capacities: θ = {r.ida.median:.3g} g, β = {r.ida.beta:.2f}")
        ax.set_title(name, fontsize=9, loc="left")
        ax.set_xlabel(a.cases.im_label)
        ax.set_ylabel("P(exceeded)")
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlim(0.0, grid[-1])
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=6.5, loc="lower right")
    fig.suptitle(f"{a.cases.config.name}: fragility curves ({len(a.records)} records × "
                 f"{x.size} levels)", fontsize=10)
    fig.tight_layout()
    return fig


def plot_gap_probability(a: Any) -> Figure:
    """P(pounding) against the gap at the gap level: the fraction of records whose needed
    gap exceeds it (steps), the lognormal fit with its bootstrap band, the target
    probability and the gaps for it, and the code gaps ABS / SRSS / DDC."""
    ga = a.gap
    fig = new_figure(7.6, 4.6, laid_out=False)
    ax = fig.add_subplot(1, 1, 1)
    mm = 1000.0
    g = ga.grid * mm
    ax.step(g, ga.p_empirical, where="post", color="k", lw=1.4,
            label=f"records ({len(a.records)}): fraction whose needed gap is larger")
    ax.fill_between(g, *ga.p_band, color="C0", alpha=0.18, lw=0,
                    label=f"{100 * a.cases.config.bootstrap.confidence:g} % band (bootstrap)")
    ax.plot(g, ga.p_fit, color="C0", lw=1.8,
            label=f"lognormal: θ = {ga.median * mm:.3g} mm, β = {ga.beta:.2f}")
    ax.axhline(ga.target, color="0.4", lw=0.9, ls=":")
    ax.plot([ga.gap_fit * mm], [ga.target], "o", color="C0",
            label=f"gap for P = {ga.target:g}: {ga.gap_fit * mm:.0f} mm (fit), "
                  f"{ga.gap_empirical * mm:.0f} mm (records)")
    for k, v in ga.needed.code.items():
        ax.axvline(v * mm, color=RULE_STYLE.get(k, "0.3"), ls="--", lw=1.2,
                   label=f"{k}: {v * mm:.0f} mm")
    ax.set_xlabel("gap [mm]")
    ax.set_ylabel("P(pounding)")
    ax.set_xlim(0.0, g[-1])
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    ax.set_title(f"{a.cases.config.name}: probability of pounding at "
                 f"{a.cases.im_label.replace(' [g]', '')} = {ga.needed.at:g} g", fontsize=9,
                 loc="left")
    fig.tight_layout()
    return fig


def plot_gap_surface(a: Any) -> Figure:
    """P(pounding | gap, intensity): filled contours of the lognormal fit at each level,
    with the records' fractions as contour lines at 10, 50 and 90 %, and the gap level."""
    ga = a.gap
    fig = new_figure(7.2, 4.8, laid_out=False)
    ax = fig.add_subplot(1, 1, 1)
    g = ga.grid * 1000.0
    x = a.levels
    z = np.nan_to_num(ga.surface_fit.T, nan=0.0)
    cs = ax.contourf(g, x, z, levels=np.linspace(0.0, 1.0, 11), cmap="viridis")
    cbar = fig.colorbar(cs, ax=ax)
    cbar.set_label("P(pounding), lognormal over records")
    lines = ax.contour(g, x, ga.surface_empirical.T, levels=[0.1, 0.5, 0.9], colors="w",
                       linewidths=1.0, linestyles="--")
    ax.clabel(lines, fmt=lambda v: f"{100 * v:.0f} % (records)", fontsize=7)
    ax.axhline(ga.needed.at, color="w", lw=0.8, ls=":")
    ax.set_xlabel("gap [mm]")
    ax.set_ylabel(a.cases.im_label)
    ax.set_title(f"{a.cases.config.name}: probability of pounding over gap × intensity",
                 fontsize=9, loc="left")
    fig.tight_layout()
    return fig
