"""What the solver can follow: refusals, before a run, of a model that moves millions of
times faster than any building — a contact, a building or a link whose period (or damping
decay time) is far below the output step. Such a run would overflow (the exact step's
matrix exponential, the adaptive steps) or take hours of ever smaller steps; each is
refused in one line naming the input."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from pounding.model import PoundingModel

if TYPE_CHECKING:
    from pounding.contact.geometry import ContactPoint

CONTACT_PERIOD_FLOOR: float = 1e-6
"""A contact whose natural period is below this fraction of the output step is refused
before the run: the adaptive steps through its impacts would fall to the solver's floor
(10⁻¹⁴ of the step) or use up the step budget. Real building contacts are 10⁻⁴–10⁻¹ s long
against 10⁻³ s steps; a period a million times shorter than the step means masses or a
stiffness far outside any building (a floor mass of 10⁻³⁰⁰ kg, say)."""

REFERENCE_PENETRATION: float = 1e-3
"""Penetration [m] at which a contact's secant stiffness sets its natural period."""


def check_contact_periods(model: PoundingModel, step: float) -> None:
    """Refuse, before the run, a contact that would ring far faster than the solver can
    follow (:data:`CONTACT_PERIOD_FLOOR`): one line naming the contact, the apparent
    masses of its two points and the law.

    The period is ``2π sqrt(m_eff / k)`` with ``m_eff = m1 m2 / (m1 + m2)`` of the two
    points' apparent masses and ``k`` the law's secant stiffness at
    :data:`REFERENCE_PENETRATION` (the natural period of the linearised two-mass impact).
    """
    from pounding.contact.base import m_effective

    floor = CONTACT_PERIOD_FLOOR * step
    for c in model.contacts:
        m1, m2 = (_apparent_mass(model, point) for point in (c.left, c.right))
        k = c.law.secant_stiffness(REFERENCE_PENETRATION)
        period = 2.0 * math.pi * math.sqrt(m_effective(m1, m2) / k)
        if not period >= floor:
            raise ValueError(
                f"contact {c.label}: apparent masses {m1:.3g} kg and {m2:.3g} kg against a "
                f"contact stiffness of {k:.3g} N/m (at {REFERENCE_PENETRATION * 1e3:g} mm) "
                f"ring with a period of {period:.3g} s, below {CONTACT_PERIOD_FLOOR:g} of the "
                f"{step:g} s output step: no building moves that fast; check the floor "
                "masses and the contact stiffness")


def _apparent_mass(model: PoundingModel, point: ContactPoint) -> float:
    """The mass a contact point meets [kg]: of its building's floors, or infinite for a
    point that moves with no building (a moat wall's side, building −1)."""
    if point.building < 0:
        return math.inf
    return point.effective_mass(model.buildings[point.building].masses)


def fastest_dofs(model: PoundingModel) -> tuple[np.ndarray, np.ndarray]:
    """Per DOF, upper bounds of the fastest natural frequency ω [rad/s] and damping rate
    [1/s] of the model's buildings: Gershgorin row sums of ``M^-1/2 |K| M^-1/2`` (≥ every
    ω² of the undamped buildings) and of ``M^-1/2 |C| M^-1/2``. A DOF's fastest motion
    takes about ``2π / max(ω, rate)``; ``inf`` where a sum overflows."""
    sys_ = model.system
    m = np.diag(sys_.M)
    with np.errstate(all="ignore"):
        s = 1.0 / np.sqrt(m)
        w2 = (np.abs(sys_.K) @ s) * s
        rate = (np.abs(sys_.C) @ s) * s
        omega = np.sqrt(w2)
    return (np.where(np.isfinite(omega), omega, np.inf),
            np.where(np.isfinite(rate), rate, np.inf))


