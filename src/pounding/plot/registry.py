"""The figures of a run folder: key → file name, caption and the function that draws it.

Light on purpose: it imports neither matplotlib nor the figure modules, so
``pounding run`` (and anything else that needs only the file names) can read it without
the cost of importing matplotlib. :meth:`RunFigure.make` imports the figure's module when a
figure is drawn.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from pounding.model import PoundingModel
    from pounding.result import Result

__all__ = ["RUN_FIGURES", "RunFigure", "figures_for", "is_bridge_model"]


class RunFigure(NamedTuple):
    """One of the figures of a run folder.

    Attributes
    ----------
    file : str
        File name in the run folder.
    caption : str
        What it shows (the report's caption).
    function : str
        ``"module:function"`` drawing it from a :class:`pounding.result.Result`.
    yielding_only : bool
        Drawn only for models with yielding storeys.
    bridge : bool or None
        True: drawn only for a bridge (every building a bridge frame,
        :mod:`pounding.structure.bridge`); False: never for a bridge (a figure of storeys);
        None: for every model.
    """

    file: str
    caption: str
    function: str
    yielding_only: bool = False
    bridge: bool | None = None

    def make(self, result: Result) -> Figure:
        """Draw the figure of ``result`` (imports its module on first use)."""
        module, name = self.function.split(":")
        draw = getattr(importlib.import_module(module), name)
        return draw(result)


RUN_FIGURES: dict[str, RunFigure] = {
    "bridge_figure": RunFigure(
        "bridge.png", "The bridge's elevation (piers' peak drift and shear; joints' and "
        "abutments' gaps and impacts) and the envelope of the relative displacement at "
        "every joint and abutment seat", "pounding.plot.bridge:plot_bridge_elevation",
        bridge=True),
    "envelope_figure": RunFigure(
        "envelopes.png", "Peak displacement, storey drift ratio and storey shear against "
        "height", "pounding.plot.envelope:plot_envelopes", bridge=False),
    "displacement_figure": RunFigure(
        "displacements.png", "Floor displacements, ground acceleration below",
        "pounding.plot.response:plot_displacements"),
    "force_figure": RunFigure(
        "contact_forces.png", "Contact forces, ground acceleration below",
        "pounding.plot.response:plot_contact_forces"),
    "hysteresis_figure": RunFigure(
        "hysteresis.png", "Contact hysteresis (force against penetration)",
        "pounding.plot.loops:plot_hysteresis"),
    "storey_figure": RunFigure(
        "storeys.png", "Storey shear against drift of the yielding storeys (hysteresis)",
        "pounding.plot.loops:plot_storey_hysteresis", yielding_only=True, bridge=False),
    "bridge_element_figure": RunFigure(
        "bridge_elements.png", "Pier shear against drift, bearing force against "
        "displacement, restrainer force against the joint's opening",
        "pounding.plot.bridge:plot_bridge_elements", bridge=True),
    "energy_figure": RunFigure(
        "energy.png", "Energy balance", "pounding.plot.response:plot_energy"),
}
"""Every figure a run can have, in page order (the report's full list); a given run has
:func:`figures_for` of its model."""


def figures_for(subject: Result | PoundingModel) -> dict[str, RunFigure]:
    """The figures of a run of ``subject`` (a result or its model), in page order: all of
    :data:`RUN_FIGURES` except the storey hysteresis figure when no storey can yield (a
    linear storey's shear against drift is a straight line of slope ``k``, nothing to
    read); of a bridge (every building a bridge frame) its elevation and element figures
    in place of the storeys' envelope and hysteresis, of any other model not those."""
    model = subject.model if hasattr(subject, "model") else subject
    yielding = bool(model.is_inelastic)
    bridge = is_bridge_model(model)
    return {key: fig for key, fig in RUN_FIGURES.items()
            if (yielding or not fig.yielding_only)
            and (fig.bridge is None or fig.bridge == bridge)}


def is_bridge_model(model: PoundingModel) -> bool:
    """True if every building of ``model`` is a bridge frame
    (:class:`~pounding.structure.bridge.BridgeFrame`: one with a deck) of a bridge along its
    axis (:func:`pounding.result.bridge_peaks.is_bridge`; across it there are no seats to
    draw)."""
    from pounding.result.bridge_peaks import is_bridge

    return is_bridge(model)
