"""Import a planar frame from a live OpenSeesPy domain into a :class:`~pounding.structure.frame.Frame`.

The user builds the frame in OpenSeesPy as usual and calls :func:`frame_from_opensees`; the
domain is read, not changed (no analysis is set up or run). What is read, and how
(OpenSeesPy 3.7, checked by ``tests/structure/test_frame_opensees_import.py``):

* **nodes**: ``getNodeTags``, ``nodeCoord``, ``nodeMass`` (exact); fixities
  ``getFixedNodes``/``getFixedDOFs``; the model must be 2-D with 3 DOFs a node.
* **element and material types, parameters**: ``printModel('-JSON', '-file', …)`` names every
  element's type, nodes, geometric transformation and releases, and every uniaxial
  material's type and parameters — but to 6 significant digits only (``setPrecision`` does
  not change it). So the numbers that matter are read again exactly
  (:mod:`pounding.structure.opensees_domain`):

  - ``elasticBeamColumn`` (``ElasticBeam2d``): ``EA`` and ``EI`` from the element's basic
    stiffness ``basicStiffness(tag)`` = ``[[EA/L, 0, 0], [0, 4EI/L, 2EI/L], [0, 2EI/L,
    4EI/L]]`` times the length from ``nodeCoord`` (exact to rounding);
  - the hinge materials' constants (``E``, ``Fy``, ``b``, ``a1``, ``a3``) through an OpenSees
    parameter on the zeroLength's material, added, read with ``getParamValue`` and removed
    (the material's state is untouched; ``ElasticPP``'s ``epsyN`` and ``eps0``, which no
    parameter reads, from the printout);

* **hinges**: a ``zeroLength`` element between two nodes at one place, with one rotational
  material (``-dir 3`` or ``-dir 6``) and its two nodes tied in translation (``equalDOF a b
  1 2``, both fixed, or elastic ``-dir 1 2`` materials, taken as rigid). The member-end node
  (``b``: the constrained node of the ``equalDOF``, else the one node with one element) is
  merged into the joint (``a``); the element that used ``b`` gets a
  :class:`~pounding.structure.frame.FrameHinge` at that end. Materials:

  - ``ElasticPP`` (symmetric, ``eps0 = 0``) → :class:`~pounding.hysteresis.hinges.ElasticPlastic`;
  - ``Steel01`` with no isotropic hardening (``a1 = a3 = 0``) →
    :class:`~pounding.hysteresis.hinges.BilinearHinge` with hardening ``b``;
  - ``IMKBilin`` and ``IMKPeakOriented`` → :class:`~pounding.hysteresis.imk.IMKBilinear` and
    :class:`~pounding.hysteresis.imk.IMKPeakOriented`, their constants from the printout (no
    parameter reads them: 6 significant digits, exact for constants typed with 6 or fewer;
    :func:`pounding.structure.opensees_domain.imk_law`);
  - ``Bilin`` (the older implementation OpenSees says to replace by ``IMKBilin``) without
    cyclic deterioration → :class:`~pounding.hysteresis.imk.IMKBilinear` (with it: refused,
    its rules differ; :func:`pounding.structure.opensees_domain.bilin_law`);
  - any material can be given as a hinge law with ``materials={tag: law}``, which takes
    precedence over what the domain says;

* **rigid floors**: ``equalDOF r c 1`` between nodes of one level; every floor's nodes tied
  in x gives ``diaphragm=True`` (some floors or some nodes only: refused);
* **a leaning column**: pin-ended ``elasticBeamColumn`` elements (``-release 3``) in a line
  of nodes, one per floor, tied to the floors by ``equalDOF … 1``, with their rotations fixed,
  carrying vertical loads only; their loads become ``leaning_loads`` (their P-Delta, with a
  ``PDelta`` transformation; with ``Linear`` they add nothing laterally in OpenSees, and the
  import drops them);
* **geometry**: the columns' transformation, ``Linear`` → ``"linear"``, ``PDelta`` →
  ``"p-delta"`` (pounding holds the axial forces of the gravity analysis constant, OpenSees
  uses the current ones: the two differ by the change of the columns' axial forces under
  lateral load);
* **gravity loads**: the reference loads of the load patterns (``getNodeLoadData``, and
  ``-beamUniform`` element loads from ``getEleLoadData`` as member loads, which must be
  vertical), every pattern or those named by ``load_patterns``.

Anything else is refused with a :class:`ValueError` in one line naming the element, node or
material. Damping is not read (the frame gets pounding's default).

A note for the OpenSees side of a comparison: a hinge's member-end node tied to a joint that
a rigid floor ties in turn is a chain of ``equalDOF`` constraints, which OpenSees 3.7.1's
``Transformation`` handler gets wrong silently (the first period of the 3-storey frame of the
tests came out 13 % short); ``constraints('Plain')`` handles these identity ties exactly.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.hinges import HingeLaw
from pounding.structure.frame import LEVEL_TOL, Frame, FrameHinge
from pounding.structure.opensees_domain import (
    hinge_law,
    model_json,
    mp_ties,
    pattern_loads,
)

__all__ = ["ImportedFrame", "frame_from_opensees", "read_opensees_frame"]

_BEAM = "ElasticBeam2d"
_ZERO = "ZeroLength"
_TRANSFORMS = ("LinearCrdTransf2d", "PDeltaCrdTransf2d")


@dataclass(frozen=True)
class ImportedFrame:
    """What :func:`read_opensees_frame` returns: the frame and where its parts came from.

    Attributes
    ----------
    frame : Frame
        The frame.
    node_tags : tuple of int
        OpenSees tag of each frame node (member-end nodes of hinges are merged into their
        joints; leaning-column nodes are left out).
    element_tags : tuple of int
        OpenSees tag of each frame element.
    hinge_tags : tuple of int
        OpenSees tag of the ``zeroLength`` element of each hinge (in ``frame.hinges`` order).
    """

    frame: Frame
    node_tags: tuple[int, ...]
    element_tags: tuple[int, ...]
    hinge_tags: tuple[int, ...]


Tie = tuple[int, int, tuple[int, ...], tuple[int, ...]]


@dataclass
class _Domain:
    """What the import read from the domain (tags are OpenSees tags)."""

    ops: Any
    coord: dict[int, NDArray[np.float64]]
    fixed: dict[int, NDArray[np.bool_]]
    mass: dict[int, NDArray[np.float64]]
    ele_info: dict[int, dict[str, Any]]
    mat_info: dict[int, dict[str, Any]]
    transf: dict[str, str]
    ends: dict[int, tuple[int, int]]
    beams: list[int]
    zeros: list[int]
    ties: list[Tie]
    scale: float
    attached: dict[int, list[int]] = field(default_factory=dict)
    used_ties: set[int] = field(default_factory=set)

    def transformation(self, e: int) -> str:
        return self.transf.get(str(self.ele_info.get(e, {}).get("crdTransformation")), "?")


def _read(ops: Any) -> _Domain:
    """Nodes, fixities, masses, elements and constraints of the domain."""
    model = model_json(ops)
    geometry = model.get("geometry", {})
    props = model.get("properties", {})
    node_info = {int(n["name"]): n for n in geometry.get("nodes", [])}
    ele_info = {int(e["name"]): e for e in geometry.get("elements", [])}
    mat_info = {int(m["name"]): m for m in props.get("uniaxialMaterials", [])
                if str(m.get("name", "")).lstrip("-").isdigit()}
    transf = {str(t["name"]): str(t["type"]) for t in props.get("crdTransformations", [])}
    tags = [int(t) for t in ops.getNodeTags()]
    if not tags:
        raise ValueError("the OpenSees domain has no nodes")
    coord = {}
    for t in tags:
        xy = np.asarray(ops.nodeCoord(t), dtype=float)
        ndf = int(node_info.get(t, {}).get("ndf", 3))
        if xy.size != 2 or ndf != 3:
            raise ValueError(f"node {t}: {xy.size}-D with {ndf} DOFs; pounding imports planar "
                             "frames (model basic -ndm 2 -ndf 3)")
        coord[t] = xy
    fixed = {t: np.zeros(3, dtype=bool) for t in tags}
    for t in ops.getFixedNodes():
        for d in ops.getFixedDOFs(int(t)):
            fixed[int(t)][int(d) - 1] = True
    mass = {t: np.asarray(ops.nodeMass(t), dtype=float)[:3] for t in tags}
    d = _Domain(ops, coord, fixed, mass, ele_info, mat_info, transf, {}, [], [], mp_ties(ops),
                max(1.0, max(float(np.max(np.abs(c))) for c in coord.values())),
                {t: [] for t in tags})
    for e in (int(t) for t in ops.getEleTags()):
        kind = ops.eleType(e) if hasattr(ops, "eleType") else ele_info.get(e, {}).get("type")
        info = ele_info.get(e, {})
        if kind == _BEAM:
            if float(info.get("massperlength", 0.0)) != 0.0:
                raise ValueError(f"element {e} ({kind}): a distributed mass (-mass "
                                 f"{info['massperlength']}); give the masses at the nodes")
            if int(info.get("release", 0)) not in (0, 3):
                raise ValueError(f"element {e} ({kind}): -release {info['release']} (one end "
                                 "pinned); use a zeroLength hinge, or release both ends for a "
                                 "leaning column")
            d.beams.append(e)
        elif kind == _ZERO:
            d.zeros.append(e)
        else:
            raise ValueError(f"element {e} ({kind}): not supported; pounding imports "
                             "elasticBeamColumn elements and zeroLength rotational hinges")
        nodes = tuple(int(n) for n in ops.eleNodes(e))
        d.ends[e] = (nodes[0], nodes[1])
        for n in nodes:
            d.attached[n].append(e)
    return d


def _hinge(d: _Domain, z: int, materials: Mapping[int, HingeLaw]
           ) -> tuple[int, int, HingeLaw]:
    """(joint a, member end b, law) of zeroLength element ``z``."""
    who = f"element {z} (zeroLength)"
    info = d.ele_info.get(z, {})
    dofs = [str(x) for x in info.get("dof", [])]
    mats = [int(m) for m in info.get("materials", [])]
    if dofs.count("Mz") != 1 or any(x not in ("P", "Vy", "Mz") for x in dofs):
        raise ValueError(f"{who}: directions {dofs}: need one rotational material (-dir 3 or "
                         "6) and rigid translations; pounding imports zeroLength elements as "
                         "rotational hinges")
    i, j = d.ends[z]
    if np.hypot(*(d.coord[i] - d.coord[j])) > 1e-9 * d.scale:
        raise ValueError(f"{who}: its nodes {i} and {j} are apart; a hinge joins two nodes "
                         "at one place")
    tied: set[int] = set()
    constrained = []
    for k, (r, c, rd, cd) in enumerate(d.ties):
        if {r, c} == {i, j}:
            if rd != cd or 3 in cd:
                raise ValueError(f"{who}: equalDOF {r} {c} ties DOFs {list(cd)}; a hinge's two "
                                 "nodes are tied in translation only (1 2)")
            tied |= set(cd)
            constrained.append(c)
            d.used_ties.add(k)
    for name, dof in (("P", 1), ("Vy", 2)):
        if name in dofs:
            mtag = mats[dofs.index(name)]
            if str(d.mat_info.get(mtag, {}).get("type")) != "ElasticMaterial":
                raise ValueError(f"{who}: material {mtag} in direction {dof} is not Elastic; "
                                 "the translations of a hinge are rigid ties")
            tied.add(dof)
    tied |= {k + 1 for k in range(2) if d.fixed[i][k] and d.fixed[j][k]}
    if not {1, 2} <= tied:
        raise ValueError(f"{who}: nodes {i} and {j} are not tied in translation (equalDOF "
                         f"{i} {j} 1 2)")

    def member_end(n: int) -> bool:
        others = [e for e in d.attached[n] if e != z]
        return len(others) == 1 and others[0] in d.beams and not d.fixed[n][2]

    order = [constrained[0], i + j - constrained[0]] if constrained else [j, i]
    b = next((n for n in order if member_end(n)), None)
    if b is None:
        raise ValueError(f"{who}: neither node {i} nor {j} is a member end (one "
                         "elasticBeamColumn and this hinge, rotation free)")
    place = dofs.index("Mz")
    mtag = mats[place]
    law = hinge_law(d.ops, mtag, d.mat_info.get(mtag), materials, z, place + 1)
    return i + j - b, b, law


def _leaning(d: _Domain) -> tuple[list[int], set[int], bool]:
    """The leaning column: its pin-ended elements, their nodes, and whether their
    transformation is PDelta."""
    elems = [e for e in d.beams if int(d.ele_info.get(e, {}).get("release", 0)) == 3]
    nodes: set[int] = set()
    for e in elems:
        nodes |= set(d.ends[e])
    for n in nodes:
        if any(e not in elems for e in d.attached[n]):
            raise ValueError(f"node {n}: joins a pin-ended (leaning) element and other "
                             "elements; a leaning column stands apart, tied to the floors by "
                             "equalDOF 1")
    kinds = set()
    for e in elems:
        i, j = d.ends[e]
        if abs(d.coord[j][0] - d.coord[i][0]) > 1e-9 * d.scale:
            raise ValueError(f"element {e} ({_BEAM}, -release 3): not vertical; pounding "
                             "reads pin-ended elements as a leaning column")
        kind = d.transformation(e)
        if kind not in _TRANSFORMS:
            raise ValueError(f"element {e} ({_BEAM}): transformation {kind} not supported "
                             "(Linear or PDelta)")
        kinds.add(kind)
    if len(kinds) > 1:
        raise ValueError("leaning column: some of its elements have a PDelta transformation "
                         "and some do not")
    return elems, nodes, kinds == {"PDeltaCrdTransf2d"}


@dataclass
class _Members:
    elements: list[tuple[int, int]] = field(default_factory=list)
    EA: list[float] = field(default_factory=list)
    EI: list[float] = field(default_factory=list)
    w: list[float] = field(default_factory=list)
    hinges: list[FrameHinge] = field(default_factory=list)
    hinge_tags: list[int] = field(default_factory=list)
    geometry: str = "linear"


def _members(d: _Domain, elems: list[int], node_index: Callable[[int], int],
             hinge_at: dict[int, tuple[int, HingeLaw]],
             member_loads: dict[int, NDArray[np.float64]]) -> _Members:
    """Rigidities, hinges, member loads and geometry of the frame elements ``elems``."""
    out = _Members()
    columns: set[str] = set()
    beams: set[str] = set()
    for k, e in enumerate(elems):
        i, j = d.ends[e]
        delta = d.coord[j] - d.coord[i]
        L = float(np.hypot(*delta))
        kb = np.asarray(d.ops.basicStiffness(e), dtype=float)
        if kb.size != 9 or not math.isclose(kb[5], 0.5 * kb[4], rel_tol=1e-9) or not \
                math.isclose(kb[7], kb[5], rel_tol=1e-9) or kb[1] != 0.0 or kb[2] != 0.0:
            raise ValueError(f"element {e} ({_BEAM}): its basic stiffness {kb.tolist()} is "
                             "not that of an elastic Euler-Bernoulli beam-column")
        out.EA.append(float(kb[0]) * L)
        out.EI.append(float(kb[4]) * L / 4.0)
        out.elements.append((node_index(i), node_index(j)))
        for end, n in ((0, i), (1, j)):
            if n in hinge_at:
                z, law = hinge_at[n]
                out.hinges.append(FrameHinge(k, end, law))
                out.hinge_tags.append(z)
        (columns if abs(delta[1]) > abs(delta[0]) else beams).add(d.transformation(e))
        wy, wx = member_loads.get(e, np.zeros(2))
        c, s = delta / L
        # the global load per length wy (−s, c) + wx (c, s) must be (0, −w)
        gx, gy = -wy * s + wx * c, wy * c + wx * s
        if abs(gx) > 1e-9 * max(abs(wy), abs(wx)):
            raise ValueError(f"element {e} ({_BEAM}): its -beamUniform load ({wy:.6g}, "
                             f"{wx:.6g}) N/m is not vertical; pounding's member loads are "
                             "gravity loads")
        out.w.append(0.0 - float(gy))
    for e in member_loads:
        if e not in elems:
            raise ValueError(f"element {e}: an element load on an element that is not a "
                             "frame member")
    unknown = (columns | beams) - set(_TRANSFORMS)
    if unknown:
        raise ValueError(f"geometric transformation {min(unknown)}: not supported "
                         "(Linear or PDelta)")
    if len(columns) > 1:
        raise ValueError("columns: some have a Linear and some a PDelta transformation; "
                         "pounding takes one for all")
    out.geometry = "p-delta" if columns == {"PDeltaCrdTransf2d"} else "linear"
    return out


def _find(parent: dict[int, int], x: int) -> int:
    while parent.setdefault(x, x) != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


def _floors(d: _Domain, frame: Frame, keep: list[int], joint: Callable[[int], int],
            leaning_nodes: set[int]) -> tuple[bool, dict[int, int]]:
    """Rigid floors from the remaining equalDOF ties: (diaphragm, the floor each
    leaning-column node is tied to)."""
    index = {t: k for k, t in enumerate(keep)}
    level = frame.node_level
    parent: dict[int, int] = {}
    floor_ties = 0
    lean_at: dict[int, int] = {}
    for k, (r, c, rd, cd) in enumerate(d.ties):
        if k in d.used_ties:
            continue
        if rd != (1,) or cd != (1,):
            raise ValueError(f"equalDOF {r} {c} (DOFs {list(cd)}): pounding reads equalDOF as "
                             "rigid-floor ties (DOF 1 at one level) and hinge ties (1 2)")
        if abs(d.coord[r][1] - d.coord[c][1]) > LEVEL_TOL:
            raise ValueError(f"equalDOF {r} {c} 1: the nodes stand at different levels "
                             f"({d.coord[r][1]:.6g} m, {d.coord[c][1]:.6g} m)")
        if r in leaning_nodes or c in leaning_nodes:
            lean, other = (r, c) if r in leaning_nodes else (c, r)
            if other in leaning_nodes or level[index[joint(other)]] < 0:
                raise ValueError(f"equalDOF {r} {c} 1: a leaning-column node must be tied to "
                                 "a floor of the frame")
            lean_at[lean] = int(level[index[joint(other)]])
            continue
        ra, ca = index[joint(r)], index[joint(c)]
        if level[ra] < 0 or frame.supports[ra, 0] or frame.supports[ca, 0]:
            raise ValueError(f"equalDOF {r} {c} 1: ties nodes that are not on a floor above "
                             "the base, or are fixed in x")
        parent[_find(parent, ra)] = _find(parent, ca)
        floor_ties += 1
    diaphragm = floor_ties > 0 or bool(lean_at)
    if diaphragm:
        for f, y in enumerate(frame.levels):
            members = [n for n in range(len(keep))
                       if level[n] == f and not frame.supports[n, 0]]
            if not members:
                continue  # every node of this floor is fixed in x: nothing to tie
            first = _find(parent, members[0])
            loose = [keep[n] for n in members if _find(parent, n) != first]
            if loose:
                raise ValueError(f"equalDOF: the floor at y = {y:.6g} m does not tie nodes "
                                 f"{loose} to node {keep[members[0]]} in x; pounding's rigid "
                                 "floors tie every node of every floor (tie all, or none)")
    return diaphragm, lean_at


def _leaning_loads(d: _Domain, frame: Frame, elems: list[int], nodes: set[int],
                   lean_at: dict[int, int], nodal: dict[int, NDArray[np.float64]]
                   ) -> NDArray[np.float64]:
    """The gravity load the leaning column takes at each floor [N]."""
    leaning = np.zeros(frame.levels.size)
    base = frame.base
    for n in sorted(nodes):
        if np.any(d.mass[n] != 0.0):
            raise ValueError(f"node {n}: a mass on the leaning column; put it on the floor")
        f = nodal.get(n, np.zeros(3))
        if f[0] != 0.0 or f[2] != 0.0:
            raise ValueError(f"node {n}: a leaning-column load that is not vertical "
                             f"({f.tolist()})")
        if abs(d.coord[n][1] - base) <= LEVEL_TOL:
            if not (d.fixed[n][0] and d.fixed[n][1]):
                raise ValueError(f"node {n}: the leaning column's base must be fixed in x "
                                 "and y")
            continue
        if not d.fixed[n][2]:
            raise ValueError(f"node {n}: fix the leaning column's rotations (fix {n} 0 0 1); "
                             "they have no stiffness")
        if n not in lean_at:
            raise ValueError(f"node {n}: a leaning-column node not tied to a floor "
                             f"(equalDOF <floor node> {n} 1)")
        leaning[lean_at[n]] -= f[1]
    for e in elems:
        lo, hi = sorted(d.ends[e], key=lambda n: d.coord[n][1])
        below = -1 if abs(d.coord[lo][1] - base) <= LEVEL_TOL else lean_at.get(lo, -2)
        if lean_at.get(hi, -3) != below + 1:
            raise ValueError(f"element {e} (leaning column): must span one storey, from a "
                             "floor (or the base) to the next")
    if np.any(leaning < 0.0):
        raise ValueError(f"leaning column: an upward load ({leaning.tolist()} N)")
    return leaning


def read_opensees_frame(ops_module: Any = None, *, name: str = "frame",
                        materials: Mapping[int, HingeLaw] | None = None,
                        load_patterns: Sequence[int] | None = None) -> ImportedFrame:
    """Read the planar frame of the current OpenSeesPy domain (see the module docstring).

    Parameters
    ----------
    ops_module : module, optional
        ``openseespy.opensees`` (imported when not given).
    name : str
        The frame's name.
    materials : mapping of int to HingeLaw, optional
        Hinge laws for uniaxial material tags, used instead of reading those materials (for
        materials pounding does not read, or to override).
    load_patterns : sequence of int, optional
        The load patterns whose loads are the gravity loads (default: every pattern).

    Returns
    -------
    ImportedFrame
        The frame, and the OpenSees tags of its nodes, elements and hinges.

    Raises
    ------
    ValueError
        One line naming what is not supported or inconsistent.
    """
    ops = ops_module
    if ops is None:
        from openseespy import opensees

        ops = opensees
    given = dict(materials or {})
    for tag, law in given.items():
        if not isinstance(law, HingeLaw):
            raise ValueError(f"materials[{tag}]: need a hinge law (got {law!r})")
    d = _read(ops)

    merged: dict[int, int] = {}  # member-end node b -> joint a
    hinge_at: dict[int, tuple[int, HingeLaw]] = {}  # node b -> (zeroLength tag, law)
    for z in d.zeros:
        a, b, law = _hinge(d, z, given)
        if b in merged:
            raise ValueError(f"element {z} (zeroLength): node {b} already ends another hinge")
        merged[b] = a
        hinge_at[b] = (z, law)
    for b, a in merged.items():
        if a in merged:
            raise ValueError(f"element {hinge_at[b][0]} (zeroLength): its joint {a} ends "
                             f"another hinge (element {hinge_at[a][0]}); hinges in series are "
                             "not supported")

    def joint(n: int) -> int:
        return merged.get(n, n)

    nodal, member_loads = pattern_loads(ops, load_patterns, 3)
    lean_elems, lean_nodes, lean_pdelta = _leaning(d)
    keep = [t for t in d.coord if t not in merged and t not in lean_nodes]
    index = {t: k for k, t in enumerate(keep)}
    supports = np.array([d.fixed[t] for t in keep], dtype=bool)
    masses = np.array([d.mass[t] for t in keep])
    loads = np.zeros((len(keep), 3))
    for t, f in nodal.items():
        if t in lean_nodes:
            continue
        if t in merged and f[2] != 0.0:
            raise ValueError(f"node {t}: a moment load on a hinge's member-end node; load "
                             f"the joint {merged[t]}")
        loads[index[joint(t)]] += f
    for b, a in merged.items():
        supports[index[a], :2] |= d.fixed[b][:2]
        if d.mass[b][2] != 0.0:
            raise ValueError(f"node {b}: a rotational mass on a hinge's member-end node; put "
                             f"it on the joint {a}")
        masses[index[a], :2] += d.mass[b][:2]
    frame_elems = [e for e in d.beams if e not in lean_elems]
    if not frame_elems:
        raise ValueError("the OpenSees domain has no elasticBeamColumn frame members")
    m = _members(d, frame_elems, lambda n: index[joint(n)], hinge_at, member_loads)
    nodes = np.array([d.coord[t] for t in keep])
    elements = np.array(m.elements, dtype=np.int64)
    bare = Frame(nodes=nodes, elements=elements, EA=np.array(m.EA), EI=np.array(m.EI),
                 supports=supports, masses=masses, diaphragm=False, name=name)
    diaphragm, lean_at = _floors(d, bare, keep, joint, lean_nodes)
    leaning = _leaning_loads(d, bare, lean_elems, lean_nodes, lean_at, nodal)
    if not lean_pdelta:  # a Linear pin-ended column adds nothing laterally
        leaning[:] = 0.0
    frame = Frame(nodes=nodes, elements=elements, EA=np.array(m.EA), EI=np.array(m.EI),
                  supports=supports, hinges=tuple(m.hinges), masses=masses, nodal_loads=loads,
                  member_loads=np.array(m.w), diaphragm=diaphragm, leaning_loads=leaning,
                  geometry=m.geometry, name=name)
    return ImportedFrame(frame, tuple(keep), tuple(frame_elems), tuple(m.hinge_tags))


def frame_from_opensees(ops_module: Any = None, *, name: str = "frame",
                        materials: Mapping[int, HingeLaw] | None = None,
                        load_patterns: Sequence[int] | None = None) -> Frame:
    """The planar frame of the current OpenSeesPy domain (:func:`read_opensees_frame`'s
    frame, with the same parameters; see the module docstring for what is read and how).

    Examples
    --------
    ::

        import openseespy.opensees as ops
        ...  # build the frame: nodes, fix, mass, elasticBeamColumn, zeroLength hinges
        frame = frame_from_opensees(ops, name="SMRF")
    """
    return read_opensees_frame(ops_module, name=name, materials=materials,
                               load_patterns=load_patterns).frame
