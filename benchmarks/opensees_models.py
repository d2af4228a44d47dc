"""OpenSeesPy versions of the benchmark pounding models (optional: needs ``openseespy``).

Every function builds a fresh OpenSees domain, runs a transient analysis under a uniform
ground acceleration and returns plain numpy arrays, so the benchmark script can compare them
with :mod:`pounding` without OpenSees objects leaking out.

Models (1-D, ``-ndm 1 -ndf 1``; every node at x = 0, the elements are ``zeroLength``):

* SDOF pair (:func:`run_opensees_sdof_pair`): ground node 1 — floor node 2 (left building,
  mass m1) and ground node 3 — floor node 4 (right building, mass m2). Each storey is a
  ``zeroLength`` with ``uniaxialMaterial Elastic k eta`` where ``eta = c = 2 ζ m ω``: the
  material's stress is ``k ε + η ε̇`` and its damping tangent is ``η``, so the equation of
  motion is exactly ``m ü + c u̇ + k u = −m a_g + contact``.
* Shear pair (:func:`run_opensees_shear_pair`): two uniform n-storey chains, built by
  :func:`run_opensees_building_pair`, which takes any floor masses, storey stiffnesses,
  Rayleigh coefficients and floor-to-floor contacts. Storey springs are
  ``Elastic k_i, a1 k_i`` (the stiffness-proportional Rayleigh part, ``a1 K``, element by
  element) and the mass-proportional part ``a0 M`` comes from
  ``region(…, '-node', floors…, '-rayleigh', a0, 0, 0, 0)`` per building (it acts on the
  nodal masses only; the zeroLength elements do not take Rayleigh damping unless
  ``-doRayleigh`` is given). A ``betaK`` Rayleigh term is deliberately *not* used: it would
  also multiply the contact elements' tangent.

Contact: a ``zeroLength`` element from the left floor (node i) to the right floor (node j)
in direction 1. Its deformation is ``ε = u_j − u_i = u_right − u_left``, so pounding
(``u_left − u_right > gap``) is ``ε < −gap``: OpenSees' gap arguments are negative. The
materials (read in OpenSees ``SRC/material/uniaxial/ViscoelasticGap.cpp`` and
``JankowskiImpact.cpp``, P. J. Hughes 2019):

* ``uniaxialMaterial('ViscoelasticGap', tag, K, C, gap)`` with ``gap < 0``: for ``ε < gap``
  the stress is ``K (ε − gap) + C ε̇`` (negative = compression; the dashpot may pull, i.e.
  the stress may turn positive before the gap reopens), else 0. Tangent ``K``; the damping
  tangent is not returned (0), so Newton sees only ``K``.
* ``uniaxialMaterial('JankowskiImpact', tag, Kh, xi, mEff, gap, n=1.5)`` with ``gap < 0``
  (a non-negative gap aborts the process): with ``δ = gap − ε > 0``, stress
  ``−(Kh δⁿ + 2 ξ sqrt(Kh δ^(n−1) mEff) δ̇)`` while approaching (``ε̇ < 0``) and ``−Kh δⁿ``
  while separating.

The returned contact force is ``−stress`` (positive in compression), one column per contact.
Both materials print a line per impact, so the log is sent to a file with ``-noEcho``.

Links between the buildings (``run_opensees_building_pair(..., links=[(i, j, material)])``,
``bench_devices.py``): a ``zeroLength`` element from the left floor to the right one in
direction 1 with any uniaxial material, e.g. ``Viscous C alpha`` (stress ``C |ε̇|^alpha sgn ε̇``;
tangent 0, damping tangent ``alpha C max(|ε̇|, minVel)^(alpha−1)``) or
``ViscousDamper K Cd alpha`` (a spring in series with that dashpot, ``Ḟ = K (ε̇ − sgn F
(|F|/Cd)^(1/alpha))`` integrated inside each step by Dormand–Prince 5(4) at RelTol 1e-6
with ``ε̇`` linear over the step; tangent and damping tangent 0, so Newton iterates on the
rest of the model's tangent), read in OpenSees ``ViscousMaterial.cpp`` and
``ViscousDamper.cpp``. The link force returned is the material's stress.

Note on ``JankowskiImpact``: in the source read, its ``getTangent`` returns
``−(n Kh δ^(n−1) + …)``, i.e. the *negative* of ``d stress / d ε``. Newton still converges at
the steps used here because the Newmark effective stiffness is dominated by ``4 M / Δt²``
(≈ 10¹¹ N/m against ≈ 10⁸ N/m of contact tangent), but it converges linearly, not
quadratically. ``ViscoelasticGap`` returns ``K`` (correct) but no damping tangent.

Analysis: ``UniformExcitation`` of a ``Path`` series (linear between record samples, zero
after the record), Newmark γ = 1/2, β = 1/4 (average acceleration), Newton, test
``NormDispIncr`` 1e-10 m, 50 iterations, ``BandSPD`` system (the effective stiffness is
symmetric positive definite). One ``analyze(1, dt_out)`` per output step, reading
``nodeDisp`` and ``eleResponse(…, 'basicForce')`` after each (that Python loop is part of the
timed analysis). A step whose Newton iteration fails is retried as OpenSees users do:
``KrylovNewton``, ``NewtonLineSearch``, ``ModifiedNewton -initial``, then ten sub-steps
(:func:`_retry`); the count is returned as ``retried``.
"""

