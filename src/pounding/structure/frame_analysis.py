"""Static analyses of a frame, event to event: gravity first, then a pushover.

Every hinge law is piecewise linear along a monotonic path
(:mod:`pounding.hysteresis.hinges`), so between two *events* — a hinge reaching the end of
its branch (yield, capping, residual, ultimate) — the frame is linear and its response to a
growing load or displacement is a straight line. The analysis goes from event to event
(the classical event-to-event method of plastic analysis; Powell, *Nonlinear Dynamic
Analysis of Structures*, CSI 1993; Neal, *The Plastic Methods of Structural Analysis*):

1. in the current configuration (each hinge on its branch for the direction it is moving),
   solve once for the response to a unit increment of the control (a load factor, or the
   roof displacement) — a bordered system ``[[K_t, −P], [cᵀ, c_λ]]`` that stays regular when
   ``K_t`` is singular or negative (a mechanism or the deteriorating branch under
   displacement control);
2. check that every hinge moves the way its branch assumed (a hinge assumed loading that
   would unload is given its unloading branch, and the solve repeated);
3. advance to the nearest event in closed form, land the hinge that causes it exactly on its
   breakpoint, commit, and repeat.

There are no equilibrium iterations, so nothing can fail to converge; the curve is exact
(piecewise linear between the events it reports). It stops at the target, when the frame
becomes a mechanism under load control (gravity it cannot carry), or — under displacement
control — when the control can no longer grow (a snap-back), each said in the result.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.hinges import HingeState
from pounding.structure.frame import Frame
from pounding.structure.frame_mass import frame_mass_matrix
from pounding.structure.frame_stiffness import (
    FrameDofs,
    condense,
    configuration_stiffness,
    elastic_stiffness,
    element_end_forces,
    frame_dofs,
    geometric_stiffness,
    gravity_load_vector,
    hinge_incidence,
    hinge_rotations,
)

__all__ = ["FrameState", "PushoverResult", "gravity", "lateral_pattern", "pushover",
           "frame_modes", "PATTERNS"]

PATTERNS: tuple[str, ...] = ("first-mode", "uniform", "triangular")
"""Lateral load patterns of a pushover (ASCE 41-17 §7.4.3.2.3 and FEMA 356 §3.3.3.2.3)."""

MAX_EVENTS: int = 200_000
"""A bound on the events of one analysis (each is one linear solve)."""


@dataclass
class FrameState:
    """Where a frame stands after an analysis: displacements, load factors, hinge states."""

    frame: Frame
    dofs: FrameDofs
    base: NDArray[np.float64]  #: elastic + geometric stiffness (hinges excluded)
    U: NDArray[np.float64]  #: displacements [m, rad]
    hinges: list[HingeState]
    directions: NDArray[np.int64]  #: last direction each hinge moved (+1/−1; 0: not yet)
    gravity_factor: float = 0.0
    axial: NDArray[np.float64] | None = None  #: column axial forces of the gravity analysis
    peak_rotation: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))

    def hinge_moments(self) -> NDArray[np.float64]:
        """Hinge moments [N·m]."""
        return np.array([s.moment for s in self.hinges])

    def hinge_rotations(self) -> NDArray[np.float64]:
        """Hinge rotations [rad]."""
        return np.array([s.theta for s in self.hinges])

    def floor_displacements(self) -> NDArray[np.float64]:
        """Lateral displacement of each floor [m]."""
        return self.dofs.floor @ self.U


def _start(frame: Frame) -> FrameState:
    dofs = frame_dofs(frame)
    K = elastic_stiffness(frame, dofs)
    nh = len(frame.hinges)
    return FrameState(frame, dofs, K, np.zeros(dofs.n), [h.law.start() for h in frame.hinges],
                      np.zeros(nh, dtype=np.int64), peak_rotation=np.zeros(nh))


def _tangents(state: FrameState, directions: NDArray[np.int64]) -> NDArray[np.float64]:
    laws = [h.law for h in state.frame.hinges]
    return np.array([laws[h].branch(state.hinges[h], int(directions[h]) or 1).k_t
                     for h in range(len(laws))])


def _hinge_matrix(dofs: FrameDofs, tangents: NDArray[np.float64]) -> Any:
    """The hinges' springs as a sparse matrix, ``B diag(k) Bᵀ`` (:func:`configuration_stiffness`
    without the base)."""
    import scipy.sparse

    B = hinge_incidence(dofs)
    return (B @ scipy.sparse.diags(np.asarray(tangents, dtype=float)) @ B.T).tocsc()


def _solve_unit(K: Any, P: NDArray[np.float64], control: NDArray[np.float64],
                load_control: bool, drive: NDArray[np.float64] | None = None
                ) -> tuple[NDArray[np.float64], float] | None:
    """``(dU, dλ)`` for a unit increment of the control: ``K dU = P dλ`` with ``dλ = 1`` (load
    control) or ``control · dU = 1``; ``K`` sparse. With ``drive`` (a redistribution,
    :func:`_advance`): ``K dU − P dλ = drive`` with the control held (``dλ = 0`` or
    ``control · dU = 0``). DOFs with no stiffness at all (a joint
    whose every connection is a plastic hinge of zero tangent) do not move. None if
    singular.

    The bordered matrix ``[[K, −P], [cᵀ, c_λ]]`` is equilibrated (rows and columns by the
    square root of the diagonal's size, so that the pivots compare DOFs of different units)
    and factorised sparse (SuperLU); a pivot 1e-15 below the largest means singular."""
    import scipy.sparse
    import scipy.sparse.linalg

    n = K.shape[0]
    K = scipy.sparse.csc_matrix(K)
    nonzero = np.diff(K.indptr) > 0
    live = np.flatnonzero(nonzero & (np.abs(K).sum(axis=0).A1 > 0.0))
    Kl = K[live][:, live]
    border_row = (scipy.sparse.csr_matrix(([1.0], ([0], [live.size])), shape=(1, live.size + 1))
                  if load_control else scipy.sparse.hstack(
                      [scipy.sparse.csr_matrix(control[live]), scipy.sparse.csr_matrix((1, 1))]))
    A = scipy.sparse.vstack([scipy.sparse.hstack([Kl, scipy.sparse.csc_matrix(-P[live][:, None])]),
                             border_row]).tocsc()
    diag = np.abs(A.diagonal())
    scale = float(abs(A).max()) if A.nnz else 1.0
    d = np.sqrt(np.maximum(diag, scale * 1e-30))
    if not load_control:
        d[-1] = 1.0
    Dinv = scipy.sparse.diags(1.0 / d)
    As = (Dinv @ A @ Dinv).tocsc()
    rhs = np.zeros(live.size + 1)
    if drive is None:
        rhs[-1] = 1.0
    else:
        rhs[:-1] = drive[live]
    try:
        lu = scipy.sparse.linalg.splu(As, permc_spec="COLAMD")
    except RuntimeError:  # exactly singular
        return None
    pivots = np.abs(lu.U.diagonal())
    if not np.all(np.isfinite(pivots)) or np.min(pivots) <= 1e-15 * np.max(pivots):
        return None
    x = lu.solve(rhs / d) / d
    if not np.all(np.isfinite(x)):
        return None
    dU = np.zeros(n)
    dU[live] = x[:-1]
    return dU, float(x[-1])


@dataclass
class _Path:
    """The points of a piecewise-linear path: control, load factor, displacements."""

    lam: list[float] = field(default_factory=list)
    U: list[NDArray[np.float64]] = field(default_factory=list)
    moments: list[NDArray[np.float64]] = field(default_factory=list)
    rotations: list[NDArray[np.float64]] = field(default_factory=list)


def _jump_force(dofs: FrameDofs, h: int, dm: float) -> NDArray[np.float64]:
    """The out-of-balance force when hinge ``h``'s moment jumps by ``dm`` [N·m] at fixed
    rotation (fracture at the ultimate rotation, complete deterioration): the hinge pushes
    ``+M`` on its node's rotation and ``−M`` on the member end's, so equilibrium is restored
    by ``K ΔU = −b_h dm``."""
    r = np.zeros(dofs.n)
    r[dofs.hinge[h]] += dm
    if dofs.hinge_node[h] >= 0:
        r[dofs.hinge_node[h]] -= dm
    return r


def _advance(state: FrameState, P: NDArray[np.float64], control: NDArray[np.float64] | None,
             lam0: float, target: float, path: _Path | None,
             stop_below: float | None = None, drive: NDArray[np.float64] | None = None,
             depth: int = 0) -> tuple[float, str]:
    """Move the control from its current value to ``target`` event by event; returns the
    final load factor and why it stopped (``"target"``, ``"mechanism"``, ``"snap-back"``,
    ``"strength"``).

    A hinge whose moment jumps at an event (a law that fractures at its ultimate rotation,
    or deteriorates completely) leaves the frame out of balance at the same control: the
    out-of-balance force is then released event by event at that control — ``drive`` is
    that force and the control is the fraction of it released, from 0 to ``target`` = 1 — so
    the other hinges take the moment it shed (yielding or unloading on the way), and the
    curve drops at that roof displacement. A jump during a release is released the same
    way, inside it."""
    frame, dofs = state.frame, state.dofs
    laws = [h.law for h in frame.hinges]
    nh = len(laws)
    load_control = control is None
    lam = lam0
    if drive is not None:
        c_now = 0.0
    else:
        c_now = lam if load_control else float(control @ state.U)  # type: ignore[operator]
    peak_lam = abs(lam)
    import scipy.sparse

    base_sparse = scipy.sparse.csc_matrix(state.base)
    for _ in range(MAX_EVENTS):
        remaining = target - c_now
        if remaining <= 1e-14 * max(1.0, abs(target)):
            return lam, "target"
        directions = state.directions.copy()
        solved = None
        for _it in range(2 * nh + 2):
            K = base_sparse + _hinge_matrix(dofs, _tangents(state, directions))
            solved = _solve_unit(K, P, control if control is not None else np.zeros(0),
                                 load_control, drive)
            if solved is None:
                break
            dth = hinge_rotations(dofs, solved[0])
            flips = []
            for h in range(nh):
                tiny = 1e-12 * (np.max(np.abs(dth)) if nh else 0.0)
                if abs(dth[h]) <= tiny:
                    continue
                want = 1 if dth[h] > 0 else -1
                if want != (directions[h] or want):
                    st = state.hinges[h]
                    if laws[h].branch(st, want).k_t != laws[h].branch(st, -want).k_t:
                        flips.append(h)
                    directions[h] = want
                elif directions[h] == 0:
                    directions[h] = want
            if not flips:
                break
        if solved is None:
            return lam, "mechanism"
        dU, dlam = solved
        dth = hinge_rotations(dofs, dU)
        if drive is None and load_control is False and dlam == 0.0 and not np.any(dU):
            return lam, "snap-back"
        # nearest event along the control
        step = remaining
        hits: list[int] = []
        # a hinge turns only as fast as rounding allows (or against the way its branch was
        # chosen, by rounding): it reaches no breakpoint in this segment
        moving = 1e-12 * (float(np.max(np.abs(dth))) if nh else 0.0)
        for h in range(nh):
            if directions[h] == 0 or dth[h] * directions[h] <= moving:
                continue
            br = laws[h].branch(state.hinges[h], int(directions[h]))
            if not math.isfinite(br.theta_end):
                continue
            s = (br.theta_end - state.hinges[h].theta) / dth[h]
            if s < 0.0:
                s = 0.0
            if s < step - 1e-15 * max(1.0, step):
                step, hits = s, [h]
            elif abs(s - step) <= 1e-15 * max(1.0, step):
                hits.append(h)
        state.U = state.U + step * dU
        lam += step * dlam
        c_now += step
        theta = hinge_rotations(dofs, state.U)
        jumps: list[tuple[int, float]] = []
        shown = np.zeros(nh)
        for h in range(nh):
            before = state.hinges[h]
            br = laws[h].branch(before, int(directions[h]) or 1)
            theta_h = br.theta_end if h in hits else float(theta[h])
            # the moment the segment's linear solution assumed (its branch's tangent)
            continuous = before.moment + br.k_t * (theta_h - before.theta)
            state.hinges[h] = laws[h].moved(before, theta_h)
            shown[h] = continuous
            if abs(state.hinges[h].moment - continuous) > 1e-9 * laws[h].m_y:
                jumps.append((h, state.hinges[h].moment - continuous))
            else:
                shown[h] = state.hinges[h].moment
            state.peak_rotation[h] = max(state.peak_rotation[h], abs(theta_h))
        state.directions = directions
        if path is not None:
            path.lam.append(lam)
            path.U.append(state.U.copy())
            path.moments.append(shown)
            path.rotations.append(state.hinge_rotations())
        if jumps:
            if depth > 50:
                raise RuntimeError(f"{frame.name}: more than 50 moment jumps in a cascade")
            release = sum(_jump_force(dofs, h, dm) for h, dm in jumps)
            lam, why = _advance(state, P, control, lam, 1.0, path, None,
                                np.asarray(release, dtype=float), depth + 1)
            if why != "target":
                return lam, why
        peak_lam = max(peak_lam, abs(lam))
        if stop_below is not None and abs(lam) < stop_below * peak_lam:
            return lam, "strength"
    raise RuntimeError(f"{frame.name}: more than {MAX_EVENTS} events")  # pragma: no cover


def gravity(frame: Frame) -> FrameState:
    """The frame under its gravity loads, applied first (event to event under load control),
    with the columns' axial forces from a first elastic gravity analysis held for the
    geometric stiffness (:mod:`pounding.structure.frame_stiffness`).

    Raises
    ------
    ValueError
        When the frame cannot carry its gravity loads (a mechanism forms first).
    """
    state = _start(frame)
    dofs = state.dofs
    G = gravity_load_vector(frame, dofs)
    nh = len(frame.hinges)
    K0 = configuration_stiffness(state.base, dofs, np.array([h.law.k0 for h in frame.hinges]))
    import scipy.linalg

    try:
        U_lin = scipy.linalg.solve(K0, G, assume_a="sym") if np.any(G) else np.zeros(dofs.n)
    except (np.linalg.LinAlgError, ValueError) as exc:
        raise ValueError(f"{frame.name}: the frame is unstable (its elastic stiffness matrix "
                         f"is singular: {exc}); check supports and connections") from None
    axial = -element_end_forces(frame, dofs, U_lin)[:, 0]
    state.axial = axial
    state.base = state.base + geometric_stiffness(frame, dofs, axial)
    if frame.geometry != "linear" or np.any(frame.leaning_loads):
        try:
            np.linalg.cholesky(configuration_stiffness(
                state.base, dofs, np.array([h.law.k0 for h in frame.hinges])))
        except np.linalg.LinAlgError:
            raise ValueError(f"{frame.name}: buckles under its gravity loads: with P-Delta "
                             f"(geometry {frame.geometry!r}, leaning column) its stiffness is "
                             "no longer positive definite") from None
    if np.any(G):
        lam, why = _advance(state, G, None, 0.0, 1.0, None)
        if why != "target":
            raise ValueError(f"{frame.name}: the frame cannot carry its gravity loads: a "
                             f"mechanism forms at {lam:.3g} of them")
    state.gravity_factor = 1.0
    state.directions = np.zeros(nh, dtype=np.int64)
    return state


def _mass_vector(frame: Frame, dofs: FrameDofs) -> NDArray[np.float64]:
    """The frame's lumped masses on its DOFs [kg, kg·m²] (its nodes' and its members' own,
    lumped at their ends)."""
    if frame.mass_matrix != "lumped":
        raise ValueError(f"{frame.name}: mass_matrix: a time history takes lumped masses (got "
                         f"{frame.mass_matrix!r}; the consistent one serves the modes)")
    return np.diag(frame_mass_matrix(frame, dofs)).copy()


def frame_modes(frame: Frame, state: FrameState | None = None
                ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64],
                           NDArray[np.float64], NDArray[np.float64]]:
    """Elastic modes of the frame under its gravity loads (hinges at their elastic stiffness,
    massless DOFs condensed out): ``(periods [s], shapes (n_mass, n_modes), mass DOFs,
    the condensed K, their mass matrix)`` — the mass matrix lumped (diagonal) or consistent
    as the frame says (:mod:`pounding.structure.frame_mass`)."""
    state = state or gravity(frame)
    dofs = state.dofs
    M = frame_mass_matrix(frame, dofs)
    keep = np.flatnonzero(np.any(M != 0.0, axis=1))
    if keep.size == 0:
        raise ValueError(f"{frame.name}: no masses: give floor masses to find its modes")
    K = configuration_stiffness(state.base, dofs, np.array([h.law.k0 for h in frame.hinges]))
    Kc = condense(K, keep)
    Mk = M[np.ix_(keep, keep)]
    import scipy.linalg

    w2, phi = scipy.linalg.eigh(Kc, Mk)
    if w2[0] <= 0.0:
        raise ValueError(f"{frame.name}: unstable under its gravity loads (the lateral "
                         f"stiffness with P-Delta is not positive: ω² = {w2[0]:.3g})")
    return 2.0 * np.pi / np.sqrt(w2), phi, keep, Kc, Mk


def lateral_pattern(frame: Frame, pattern: str, state: FrameState | None = None
                    ) -> NDArray[np.float64]:
    """Lateral load per floor (normalised to sum 1) of a pushover ``pattern``: ``"uniform"``
    (proportional to floor mass, or equal without masses), ``"triangular"`` (mass × height)
    or ``"first-mode"`` (mass × first-mode shape; ASCE 41-17 §7.4.3.2.3)."""
    if pattern not in PATTERNS:
        raise ValueError(f"pattern: must be one of {', '.join(PATTERNS)} (got {pattern!r})")
    mass = frame.floor_masses
    nf = frame.levels.size
    if not np.any(mass > 0):
        if pattern == "first-mode":
            raise ValueError(f"pattern: first-mode needs floor masses; {frame.name} has none "
                             "(use uniform or triangular, or give masses)")
        mass = np.ones(nf)
    if pattern == "uniform":
        p = mass.copy()
    elif pattern == "triangular":
        p = mass * (frame.levels - frame.base)
    else:
        _, phi, keep, _, _ = frame_modes(frame, state)
        dofs = (state or _start(frame)).dofs
        full = np.zeros(dofs.n)
        full[keep] = phi[:, 0]
        shape = dofs.floor @ full
        shape = shape / shape[np.argmax(np.abs(shape))]
        p = mass * shape
    return p / np.sum(p)


@dataclass(frozen=True)
class PushoverResult:
    """A pushover curve, exact between its points (events).

    Attributes
    ----------
    roof_displacement : ndarray (n,)
        Roof (top floor) displacement [m].
    base_shear : ndarray (n,)
        Base shear [N]: the sum of the lateral loads (= of the horizontal base reactions).
    floor_displacements : ndarray (n, n_floors)
        Floor displacements [m].
    storey_drifts : ndarray (n, n_floors)
        Storey drifts [m].
    storey_shears : ndarray (n, n_floors)
        Storey shears [N]: the lateral loads above each storey.
    hinge_rotations, hinge_moments : ndarray (n, n_hinges)
        Hinge rotations [rad] and moments [N·m].
    pattern : str
        Load pattern.
    load_shape : ndarray (n_floors,)
        Lateral load per floor per newton of base shear.
    stopped : str
        Why the analysis ended: ``"target"``, ``"strength"`` (base shear fell below the
        requested fraction of its peak), ``"mechanism"`` or ``"snap-back"``.
    """

    roof_displacement: NDArray[np.float64]
    base_shear: NDArray[np.float64]
    floor_displacements: NDArray[np.float64]
    storey_drifts: NDArray[np.float64]
    storey_shears: NDArray[np.float64]
    hinge_rotations: NDArray[np.float64]
    hinge_moments: NDArray[np.float64]
    pattern: str
    load_shape: NDArray[np.float64]
    stopped: str

    @property
    def peak_base_shear(self) -> float:
        """Largest base shear [N]."""
        return float(np.max(self.base_shear))


def pushover(frame: Frame, target: float, *, pattern: str = "uniform",
             stop_below: float | None = None) -> PushoverResult:
    """Static pushover: gravity first, then lateral loads in ``pattern`` growing under
    control of the roof displacement up to ``target`` [m] (event to event: exact, no
    iterations; see the module docstring).

    Parameters
    ----------
    frame : Frame
        The frame.
    target : float
        Roof displacement to reach [m] (> 0).
    pattern : str
        ``"uniform"``, ``"triangular"`` or ``"first-mode"`` (:func:`lateral_pattern`).
    stop_below : float, optional
        Stop once the base shear falls below this fraction of its peak (the deteriorating
        branch), e.g. 0.2.

    Examples
    --------
    The portal frame of ``examples/portal_pushover.toml``: its sway mechanism carries
    ``4 M_p / h = 300 kN``.

    >>> from pounding.hysteresis.hinges import ElasticPlastic
    >>> from pounding.structure.frame import regular_frame
    >>> f = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
    ...                   column_hinge=ElasticPlastic(k0=1e11, m_y=3e5),
    ...                   beam_hinge=ElasticPlastic(k0=1e11, m_y=6e5))
    >>> round(pushover(f, 0.2).peak_base_shear)
    300000
    """
    t = float(target)
    if not (math.isfinite(t) and t > 0.0):
        raise ValueError(f"target: the roof displacement must be finite and > 0 [m] "
                         f"(got {target!r})")
    if stop_below is not None and not (0.0 <= float(stop_below) < 1.0):
        raise ValueError(f"stop_below: must be in [0, 1) (got {stop_below!r})")
    if frame.levels.size == 0:
        raise ValueError(f"{frame.name}: no floor above the base to push")
    state = gravity(frame)
    shape = lateral_pattern(frame, pattern, state)
    dofs = state.dofs
    P = dofs.floor.T @ shape
    roof = dofs.floor[-1]
    path = _Path()
    path.lam.append(0.0)
    path.U.append(state.U.copy())
    path.moments.append(state.hinge_moments())
    path.rotations.append(state.hinge_rotations())
    u0 = float(roof @ state.U)
    _, why = _advance(state, P, roof, 0.0, u0 + t, path, stop_below)
    lam = np.array(path.lam)
    U = np.array(path.U)
    floors = U @ dofs.floor.T
    drifts = np.diff(np.concatenate([np.zeros((floors.shape[0], 1)), floors], axis=1), axis=1)
    above = np.cumsum(shape[::-1])[::-1]
    return PushoverResult(
        roof_displacement=floors[:, -1], base_shear=lam, floor_displacements=floors,
        storey_drifts=drifts, storey_shears=np.outer(lam, above),
        hinge_rotations=np.array(path.rotations), hinge_moments=np.array(path.moments),
        pattern=pattern, load_shape=shape, stopped=why)
