"""Read the parts of a live OpenSeesPy domain that a frame import needs.

* :func:`model_json` — the domain as ``printModel('-JSON', '-file', …)`` prints it: element
  and material types, nodes, transformations, releases, material parameters (to 6
  significant digits only; ``setPrecision`` does not change it);
* :func:`hinge_law` — a uniaxial material as a pounding hinge law, its constants read exactly
  through OpenSees parameters on the zeroLength element's material (``parameter``,
  ``getParamValue``, then ``remove('parameter', …)``). Not by straining it with
  ``testUniaxialMaterial``/``setStrain``: in OpenSeesPy 3.7.1 that strains the material
  library's own object (no copy), whose state later ``element`` commands would copy;
* :func:`mp_ties` — the multi-point constraints (``equalDOF``) with their DOFs;
* :func:`pattern_loads` — nodal loads and uniform member loads of load patterns.

Used by :mod:`pounding.structure.frame_opensees`; the OpenSeesPy module is passed in.
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic, HingeLaw

__all__ = ["IMK_MATERIALS", "bilin_law", "hinge_law", "imk_law", "model_json", "mp_ties",
           "pattern_loads"]

IMK_MATERIALS: tuple[str, ...] = ("IMKBilin", "IMKPeakOriented")
"""OpenSees' modified Ibarra–Medina–Krawinkler materials read as
:mod:`pounding.hysteresis.imk` laws (OpenSees 3.7.1 prints an IMKBilin material's type as
IMKPeakOriented; the bilinear one has no ``Lamda_A``)."""

_IMK_SIDE = (("dp", "theta_p"), ("dpc", "theta_pc"), ("du", "theta_u"), ("Fy", "m_y"),
             ("FmaxFy", "mc_my"), ("FresFy", "kappa"))
"""OpenSees' IMK constants of one side → the law's (``_pos`` → as named, ``_neg`` → ``*_neg``)."""


def imk_law(info: dict[str, Any], who: str) -> HingeLaw:
    """An OpenSees ``IMKBilin`` / ``IMKPeakOriented`` material as its pounding law, from the
    model's printout (:func:`model_json`). No OpenSees parameter reads these materials'
    constants, so they carry the printout's precision: 6 significant digits, which is exact
    for constants given with 6 digits or fewer (``0.025``, ``3e5``), and rounds others at
    the 6th."""
    from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented

    def get(key: str) -> float:
        if key not in info:
            raise ValueError(f"{who}: the printout has no {key}; pounding reads IMKBilin and "
                             "IMKPeakOriented by the names OpenSees 3.7 prints")
        return float(info[key])

    kw: dict[str, float] = {"k0": get("Ke")}
    for theirs, ours in _IMK_SIDE:
        kw[ours] = get(f"{theirs}_pos")
        kw[f"{ours}_neg"] = get(f"{theirs}_neg")
    peak = "Lamda_A" in info
    for mode in ("S", "C", "K") + (("A",) if peak else ()):
        kw[f"lambda_{mode.lower()}"] = get(f"Lamda_{mode}")
        kw[f"c_{mode.lower()}"] = get(f"c_{mode}")
    kw["d_pos"], kw["d_neg"] = get("D_pos"), get("D_neg")
    for key in ("theta_u", "theta_u_neg"):
        if kw[key] >= 1e9:  # OpenSees' way of saying "no ultimate rotation"
            kw[key] = math.inf
    law = IMKPeakOriented(**kw) if peak else IMKBilinear(**kw)
    return law

def bilin_law(info: dict[str, Any], who: str) -> HingeLaw:
    """An OpenSees ``Bilin`` material (the older modified-IMK implementation, which OpenSees
    itself says to replace by ``IMKBilin``) as the bilinear IMK law, from the printout (6
    significant digits): ``Ke0``; each side's ``My``, the hardening ratio ``As = K_p/K_e``
    (so ``M_c/M_y = 1 + As K_e θ_p / M_y``), ``Thetap``, ``Thetapc``, ``Thetau`` and the
    residual ratio ``K``. Without cyclic deterioration (every ``Lamda`` 0) it moves as
    ``IMKBilin`` to rounding (checked along cyclic paths: 2e-16 of ``M_y``); with it, its
    deterioration rules differ from ``IMKBilin``'s (by 9 % of ``M_y`` on a cyclic path), so it
    is refused, as is its ``nFactor`` (an elastic stiffness split with the member)."""
    from pounding.hysteresis.imk import IMKBilinear

    def get(key: str) -> float:
        if key not in info:
            raise ValueError(f"{who}: the printout has no {key}; pounding reads Bilin by the "
                             "names OpenSees 3.7 prints")
        return float(info[key])

    lam = {k: get(k) for k in ("LamdaS", "LamdaK", "LamdaA", "LamdaD")}
    if any(lam.values()):
        given = ", ".join(f"{k} = {v:g}" for k, v in lam.items() if v)
        raise ValueError(f"{who}: cyclic deterioration ({given}) is not read: OpenSees "
                         "replaced Bilin by IMKBilin, whose rules pounding follows and whose "
                         "deterioration differs from Bilin's; build the hinge as IMKBilin, or "
                         "give its law with materials={tag: law}")
    if get("nFactor") != 0.0:
        raise ValueError(f"{who}: nFactor = {get('nFactor'):g} (the member's stiffness "
                         "amplified, Ibarra & Krawinkler 2005) is not read; give nFactor = 0 "
                         "and the spring's own stiffness")
    k0 = get("Ke0")
    kw: dict[str, float] = {"k0": k0}
    for side, suffix, sign in (("pos", "", 1.0), ("neg", "_neg", -1.0)):
        my = sign * get(f"My_{side}")
        theta_p = get(f"Thetap_{side}")
        kw["m_y" + suffix] = my
        kw["theta_p" + suffix] = theta_p
        kw["theta_pc" + suffix] = get(f"Thetapc_{side}")
        theta_u = get(f"Thetau_{side}")
        kw["theta_u" + suffix] = math.inf if theta_u >= 1e9 else theta_u
        kw["kappa" + suffix] = get("KPos" if side == "pos" else "KNeg")
        kw["mc_my" + suffix] = 1.0 + get("AsPos" if side == "pos" else "AsNeg") * k0 * theta_p / my
    return IMKBilinear(**kw)


UNIFORM_LOAD_CLASS = 3
"""OpenSees class tag of ``Beam2dUniformLoad`` (``-beamUniform``), whose data are (w_y, w_x)."""


def model_json(ops: Any) -> dict[str, Any]:
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
    return dict(model)


def _parameter(ops: Any, element: int, index: int, name: str) -> float:
    """The value of constant ``name`` of material number ``index`` (from 1) of ``element``,
    read through a parameter added and removed at once (``parameter``, ``getParamValue``,
    ``remove('parameter', …)``), exact and without touching the material's state."""
    tag = max([0, *(int(t) for t in ops.getParamTags())]) + 1
    ops.parameter(tag, "element", element, "material", str(index), name)
    try:
        return float(ops.getParamValue(tag))
    finally:
        ops.remove("parameter", tag)


