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

__all__ = ["RunFigure", "RUN_FIGURES", "figures_for"]


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
    """

    file: str
    caption: str
    function: str
    yielding_only: bool = False

    def make(self, result: Result) -> Figure:
        """Draw the figure of ``result`` (imports its module on first use)."""
        module, name = self.function.split(":")
        draw = getattr(importlib.import_module(module), name)
        return draw(result)


RUN_FIGURES: dict[str, RunFigure] = {
    "envelope_figure": RunFigure(
        "envelopes.png", "Peak displacement, storey drift ratio and storey shear against "
        "height", "pounding.plot.envelope:plot_envelopes"),
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
        "pounding.plot.loops:plot_storey_hysteresis", yielding_only=True),
    "energy_figure": RunFigure(
        "energy.png", "Energy balance", "pounding.plot.response:plot_energy"),
}
"""Every figure a run can have, in page order (the report's full list); a given run has
:func:`figures_for` of its model."""


def figures_for(subject: Result | PoundingModel) -> dict[str, RunFigure]:
    """The figures of a run of ``subject`` (a result or its model), in page order: all of
    :data:`RUN_FIGURES` except the storey hysteresis figure when no storey can yield (a
    linear storey's shear against drift is a straight line of slope ``k``, nothing to
    read)."""
    model = subject.model if hasattr(subject, "model") else subject
    yielding = bool(model.is_inelastic)
    return {key: fig for key, fig in RUN_FIGURES.items() if yielding or not fig.yielding_only}
