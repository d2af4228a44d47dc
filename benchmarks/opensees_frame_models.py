"""Build a pounding :class:`~pounding.structure.frame.Frame` in OpenSeesPy and push it there.

For ``bench_pushover.py`` and ``bench_frames.py`` (not part of the package; adapted from the test helper
``tests/structure/opensees_frames.py``, which the benchmarks do not import, with the IMK
hinges added and a pushover that takes any step size). The OpenSees model is the usual
concentrated-plasticity one (Lignos & Krawinkler 2011; the OpenSees examples'
``rotSpring2D``):

* node ``i`` of the frame is OpenSees node ``i + 1``;
* element ``e`` is an ``elasticBeamColumn`` with tag ``e + 1``, ``E = 1``, ``A = EA``,
  ``Iz = EI``; columns with the ``Linear`` or ``PDelta`` transformation as the frame's
  ``geometry``, beams ``Linear``;
* a hinge at an element end is a ``zeroLength`` element (tag ``10001 + h``) between the joint
  (retained) and a new member-end node at the same place (tag ``1001 + h``, tied by
  ``equalDOF joint end 1 2``, or fixed in x, y where the joint is), in rotation, with the
  material (tag ``h + 1``) of its law: ``ElasticPP`` (elastic-plastic), ``Steel01``
  (bilinear), ``IMKBilin`` (:class:`~pounding.hysteresis.imk.IMKBilinear`);
* rigid floors: ``equalDOF`` in x from the floor's first node to the others;
* a leaning column (``leaning_loads``): pin-ended (``-release 3``) ``elasticBeamColumn``
  elements with the ``PDelta`` transformation at ``x = max x + 1 m``, one node a floor
  (tags ``2001 …``, base ``2000``) tied to the floor by ``equalDOF … 1``, rotations fixed,
  carrying the floor's leaning load;
* gravity: nodal loads and ``-beamUniform`` member loads in load pattern 1, applied in
  load steps and held (``loadConst``);
* two frames in one domain (``opensees_frame_pair.py``): :func:`add_frame` with an
  ``offset`` added to every tag above (node, element, material and transformation tags) and
  the nodes moved by ``dx``, :func:`add_gravity_loads` in the current load pattern;
  :func:`build` is ``add_frame`` with no offset and the loads in pattern 1;
* the pushover: lateral loads in pattern 2, ``DisplacementControl`` of the roof floor's x,
  Newton on each step and, where it fails, ``NewtonLineSearch``, ``KrylovNewton``, then
  ``ModifiedNewton -initial`` (:data:`FALLBACKS`) — what practitioners do.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic, HingeLaw
from pounding.hysteresis.imk import IMKBilinear
from pounding.structure.frame import Frame

LEAN_X_OFFSET = 1.0  # m, where the leaning column stands right of the frame
CONSTRAINTS = "Plain"  # the equalDOF ties are identities, which Plain enforces
TRANSF = {"linear": "Linear", "p-delta": "PDelta"}


@dataclass(frozen=True)
class OpenSeesFrame:
    """Tags of a frame built by :func:`build` (or :func:`add_frame` with ``offset``: every
    tag below, and the frame's material and transformation tags, are the ones of
    :func:`build` plus ``offset``)."""

    node: tuple[int, ...]  #: OpenSees tag of each frame node
    floor: tuple[int, ...]  #: a node of each floor (the equalDOF retained one), lowest first
    leaning: tuple[int, ...]  #: leaning-column nodes (base first), or ()
    offset: int = 0  #: added to every tag of :func:`build`
    hinge: tuple[int, ...] = ()  #: the zeroLength element of each hinge (frame.hinges order)
    element: tuple[int, ...] = ()  #: the elasticBeamColumn of each frame element


def _imk_args(law: IMKBilinear) -> list[float]:
    """``IMKBilin`` arguments of an :class:`IMKBilinear` law (OpenSees' IMKBilin.rst)::

        Ke  dp+ dpc+ du+ Fy+ FmaxFy+ FresFy+  dp- dpc- du- Fy- FmaxFy- FresFy-
        LamdaS LamdaC LamdaK  cS cC cK  D+ D-
    """
    def side(suffix: str) -> list[float]:
        def get(name: str) -> float:
            value = getattr(law, name + suffix, None)
            return float(getattr(law, name) if value is None else value)
        theta_u = get("theta_u")
        return [get("theta_p"), get("theta_pc"), 1e10 if math.isinf(theta_u) else theta_u,
                get("m_y"), get("mc_my"), get("kappa")]

    lam = [float(law.lambda_ if getattr(law, f"lambda_{m}") is None
                 else getattr(law, f"lambda_{m}")) for m in ("s", "c", "k")]
    c = [float(law.c if getattr(law, f"c_{m}") is None else getattr(law, f"c_{m}"))
         for m in ("s", "c", "k")]
    return [float(law.k0), *side(""), *side("_neg"), *lam, *c, float(law.d_pos),
            float(law.d_neg)]


def hinge_material(ops: Any, tag: int, law: HingeLaw) -> None:
    """The OpenSees uniaxial material of a pounding hinge law."""
    if isinstance(law, ElasticPlastic):
        ops.uniaxialMaterial("ElasticPP", tag, law.k0, law.m_y / law.k0)
    elif isinstance(law, BilinearHinge):
        ops.uniaxialMaterial("Steel01", tag, law.m_y, law.k0, law.hardening)
    elif type(law) is IMKBilinear:
        ops.uniaxialMaterial("IMKBilin", tag, *_imk_args(law))
    else:
        raise ValueError(f"no OpenSees material for {law.describe()}")


def build(ops: Any, frame: Frame, *, lean_transf: str = "PDelta") -> OpenSeesFrame:
    """Build ``frame`` in a wiped OpenSees domain, its gravity loads in load pattern 1;
    returns the tags."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    built = add_frame(ops, frame, lean_transf=lean_transf)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    add_gravity_loads(ops, frame, built)
    return built


def add_frame(ops: Any, frame: Frame, *, offset: int = 0, dx: float = 0.0,
              lean_transf: str = "PDelta") -> OpenSeesFrame:
    """Add ``frame`` to the current (2-D, 3 DOFs a node) domain, moved ``dx`` [m] to the
    right, every tag of the module docstring plus ``offset`` (so that two frames can stand in
    one domain: give the second an offset above the first's largest tag, 10001 + its
    hinges); no loads (:func:`add_gravity_loads`)."""
    if frame.geometry not in TRANSF:
        raise ValueError(f"no OpenSees transformation for geometry {frame.geometry!r}")
    o = int(offset)
    tags = tuple(o + i + 1 for i in range(frame.n_nodes))
    for i, (x, y) in enumerate(frame.nodes):
        ops.node(tags[i], float(x) + dx, float(y))
        if np.any(frame.supports[i]):
            ops.fix(tags[i], *(int(s) for s in frame.supports[i]))
        if np.any(frame.masses[i]):
            ops.mass(tags[i], *(float(m) for m in frame.masses[i]))
    ops.geomTransf("Linear", o + 1)
    ops.geomTransf(TRANSF[frame.geometry], o + 2)
    ops.geomTransf(lean_transf, o + 3)
    ends = [[tags[a], tags[b]] for a, b in frame.elements]
    hinge_tags = []
    for h, fh in enumerate(frame.hinges):
        joint = ends[fh.element][fh.end]
        end = o + 1001 + h
        x, y = frame.nodes[frame.elements[fh.element, fh.end]]
        ops.node(end, float(x) + dx, float(y))
        hinge_material(ops, o + h + 1, fh.law)
        ops.element("zeroLength", o + 10001 + h, joint, end, "-mat", o + h + 1, "-dir", 6)
        hinge_tags.append(o + 10001 + h)
        fixed = frame.supports[frame.elements[fh.element, fh.end]]
        if fixed[0] and fixed[1]:
            ops.fix(end, 1, 1, 0)
        else:
            ops.equalDOF(joint, end, 1, 2)
        ends[fh.element][fh.end] = end
    column = frame.is_column
    for e, (i, j) in enumerate(ends):
        ops.element("elasticBeamColumn", o + e + 1, i, j, float(frame.EA[e]), 1.0,
                    float(frame.EI[e]), o + (2 if column[e] else 1))
    level = frame.node_level
    floors = []
    for f in range(frame.levels.size):
        members = [tags[i] for i in np.flatnonzero(level == f) if not frame.supports[i, 0]]
        floors.append(members[0])
        if frame.diaphragm:
            for other in members[1:]:
                ops.equalDOF(members[0], other, 1)
    leaning: list[int] = []
    if np.any(frame.leaning_loads):
        x = float(np.max(frame.nodes[:, 0])) + LEAN_X_OFFSET + dx
        ops.node(o + 2000, x, frame.base)
        ops.fix(o + 2000, 1, 1, 1)
        leaning.append(o + 2000)
        for f, y in enumerate(frame.levels):
            ops.node(o + 2001 + f, x, float(y))
            ops.fix(o + 2001 + f, 0, 0, 1)
            ops.equalDOF(floors[f], o + 2001 + f, 1)
            ops.element("elasticBeamColumn", o + 3001 + f, o + 2000 + f, o + 2001 + f, 1e12,
                        1.0, 1.0, o + 3, "-release", 3)
            leaning.append(o + 2001 + f)
    return OpenSeesFrame(tags, tuple(floors), tuple(leaning), o, tuple(hinge_tags),
                         tuple(o + e + 1 for e in range(frame.n_elements)))


def add_gravity_loads(ops: Any, frame: Frame, built: OpenSeesFrame) -> None:
    """The frame's gravity loads (nodal, leaning column, ``-beamUniform``) in the current
    load pattern."""
    tags, o = built.node, built.offset
    for i in range(frame.n_nodes):
        if np.any(frame.nodal_loads[i]):
            ops.load(tags[i], *(float(v) for v in frame.nodal_loads[i]))
    for f, p in enumerate(frame.leaning_loads):
        if p:
            ops.load(o + 2001 + f, 0.0, -float(p), 0.0)
    for e in range(frame.n_elements):
        w = float(frame.member_loads[e])
        if w:
            a, b = frame.elements[e]
            c, s = (frame.nodes[b] - frame.nodes[a]) / frame.lengths[e]
            ops.eleLoad("-ele", o + e + 1, "-type", "-beamUniform", -w * c, -w * s)


def first_mode_shape(ops: Any, built: OpenSeesFrame) -> NDArray[np.float64]:
    """The first mode's floor displacements (largest 1), from OpenSees' full generalized
    eigen solver (which handles the massless DOFs), in the current state (after gravity:
    with its P-Delta)."""
    ops.wipeAnalysis()
    ops.constraints(CONSTRAINTS)
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.eigen("-fullGenLapack", 1)
    shape = np.array([ops.nodeEigenvector(n, 1, 1) for n in built.floor])
    return shape / shape[np.argmax(np.abs(shape))]


def _static(ops: Any, tol: float, system: str = "BandGeneral") -> None:
    ops.wipeAnalysis()
    ops.constraints(CONSTRAINTS)
    ops.numberer("RCM")
    ops.system(system)
    ops.test("NormDispIncr", tol, 100)
    ops.algorithm("Newton")


def gravity(ops: Any, steps: int = 10, tol: float = 1e-10,
            system: str = "BandGeneral") -> None:
    """Apply load pattern 1 in ``steps`` load steps and hold it (``loadConst``), solving
    with OpenSees' ``system``."""
    _static(ops, tol, system)
    ops.integrator("LoadControl", 1.0 / steps)
    ops.analysis("Static")
    if ops.analyze(steps) != 0:
        raise RuntimeError("OpenSees: the gravity analysis failed")
    ops.loadConst("-time", 0.0)


FALLBACKS: tuple[tuple[tuple[str, ...], int], ...] = (
    (("Newton",), 25),
    (("NewtonLineSearch",), 100),
    (("KrylovNewton",), 200),
    (("ModifiedNewton", "-initial"), 5000),
)
"""What an OpenSees user tries when a step fails: other algorithms, then the initial
stiffness (positive definite, so it goes on where the tangent is singular), in this order."""


@dataclass(frozen=True)
class PushoverCurve:
    """An OpenSees pushover: roof displacements [m] and base shears [N] at its converged steps
    (from the gravity state), how many steps needed a fallback algorithm, and whether it
    reached the target."""

    roof: NDArray[np.float64]
    base_shear: NDArray[np.float64]
    rescued: int
    complete: bool


def pushover(ops: Any, built: OpenSeesFrame, shape: NDArray[np.float64], target: float,
             step: float, tol: float = 1e-10, newton_iterations: int = 25) -> PushoverCurve:
    """Displacement-controlled pushover: lateral loads ``shape`` (per floor, summing to 1) in
    load pattern 2, the roof floor's x pushed by ``step`` [m] through ``target`` (from where
    gravity left it), Newton on each step with the tolerance ``tol`` [m] on the norm of the
    displacement increment and at most ``newton_iterations``. A step that fails is tried
    with the other :data:`FALLBACKS` (with their own iteration limits); where every one
    fails the curve stops there. The base shear is the load factor of pattern 2 (its loads
    sum to 1 N)."""
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    for node, p in zip(built.floor, shape, strict=True):
        ops.load(node, float(p), 0.0, 0.0)
    roof = built.floor[-1]
    _static(ops, tol)
    ops.test("NormDispIncr", tol, newton_iterations)
    ops.integrator("DisplacementControl", roof, 1, step)
    ops.analysis("Static")
    u, V = [ops.nodeDisp(roof, 1)], [0.0]
    rescued = 0
    n = round(target / step)
    for _ in range(n):
        ok = False
        for k, (algorithm, iterations) in enumerate(FALLBACKS):
            if k:
                ops.test("NormDispIncr", tol, iterations)
                ops.algorithm(*algorithm)
            if ops.analyze(1) == 0:
                ok = True
                rescued += k > 0
                break
        if k:  # back to Newton for the next step
            ops.test("NormDispIncr", tol, newton_iterations)
            ops.algorithm(*FALLBACKS[0][0])
        if not ok:
            break
        u.append(ops.nodeDisp(roof, 1))
        V.append(ops.getLoadFactor(2))
    return PushoverCurve(np.array(u), np.array(V), rescued, len(u) == n + 1)