def hinge_law(ops: Any, tag: int, info: dict[str, Any] | None,
              materials: Mapping[int, HingeLaw], element: int, index: int) -> HingeLaw:
    """The hinge law of uniaxial material ``tag``, the ``index``-th (from 1) material of
    zeroLength ``element``.

    ``materials[tag]`` when given; else ``ElasticPP`` (symmetric, ``eps0 = 0``) →
    :class:`~pounding.hysteresis.hinges.ElasticPlastic`, ``Steel01`` with no isotropic
    hardening (``a1 = a3 = 0``) → :class:`~pounding.hysteresis.hinges.BilinearHinge`, and
    ``IMKBilin`` / ``IMKPeakOriented`` → :class:`~pounding.hysteresis.imk.IMKBilinear` /
    :class:`~pounding.hysteresis.imk.IMKPeakOriented` (:func:`imk_law`: to the printout's 6
    digits). The first two's
    constants (``E``, ``Fy``, ``b``, ``a1``, ``a3``) are read exactly through OpenSees
    parameters on the element's material (:func:`_parameter`); the printout only names the
    type and, for ``ElasticPP``, gives ``epsyN`` and ``eps0``, which no parameter reads.

    Parameters
    ----------
    ops : module
        ``openseespy.opensees``.
    tag : int
        The material's tag.
    info : dict or None
        Its entry in :func:`model_json`'s ``uniaxialMaterials``.
    materials : mapping
        Laws given by the user for material tags (taken as they are).
    element, index : int
        A zeroLength element that uses the material, and its place in the element's list.
    """
    if tag in materials:
        return materials[tag]
    if info is None:
        raise ValueError(f"material {tag}: not in the model's printed materials")
    kind = str(info.get("type", "?"))
    who = f"material {tag} ({kind})"
    if kind in IMK_MATERIALS or kind == "Bilin":
        try:
            return imk_law(info, who) if kind != "Bilin" else bilin_law(info, who)
        except ValueError as exc:
            text = str(exc)
            raise ValueError(text if text.startswith(who) else f"{who}: {text}") from None
    if kind == "ElasticPPMaterial":
        if float(info.get("eps0", 0.0)) != 0.0:
            raise ValueError(f"{who}: eps0 = {info['eps0']} (an initial strain); pounding's "
                             "elastic-plastic hinge starts unstrained (eps0 = 0)")
        ep, en = float(info["epsyp"]), float(info["epsyn"])
        if not math.isclose(-en, ep, rel_tol=1e-5):
            raise ValueError(f"{who}: yield rotations epsyP = {ep:.6g}, epsyN = {en:.6g}; "
                             "pounding's hinges are symmetric (epsyN = -epsyP)")
        return ElasticPlastic(k0=_parameter(ops, element, index, "E"),
                              m_y=_parameter(ops, element, index, "Fy"))
    if kind == "Steel01":
        iso = [_parameter(ops, element, index, a) for a in ("a1", "a3")]
        if any(iso):
            raise ValueError(f"{who}: isotropic hardening a1 = {iso[0]:g}, a3 = {iso[1]:g}; "
                             "pounding's bilinear hinge has kinematic hardening only "
                             "(a1 = a3 = 0)")
        k0, m_y, b = (_parameter(ops, element, index, name) for name in ("E", "Fy", "b"))
        if b == 0.0:
            return ElasticPlastic(k0=k0, m_y=m_y)
        return BilinearHinge(k0=k0, m_y=m_y, hardening=b)
    raise ValueError(f"{who}: not supported as a hinge (pounding reads ElasticPP, Steel01; "
                     "give materials={" + str(tag) + ": <HingeLaw>} for another)")


