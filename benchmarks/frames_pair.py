"""The LA9-type frame pair of ``bench_frames.py``: two 9-storey, 5-bay steel moment frames
side by side, the records they are shaken by, and how an OpenSees run of the pair is
compared with pounding's.

The pair
--------
* **Frame A** (left): the LA9-type frame of ``frames_la9.py`` as it is —
  ``la9_frame(name="A")``: IMK beams (Lignos & Krawinkler 2011), bilinear columns, leaning
  column, P-Delta, 2 % Rayleigh at modes 1 and 3, T1 = 2.117 s.
* **Frame B** (right): the same frame carrying half the mass — every floor's seismic mass,
  its beams' gravity load and its leaning-column load × :data:`B_MASS_FACTOR` (0.5): the
  perimeter frame of a building of the same structure with half the plan depth (its
  tributary floor area halved). Same sections, hinges and storeys, so the floors meet at
  every level; T1 = 1.481 s, 0.70 of A's, so the two sway out of phase and pound. Being
  lighter and as strong, B yields less than A.
* **Gap** :data:`GAP` = 20 mm at every floor; "without pounding" is the same pair with a
  gap of :data:`NO_POUNDING_GAP` (10 m, never closed).
* **Contact**: Kelvin–Voigt, ``k`` = 2e9 N/m, ``e`` = 0.65 (``c`` from Anagnostopoulos'
  formula with the two floors' masses), the dashpot allowed to pull until the gap reopens
  (``tension=True``) — the law of OpenSees' ``ViscoelasticGap``, so both programs solve
  the same equations (``opensees_frame_pair.py``).

Records
-------
* El Centro 1940, Array #9, 180 (pounding's bundled ``el_centro()``: 0.01 s, 39.99 s,
  PGA 0.313 g), scaled by :data:`SCALES` ``["El Centro"]``;
* Northridge 1994, Newhall – Fire Station, 360 (PEER NGA RSN1044, ``/work/shared/records``
  or ``--northridge``: 0.02 s, 39.98 s, PGA 0.590 g), scaled by :data:`SCALES`
  ``["Northridge"]``.

The scales are chosen so that frame A's beams yield well past their capping-free range and
its storey drifts reach a few per cent (measured: ``bench_frames.py --sections accuracy``).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np
from frames_la9 import STOREY_HEIGHTS, la9_frame
from numpy.typing import NDArray

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotion, el_centro, read_record
from pounding.model import PoundingModel
from pounding.structure.frame import Frame
from pounding.structure.frame_linear import FrameBuilding, frame_matrix_building

GAP = 0.02  # m
NO_POUNDING_GAP = 10.0  # m: never closes
B_MASS_FACTOR = 0.5
CONTACT = ContactSpec("kelvin-voigt", k=2e9, e=0.65, tension=True)
NORTHRIDGE = Path("/work/shared/records/northridge_1994_newhall_360_RSN1044.AT2")
SCALES: dict[str, float] = {"El Centro": 2.5, "Northridge": 1.0}
"""Scale factors of the records (module docstring)."""


def pair_frames() -> tuple[Frame, Frame]:
    """Frames A and B (module docstring)."""
    a = la9_frame(name="A")
    b = la9_frame(name="B")
    f = B_MASS_FACTOR
    b = dataclasses.replace(b, masses=b.masses * f, member_loads=b.member_loads * f,
                            leaning_loads=b.leaning_loads * f)
    return a, b


@dataclasses.dataclass(frozen=True)
class Pair:
    """The pair as pounding takes it: the frames, their buildings and the model."""

    frames: tuple[Frame, Frame]
    buildings: tuple[FrameBuilding, FrameBuilding]
    gap: float

    @property
    def model(self) -> PoundingModel:
        return PoundingModel(list(self.buildings), [self.gap], CONTACT)

    def with_gap(self, gap: float) -> Pair:
        return Pair(self.frames, self.buildings, gap)


def pair(gap: float = GAP) -> Pair:
    """Frames A and B, their :class:`FrameBuilding` s, at ``gap`` [m]."""
    a, b = pair_frames()
    return Pair((a, b), (frame_matrix_building(a), frame_matrix_building(b)), gap)


def record(name: str, northridge: Path = NORTHRIDGE) -> GroundMotion:
    """``"El Centro"`` or ``"Northridge"``, unscaled."""
    if name == "El Centro":
        return el_centro()
    if name == "Northridge":
        return read_record(northridge)
    raise ValueError(f"record: one of {', '.join(SCALES)} (got {name!r})")


def opensees_contacts(model: PoundingModel) -> list[tuple[int, int, float, float]]:
    """``(left floor, right floor, K [N/m], C [N·s/m])`` of every contact of ``model``, its
    Kelvin–Voigt constants as pounding built them (for ``ViscoelasticGap``)."""
    out = []
    for c in model.contacts:
        law: Any = c.law
        out.append((int(c.left.upper), int(c.right.upper), float(law.k), float(law.c)))
    return out


def storey_heights() -> NDArray[np.float64]:
    """Storey heights of either frame [m], ground storey first."""
    return np.array(STOREY_HEIGHTS)


@dataclasses.dataclass(frozen=True)
class Measures:
    """What the comparison reads of one run (either program), SI units."""

    impacts: int
    peak_force: float  #: N, all contacts
    drift_a: NDArray[np.float64]  #: peak |storey drift| ratio of each storey of A [-]
    drift_b: NDArray[np.float64]  #: the same of B [-]
    hinge: NDArray[np.float64]  #: peak |rotation| of every hinge, A's then B's [rad]


def pounding_measures(r: Any) -> Measures:
    """The :class:`Measures` of a pounding :class:`~pounding.result.Result` of the pair."""
    h = storey_heights()
    n = h.size
    drift = np.asarray(r.peak_drift)
    return Measures(int(r.n_impacts), float(np.max(r.peak_contact_force, initial=0.0)),
                    drift[:n] / h, drift[n:2 * n] / h, np.asarray(r.hinge_peak_rotation))


def opensees_measures(history: Any) -> Measures:
    """The :class:`Measures` of an ``opensees_frame_pair.PairHistory``."""
    h = storey_heights()
    return Measures(history.n_impacts, float(np.max(history.peak_contact_force, initial=0.0)),
                    history.peak_drift("left") / h, history.peak_drift("right") / h,
                    np.asarray(history.hinge_peak))


@dataclasses.dataclass(frozen=True)
class Errors:
    """An OpenSees run against pounding's (each relative to pounding's largest value of the
    quantity, so that small peaks do not blow a ratio up)."""

    impacts: int  #: OpenSees' impacts − pounding's
    force: float  #: |ΔF_peak| / F_peak (0 if neither pounds)
    drift: float  #: max over both frames' storeys |Δ drift ratio| / max drift ratio
    hinge: float  #: max over hinges |Δθ_peak| / max θ_peak
    history: float  #: max |Δu| of the floors at OpenSees' steps / max |u|


def errors(ours: Measures, theirs: Measures, r: Any, history: Any) -> Errors:
    """OpenSees' :class:`Errors` against pounding's result ``r`` (``history``: its
    ``PairHistory``; the displacement history compared at OpenSees' steps, pounding's
    output interpolated linearly — exact when OpenSees' step is a multiple of pounding's
    output step)."""
    d_ours = np.concatenate([ours.drift_a, ours.drift_b])
    d_theirs = np.concatenate([theirs.drift_a, theirs.drift_b])
    force = (abs(theirs.peak_force - ours.peak_force) / ours.peak_force if ours.peak_force
             else float(theirs.peak_force > 0.0))
    u = np.hstack([history.left, history.right])
    ref = np.array([np.interp(history.time, r.time, r.displacement[:, k])
                    for k in range(u.shape[1])]).T
    return Errors(theirs.impacts - ours.impacts, float(force),
                  float(np.max(np.abs(d_theirs - d_ours)) / np.max(d_ours)),
                  float(np.max(np.abs(theirs.hinge - ours.hinge)) / np.max(ours.hinge)),
                  float(np.max(np.abs(u - ref)) / np.max(np.abs(r.displacement))))
