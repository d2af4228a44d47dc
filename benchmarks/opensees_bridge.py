"""A multiple-frame bridge, longitudinal direction, in OpenSeesPy: the reference model for
``bench_bridge.py`` (issue 28). Not part of the package.

The classic two-frame bridge with an expansion joint (DesRoches & Fenves 2000; DesRoches &
Muthukumar 2002; Muthukumar & DesRoches 2006): each frame's deck is a rigid mass on its
piers through its bearings; the decks pound at the joint between them, are tied across it
by cable restrainers with a slack, and pound on the abutments' backwalls at the ends.

Model (1-D, ``-ndm 1 -ndf 1``, every node at x = 0, all elements ``zeroLength`` in
direction 1, displacements relative to the ground, positive to the right, frames numbered
from the left):

* **Frame** f: a deck node (mass ``deck_mass``) and one pier-cap node per pier (mass
  ``cap_mass``). Pier = ground → cap: ``Elastic k`` or, with ``yield_force``, ``Steel01 Fy
  k b``. Bearing = cap → deck: ``Elastic k_b c_b`` (stress ``k_b ε + c_b ε̇``: an elastic
  pad with a dashpot).
* **Frame damping** ``C = a0 M + a1 K`` per frame, K its piers and bearings (never the
  contacts, restrainers or abutments): ``a0 M`` by ``region … -node deck caps -rayleigh a0
  0 0 0``; ``a1 K`` by a dashpot ``a1 k`` in each pier and bearing (the bearing's in its
  ``Elastic`` eta, the pier's in a ``Parallel`` with ``Elastic 0 a1·k``: on a yielding pier
  it is proportional to the *initial* stiffness). No global ``betaK``: it would also damp
  the contact elements (see ``opensees_models.py``).
* **Joint** between frames f and f+1: deck f → deck f+1, ``ε = u_{f+1} − u_f``; the decks
  close when ``u_f − u_{f+1} > gap`` (``ε < −gap``). Laws: ``"linear"``: ``ElasticPPGap k
  −Fmax −gap`` (a linear spring behind the gap, Fmax = 10²⁰ N so it never yields);
  ``"kelvin-voigt"``: ``ViscoelasticGap k c −gap`` (pounding's Kelvin–Voigt law);
  ``"impact"``: ``ImpactMaterial K1 K2 −δy −gap`` (Muthukumar's bilinear approximation of
  the Hertz law with hysteresis damping; :func:`impact_from_hertz`). Force returned
  positive in compression.
* **Restrainers** across a joint: deck f → deck f+1, ``ElasticPPGap k_r F_y slack`` (tension
  only, engaged once the joint has opened by ``slack``, yielding at ``F_y``, the yielded
  elongation kept: ``damage``, i.e. the slack grows, as a stretched cable's does; without
  ``yield_force`` it stays elastic). Force returned positive in tension.
* **Abutments** at the row's ends: ground → deck 0 (left) and deck n−1 → ground (right), so
  that a deck moving into its backwall is ``ε < −gap``. Laws: ``"epp"``: ``ElasticPPGap K
  −P_bw −gap`` (Caltrans SDC 2.0 §7.8.1's elastic–perfectly-plastic backfill behind the
  gap; ``damage``: the backfill's permanent deformation stays); ``"hyperbolic"``:
  ``HyperbolicGapMaterial Kmax Kur Rf −Fult −gap`` (Shamsabadi et al. 2007's hyperbolic
  backbone, unloading at ``Kur``); piles (``pile_stiffness``) an ``ElasticPPGap`` in
  parallel behind the same gap. Force returned positive in compression.

Ground motion: ``UniformExcitation`` of a ``Path`` series (linear between samples), every
mass. Analysis as ``opensees_models.py``: Newmark average acceleration (γ = 1/2, β = 1/4),
Newton, ``NormDispIncr`` 1e-10 m / 50 iterations, ``BandSPD``, ``RCM``; one ``analyze(1,
dt)`` per step with every history read after it (the loop is timed); a step Newton fails is
retried by :func:`opensees_models._retry`.

Parameters of the self-check bridge (``__main__``) and where they come from
---------------------------------------------------------------------------
Read (full text, through the project's search of stored public copies):

* OpenSees wiki, *Impact Material* (stored as an HTML page of the OpenSees command manual):
  the bilinear impact law's parameters — Hertz stiffness ``kh`` "typical value EA/L or
  25,000 k-in.^-3/2", exponent n = 3/2, coefficient of restitution e "typical values from
  0.6–0.8", yield displacement δy = a·δm with a "typically 0.1", and
  ``Keff = kh √δm``, ``ΔE = kh δm^(n+1) (1 − e²)/(n + 1)``,
  ``K1 = Keff + ΔE/(a δm²)``, ``K2 = Keff − ΔE/((1 − a) δm²)``, citing Muthukumar &
  DesRoches (2006) and Muthukumar (2003). Used: kh = 25,000 kip/in^1.5 = 2.747e10 N/m^1.5,
  e = 0.7, a = 0.1; the linear joint spring is that page's ``Keff``.
* OpenSees command list (``uniaxialMaterial ElasticPPGap $matTag $E $Fy $gap <$eta>
  <damage>``, ``HyperbolicGapMaterial $matTag $Kmax $Kur $Rf $Fult $gap`` with Fult and gap
  negative, ``ImpactMaterial`` with δy and gap negative): the materials' signatures.
* BridgePM (A. Saeidpour, Univ. of Georgia; ``materials.tcl``, an OpenSees bridge model in
  the Nielson (2005) tradition): the abutment backfill "K1p soil ranges 11.5 to 28.5 kN/mm
  per meter of the abutment width" scaled by h/1.7 m, ultimate passive force 239 kPa × h ×
  w × (h/1.7) — Caltrans SDC's abutment expressions — and 7 kN/mm per pile. Used for the
  abutment: K = 28.7 kN/mm/m × w × h/1.7, P_bw = 239 kPa × h w × h/1.7 (w = 12 m, h = 2 m:
  K = 4.05e8 N/m, P_bw = 6.75 MN), 3 piles × 7 kN/mm = 2.1e7 N/m.

Reached only as abstracts (no numbers): DesRoches & Fenves (1997) UCB/EERC-97/12 and (2000)
EESD 29 (the two-frame model: nonlinear frames, tension-only restrainers, friction, pounding;
response governed by the frame period ratio, ductility and restrainer stiffness); DesRoches
& Fenves (2001) Earthquake Spectra 17 (simplified restrainer design); Muthukumar &
DesRoches (2006) Earthquake Spectra 22 (frame hysteresis and pounding: "highly out-of-phase
frames"). Muthukumar & DesRoches (2006) EESD 35 only through a review's summary (two SDOF
systems of varied period ratio, 27 records, the Hertz-damp law recommended at moderate and
high PGA). Not reached at all: DesRoches & Fenves (2000) J. Struct. Eng. 126(4); DesRoches
& Muthukumar (2002) J. Struct. Eng. 128(7); Muthukumar (2003) thesis. So the frames'
masses, stiffnesses, the joint gap and the restrainers' numbers below are **plausible
values chosen here, not the papers'**: an out-of-phase pair (fundamental periods 0.61 s
and 1.44 s, ratio 0.42, stiff frame left) with box-girder-sized decks (3000 t, 4000 t); a
1-in (25.4 mm) joint gap; ½-in (12.7 mm) restrainer slack; a 2-in (50.8 mm) abutment gap;
ten ¾-in cable restrainers at 1.76 kN/mm and 176 kN each; elastomeric bearings twice as
stiff as the piers; cap masses 10 % of the deck; 5 % Rayleigh damping at each frame's two
modes; 2 % of critical in each bearing (deck on its bearings); yielding piers (second
self-check case) at 8 MN and 6 MN with 2 % hardening; the hyperbolic abutment with Kmax =
Kur = the Caltrans K, Fult = P_bw, Rf = 0.7. δm = 25.4 mm for the impact law's stiffnesses
is assumed, as the wiki leaves it to the user: K_eff = 4378 kN/mm (the linear joint's k),
K1 = 13310 kN/mm, K2 = 3386 kN/mm, δy = 2.54 mm; the Kelvin–Voigt option's dashpot is
``opensees_models.kv_dashpot(K_eff, e = 0.7, m1, m2)`` (Anagnostopoulos' ζ).
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

BIG_FORCE = 1.0e20
"""A force no element reaches [N]: a gap element's 'never yields'."""
KIP, INCH = 4448.2216152605, 0.0254
"""US units [N], [m]."""