def mp_ties(ops: Any) -> list[tuple[int, int, tuple[int, ...], tuple[int, ...]]]:
    """Every MP constraint as (retained, constrained, retained DOFs, constrained DOFs)."""
    out = []
    for r in sorted({int(t) for t in ops.getRetainedNodes()}):
        for c in sorted({int(t) for t in ops.getConstrainedNodes(r)}):
            out.append((r, c, tuple(int(d) for d in ops.getRetainedDOFs(r, c)),
                        tuple(int(d) for d in ops.getConstrainedDOFs(c, r))))
    return out


def pattern_loads(ops: Any, patterns: Sequence[int] | None, ndf: int
                  ) -> tuple[dict[int, NDArray[np.float64]], dict[int, NDArray[np.float64]]]:
    """Nodal loads {node: (F_x, F_y, M)} and uniform element loads {element: (w_y, w_x)}
    summed over the chosen load patterns."""
    have = [int(p) for p in ops.getPatterns()]
    chosen = have if patterns is None else [int(p) for p in patterns]
    for p in chosen:
        if p not in have:
            raise ValueError(f"load_patterns: pattern {p} is not in the domain (it has "
                             f"{have})")
    nodal: dict[int, NDArray[np.float64]] = {}
    member: dict[int, NDArray[np.float64]] = {}
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
            if c != UNIFORM_LOAD_CLASS:
                raise ValueError(f"load pattern {p}: element {t}: element load of class "
                                 f"{c} not supported (pounding reads -beamUniform loads over "
                                 "the whole member)")
        if edata.size != 2 * len(etags):
            raise ValueError(f"load pattern {p}: {edata.size} element load values for "
                             f"{len(etags)} uniform loads")
        for k, t in enumerate(etags):
            member[t] = member.get(t, np.zeros(2)) + edata[2 * k: 2 * k + 2]
    return nodal, member
