"""The separation-gap figure: critical gap against elevation, simulated and by code rules."""

from __future__ import annotations

from typing import Protocol

import numpy as np
from matplotlib.figure import Figure
from numpy.typing import NDArray

from pounding.contact.geometry import Contact
from pounding.model import PoundingModel
from pounding.plot import new_figure
from pounding.plot.layout import MM
from pounding.spectra import DesignSpectrum


class GapStudyFigureData(Protocol):
    """What the figure reads of a gap study (:class:`pounding.studies.gap.GapStudy`, which
    the figure does not import: the studies sit above the figures, docs/architecture.md)."""

    @property
    def model(self) -> PoundingModel: ...

    @property
    def records(self) -> tuple[str, ...]: ...

    @property
    def elevation(self) -> NDArray[np.float64]: ...

    @property
    def critical(self) -> NDArray[np.float64]: ...

    @property
    def period(self) -> NDArray[np.float64]: ...

    @property
    def rho(self) -> NDArray[np.float64]: ...

    @property
    def gap_names(self) -> tuple[str, ...]: ...

    @property
    def contacts(self) -> tuple[Contact, ...]: ...

    @property
    def max_critical(self) -> NDArray[np.float64]: ...

    def rules_from_peaks(self, stat: str = "mean") -> dict[str, NDArray[np.float64]]: ...

    def rules_from_spectrum(self, spectrum: DesignSpectrum
                            ) -> dict[str, NDArray[np.float64]]: ...


RULE_STYLE = {"ABS": "tab:red", "SRSS": "tab:green", "DDC": "tab:purple"}
"""Colour of each code rule."""


def plot_gap_study(study: GapStudyFigureData, spectrum: DesignSpectrum | None = None) -> Figure:
    """Gap [mm] against elevation [m], one panel per pair of neighbours.

    * thin grey lines: the critical gap by simulation for each record;
    * thick black line: its maximum over the records;
    * dashed: ABS, SRSS and DDC from the mean simulated peak displacements;
    * dotted (with ``spectrum``): the same rules from the design spectrum.

    A pair with one shared level shows points (markers on every line). A moat wall has a
    panel of its own (the moat width the building needs); where a level has several contacts
    (the two ends of facing façades in plan), each line shows the largest at that level.

    Parameters
    ----------
    study : GapStudy
        From :func:`pounding.studies.gap.critical_gaps`.
    spectrum : DesignSpectrum, optional
        Adds the rules from this spectrum.

    Returns
    -------
    matplotlib.figure.Figure
        Write it with :func:`pounding.plot.save_figure`.
    """
    names = list(dict.fromkeys(study.gap_names))
    fig = new_figure(4.2 * len(names) + 1.4, 5.2, laid_out=False)
    axes = [fig.add_subplot(1, len(names), i + 1) for i in range(len(names))]
    from_peaks = study.rules_from_peaks("mean")
    from_spec = study.rules_from_spectrum(spectrum) if spectrum is not None else None
    gap_names = np.array(study.gap_names)
    for ax, name in zip(axes, names):
        sel = gap_names == name
        z, at = np.unique(study.elevation[sel], return_inverse=True)

        def by_level(values: np.ndarray) -> np.ndarray:
            out = np.full(z.size, -np.inf)
            np.maximum.at(out, at, values[sel])
            return out * MM.factor

        mk = "o" if z.size == 1 else "."
        for i in range(len(study.records)):
            ax.plot(by_level(study.critical[i]), z, color="0.55", lw=0.8, marker=mk, ms=3,
                    label="simulated, each record" if i == 0 else None)
        ax.plot(by_level(study.max_critical), z, color="k", lw=2.4, marker=mk, ms=5,
                label="simulated, max over records")
        for rule, values in from_peaks.items():
            ax.plot(by_level(values), z, ls="--", lw=1.4, color=RULE_STYLE[rule],
                    marker=mk, ms=4, label=f"{rule} (mean simulated peaks)")
        if from_spec is not None:
            for rule, values in from_spec.items():
                ax.plot(by_level(values), z, ls=":", lw=1.6, color=RULE_STYLE[rule],
                        marker="x", ms=5, label=f"{rule} (design spectrum)")
        ax.set_title(_panel_title(study, name), fontsize=9)
        ax.set_xlabel(f"separation gap [{MM.unit}]")
        ax.set_xlim(left=0.0)
        ax.set_ylim(0.0, max(float(z.max()) * 1.08, 0.1))
        ax.grid(True, lw=0.4, alpha=0.5)
    axes[0].set_ylabel("elevation above ground [m]")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=2,
               fontsize=7, frameon=False)
    fig.suptitle(f"{study.model.name}: critical gap by simulation ({len(study.records)} "
                 f"record{'s' if len(study.records) != 1 else ''}) and code rules", fontsize=10)
    fig.tight_layout()
    return fig


def _panel_title(study: GapStudyFigureData, name: str) -> str:
    """``B1 name – B2 name`` with the periods and ρ; ``B1 name – moat wall W`` (the moat
    width the building needs) for a wall."""
    from pounding.structure.wall import WallPoint

    c = study.contacts[study.gap_names.index(name)]
    for wall, other, side in ((c.left, c.right, "left"), (c.right, c.left, "right")):
        if isinstance(wall, WallPoint):
            b = other.building
            return (f"B{b + 1} {study.model.buildings[b].name} – moat wall {wall.label()} "
                    f"on its {side}\n"
                    f"moat width needed, T1 = {study.period[b]:.3g} s")
    p = c.pair
    b1, b2 = study.model.buildings[p], study.model.buildings[p + 1]
    return (f"B{p + 1} {b1.name} – B{p + 2} {b2.name}\n"
            f"T1 = {study.period[p]:.3g} s / {study.period[p + 1]:.3g} s, "
            f"ρ = {study.rho[p]:.3f}")
