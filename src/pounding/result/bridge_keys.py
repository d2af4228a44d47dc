"""The shear keys of a run (a bridge across its axis, :mod:`pounding.structure.bridge.
transverse`; any contact whose law is :class:`~pounding.contact.shear_key.ShearKey`): per
key its peak force, how far it was pushed, the set it kept, and whether and when it broke
off.

Read from the run's impact table and peak forces, and the key's law: a key breaks off the
first time its penetration past the gap reaches its fracture deformation ``δ_u`` (the
kernel locates that instant and ends the key's impact there), so it broke if an impact of
it reached ``δ_u``, at that impact's end. Its set is the plastic part of the largest
penetration it took while intact, ``max(δ_max − F_c/k, 0)`` (an elastic–perfectly-plastic
key's set grows only on its plateau, to the largest penetration less ``F_c/k``).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import TYPE_CHECKING, Any

from pounding.result.columns import IMPACT_COLUMNS

if TYPE_CHECKING:
    from pounding.result.response import Response

__all__ = ["KeyState", "key_summary", "shear_keys"]


@dataclass(frozen=True)
class KeyState:
    """One shear key after a run (module docstring).

    Attributes
    ----------
    contact : str
        The key's contact (``'B1F1-A1+y/key'``).
    capacity_N : float
        Its capacity F_c [N].
    peak_force_N : float
        Its largest force [N] (F_c if it yielded).
    peak_force_time_s : float or None
        When [s] (on a plateau, an instant on it); None if it was never touched.
    peak_deformation_m : float
        Its largest penetration past the gap while intact [m] (δ_u if it broke).
    yielded : bool
        True if it reached its capacity.
    set_m : float or None
        Its permanent set at the end [m]; None if it broke off.
    failed : bool
        True if it broke off.
    failure_time_s : float or None
        When it broke [s].
    """

    contact: str
    capacity_N: float
    peak_force_N: float
    peak_force_time_s: float | None
    peak_deformation_m: float
    yielded: bool
    set_m: float | None
    failed: bool
    failure_time_s: float | None


FRACTURE_TOL = 1e-9
"""A key whose impact reached its fracture deformation δ_u within this fraction of it broke
off there (the break is a located event: δ at it is δ_u to the event's tolerance)."""


def shear_keys(r: Response) -> list[KeyState]:
    """Every shear key of the run, in contact order (module docstring); empty without
    keys."""
    from pounding.contact.shear_key import ShearKey

    imp = r.impact_array
    col = {name: i for i, name in enumerate(IMPACT_COLUMNS)}
    out = []
    for c in r.model.contacts:
        law = c.law
        if not isinstance(law, ShearKey):
            continue
        rows = imp[imp[:, col["contact"]] == c.index]
        dmax = float(rows[:, col["max_penetration"]].max()) if rows.size else 0.0
        du = law.fracture_displacement
        # (a key's impact ends where it breaks: its row's largest penetration is δ_u, as
        # located by the solver's event, to its tolerance)
        broken = (rows[rows[:, col["max_penetration"]] >= du * (1.0 - FRACTURE_TOL)]
                  if du is not None else rows[:0])
        failed = bool(broken.shape[0])
        peak = float(r.peak_contact_force[c.index])
        touched = rows.size > 0 and peak > 0.0
        deformation = min(dmax, du) if du is not None and failed else dmax
        out.append(KeyState(
            contact=c.label, capacity_N=law.capacity, peak_force_N=peak,
            peak_force_time_s=float(r.peak_contact_force_time[c.index]) if touched else None,
            peak_deformation_m=float(max(deformation, 0.0)),
            yielded=bool(dmax >= law.yield_displacement),
            set_m=None if failed else max(dmax - law.yield_displacement, 0.0),
            failed=failed,
            failure_time_s=float(broken[0, col["end"]]) if failed else None))
    return out


def key_summary(r: Response) -> dict[str, Any]:
    """``shear_keys`` of ``summary.json``: each key's :class:`KeyState` by its contact
    label (units in the names), if the run has keys."""
    keys = shear_keys(r)
    if not keys:
        return {}
    return {"shear_keys": {k.contact: {name: v for name, v in asdict(k).items()
                                       if name != "contact"} for k in keys}}