# ----------------------------------------------------------------------- parameters
@dataclass(frozen=True)
class Pier:
    """A pier with its bearing and its cap: pier stiffness [N/m] (``Steel01`` if
    ``yield_force`` [N] is given, post-yield ratio ``hardening``), cap mass [kg], bearing
    stiffness [N/m] and dashpot [N·s/m]."""

    stiffness: float
    bearing_stiffness: float
    cap_mass: float = 0.0
    bearing_damping: float = 0.0
    yield_force: float | None = None
    hardening: float = 0.02


@dataclass(frozen=True)
class Frame:
    """A deck [kg] on its piers, with its Rayleigh ``a0`` [1/s] and ``a1`` [s]."""

    deck_mass: float
    piers: Sequence[Pier]
    a0: float = 0.0
    a1: float = 0.0


@dataclass(frozen=True)
class Restrainers:
    """Cable restrainers across a joint: total stiffness [N/m], slack [m] (joint opening
    at which they engage), total yield force [N] (None: elastic)."""

    stiffness: float
    slack: float
    yield_force: float | None = None


@dataclass(frozen=True)
class Joint:
    """An expansion joint: the gap [m] and its contact law (module docstring): ``law`` one
    of ``"linear"`` (``stiffness``), ``"kelvin-voigt"`` (``stiffness``, ``damping``),
    ``"impact"`` (``k1``, ``k2``, ``yield_displacement``)."""

    gap: float
    law: str = "linear"
    stiffness: float = 0.0
    damping: float = 0.0
    k1: float = 0.0
    k2: float = 0.0
    yield_displacement: float = 0.0
    restrainers: Restrainers | None = None


