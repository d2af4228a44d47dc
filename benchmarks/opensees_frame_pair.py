"""The time history of a pair of pounding frames in OpenSeesPy, for ``bench_frames.py``.

Two :class:`~pounding.structure.frame.Frame` objects built by
:func:`opensees_frame_models.add_frame` in one OpenSees domain (the right frame's tags
offset by :data:`RIGHT_OFFSET`, its nodes moved right of the left one), so that both are
the concentrated-plasticity model of ``opensees_frame_models.py`` (elasticBeamColumn
members, zeroLength hinges with ``Steel01`` / ``IMKBilin`` / ``ElasticPP``, equalDOF rigid
floors, a pin-ended ``PDelta`` leaning column). Not part of the package.

The analysis is the one the pounding kernel solves, term for term:

* **gravity first**: both frames' gravity loads in load pattern 1, 10 static load steps,
  held (``loadConst``), time reset to 0;
* **damping** as pounding applies it to a frame (:class:`pounding.structure.frame_linear.
  FrameBuilding`): ``C = a₀ M + a₁ K`` on the floors' lateral motion, constant, with ``K``
  the frame's elastic lateral stiffness condensed onto its floors (hinges at their elastic
  stiffness, P-Delta of gravity included) — Rayleigh damping on the elastic stiffness, not
  the hinges' tangent (Zareian & Medina 2010). ``a₀, a₁`` come from the frame's damping
  anchors (:class:`~pounding.structure.damping.RayleighDamping` modes ``i``, ``j``), their
  periods from OpenSees' own eigen analysis after gravity (:func:`floor_damping`). OpenSees
  has no damping matrix on a condensed set of DOFs, so ``C`` is built from dashpots: one
  node a floor at one point (tied to the floor by ``equalDOF … 1``), and between every two
  of them a ``zeroLength`` with ``uniaxialMaterial Elastic 0 η``, ``η = −C_ij``, and from
  each to a fixed node ``η = Σ_j C_ij`` (the row sum). ``Elastic``'s stress is ``E ε + η ε̇``
  and its damping tangent ``η``, so their forces are exactly ``C u̇``; the hinges, members and
  contacts take no Rayleigh damping (no ``rayleigh`` command);
* **contact**: at every floor the frames share (equal elevations), a ``zeroLength`` in x
  between two nodes at one point, tied to the left and the right floor, with
  ``uniaxialMaterial ViscoelasticGap K C −gap``: force ``K (ε + gap) + C ε̇`` while
  ``ε = u_right − u_left < −gap``, pounding's Kelvin–Voigt law with ``tension=True`` (the
  dashpot may pull until the gap reopens; ``opensees_models.py``);
* **excitation**: ``UniformExcitation`` in x of a ``Path`` series (linear between the
  record's samples, as pounding interpolates it), relative displacements;
* **integration**: Newmark average acceleration (γ = ½, β = ¼), ``NormDispIncr`` test,
  ``Newton``; a step that fails is tried again as practitioners do (:data:`FALLBACKS`):
  other algorithms, then the step cut into 10, then 100 sub-steps with the same list; a
  step that no strategy completes ends the run (recorded in :attr:`PairHistory.failures`,
  with the time). Every step rescued by a fallback is recorded too (:attr:`PairHistory.
  rescued`).

Outputs (:class:`PairHistory`), at every analysis step: floor displacements of both frames,
contact forces (the elements' ``basicForce``, positive in compression); impacts counted as
pounding counts them, one each time a contact closes (open → closed between two steps:
OpenSees sees only its steps, so a contact that closes and reopens inside one is missed);
every hinge's largest |rotation| (its ``zeroLength`` deformation, gravity's included) from an
``EnvelopeElement`` recorder, and on request (``hinge_history``) the rotations at every
step (slow: one Python call a hinge a step).
"""

from __future__ import annotations

import os
import tempfile
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import opensees_frame_models as osf
from numpy.typing import NDArray

from pounding.structure.damping import RayleighDamping
from pounding.structure.frame import Frame

RIGHT_OFFSET = 100_000
"""Added to every OpenSees tag of the right frame (its own tags stay below 20,000)."""
CONTACT_OFFSET = 200_000
"""Tags of the contact nodes, materials and elements (``CONTACT_OFFSET + …``)."""
DASHPOT_TAG = 50_000
"""Tags of a frame's damping nodes, materials and elements (``offset + DASHPOT_TAG + …``)."""
GAP_BETWEEN_DRAWINGS = 10.0
"""m between the left frame's leaning column and the right frame's first column line in the
OpenSees drawing (the frames interact only through the contact elements: any distance
would do)."""

