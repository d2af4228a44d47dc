"""OpenSeesPy versions of the yielding benchmark models (optional: needs ``openseespy``).

Companion of :mod:`opensees_models` (same 1-D ``zeroLength`` modelling, same analysis, same
per-step reads, same retry of non-converged steps; its helpers are reused), for SDOF
oscillators whose storey yields. Every function builds a fresh OpenSees domain, runs it and
returns plain numpy arrays.

Model of one yielding SDOF (building ``i`` = 0, 1): ground node ``10 i + 1`` (fixed), floor
node ``10 i + 2`` with mass ``m``, and two ``zeroLength`` elements in parallel between them:

* element ``10 i + 1``: the hysteretic storey, one of

  - ``uniaxialMaterial('Steel01', tag, Fy, k, b)`` — bilinear with kinematic hardening;
    the isotropic-hardening parameters a1…a4 are left at their defaults (a1 = a3 = 0: none).
    ``b = 0`` (elastic–perfectly plastic) is accepted by Steel01 and used as is;
  - ``uniaxialMaterial('BoucWen', tag, alpha, ko, n, gamma, beta, Ao, deltaA, deltaNu,
    deltaEta)`` with ``Ao = 1`` and no degradation (``deltaA = deltaNu = deltaEta = 0``).
    Read in OpenSees ``SRC/material/uniaxial/BoucWenMaterial.cpp`` (T. Haukaas): the stress is
    ``alpha ko ε + (1 − alpha) ko z`` with a hysteretic *displacement* ``z`` [m] and
    ``dz/dε = Ao − |z|^n (gamma + beta sgn(Δε z))``, solved per step by backward Euler in
    the strain increment (Newton on ``z``, tolerance 1e-8, 20 iterations, its defaults).
    pounding's Bouc–Wen is ``V = α k d + (1 − α) F_y z̄`` with a dimensionless ``z̄`` and
    ``d_y dz̄/dd = 1 − |z̄|^n (γ + β sgn(ḋ z̄))``, ``d_y = F_y / k``. With ``z = d_y z̄`` the
    two are the same equation when ``ko = k``, ``Ao = 1``, ``alpha = α``, ``n = n`` and
    **``gamma_OS = γ / d_yⁿ``, ``beta_OS = β / d_yⁿ``** — OpenSees' ``beta`` multiplies the
    sign term as ours does, so the names correspond one to one; only the scale differs
    (:func:`boucwen_opensees_params`).

* element ``10 i + 2``: the viscous dashpot, ``uniaxialMaterial('Elastic', tag, 0.0, c)``
  (stress ``η ε̇``, damping tangent ``η``), ``c = 2 ζ m ω`` from the initial stiffness, as
  pounding's ``ShearBuilding.sdof`` does. A separate element keeps the storey's
  ``basicForce`` the hysteretic shear alone.

Contact (the pair): ``ViscoelasticGap`` between the two floor nodes, exactly as
:func:`opensees_models.run_opensees_sdof_pair` (element 100, deformation ``u_right − u_left``,
negative gap).

Analysis: as :mod:`opensees_models` — ``Path`` series, ``UniformExcitation``, Newmark
(½, ¼), Newton, ``NormDispIncr`` 1e-10 m / 50 iterations, ``BandSPD``, one
``analyze(1, dt)`` per output step. The per-step reads are the floor displacement, the
storey shear (``eleResponse(storey, 'basicForce')``) and, for the pair, the contact force.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

import opensees_models as osm

G = 9.81


@dataclass(frozen=True)
class YieldingSdof:
    """One yielding oscillator: mass [kg], period [s] (initial stiffness), damping ratio,
    yield force [N], and the storey law: ``"bilinear"`` (``b``) or ``"bouc-wen"``
    (``alpha``, ``n``, ``beta``, ``gamma``)."""

    mass: float
    period: float
    zeta: float
    fy: float
    law: str = "bilinear"
    b: float = 0.05
    alpha: float = 0.05
    n: float = 2.0
    beta: float = 0.5
    gamma: float = 0.5
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def k(self) -> float:
        return self.mass * (2.0 * math.pi / self.period) ** 2

    @property
    def c(self) -> float:
        return 2.0 * self.zeta * self.mass * 2.0 * math.pi / self.period

    @property
    def dy(self) -> float:
        return self.fy / self.k


def boucwen_opensees_params(s: YieldingSdof) -> tuple[float, ...]:
    """``(alpha, ko, n, gamma, beta, Ao, deltaA, deltaNu, deltaEta)`` of OpenSees' BoucWen
    equivalent to pounding's ``BoucWen(yield_force=fy, alpha, n, beta, gamma)``."""
    scale = s.dy ** s.n
    return (s.alpha, s.k, s.n, s.gamma / scale, s.beta / scale, 1.0, 0.0, 0.0, 0.0)


