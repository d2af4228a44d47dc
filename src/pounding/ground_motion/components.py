"""Several components of one ground motion applied together: :class:`GroundMotionComponents`.

A model whose influence matrix R has G columns (``M ü + C u̇ + K u + … = −M R a_g(t)``, for
example a building in plan with ``u_x``, ``u_y``, ``θ`` floors shaken along x and y) is run
under G records of the same sampling step, one per column of R, in that order: component g
is the ground acceleration along the direction of R's column g (for R of a plan building,
the model's global x then y axes). Each component is a :class:`GroundMotion`; rotating a
pair to an angle of incidence is the caller's business.

Components of different lengths run for the longest: each shorter one returns linearly to
zero over one record step after its last sample and stays zero (the rule of
:func:`pounding.integrate.grid.ground_on_grid` for any record past its end).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.ground_motion.motion import GroundMotion
from pounding.units import G

__all__ = ["GroundMotionComponents", "records_of_one_step"]


def records_of_one_step(records: Iterable[GroundMotion], what: str, item: str
                        ) -> tuple[GroundMotion, ...]:
    """``records`` as a tuple, checked: at least one, each a :class:`GroundMotion`, all of
    one step (to 1e-12); else one line naming ``what``, the ``item`` and its value
    (``"component 1 ('b') has dt = …"``)."""
    recs = tuple(records)
    if not recs:
        raise ValueError(f"{what}: need at least one record (got none)")
    for g, c in enumerate(recs):
        if not isinstance(c, GroundMotion):
            raise ValueError(f"{what}: {item} {g} must be a GroundMotion (got "
                             f"{type(c).__name__})")
    dt0 = recs[0].dt
    for g, c in enumerate(recs[1:], start=1):
        if not math.isclose(c.dt, dt0, rel_tol=1e-12, abs_tol=0.0):
            raise ValueError(f"{what}: {item} {g} ({c.name!r}) has dt = {c.dt:g} s, {item} 0 "
                             f"({recs[0].name!r}) dt = {dt0:g} s; resample to one step")
    return recs


@dataclass(frozen=True, eq=False)
class GroundMotionComponents:
    """G ground-acceleration records applied together, along the columns of a model's
    influence matrix R (in that order).

    Parameters
    ----------
    components : sequence of GroundMotion
        One or more records with the same time step ``dt`` [s].
    name : str, optional
        Name for tables and titles (default: the components' names joined by ``" + "``).

    Raises
    ------
    ValueError
        No component, a component that is not a :class:`GroundMotion`, or steps that
        differ; the message names the component and its value.
    """

    components: tuple[GroundMotion, ...]
    name: str = ""

    def __post_init__(self) -> None:
        comps = records_of_one_step(self.components, "ground motion components", "component")
        object.__setattr__(self, "components", comps)
        if not self.name:
            object.__setattr__(self, "name", " + ".join(c.name for c in comps))

    @classmethod
    def of(cls, *components: GroundMotion, name: str = "") -> GroundMotionComponents:
        """``GroundMotionComponents((a, b, …))``, written ``GroundMotionComponents.of(a, b)``."""
        return cls(tuple(components), name)

    @property
    def n_components(self) -> int:
        """G, the number of components."""
        return len(self.components)

    @property
    def dt(self) -> float:
        """Time step of every component [s]."""
        return self.components[0].dt

    @property
    def npts(self) -> int:
        """Samples of the longest component."""
        return max(c.npts for c in self.components)

    @property
    def duration(self) -> float:
        """Time of the last sample of the longest component [s] (the shorter ones are
        zero after their end, see the module)."""
        return (self.npts - 1) * self.dt

    @property
    def time(self) -> NDArray[np.float64]:
        """Sample times [s] of the longest component."""
        return np.arange(self.npts, dtype=np.float64) * self.dt

    @property
    def accel(self) -> NDArray[np.float64]:
        """The components' samples [m/s²], (npts, G), the shorter ones padded with zeros."""
        out = np.zeros((self.npts, self.n_components))
        for g, c in enumerate(self.components):
            out[: c.npts, g] = c.accel
        return out

    @property
    def pga(self) -> float:
        """The largest peak ground acceleration of the components [m/s²] (of each
        component alone, not of their vector sum)."""
        return max(c.pga for c in self.components)

    @property
    def pga_g(self) -> float:
        """:attr:`pga` in units of standard gravity [g]."""
        return self.pga / G

    @property
    def pgv(self) -> float:
        """The largest peak ground velocity of the components [m/s]."""
        return max(c.pgv for c in self.components)