FALLBACKS: tuple[tuple[str, ...], ...] = (
    ("Newton",),
    ("KrylovNewton",),
    ("NewtonLineSearch", 0.8),
    ("ModifiedNewton", "-initial"),
)
"""Algorithms tried, in order, on a step that has not converged."""
SPLIT = 10
"""A step that no algorithm completes is cut into this many sub-steps, …"""
MAX_SPLITS = 2
"""… at most this many times over (down to ``dt/100``)."""


@dataclass
class PairHistory:
    """An OpenSees time history of a frame pair (SI units; relative displacements)."""

    dt: float  #: analysis (= output) step [s]
    time: NDArray[np.float64]  #: (nt,) [s], up to the last converged step
    left: NDArray[np.float64]  #: (nt, n_floors_left) floor displacements [m]
    right: NDArray[np.float64]  #: (nt, n_floors_right) floor displacements [m]
    contact_force: NDArray[np.float64]  #: (nt, n_contacts) [N], compression positive
    impacts: NDArray[np.int64]  #: (n_contacts,) closures seen at the steps
    hinge_peak: NDArray[np.float64]  #: (n_hinges,) largest |rotation| [rad], left then right
    hinge_rotation: NDArray[np.float64] | None  #: (nt, n_hinges) [rad], or None
    complete: bool  #: every step converged
    failures: list[str] = field(default_factory=list)  #: the step no strategy completed
    rescued: list[tuple[float, str]] = field(default_factory=list)  #: (time, what worked)
    wall: float = 0.0  #: gravity + transient analysis [s] (building excluded)
    steps: int = 0  #: steps asked for

    @property
    def n_impacts(self) -> int:
        """Impacts of all contacts."""
        return int(self.impacts.sum())

    @property
    def peak_contact_force(self) -> NDArray[np.float64]:
        """(n_contacts,) largest contact force [N] at the steps."""
        if self.contact_force.shape[0] == 0:
            return np.zeros(self.contact_force.shape[1])
        return np.max(self.contact_force, axis=0)

    def peak_drift(self, side: str) -> NDArray[np.float64]:
        """Largest |storey drift| [m] of each storey of the ``"left"`` or ``"right"`` frame
        (at the steps)."""
        u = self.left if side == "left" else self.right
        drift = np.diff(np.hstack([np.zeros((u.shape[0], 1)), u]), axis=1)
        return np.max(np.abs(drift), axis=0)


# ----------------------------------------------------------------------------- damping
def rayleigh_coefficients(w_i: float, w_j: float, zeta_i: float,
                          zeta_j: float) -> tuple[float, float]:
    """``(a₀, a₁)`` of ``C = a₀ M + a₁ K`` giving ``ζ_i`` at ``ω_i`` and ``ζ_j`` at ``ω_j``
    (Chopra, *Dynamics of Structures*, eq. 11.4.9)."""
    a0 = 2.0 * w_i * w_j * (zeta_i * w_j - zeta_j * w_i) / (w_j**2 - w_i**2)
    a1 = 2.0 * (zeta_j * w_j - zeta_i * w_i) / (w_j**2 - w_i**2)
    return a0, a1


def opensees_periods(ops: Any, frame: Frame, n: int) -> NDArray[np.float64]:
    """The first ``n`` periods [s] of ``frame`` alone in OpenSees, after its gravity
    analysis (with its P-Delta); the domain is wiped after."""
    osf.build(ops, frame)
    osf.gravity(ops)
    ops.wipeAnalysis()
    ops.constraints(osf.CONSTRAINTS)
    ops.numberer("Plain")
    ops.system("FullGeneral")
    lam = np.array(ops.eigen("-fullGenLapack", n))
    ops.wipe()
    return 2.0 * np.pi / np.sqrt(lam)


def floor_damping(ops: Any, frame: Frame, masses: NDArray[np.float64],
                  stiffness: NDArray[np.float64]) -> tuple[NDArray[np.float64], float, float]:
    """The frame's damping matrix on its floors as pounding forms it (module docstring):
    ``C = a₀ M + a₁ K`` with ``M = diag(masses)`` [kg], ``K`` = ``stiffness`` [N/m] (the
    frame's condensed elastic lateral stiffness under gravity), ``a₀, a₁`` from the periods of
    the frame's anchor modes computed by OpenSees (:func:`opensees_periods`). Returns
    ``(C, a₀, a₁)``."""
    d = frame.damping
    if not isinstance(d, RayleighDamping) or d.period_i is not None:
        raise ValueError(f"{frame.name}: only Rayleigh damping at two modes is built here "
                         f"(got {d!r})")
    periods = opensees_periods(ops, frame, max(d.mode_i, d.mode_j))
    w = 2.0 * np.pi / periods
    a0, a1 = rayleigh_coefficients(float(w[d.mode_i - 1]), float(w[d.mode_j - 1]), d.zeta_i,
                                   d.zeta_j)
    return a0 * np.diag(masses) + a1 * np.asarray(stiffness, dtype=float), a0, a1