@dataclass(frozen=True)
class Abutment:
    """An abutment's backwall: gap [m]; ``law`` ``"epp"`` (``stiffness`` [N/m],
    ``capacity`` P_bw [N]) or ``"hyperbolic"`` (``stiffness`` = Kmax, ``unloading_stiffness``
    = Kur [N/m], ``capacity`` = Fult [N], ``failure_ratio`` Rf); ``pile_stiffness`` [N/m]
    in parallel behind the same gap."""

    gap: float
    stiffness: float
    capacity: float
    law: str = "epp"
    unloading_stiffness: float = 0.0
    failure_ratio: float = 0.7
    pile_stiffness: float = 0.0


@dataclass(frozen=True)
class Bridge:
    """Frames from the left, the joints between them (``len(frames) − 1``), and the
    abutments (None: a free end)."""

    frames: Sequence[Frame]
    joints: Sequence[Joint]
    left_abutment: Abutment | None = None
    right_abutment: Abutment | None = None

    def __post_init__(self) -> None:
        if len(self.joints) != len(self.frames) - 1:
            raise ValueError(f"a bridge of {len(self.frames)} frames needs "
                             f"{len(self.frames) - 1} joints (got {len(self.joints)})")


# ----------------------------------------------------------------------- closed forms
def impact_from_hertz(kh: float, e: float, delta_m: float, a: float = 0.1,
                      n: float = 1.5) -> tuple[float, float, float, float]:
    """Muthukumar's bilinear impact law from a Hertz contact (OpenSees wiki, Impact
    Material): ``(K_eff, K1, K2, δy)`` with ``K_eff = kh δm^(n−1)``, ``ΔE = kh δm^(n+1)
    (1 − e²)/(n + 1)``, ``K1 = K_eff + ΔE/(a δm²)``, ``K2 = K_eff − ΔE/((1 − a) δm²)``,
    ``δy = a δm``. SI: kh [N/m^n], δm [m]."""
    k_eff = kh * delta_m ** (n - 1.0)
    energy = kh * delta_m ** (n + 1.0) * (1.0 - e * e) / (n + 1.0)
    k1 = k_eff + energy / (a * delta_m ** 2)
    k2 = k_eff - energy / ((1.0 - a) * delta_m ** 2)
    return k_eff, k1, k2, a * delta_m


