"""A pounding pair with a building on a flexible base (soil–structure interaction) in
OpenSeesPy, for ``bench_ssi.py``. Not part of the package.

The model is built from its physical parts, not from pounding's matrices, so that its
matrices are an independent check of :func:`pounding.structure.foundation.flexible_base`
(``bench_ssi.py`` assembles them with OpenSees' ``GimmeMCK`` integrator and compares):

* **2-D, three DOFs a node** (``-ndm 2 -ndf 3``: x, y, rotation θ counter-clockwise). Every
  node's y is fixed (a shear building has no vertical motion); every node lies on the
  vertical line x = 0.
* **The footing** of a building on a flexible base: a node at the ground surface, free in x
  and θ, with mass ``m_f`` (x) and rotational mass ``I_f`` (θ). Two ``zeroLength`` elements
  join it to a fixed ground node, each in directions 1 (x) and 3 (θ): the soil's springs
  (``uniaxialMaterial Elastic k_x`` and ``Elastic k_r``) and its dashpots
  (``uniaxialMaterial Viscous c_x 1`` and ``Viscous c_r 1``: stress ``c ε̇``, damping
  tangent ``c``). On a fixed base the footing node is fixed.
* **The storeys**: an ``elasticBeamColumn`` from each floor node to the one below (the
  footing node for storey 1) with ``12 E I / h³ = k`` (E = 1, I = k h³/12), and every floor
  node's rotation tied to the footing's by ``equalDOF footing floor 3`` (on a fixed base the
  rotations are fixed). With both end rotations equal to the footing's θ, a beam's shear is
  ``k (Δx + h θ)`` and its strain energy ``½ k (Δx + h θ)²`` — the storey drift less the
  footing's rigid rotation, ``u = x − u_f − z φ`` with ``φ = −θ`` — and its end moments go to
  the footing: the rocking coupling of the floors is the beams' own, with nothing assembled
  by hand. (Axial: all y fixed, so ``A`` plays no part.)
* **The building's damping** ``C = a₀ M + a₁ K`` acting on its deformation, as pounding
  applies it (its fixed-base Rayleigh damping on ``u``): ``a₁ K`` as element Rayleigh
  damping of the beams (``region … -ele beams -rayleigh 0 a₁ 0 0``: ``a₁`` times each beam's
  stiffness, so on the same deformation); ``a₀ M`` by a ``zeroLength`` dashpot
  (``Elastic 0 a₀m_j``) from each floor node to a node that follows the footing rigidly
  (``rigidLink beam footing node`` at the floor's elevation: it moves ``u_f + z φ``), i.e.
  on the floor's motion relative to its base's rigid motion. On a fixed base those nodes
  are fixed.
* **Masses**: the floors' masses in x only (no rotary inertia of the floors, as pounding);
  ``UniformExcitation`` in x then loads every mass in x (floors and footing, ``r = 1``) and
  not the rocking (``r = 0``).
* **Contact**: a ``zeroLength`` from a left floor node to the right one at the same
  elevation (the nodes coincide), ``uniaxialMaterial ViscoelasticGap K C −gap`` (pounding's
  Kelvin–Voigt law with ``tension=True``; ``opensees_models.py``).

Analysis as ``opensees_models.py``: ``Transformation`` constraints (the ``equalDOF`` and
``rigidLink`` ties), ``RCM`` numbering, a ``Path`` series of the record, Newmark average
acceleration, Newton with ``NormDispIncr`` and the usual fallbacks
(:func:`opensees_models._retry`), one ``analyze(1, dt)`` a step with every DOF and contact
force read after it. Displacements are relative to the free-field ground (pounding's DOFs);
the rocking is returned as ``φ = −θ``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import opensees_models as osm
from numpy.typing import NDArray

E_BEAM = 1.0
"""Young's modulus of the storey beams (their I is set from it: only E·I matters)."""
TRANSFORMATION = 1
"""The beams' geometric transformation tag (``Linear``)."""


@dataclass(frozen=True)
class Soil:
    """A footing and its soil: the footing's mass [kg] and rotational inertia [kg·m²], the
    sway and rocking springs [N/m, N·m/rad] and dashpots [N·s/m, N·m·s/rad]."""

    mass: float
    inertia: float
    k_x: float
    k_r: float
    c_x: float
    c_r: float


@dataclass(frozen=True)
class Building:
    """A shear building: floor masses [kg], storey stiffnesses [N/m] and storey heights [m]
    from the ground up, Rayleigh ``a₀`` [1/s] and ``a₁`` [s] of its fixed-base damping, and
    its soil (None: a fixed base)."""

    masses: Sequence[float]
    stiffnesses: Sequence[float]
    heights: Sequence[float]
    a0: float
    a1: float
    soil: Soil | None = None

    @property
    def n(self) -> int:
        return len(self.masses)

    @property
    def dofs(self) -> int:
        """pounding's DOFs of the building: its floors, then sway and rocking on soil."""
        return self.n + (2 if self.soil is not None else 0)