def add_floor_dashpots(ops: Any, built: osf.OpenSeesFrame, C: NDArray[np.float64],
                       where: tuple[float, float]) -> None:
    """``C`` [N·s/m] on the floors of ``built`` as a network of dashpots (module
    docstring), its nodes at ``where`` (x, y) [m]."""
    o = built.offset + DASHPOT_TAG
    n = C.shape[0]
    x, y = where
    ops.node(o, x, y)
    ops.fix(o, 1, 1, 1)
    for f in range(n):
        ops.node(o + 1 + f, x, y)
        ops.fix(o + 1 + f, 0, 1, 1)
        ops.equalDOF(built.floor[f], o + 1 + f, 1)
    k = 0
    for i in range(n):
        for j in range(i, n):
            eta = float(np.sum(C[i])) if i == j else -float(C[i, j])
            if eta == 0.0:
                continue
            k += 1
            ops.uniaxialMaterial("Elastic", o + k, 0.0, eta)
            ops.element("zeroLength", o + k, o if i == j else o + 1 + i, o + 1 + j, "-mat",
                        o + k, "-dir", 1)


# ----------------------------------------------------------------------------- the pair
@dataclass(frozen=True)
class PairModel:
    """The tags of a pair built by :func:`build_pair`."""

    left: osf.OpenSeesFrame
    right: osf.OpenSeesFrame
    contacts: tuple[int, ...]  #: contact element tags (shared floors, lowest first)
    contact_floors: tuple[tuple[int, int], ...]  #: (left floor, right floor) of each


