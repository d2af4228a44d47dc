"""Import a planar frame from a live OpenSeesPy domain into a :class:`~pounding.structure.frame.Frame`.

The user builds the frame in OpenSeesPy as usual and calls :func:`frame_from_opensees`; the
domain is read, not changed (no analysis is set up or run). What is read, and how
(OpenSeesPy 3.7, checked by ``tests/structure/test_frame_opensees_import.py``):

* **nodes**: ``getNodeTags``, ``nodeCoord``, ``nodeMass`` (exact); fixities
  ``getFixedNodes``/``getFixedDOFs``; the model must be 2-D with 3 DOFs a node.
* **element and material types, parameters**: ``printModel('-JSON', '-file', …)`` names every
  element's type, nodes, geometric transformation and releases, and every uniaxial
  material's type and parameters — but to 6 significant digits only (``setPrecision`` does
  not change it). So the numbers that matter are read again exactly:

  - ``elasticBeamColumn`` (``ElasticBeam2d``): ``EA`` and ``EI`` from the element's basic
    stiffness ``basicStiffness(tag)`` = ``[[EA/L, 0, 0], [0, 4EI/L, 2EI/L], [0, 2EI/L,
    4EI/L]]`` times the length from ``nodeCoord`` (exact to rounding);
  - the hinge materials by probing a copy of each with ``testUniaxialMaterial``/``setStrain``/
    ``getStress``/``getTangent`` (the domain's material is untouched): the tangent at zero
    strain is ``k0``; past yield (twice the printed yield rotation) the tangent is ``b k0``
    and the stress gives ``M_y = (M − b k0 θ)/(1 − b)``;

* **hinges**: a ``zeroLength`` element between two nodes at one place, with one rotational
  material (``-dir 3`` or ``-dir 6``) and its two nodes tied in translation (``equalDOF a b
  1 2``, both fixed, or elastic ``-dir 1 2`` materials, taken as rigid). The member-end node
  (``b``: the constrained node of the ``equalDOF``, else the one node with one element) is
  merged into the joint (``a``); the element that used ``b`` gets a
  :class:`~pounding.structure.frame.FrameHinge` at that end. Materials:

  - ``ElasticPP`` (symmetric, ``eps0 = 0``) → :class:`~pounding.hysteresis.hinges.ElasticPlastic`;
  - ``Steel01`` with no isotropic hardening (``a1 = a3 = 0``) →
    :class:`~pounding.hysteresis.hinges.BilinearHinge` with hardening ``b``;
  - ``Bilin``, ``IMKBilin``, ``IMKPeakOriented``: not yet supported (the IMK laws are not in
    pounding yet); any material can be given as a hinge law with ``materials={tag: law}``,
    which takes precedence over what the domain says;

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
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic, HingeLaw
from pounding.structure.frame import LEVEL_TOL, Frame, FrameHinge

__all__ = ["ImportedFrame", "frame_from_opensees", "read_opensees_frame"]

IMK_MATERIALS: tuple[str, ...] = ("Bilin", "IMKBilin", "IMKPeakOriented")
"""OpenSees deteriorating hinge materials that pounding will import once its IMK laws exist."""

_BEAM = "ElasticBeam2d"
_ZERO = "ZeroLength"
_UNIFORM_LOAD_CLASS = 3  # OpenSees LOAD_TAG_Beam2dUniformLoad: data (w_y, w_x)


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


def _model_json(ops: Any) -> dict[str, Any]:
    """The domain as OpenSees prints it with ``printModel -JSON`` (6 significant digits)."""
    with tempfile.TemporaryDirectory(prefix="pounding-ops-") as tmp:
        path = os.path.join(tmp, "model.json")
        ops.printModel("-JSON", "-file", path)
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
    text = re.sub(r"(?<![\w.])(-?)inf\b", r"\1Infinity", text)
    text = re.sub(r"(?<![\w.])-?nan\b", "NaN", text)
    try:
        model = json.loads(text)["StructuralAnalysisModel"]
    except (ValueError, KeyError) as exc:
        raise ValueError(f"OpenSees printModel -JSON: could not read the model it printed "
                         f"({exc})") from None
    return model  # type: ignore[no-any-return]


def _probe(ops: Any, tag: int, strain: float) -> tuple[float, float]:
    """(stress, tangent) of a fresh copy of material ``tag`` strained monotonically from 0."""
    ops.testUniaxialMaterial(tag)
    ops.setStrain(float(strain))
    return float(ops.getStress()), float(ops.getTangent())


def _hinge_law(ops: Any, tag: int, info: dict[str, Any] | None,
               materials: Mapping[int, HingeLaw]) -> HingeLaw:
    """The hinge law of uniaxial material ``tag`` (module docstring)."""
    if tag in materials:
        return materials[tag]
    if info is None:
        raise ValueError(f"material {tag}: not in the model's printed materials")
    kind = str(info.get("type", "?"))
    who = f"material {tag} ({kind})"
    if kind in IMK_MATERIALS:
        raise ValueError(f"{who}: not yet supported (the IMK hinge laws are not in pounding "
                         "yet); give materials={" + str(tag) + ": <HingeLaw>}")
    if kind == "ElasticPPMaterial":
        if float(info.get("eps0", 0.0)) != 0.0:
            raise ValueError(f"{who}: eps0 = {info['eps0']} (an initial strain); pounding's "
                             "elastic-plastic hinge starts unstrained (eps0 = 0)")
        ep, en = float(info["epsyp"]), float(info["epsyn"])
        k0 = _probe(ops, tag, 0.0)[1]
        m_pos = _probe(ops, tag, 2.0 * ep)[0]
        m_neg = _probe(ops, tag, 2.0 * en)[0]
        if not math.isclose(-m_neg, m_pos, rel_tol=1e-9):
            raise ValueError(f"{who}: yield moments +{m_pos:.6g} / {m_neg:.6g} differ; "
                             "pounding's hinges are symmetric (epsyN = -epsyP)")
        return ElasticPlastic(k0=k0, m_y=m_pos)
    if kind == "Steel01":
        iso = [float(info.get(k, 0.0)) for k in ("a1", "a2", "a3", "a4")]
        if iso[0] != 0.0 or iso[2] != 0.0:
            raise ValueError(f"{who}: isotropic hardening a1 … a4 = {iso}; pounding's bilinear "
                             "hinge has kinematic hardening only (a1 = a3 = 0)")
        k0 = _probe(ops, tag, 0.0)[1]
        theta = 2.0 * float(info["fy"]) / float(info["E"])
        m, kt = _probe(ops, tag, theta)
        b = kt / k0
        m_y = (m - kt * theta) / (1.0 - b)
        if not math.isclose(m_y, float(info["fy"]), rel_tol=1e-5):  # pragma: no cover
            raise ValueError(f"{who}: probing it gave a yield moment {m_y:.6g}, its printout "
                             f"{info['fy']}")
        if b == 0.0:
            return ElasticPlastic(k0=k0, m_y=m_y)
        return BilinearHinge(k0=k0, m_y=m_y, hardening=b)
    raise ValueError(f"{who}: not supported as a hinge (pounding reads ElasticPP, Steel01; "
                     "give materials={" + str(tag) + ": <HingeLaw>} for another)")


def _ties(ops: Any) -> list[tuple[int, int, tuple[int, ...], tuple[int, ...]]]:
    """Every MP constraint as (retained, constrained, retained DOFs, constrained DOFs)."""
    out = []
    for r in sorted({int(t) for t in ops.getRetainedNodes()}):
        for c in sorted({int(t) for t in ops.getConstrainedNodes(r)}):
            out.append((r, c, tuple(int(d) for d in ops.getRetainedDOFs(r, c)),
                        tuple(int(d) for d in ops.getConstrainedDOFs(c, r))))
    return out


def _loads(ops: Any, patterns: Sequence[int] | None, ndf: int
           ) -> tuple[dict[int, np.ndarray], dict[int, np.ndarray]]:
    """Nodal loads {node: (F_x, F_y, M)} and uniform element loads {element: (w_y, w_x)}
    summed over the chosen load patterns."""
    have = [int(p) for p in ops.getPatterns()]
    chosen = have if patterns is None else [int(p) for p in patterns]
    for p in chosen:
        if p not in have:
            raise ValueError(f"load_patterns: pattern {p} is not in the domain (it has "
                             f"{have})")
    nodal: dict[int, np.ndarray] = {}
    member: dict[int, np.ndarray] = {}
    for p in chosen:
        tags = [int(t) for t in ops.getNodeLoadTags(p)]
        data = np.asarray(ops.getNodeLoadData(p), dtype=float)
        if data.size != ndf * len(tags):
            raise ValueError(f"load pattern {p}: {data.size} nodal load values for "
                             f"{len(tags)} loads of {ndf} components")
        for k, t in enumerate(tags):
            nodal[t] = nodal.get(t, np.zeros(3)) + data[ndf * k: ndf * (k + 1)]
        etags = [int(t) for t in ops.getEleLoadTags(p)]
        classes = [int(c) for c in ops.getEleLoadClassTags(p)]
        edata = np.asarray(ops.getEleLoadData(p), dtype=float)
        for t, c in zip(etags, classes, strict=False):
            if c != _UNIFORM_LOAD_CLASS:
                raise ValueError(f"load pattern {p}: element {t}: element load of class "
                                 f"{c} not supported (pounding reads -beamUniform loads over "
                                 "the whole member)")
        if edata.size != 2 * len(etags):
            raise ValueError(f"load pattern {p}: {edata.size} element load values for "
                             f"{len(etags)} uniform loads")
        for k, t in enumerate(etags):
            member[t] = member.get(t, np.zeros(2)) + edata[2 * k: 2 * k + 2]
    return nodal, member


def _find(parent: dict[int, int], x: int) -> int:
    while parent.setdefault(x, x) != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


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
    if ops_module is None:
        import openseespy.opensees as ops_module
    ops = ops_module
    materials = dict(materials or {})
    for tag, law in materials.items():
        if not isinstance(law, HingeLaw):
            raise ValueError(f"materials[{tag}]: need a hinge law (got {law!r})")
    model = _model_json(ops)
    geometry_json = model.get("geometry", {})
    node_info = {int(n["name"]): n for n in geometry_json.get("nodes", [])}
    ele_info = {int(e["name"]): e for e in geometry_json.get("elements", [])}
    mat_info = {int(m["name"]): m for m in model.get("properties", {}).get(
        "uniaxialMaterials", []) if str(m.get("name", "")).lstrip("-").isdigit()}
    transf = {str(t["name"]): str(t["type"]) for t in model.get("properties", {}).get(
        "crdTransformations", [])}

    tags = [int(t) for t in ops.getNodeTags()]
    if not tags:
        raise ValueError("the OpenSees domain has no nodes")
    coord: dict[int, np.ndarray] = {}
    for t in tags:
        xy = np.asarray(ops.nodeCoord(t), dtype=float)
        ndf = int(node_info.get(t, {}).get("ndf", 3))
        if xy.size != 2 or ndf != 3:
            raise ValueError(f"node {t}: {xy.size}-D with {ndf} DOFs; pounding imports planar "
                             "frames (model basic -ndm 2 -ndf 3)")
        coord[t] = xy
    scale = max(1.0, max(float(np.max(np.abs(c))) for c in coord.values()))
    fixed = {t: np.zeros(3, dtype=bool) for t in tags}
    for t in ops.getFixedNodes():
        for d in ops.getFixedDOFs(int(t)):
            fixed[int(t)][int(d) - 1] = True
    mass = {t: np.asarray(ops.nodeMass(t), dtype=float)[:3] for t in tags}

    # ---------------------------------------------------------------- elements
    beams: list[int] = []
    zeros: list[int] = []
    ends: dict[int, tuple[int, int]] = {}
    for e in (int(t) for t in ops.getEleTags()):
        kind = ops.eleType(e) if hasattr(ops, "eleType") else ele_info.get(e, {}).get("type")
        info = ele_info.get(e, {})
        nodes = tuple(int(n) for n in ops.eleNodes(e))
        if kind == _BEAM:
            if float(info.get("massperlength", 0.0)) != 0.0:
                raise ValueError(f"element {e} ({kind}): a distributed mass (-mass "
                                 f"{info['massperlength']}); give the masses at the nodes")
            if int(info.get("release", 0)) not in (0, 3):
                raise ValueError(f"element {e} ({kind}): -release {info['release']} (one end "
                                 "pinned); use a zeroLength hinge, or release both ends for a "
                                 "leaning column")
            beams.append(e)
        elif kind == _ZERO:
            zeros.append(e)
        else:
            raise ValueError(f"element {e} ({kind}): not supported; pounding imports "
                             "elasticBeamColumn elements and zeroLength rotational hinges")
        ends[e] = (nodes[0], nodes[1])
    attached: dict[int, list[int]] = {t: [] for t in tags}
    for e in beams + zeros:
        for n in ends[e]:
            attached[n].append(e)

    ties = _ties(ops)
    used_ties: set[int] = set()

    # ---------------------------------------------------------------- hinges
    merged: dict[int, int] = {}  # member-end node b -> joint a
    hinge_of_end: dict[int, tuple[int, HingeLaw]] = {}  # node b -> (zeroLength tag, law)
    for z in zeros:
        who = f"element {z} (zeroLength)"
        info = ele_info.get(z, {})
        dofs = [str(d) for d in info.get("dof", [])]
        mats = [int(m) for m in info.get("materials", [])]
        if "Mz" not in dofs or dofs.count("Mz") != 1:
            raise ValueError(f"{who}: no single rotational material (-dir 3 or 6); pounding "
                             "imports zeroLength elements as rotational hinges")
        i, j = ends[z]
        if np.hypot(*(coord[i] - coord[j])) > 1e-9 * scale:
            raise ValueError(f"{who}: its nodes {i} and {j} are apart; a hinge joins two "
                             "nodes at one place")
        tied = set()
        for k, (r, c, rd, cd) in enumerate(ties):
            if {r, c} == {i, j}:
                if rd != cd or 3 in cd:
                    raise ValueError(f"{who}: equalDOF {r} {c} ties DOFs {list(cd)}; a hinge's "
                                     "two nodes are tied in translation only (1 2)")
                tied |= set(cd)
                used_ties.add(k)
        for d_name, dof in (("P", 1), ("Vy", 2)):
            if d_name in dofs:
                mtag = mats[dofs.index(d_name)]
                if str(mat_info.get(mtag, {}).get("type")) != "ElasticMaterial":
                    raise ValueError(f"{who}: material {mtag} in direction {dof} is not "
                                     "Elastic; the translations of a hinge are rigid ties")
                tied.add(dof)
        for d in (1, 2):
            if fixed[i][d - 1] and fixed[j][d - 1]:
                tied.add(d)
        if not {1, 2} <= tied:
            raise ValueError(f"{who}: nodes {i} and {j} are not tied in translation "
                             f"(equalDOF {i} {j} 1 2)")
        for d_name in dofs:
            if d_name not in ("P", "Vy", "Mz"):
                raise ValueError(f"{who}: direction {d_name} not supported")

        def member_end(n: int) -> bool:
            others = [e for e in attached[n] if e != z]
            return len(others) == 1 and others[0] in beams and not fixed[n][2]

        constrained = [c for (r, c, _, _) in ties if {r, c} == {i, j}]
        order = ([constrained[0], i if constrained[0] == j else j] if constrained
                 else [j, i])
        b = next((n for n in order if member_end(n)), None)
        if b is None:
            raise ValueError(f"{who}: neither node {i} nor {j} is a member end (one "
                             "elasticBeamColumn and this hinge, rotation free)")
        a = j if b == i else i
        if b in merged or b in hinge_of_end:
            raise ValueError(f"{who}: node {b} already ends another hinge")
        merged[b] = a
        mtag = mats[dofs.index("Mz")]
        hinge_of_end[b] = (z, _hinge_law(ops, mtag, mat_info.get(mtag), materials))
    for b, a in merged.items():
        if a in merged:
            raise ValueError(f"element {hinge_of_end[b][0]} (zeroLength): its joint {a} ends "
                             f"another hinge (element {hinge_of_end[a][0]}); hinges in series "
                             "are not supported")

    def joint(n: int) -> int:
        return merged.get(n, n)

    # ---------------------------------------------------------------- loads
    nodal, member = _loads(ops, load_patterns, 3)

    # ---------------------------------------------------------------- leaning column
    leaning_elems = [e for e in beams if int(ele_info.get(e, {}).get("release", 0)) == 3]
    frame_elems = [e for e in beams if e not in leaning_elems]
    leaning_nodes: set[int] = set()
    for e in leaning_elems:
        leaning_nodes |= set(ends[e])
    for n in leaning_nodes:
        if any(e not in leaning_elems for e in attached[n]):
            raise ValueError(f"node {n}: joins a pin-ended (leaning) element and other "
                             "elements; a leaning column stands apart, tied to the floors by "
                             "equalDOF 1")
    lean_pdelta = False
    for e in leaning_elems:
        i, j = ends[e]
        d = coord[j] - coord[i]
        kind = transf.get(str(ele_info[e].get("crdTransformation")), "?")
        if abs(d[0]) > 1e-9 * scale:
            raise ValueError(f"element {e} ({_BEAM}, -release 3): not vertical; pounding "
                             "reads pin-ended elements as a leaning column")
        if kind not in ("LinearCrdTransf2d", "PDeltaCrdTransf2d"):
            raise ValueError(f"element {e} ({_BEAM}): transformation {kind} not supported "
                             "(Linear or PDelta)")
        lean_pdelta |= kind == "PDeltaCrdTransf2d"
    if leaning_elems and lean_pdelta and any(
            transf.get(str(ele_info[e].get("crdTransformation"))) != "PDeltaCrdTransf2d"
            for e in leaning_elems):
        raise ValueError("leaning column: some of its elements have a PDelta transformation "
                         "and some do not")

    # ---------------------------------------------------------------- the frame's nodes
    keep = [t for t in tags if t not in merged and t not in leaning_nodes]
    index = {t: k for k, t in enumerate(keep)}
    nodes = np.array([coord[t] for t in keep])
    supports = np.array([fixed[t] for t in keep], dtype=bool)
    masses = np.array([mass[t] for t in keep])
    loads = np.zeros((len(keep), 3))
    for t, f in nodal.items():
        if t in leaning_nodes:
            continue
        loads[index[joint(t)]] += f
        if t in merged and f[2] != 0.0:
            raise ValueError(f"node {t}: a moment load on a hinge's member-end node; load "
                             f"the joint {merged[t]}")
    for b, a in merged.items():
        if fixed[b][2]:
            raise ValueError(f"node {b}: its rotation is fixed, so its hinge cannot turn")
        supports[index[a], :2] |= fixed[b][:2]
        if mass[b][2] != 0.0:
            raise ValueError(f"node {b}: a rotational mass on a hinge's member-end node; put "
                             f"it on the joint {a}")
        masses[index[a], :2] += mass[b][:2]

    # ---------------------------------------------------------------- elements, hinges
    elements = []
    EA, EI, w = [], [], []
    hinges: list[FrameHinge] = []
    hinge_tags: list[int] = []
    columns_transf: set[str] = set()
    beams_transf: set[str] = set()
    for k, e in enumerate(frame_elems):
        i, j = ends[e]
        d = coord[j] - coord[i]
        L = float(np.hypot(*d))
        kb = np.asarray(ops.basicStiffness(e), dtype=float)
        if kb.size != 9 or not math.isclose(kb[5], 0.5 * kb[4], rel_tol=1e-9) or not \
                math.isclose(kb[7], kb[5], rel_tol=1e-9) or kb[1] != 0.0 or kb[2] != 0.0:
            raise ValueError(f"element {e} ({_BEAM}): its basic stiffness {kb.tolist()} is "
                             "not that of an elastic Euler-Bernoulli beam-column")
        EA.append(kb[0] * L)
        EI.append(kb[4] * L / 4.0)
        elements.append((index[joint(i)], index[joint(j)]))
        for end, n in ((0, i), (1, j)):
            if n in hinge_of_end:
                z, law = hinge_of_end[n]
                hinges.append(FrameHinge(k, end, law))
                hinge_tags.append(z)
        kind = transf.get(str(ele_info.get(e, {}).get("crdTransformation")), "?")
        (columns_transf if abs(d[1]) > abs(d[0]) else beams_transf).add(kind)
        wy, wx = member.get(e, np.zeros(2))
        c, s = d / L
        # global load per length: wy (−s, c) + wx (c, s) must be (0, −w)
        gx, gy = -wy * s + wx * c, wy * c + wx * s
        if abs(gx) > 1e-9 * max(abs(wy), abs(wx)):
            raise ValueError(f"element {e} ({_BEAM}): its -beamUniform load ({wy:.6g}, "
                             f"{wx:.6g}) N/m is not vertical; pounding's member loads are "
                             "gravity loads")
        w.append(0.0 - gy)
    for e in member:
        if e not in frame_elems:
            raise ValueError(f"element {e}: an element load on an element that is not a "
                             "frame member")
    if not elements:
        raise ValueError("the OpenSees domain has no elasticBeamColumn frame members")
    unknown = (columns_transf | beams_transf) - {"LinearCrdTransf2d", "PDeltaCrdTransf2d"}
    if unknown:
        raise ValueError(f"geometric transformation {sorted(unknown)[0]}: not supported "
                         "(Linear or PDelta)")
    if len(columns_transf) > 1:
        raise ValueError("columns: some have a Linear and some a PDelta transformation; "
                         "pounding takes one for all")
    geometry = "p-delta" if columns_transf == {"PDeltaCrdTransf2d"} else "linear"

    # ---------------------------------------------------------------- rigid floors
    probe = Frame(nodes=nodes, elements=np.array(elements, dtype=np.int64), EA=EA, EI=EI,
                  supports=supports, masses=masses, diaphragm=False, name=name)
    levels = probe.levels
    level = probe.node_level
    parent: dict[int, int] = {}
    floor_ties = 0
    lean_at: dict[int, int] = {}  # leaning node -> floor level
    for k, (r, c, rd, cd) in enumerate(ties):
        if k in used_ties:
            continue
        if rd != (1,) or cd != (1,):
            raise ValueError(f"equalDOF {r} {c} (DOFs {list(cd)}): pounding reads equalDOF as "
                             "rigid-floor ties (DOF 1 at one level) and hinge ties (1 2)")
        if abs(coord[r][1] - coord[c][1]) > LEVEL_TOL:
            raise ValueError(f"equalDOF {r} {c} 1: the nodes stand at different levels "
                             f"({coord[r][1]:.6g} m, {coord[c][1]:.6g} m)")
        if r in leaning_nodes or c in leaning_nodes:
            lean, other = (r, c) if r in leaning_nodes else (c, r)
            if other in leaning_nodes or level[index[joint(other)]] < 0:
                raise ValueError(f"equalDOF {r} {c} 1: a leaning-column node must be tied to "
                                 "a floor of the frame")
            lean_at[lean] = int(level[index[joint(other)]])
            continue
        ra, ca = index[joint(r)], index[joint(c)]
        if level[ra] < 0 or supports[ra, 0] or supports[ca, 0]:
            raise ValueError(f"equalDOF {r} {c} 1: ties nodes that are not on a floor above "
                             "the base, or are fixed in x")
        parent[_find(parent, ra)] = _find(parent, ca)
        floor_ties += 1
    diaphragm = floor_ties > 0 or bool(lean_at)
    if diaphragm:
        for f, y in enumerate(levels):
            members = [n for n in range(len(keep)) if level[n] == f and not supports[n, 0]]
            roots = {_find(parent, n) for n in members}
            if len(roots) > 1:
                loose = [keep[n] for n in members if _find(parent, n) != _find(
                    parent, members[0])]
                raise ValueError(f"equalDOF: the floor at y = {y:.6g} m does not tie nodes "
                                 f"{loose} to node {keep[members[0]]} in x; pounding's rigid "
                                 "floors tie every node of every floor (tie all, or none)")

    # ---------------------------------------------------------------- leaning loads
    leaning = np.zeros(levels.size)
    base = probe.base
    for n in leaning_nodes:
        if np.any(mass[n] != 0.0):
            raise ValueError(f"node {n}: a mass on the leaning column; put it on the floor")
        f = nodal.get(n, np.zeros(3))
        if f[0] != 0.0 or f[2] != 0.0:
            raise ValueError(f"node {n}: a leaning-column load that is not vertical "
                             f"({f.tolist()})")
        if abs(coord[n][1] - base) <= LEVEL_TOL:
            if not (fixed[n][0] and fixed[n][1]):
                raise ValueError(f"node {n}: the leaning column's base must be fixed in x "
                                 "and y")
            continue
        if not fixed[n][2]:
            raise ValueError(f"node {n}: fix the leaning column's rotations (fix {n} 0 0 1); "
                             "they have no stiffness")
        if n not in lean_at:
            raise ValueError(f"node {n}: a leaning-column node not tied to a floor "
                             f"(equalDOF <floor node> {n} 1)")
        leaning[lean_at[n]] += -f[1]
    for e in leaning_elems:
        lo, hi = sorted(ends[e], key=lambda n: coord[n][1])
        f_lo = -1 if abs(coord[lo][1] - base) <= LEVEL_TOL else lean_at.get(lo, -2)
        if lean_at.get(hi, -3) != f_lo + 1:
            raise ValueError(f"element {e} (leaning column): must span one storey, from a "
                             "floor (or the base) to the next")
    if np.any(leaning < 0.0):
        raise ValueError("leaning column: an upward load")
    if not lean_pdelta:
        leaning[:] = 0.0

    frame = Frame(nodes=nodes, elements=np.array(elements, dtype=np.int64), EA=np.array(EA),
                  EI=np.array(EI), supports=supports, hinges=tuple(hinges), masses=masses,
                  nodal_loads=loads, member_loads=np.array(w), diaphragm=diaphragm,
                  leaning_loads=leaning, geometry=geometry, name=name)
    return ImportedFrame(frame, tuple(keep), tuple(frame_elems), tuple(hinge_tags))


def frame_from_opensees(ops_module: Any = None, *, name: str = "frame",
                        materials: Mapping[int, HingeLaw] | None = None,
                        load_patterns: Sequence[int] | None = None) -> Frame:
    """The planar frame of the current OpenSeesPy domain (:func:`read_opensees_frame`'s
    frame; see the module docstring for what is read and how).

    Examples
    --------
    ::

        import openseespy.opensees as ops
        ...  # build the frame: nodes, fix, mass, elasticBeamColumn, zeroLength hinges
        frame = frame_from_opensees(ops, name="SMRF")
    """
    return read_opensees_frame(ops_module, name=name, materials=materials,
                               load_patterns=load_patterns).frame