@dataclass
class Built:
    """The tags of one building in the domain."""

    floors: list[int]
    footing: int | None
    beams: list[int] = field(default_factory=list)


@dataclass
class PairTags:
    """The tags of a pair built by :func:`build_pair`."""

    left: Built
    right: Built
    contacts: list[int]

    def dof_reads(self) -> list[tuple[int, int, float]]:
        """(node, OpenSees DOF, sign) of each of pounding's DOFs, in pounding's order: the
        left building's floors, its sway and rocking (``φ = −θ``) if on soil, the right
        building's floors (and footing)."""
        out: list[tuple[int, int, float]] = []
        for b in (self.left, self.right):
            out += [(nd, 1, 1.0) for nd in b.floors]
            if b.footing is not None:
                out += [(b.footing, 1, 1.0), (b.footing, 3, -1.0)]
        return out


def _add_building(ops: Any, spec: Building, offset: int) -> Built:
    """One building, its tags from ``offset`` (module docstring)."""
    ground, footing = offset + 1, offset + 2
    ops.node(ground, 0.0, 0.0)
    ops.fix(ground, 1, 1, 1)
    ops.node(footing, 0.0, 0.0)
    soil = spec.soil
    if soil is None:
        ops.fix(footing, 1, 1, 1)
    else:
        ops.fix(footing, 0, 1, 0)
        ops.mass(footing, float(soil.mass), 0.0, float(soil.inertia))
        m = offset + 1
        ops.uniaxialMaterial("Elastic", m, float(soil.k_x))
        ops.uniaxialMaterial("Elastic", m + 1, float(soil.k_r))
        ops.uniaxialMaterial("Viscous", m + 2, float(soil.c_x), 1.0)
        ops.uniaxialMaterial("Viscous", m + 3, float(soil.c_r), 1.0)
        ops.element("zeroLength", offset + 1, ground, footing, "-mat", m, m + 1,
                    "-dir", 1, 3)
        ops.element("zeroLength", offset + 2, ground, footing, "-mat", m + 2, m + 3,
                    "-dir", 1, 3)
    built = Built([], footing if soil is not None else None)
    below, z = footing, 0.0
    for j in range(spec.n):
        h = float(spec.heights[j])
        z += h
        node = offset + 10 + j
        ops.node(node, 0.0, z)
        ops.mass(node, float(spec.masses[j]), 0.0, 0.0)
        if soil is None:
            ops.fix(node, 0, 1, 1)
        else:
            ops.fix(node, 0, 1, 0)
            ops.equalDOF(footing, node, 3)
        beam = offset + 10 + j
        ops.element("elasticBeamColumn", beam, below, node, 1.0, E_BEAM,
                    float(spec.stiffnesses[j]) * h ** 3 / (12.0 * E_BEAM), TRANSFORMATION)
        built.beams.append(beam)
        # a0 M on the floor's motion relative to the base's rigid motion
        follower = offset + 100 + j
        ops.node(follower, 0.0, z)
        if soil is None:
            ops.fix(follower, 1, 1, 1)
        else:
            ops.rigidLink("beam", footing, follower)
        if spec.a0 > 0.0:
            ops.uniaxialMaterial("Elastic", offset + 100 + j, 0.0,
                                 float(spec.a0) * float(spec.masses[j]))
            ops.element("zeroLength", offset + 100 + j, follower, node, "-mat",
                        offset + 100 + j, "-dir", 1)
        built.floors.append(node)
        below = node
    if spec.a1 > 0.0:
        ops.region(offset // 1000, "-ele", *built.beams, "-rayleigh", 0.0, float(spec.a1),
                   0.0, 0.0)
    return built


def build_pair(ops: Any, left: Building, right: Building,
               contacts: Sequence[tuple[int, int, float, float]], gap: float,
               log: str = osm._LOG) -> PairTags:
    """Both buildings in a wiped domain (module docstring), with a ``ViscoelasticGap``
    contact for each ``(left floor, right floor, K [N/m], C [N·s/m])`` at ``gap`` [m]."""
    ops.wipe()
    ops.logFile(log, "-noEcho")
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.geomTransf("Linear", TRANSFORMATION)
    a = _add_building(ops, left, 1000)
    b = _add_building(ops, right, 2000)
    tags = []
    for c, (i, j, k, cc) in enumerate(contacts):
        tag = 5000 + c
        ops.uniaxialMaterial("ViscoelasticGap", tag, float(k), float(cc), -abs(float(gap)))
        ops.element("zeroLength", tag, a.floors[i], b.floors[j], "-mat", tag, "-dir", 1)
        tags.append(tag)
    return PairTags(a, b, tags)