def frame_periods(frame: Frame) -> NDArray[np.float64]:
    """A frame alone (joints open): its periods [s] from its M and K (deck, then caps):
    by hand for one pier (``m_c m_d ω⁴ − (m_c k_b + m_d (k_p + k_b)) ω² + k_p k_b = 0``),
    else by ``eigvalsh``. Massless caps: the one DOF ``ω² = Σ k_p k_b/(k_p + k_b) / m_d``."""
    m_d = frame.deck_mass
    if all(p.cap_mass == 0.0 for p in frame.piers):
        k_eq = sum(p.stiffness * p.bearing_stiffness / (p.stiffness + p.bearing_stiffness)
                   for p in frame.piers)
        return np.array([2.0 * math.pi * math.sqrt(m_d / k_eq)])
    if len(frame.piers) == 1:
        p = frame.piers[0]
        m_c, k_p, k_b = p.cap_mass, p.stiffness, p.bearing_stiffness
        qa, qb, qc = m_c * m_d, -(m_c * k_b + m_d * (k_p + k_b)), k_p * k_b
        root = math.sqrt(qb * qb - 4.0 * qa * qc)
        w2 = np.array([(-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)])
        return 2.0 * math.pi / np.sqrt(w2)
    n = 1 + len(frame.piers)
    M, K = np.zeros((n, n)), np.zeros((n, n))
    M[0, 0] = m_d
    for i, p in enumerate(frame.piers, start=1):
        M[i, i] = p.cap_mass
        K[0, 0] += p.bearing_stiffness
        K[i, i] += p.bearing_stiffness + p.stiffness
        K[0, i] = K[i, 0] = -p.bearing_stiffness
    m_half = np.diag(1.0 / np.sqrt(np.diag(M)))
    w2 = np.sort(np.linalg.eigvalsh(m_half @ K @ m_half))
    return 2.0 * math.pi / np.sqrt(w2)


def rayleigh_for(frame: Frame, zeta: float) -> tuple[float, float]:
    """``(a0, a1)`` giving ζ at the frame's first two modes (one mode: at it twice)."""
    w = np.sort(2.0 * math.pi / frame_periods(frame))
    return osm.rayleigh_coefficients(float(w[0]), float(w[min(1, w.size - 1)]), zeta)


# ----------------------------------------------------------------------- the domain
@dataclass
class BridgeTags:
    """Tags of a built bridge (node and element numbers)."""

    decks: list[int] = field(default_factory=list)
    caps: list[int] = field(default_factory=list)
    cap_frame: list[int] = field(default_factory=list)
    joints: list[int] = field(default_factory=list)
    restrainers: list[int] = field(default_factory=list)
    restrainer_joint: list[int] = field(default_factory=list)
    abutments: list[int] = field(default_factory=list)
    abutment_side: list[str] = field(default_factory=list)


GROUND = 1


def _pier(ops: Any, tag: int, pier: Pier, a1: float) -> None:
    """The pier's material ``tag`` (its ``a1 k`` dashpot in parallel)."""
    k = float(pier.stiffness)
    if pier.yield_force is None:
        ops.uniaxialMaterial("Elastic", tag, k, a1 * k)
        return
    ops.uniaxialMaterial("Steel01", tag + 1, float(pier.yield_force), k, float(pier.hardening))
    if a1 == 0.0:
        ops.uniaxialMaterial("Parallel", tag, tag + 1)
        return
    ops.uniaxialMaterial("Elastic", tag + 2, 0.0, a1 * k)
    ops.uniaxialMaterial("Parallel", tag, tag + 1, tag + 2)


