"""The plastic hinges' part of a case's row: what the yielding frames of a run did, in the
terms limit states are written in.

For every hinge of every yielding frame (:attr:`pounding.model.PoundingModel.yielding_frames`)
three things are read from the run's :class:`~pounding.result.Result` (nothing is recomputed
along the hinge laws):

* its **peak rotation** ``max |θ|`` [rad] (the located peak of the Result:
  ``hinge_peak_rotation``);
* its **peak plastic rotation** ``max |θ − M/k0|`` [rad]: the rotation less its elastic part,
  ``k0`` the law's elastic stiffness — the plastic rotation angle of ASCE/SEI 41-17's
  modeling parameters and acceptance criteria for nonlinear procedures (Table 9-7.1 for
  structural steel components). Taken at the output steps: a hinge
  that unloads at ``k0`` (elastic–plastic, bilinear, IMK until its unloading stiffness
  deteriorates) keeps its plastic rotation on the way back, so the first output step after
  a peak holds it exactly; an IMK hinge whose unloading stiffness ``K_u`` has dropped loses
  ``(1 − K_u/k0) Δθ`` of it in the part of a step after the peak (``Δθ`` the rotation in
  that part of the step, small where the hinge turns back);
* whether it went **past its capping point**: for a modified Ibarra–Medina–Krawinkler law
  (:class:`pounding.hysteresis.imk_backbone.IMKLaw`), a rotation on either side beyond
  ``min(θ_cap, θ_u)`` of that side, ``θ_cap = θ_y + θ_p`` (``θ_y = M_y/k0``) the capping
  rotation of the monotonic backbone (Lignos & Krawinkler 2011, Fig. 1) and ``θ_u`` the
  ultimate (fracture) rotation: the hinge was on its negative-stiffness branch, its residual
  plateau, or fractured. The largest rotation on each side is the largest output sample of
  that sign, and the located peak on its side. Cyclic deterioration can move the capping
  point of a hinge inward (the post-capping branch of a deteriorated IMK hinge starts at a
  smaller rotation): a hinge the run saw reach its law's own capping point or fracture
  (``Result.hinge_capped``, from the branch its law put it on) is past its cap too.

A run whose frame lost its strength — its hinges' moments cascading to zero (IMK fractures
at ``θ_u``, complete deterioration) until no equilibrium is left, or a storey swayed past
its own height — stops with a
:class:`~pounding.structure.frame_configuration.FrameCollapse`: :func:`is_strength_loss`
tells it from a run that failed for another reason, and its row says ``strength_lost``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

__all__ = ["HINGE_MEASURES", "HingePeaks", "hinge_peaks",
           "hinge_row", "is_strength_loss", "stopped_row"]

HINGE_MEASURES: dict[str, str] = {
    "peak_hinge_rotation_rad": "float64",
    "peak_plastic_rotation_rad": "float64",
    "hinge_past_cap": "bool",
    "strength_lost": "bool",
}
"""Columns of a sweep's table for models with plastic hinges (column → type), absent for
models without: the largest |rotation| of any hinge [rad]; the largest plastic rotation
``|θ − M/k0|`` of any hinge [rad]; whether any IMK hinge went past its capping rotation (or
its ultimate rotation) on either side (null where no hinge follows an IMK law); and whether
the run stopped because a frame lost its strength (true: the other measures are null)."""


class HingePeaks(NamedTuple):
    """Per hinge of a run (:meth:`pounding.model.PoundingModel.hinge_labels` order)."""

    rotation: NDArray[np.float64]
    """Largest |θ| [rad]."""
    plastic: NDArray[np.float64]
    """Largest |θ − M/k0| [rad]."""
    past_cap: NDArray[np.bool_]
    """Past ``min(θ_cap, θ_u)`` on either side (False for a law without a capping point)."""
    has_cap: NDArray[np.bool_]
    """Whether the hinge's law has a capping point (the IMK laws)."""


