"""What a run that stops says, in one line (:class:`pounding.integrate.IntegrationError`):
why and when the integration stopped (the adaptive step's budget, a step too small, a state
that overflowed, a law code no compiled law implements), what was closed then, and the
inputs most likely to blame."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from pounding.integrate.layout import (
    FAIL_BUDGET,
    FAIL_NONFINITE,
    FAIL_UNKNOWN_LAW,
    I_FAIL_ROW,
    I_FAIL_STEP,
    I_FAILED,
    I_STEP_BUDGET,
)
from pounding.integrate.periods import stiff_frame_rate

if TYPE_CHECKING:
    from pounding.ground_motion import GroundMotion, GroundMotionComponents
    from pounding.integrate.kernel_model import KernelModel
    from pounding.model import PoundingModel

__all__ = ["failure_text", "nonfinite_text", "unknown_law_text"]


def failure_text(model: PoundingModel, km: KernelModel,
                  motion: GroundMotion | GroundMotionComponents, ws_i: np.ndarray,
                  committed: np.ndarray, step: float, rtol: float) -> str:
    """One line: why and when the integration stopped, the contacts closed then, and what
    to check."""
    t = int(ws_i[I_FAIL_STEP]) * step
    if ws_i[I_FAILED] == FAIL_NONFINITE:
        return nonfinite_text(model, motion, t, step)
    if ws_i[I_FAILED] == FAIL_UNKNOWN_LAW:
        return unknown_law_text(model, km, int(ws_i[I_FAIL_ROW]))
    closed = [c.label for c, st in zip(model.contacts, committed) if st[0] > 0.0]
    where = (f" with contact {', '.join(closed[:4])}{' …' if len(closed) > 4 else ''} closed"
             if closed else "")
    if ws_i[I_FAILED] == FAIL_BUDGET:
        why = (f"solver: stopped after {int(ws_i[I_STEP_BUDGET]):,} adaptive steps at "
               f"t = {t:.4f} s{where}")
    else:
        why = (f"solver: the adaptive step fell below 1e-14 of the {step:g} s output step at "
               f"t = {t:.4f} s{where} (rtol = {rtol:g})")
    stiff = stiff_frame_rate(model)[1] if ws_i[I_FAILED] == FAIL_BUDGET and not closed else ""
    if stiff:
        return why + ": a yielding frame's damping over-damps a stiff mode" + stiff
    return (why + ": the model moves millions of times faster than a building does there; "
            "check the masses, storey and contact stiffnesses and the contact damping "
            "(e.g. e far below 0.1), or raise max_rk_steps")


def unknown_law_text(model: PoundingModel, km: KernelModel, row: int) -> str:
    """One line for a contact or element row whose law code no compiled law implements."""
    from pounding.contact.dispatch import CONTACT_LAW_CODES
    from pounding.devices.laws import DEVICE_CODES, DEVICE_MIN
    from pounding.hysteresis.dispatch import STOREY_LAW_CODES

    nc = km.contacts.gap.size
    if row < nc:
        what, code, codes = f"contact {model.contacts[row].label}", \
            int(km.contacts.code[row]), CONTACT_LAW_CODES
    else:
        s = row - nc
        n_storeys = len(model.element_rows)
        what = ((f"yielding storey {s + 1}" if model.element_rows[s][1].storey >= 0
                 else f"element {model.element_labels()[s]}") if s < n_storeys
                else f"link {model.links[s - n_storeys].name}")
        code = int(km.elements.code[s])
        codes = DEVICE_CODES if code >= DEVICE_MIN else STOREY_LAW_CODES
    known = ", ".join(f"{k} {name}" for k, name in codes.items())
    return (f"solver: {what} has law code {code}, which no compiled law implements "
            f"(codes: {known}): refused, not run as another law")


def nonfinite_text(model: PoundingModel, motion: GroundMotion | GroundMotionComponents,
                    t: float | None, step: float) -> str:
    """One line for a state (or the exact step's matrices, ``t`` None) that stopped being
    finite numbers: when, and the inputs most likely to blame — the record's peak, and the
    building DOF that moves fastest (its stiffness, mass and damping)."""
    from pounding.integrate.periods import fastest_dofs

    when = (f"the state stopped being finite numbers (an overflow) at t = {t:.4f} s"
            if t is not None else
            f"the exact step over {step:g} s overflowed (its matrix exponential is not "
            "finite)")
    record = f"the record's PGA is {motion.pga:.3g} m/s² ({motion.pga_g:.3g} g)"
    suspects = []
    if model.n_dof:
        omega, rate = fastest_dofs(model)
        i = int(np.argmax(np.maximum(omega, rate)))
        sys_ = model.system
        b = int(np.searchsorted(sys_.offsets, i, side="right")) - 1
        suspects.append(f"the fastest DOF, B{b + 1}{model.dof_names()[i]}, has a stiffness "
                        f"of {sys_.K[i, i]:.3g}, a mass of {sys_.M[i, i]:.3g} and a damping "
                        f"of {sys_.C[i, i]:.3g} (SI units)")
    # a record far stronger than any earthquake (PGA above 10 g) first
    suspects.insert(0 if not motion.pga_g <= 10.0 else len(suspects), record)
    return (f"solver: {when}: check the stiffness, mass, damping and record values ("
            + "; ".join(suspects) + ")")