def build_pair(ops: Any, left: Frame, right: Frame, damping: tuple[NDArray[np.float64],
                                                                    NDArray[np.float64]],
               contacts: list[tuple[int, int, float, float]], gap: float) -> PairModel:
    """Both frames in a wiped domain with their gravity loads (pattern 1), floor dashpots
    ``damping`` (each frame's ``C`` on its floors) and a ``ViscoelasticGap`` contact for each
    ``(left floor, right floor, K [N/m], C [N·s/m])`` of ``contacts`` at ``gap`` [m]."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    a = osf.add_frame(ops, left)
    dx = (float(np.max(left.nodes[:, 0])) + osf.LEAN_X_OFFSET + GAP_BETWEEN_DRAWINGS
          - float(np.min(right.nodes[:, 0])))
    b = osf.add_frame(ops, right, offset=RIGHT_OFFSET, dx=dx)
    add_floor_dashpots(ops, a, damping[0], (-20.0, -10.0))
    add_floor_dashpots(ops, b, damping[1], (dx + float(np.max(right.nodes[:, 0])) + 20.0,
                                            -10.0))
    xc = float(np.max(left.nodes[:, 0])) + osf.LEAN_X_OFFSET + GAP_BETWEEN_DRAWINGS / 2
    tags = []
    for c, (i, j, k, cc) in enumerate(contacts):
        y = float(left.levels[i])
        nl, nr = CONTACT_OFFSET + 1 + 2 * c, CONTACT_OFFSET + 2 + 2 * c
        for node, floor in ((nl, a.floor[i]), (nr, b.floor[j])):
            ops.node(node, xc, y)
            ops.fix(node, 0, 1, 1)
            ops.equalDOF(floor, node, 1)
        tag = CONTACT_OFFSET + 1 + c
        ops.uniaxialMaterial("ViscoelasticGap", tag, float(k), float(cc), -abs(float(gap)))
        ops.element("zeroLength", tag, nl, nr, "-mat", tag, "-dir", 1)
        tags.append(tag)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    osf.add_gravity_loads(ops, left, a)
    osf.add_gravity_loads(ops, right, b)
    return PairModel(a, b, tuple(tags), tuple((i, j) for i, j, _, _ in contacts))


def _set_transient(ops: Any, tol: float, iterations: int, system: str) -> None:
    ops.wipeAnalysis()
    ops.constraints(osf.CONSTRAINTS)
    ops.numberer("RCM")
    ops.system(system)
    ops.test("NormDispIncr", tol, iterations)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")


def _step(ops: Any, dt: float, tol: float, iterations: int, depth: int = 0) -> str | None:
    """One step of ``dt`` (module docstring): each of :data:`FALLBACKS` in turn, then (up to
    :data:`MAX_SPLITS` times deep) the step cut into :data:`SPLIT` sub-steps, each done the
    same way. Returns ``""`` if plain Newton did it, else what it took, or None if nothing
    did (the domain is then at the last sub-step that converged)."""
    used = ""
    for k, algorithm in enumerate(FALLBACKS):
        if k:
            ops.algorithm(*algorithm)
            ops.test("NormDispIncr", tol, 4 * iterations)
        ok = ops.analyze(1, dt) == 0
        if k:
            ops.algorithm("Newton")
            ops.test("NormDispIncr", tol, iterations)
        if ok:
            return " ".join(map(str, algorithm)) if k else used
    if depth >= MAX_SPLITS:
        return None
    hows = []
    for _ in range(SPLIT):
        how = _step(ops, dt / SPLIT, tol, iterations, depth + 1)
        if how is None:
            return None
        hows.append(how.split(" in ")[0] if how else "Newton")
    algorithms = sorted({h.split(" in ")[0] for h in hows})
    return f"{' / '.join(algorithms)} in {SPLIT ** (depth + 1)} sub-steps"


def run_pair(ops: Any, model: PairModel, accel: NDArray[np.float64], record_dt: float,
             dt: float, duration: float, *, tol: float = 1e-8, iterations: int = 50,
             system: str = "SparseGEN", hinge_history: bool = False,
             log: str | None = None) -> PairHistory:
    """Gravity, then the ground acceleration ``accel`` [m/s²] (sampled at ``record_dt``
    [s]) for ``duration`` [s] in steps of ``dt`` [s], on the pair built by
    :func:`build_pair` (module docstring). ``tol`` [m] and ``iterations`` are Newton's
    test; ``system`` the OpenSees solver. Warnings go to ``log`` (default a file in the
    temporary folder)."""
    log = log or os.path.join(tempfile.gettempdir(), f"opensees_frame_pair_{os.getpid()}.log")
    ops.logFile(log, "-noEcho")
    hinges = model.left.hinge + model.right.hinge
    floors_l, floors_r = model.left.floor, model.right.floor
    n = round(duration / dt)
    ul = np.zeros((n + 1, len(floors_l)))
    ur = np.zeros((n + 1, len(floors_r)))
    force = np.zeros((n + 1, len(model.contacts)))
    rot = np.zeros((n + 1, len(hinges))) if hinge_history else None
    envelope = os.path.join(tempfile.gettempdir(), f"opensees_frame_pair_{os.getpid()}.env")
    if os.path.exists(envelope):
        os.remove(envelope)
    node_disp, ele_response = ops.nodeDisp, ops.eleResponse
    t0 = time.perf_counter()
    osf.gravity(ops, system=system)
    ops.timeSeries("Path", 2, "-dt", float(record_dt), "-values", *map(float, accel))
    ops.pattern("UniformExcitation", 2, 1, "-accel", 2)
    _set_transient(ops, tol, iterations, system)
    ops.recorder("EnvelopeElement", "-file", envelope, "-ele", *hinges, "deformation")
    at_rest = np.array([ele_response(h, "deformation")[0] for h in hinges])
    if rot is not None:
        rot[0] = at_rest
    for j, nd in enumerate(floors_l):
        ul[0, j] = node_disp(nd, 1)
    for j, nd in enumerate(floors_r):
        ur[0, j] = node_disp(nd, 1)
    failures: list[str] = []
    rescued: list[tuple[float, str]] = []
    done = n
    for s in range(1, n + 1):
        how = _step(ops, dt, tol, iterations)
        if how is None:
            failures.append(f"t = {(s - 1) * dt:.4f} s: no strategy completed the step to "
                            f"{s * dt:.4f} s")
            done = s - 1
            break
        if how:
            rescued.append((s * dt, how))
        for j, nd in enumerate(floors_l):
            ul[s, j] = node_disp(nd, 1)
        for j, nd in enumerate(floors_r):
            ur[s, j] = node_disp(nd, 1)
        for j, el in enumerate(model.contacts):
            force[s, j] = 0.0 - ele_response(el, "basicForce")[0]
        if rot is not None:
            rot[s] = [ele_response(h, "deformation")[0] for h in hinges]
    ops.remove("recorders")  # (the envelope is written when its recorder goes)
    wall = time.perf_counter() - t0
    with open(envelope) as fh:
        rows = [np.array(line.split(), dtype=float) for line in fh if line.strip()]
    os.remove(envelope)
    hinge_peak = rows[2] if len(rows) >= 3 else np.full(len(hinges), np.nan)
    # the envelope holds the transient steps only: the gravity state's rotation counts too
    hinge_peak = np.maximum(hinge_peak, np.abs(at_rest))
    keep = done + 1
    ul, ur, force = ul[:keep], ur[:keep], force[:keep]
    return PairHistory(dt, np.arange(keep) * dt, ul, ur, force,
                       _closures(force), hinge_peak,
                       None if rot is None else rot[:keep], not failures, failures, rescued,
                       wall, n)


def _closures(force: NDArray[np.float64]) -> NDArray[np.int64]:
    """Per contact, how many times its force turns on (zero → nonzero) between steps."""
    on = force != 0.0
    if on.shape[0] == 0:
        return np.zeros(on.shape[1], dtype=np.int64)
    return (np.sum(on[1:] & ~on[:-1], axis=0) + on[0]).astype(np.int64)