from __future__ import annotations

import math
import os
import tempfile
import time
from typing import Any, Sequence

import numpy as np

LAWS = ("kelvin-voigt", "jankowski")

K_KV_DEFAULT = 9.3e8
"""Kelvin–Voigt stiffness [N/m] (a linear stiffness of the order of Jankowski's concrete
Hertz contact at the few-mm penetrations of these models)."""

K_H_DEFAULT = 2.75e9
"""Jankowski's Hertz stiffness for concrete [N/m^1.5]."""


# ----------------------------------------------------------------------- formulas
def zeta_anagnostopoulos(e: float) -> float:
    """Kelvin–Voigt impact damping ratio: ζ = −ln e / sqrt(π² + ln² e) (Anagnostopoulos 1988)."""
    le = math.log(e)
    return -le / math.sqrt(math.pi ** 2 + le ** 2)


def zeta_jankowski(e: float) -> float:
    """Nonlinear viscoelastic damping ratio, Jankowski (2006):
    ζ = (9√5/2)(1 − e²) / (e (e (9π − 16) + 16))."""
    return 9.0 * math.sqrt(5.0) / 2.0 * (1.0 - e * e) / (e * (e * (9.0 * math.pi - 16.0) + 16.0))


def m_effective(m1: float, m2: float) -> float:
    return m1 * m2 / (m1 + m2)


def kv_dashpot(k: float, e: float, m1: float, m2: float) -> float:
    """c = 2 ζ sqrt(k m_eff) with ζ from Anagnostopoulos."""
    return 2.0 * zeta_anagnostopoulos(e) * math.sqrt(k * m_effective(m1, m2))


def rayleigh_coefficients(w1: float, w2: float, zeta: float) -> tuple[float, float]:
    """a0, a1 of C = a0 M + a1 K giving ratio ζ in the two modes w1, w2."""
    a0 = zeta * 2.0 * w1 * w2 / (w1 + w2)
    a1 = zeta * 2.0 / (w1 + w2)
    return a0, a1