def _joint_material(ops: Any, tag: int, joint: Joint) -> None:
    gap = -abs(float(joint.gap))
    if joint.law == "linear":
        ops.uniaxialMaterial("ElasticPPGap", tag, float(joint.stiffness), -BIG_FORCE, gap)
    elif joint.law == "kelvin-voigt":
        ops.uniaxialMaterial("ViscoelasticGap", tag, float(joint.stiffness),
                             float(joint.damping), gap)
    elif joint.law == "impact":
        ops.uniaxialMaterial("ImpactMaterial", tag, float(joint.k1), float(joint.k2),
                             -abs(float(joint.yield_displacement)), gap)
    else:
        raise ValueError(f"joint law must be linear, kelvin-voigt or impact "
                         f"(got {joint.law!r})")


def _abutment_material(ops: Any, tag: int, ab: Abutment) -> None:
    gap = -abs(float(ab.gap))
    if ab.law == "epp":
        ops.uniaxialMaterial("ElasticPPGap", tag + 1, float(ab.stiffness),
                             -abs(float(ab.capacity)), gap, 0.0, "damage")
    elif ab.law == "hyperbolic":
        ops.uniaxialMaterial("HyperbolicGapMaterial", tag + 1, float(ab.stiffness),
                             float(ab.unloading_stiffness), float(ab.failure_ratio),
                             -abs(float(ab.capacity)), gap)
    else:
        raise ValueError(f"abutment law must be epp or hyperbolic (got {ab.law!r})")
    parts = [tag + 1]
    if ab.pile_stiffness > 0.0:
        ops.uniaxialMaterial("ElasticPPGap", tag + 2, float(ab.pile_stiffness), -BIG_FORCE,
                             gap)
        parts.append(tag + 2)
    ops.uniaxialMaterial("Parallel", tag, *parts)


def build_bridge(ops: Any, bridge: Bridge, log: str = osm._LOG) -> BridgeTags:
    """The bridge in a wiped domain (module docstring)."""
    ops.wipe()
    ops.logFile(log, "-noEcho")
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(GROUND, 0.0)
    ops.fix(GROUND, 1)
    tags = BridgeTags()
    for f, frame in enumerate(bridge.frames):
        base = 1000 * (f + 1)
        deck = base + 1
        ops.node(deck, 0.0)
        ops.mass(deck, float(frame.deck_mass))
        tags.decks.append(deck)
        nodes = [deck]
        for p, pier in enumerate(frame.piers):
            cap = base + 10 + p
            ops.node(cap, 0.0)
            if pier.cap_mass > 0.0:
                ops.mass(cap, float(pier.cap_mass))
            _pier(ops, base + 100 + 10 * p, pier, frame.a1)
            ops.element("zeroLength", base + 10 + p, GROUND, cap, "-mat", base + 100 + 10 * p,
                        "-dir", 1)
            kb = float(pier.bearing_stiffness)
            ops.uniaxialMaterial("Elastic", base + 500 + p, kb,
                                 float(pier.bearing_damping) + frame.a1 * kb)
            ops.element("zeroLength", base + 50 + p, cap, deck, "-mat", base + 500 + p,
                        "-dir", 1)
            tags.caps.append(cap)
            tags.cap_frame.append(f)
            nodes.append(cap)
        if frame.a0 > 0.0:
            ops.region(f + 1, "-node", *nodes, "-rayleigh", float(frame.a0), 0.0, 0.0, 0.0)
    for j, joint in enumerate(bridge.joints):
        tag = 90000 + 100 * j
        _joint_material(ops, tag, joint)
        ops.element("zeroLength", tag, tags.decks[j], tags.decks[j + 1], "-mat", tag,
                    "-dir", 1)
        tags.joints.append(tag)
        r = joint.restrainers
        if r is not None:
            fy = BIG_FORCE if r.yield_force is None else abs(float(r.yield_force))
            ops.uniaxialMaterial("ElasticPPGap", tag + 1, float(r.stiffness), fy,
                                 abs(float(r.slack)), 0.0, "damage")
            ops.element("zeroLength", tag + 1, tags.decks[j], tags.decks[j + 1], "-mat",
                        tag + 1, "-dir", 1)
            tags.restrainers.append(tag + 1)
            tags.restrainer_joint.append(j)
    for side, ab, pair in (("left", bridge.left_abutment, (GROUND, tags.decks[0])),
                           ("right", bridge.right_abutment, (tags.decks[-1], GROUND))):
        if ab is None:
            continue
        tag = 95000 if side == "left" else 95100
        _abutment_material(ops, tag, ab)
        ops.element("zeroLength", tag, *pair, "-mat", tag, "-dir", 1)
        tags.abutments.append(tag)
        tags.abutment_side.append(side)
    return tags


