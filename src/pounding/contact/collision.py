"""One collision of two free bodies, simulated to convergence.

Two masses ``m1`` and ``m2`` close at relative velocity ``v0`` and meet through a contact
law. In the relative coordinate the problem is exactly ``m_eff δ̈ = −F(δ, δ̇)`` with
``m_eff = m1 m2 / (m1 + m2)``, starting at the located instant of contact (``δ = 0``,
``δ̇ = v0``). :func:`simulate_collision` integrates it with SciPy's ``DOP853`` at tight
tolerance, splitting the impact into segments at located events — maximum compression
(``δ̇ = 0``, where laws switch from approach to restitution and the contact state is
committed) and separation (``δ = 0``, or the force returning to zero for laws that cannot
pull) — so no kink of a law is stepped over. The work of the contact force
``W = ∫ F δ̇ dt`` is integrated alongside, as an independent check of the energy lost:
``W = ½ m_eff v0² (1 − e²)``.

This module is the reference against which every damping formula is audited
(:mod:`pounding.contact.audit`) and the engine of calibration and fitting
(:mod:`pounding.contact.calibration`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, minimize_scalar

from pounding.contact.base import ContactLaw, m_effective
from pounding.contact.codes import STATE_SIZE, V0
from pounding.contact.dispatch import check_contact_law, contact_trial
from pounding.validation import positive

RTOL: float = 1e-11
"""Default relative tolerance of the collision integrator (results converge to ~1e-9)."""

STIFF_RATIO: float = 500.0
"""Above this ratio of the dashpot's rate ``(∂F/∂δ̇)/m_eff`` to the elastic contact time, a
collision is integrated with the implicit Radau method instead of DOP853."""

CREEP_AFTER: float = 100.0
"""Elastic contact times after maximum compression beyond which a restitution still going on
is integrated again, from maximum compression, with Radau (an over-damped creep)."""


@dataclass(frozen=True)
class CollisionResult:
    """What one simulated collision did.

    Attributes
    ----------
    law : ContactLaw
        The law simulated.
    m1, m2, m_eff : float
        Masses and effective mass [kg].
    v0 : float
        Approach velocity at first contact [m/s].
    e : float
        Achieved coefficient of restitution, ``−δ̇_end / v0`` (0 if the bodies stick).
    separated : bool
        False if the bodies stuck: still in contact at the end of the time allowed (10⁴
        elastic contact times), or creeping back to δ = 0 with no velocity left.
    duration : float
        Contact duration [s], first contact to separation; NaN if the bodies stuck (the
        time the integration stopped is not a contact duration).
    time_to_max : float
        Time from first contact to maximum compression [s].
    delta_max : float
        Maximum penetration [m].
    peak_force : float
        Maximum contact force [N].
    energy_dissipated : float
        ``∫ F dδ`` over the impact [J], integrated alongside the motion.
    energy_expected : float
        ``½ m_eff v0² (1 − e²)`` [J] from the achieved e.
    t, delta, rate, force : numpy.ndarray
        Sampled histories from first contact to separation [s, m, m/s, N].
    """

    law: ContactLaw
    m1: float
    m2: float
    m_eff: float
    v0: float
    e: float
    separated: bool
    duration: float
    time_to_max: float
    delta_max: float
    peak_force: float
    energy_dissipated: float
    energy_expected: float
    t: NDArray[np.float64] = field(repr=False)
    delta: NDArray[np.float64] = field(repr=False)
    rate: NDArray[np.float64] = field(repr=False)
    force: NDArray[np.float64] = field(repr=False)

    @property
    def energy_error(self) -> float:
        """Relative mismatch between the integrated and the expected energy loss,
        ``|W − ½ m_eff v0² (1 − e²)| / (½ m_eff v0²)``."""
        return abs(self.energy_dissipated - self.energy_expected) / (0.5 * self.m_eff * self.v0**2)

    def force_at(self, t: NDArray[np.float64] | float) -> NDArray[np.float64]:
        """Contact force [N] at times ``t`` [s] after first contact (zero outside contact)."""
        tt = np.asarray(t, dtype=float)
        out = np.interp(tt, self.t, self.force, left=0.0, right=0.0)
        return out


def _elastic_scale(law: ContactLaw, m_eff: float, v0: float) -> float:
    """Penetration [m] at which the law's zero-rate backbone stores ½ m_eff v0².

    Used only to scale tolerances and time limits, never as a result.
    """
    params = law.params()
    st, out = np.zeros(STATE_SIZE), np.zeros(STATE_SIZE)

    def backbone(d: float) -> float:
        return contact_trial(law.code, params, d, 0.0, st, out)[0]

    target = 0.5 * m_eff * v0**2

    def stored(d: float) -> float:
        return quad(backbone, 0.0, d, limit=200)[0] - target

    hi = 1e-6
    while stored(hi) < 0.0:
        hi *= 4.0
        if hi > 1e6:
            raise ValueError(f"{law.label}: contact too soft to stop the bodies")
    return brentq(stored, hi / 4.0 if hi > 1e-6 else 0.0, hi, xtol=hi * 1e-6)


def simulate_collision(law: ContactLaw, m1: float, m2: float, v0: float, *,
                       rtol: float = RTOL, samples: int = 400) -> CollisionResult:
    """Simulate one impact of two free bodies through ``law`` and measure it.

    Parameters
    ----------
    law : ContactLaw
        Any contact law of :mod:`pounding.contact`.
    m1, m2 : float
        Masses of the two bodies [kg] (``inf`` for a rigid wall).
    v0 : float
        Closing velocity at first contact [m/s], > 0.
    rtol : float
        Relative tolerance of ``DOP853``; absolute tolerances are scaled from the elastic
        penetration, ``v0`` and ``½ m_eff v0²``.
    samples : int
        Points per segment in the returned histories.

    Returns
    -------
    CollisionResult

    Examples
    --------
    >>> from pounding.contact import KelvinVoigt
    >>> law = KelvinVoigt.from_restitution(k=1e8, e=0.65, m1=2e5, m2=3e5)
    >>> round(simulate_collision(law, 2e5, 3e5, v0=0.5).e, 6)
    0.65
    """
    check_contact_law(law)
    m_eff = m_effective(m1, m2)
    v0 = positive("v0", v0)
    params = law.params()
    code = law.code
    d_ref = _elastic_scale(law, m_eff, v0)
    t_ref = d_ref / v0
    e_ref = 0.5 * m_eff * v0**2
    atol = np.array([d_ref, v0, e_ref]) * min(rtol, 1e-6) * 1e-2

    committed = np.zeros(STATE_SIZE)
    committed[V0] = v0  # contract step 3, at the located instant of contact
    trial = np.zeros(STATE_SIZE)

    def force(d: float, r: float) -> float:
        return contact_trial(code, params, d, r, committed, trial)[0]

    def rhs(_t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        f = force(y[0], y[1])
        return np.array([y[1], -f / m_eff, f * y[1]])

    def jac(_t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        f, kd, kr = contact_trial(code, params, y[0], y[1], committed, trial)
        return np.array([[0.0, 1.0, 0.0],
                         [-kd / m_eff, -kr / m_eff, 0.0],
                         [kd * y[1], kr * y[1] + f, 0.0]])

    # A dashpot much faster than the contact's elastic time scale makes the problem stiff:
    # then use an implicit Radau method with the law's exact tangents as the Jacobian. The
    # explicit DOP853 stays far faster up to ratios of some hundreds (measured: 10–17 ms
    # against 0.3–0.5 s for Radau at ratios 10–100, with the same e to 1e-12), so Radau only
    # takes over beyond STIFF_RATIO.
    _, _, kr_ref = contact_trial(code, params, d_ref, v0, committed, trial)
    stiff = kr_ref / m_eff * t_ref > STIFF_RATIO
    method = {"method": "Radau", "jac": jac} if stiff else {"method": "DOP853"}

    def at_max(_t: float, y: NDArray[np.float64]) -> float:
        return y[1]

    at_max.terminal = True  # type: ignore[attr-defined]
    at_max.direction = -1.0  # type: ignore[attr-defined]

    def at_separation(_t: float, y: NDArray[np.float64]) -> float:
        return y[0]

    at_separation.terminal = True  # type: ignore[attr-defined]
    at_separation.direction = -1.0  # type: ignore[attr-defined]

    release = law.release_function()
    events_rest: list = [at_separation]
    if release is not None:
        def at_release(_t: float, y: NDArray[np.float64]) -> float:
            return release(y[0], y[1], v0)

        at_release.terminal = True  # type: ignore[attr-defined]
        at_release.direction = -1.0  # type: ignore[attr-defined]
        events_rest.append(at_release)

    segments = []
    y = np.array([0.0, v0, 0.0])
    t0 = 0.0
    # approach: until maximum compression
    sol = solve_ivp(rhs, (t0, t0 + 1e3 * t_ref), y, rtol=rtol, atol=atol,
                    events=[at_max], dense_output=True, **method)
    if sol.status != 1:
        raise RuntimeError(f"{law.label}: maximum compression not reached ({sol.message})")
    segments.append(sol)
    t_max_c = float(sol.t_events[0][0])
    y = sol.y_events[0][0].copy()
    y[1] = 0.0
    contact_trial(code, params, y[0], 0.0, committed, trial)
    committed[:] = trial
    # restitution: until separation, or until the bodies are judged stuck
    t_end_allowed = t_max_c + 1e4 * t_ref
    sol = solve_ivp(rhs, (t_max_c, min(t_end_allowed, t_max_c + CREEP_AFTER * t_ref)), y,
                    rtol=rtol, atol=atol, events=events_rest, dense_output=True, **method)
    if sol.status == 0 and not stiff:
        # still in contact after CREEP_AFTER contact times: an over-damped contact creeping
        # back, whose dashpot limits an explicit method's step (a dashpot ζ = 33 took DOP853
        # 0.4 million steps over the time allowed, a minute); the implicit Radau method with
        # the law's exact tangents goes through the creep in a few hundred
        sol = solve_ivp(rhs, (t_max_c, t_end_allowed), y, rtol=rtol, atol=atol,
                        events=events_rest, dense_output=True, method="Radau", jac=jac)
    segments.append(sol)
    separated = sol.status == 1
    y_end = sol.y[:, -1]
    t_end = float(sol.t[-1])
    if separated:
        for te, ye in zip(sol.t_events, sol.y_events):
            if len(te):
                t_end, y_end = float(te[0]), ye[0]
    v_out = -float(y_end[1])
    # an over-damped contact creeps towards δ = 0 for ever; a round-off crossing after a
    # long creep, with no velocity left, is sticking, not separation
    if separated and v_out <= 1e-9 * v0:
        separated = False
    e = max(v_out, 0.0) / v0 if separated else 0.0
    w = float(y_end[2])

    # sampled histories, with the force recomputed from the committed state of each segment
    ts, ds, rs, fs = [], [], [], []
    state_by_segment = [np.array([v0, 0.0, 0.0]), committed.copy()]
    seg_ends = [(0.0, t_max_c), (t_max_c, t_end)]
    peak = 0.0
    for sol_k, st, (a, b) in zip(segments, state_by_segment, seg_ends):
        tt = np.linspace(a, b, samples)
        yy = sol_k.sol(tt)
        # the contact is closed on the whole closed interval [onset, separation]: evaluate at
        # δ ≥ 0+ so the end samples hold the force's one-sided limits (c v0 at onset for a
        # dashpot law, its tension just before separation), not round-off of the located δ
        ff = np.array([contact_trial(code, params, max(d, 1e-300), r, st, trial)[0]
                       for d, r in zip(yy[0], yy[1])])
        i = int(np.argmax(ff))
        peak = max(peak, float(ff[i]))
        if 0 < i < samples - 1:  # refine the interior maximum on the dense output
            def neg_force(s: float, sol_k: Any = sol_k, st: NDArray[np.float64] = st
                          ) -> float:
                yk = sol_k.sol(s)
                return -contact_trial(code, params, max(yk[0], 1e-300), yk[1], st, trial)[0]

            res = minimize_scalar(neg_force, bounds=(tt[i - 1], tt[i + 1]), method="bounded",
                                  options={"xatol": (b - a) * 1e-12})
            peak = max(peak, -float(res.fun))
        ts.append(tt)
        ds.append(yy[0])
        rs.append(yy[1])
        fs.append(ff)
    return CollisionResult(
        law=law, m1=float(m1), m2=float(m2), m_eff=m_eff, v0=v0, e=e, separated=separated,
        duration=t_end if separated else float("nan"), time_to_max=t_max_c, delta_max=float(segments[0].y_events[0][0][0]),
        peak_force=peak, energy_dissipated=w, energy_expected=0.5 * m_eff * v0**2 * (1.0 - e**2),
        t=np.concatenate(ts), delta=np.concatenate(ds), rate=np.concatenate(rs),
        force=np.concatenate(fs),
    )
