"""The yielding frames' part of a grid point's outputs (:func:`pounding.integrate.adaptive.
grid_outputs`): every hinge's rotation and moment, and the frames' strain and hysteretic
energy. Called, not inlined, and only where there are frames: inlined into the adaptive
loop, its loops cost the SDOF pair's contact steps 5 %."""

from __future__ import annotations

from numba import njit

from pounding.integrate.layout import (
    HS_K_UNLOAD,
    HS_KT,
    HS_M_C,
    HS_Q,
    HS_REC0,
    HS_THETA_C,
    HS_WORK_C,
)
from pounding.integrate.rhs import NRT_FREE, hinge_row


@njit(**NRT_FREE)
def frame_outputs(o, x, n, fl, hg, rotation, moment):
    """The yielding frames' part of :func:`grid_outputs` at output ``o``, state ``x``: every
    hinge's rotation and moment (written to row o of ``rotation`` and ``moment``), and
    ``(strain, hysteretic)`` energy [J]: the frames' restoring-force work less their
    hinges' hysteretic energy, beyond the ``½ uᵀ K u`` of their floors, and that hysteretic
    energy ``Σ (∫ M dθ − M²/(2 k_unload))`` less its value at the start.

    A frame's work within a configuration is ``½ uᵀ K u + f0ᵀ u + c`` (``fl.f_rows``: each
    floor's DOF, f0 and c, set at each event so that it runs on continuously); a hinge's
    ``∫ M dθ`` is exact along its branch (M linear in θ since the last commit)."""
    hst = hg.state
    e_hinge = 0.0
    for q in range(hst.shape[0]):
        th = hinge_row(q, x, n, hg)[0]
        mom = hst[q, HS_KT] * th + hst[q, HS_Q]
        rotation[o, q] = th
        moment[o, q] = mom
        work_q = hst[q, HS_WORK_C] + 0.5 * (hst[q, HS_M_C] + mom) * (th - hst[q, HS_THETA_C])
        e_hinge += work_q - 0.5 * mom * mom / hst[q, HS_K_UNLOAD] + hst[q, HS_REC0]
    fr = fl.f_rows
    e_frame = 0.0
    for q in range(fr.shape[0]):
        e_frame += fr[q, 1] * x[int(fr[q, 0])] + fr[q, 2]
    return e_frame - e_hinge, e_hinge