def eigen_periods(ops: Any, n: int) -> NDArray[np.float64]:
    """The first ``n`` periods [s] of the built domain (contacts open), full LAPACK."""
    ops.wipeAnalysis()
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    lam = np.array(ops.eigen("-fullGenLapack", n))
    ops.wipeAnalysis()
    return 2.0 * np.pi / np.sqrt(lam)


# ----------------------------------------------------------------------- the run
@dataclass
class BridgeHistory:
    """OpenSees histories of a bridge (SI, relative to the ground, every ``dt``)."""

    dt: float  #: analysis (= output) step [s]
    time: NDArray[np.float64]  #: (nt,) [s]
    deck: NDArray[np.float64]  #: (nt, n_frames) deck displacements [m]
    cap: NDArray[np.float64]  #: (nt, n_piers) pier-cap displacements [m], frames in order
    cap_frame: list[int]  #: the frame of each cap column
    joint_force: NDArray[np.float64]  #: (nt, n_joints) [N], compression positive
    restrainer_force: NDArray[np.float64]  #: (nt, n_restrained) [N], tension positive
    restrainer_joint: list[int]  #: the joint of each restrainer column
    abutment_force: NDArray[np.float64]  #: (nt, n_abutments) [N], compression positive
    abutment_side: list[str]  #: "left"/"right" of each abutment column
    wall: float  #: build + analysis with its reads [s]
    wall_analyze: float  #: the analysis loop with its reads [s]
    retried: int  #: steps Newton alone did not complete
    failed: int  #: steps nothing completed (the run stops at the first)

    @property
    def joint_opening(self) -> NDArray[np.float64]:
        """(nt, n_joints) ``u_{f+1} − u_f`` [m]: the joint closes at ``−gap``."""
        return np.diff(self.deck, axis=1)

    @property
    def pier_deformation(self) -> NDArray[np.float64]:
        """(nt, n_piers) cap displacement [m] (pier drift)."""
        return self.cap

    @property
    def bearing_deformation(self) -> NDArray[np.float64]:
        """(nt, n_piers) deck − cap [m]."""
        return self.deck[:, self.cap_frame] - self.cap

    @property
    def joint_impacts(self) -> int:
        """Closures seen at the steps, all joints (opensees_models.count_impacts)."""
        return osm.count_impacts(self.joint_force)


