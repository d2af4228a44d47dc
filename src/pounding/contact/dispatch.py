"""The one compiled entry point to every contact law.

:func:`law_trial` switches on a law's integer code (:mod:`pounding.contact.codes`) and
calls that law's compiled, pure, scalar trial function (:mod:`pounding.contact.kernels`).
The time-history kernel calls it directly; :func:`contact_trial` wraps it for arrays (used
by the Python law objects and the single-collision analysis). So there is exactly one
implementation of each law.

A code that no branch implements is not run as some other law: the compiled functions
return NaN (the failure value the kernel reports as an
:class:`~pounding.integrate.IntegrationError`), and :func:`check_contact_law` refuses such a
law in Python, in one line naming its class and code, where a model is built and before a
law object computes anything.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.codes import (
    ABUTMENT,
    BROKEN,
    BILINEAR_IMPACT,
    DMAX,
    HERTZ,
    HUNT_CROSSLEY,
    KELVIN_VOIGT,
    LINEAR_SPRING,
    MODIFIED_KELVIN_VOIGT,
    NONLINEAR_VISCOELASTIC,
    SHEAR_KEY,
    SLIP,
    STATE_SIZE,
    V0,
)
from pounding.contact.kernels import (
    abutment_backbone,
    abutment_trial,
    bilinear_impact_trial,
    hertz_trial,
    hunt_crossley_trial,
    kelvin_voigt_trial,
    linear_spring_trial,
    modified_kelvin_voigt_trial,
    nonlinear_viscoelastic_trial,
    shear_key_trial,
)

PARAMS_SIZE: int = 3
"""Every law's constants fit in three numbers (zero-padded)."""

CONTACT_LAW_CODES: dict[int, str] = {
    LINEAR_SPRING: "linear spring", KELVIN_VOIGT: "Kelvin-Voigt",
    MODIFIED_KELVIN_VOIGT: "modified Kelvin-Voigt", HERTZ: "Hertz",
    HUNT_CROSSLEY: "Hunt-Crossley", NONLINEAR_VISCOELASTIC: "nonlinear viscoelastic",
    BILINEAR_IMPACT: "bilinear impact", ABUTMENT: "abutment backfill",
    SHEAR_KEY: "shear key",
}
"""The codes :func:`law_trial` implements, each with its law (a branch apiece)."""


def unknown_code_text(kind: str, law: object, code: object, codes: dict[int, str]) -> str:
    """One line: a law whose code no compiled branch implements, and the codes there are."""
    known = ", ".join(f"{k} {name}" for k, name in codes.items())
    return (f"{kind} {type(law).__name__} has code {code}, which no compiled {kind} "
            f"implements (codes: {known}); a new law needs its own code and branch")


def check_contact_law(law: object) -> None:
    """Refuse a contact law whose :attr:`~pounding.contact.base.ContactLaw.code` the compiled
    dispatcher does not implement (a subclass with a new code would otherwise compute
    nothing: NaN): a ``ValueError`` naming the law's class and code."""
    code = getattr(law, "code", None)
    if not isinstance(code, (int, np.integer)) or int(code) not in CONTACT_LAW_CODES:
        raise ValueError(unknown_code_text("contact law", law, code, CONTACT_LAW_CODES))


@njit(cache=True, inline="always", error_model="numpy")
def law_trial(code, p0, p1, p2, delta, rate, v0, slip, dmax):
    """Trial of the law ``code`` (contract step 4), all scalars.

    Returns
    -------
    (F [N], ∂F/∂δ [N/m], ∂F/∂δ̇ [N·s/m], v0', slip', dmax')
        For a code not in :data:`CONTACT_LAW_CODES`, F and both tangents are NaN: no law
        stands in for an unknown one.
    """
    if code == LINEAR_SPRING:
        return linear_spring_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == KELVIN_VOIGT:
        return kelvin_voigt_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == MODIFIED_KELVIN_VOIGT:
        return modified_kelvin_voigt_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == HERTZ:
        return hertz_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == HUNT_CROSSLEY:
        return hunt_crossley_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == NONLINEAR_VISCOELASTIC:
        return nonlinear_viscoelastic_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == BILINEAR_IMPACT:
        return bilinear_impact_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == ABUTMENT:
        return abutment_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    if code == SHEAR_KEY:
        return shear_key_trial(p0, p1, p2, delta, rate, v0, slip, dmax)
    return np.nan, np.nan, np.nan, v0, slip, dmax


@njit(cache=True, inline="always")
def has_linear_spring(code):
    """True for the laws whose spring is linear in δ (∂F/∂δ bounded at δ = 0): linear
    spring, Kelvin–Voigt, modified Kelvin–Voigt, bilinear impact, abutment backfill (its
    backbone's slope at δ = 0 is K), shear key. The Hertz family's is not (a Hertz-damped
    law's ∂F/∂δ is unbounded at δ = 0 while approaching)."""
    return (code == LINEAR_SPRING or code == KELVIN_VOIGT or code == MODIFIED_KELVIN_VOIGT
            or code == BILINEAR_IMPACT or code == ABUTMENT or code == SHEAR_KEY)


@njit(cache=True, inline="always")
def keeps_set(code):
    """True for a law whose ``state[SLIP]`` is a permanent set that outlasts its impact
    (the abutment backfill, the shear key — whose set says also whether it has broken
    off): the kernel keeps it when the gap opens and at the next onset, where it zeroes
    every other law's state."""
    return code == ABUTMENT or code == SHEAR_KEY


