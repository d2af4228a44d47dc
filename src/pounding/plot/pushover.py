"""The capacity curve of a pushover (``pounding pushover``): base shear against roof
displacement, with the events where hinges yield, and the storey drifts at the end."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from pounding.plot import new_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["PushoverCurve", "plot_pushover"]


class PushoverCurve(Protocol):
    """What the figure reads of a pushover
    (:class:`pounding.structure.frame_analysis.PushoverResult`)."""

    @property
    def roof_displacement(self) -> NDArray[np.float64]: ...  # [m]
    @property
    def base_shear(self) -> NDArray[np.float64]: ...  # [N]
    @property
    def storey_drifts(self) -> NDArray[np.float64]: ...  # [m], (points, storeys)
    @property
    def pattern(self) -> str: ...
    @property
    def stopped(self) -> str: ...


def plot_pushover(curve: PushoverCurve, storey_heights: NDArray[np.float64],
                  title: str = "") -> Figure:
    """Two panels: (left) base shear [kN, or MN above 10 MN] against roof displacement [mm],
    every event marked (the curve is straight between them), the peak labelled; (right) the
    storey drift ratios [%] at the end of the push."""
    fig = new_figure(11, 4.6, laid_out=False, layout="constrained")
    ax, bx = fig.subplots(1, 2, gridspec_kw={"width_ratios": [2.2, 1]})
    v = np.asarray(curve.base_shear)
    scale, unit = (1e-6, "MN") if np.max(np.abs(v)) >= 1e7 else (1e-3, "kN")
    x = np.asarray(curve.roof_displacement) * 1e3
    ax.plot(x, v * scale, color="C0", lw=1.6)
    ax.plot(x, v * scale, "o", color="C0", ms=3, label="events (straight between them)")
    k = int(np.argmax(v))
    ax.annotate(f"peak {v[k] * scale:.4g} {unit} at {x[k]:.4g} mm", (x[k], v[k] * scale),
                textcoords="offset points", xytext=(8, -14), fontsize=9)
    ax.set_xlabel("roof displacement [mm]")
    ax.set_ylabel(f"base shear [{unit}]")
    ax.set_title(f"capacity curve ({curve.pattern} load pattern; ended: {curve.stopped})",
                 fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    drifts = np.asarray(curve.storey_drifts)[-1] / np.asarray(storey_heights) * 100
    storeys = np.arange(1, drifts.size + 1)
    bx.barh(storeys, drifts, color="C1")
    bx.set_yticks(storeys)
    bx.set_xlabel("storey drift ratio at the end [%]")
    bx.set_ylabel("storey")
    bx.grid(alpha=0.3, axis="x")
    if title:
        fig.suptitle(f"{title}: pushover")
    return fig
