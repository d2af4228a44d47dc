"""Storey force–drift laws: how a storey of a shear building yields.

* :class:`Bilinear` — bilinear with kinematic hardening (elastic stiffness, yield force,
  post-yield ratio).
* :class:`BoucWen` — smooth hysteresis of Bouc and Wen.
* :func:`respond_drift_path` — drive a law along a drift history (cyclic push test).
* :class:`BilinearIsolator`, :class:`FrictionPendulum` — isolation bearings, which build one
  of the laws above for the isolation storey of a base-isolated building
  (:mod:`pounding.hysteresis.isolators`, :meth:`pounding.structure.ShearBuilding.base_isolated`).

The contract every law follows (trial/commit, like the contact laws) is in
:mod:`pounding.hysteresis.base`. Attach a law to a building with
``ShearBuilding(..., storey_law=Bilinear(yield_force=…, hardening=0.05))``.
"""

from pounding.hysteresis.base import StoreyLaw
from pounding.hysteresis.bilinear import Bilinear
from pounding.hysteresis.bouc_wen import BoucWen
from pounding.hysteresis.dispatch import respond_drift_path
from pounding.hysteresis.isolators import BilinearIsolator, FrictionPendulum

STOREY_LAWS: dict[str, type[StoreyLaw]] = {"bilinear": Bilinear, "bouc-wen": BoucWen}
"""Storey laws by the name used in model files (``storey_law = {type = "bilinear", …}``)."""

__all__ = ["StoreyLaw", "Bilinear", "BoucWen", "BilinearIsolator", "FrictionPendulum",
           "respond_drift_path", "STOREY_LAWS"]
