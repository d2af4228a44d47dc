"""The one compiled entry point to every contact law.

:func:`contact_trial` switches on a law's integer code and calls that law's compiled trial
function. The Python law objects, the single-collision analysis and the time-history kernel
all go through it, so there is exactly one implementation of each law.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.base import (
    BILINEAR_IMPACT,
    HERTZ,
    HUNT_CROSSLEY,
    KELVIN_VOIGT,
    LINEAR_SPRING,
    MODIFIED_KELVIN_VOIGT,
    NONLINEAR_VISCOELASTIC,
    STATE_SIZE,
)
from pounding.contact.bilinear import bilinear_impact_trial
from pounding.contact.hertz import hertz_trial, hunt_crossley_trial, nonlinear_viscoelastic_trial
from pounding.contact.linear import (
    kelvin_voigt_trial,
    linear_spring_trial,
    modified_kelvin_voigt_trial,
)


@njit(cache=True)
def contact_trial(code, params, delta, rate, committed, out):
    """Trial force of the law ``code`` (contract step 4).

    Parameters
    ----------
    code : int
        Law code (``pounding.contact.base``).
    params : float64[:]
        The law's constants, as ``ContactLaw.params()`` returns them.
    delta, rate : float
        Penetration [m] and its rate [m/s].
    committed : float64[STATE_SIZE]
        Committed state (read only).
    out : float64[STATE_SIZE]
        Receives the trial state.

    Returns
    -------
    (float, float, float)
        Force [N], ∂F/∂δ [N/m], ∂F/∂δ̇ [N·s/m].
    """
    if code == LINEAR_SPRING:
        return linear_spring_trial(params, delta, rate, committed, out)
    if code == KELVIN_VOIGT:
        return kelvin_voigt_trial(params, delta, rate, committed, out)
    if code == MODIFIED_KELVIN_VOIGT:
        return modified_kelvin_voigt_trial(params, delta, rate, committed, out)
    if code == HERTZ:
        return hertz_trial(params, delta, rate, committed, out)
    if code == HUNT_CROSSLEY:
        return hunt_crossley_trial(params, delta, rate, committed, out)
    if code == NONLINEAR_VISCOELASTIC:
        return nonlinear_viscoelastic_trial(params, delta, rate, committed, out)
    if code == BILINEAR_IMPACT:
        return bilinear_impact_trial(params, delta, rate, committed, out)
    raise ValueError("unknown contact law code")


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