def check_building_periods(model: PoundingModel, step: float) -> None:
    """Refuse, before the run, a building that moves far faster than the solver can
    follow: a natural period (or a damping decay time ``2π m/c``) below
    :data:`CONTACT_PERIOD_FLOOR` of the output step — a storey stiffness, floor mass,
    inertia or damping far outside any building's (a storey stiffness of 10³⁰⁰ N/m rings
    with a period of 10⁻¹⁴⁷ s: the exact step's matrix exponential and the adaptive steps
    overflow). One line naming the DOF, its stiffness, mass and damping and the period.

    The periods are bounded below by Gershgorin's circles (:func:`fastest_dofs`); where a
    bound is below the floor, the building's exact fastest period decides.
    """
    floor = CONTACT_PERIOD_FLOOR * step
    omega, rate = fastest_dofs(model)
    fast = np.maximum(omega, rate)
    with np.errstate(divide="ignore"):
        period = 2.0 * math.pi / fast
    if model.n_dof == 0 or float(period.min()) >= floor:
        return
    i = int(np.argmin(period))
    exact = _fastest_period(model, i)
    if exact >= floor:
        return
    if exact <= 0.0:  # (the matrices overflow: the bound of the undamped period, if finite)
        exact = 2.0 * math.pi / float(omega[i]) if omega[i] < np.inf else 0.0
    raise ValueError(_fast_building_text(model, i, exact, step,
                                         bool(omega[i] < rate[i] < np.inf)))


def _fast_building_text(model: PoundingModel, i: int, period: float, step: float,
                        damping: bool) -> str:
    """The line of :func:`check_building_periods`: the building, the inputs at DOF i (a
    shear building's storey stiffness and floor mass as given), and the period."""
    from pounding.structure import ShearBuilding

    sys_ = model.system
    b = int(np.searchsorted(sys_.offsets, i, side="right")) - 1
    j = i - int(sys_.offsets[b])
    building = model.buildings[b]
    name = building.name
    who = f"building B{b + 1}" + (f" ({name})" if name and name != f"B{b + 1}" else "")
    if isinstance(building, ShearBuilding):
        storeys = [s for s in (j, j + 1) if s < building.n]
        s_max = max(storeys, key=lambda s: abs(float(building.stiffnesses[s])))
        inputs = (f"a storey stiffness of {float(building.stiffnesses[s_max]):.3g} N/m (storey "
                  f"{s_max + 1}) and a floor mass of {float(building.masses[j]):.3g} kg (floor "
                  f"{j + 1})")
    else:
        label = model.dof_names()[i]
        k_unit, m_unit = ("N·m/rad", "kg·m²") if label.endswith("θ") else ("N/m", "kg")
        inputs = (f"at {label} a stiffness of {sys_.K[i, i]:.3g} {k_unit} and a mass of "
                  f"{sys_.M[i, i]:.3g} {m_unit}")
    if damping:
        inputs += f" with its damping ({sys_.C[i, i]:.3g} in C)"
    shown = f"{period:.3g} s" if period > 0.0 else "too short a time to represent"
    return (f"{who}: {inputs} make it move with a period of {shown}, below "
            f"{CONTACT_PERIOD_FLOOR:g} of the {step:g} s output step: no building moves "
            "that fast; check its stiffnesses, masses and damping")


def check_link_periods(model: PoundingModel, step: float) -> None:
    """Refuse, before the run, a link between buildings that rings or decays far faster
    than the solver can follow (:data:`CONTACT_PERIOD_FLOOR` of the output step): the
    period ``2π sqrt(m_eff / k)`` of its spring, or the decay time ``2π m_eff / c`` of a
    linear dashpot (α = 1), with ``m_eff = m_a m_b / (m_a + m_b)`` of the two floors'
    masses. One line naming the link, its constants and the masses."""
    floor = CONTACT_PERIOD_FLOOR * step
    m = np.diag(model.system.M)
    for link, (lo, hi) in zip(model.links, model.link_dofs):
        m_a, m_b = float(m[lo]), float(m[hi])
        m_eff = m_a * m_b / (m_a + m_b)
        times = []
        if link.k is not None:
            times.append((2.0 * math.pi * math.sqrt(m_eff / link.k),
                          f"a spring of {link.k:.3g} N/m", "rings with a period of"))
        if link.c is not None and link.alpha == 1.0:
            times.append((2.0 * math.pi * m_eff / link.c, f"a dashpot of {link.c:.3g} N·s/m",
                          "decays in"))
        for time, what, verb in times:
            if not time >= floor:
                raise ValueError(
                    f"link {link.name}: {what} between floor masses of {m_a:.3g} kg and "
                    f"{m_b:.3g} kg {verb} {time:.3g} s, below {CONTACT_PERIOD_FLOOR:g} of the "
                    f"{step:g} s output step: no building moves that fast; check the link's "
                    "k and c")