def shear_matrices(masses: np.ndarray, stiffnesses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Diagonal M and tridiagonal K of a shear building (storey 1 joins floor 1 to ground)."""
    n = len(masses)
    K = np.zeros((n, n))
    for i in range(n):
        K[i, i] += stiffnesses[i]
        if i + 1 < n:
            K[i, i] += stiffnesses[i + 1]
            K[i, i + 1] = K[i + 1, i] = -stiffnesses[i + 1]
    return np.diag(np.asarray(masses, dtype=float)), K


def uniform_building(n: int, mass: float, period: float) -> tuple[np.ndarray, np.ndarray]:
    """Floor masses and storey stiffnesses of a uniform n-storey building with period T1."""
    # fixed-free uniform chain: ω1 = 2 sqrt(k/m) sin(π / (2 (2n + 1)))
    w1 = 2.0 * math.pi / period
    s = math.sin(math.pi / (2.0 * (2 * n + 1)))
    k = mass * (w1 / (2.0 * s)) ** 2
    return np.full(n, float(mass)), np.full(n, k)


def natural_frequencies(masses: np.ndarray, stiffnesses: np.ndarray) -> np.ndarray:
    M, K = shear_matrices(masses, stiffnesses)
    minv_half = np.diag(1.0 / np.sqrt(np.diag(M)))
    return np.sqrt(np.sort(np.linalg.eigvalsh(minv_half @ K @ minv_half)))


# ----------------------------------------------------------------------- OpenSees core
def _ops() -> Any:
    try:
        import openseespy.opensees as ops
    except ImportError as exc:  # pragma: no cover - depends on the machine
        raise ImportError(
            "openseespy is not importable: see benchmarks/README.md (pip install openseespy; "
            "on Python 3.11 it also needs the system BLAS: apt-get install libblas3 liblapack3)"
        ) from exc
    return ops


_LOG = os.path.join(tempfile.gettempdir(), "pounding-bench-opensees.log")


def _contact_material(ops: Any, tag: int, law: str, gap: float, *, k: float, c: float,
                      k_h: float, xi: float, m_eff: float, n_exp: float) -> None:
    if law == "kelvin-voigt":
        ops.uniaxialMaterial("ViscoelasticGap", tag, k, c, -abs(gap))
    elif law == "jankowski":
        ops.uniaxialMaterial("JankowskiImpact", tag, k_h, xi, m_eff, -abs(gap), n_exp)
    else:
        raise ValueError(f"law must be one of {LAWS} (got {law!r})")


def _analysis(ops: Any, dt_record: float, accel: np.ndarray, tol: float, max_iter: int,
              system: str, numberer: str) -> None:
    ops.timeSeries("Path", 1, "-dt", float(dt_record), "-values", *map(float, accel),
                   "-factor", 1.0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain")
    ops.numberer(numberer)
    ops.system(system)
    ops.test("NormDispIncr", tol, max_iter, 0)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")


def _run(ops: Any, n_steps: int, dt_out: float, left: list[int], right: list[int],
         contacts: list[int]) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, int]:
    """The timed loop: analyze(1, dt) per step, reading displacements and contact forces."""
    nl, nr, nc = len(left), len(right), len(contacts)
    ul = np.zeros((n_steps + 1, nl))
    ur = np.zeros((n_steps + 1, nr))
    f = np.zeros((n_steps + 1, nc))
    node_disp, ele_resp, analyze = ops.nodeDisp, ops.eleResponse, ops.analyze
    failed = retried = 0
    t0 = time.perf_counter()
    for s in range(1, n_steps + 1):
        if analyze(1, dt_out) != 0:
            retried += 1
            if not _retry(ops, dt_out):
                failed += 1
                break
        for j, nd in enumerate(left):
            ul[s, j] = node_disp(nd, 1)
        for j, nd in enumerate(right):
            ur[s, j] = node_disp(nd, 1)
        for j, el in enumerate(contacts):
            f[s, j] = 0.0 - ele_resp(el, "basicForce")[0]  # 0.0 - : no -0.0
    wall = time.perf_counter() - t0
    return ul, ur, f, wall, failed, retried


def _run_unread(ops: Any, n_steps: int, dt_out: float) -> tuple[float, int]:
    """The analysis alone, nothing read: one ``analyze(n_steps, dt)`` call (a lower bound
    of OpenSees' cost: no history, so no peaks or impacts). Returns the wall time and 1 if
    the call failed (OpenSees stops at the step that did not converge), else 0."""
    t0 = time.perf_counter()
    failed = int(ops.analyze(n_steps, dt_out) != 0)
    return time.perf_counter() - t0, failed


def _retry(ops: Any, dt: float) -> bool:
    """The usual OpenSees recovery for a step whose Newton iteration did not converge:
    other algorithms first, then ten sub-steps, then back to Newton. True if one worked."""
    ok = False
    for alg in (("KrylovNewton",), ("NewtonLineSearch",), ("ModifiedNewton", "-initial")):
        ops.algorithm(*alg)
        if ops.analyze(1, dt) == 0:
            ok = True
            break
    if not ok:
        ops.algorithm("Newton")
        ok = ops.analyze(10, dt / 10.0) == 0
    ops.algorithm("Newton")
    return ok


def count_impacts(force: np.ndarray) -> int:
    """Impacts in a force history: separate runs of nonzero force, summed over contacts."""
    f = np.atleast_2d(np.asarray(force).T).T if np.ndim(force) == 1 else np.asarray(force)
    on = f != 0.0
    starts = on[1:] & ~on[:-1]
    return int(starts.sum() + on[0].sum())


# ----------------------------------------------------------------------- models
def run_opensees_sdof_pair(law: str, accel_ms2: np.ndarray, dt_record: float,
                           dt_out: float = 1e-3, *, m1: float = 2e5, T1: float = 0.5,
                           m2: float = 3e5, T2: float = 1.0, zeta: float = 0.05,
                           gap: float = 0.02, e: float = 0.65, k: float = K_KV_DEFAULT,
                           k_h: float = K_H_DEFAULT, n_exp: float = 1.5,
                           duration: float | None = None, tol: float = 1e-10,
                           max_iter: int = 50, system: str = "BandSPD",
                           numberer: str = "Plain") -> dict[str, Any]:
    """Two SDOF oscillators with a contact between them, in OpenSees.

    Parameters
    ----------
    law : "kelvin-voigt" or "jankowski"
        ``ViscoelasticGap`` (K = k, C from e by Anagnostopoulos) or ``JankowskiImpact``
        (Kh = k_h, ξ from e by Jankowski 2006, mEff = m1 m2 / (m1 + m2), exponent n_exp).
    accel_ms2, dt_record
        Ground acceleration [m/s²] sampled at ``dt_record`` [s], first sample at t = 0.
    dt_out
        Analysis (= output) step [s].
    duration
        Time analysed [s]; default the record's, ``(npts − 1) dt_record``.

    Returns
    -------
    dict
        ``time`` (nt,), ``u1``, ``u2`` (nt,) relative displacements [m] of the left / right
        mass, ``force`` (nt,) contact force [N] (compression positive),
        ``peak_force``, ``n_impacts``, ``peak_u1``, ``peak_u2``, ``wall_analyze`` (the
        analyze loop only) and ``wall_total`` (build + analyze) [s], ``n_steps``,
        ``retried`` (steps whose Newton iteration failed and were redone by :func:`_retry`),
        ``failed`` (steps that could not be done at all; the run stops at the first),
        ``params``.
    """
    ops = _ops()
    accel = np.asarray(accel_ms2, dtype=float)
    t_end = (accel.size - 1) * dt_record if duration is None else float(duration)
    n_steps = int(round(t_end / dt_out))
    w1, w2 = 2.0 * math.pi / T1, 2.0 * math.pi / T2
    k1, k2 = m1 * w1 ** 2, m2 * w2 ** 2
    c1, c2 = 2.0 * zeta * m1 * w1, 2.0 * zeta * m2 * w2
    m_eff = m_effective(m1, m2)
    c_kv = kv_dashpot(k, e, m1, m2)
    xi = zeta_jankowski(e)

    t_build = time.perf_counter()
    ops.wipe()
    ops.logFile(_LOG, "-noEcho")
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for nd in (1, 2, 3, 4):
        ops.node(nd, 0.0)
    ops.fix(1, 1)
    ops.fix(3, 1)
    ops.mass(2, m1)
    ops.mass(4, m2)
    ops.uniaxialMaterial("Elastic", 1, k1, c1)
    ops.uniaxialMaterial("Elastic", 2, k2, c2)
    _contact_material(ops, 3, law, gap, k=k, c=c_kv, k_h=k_h, xi=xi, m_eff=m_eff, n_exp=n_exp)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 3, 4, "-mat", 2, "-dir", 1)
    ops.element("zeroLength", 3, 2, 4, "-mat", 3, "-dir", 1)  # i = left, j = right
    _analysis(ops, dt_record, accel, tol, max_iter, system, numberer)
    ul, ur, f, wall, failed, retried = _run(ops, n_steps, dt_out, [2], [4], [3])
    wall_total = time.perf_counter() - t_build
    ops.wipe()
    force = f[:, 0]
    return {
        "time": np.arange(n_steps + 1) * dt_out,
        "u1": ul[:, 0], "u2": ur[:, 0], "force": force,
        "peak_force": float(force.max()), "n_impacts": count_impacts(force),
        "peak_u1": float(np.abs(ul[:, 0]).max()), "peak_u2": float(np.abs(ur[:, 0]).max()),
        "wall_analyze": wall, "wall_total": wall_total, "n_steps": n_steps, "failed": failed,
        "retried": retried,
        "params": {"law": law, "k1": k1, "k2": k2, "c1": c1, "c2": c2, "k": k, "c_kv": c_kv,
                   "k_h": k_h, "xi": xi, "m_eff": m_eff, "gap": gap, "e": e, "n": n_exp},
    }


def run_opensees_shear_pair(accel_ms2: np.ndarray, dt_record: float, dt_out: float = 1e-3, *,
                            n_storeys: int = 10, mass: float = 2e5, T1: float = 1.0,
                            T2: float = 1.5, zeta: float = 0.05, gap: float = 0.02,
                            e: float = 0.65, k: float = K_KV_DEFAULT, k_h: float = K_H_DEFAULT,
                            law: str = "kelvin-voigt", n_exp: float = 1.5,
                            duration: float | None = None, tol: float = 1e-10,
                            max_iter: int = 50, system: str = "BandSPD",
                            numberer: str = "RCM") -> dict[str, Any]:
    """Two uniform n-storey shear buildings with a contact at every floor, in OpenSees.

    Both buildings have floor mass ``mass`` at every floor and a uniform storey stiffness
    chosen so that their fundamental periods are ``T1`` (left) and ``T2`` (right); damping
    is Rayleigh, ratio ``zeta`` in modes 1 and 2 of each building. The contact law of every
    floor uses the two floor masses (as :class:`pounding.model.ContactSpec` does).

    Returns
    -------
    dict
        ``time`` (nt,), ``u_left``, ``u_right`` (nt, n) floor displacements [m], ``force``
        (nt, n) contact forces [N], ``peak_force`` (n,), ``n_impacts`` (all contacts),
        ``peak_u_left``, ``peak_u_right`` (n,), ``wall_analyze``, ``wall_total``,
        ``n_steps``, ``retried``, ``failed``, ``params``.
    """
    n = int(n_storeys)
    bl = uniform_building(n, mass, T1)
    br = uniform_building(n, mass, T2)
    ray = []
    for m_, k_ in (bl, br):
        w = natural_frequencies(m_, k_)
        ray.append(rayleigh_coefficients(w[0], w[1] if n > 1 else w[0], zeta))
    if n == 1:  # one mode: C = 2 ζ m ω as pure stiffness-proportional damping
        ray = [(0.0, 2.0 * zeta / natural_frequencies(*b)[0]) for b in (bl, br)]
    return run_opensees_building_pair(
        accel_ms2, dt_record, dt_out, left=bl, right=br, rayleigh=ray,
        contacts=[(i, i) for i in range(n)], gap=gap, e=e, k=k, k_h=k_h, law=law,
        n_exp=n_exp, duration=duration, tol=tol, max_iter=max_iter, system=system,
        numberer=numberer)


def run_opensees_building_pair(accel_ms2: np.ndarray, dt_record: float, dt_out: float = 1e-3,
                               *, left: tuple[np.ndarray, np.ndarray],
                               right: tuple[np.ndarray, np.ndarray],
                               rayleigh: list[tuple[float, float]],
                               contacts: list[tuple[int, int]], gap: float = 0.02,
                               e: float = 0.65, k: float = K_KV_DEFAULT,
                               k_h: float = K_H_DEFAULT, law: str = "kelvin-voigt",
                               n_exp: float = 1.5, duration: float | None = None,
                               tol: float = 1e-10, max_iter: int = 50,
                               system: str = "BandSPD", numberer: str = "RCM",
                               reads: bool = True,
                               links: Sequence[tuple[int, int, Sequence[Any]]] = ()
                               ) -> dict[str, Any]:
    """Two shear buildings of any floor masses and storey stiffnesses, in OpenSees, with
    contacts between the floors named in ``contacts``.

    Parameters
    ----------
    left, right : (masses, stiffnesses)
        Floor masses [kg] and storey stiffnesses [N/m] of each building, ground upwards.
    rayleigh : [(a0, a1), (a0, a1)]
        ``C = a0 M + a1 K`` of each building (``a1 K`` in the storey materials, ``a0 M`` by
        ``region -rayleigh`` on its floor nodes).
    contacts : list of (i, j)
        A contact element from floor ``i`` of the left building to floor ``j`` of the
        right one (0 = first floor); its law uses those two floor masses (``mEff``, and
        the Kelvin–Voigt dashpot).
    reads : bool
        False: the analysis alone, one ``analyze(n_steps, dt_out)`` call reading nothing
        (:func:`_run_unread`); the result then has only the wall times, ``n_steps``,
        ``failed`` and ``params`` (histories, peaks and impacts are None).
    links : list of (i, j, material)
        Links between the buildings (dampers acting at all times): a ``zeroLength``
        element from floor ``i`` of the left building to floor ``j`` of the right one,
        direction 1, with ``uniaxialMaterial(*material)`` less its tag, e.g.
        ``("Viscous", C, alpha)``, ``("ViscousDamper", K, Cd, alpha)`` or
        ``("Maxwell", K, C, alpha, 1.0)``. Its deformation is ``u_right − u_left`` (as
        pounding's :class:`pounding.devices.Link`) and the elements take no Rayleigh
        damping (no ``-doRayleigh``). ``contacts`` may then be empty (no contact element).

    Returns
    -------
    dict
        As :func:`run_opensees_shear_pair` (``force`` and ``peak_force`` one column per
        contact), and with links ``link_force`` (nt, n_links): each link's material stress,
        the force ``F`` resisting ``d = u_right − u_left`` (floor j receives ``−F``), read
        every step with the contact forces; ``peak_link_force`` its largest ``|F|``.
    """
    ops = _ops()
    bl = tuple(np.asarray(a, dtype=float) for a in left)
    br = tuple(np.asarray(a, dtype=float) for a in right)
    nl, nr = len(bl[0]), len(br[0])
    accel = np.asarray(accel_ms2, dtype=float)
    t_end = (accel.size - 1) * dt_record if duration is None else float(duration)
    n_steps = int(round(t_end / dt_out))
    ray = [tuple(map(float, r)) for r in rayleigh]
    pairs = [(int(i), int(j)) for i, j in contacts]
    laws = [(m_effective(bl[0][i], br[0][j]), kv_dashpot(k, e, bl[0][i], br[0][j]))
            for i, j in pairs]
    xi = zeta_jankowski(e)

    t_build = time.perf_counter()
    ops.wipe()
    ops.logFile(_LOG, "-noEcho")
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    left_nodes = [1000 + i for i in range(1, nl + 1)]
    right_nodes = [2000 + i for i in range(1, nr + 1)]
    mat = ele = 0
    for base, (m_, k_), (a0, a1) in ((1000, bl, ray[0]), (2000, br, ray[1])):
        n = len(m_)
        ops.node(base, 0.0)
        ops.fix(base, 1)
        for i in range(1, n + 1):
            ops.node(base + i, 0.0)
            ops.mass(base + i, float(m_[i - 1]))
            mat += 1
            ele += 1
            ops.uniaxialMaterial("Elastic", mat, float(k_[i - 1]), a1 * float(k_[i - 1]))
            ops.element("zeroLength", ele, base + i - 1, base + i, "-mat", mat, "-dir", 1)
        if a0 > 0.0:
            ops.region(base // 1000, "-node", *range(base + 1, base + n + 1),
                       "-rayleigh", a0, 0.0, 0.0, 0.0)
    contact_eles = []
    for (i, j), (m_eff, c_kv) in zip(pairs, laws):
        mat += 1
        ele += 1
        _contact_material(ops, mat, law, gap, k=k, c=c_kv, k_h=k_h, xi=xi, m_eff=m_eff,
                          n_exp=n_exp)
        ops.element("zeroLength", ele, left_nodes[i], right_nodes[j], "-mat", mat, "-dir", 1)
        contact_eles.append(ele)
    link_eles = []
    for i, j, material in links:
        mat += 1
        ele += 1
        ops.uniaxialMaterial(str(material[0]), mat, *map(float, material[1:]))
        ops.element("zeroLength", ele, left_nodes[int(i)], right_nodes[int(j)], "-mat", mat,
                    "-dir", 1)
        link_eles.append(ele)
    _analysis(ops, dt_record, accel, tol, max_iter, system, numberer)
    params = {"law": law, "left": bl, "right": br, "rayleigh": ray, "k": k,
              "c_kv": laws[0][1] if laws else None, "k_h": k_h, "xi": xi,
              "m_eff": laws[0][0] if laws else None, "gap": gap, "e": e,
              "contacts": pairs, "contact_laws": laws,
              "links": [(int(i), int(j), tuple(m)) for i, j, m in links]}
    if not reads:
        wall, failed = _run_unread(ops, n_steps, dt_out)
        wall_total = time.perf_counter() - t_build
        ops.wipe()
        return {"time": None, "u_left": None, "u_right": None, "force": None,
                "peak_force": None, "n_impacts": None, "peak_u_left": None,
                "peak_u_right": None, "wall_analyze": wall, "wall_total": wall_total,
                "n_steps": n_steps, "failed": failed, "retried": 0, "params": params}
    # the links' forces are read in the same loop as the contacts' (as −stress: negated
    # back below)
    ul, ur, f, wall, failed, retried = _run(ops, n_steps, dt_out, left_nodes, right_nodes,
                                            contact_eles + link_eles)
    wall_total = time.perf_counter() - t_build
    ops.wipe()
    nc = len(contact_eles)
    f, f_link = f[:, :nc], -f[:, nc:]
    out = {
        "time": np.arange(n_steps + 1) * dt_out,
        "u_left": ul, "u_right": ur, "force": f,
        "peak_force": f.max(axis=0) if nc else np.zeros(0), "n_impacts": count_impacts(f),
        "peak_u_left": np.abs(ul).max(axis=0), "peak_u_right": np.abs(ur).max(axis=0),
        "wall_analyze": wall, "wall_total": wall_total, "n_steps": n_steps, "failed": failed,
        "retried": retried, "params": params,
    }
    if link_eles:
        out.update(link_force=f_link, peak_link_force=np.abs(f_link).max(axis=0))
    return out