def run_bridge(ops: Any, bridge: Bridge, accel: NDArray[np.float64], record_dt: float,
               dt: float, duration: float, *, tol: float = 1e-10, iterations: int = 50,
               system: str = "BandSPD", numberer: str = "RCM") -> BridgeHistory:
    """Build ``bridge`` and run it under the ground acceleration ``accel`` [m/s²] sampled
    at ``record_dt`` [s] for ``duration`` [s] in steps ``dt`` [s] (module docstring)."""
    t_build = time.perf_counter()
    tags = build_bridge(ops, bridge)
    ops.timeSeries("Path", 1, "-dt", float(record_dt), "-values", *map(float, accel),
                   "-factor", 1.0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain")
    ops.numberer(numberer)
    ops.system(system)
    ops.test("NormDispIncr", tol, iterations, 0)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    n_steps = round(duration / dt)
    nodes = tags.decks + tags.caps
    u = np.zeros((n_steps + 1, len(nodes)))
    eles = tags.joints + tags.restrainers + tags.abutments
    stress = np.zeros((n_steps + 1, len(eles)))
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
        for q, nd in enumerate(nodes):
            row[q] = node_disp(nd, 1)
        srow = stress[s]
        for q, el in enumerate(eles):
            srow[q] = ele_resp(el, "basicForce")[0]
    end = time.perf_counter()
    ops.wipe()
    keep = done + 1
    nd, nj, nr = len(tags.decks), len(tags.joints), len(tags.restrainers)
    stress = stress[:keep]
    return BridgeHistory(
        dt, np.arange(keep) * dt, u[:keep, :nd], u[:keep, nd:], tags.cap_frame,
        0.0 - stress[:, :nj], stress[:, nj:nj + nr] + 0.0, tags.restrainer_joint,
        0.0 - stress[:, nj + nr:], tags.abutment_side, end - t_build, end - t0, retried,
        failed)


# ----------------------------------------------------------------------- self-check bridge
def example_bridge(joint_law: str = "linear", abutment_law: str = "epp",
                   yielding: bool = False, zeta: float = 0.05) -> Bridge:
    """The two-frame bridge of the module docstring (values and sources there)."""
    kh = 25_000.0 * KIP / INCH ** 1.5  # Hertz stiffness, 25,000 kip/in^1.5 [N/m^1.5]
    k_eff, k1, k2, dy = impact_from_hertz(kh, e=0.7, delta_m=1.0 * INCH)
    frames = []
    for m_deck, k_pier, fy in ((3.0e6, 5.0e8, 8.0e6), (4.0e6, 1.2e8, 6.0e6)):
        k_b = 2.0 * k_pier
        c_b = 2.0 * 0.02 * math.sqrt(k_b * m_deck)
        pier = Pier(k_pier, k_b, cap_mass=0.1 * m_deck, bearing_damping=c_b,
                    yield_force=fy if yielding else None)
        bare = Frame(m_deck, (pier,))
        a0, a1 = rayleigh_for(bare, zeta)
        frames.append(Frame(m_deck, (pier,), a0, a1))
    restrainers = Restrainers(10 * 1.76e6, 0.5 * INCH, 10 * 176e3)
    joint = Joint(1.0 * INCH, joint_law, stiffness=k_eff,
                  damping=osm.kv_dashpot(k_eff, 0.7, 3.0e6, 4.0e6),
                  k1=k1, k2=k2, yield_displacement=dy, restrainers=restrainers)
    w, h = 12.0, 2.0
    k_abut = 28.7e6 * w * h / 1.7  # Caltrans SDC: 28.7 kN/mm per m, × h/1.7 m
    p_bw = 239e3 * w * h * h / 1.7  # 239 kPa × backwall area × h/1.7 m
    abutment = Abutment(2.0 * INCH, k_abut, p_bw, abutment_law, unloading_stiffness=k_abut,
                        pile_stiffness=3 * 7.0e6)
    return Bridge(frames, [joint], abutment, abutment)


def _main() -> None:  # pragma: no cover - a benchmark script
    import dataclasses
    import warnings

    from pounding.ground_motion import el_centro

    ops = osm._ops()
    bridge = example_bridge()
    print("Two-frame bridge, longitudinal (OpenSeesPy", ops.version() + ")")
    for f, fr in enumerate(bridge.frames):
        p = fr.piers[0]
        print(f"  frame {f + 1}: deck {fr.deck_mass / 1e3:.0f} t, cap {p.cap_mass / 1e3:.0f} t,"
              f" pier {p.stiffness / 1e6:.0f} kN/mm, bearing {p.bearing_stiffness / 1e6:.0f}"
              f" kN/mm, c_b {p.bearing_damping / 1e3:.0f} kN·s/m, a0 {fr.a0:.4f} 1/s,"
              f" a1 {fr.a1:.5f} s")
    j = bridge.joints[0]
    print(f"  joint: gap {j.gap * 1e3:.1f} mm, linear k = K_eff {j.stiffness / 1e6:.0f} kN/mm"
          f" (impact K1 {j.k1 / 1e6:.0f}, K2 {j.k2 / 1e6:.0f} kN/mm,"
          f" δy {j.yield_displacement * 1e3:.2f} mm);"
          f" restrainers {j.restrainers.stiffness / 1e6:.1f} kN/mm, slack"
          f" {j.restrainers.slack * 1e3:.1f} mm, Fy {j.restrainers.yield_force / 1e3:.0f} kN")
    a = bridge.left_abutment
    print(f"  abutments: gap {a.gap * 1e3:.1f} mm, K {a.stiffness / 1e6:.0f} kN/mm, P_bw"
          f" {a.capacity / 1e6:.2f} MN, piles {a.pile_stiffness / 1e6:.0f} kN/mm")

    build_bridge(ops, bridge)
    t_os = np.sort(eigen_periods(ops, 4))[::-1]
    ops.wipe()
    t_hand = np.sort(np.concatenate([frame_periods(fr) for fr in bridge.frames]))[::-1]
    print("\nEigen periods [s], contacts open (frames uncoupled); 2 DOF a frame:")
    print("  OpenSees eigen       " + "  ".join(f"{t:.6f}" for t in t_os))
    print("  closed form (2 DOF)  " + "  ".join(f"{t:.6f}" for t in t_hand))
    print(f"  max relative difference {np.max(np.abs(t_os / t_hand - 1.0)):.1e}")
    massless = Bridge([Frame(fr.deck_mass, [dataclasses.replace(p, cap_mass=0.0)
                                            for p in fr.piers], fr.a0, fr.a1)
                       for fr in bridge.frames], bridge.joints, bridge.left_abutment,
                      bridge.right_abutment)
    build_bridge(ops, massless)
    t_os = np.sort(eigen_periods(ops, 2))[::-1]
    ops.wipe()
    t_hand = np.sort(np.concatenate([frame_periods(fr) for fr in massless.frames]))[::-1]
    print("Massless caps: one DOF a frame, ω² = (k_p k_b/(k_p + k_b))/m_deck:")
    print("  OpenSees eigen       " + "  ".join(f"{t:.6f}" for t in t_os))
    print("  closed form (1 DOF)  " + "  ".join(f"{t:.6f}" for t in t_hand))
    print(f"  max relative difference {np.max(np.abs(t_os / t_hand - 1.0)):.1e}")

    gm = el_centro()
    accel = np.array(gm.accel, dtype=float)
    print(f"\nEl Centro ({gm.name}), 10 s, PGA {np.abs(accel).max() / 9.81:.3f} g:")
    print("  law     dt [ms]  impacts  peak joint [MN]  peak restrainer [MN]  peak abut [MN]"
          "  peak deck 1/2 [mm]  min opening [mm]  loop [s]  retried")
    cases = [("linear", "epp", False, 0.010), ("linear", "epp", False, 0.001),
             ("impact", "hyperbolic", True, 0.010), ("impact", "hyperbolic", True, 0.001)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for law, abut, yielding, dt in cases:
            h = run_bridge(ops, example_bridge(law, abut, yielding), accel, gm.dt, dt, 10.0)
            label = law if not yielding else law + "*"
            print(f"  {label:<8}{dt * 1e3:>6.0f}  {h.joint_impacts:>8d}  "
                  f"{h.joint_force.max() / 1e6:>15.3f}  {h.restrainer_force.max() / 1e6:>20.3f}"
                  f"  {h.abutment_force.max() / 1e6:>14.3f}  "
                  f"{np.abs(h.deck[:, 0]).max() * 1e3:>8.1f} /"
                  f"{np.abs(h.deck[:, 1]).max() * 1e3:>6.1f}"
                  f"  {h.joint_opening.min() * 1e3:>16.2f}  {h.wall_analyze:>8.2f}"
                  f"  {h.retried:>7d}")
    print("  (* : Steel01 piers, ImpactMaterial joint, HyperbolicGapMaterial abutments)")


if __name__ == "__main__":
    _main()