def _equations(ops: Any, tags: PairTags) -> list[int]:
    """The equation number of each of pounding's DOFs (:meth:`PairTags.dof_reads`)."""
    return [ops.nodeDOFs(nd)[d - 1] for nd, d, _ in tags.dof_reads()]


def matrices(ops: Any, tags: PairTags) -> tuple[NDArray[np.float64], ...]:
    """``(M, C, K)`` as OpenSees assembles them (``integrator GimmeMCK``, ``printA``), on
    pounding's DOFs in pounding's order and signs (contacts open: they add nothing)."""
    signs = np.array([s for _, _, s in tags.dof_reads()])
    out = []
    for coefficients in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
        ops.wipeAnalysis()
        ops.constraints("Transformation")
        ops.numberer("Plain")
        ops.system("FullGeneral")
        ops.algorithm("Linear")
        ops.integrator("GimmeMCK", *coefficients)
        ops.analysis("Transient")
        ops.analyze(1, 0.0)
        eqs = _equations(ops, tags)  # (numbered once an analysis exists)
        a = np.array(ops.printA("-ret"))
        n = math.isqrt(a.size)
        out.append(signs[:, None] * a.reshape(n, n)[np.ix_(eqs, eqs)] * signs[None, :])
    ops.wipeAnalysis()
    return tuple(out)


def periods(ops: Any, n: int) -> NDArray[np.float64]:
    """The first ``n`` periods [s] by OpenSees' eigen analysis (full LAPACK)."""
    ops.wipeAnalysis()
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    lam = np.array(ops.eigen("-fullGenLapack", n))
    ops.wipeAnalysis()
    return 2.0 * np.pi / np.sqrt(lam)


@dataclass
class History:
    """An OpenSees time history of the pair (SI units, relative to the free field)."""

    dt: float  #: analysis (= output) step [s]
    time: NDArray[np.float64]  #: (nt,) [s]
    u: NDArray[np.float64]  #: (nt, N) pounding's DOFs [m, rad] (rocking φ = −θ)
    force: NDArray[np.float64]  #: (nt, n_contacts) [N], compression positive
    wall: float  #: build + analysis with its reads [s]
    wall_analyze: float  #: the analysis loop with its reads [s]
    retried: int  #: steps Newton alone did not complete (redone by the fallbacks)
    failed: int  #: steps nothing completed (the run stops at the first)

    @property
    def n_impacts(self) -> int:
        """Closures seen at the steps, all contacts (opensees_models.count_impacts)."""
        return osm.count_impacts(self.force)


def run_pair(ops: Any, left: Building, right: Building,
             contacts: Sequence[tuple[int, int, float, float]], gap: float,
             accel: NDArray[np.float64], record_dt: float, dt: float, duration: float, *,
             tol: float = 1e-10, iterations: int = 50, system: str = "BandSPD",
             numberer: str = "RCM") -> History:
    """Build the pair and run it under the ground acceleration ``accel`` [m/s²] (sampled
    at ``record_dt`` [s], linear between samples) for ``duration`` [s] in steps of ``dt``
    [s] (module docstring); every DOF and contact force read after every step. ``wall``
    times all of it (the domain's build included), ``wall_analyze`` the loop."""
    t_build = time.perf_counter()
    tags = build_pair(ops, left, right, contacts, gap)
    ops.timeSeries("Path", 1, "-dt", float(record_dt), "-values", *map(float, accel),
                   "-factor", 1.0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Transformation")
    ops.numberer(numberer)
    ops.system(system)
    ops.test("NormDispIncr", tol, iterations, 0)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    reads = tags.dof_reads()
    n_steps = round(duration / dt)
    u = np.zeros((n_steps + 1, len(reads)))
    force = np.zeros((n_steps + 1, len(tags.contacts)))
    node_disp, ele_resp, analyze = ops.nodeDisp, ops.eleResponse, ops.analyze
    retried = failed = 0
    done = n_steps
    t0 = time.perf_counter()
    for s in range(1, n_steps + 1):
        if analyze(1, dt) != 0:
            retried += 1
            if not osm._retry(ops, dt):
                failed += 1
                done = s - 1
                break
        row = u[s]
        for q, (nd, d, sign) in enumerate(reads):
            row[q] = sign * node_disp(nd, d)
        for q, el in enumerate(tags.contacts):
            force[s, q] = 0.0 - ele_resp(el, "basicForce")[0]  # 0.0 - : no -0.0
    end = time.perf_counter()
    ops.wipe()
    keep = done + 1
    return History(dt, np.arange(keep) * dt, u[:keep], force[:keep], end - t_build, end - t0,
                   retried, failed)
