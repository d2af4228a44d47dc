"""Exact propagation of buildings tied by linear Maxwell links while every gap is open.

A linear Maxwell link (:data:`pounding.devices.laws.MAXWELL` with α = 1: a spring ``k`` in
series with a dashpot ``c``) has an internal variable, its spring's deformation ``z`` [m]:
``F = k z``, ``ż = ḋ − (k/c) z`` with ``d = u_hi − u_lo``; floor ``hi`` receives ``−F``,
floor ``lo`` ``+F``. It is linear, so the buildings it ties are, with every gap open, a
linear first-order system in the state extended by the links' ``z``::

    x = [u, u̇, z],   ẋ = A x + B a_g(t),
    A = [[0, I, 0], [−M⁻¹K, −M⁻¹C, −M⁻¹ L K_m], [0, Lᵀ, −K_m C_m⁻¹]],   B = [0, −R, 0]

(``L`` (N, m): +1 at each link's ``hi`` floor, −1 at its ``lo``, so that ``d = Lᵀ u``;
``K_m``, ``C_m`` the links' springs and dashpots, diagonal). Over a step ``h`` on which the
ground is linear the solution is exact, ``x(h) = Φ x(0) + Γ0 a_g(0) + Γ1 a_g(h)``, from one
matrix exponential of the augmented system (Van Loan 1978, IEEE TAC 23(3):395–404), as for
the buildings alone (:mod:`pounding.integrate.propagator`). The energies of the step are
exact quadratic forms in ``[x(0), a_g(0), a_g(h)]`` (Van Loan's integral): the input work
``−∫ u̇ᵀ M R a_g dt`` and the work the links' dashpots dissipate, ``∫ Σ F²/c dt = ∫ zᵀ K_m²
C_m⁻¹ z dt`` (plus ``∫ u̇ᵀ C_links u̇ dt`` of the links folded into C,
:func:`pounding.integrate.kernel_model.fold_linear_links`). With the kinetic energy, the
strain energy ``½ uᵀ K u + ½ Σ k z²`` and the buildings' viscous work inferred as the rest,
the balance closes exactly.

This module holds the operators, the kernel's exact step of such a structure
(:func:`compute_free_step_maxwell`, read by :func:`pounding.integrate.exact_maxwell.
maxwell_block_step`) and a plain stepper over a record (:func:`free_record`), written from
the operators alone, which checks them.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.integrate.propagator import (
    FreeStep,
    Propagator,
    _columns,
    _remembered,
    _van_loan_integral,
    compute_free_step,
    independent_blocks,
    state_matrix,
)

FloatArray = NDArray[np.float64]


class MaxwellLinks(NamedTuple):
    """Linear Maxwell links: link ``l`` joins DOF ``lo[l]`` to ``hi[l]`` (both floors, ≥ 0)
    with its spring ``k[l]`` [N/m] in series with its dashpot ``c[l]`` [N·s/m]."""

    lo: NDArray[np.int64]
    hi: NDArray[np.int64]
    k: FloatArray
    c: FloatArray

    @property
    def n_links(self) -> int:
        """How many links."""
        return int(self.lo.size)

    def incidence(self, n: int) -> FloatArray:
        """``L`` (N, m): ``d = Lᵀ u`` is every link's deformation; the links' forces on the
        floors are ``−L F``."""
        inc = np.zeros((n, self.n_links))
        cols = np.arange(self.n_links)
        inc[self.hi, cols] += 1.0
        inc[self.lo, cols] -= 1.0
        return inc


def linear_maxwell_rows(code: NDArray[np.int64], params: FloatArray) -> NDArray[np.bool_]:
    """True for every element row that is a linear Maxwell link (code
    :data:`~pounding.devices.laws.MAXWELL`, α = ``params[:, 2]`` = 1)."""
    from pounding.devices.laws import MAXWELL

    code = np.asarray(code)
    params = np.asarray(params, dtype=float)
    if code.size == 0 or params.ndim != 2 or params.shape[1] < 3:
        return np.zeros(code.size, dtype=bool)
    return (code == MAXWELL) & (params[:, 2] == 1.0)


def maxwell_links(lo: NDArray[np.int64], hi: NDArray[np.int64], code: NDArray[np.int64],
                  params: FloatArray) -> MaxwellLinks:
    """The linear Maxwell links among element rows (:func:`linear_maxwell_rows`), in row
    order: ``k = params[:, 0]``, ``c = params[:, 1]``.

    Raises
    ------
    ValueError
        A linear Maxwell row to the ground (``lo < 0``): a link joins two floors.
    """
    sel = linear_maxwell_rows(code, params)
    lo_s = np.asarray(lo, dtype=np.int64)[sel]
    if np.any(lo_s < 0):
        raise ValueError("Maxwell link to the ground: a link joins two floors")
    par = np.asarray(params, dtype=float)[sel]
    return MaxwellLinks(lo_s, np.asarray(hi, dtype=np.int64)[sel], par[:, 0].copy(),
                        par[:, 1].copy())


def extended_state_matrix(M: FloatArray, C: FloatArray, K: FloatArray,
                          links: MaxwellLinks) -> FloatArray:
    """``A`` (2N + m square) of the state ``[u, u̇, z]`` (module docstring)."""
    n = M.shape[0]
    m = links.n_links
    inc = links.incidence(n)
    a = np.zeros((2 * n + m, 2 * n + m))
    a[: 2 * n, : 2 * n] = state_matrix(M, C, K)
    a[n : 2 * n, 2 * n :] = -np.linalg.solve(M, inc * links.k)
    a[2 * n :, n : 2 * n] = inc.T
    a[2 * n :, 2 * n :] = np.diag(-links.k / links.c)
    return a


def _augmented(M: FloatArray, C: FloatArray, K: FloatArray, r: FloatArray,
               links: MaxwellLinks, h: float) -> tuple[FloatArray, FloatArray]:
    """``F`` of ``ẏ = F y`` for ``y = [x, a_g, ȧ_g]`` (x the extended state) and ``T`` with
    ``y0 = T [x0, a0, a1]`` (as :func:`pounding.integrate.propagator._augmented`)."""
    n = M.shape[0]
    rm = _columns(r)
    g = rm.shape[1]
    s = 2 * n + links.n_links
    k = s + 2 * g
    f = np.zeros((k, k))
    f[:s, :s] = extended_state_matrix(M, C, K, links)
    f[n : 2 * n, s : s + g] = -rm
    t = np.eye(k)
    for q in range(g):
        f[s + q, s + g + q] = 1.0
        t[s + g + q, s + q] = -1.0 / h
        t[s + g + q, s + g + q] = 1.0 / h
    return f, t


def compute_extended_propagator(M: FloatArray, C: FloatArray, K: FloatArray, r: FloatArray,
                                links: MaxwellLinks, h: float) -> Propagator:
    """``x(h) = Φ x(0) + Γ0 a_g(0) + Γ1 a_g(h)`` of the extended state ``[u, u̇, z]`` over a
    step ``h`` [s] on which the ground is linear: Φ (2N + m square), Γ0 and Γ1 (2N + m, G)."""
    from scipy.linalg import expm

    f, _ = _augmented(M, C, K, r, links, h)
    s = 2 * M.shape[0] + links.n_links
    g = (f.shape[0] - s) // 2
    e = expm(f * h)
    e12 = e[:s, s : s + g]
    e13 = e[:s, s + g :]
    return Propagator(np.ascontiguousarray(e[:s, :s]), np.ascontiguousarray(e12 - e13 / h),
                      np.ascontiguousarray(e13 / h))


def extended_step_forms(M: FloatArray, C: FloatArray, K: FloatArray, r: FloatArray,
                        links: MaxwellLinks, h: float, c_links: FloatArray | None = None
                        ) -> tuple[FloatArray, FloatArray]:
    """The input work and the links' dissipated work over one step ``h`` [s] as symmetric
    quadratic forms in ``[x0, a0, a1]`` (x0 the extended state, a0 and a1 the G ground
    components at the step's ends): ``(Q_in, Q_links)`` with

    * ``Q_in``: ``−∫ u̇ᵀ M R a_g dt``;
    * ``Q_links``: ``∫ (zᵀ K_m² C_m⁻¹ z + u̇ᵀ C_links u̇) dt`` — the Maxwell dashpots'
      ``F²/c`` and those of the links folded into C (``c_links``, None: none).

    Each ``y0ᵀ (∫₀ʰ e^{Fᵀs} W e^{Fs} ds) y0`` with ``y0 = T [x0, a0, a1]`` (Van Loan)."""
    n = M.shape[0]
    mr = M @ _columns(r)
    g = mr.shape[1]
    s = 2 * n + links.n_links
    f, t = _augmented(M, C, K, r, links, h)
    w_in = np.zeros_like(f)
    w_in[n : 2 * n, s : s + g] = -0.5 * mr
    w_in[s : s + g, n : 2 * n] = -0.5 * mr.T
    w_links = np.zeros_like(f)
    w_links[2 * n : s, 2 * n : s] = np.diag(links.k * links.k / links.c)
    if c_links is not None:
        w_links[n : 2 * n, n : 2 * n] = 0.5 * (c_links + c_links.T)
    q_in, q_links = (t.T @ _van_loan_integral(f, w, h) @ t for w in (w_in, w_links))
    return q_in, q_links


def extended_blocks(M: FloatArray, C: FloatArray, K: FloatArray,
                    links: MaxwellLinks) -> NDArray[np.int64]:
    """Boundaries ``[0, …, N]`` of the independent blocks of consecutive floors once the
    Maxwell links couple the floors they join
    (:func:`pounding.integrate.propagator.independent_blocks`); link ``l`` belongs to the
    block of its floors."""
    n = M.shape[0]
    tie = np.zeros((n, n))
    tie[links.lo, links.hi] = 1.0
    return independent_blocks(M, C, K, tie)


class FreeRecord(NamedTuple):
    """The histories of :func:`free_record` at the grid points (nt rows)."""

    displacement: FloatArray  #: floors' displacements relative to the ground [m] (nt, N)
    velocity: FloatArray  #: their rates [m/s] (nt, N)
    acceleration: FloatArray  #: absolute accelerations [m/s²] (nt, N)
    spring: FloatArray  #: the Maxwell links' spring deformations z [m] (nt, m)
    link_force: FloatArray  #: the Maxwell links' forces k z [N] (nt, m)
    #: cumulative energies [J] (nt, 5): input, kinetic, strain (storeys and the links'
    #: springs), the buildings' viscous work, the links' dissipated work
    energy: FloatArray


def free_record(M: FloatArray, C: FloatArray, K: FloatArray, r: FloatArray,
                links: MaxwellLinks, ag: FloatArray, h: float,
                c_links: FloatArray | None = None) -> FreeRecord:
    """Step the linear structure with its Maxwell links from rest over the ground
    accelerations ``ag`` (nt, G) [m/s²] at grid points ``h`` [s] apart (linear between
    them), every gap open, with the extended propagator and energy forms; ``C``, ``K``
    include the links folded into them, whose dashpots alone are ``c_links``.

    Slow (dense, in Python): the exact answer the kernel's exact steps are to give for such
    a model, and its check."""
    ag = _columns(ag)
    n = M.shape[0]
    m = links.n_links
    s = 2 * n + m
    nt = ag.shape[0]
    prop = compute_extended_propagator(M, C, K, r, links, h)
    q_in, q_links = extended_step_forms(M, C, K, r, links, h, c_links)
    inc = links.incidence(n)
    m_inv = 1.0 / np.diag(M)
    xs = np.zeros((nt, s))
    e = np.zeros((nt, 5))
    x = np.zeros(s)
    for j in range(nt - 1):
        y = np.concatenate([x, ag[j], ag[j + 1]])
        x = prop.phi @ x + prop.gamma0 @ ag[j] + prop.gamma1 @ ag[j + 1]
        xs[j + 1] = x
        e[j + 1, 0] = e[j, 0] + y @ q_in @ y
        e[j + 1, 4] = e[j, 4] + y @ q_links @ y
    u, v, z = xs[:, :n], xs[:, n : 2 * n], xs[:, 2 * n :]
    force = z * links.k
    e[:, 1] = 0.5 * np.einsum("ti,ij,tj->t", v, M, v)
    e[:, 2] = 0.5 * np.einsum("ti,ij,tj->t", u, K, u) + 0.5 * (force * z).sum(axis=1)
    e[:, 3] = e[:, 0] - e[:, 1] - e[:, 2] - e[:, 4]
    # the absolute acceleration ü + R a_g = −M⁻¹ (K u + C u̇ + L F)
    acc = -(u @ K.T + v @ C.T + force @ inc.T) * m_inv
    return FreeRecord(u, v, acc, z, force, e)


def compute_free_step_maxwell(M: FloatArray, C: FloatArray, K: FloatArray, r: FloatArray,
                              h: float, c_links: FloatArray | None, links: MaxwellLinks,
                              link_rows: NDArray[np.int64], z_state: NDArray[np.int64],
                              n_state: int) -> FreeStep:
    """The :class:`~pounding.integrate.propagator.FreeStep` of a structure with linear
    Maxwell links for a grid step ``h`` [s], one ground component: the blocks the links tie
    (:func:`extended_blocks`); a block without one as :func:`~pounding.integrate.
    propagator.compute_free_step` makes it; a block with ``m_b`` of them has the local state
    ``[u_b, u̇_b, z_b]`` (``s_b = 2 n_b + m_b``) and ``2 s_b + 4`` numbers a column: Φ's
    column, the input form's two linear terms, then the links' dissipation form
    (:func:`extended_step_forms`: the Maxwell dashpots' and those folded into C) and its two
    linear terms; its ``a a`` terms in ``dev_aa``. The operator's rows are the kernel's state
    ``[u, u̇, z]`` (``n_state`` entries): ``z_state[l]`` the index there of link l's z,
    ``link_rows[l]`` its element row (``FreeStep.maxwell``)."""
    n = M.shape[0]
    rm = _columns(r)
    if rm.shape[1] != 1:
        raise ValueError("compute_free_step_maxwell: one ground component")
    blk = extended_blocks(M, C, K, links)
    nblk = blk.size - 1
    gamma0 = np.zeros((n_state, 1))
    gamma1 = np.zeros((n_state, 1))
    aa = np.zeros((3, 1, 1))
    dev_aa = np.zeros((3, 1, 1))
    rows = np.zeros(nblk, dtype=np.int64)
    mx = np.zeros((nblk, 1 + max(links.n_links, 1)), dtype=np.int64)
    parts = []
    for b in range(nblk):
        p, q = int(blk[b]), int(blk[b + 1])
        nb = q - p
        sl = slice(p, q)
        mb, cb, kb, rb = M[sl, sl], C[sl, sl], K[sl, sl], rm[sl]
        cl = None if c_links is None or not np.any(c_links[sl, sl]) else c_links[sl, sl]
        own = np.flatnonzero((links.lo >= p) & (links.lo < q))
        if own.size == 0:
            sub = compute_free_step(mb, cb, kb, rb, h, cl)
            if sub.blk.tolist() != [0, nb]:
                raise AssertionError("compute_free_step_maxwell: a block split further")
            glob = np.r_[p:q, n + p : n + q]
            gamma0[glob] = sub.gamma0
            gamma1[glob] = sub.gamma1
            aa += sub.aa
            dev_aa += sub.dev_aa
            rows[b] = sub.rows[0]
            parts.append((glob, sub.ops[:, : sub.rows[0]]))
            continue
        local = MaxwellLinks(links.lo[own] - p, links.hi[own] - p, links.k[own], links.c[own])
        sb = 2 * nb + own.size
        glob = np.r_[p:q, n + p : n + q, z_state[own]]
        prop = compute_extended_propagator(mb, cb, kb, rb, local, h)
        q_in, q_links = extended_step_forms(mb, cb, kb, rb, local, h, cl)
        x_, a0_, a1_ = slice(0, sb), sb, sb + 1
        op = np.zeros((sb, 2 * sb + 4))
        op[:, :sb] = prop.phi.T
        # the cross terms appear twice in yᵀQy: 2 Q[x, a] is the linear coefficient
        op[:, sb] = 2.0 * q_in[x_, a0_]
        op[:, sb + 1] = 2.0 * q_in[x_, a1_]
        op[:, sb + 2 : 2 * sb + 2] = q_links[x_, x_]
        op[:, 2 * sb + 2] = 2.0 * q_links[x_, a0_]
        op[:, 2 * sb + 3] = 2.0 * q_links[x_, a1_]
        aa[:, 0, 0] += (q_in[a0_, a0_], 2.0 * q_in[a0_, a1_], q_in[a1_, a1_])
        dev_aa[:, 0, 0] += (q_links[a0_, a0_], 2.0 * q_links[a0_, a1_], q_links[a1_, a1_])
        gamma0[glob] = prop.gamma0
        gamma1[glob] = prop.gamma1
        rows[b] = op.shape[1]
        mx[b, 0] = own.size
        mx[b, 1 : 1 + own.size] = link_rows[own]
        parts.append((glob, op))
    width = max(op.shape[1] for _, op in parts)
    ops = np.zeros((n_state, width))
    for glob, op in parts:
        ops[glob, : op.shape[1]] = op
    no_modes = np.zeros(blk.size - 1, dtype=np.int64)  # (no block stepped modally)
    fs = FreeStep(blk, ops, gamma0, gamma1, aa, rows, dev_aa, no_modes, np.zeros((1, 1)), mx)
    for a in fs:
        a.setflags(write=False)
    return fs


_FREE_CACHE: dict[bytes, FreeStep] = {}


def free_step_maxwell(M: FloatArray, C: FloatArray, K: FloatArray, r: FloatArray, h: float,
                      c_links: FloatArray | None, links: MaxwellLinks,
                      link_rows: NDArray[np.int64], z_state: NDArray[np.int64],
                      n_state: int) -> FreeStep:
    """:func:`compute_free_step_maxwell`, remembered by the numbers it is made of (as
    :func:`pounding.integrate.propagator.free_step`): a model built afresh from the same
    numbers reuses its matrix exponentials."""
    extra = np.concatenate([
        np.ravel(c_links) if c_links is not None else np.zeros(0), links.lo, links.hi,
        links.k, links.c, link_rows, z_state, [n_state, float(c_links is None)]]).astype(float)
    return _remembered(_FREE_CACHE,
                       lambda M_, C_, K_, r_, h_: compute_free_step_maxwell(
                           M_, C_, K_, r_, h_, c_links, links, link_rows, z_state, n_state),
                       M, C, K, r, h, extra=extra)