def _storey_material(ops: Any, tag: int, s: YieldingSdof) -> None:
    if s.law == "bilinear":
        ops.uniaxialMaterial("Steel01", tag, s.fy, s.k, s.b)
    elif s.law == "bouc-wen":
        ops.uniaxialMaterial("BoucWen", tag, *boucwen_opensees_params(s))
    else:
        raise ValueError(f"law must be 'bilinear' or 'bouc-wen' (got {s.law!r})")


# ----------------------------------------------------------------------- post-processing
def recoverable_energy(s: YieldingSdof, d: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Energy the storey gives back when unloaded to zero shear, pounding's definition
    (:func:`pounding.hysteresis.dispatch.storey_recoverable`): ``V²/(2k)`` for the bilinear
    law; ``½ α k d² + ½ (1 − α) F_y d_y z̄²`` for Bouc–Wen, with ``z̄`` recovered from the
    shear, ``z̄ = (V − α k d) / ((1 − α) F_y)``."""
    d, v = np.asarray(d, float), np.asarray(v, float)
    if s.law == "bilinear":
        return 0.5 * v * v / s.k
    zbar = (v - s.alpha * s.k * d) / ((1.0 - s.alpha) * s.fy)
    return 0.5 * s.alpha * s.k * d * d + 0.5 * (1.0 - s.alpha) * s.fy * s.dy * zbar * zbar


def hysteretic_energy(s: YieldingSdof, d: np.ndarray, v: np.ndarray) -> float:
    """Work ``∫V dd`` (trapezoid over the output steps) minus the recoverable energy at the
    end [J]."""
    d, v = np.asarray(d, float), np.asarray(v, float)
    work = float(np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(d)))
    return work - float(recoverable_energy(s, d[-1:], v[-1:])[0])


def residual_drift(s: YieldingSdof, d_end: float, v_end: float) -> float:
    """``d_end − V_end / k_unload`` (pounding's ``Result.residual_drift``): ``k`` for the
    bilinear law, ``k [α + (1 − α)(1 − |z̄|ⁿ (γ − β))]`` for Bouc–Wen."""
    if s.law == "bilinear":
        return d_end - v_end / s.k
    zbar = (v_end - s.alpha * s.k * d_end) / ((1.0 - s.alpha) * s.fy)
    ku = s.k * (s.alpha + (1.0 - s.alpha) * (1.0 - abs(zbar) ** s.n * (s.gamma - s.beta)))
    return d_end - v_end / ku


# ----------------------------------------------------------------------- the timed loop
def _run(ops: Any, n_steps: int, dt_out: float, floors: list[int], storeys: list[int],
         contacts: list[int]) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, int, int]:
    """analyze(1, dt) per step, reading floor displacements, storey shears, contact forces."""
    nb, nc = len(floors), len(contacts)
    u = np.zeros((n_steps + 1, nb))
    v = np.zeros((n_steps + 1, nb))
    f = np.zeros((n_steps + 1, nc))
    node_disp, ele_resp, analyze = ops.nodeDisp, ops.eleResponse, ops.analyze
    failed = retried = 0
    t0 = time.perf_counter()
    for s in range(1, n_steps + 1):
        if analyze(1, dt_out) != 0:
            retried += 1
            if not osm._retry(ops, dt_out):
                failed += 1
                break
        for j in range(nb):
            u[s, j] = node_disp(floors[j], 1)
            v[s, j] = ele_resp(storeys[j], "basicForce")[0]
        for j, el in enumerate(contacts):
            f[s, j] = 0.0 - ele_resp(el, "basicForce")[0]  # compression positive
    wall = time.perf_counter() - t0
    return u, v, f, wall, failed, retried


def run_opensees_yielding(sdofs: list[YieldingSdof], accel_ms2: np.ndarray, dt_record: float,
                          dt_out: float = 1e-3, *, gap: float | None = None, e: float = 0.65,
                          k_contact: float = osm.K_KV_DEFAULT, duration: float | None = None,
                          tol: float = 1e-10, max_iter: int = 50,
                          system: str = "BandSPD") -> dict[str, Any]:
    """One yielding SDOF, or two with a Kelvin–Voigt (``ViscoelasticGap``) contact between
    them (``gap`` given; left = ``sdofs[0]``), under a ground acceleration.

    Returns
    -------
    dict
        ``time`` (nt,), ``u`` (nt, nb) floor displacements = storey drifts [m], ``shear``
        (nt, nb) storey shear [N], ``force`` (nt,) contact force [N] (pair only, compression
        positive), per building ``peak_u``, ``residual_drift``, ``hysteretic_energy`` (nb,),
        ``peak_force``, ``n_impacts`` (pair), ``wall_analyze``, ``wall_total``, ``n_steps``,
        ``retried``, ``failed``.
    """
    ops = osm._ops()
    accel = np.asarray(accel_ms2, dtype=float)
    t_end = (accel.size - 1) * dt_record if duration is None else float(duration)
    n_steps = int(round(t_end / dt_out))
    pair = gap is not None
    if pair and len(sdofs) != 2:
        raise ValueError("a contact needs exactly two oscillators")

    t_build = time.perf_counter()
    ops.wipe()
    ops.logFile(osm._LOG, "-noEcho")
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    floors, storeys = [], []
    for i, s in enumerate(sdofs):
        g, fl = 10 * i + 1, 10 * i + 2
        ops.node(g, 0.0)
        ops.node(fl, 0.0)
        ops.fix(g, 1)
        ops.mass(fl, s.mass)
        _storey_material(ops, 10 * i + 1, s)
        ops.uniaxialMaterial("Elastic", 10 * i + 2, 0.0, s.c)
        ops.element("zeroLength", 10 * i + 1, g, fl, "-mat", 10 * i + 1, "-dir", 1)
        ops.element("zeroLength", 10 * i + 2, g, fl, "-mat", 10 * i + 2, "-dir", 1)
        floors.append(fl)
        storeys.append(10 * i + 1)
    contacts = []
    if pair:
        c_kv = osm.kv_dashpot(k_contact, e, sdofs[0].mass, sdofs[1].mass)
        ops.uniaxialMaterial("ViscoelasticGap", 100, k_contact, c_kv, -abs(gap))
        ops.element("zeroLength", 100, floors[0], floors[1], "-mat", 100, "-dir", 1)
        contacts.append(100)
    osm._analysis(ops, dt_record, accel, tol, max_iter, system, "Plain")
    u, v, f, wall, failed, retried = _run(ops, n_steps, dt_out, floors, storeys, contacts)
    wall_total = time.perf_counter() - t_build
    ops.wipe()
    out: dict[str, Any] = {
        "time": np.arange(n_steps + 1) * dt_out, "u": u, "shear": v,
        "peak_u": np.abs(u).max(axis=0),
        "residual_drift": np.array([residual_drift(s, u[-1, j], v[-1, j])
                                    for j, s in enumerate(sdofs)]),
        "hysteretic_energy": np.array([hysteretic_energy(s, u[:, j], v[:, j])
                                       for j, s in enumerate(sdofs)]),
        "wall_analyze": wall, "wall_total": wall_total, "n_steps": n_steps,
        "failed": failed, "retried": retried,
    }
    if pair:
        force = f[:, 0]
        out.update(force=force, peak_force=float(force.max()),
                   n_impacts=osm.count_impacts(force))
    return out


def drive_material(s: YieldingSdof, drift: np.ndarray) -> np.ndarray:
    """OpenSees' storey material alone along a drift path (``testUniaxialMaterial`` /
    ``setStrain`` / ``getStress``, one call per sample): the shear [N] at every sample."""
    ops = osm._ops()
    ops.wipe()
    ops.logFile(osm._LOG, "-noEcho")
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    _storey_material(ops, 1, s)
    ops.testUniaxialMaterial(1)
    out = np.zeros(len(drift))
    for i, d in enumerate(drift):
        if i:
            ops.setStrain(float(d))
        out[i] = ops.getStress()
    ops.wipe()
    return out
