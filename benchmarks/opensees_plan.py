"""OpenSeesPy version of buildings in plan that pound at their corners (optional: needs
``openseespy``; issue 18, torsional pounding).

Builds the model of :class:`pounding.structure.plan.PlanBuilding` — rigid floors with three
DOFs each, lateral elements at plan positions — in OpenSees, independently of pounding's
engine, so that the two can be compared. Companion of :mod:`opensees_models` (its contact
materials, log file, step retry and impact count are reused).

Model (``-ndm 2 -ndf 3``: the plane is the plan, DOFs ``u_x``, ``u_y`` and the rotation ``θ``
about the vertical axis):

* **Placement.** Buildings stand in a row along x: building 0's plan ``x = 0`` edge at site
  ``X = 0``, building ``b + 1``'s at building b's ``X + width + gaps[b]``; each building's
  plan ``y = 0`` edge at site ``Y = site_y``.
* **Floors.** One node a floor at its centre of mass, with ``mass(m, m, I)`` (the
  building's ``masses`` and ``inertias``). Tags ``10000 (b + 1) + j`` (floor j = 1…n).
* **Storeys.** Each lateral element in each storey with nonzero stiffness is a
  ``zeroLength`` between two coincident nodes at the element's plan position: the lower
  one fixed (storey 1) or tied to the floor below, the upper one tied to the floor above,
  by ``rigidLink('beam', floor, node)`` — the constrained node moves with the rigid floor,
  ``u_x = u_xF − Δy θ_F``, ``u_y = u_yF + Δx θ_F``, ``θ = θ_F`` (``Δ`` from the floor's
  centre of mass), the kinematics of :meth:`PlanBuilding.point_weights`. The element's
  material is ``uniaxialMaterial('Elastic', tag, k, a1 k)``: ``-dir 1`` for an ``"x"``
  element, ``-dir 2`` for a ``"y"`` one, and for an inclined one ``-dir 1 -orient c s 0
  −s c 0`` (local x along its direction). Its deformation is then ``a_j · q_j −
  a_{j−1} · q_{j−1}``, the element's row in
  :func:`pounding.structure.plan.plan_stiffness_matrix`, so the assembled stiffness is
  ``K`` and the damping tangent ``η = a1 k`` assembles ``a1 K``.
* **Damping.** ``C = a0 M + a1 K`` with ``(a0, a1) = RayleighDamping.coefficients(M, K)``
  of each building's own damping model (only :class:`RayleighDamping` is accepted):
  ``a1 K`` element by element in the storey materials as above, ``a0 M`` by
  ``region(…, '-node', floors…, '-rayleigh', a0, 0, 0, 0)`` on the building's floor nodes
  (``m``, ``m`` and ``I`` alike). No ``betaK`` anywhere, so the contact elements take no
  Rayleigh damping (as in :mod:`opensees_models`).
* **Contacts.** Between neighbours b and b + 1, at every pair of floors at the same
  elevation (within 1e-6 m), one ``zeroLength`` along x (``-dir 1``) at each site y of
  :func:`pounding.structure.plan_row.facing_points` (the ends of the stretch over which the
  façades face each other): from a node on building b's façade ``x = width`` to a node on
  building b + 1's façade ``x = 0``, each tied to its floor by ``rigidLink('beam')``. The
  two nodes are coincident, both at the left façade's site X: only a point's y enters its
  x displacement (``u_x(p) = u_xF − (p_y − y_c) θ_F``), so putting the right node a gap to
  the left changes nothing along x, and ``ZeroLength::setDomain`` warns about nodes
  farther apart than 1e-6 of their coordinates (it expects coincident ones). The
  deformation is ``ε = u_x(right point) − u_x(left point)``; pounding is ``ε < −gap``, so
  :func:`opensees_models._contact_material` gets the gap negated:
  ``ViscoelasticGap(k, c, −gap)``, pounding's ``kelvin-voigt`` with ``tension=True`` (the
  dashpot may pull until the gap reopens). The force returned is ``−stress`` (compression
  positive).
* **Ground.** ``Path`` series of each component (``-dt record_dt``: linear between samples,
  zero after the record) and ``UniformExcitation`` along dof 1 (x) and, if given, dof 2
  (y): OpenSees applies ``−M R a_g`` with ``R`` the influence matrix of
  :meth:`PlanBuilding.influence_matrix` (no rotation).
* **Analysis.** ``constraints('Transformation')`` (the rigid links), ``numberer('RCM')``,
  ``system('BandSPD')``, Newmark γ = 1/2, β = 1/4 (average acceleration), Newton,
  ``NormDispIncr`` 1e-10 / 50 iterations, one ``analyze(1, dt)`` per step reading the floor
  displacements and the contact forces; a failed step is retried as
  :func:`opensees_models._retry` does.

Run as a script: the example torsional pair (:func:`torsional_pair`) under El Centro 1940
(Array #9, 180) along x, printing OpenSees' wall time and the peak contact forces; no y
component. ``bench_plan.py`` runs the pair against pounding, and under two components (the
bundled Düzce pair, Kocaeli 1999) as well.

Units: SI (m, kg, kg·m², N, s, rad).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import opensees_models as osm  # noqa: E402
from _environment import load  # noqa: E402
from pounding.structure.damping import RayleighDamping  # noqa: E402
from pounding.structure.plan import LateralElement, PlanBuilding  # noqa: E402
from pounding.structure.plan_row import facing_points  # noqa: E402

LAWS = ("kelvin-voigt",)
"""The contact laws offered, in pounding's names: Kelvin–Voigt as OpenSees'
``ViscoelasticGap``. (OpenSees' ``JankowskiImpact``, pounding's ``nonlinear-viscoelastic``,
is not offered here: its force in this model was not checked against the law.)"""

LEVEL_TOL = 1e-6
"""Floors whose elevations differ by at most this [m] are at the same level (in contact)."""

_FLOOR_BASE = 10000      # floor node of building b, floor j: 10000 (b + 1) + j
_NODE_START = 1_000_000  # storey and contact nodes from here on


# ----------------------------------------------------------------------- inputs
def _rayleigh(b: PlanBuilding, index: int) -> tuple[float, float]:
    if not isinstance(b.damping, RayleighDamping):
        raise ValueError(f"buildings[{index}].damping must be RayleighDamping for the OpenSees "
                         f"model (got {type(b.damping).__name__})")
    a0, a1 = b.damping.coefficients(b.mass_matrix(), b.stiffness_matrix())
    return float(a0), float(a1)


def _contact_params(contact: Mapping[str, Any]) -> dict[str, Any]:
    """Check the contact dict (see :func:`run_opensees_plan`); returns a copy."""
    if not isinstance(contact, Mapping):
        raise ValueError(f"contact must be a dict with 'law' and its constants (got {contact!r})")
    p = dict(contact)
    law = p.get("law")
    if law not in LAWS:
        raise ValueError(f"contact['law'] must be one of {LAWS} (got {law!r})")
    allowed = {"law", "k", "c", "e", "tension"}
    extra = sorted(set(p) - allowed)
    if extra:
        raise ValueError(f"contact[{extra[0]!r}] is not a field of the {law} law in OpenSees "
                         f"(fields: {', '.join(sorted(allowed))})")
    if p.get("tension", True) is not True:
        raise ValueError(f"contact['tension'] must be True: OpenSees' ViscoelasticGap lets "
                         f"the dashpot pull until the gap reopens (got {p['tension']!r})")
    if ("c" in p) == ("e" in p):
        raise ValueError("contact: give the kelvin-voigt dashpot as 'c' [N·s/m] or as "
                         "'e' (Anagnostopoulos), one of them")
    for name in ("k", "c") if "c" in p else ("k", "e"):
        v = p.get(name)
        ok = isinstance(v, (int, float, np.floating, np.integer)) and math.isfinite(v) and (
            v >= 0 if name == "c" else 0 < v < 1 if name == "e" else v > 0)
        if not ok:
            rule = {"c": ">= 0", "e": "in (0, 1)"}.get(name, "> 0")
            raise ValueError(f"contact[{name!r}] must be a finite number {rule} (got {v!r})")
    return p


def _check_inputs(buildings: Sequence[PlanBuilding], gaps: Sequence[float]) -> None:
    if not buildings:
        raise ValueError("buildings: give at least one PlanBuilding (got none)")
    for i, b in enumerate(buildings):
        if not isinstance(b, PlanBuilding):
            raise ValueError(f"buildings[{i}] must be a PlanBuilding (got {b!r})")
    if len(gaps) != len(buildings) - 1:
        raise ValueError(f"gaps must have one value per neighbouring pair, "
                         f"{len(buildings) - 1} (got {len(gaps)})")
    for i, g in enumerate(gaps):
        if not isinstance(g, (int, float, np.floating, np.integer)) or not math.isfinite(g) \
                or not g > 0:
            raise ValueError(f"gaps[{i}] must be a finite number > 0 [m] (got {g!r})")


def _record(name: str, accel: Any) -> np.ndarray:
    a = np.asarray(accel, dtype=float)
    if a.ndim != 1 or a.size < 2 or not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be a 1-D array of at least 2 finite accelerations "
                         f"[m/s²] (got shape {a.shape})")
    return a


def _positive(name: str, v: Any) -> float:
    if not isinstance(v, (int, float, np.floating, np.integer)) or not math.isfinite(v) \
            or not v > 0:
        raise ValueError(f"{name} must be a finite number > 0 [s] (got {v!r})")
    return float(v)


def site_origins(buildings: Sequence[PlanBuilding], gaps: Sequence[float]) -> np.ndarray:
    """Site ``(X, Y)`` [m] of each building's plan origin: in a row along x with the gaps
    between façades, offset along y by ``site_y``."""
    x = [0.0]
    for b, g in zip(buildings[:-1], gaps):
        x.append(x[-1] + b.width + float(g))
    return np.column_stack([x, [b.site_y for b in buildings]])


def plan_contacts(buildings: Sequence[PlanBuilding]) -> list[tuple[int, int, int, float]]:
    """The contacts ``(b, floor_left, floor_right, site_y)`` (floors 0-based): between
    neighbours b and b + 1, at floors of equal elevation (within :data:`LEVEL_TOL`), one at
    each point of :func:`facing_points`."""
    out = []
    for b, (left, right) in enumerate(zip(buildings[:-1], buildings[1:])):
        ys = facing_points(left, right)
        for i, zl in enumerate(left.floor_levels):
            for j, zr in enumerate(right.floor_levels):
                if abs(zl - zr) <= LEVEL_TOL:
                    out.extend((b, i, j, float(y)) for y in ys)
    return out


# ----------------------------------------------------------------------- the model
def _build(ops: Any, buildings: Sequence[PlanBuilding], gaps: Sequence[float],
           contact: dict[str, Any] | None) -> dict[str, Any]:
    """Build the model in a wiped domain (no loads, no analysis). Returns the floor node
    tags of each building and the contact element tags (none if ``contact`` is None)."""
    ops.wipe()
    ops.logFile(osm._LOG, "-noEcho")
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    origins = site_origins(buildings, gaps)
    next_node = _NODE_START
    mat = ele = 0

    def new_node(x: float, y: float) -> int:
        nonlocal next_node
        next_node += 1
        ops.node(next_node, float(x), float(y))
        return next_node

    floors: list[list[int]] = []
    rayleigh: list[tuple[float, float]] = []
    for b, (bld, (x0, y0)) in enumerate(zip(buildings, origins)):
        a0, a1 = _rayleigh(bld, b)
        rayleigh.append((a0, a1))
        tags = []
        for j in range(bld.n_floors):
            xc, yc = bld.mass_centres[j]
            tag = _FLOOR_BASE * (b + 1) + j + 1
            ops.node(tag, float(x0 + xc), float(y0 + yc))
            m = float(bld.masses[j])
            ops.mass(tag, m, m, float(bld.inertias[j]))
            tags.append(tag)
        floors.append(tags)
        for e in bld.elements:
            k = e.storey_stiffnesses(bld.n_floors)
            c, s = e.cosines
            if (c, s) == (1.0, 0.0):
                direction: tuple[Any, ...] = ("-dir", 1)
            elif (c, s) == (0.0, 1.0):
                direction = ("-dir", 2)
            else:
                direction = ("-dir", 1, "-orient", c, s, 0.0, -s, c, 0.0)
            ex, ey = x0 + e.x, y0 + e.y
            for j in range(bld.n_floors):
                if k[j] == 0.0:
                    continue
                lower, upper = new_node(ex, ey), new_node(ex, ey)
                if j == 0:
                    ops.fix(lower, 1, 1, 1)
                else:
                    ops.rigidLink("beam", tags[j - 1], lower)
                ops.rigidLink("beam", tags[j], upper)
                mat += 1
                ele += 1
                ops.uniaxialMaterial("Elastic", mat, float(k[j]), a1 * float(k[j]))
                ops.element("zeroLength", ele, lower, upper, "-mat", mat, *direction)
        if a0 > 0.0:
            ops.region(b + 1, "-node", *tags, "-rayleigh", a0, 0.0, 0.0, 0.0)

    contact_eles: list[int] = []
    laws: list[dict[str, float]] = []
    if contact is not None:
        for b, i, j, y in plan_contacts(buildings):
            left, right = buildings[b], buildings[b + 1]
            gap = float(gaps[b])
            m1, m2 = float(left.masses[i]), float(right.masses[j])
            m_eff = osm.m_effective(m1, m2)
            k = float(contact["k"])
            c = float(contact["c"]) if "c" in contact else osm.kv_dashpot(
                k, contact["e"], m1, m2)
            x_face = origins[b, 0] + left.width
            n_left, n_right = new_node(x_face, y), new_node(x_face, y)
            ops.rigidLink("beam", floors[b][i], n_left)
            ops.rigidLink("beam", floors[b + 1][j], n_right)
            mat += 1
            ele += 1
            osm._contact_material(ops, mat, "kelvin-voigt", gap, k=k, c=c, k_h=0.0, xi=0.0,
                                  m_eff=m_eff, n_exp=1.5)
            ops.element("zeroLength", ele, n_left, n_right, "-mat", mat, "-dir", 1)
            contact_eles.append(ele)
            laws.append({"k": k, "c": c, "m_eff": m_eff, "gap": gap})
    return {"floors": floors, "contact_eles": contact_eles, "laws": laws, "rayleigh": rayleigh}


def opensees_plan_periods(buildings: Sequence[PlanBuilding], gaps: Sequence[float]
                          ) -> np.ndarray:
    """Natural periods [s] of the buildings' OpenSees model (no contact elements), longest
    first: ``ops.eigen('-fullGenLapack', N)`` with all ``N = Σ 3 n_b`` modes."""
    _check_inputs(buildings, gaps)
    ops = osm._ops()
    _build(ops, buildings, gaps, None)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("FullGeneral")
    n = sum(b.n for b in buildings)
    lam = np.asarray(ops.eigen("-fullGenLapack", n), dtype=float)
    ops.wipe()
    return np.sort(2.0 * math.pi / np.sqrt(lam))[::-1]


def run_opensees_plan(buildings: Sequence[PlanBuilding], gaps: Sequence[float],
                      contact: Mapping[str, Any], accel_x: Any, accel_y: Any | None,
                      record_dt: float, dt: float, duration: float, *, tol: float = 1e-10,
                      max_iter: int = 50) -> dict[str, Any]:
    """Buildings in plan in a row along x, pounding at the ends of their facing façades, in
    OpenSees (the model of the module docstring).

    Parameters
    ----------
    buildings : sequence of PlanBuilding
        Left to right; each building's damping must be :class:`RayleighDamping`.
    gaps : sequence of float
        Clear distance [m] between building b's façade ``x = width`` and building b + 1's
        ``x = 0``, one per neighbouring pair (> 0).
    contact : dict
        The contact law of every contact, in pounding's names:
        ``{"law": "kelvin-voigt", "k": N/m, "c": N·s/m}`` or ``{"law": "kelvin-voigt",
        "k": N/m, "e": -}`` (``c = 2 ζ sqrt(k m_eff)``, ζ of Anagnostopoulos,
        ``m_eff`` from the two floor masses, as pounding's ``ContactSpec``); an optional
        ``"tension"`` must be True (``ViscoelasticGap`` pulls until the gap reopens, as
        pounding's ``kelvin-voigt`` with ``tension=True``).
    accel_x, accel_y : array_like or None
        Ground acceleration [m/s²] along site x and y, sampled at ``record_dt`` from t = 0
        (zero after its last sample); ``accel_y`` None: no y component.
    record_dt, dt, duration : float
        Record sampling step, analysis (= output) step and time analysed [s].
    tol, max_iter
        Newton's ``NormDispIncr`` tolerance [m] and iteration limit.

    Returns
    -------
    dict
        ``time`` (nt,) [s]; ``u`` (nt, N) the floor DOFs [m, m, rad] relative to the ground,
        building after building, each in :meth:`PlanBuilding.dof_labels` order
        (``F1x, F1y, F1θ, F2x, …``); ``dof_start`` (B + 1,) int, building b's columns
        ``u[:, dof_start[b]:dof_start[b + 1]]``; ``force`` (nt, n_contacts) contact forces
        [N], compression positive; ``contacts`` (n_contacts, 4) ``(b, floor_left,
        floor_right, site_y)`` of each (floors 0-based, site_y [m]); ``peak_force``
        (n_contacts,) [N]; ``origins`` (B, 2) site ``(X, Y)`` of each plan origin [m];
        ``n_impacts``, ``n_steps``, ``failed``, ``retried`` (ints), ``wall_analyze``
        (the analyze loop with its reads) and ``wall_total`` (build + analyze) [s];
        ``params``: ``law``, ``rayleigh`` the ``(a0 [1/s], a1 [s])`` of each building and
        ``contact_laws`` one dict a contact with its ``k`` [N/m], ``c`` [N·s/m], ``m_eff``
        (the two floor masses' ``m1 m2 / (m1 + m2)``) [kg] and ``gap`` [m].
    """
    _check_inputs(buildings, gaps)
    law = _contact_params(contact)
    ax = _record("accel_x", accel_x)
    ay = None if accel_y is None else _record("accel_y", accel_y)
    record_dt = _positive("record_dt", record_dt)
    dt = _positive("dt", dt)
    duration = _positive("duration", duration)
    n_steps = int(round(duration / dt))
    ops = osm._ops()

    t_build = time.perf_counter()
    model = _build(ops, buildings, gaps, law)
    for tag, (direction, a) in enumerate(((1, ax), (2, ay)), start=1):
        if a is None:
            continue
        ops.timeSeries("Path", tag, "-dt", record_dt, "-values", *map(float, a),
                       "-factor", 1.0)
        ops.pattern("UniformExcitation", tag, direction, "-accel", tag)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("BandSPD")
    ops.test("NormDispIncr", tol, max_iter, 0)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")

    floor_nodes = [t for tags in model["floors"] for t in tags]
    eles = model["contact_eles"]
    u = np.zeros((n_steps + 1, 3 * len(floor_nodes)))
    f = np.zeros((n_steps + 1, len(eles)))
    node_disp, ele_resp, analyze = ops.nodeDisp, ops.eleResponse, ops.analyze
    failed = retried = 0
    t0 = time.perf_counter()
    for s in range(1, n_steps + 1):
        if analyze(1, dt) != 0:
            retried += 1
            if not osm._retry(ops, dt):
                failed += 1
                break
        for j, nd in enumerate(floor_nodes):
            u[s, 3 * j: 3 * j + 3] = node_disp(nd)
        for j, el in enumerate(eles):
            f[s, j] = 0.0 - ele_resp(el, "basicForce")[0]  # 0.0 - : no -0.0
    wall = time.perf_counter() - t0
    wall_total = time.perf_counter() - t_build
    ops.wipe()
    contacts = plan_contacts(buildings)
    return {
        "time": np.arange(n_steps + 1) * dt,
        "u": u,
        "dof_start": np.cumsum([0] + [b.n for b in buildings]),
        "force": f,
        "contacts": np.array(contacts, dtype=float).reshape(-1, 4),
        "peak_force": f.max(axis=0) if eles else np.zeros(0),
        "origins": site_origins(buildings, gaps),
        "n_impacts": osm.count_impacts(f) if eles else 0,
        "n_steps": n_steps, "failed": failed, "retried": retried,
        "wall_analyze": wall, "wall_total": wall_total,
        "params": {"law": law["law"], "rayleigh": model["rayleigh"],
                   "contact_laws": model["laws"]},
    }


# ----------------------------------------------------------------------- the example
def torsional_pair() -> tuple[PlanBuilding, PlanBuilding, float]:
    """Two 3-storey buildings side by side along x, offset along y so that their façades face
    each other over 6 m of 12 m, and the right one twisting under x shaking. Returns
    ``(left, right, gap [m])``.

    * Left, 20 m × 12 m, at ``site_y = 0``: 2.5×10⁵ kg floors, x frames at y = 0 and 12 m,
      y frames at x = 0 and 20 m, symmetric (no eccentricity).
    * Right, 16 m × 12 m, at ``site_y = 6`` m: 2×10⁵ kg floors; its x frame at plan
      y = 12 m is four times as stiff as the one at y = 0 (site y = 6 m), a stiffness
      eccentricity ``e_y = +3.6`` m (30 % of the depth) that couples x and torsion: under x
      shaking its flexible side, plan y = 0, swings most, and the half of its west façade that
      faces the left building is that side.
    * Storey heights 3.5, 3.0, 3.0 m in both, so all three floors meet; the façades face
      each other over site y ∈ [6, 12] m: contacts at y = 6 m (the right building's corner,
      6 m from its centre of mass) and y = 12 m (the left building's corner, 6 m from its
      centre of mass). Gap 20 mm.
    * Rayleigh 5 % at modes 1 and 3 (the default). Periods: left 0.399 s (x and y alike),
      right 0.532 s (x–torsion) and 0.482 s (y); see ``python benchmarks/opensees_plan.py``.
    """
    heights = [3.5, 3.0, 3.0]
    left = PlanBuilding(masses=[2.5e5] * 3, heights=heights, width=20.0, depth=12.0,
                        name="left (symmetric)", site_y=0.0, elements=[
                            LateralElement(10.0, 0.0, "x", [1.8e8, 1.5e8, 1.05e8], "x south"),
                            LateralElement(10.0, 12.0, "x", [1.8e8, 1.5e8, 1.05e8], "x north"),
                            LateralElement(0.0, 6.0, "y", [1.8e8, 1.5e8, 1.05e8], "y west"),
                            LateralElement(20.0, 6.0, "y", [1.8e8, 1.5e8, 1.05e8], "y east")])
    right = PlanBuilding(masses=[2.0e5] * 3, heights=heights, width=16.0, depth=12.0,
                         name="right (eccentric)", site_y=6.0, elements=[
                             LateralElement(8.0, 0.0, "x", [0.4e8, 0.33e8, 0.23e8], "x south"),
                             LateralElement(8.0, 12.0, "x", [1.6e8, 1.3e8, 0.9e8], "x north"),
                             LateralElement(0.0, 6.0, "y", [1.0e8, 0.8e8, 0.6e8], "y west"),
                             LateralElement(16.0, 6.0, "y", [1.0e8, 0.8e8, 0.6e8], "y east")])
    return left, right, 0.02


EXAMPLE_CONTACT = {"law": "kelvin-voigt", "k": osm.K_KV_DEFAULT, "e": 0.65}
"""The example's contact: Kelvin–Voigt, k = 9.3×10⁸ N/m, e = 0.65 (Anagnostopoulos ζ,
``m_eff`` from the two floor masses), the dashpot pulling until the gap reopens."""


def main(argv: Sequence[str] | None = None) -> int:
    from pounding.ground_motion import el_centro

    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--dt", type=float, default=1e-3, help="analysis step [s] (default 1e-3)")
    p.add_argument("--duration", type=float, default=None,
                   help="time analysed [s] (default the whole record)")
    p.add_argument("--repeat", type=int, default=3,
                   help="timing repeats, the best kept (default 3)")
    a = p.parse_args(argv)
    if not (a.dt > 0 and math.isfinite(a.dt)):
        p.error(f"--dt must be a finite number > 0 [s] (got {a.dt!r})")
    if a.repeat < 1:
        p.error(f"--repeat must be >= 1 (got {a.repeat!r})")
    gm = el_centro()
    duration = (gm.accel.size - 1) * gm.dt if a.duration is None else a.duration
    if not (duration > 0 and math.isfinite(duration)):
        p.error(f"--duration must be a finite number > 0 [s] (got {a.duration!r})")
    left, right, gap = torsional_pair()
    print(f"record: {gm.name}, {gm.accel.size} samples at {gm.dt:g} s, along x; "
          f"y component: none (x only; bench_plan.py adds two components)")
    for b in (left, right):
        ecc = b.stiffness_eccentricity()
        print(f"{b.name}: {b.width:g} m x {b.depth:g} m at site y = {b.site_y:g} m, periods "
              f"{', '.join(f'{t:.3f}' for t in b.modes().periods)} s; stiffness eccentricity "
              f"(e_x, e_y) storey 1 = ({ecc[0, 0]:.2f}, {ecc[0, 1]:.2f}) m")
    print(f"gap {gap * 1e3:g} mm; contact {EXAMPLE_CONTACT['law']}, k = "
          f"{EXAMPLE_CONTACT['k']:.3g} N/m, e = {EXAMPLE_CONTACT['e']:g}; dt = {a.dt:g} s, "
          f"{duration:g} s analysed")
    print(f"openseespy {osm._ops().version()}; {load()}")
    runs = [run_opensees_plan([left, right], [gap], EXAMPLE_CONTACT, gm.accel, None, gm.dt,
                              a.dt, duration) for _ in range(a.repeat)]
    r = min(runs, key=lambda x: x["wall_analyze"])
    loops = sorted(x["wall_analyze"] for x in runs)
    totals = sorted(x["wall_total"] for x in runs)
    print(f"OpenSees: {r['n_steps']} steps; analyze loop (with the per-step reads) best "
          f"{loops[0]:.3f} s = {1e6 * loops[0] / r['n_steps']:.1f} µs/step, build + analyze "
          f"best {totals[0]:.3f} s; {a.repeat} run(s), loop {loops[0]:.3f}–{loops[-1]:.3f} s; "
          f"failed steps {r['failed']}, retried {r['retried']}; impacts {r['n_impacts']}")
    print("contact            corner of   peak force [kN]   impacts")
    for (b, i, j, y), peak, col in zip(r["contacts"], r["peak_force"], r["force"].T):
        corner = [bld.name.split()[0] for bld in (left, right)
                  if y in (bld.site_y, bld.site_y + bld.depth)]
        print(f"  floor {int(i) + 1}, y = {y:5.2f} m  {'/'.join(corner):9s}  "
              f"{peak / 1e3:15.1f}   {osm.count_impacts(col):7d}")
    s = r["dof_start"]
    for b, bld in enumerate((left, right)):
        ub = r["u"][:, s[b]:s[b + 1]]
        print(f"{bld.name}: peak roof u_x {np.abs(ub[:, -3]).max() * 1e3:.1f} mm, "
              f"u_y {np.abs(ub[:, -2]).max() * 1e3:.1f} mm, θ {np.abs(ub[:, -1]).max() * 1e3:.3f}"
              f" mrad")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