def _fastest_period(model: PoundingModel, i: int) -> float:
    """The shortest time scale [s] of the building that holds DOF i: ``2π/|λ|`` of its
    largest eigenvalue of the first-order system (0 if the matrices overflow)."""
    import scipy.linalg

    sys_ = model.system
    offsets = list(sys_.offsets) + [model.n_dof]
    b = int(np.searchsorted(sys_.offsets, i, side="right")) - 1
    lo, hi = offsets[b], offsets[b + 1]
    M = sys_.M[lo:hi, lo:hi]
    K = sys_.K[lo:hi, lo:hi]
    C = sys_.C[lo:hi, lo:hi]
    n = hi - lo
    with np.errstate(all="ignore"):
        m_inv = 1.0 / np.diag(M)
        a = np.zeros((2 * n, 2 * n))
        a[:n, n:] = np.eye(n)
        a[n:, :n] = -m_inv[:, None] * K
        a[n:, n:] = -m_inv[:, None] * C
    if not np.all(np.isfinite(a)):
        return 0.0
    try:
        lam = scipy.linalg.eigvals(a)
    except (ValueError, np.linalg.LinAlgError):
        return 0.0
    fastest = float(np.max(np.abs(lam)))
    return 2.0 * math.pi / fastest if fastest > 0.0 else math.inf


RK_STABILITY: float = 3.3
"""The explicit Runge–Kutta steps (Dormand–Prince) are stable up to about this many over
the fastest decay rate |λ| of the motion: a run needs at least ``duration |λ| / 3.3``."""


def stiff_frame_rate(model: PoundingModel) -> tuple[float, str]:
    """Where a yielding frame's adaptive steps are held short by a mode its damping
    over-damps: its decay rate |λ| [1/s] and ``" (B1 'portal': a mode of period 0.45 ms
    damped at ζ = 9.1, whose fast decay the steps must follow every 13 µs …)"``, or
    ``(0, "")`` where no frame has one.

    A yielding frame is stepped by explicit Runge–Kutta, stable for steps up to about
    ``3.3 / |λ|`` with ``λ`` the fastest eigenvalue of its motion; a mode of circular
    frequency ``ω`` damped at ``ζ > 1`` has ``|λ| = ω (ζ + √(ζ² − 1))``. Rayleigh damping's
    stiffness part gives the stiff modes (vertical ones, where nodes carry vertical mass)
    ``ζ = a₁ ω / 2`` far above 1. Modes from the frame's own ``M``, ``K`` and ``C`` (its
    damping is classical: Rayleigh or modal)."""
    import scipy.linalg

    worst: tuple[float, str] = (0.0, "")  # (rate, text)
    for b, bl in model.yielding_frames:
        M, K, C = np.diag(bl.masses), bl.stiffness_matrix(), bl.damping_matrix()
        w2, phi = scipy.linalg.eigh(K, M)
        w = np.sqrt(np.maximum(w2, 0.0))
        zeta = np.einsum("ij,ik,kj->j", phi, C, phi) / np.maximum(2.0 * w, 1e-300)
        rate = w * np.where(zeta > 1.0, zeta + np.sqrt(np.maximum(zeta * zeta - 1.0, 0.0)),
                            1.0)
        j = int(np.argmax(rate))
        if zeta[j] > 1.0 and rate[j] > worst[0]:
            worst = (float(rate[j]), (
                f" (B{b + 1} {bl.name!r}: a mode of period {2e3 * math.pi / w[j]:.3g} ms "
                f"damped at ζ = {zeta[j]:.3g}, whose fast decay the steps must follow every "
                f"{RK_STABILITY * 1e6 / rate[j]:.3g} µs: give that frame modal damping — "
                "damping = { ratio = 0.05 } — or no mass on its stiff, over-damped modes)"))
    return worst