def _laws(model: Any) -> list[Any]:
    """The hinge law of every hinge of the model's yielding frames, in hinge order."""
    return [fh.law for _, bl in model.yielding_frames for fh in bl.frame.hinges]


def _cap_rotations(law: Any) -> tuple[float, float] | None:
    """``min(θ_cap, θ_u)`` of the positive and the negative side [rad], as magnitudes; None
    for a law without a capping point."""
    from pounding.hysteresis.imk_backbone import IMKLaw

    if not isinstance(law, IMKLaw):
        return None
    sides = law.sides
    return (min(sides[1].ucap0, sides[1].uu), min(sides[-1].ucap0, sides[-1].uu))


def hinge_peaks(result: Any) -> HingePeaks | None:
    """Peak rotation, peak plastic rotation and capping of every hinge of a run (module
    docstring); None for a model without yielding frames.

    Parameters
    ----------
    result : pounding.result.Result
        A finished run.
    """
    model = result.model
    laws = _laws(model)
    if not laws or result.hinge_peak_rotation is None:
        return None
    theta = np.asarray(result.hinge_rotation, dtype=float)
    moment = np.asarray(result.hinge_moment, dtype=float)
    k0 = np.array([float(law.k0) for law in laws])
    peak = np.asarray(result.hinge_peak_rotation, dtype=float)
    t_peak = np.asarray(result.hinge_peak_rotation_time, dtype=float)
    t = np.asarray(result.time, dtype=float)
    n = len(laws)
    plastic = np.abs(theta - moment / k0).max(axis=0) if theta.size else np.zeros(n)
    past = np.zeros(n, dtype=bool)
    has_cap = np.zeros(n, dtype=bool)
    for h, law in enumerate(laws):
        caps = _cap_rotations(law)
        if caps is None:
            continue
        has_cap[h] = True
        th_h = theta[:, h]
        at = float(np.interp(t_peak[h], t, th_h))
        if at == 0.0:  # the located peak between two samples of opposite sign: the larger one
            at = float(th_h[np.argmax(np.abs(th_h))])
        side = 1.0 if at >= 0.0 else -1.0
        largest_pos = max(float(th_h.max()), peak[h] if side > 0 else 0.0)
        largest_neg = max(float(-th_h.min()), peak[h] if side < 0 else 0.0)
        past[h] = largest_pos > caps[0] or largest_neg > caps[1]
    if result.hinge_capped is not None:  # on its law's own post-capping branch, or fractured
        past |= np.asarray(result.hinge_capped, dtype=bool) & has_cap
    return HingePeaks(peak.copy(), plastic, past, has_cap)


def hinge_row(result: Any) -> dict[str, Any]:
    """The :data:`HINGE_MEASURES` of a finished run (empty for a model without plastic
    hinges)."""
    p = hinge_peaks(result)
    if p is None:
        return {}
    return {"peak_hinge_rotation_rad": float(p.rotation.max()),
            "peak_plastic_rotation_rad": float(p.plastic.max()),
            "hinge_past_cap": bool(p.past_cap.any()) if p.has_cap.any() else None,
            "strength_lost": False}


def is_strength_loss(exc: BaseException) -> bool:
    """Whether a run stopped because a frame lost its strength — its hinges' moments
    cascading to zero, or a storey swayed past its height
    (:class:`pounding.structure.frame_configuration.FrameCollapse`) — rather than failed."""
    from pounding.structure.frame_configuration import FrameCollapse

    return isinstance(exc, FrameCollapse)


def stopped_row(exc: BaseException) -> dict[str, Any]:
    """The :data:`HINGE_MEASURES` of a run that raised ``exc``: ``strength_lost`` true for a
    frame that lost its strength, nothing otherwise (a failed run)."""
    if not is_strength_loss(exc):
        return {}
    return {"peak_hinge_rotation_rad": None, "peak_plastic_rotation_rad": None,
            "hinge_past_cap": None, "strength_lost": True}
