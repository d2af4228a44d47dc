"""What the Python law objects and the compiled kernels agree on: each law's integer code and
the layout of a contact's per-impact state vector (the contract of
:mod:`pounding.contact.base`, steps 3 and 6).

Plain integers and floats, no NumPy: both sides import them, and numba freezes them into
compiled code as constants.

State vector (float64, length :data:`STATE_SIZE`)
-------------------------------------------------
``state[V0]``
    impact velocity of the current impact [m/s]; 0 while the gap is open.
``state[SLIP]``
    plastic offset of the bilinear element's elasto-plastic branch [m]; the abutment
    backfill's and the shear key's permanent set [m], which outlasts its impact
    (:func:`keeps_set` laws: the kernel keeps it when the gap opens) — a broken shear
    key's is ``+∞`` (:data:`BROKEN`); 0 for other laws.
``state[DMAX]``
    largest penetration reached in the current impact [m].
"""

from __future__ import annotations

V0: int = 0
SLIP: int = 1
DMAX: int = 2
STATE_SIZE: int = 3

V0_MIN: float = 1e-6
"""Floor on the recorded impact velocity [m/s], so grazing contacts keep ``δ̇/v0`` finite."""

# Law codes for the compiled dispatcher (one per family member; never reuse a number).
LINEAR_SPRING: int = 0
KELVIN_VOIGT: int = 1
MODIFIED_KELVIN_VOIGT: int = 2
HERTZ: int = 3
HUNT_CROSSLEY: int = 4
NONLINEAR_VISCOELASTIC: int = 5
BILINEAR_IMPACT: int = 6
ABUTMENT: int = 7
SHEAR_KEY: int = 8

BROKEN: float = float("inf")
"""``state[SLIP]`` of a shear key that has broken off: a set of ``+∞``, so the key never
pushes again (:mod:`pounding.contact.shear_key`)."""
