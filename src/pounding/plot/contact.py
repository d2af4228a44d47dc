"""Figures of the contact core: the seed's Fig 4 (ζ against e) and the restitution audit."""

from __future__ import annotations

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from pounding.contact.restitution import FORMULAS, PUBLISHED, TABLE1_E, TABLE1_ZETA
from pounding.plot import new_figure


def plot_damping_formulas(e: np.ndarray | None = None) -> Figure:
    """The seed's Fig 4: every published ζ(e) formula (log scale), with Table 1 marked; χ(e)
    beside it. The exact inverses (``exact-*``, the laws' defaults) are not drawn: each is a
    law's own e(ζ) inverted, not a formula the seed compares.

    Parameters
    ----------
    e : numpy.ndarray, optional
        Coefficients of restitution to draw (default 0.05 … 1).
    """
    e = np.linspace(0.05, 1.0, 400) if e is None else np.asarray(e, dtype=float)
    fig = new_figure(11, 6.2, laid_out=False, layout="constrained")
    ax_z, ax_c = fig.subplots(1, 2)
    for f in (FORMULAS[k] for k in PUBLISHED):
        ax = ax_z if f.kind == "zeta" else ax_c
        ax.plot(e, f(e), label=f"{f.key} ({f.equation})")
    ax_z.plot(TABLE1_E, TABLE1_ZETA, "ko", mfc="none", label="seed Table 1")
    ax_z.set_yscale("log")
    ax_z.set_ylim(1e-3, 1e3)
    ax_z.set_xlabel("coefficient of restitution e [-]")
    ax_z.set_ylabel("impact damping ratio ζ [-]")
    ax_z.set_title("ζ(e): viscoelastic laws (seed Fig 4)")
    ax_c.set_xlabel("coefficient of restitution e [-]")
    ax_c.set_ylabel("damping factor χ [-]")
    ax_c.set_yscale("log")
    ax_c.set_title("χ(e): Hunt–Crossley family")
    for ax in (ax_z, ax_c):
        ax.grid(True, which="both", alpha=0.3)
    # one legend below the panels: the ζ laws in the left column, the χ laws in the right
    (hz, lz), (hc, lc) = (ax.get_legend_handles_labels() for ax in (ax_z, ax_c))
    blank = [Line2D([], [], ls="none")] * (len(lz) - len(lc))
    fig.legend(hz + hc + blank, lz + lc + [""] * len(blank), loc="outside lower center",
               ncol=2, fontsize=7, frameon=False)
    return fig


def plot_audit(table: pd.DataFrame) -> Figure:
    """Achieved against target e for every (formula, law) pair of a restitution audit.

    Parameters
    ----------
    table : pandas.DataFrame
        Output of :func:`pounding.contact.audit.restitution_audit`.
    """
    fig = new_figure(11, 6.2, laid_out=False, layout="constrained")
    ax_a, ax_b = fig.subplots(1, 2, sharex=True)
    tab20 = matplotlib.colormaps["tab20"]
    for i, ((formula, law), g) in enumerate(table.groupby(["formula", "law"], sort=False)):
        kw = {"color": tab20(i % tab20.N)}
        style = "-o" if bool(g["intended"].iloc[0]) else "--x"
        label = f"{formula} / {law}"
        ax_a.plot(g["target_e"], g["achieved_e"], style, ms=4, label=label, **kw)
        ax_b.plot(g["target_e"], g["error"], style, ms=4, label=label, **kw)
    ax_a.plot([0, 1], [0, 1], "k:", lw=1, label="achieved = target")
    ax_a.set_xlabel("target e [-]")
    ax_a.set_ylabel("achieved e [-]")
    ax_b.axhline(0.0, color="k", lw=1)
    ax_b.set_xlabel("target e [-]")
    ax_b.set_ylabel("achieved − target [-]")
    ax_a.set_xlim(0, 1)
    ax_a.set_ylim(0, 1)
    for ax in (ax_a, ax_b):
        ax.grid(True, alpha=0.3)
    fig.suptitle("Restitution audit (solid: formula with the law it was derived for)")
    # one legend below both panels (formula / law pairs, then the diagonal): it hides nothing
    fig.legend(*ax_a.get_legend_handles_labels(), loc="outside lower center", ncol=3,
               fontsize=7, frameon=False)
    return fig
