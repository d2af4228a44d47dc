"""What a simulation computed of its contacts and links: the impacts and peak force of every
contact, and the links' motion, forces and energies — the part of
:class:`pounding.result.response.Response` that reads the impact table, the contact and
link histories (a base it builds on: this module imports none of the package's others but
the impact table's columns).
"""

from __future__ import annotations

from functools import cached_property
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.result.columns import IMPACT_COLUMNS
from pounding.result.peaks import peak_abs

if TYPE_CHECKING:
    from pounding.model import PoundingModel

__all__ = ["ContactPeak", "ContactsAndLinks"]


class ContactsAndLinks:
    """The contacts' impacts and peaks and the links' motion, forces and energies, from the
    arrays a :class:`~pounding.result.response.Response` holds (its fields, read here)."""

    model: PoundingModel
    dt: float
    displacement: NDArray[np.float64]
    velocity: NDArray[np.float64]
    impact_array: NDArray[np.float64]
    contact_peak: NDArray[np.float64] | None
    contact_impacts: NDArray[np.int64] | None
    contact_peak_time: NDArray[np.float64] | None
    link_force: NDArray[np.float64] | None
    link_ground: NDArray[np.float64] | None
    final_z: NDArray[np.float64] | None
    energy: NDArray[np.float64]

    @cached_property
    def impacts_per_contact(self) -> NDArray[np.int64]:
        """Number of impacts of every contact (n_c,), complete even when the impact table
        overflowed."""
        if self.contact_impacts is not None:
            return np.asarray(self.contact_impacts, dtype=np.int64)
        return np.bincount(self.impact_array[:, 0].astype(np.int64),
                           minlength=len(self.model.contacts))

    @cached_property
    def dissipated_per_contact(self) -> NDArray[np.float64]:
        """Energy dissipated by the finished impacts of every contact [J] (n_c,), summed over
        the impact table (an impact still open at the end is not counted)."""
        out = np.zeros(len(self.model.contacts))
        rows = self.impact_array
        col = IMPACT_COLUMNS.index("energy_dissipated")
        done = np.isfinite(rows[:, col]) if rows.size else np.zeros(0, dtype=bool)
        np.add.at(out, rows[done, 0].astype(np.int64), rows[done, col])
        return out

    @property
    def n_impacts(self) -> int:
        """Number of impacts (all contacts)."""
        if self.contact_impacts is not None:
            return int(np.asarray(self.contact_impacts).sum())
        return int(self.impact_array.shape[0])

    @cached_property
    def peak_contact_force(self) -> NDArray[np.float64]:
        """Largest force of every contact [N] (n_c,), located inside solver steps, or 0 for
        a contact that never closed."""
        if self.contact_peak is not None:
            return np.asarray(self.contact_peak, dtype=float)
        out = np.zeros(len(self.model.contacts))
        if self.impact_array.size:
            np.maximum.at(out, self.impact_array[:, 0].astype(int), self.impact_array[:, 4])
        return out

    @cached_property
    def contact_peaks(self) -> dict[str, ContactPeak]:
        """Every contact's peak force [N] and its time [s], impacts and dissipated energy
        [J], by contact label (``"B1F3-B2F3"``); a contact that never closed has force 0
        and time NaN."""
        return {c.label: ContactPeak(float(self.peak_contact_force[c.index]),
                                     float(self.peak_contact_force_time[c.index]),
                                     int(self.impacts_per_contact[c.index]),
                                     float(self.dissipated_per_contact[c.index]))
                for c in self.model.contacts}

    @cached_property
    def peak_contact_force_time(self) -> NDArray[np.float64]:
        """Time of every contact's peak force [s] (n_c,); NaN for a contact that never
        closed."""
        if self.contact_peak_time is not None:
            t = np.asarray(self.contact_peak_time, dtype=float).copy()
        else:
            t = np.full(len(self.model.contacts), np.nan)
            rows = self.impact_array
            for c in range(t.size):
                mine = rows[rows[:, 0] == c] if rows.size else rows
                if len(mine):
                    t[c] = mine[int(np.argmax(mine[:, 4])), 5]
        t[self.peak_contact_force <= 0.0] = np.nan
        return t

    @property
    def link_displacement(self) -> NDArray[np.float64]:
        """Relative displacement of every link, right floor less left floor [m] (nt, n_l)
        (with the grounds' offset for a link between buildings on different grounds,
        :attr:`link_ground`)."""
        return self._link_kinematics(self.displacement, 0)

    @property
    def link_velocity(self) -> NDArray[np.float64]:
        """Rate of :attr:`link_displacement` [m/s] (nt, n_l)."""
        return self._link_kinematics(self.velocity, 1)

    def _link_kinematics(self, floors: NDArray[np.float64], which: int
                         ) -> NDArray[np.float64]:
        cols = self.model.link_dofs
        out = np.zeros((floors.shape[0], len(cols)))
        for i, (lo, hi) in enumerate(cols):
            out[:, i] = floors[:, hi] - floors[:, lo]
        if self.link_ground is not None:
            out += self.link_ground[which]
        return out

    @property
    def link_peak_force(self) -> NDArray[np.float64]:
        """Largest |force| of every link at the output steps [N] (n_l,).

        Column by column (:func:`pounding.result.peaks.peak_abs`), the same numbers as
        ``np.abs(f).max(axis=0)``, which across a tall, narrow (nt, n_l) history is slow:
        the 10-storey pair's ten links under El Centro (40 000 rows) 1.9–2.1 ms against
        1.0–1.4 ms (CPU time, load 7, 2026-11-28), a part of the links' price in
        ``benchmarks/bench_devices.py --sections cost``, which reads it with every run."""
        f = self.link_force
        if f is None or f.shape[1] == 0:
            return np.zeros(len(self.model.links))
        return peak_abs(f)

    @property
    def link_dissipated(self) -> NDArray[np.float64]:
        """Energy each link has dissipated by the end [J] (n_l,): its work ``∫ F ḋ dt`` (the
        trapezoidal rule on the output steps, O(dt²)) less its springs' energy at the end.
        Their sum is the exact ``links`` energy of the solver to that order; use that
        (``energy[-1, 7]``) for the total."""
        links = self.model.links
        if not links or self.link_force is None:
            return np.zeros(len(links))
        power = self.link_force * self.link_velocity
        work = np.trapezoid(power, dx=self.dt, axis=0)
        d_end = self.link_displacement[-1]
        z = self.final_z if self.final_z is not None else np.zeros(0)
        z_links = z[z.size - sum(lk.has_internal_variable for lk in links):]
        stored = np.zeros(len(links))
        iz = 0
        for i, link in enumerate(links):
            if link.kind == "kelvin":
                stored[i] = 0.5 * float(link.k) * d_end[i] ** 2  # type: ignore[arg-type]
            elif link.kind == "maxwell":
                stored[i] = 0.5 * float(link.k) * z_links[iz] ** 2  # type: ignore[arg-type]
                iz += 1
            elif link.kind == "restrainer":  # its cables' elastic energy F²/(2k) (its z
                k = float(link.k)  # type: ignore[arg-type]  # is its plastic elongation)
                stored[i] = self.link_force[-1, i] ** 2 / (2.0 * k)
                iz += 1
        return work - stored

    @property
    def contact_dissipated(self) -> NDArray[np.float64]:
        """Energy dissipated in contacts so far [J] (nt,)."""
        return self.energy[:, 4] - self.energy[:, 5]


class ContactPeak(NamedTuple):
    """One contact's peak (:attr:`Response.contact_peaks`)."""

    force: float
    """Largest contact force [N], located inside solver steps."""
    time: float
    """When it occurred [s] (NaN if the contact never closed)."""
    impacts: int
    """Number of impacts."""
    dissipated: float
    """Energy dissipated by its finished impacts [J]."""