@njit(cache=True, inline="always")
def can_break(code, p2, slip):
    """True for a shear key that is intact and breaks off at a fracture deformation
    (params ``[k, F_c, δ_u]``, ``δ_u > 0``; its ``slip`` not :data:`BROKEN`): the kernel
    locates the instant its penetration reaches ``δ_u`` (:func:`fracture_value`)."""
    return code == SHEAR_KEY and p2 > 0.0 and slip != BROKEN


@njit(cache=True, inline="always")
def is_broken(code, slip):
    """True for a shear key that has broken off (its ``slip`` :data:`BROKEN`): its gap
    closing again is no impact — it has nothing left to push with."""
    return code == SHEAR_KEY and slip == BROKEN


@njit(cache=True, inline="always")
def fracture_value(p2, delta):
    """The event function of a key's fracture, ``δ − δ_u`` [m]: it crosses zero upward
    where the key breaks off (:func:`can_break`). Its rate is the penetration's."""
    return delta - p2


@njit(cache=True, inline="always")
def law_releases(code, p0, p1, p2):
    """True for a law whose force returns to zero *before* δ = 0 and is clipped there:
    Kelvin–Voigt without tension and with a dashpot (params ``[k, c, 0]``)."""
    return code == KELVIN_VOIGT and p2 == 0.0 and p1 > 0.0


@njit(cache=True, inline="always")
def release_value(p0, p1, delta, rate):
    """The unclipped force ``k δ + c δ̇`` of a releasing law (:func:`law_releases`): it
    crosses zero downward where the clipped force leaves the bodies with the spring still
    compressed (Schwager & Pöschel 2007, Granular Matter 9:465–469), upward where a
    released contact engages again before δ = 0. The time-history kernel locates both as
    events, so no step integrates across the clip's kink."""
    return p0 * delta + p1 * rate


@njit(cache=True)
def contact_trial(code, params, delta, rate, committed, out):
    """Array form of :func:`law_trial`: reads ``committed`` (STATE_SIZE), writes the trial
    state into ``out``, returns ``(F, ∂F/∂δ, ∂F/∂δ̇)``."""
    p = np.zeros(PARAMS_SIZE)
    for i in range(min(params.shape[0], PARAMS_SIZE)):
        p[i] = params[i]
    f, kd, kr, v0, slip, dmax = law_trial(code, p[0], p[1], p[2], delta, rate, committed[V0],
                                          committed[SLIP], committed[DMAX])
    out[V0] = v0
    out[SLIP] = slip
    out[DMAX] = dmax
    return f, kd, kr


@njit(cache=True)
def respond_path(code, params, delta, rate):
    """Force history along a sampled (δ, δ̇) path, committing after every sample."""
    n = delta.shape[0]
    force = np.empty(n)
    committed = np.zeros(STATE_SIZE)
    trial = np.zeros(STATE_SIZE)
    for i in range(n):
        f, _, _ = contact_trial(code, params, delta[i], rate[i], committed, trial)
        force[i] = f
        committed[:] = trial
    return force


@njit(cache=True, inline="always", error_model="numpy")
def stored_energy(code, p0, p1, p2, delta, slip):
    """Elastic energy [J] the contact would give back if unloaded now (scalar form).

    The work the contact force has done on the bodies, minus this, is the energy the impact
    has dissipated so far. Zero while the gap is open; NaN for a code not in
    :data:`CONTACT_LAW_CODES`.
    """
    if delta <= 0.0:
        return 0.0
    if code == LINEAR_SPRING or code == KELVIN_VOIGT or code == MODIFIED_KELVIN_VOIGT:
        return 0.5 * p0 * delta * delta
    if code == HERTZ or code == HUNT_CROSSLEY:
        return p0 * delta ** (p1 + 1.0) / (p1 + 1.0)
    if code == NONLINEAR_VISCOELASTIC:
        return p0 * delta * delta * np.sqrt(delta) / 2.5  # k_h δ^2.5 / 2.5
    if code == BILINEAR_IMPACT:
        # K2 spring plus the elastic part of the elasto-plastic branch
        kp = p0 - p1
        fp = min(max(kp * (delta - slip), 0.0), kp * p2)
        return 0.5 * p1 * delta * delta + 0.5 * fp * fp / kp
    if code == ABUTMENT:
        # the elastic part F²/(2K) of the force on the line K (δ − set) or the backbone
        f = min(p0 * (delta - slip), abutment_backbone(p0, p1, p2, delta)[0])
        return 0.5 * f * f / p0 if f > 0.0 else 0.0
    if code == SHEAR_KEY:
        # F²/(2k) of the force on the line k (δ − set), capped at the capacity; a broken
        # key (set +∞) holds nothing
        f = min(p0 * (delta - slip), p1)
        return 0.5 * f * f / p0 if f > 0.0 else 0.0
    return np.nan


@njit(cache=True)
def contact_stored_energy(code, params, delta, state):
    """Array form of :func:`stored_energy` (``state`` as the contract's vector)."""
    p = np.zeros(PARAMS_SIZE)
    for i in range(min(params.shape[0], PARAMS_SIZE)):
        p[i] = params[i]
    return stored_energy(code, p[0], p[1], p[2], delta, state[SLIP])
