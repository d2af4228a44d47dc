"""Exact discrete-time propagation of the linear structure between impacts.

While every gap is open the buildings are linear: ``ẋ = A x + B a_g(t)`` with
``x = [u, u̇]``, ``A = [[0, I], [−M⁻¹K, −M⁻¹C]]`` and ``B = [0, −R]``, R the (N, G)
influence matrix of the G ground components ``a_g`` (an (N,) influence vector is G = 1).
The ground acceleration of a record is linear between its samples, so over one step ``h``
on which ``a_g`` is linear the solution is exactly

    x(h) = Φ x(0) + Γ0 a_g(0) + Γ1 a_g(h)

with ``Φ = e^{Ah}`` and Γ0, Γ1 (2N × G) from one matrix exponential of the augmented system
``d/dt [x, a, ȧ] = [[A, B, 0], [0, 0, I], [0, 0, 0]] [x, a, ȧ]`` (Van Loan 1978, IEEE TAC
23(3):395–404; the same idea as Nigam & Jennings' exact piecewise-linear method for SDOF,
BSSA 59(2):909–922, 1969). The time-history kernel uses it for every step without
contact; it is exact to round-off whatever the step.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from typing import Any, NamedTuple, TypeVar

import numpy as np
from numpy.typing import NDArray


class Propagator(NamedTuple):
    """``x(h) = phi @ x(0) + gamma0 @ a_g(0) + gamma1 @ a_g(h)`` for one step ``h`` [s]
    (``gamma0``, ``gamma1``: (2N,) for an influence vector, (2N, G) for a matrix)."""

    phi: NDArray[np.float64]
    gamma0: NDArray[np.float64]
    gamma1: NDArray[np.float64]


def state_matrix(M: NDArray[np.float64], C: NDArray[np.float64],
                 K: NDArray[np.float64]) -> NDArray[np.float64]:
    """First-order system matrix ``A = [[0, I], [−M⁻¹K, −M⁻¹C]]`` (2N × 2N)."""
    n = M.shape[0]
    minv = np.linalg.inv(M)
    a = np.zeros((2 * n, 2 * n))
    a[:n, n:] = np.eye(n)
    a[n:, :n] = -minv @ K
    a[n:, n:] = -minv @ C
    return a


_CACHE: dict[bytes, Propagator] = {}
_CACHE_SIZE = 64


def propagator(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
               r: NDArray[np.float64], h: float) -> Propagator:
    """Exact propagator of the linear structure over a step ``h`` [s] with linear ``a_g``
    (see :func:`compute_propagator`), remembered per structure and step: a sweep over gaps,
    restitution or records reuses one matrix exponential. The arrays are read-only."""
    return _remembered(_CACHE, compute_propagator, M, C, K, r, h)


Arrays = TypeVar("Arrays", bound=tuple[NDArray[Any], ...])
"""A named tuple of arrays a structure and a step make (:func:`_remembered`)."""


def _remembered(cache: dict[bytes, Arrays],
                compute: Callable[[NDArray[np.float64], NDArray[np.float64],
                                   NDArray[np.float64], NDArray[np.float64], float], Arrays],
                M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                r: NDArray[np.float64], h: float,
                extra: NDArray[np.float64] | None = None) -> Arrays:
    """``compute(M, C, K, r, h)`` looked up in ``cache`` by the arrays' bytes (and those of
    ``extra``, another array the computation reads) and ``h``; the result's arrays are made
    read-only; the oldest entry goes beyond ``_CACHE_SIZE``. Computed with one BLAS
    thread."""
    arrays = (M, C, K, r) if extra is None else (M, C, K, r, extra)
    key = hashlib.sha1(b"".join(np.ascontiguousarray(a, dtype=float).tobytes()
                                for a in arrays)
                       + repr((M.shape, np.shape(r), float(h), extra is None)).encode()
                       ).digest()
    hit = cache.get(key)
    if hit is None:
        from threadpoolctl import threadpool_limits

        # one BLAS thread: the products are small, and a second OpenBLAS thread waiting for
        # a core on a busy machine made each small expm 2–8 ms instead of 0.03–0.2 ms
        # (2026-11-28, load 4); results the same
        with threadpool_limits(limits=1, user_api="blas"):
            hit = compute(M, C, K, r, h)
        for a in hit:
            a.setflags(write=False)
        if len(cache) >= _CACHE_SIZE:
            cache.pop(next(iter(cache)))
        cache[key] = hit
    return hit


def compute_propagator(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                       r: NDArray[np.float64], h: float) -> Propagator:
    """Exact propagator of the linear structure over a step ``h`` [s] with linear ``a_g``.

    Parameters
    ----------
    M, C, K : ndarray (N, N)
        Mass [kg], damping [N·s/m], stiffness [N/m].
    r : ndarray (N,) or (N, G)
        Influence vector, or influence matrix of G ground components.
    h : float
        Step [s].
    """
    f, _ = _augmented(M, C, K, r, h)
    n = M.shape[0]
    g = f.shape[0] // 2 - n
    from scipy.linalg import expm

    e = expm(f * h)
    phi = np.ascontiguousarray(e[: 2 * n, : 2 * n])
    e12 = e[: 2 * n, 2 * n : 2 * n + g]
    e13 = e[: 2 * n, 2 * n + g :]
    g0, g1 = e12 - e13 / h, e13 / h
    if np.ndim(r) == 1:
        g0, g1 = g0[:, 0], g1[:, 0]
    return Propagator(phi, np.ascontiguousarray(g0), np.ascontiguousarray(g1))


# ----------------------------------------------------------------------------- exact steps
class FreeStep(NamedTuple):
    """Everything the kernel needs for one exact grid step with every gap open.

    The structure splits into independent blocks of consecutive floors (no stiffness or
    damping couples two blocks: typically one block per building). Block ``b`` holds floors
    ``blk[b] … blk[b+1]−1``; its local state is ``z_b = [u_b, u̇_b]`` (length ``2 n_b``).
    ``ops[glob_b, :2n_b+2G]`` is that block's operator, stored column by column: column ``j``
    (``2 n_b + 2 G`` numbers) multiplies ``z_b[j]`` and holds

    * rows ``0 … 2n_b−1``: column ``j`` of the block of Φ;
    * rows ``2n_b + 2g, 2n_b + 2g + 1``: the linear input-energy terms ``w_in,0,g``,
      ``w_in,1,g`` of ground component g.

    Over the step, with ``z = z_b(0)`` and the ground components ``a0``, ``a1`` (G,) at its
    ends,

        z_b(h)   = Φ_b z + γ0_b a0 + γ1_b a1
        E_input  = Σ_b Σ_g (w_in,0,g · z) a0_g + (w_in,1,g · z) a1_g
                   + Σ_gq aa[0,g,q] a0_g a0_q + aa[1,g,q] a0_g a1_q + aa[2,g,q] a1_g a1_q

    exactly (see :func:`step_energy_forms`); for G = 1 the last line is
    ``aa · (a0², a0 a1, a1²)``. The viscous work of the step is then exactly
    the input work less the change of kinetic and strain energy (nothing else stores or
    dissipates energy while every gap is open), which the kernel uses instead of the
    viscous quadratic form: half the work a step. ``gamma0``/``gamma1`` (2N, G) are in the
    global state order ``[u, u̇]``; ``aa`` is (3, G, G).

    A block that holds dashpots of links folded into C (``C_links`` of
    :func:`compute_free_step`) has ``2 n_b + 2 G`` more numbers in each column: column j of
    the links' dissipation form ``Q_xx`` and its cross terms ``2 Q_x,a0,g``, ``2 Q_x,a1,g``,
    so that the same sweep gives the energy the links' dashpots dissipate over the step,
    ``zᵀ Q_xx z + Σ_g (2 Q_x,a0,g · z) a0_g + (2 Q_x,a1,g · z) a1_g`` plus
    ``dev_aa`` (3, G, G) like ``aa``: the viscous work is then split exactly between the
    buildings' damping and the links. ``rows[b]``: the numbers of block b's columns the
    kernel's sweep reads: ``2 n_b + 2`` (the state and the first ground component's input
    terms), or the whole column, ``4 n_b + 4 G``, for a block with link dashpots.

    A block of at least :data:`~pounding.integrate.modal_propagator.MODAL_MIN_FLOORS` floors
    with classical damping, one ground component and no link dashpots has ``modal[b] = 1``:
    the kernel steps it in modal coordinates (2 n_b² products a step instead of 4 n_b²),
    from ``modes[glob_b[:n_b], :2n_b + 12]``, row j the table of mode j
    (:func:`pounding.integrate.modal_propagator.mode_table`); its columns of ``ops``,
    ``gamma0``, ``gamma1`` and ``aa`` hold the same step as dense operators, built from the
    modes (equal to the exponential's to round-off). ``modes`` is (N, width), zero in the
    rows of the other blocks.

    ``maxwell`` (n_blocks, W): ``maxwell[b, 0]`` linear Maxwell links in block b, whose
    state then holds their spring deformations too (``[u_b, u̇_b, z_b]``, the element rows
    ``maxwell[b, 1:1 + m_b]`` in that order; :func:`pounding.integrate.maxwell_propagator.
    compute_free_step_maxwell`: ``ops``, ``gamma0`` and ``gamma1`` then have a row for
    every entry of the kernel's state ``[u, u̇, z]``, and such a block's columns their own
    layout); zeros (one column) without.
    """

    blk: NDArray[np.int64]
    ops: NDArray[np.float64]
    gamma0: NDArray[np.float64]
    gamma1: NDArray[np.float64]
    aa: NDArray[np.float64]
    rows: NDArray[np.int64]
    dev_aa: NDArray[np.float64]
    modal: NDArray[np.int64]
    modes: NDArray[np.float64]
    maxwell: NDArray[np.int64]


def independent_blocks(*mats: NDArray[np.float64]) -> NDArray[np.int64]:
    """Boundaries ``[0, …, N]`` of the finest split of the floors into runs of consecutive
    floors that no non-zero entry of any matrix couples (a run ends after floor i when no
    entry links a floor ≤ i to a floor > i)."""
    n = mats[0].shape[0]
    reach = np.arange(n)  # reach[i]: the largest floor coupled to floor i
    for a in mats:
        rows, cols = np.nonzero(a)
        np.maximum.at(reach, rows, cols)
        np.maximum.at(reach, cols, rows)
    bounds = [0]
    far = -1
    for i in range(n):
        far = max(far, int(reach[i]))
        if far == i:
            bounds.append(i + 1)
    return np.array(bounds, dtype=np.int64)


def _van_loan_integral(f: NDArray[np.float64], w: NDArray[np.float64],
                       h: float) -> NDArray[np.float64]:
    """``∫₀ʰ e^{Fᵀs} W e^{Fs} ds`` from one matrix exponential (Van Loan 1978, §4): with
    ``H = [[−Fᵀ, W], [0, F]]``, ``e^{Hh} = [[·, G], [0, e^{Fh}]]`` and the integral is
    ``e^{Fh}ᵀ G``. The result is linear in W, so W is scaled to the size of F first (the
    exponential's scaling-and-squaring then sees a balanced matrix) and scaled back."""
    k = f.shape[0]
    wn = np.abs(w).max()
    if wn == 0.0:
        return np.zeros((k, k))
    scale = max(np.abs(f).max(), 1.0 / h) / wn
    big = np.zeros((2 * k, 2 * k))
    big[:k, :k] = -f.T
    big[:k, k:] = w * scale
    big[k:, k:] = f
    from scipy.linalg import expm

    e = expm(big * h)
    out = e[k:, k:].T @ e[:k, k:] / scale
    return 0.5 * (out + out.T)


def _columns(r: NDArray[np.float64]) -> NDArray[np.float64]:
    """The influence matrix (N, G) of an influence vector (N,) or matrix."""
    r = np.asarray(r, dtype=float)
    return r.reshape(r.shape[0], -1)


def _augmented(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
               r: NDArray[np.float64], h: float
               ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``F`` of ``ẏ = F y`` for ``y = [x, a_g, ȧ_g]`` (a_g, ȧ_g: G components each) and ``T``
    with ``y0 = T [x0, a0, a1]``."""
    n = M.shape[0]
    rm = _columns(r)
    g = rm.shape[1]
    k = 2 * n + 2 * g
    f = np.zeros((k, k))
    f[: 2 * n, : 2 * n] = state_matrix(M, C, K)
    f[n : 2 * n, 2 * n : 2 * n + g] = -rm
    t = np.eye(k)
    for q in range(g):
        f[2 * n + q, 2 * n + g + q] = 1.0
        t[2 * n + g + q, 2 * n + q] = -1.0 / h
        t[2 * n + g + q, 2 * n + g + q] = 1.0 / h
    return f, t


def _input_weight(M: NDArray[np.float64], r: NDArray[np.float64]) -> NDArray[np.float64]:
    """W of the input power ``−u̇ᵀ M R a_g = yᵀ W y``."""
    n = M.shape[0]
    mr = M @ _columns(r)
    g = mr.shape[1]
    w_in = np.zeros((2 * n + 2 * g, 2 * n + 2 * g))
    w_in[n : 2 * n, 2 * n : 2 * n + g] = -0.5 * mr
    w_in[2 * n : 2 * n + g, n : 2 * n] = -0.5 * mr.T
    return w_in


def step_input_form(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                    r: NDArray[np.float64], h: float) -> NDArray[np.float64]:
    """Input energy over one exact step as a quadratic form in ``[x0, a0, a1]`` (the first
    of :func:`step_energy_forms`; a0, a1 of G components each)."""
    f, t = _augmented(M, C, K, r, h)
    return t.T @ _van_loan_integral(f, _input_weight(M, r), h) @ t


def step_viscous_form(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                      r: NDArray[np.float64], h: float,
                      c_part: NDArray[np.float64]) -> NDArray[np.float64]:
    """Work of the dashpots ``c_part`` (a part of C: the links folded into it) over one exact
    step as a quadratic form in ``[x0, a0, a1]`` (``∫ u̇ᵀ c_part u̇ dt``; the second form of
    :func:`step_energy_forms` with ``c_part`` for C)."""
    n = M.shape[0]
    f, t = _augmented(M, C, K, r, h)
    w_d = np.zeros_like(f)
    w_d[n : 2 * n, n : 2 * n] = 0.5 * (c_part + c_part.T)
    return t.T @ _van_loan_integral(f, w_d, h) @ t


def step_energy_forms(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                      r: NDArray[np.float64], h: float
                      ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Input and viscous energy over one exact step as quadratic forms in ``[x0, a0, a1]``.

    With every gap open, ``y = [x, a_g, ȧ_g]`` obeys ``ẏ = F y``, ``F = [[A, B, 0], [0, 0, 1],
    [0, 0, 0]]`` (a_g linear in the step), so ``y(s) = e^{Fs} y0``. The input power
    ``−a_g (M r)ᵀ u̇`` and the viscous power ``u̇ᵀ C u̇`` are quadratic forms ``yᵀ W y``,
    hence their integrals over the step are ``y0ᵀ (∫ e^{Fᵀs} W e^{Fs} ds) y0`` — exact, for
    any step and any frequency content. ``y0 = T [x0, a0, a1]`` with
    ``ȧ_g = (a1 − a0) / h`` gives the forms in the grid values.

    With G ground components ``a0``, ``a1`` are G values each and ``W_in`` is
    ``−u̇ᵀ M R a_g``. Returns ``(Q_in, Q_visc)``, each ``(2N+2G, 2N+2G)`` symmetric. (The
    kernel needs only ``Q_in``; ``Q_visc`` checks that the viscous work it infers from the
    balance is exact.)
    """
    n = M.shape[0]
    f, t = _augmented(M, C, K, r, h)
    w_d = np.zeros_like(f)
    w_d[n : 2 * n, n : 2 * n] = 0.5 * (C + C.T)
    q_in, q_visc = (t.T @ _van_loan_integral(f, w, h) @ t for w in (_input_weight(M, r), w_d))
    return q_in, q_visc


def compute_free_step(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                      r: NDArray[np.float64], h: float,
                      c_links: NDArray[np.float64] | None = None,
                      modal_from: int | None = None) -> FreeStep:
    """The :class:`FreeStep` operators of the structure for a grid step ``h`` [s];
    ``c_links``: the part of C that is the dashpots of links folded into it (None: none),
    whose dissipated energy each step gives apart; ``modal_from``: the fewest floors of a
    block stepped in modal coordinates if its damping is classical (None:
    :data:`~pounding.integrate.modal_propagator.MODAL_MIN_FLOORS`; 0 disables: every block
    dense, from the matrix exponentials)."""
    from pounding.integrate import modal_propagator

    least = modal_propagator.MODAL_MIN_FLOORS if modal_from is None else modal_from
    n = M.shape[0]
    rm = _columns(r)
    ng = rm.shape[1]
    blk = independent_blocks(M, C, K)
    gamma0 = np.zeros((2 * n, ng))
    gamma1 = np.zeros((2 * n, ng))
    aa = np.zeros((3, ng, ng))
    dev_aa = np.zeros((3, ng, ng))
    rows = np.zeros(blk.size - 1, dtype=np.int64)
    modal = np.zeros(blk.size - 1, dtype=np.int64)
    tables: list[tuple[int, NDArray[np.float64]]] = []
    parts = []
    for b in range(blk.size - 1):
        p, q = int(blk[b]), int(blk[b + 1])
        nb = q - p
        glob = np.r_[p:q, n + p : n + q]
        sl = slice(p, q)
        mb, cb, kb, rb = M[sl, sl], C[sl, sl], K[sl, sl], rm[sl]
        cb_links = None if c_links is None else c_links[sl, sl]
        linked = cb_links is not None and bool(np.any(cb_links != 0.0))
        forms = (modal_propagator.block_forms(mb, cb, kb, rb, h)
                 if 0 < least <= nb and ng == 1 and not linked else None)
        if forms is not None:
            # classical damping: every form from the modes (modal_propagator)
            prop = Propagator(forms.phi, forms.gamma0[:, None], forms.gamma1[:, None])
            q_in = forms.q_in
            modal[b] = 1
            tables.append((p, forms.table))
        else:
            prop = compute_propagator(mb, cb, kb, rb, h)
            q_in = step_input_form(mb, cb, kb, rb, h)
        gamma0[glob] = prop.gamma0
        gamma1[glob] = prop.gamma1
        x_ = slice(0, 2 * nb)
        a0_ = slice(2 * nb, 2 * nb + ng)
        a1_ = slice(2 * nb + ng, 2 * nb + 2 * ng)
        op = np.zeros((2 * nb, 2 * nb + 2 * ng))
        op[:, : 2 * nb] = prop.phi.T
        # the cross terms appear twice in yᵀQy: 2 Q[x, a] is the linear coefficient
        op[:, 2 * nb + 0 :: 2] = 2.0 * q_in[x_, a0_]
        op[:, 2 * nb + 1 :: 2] = 2.0 * q_in[x_, a1_]
        aa += (q_in[a0_, a0_], 2.0 * q_in[a0_, a1_], q_in[a1_, a1_])
        rows[b] = 2 * nb + 2
        if cb_links is not None and linked:
            # the links' dashpots in this block: their dissipation form after the input's
            q_dev = step_viscous_form(mb, cb, kb, rb, h, cb_links)
            dev = np.zeros((2 * nb, 2 * nb + 2 * ng))
            dev[:, : 2 * nb] = q_dev[x_, x_]
            dev[:, 2 * nb + 0 :: 2] = 2.0 * q_dev[x_, a0_]
            dev[:, 2 * nb + 1 :: 2] = 2.0 * q_dev[x_, a1_]
            dev_aa += (q_dev[a0_, a0_], 2.0 * q_dev[a0_, a1_], q_dev[a1_, a1_])
            op = np.concatenate([op, dev], axis=1)
            rows[b] = op.shape[1]
        parts.append((glob, op))
    width = max((op.shape[1] for _, op in parts), default=0)
    ops = np.zeros((2 * n, width))
    for glob, op in parts:
        ops[glob, : op.shape[1]] = op
    modes_all = np.zeros((n if tables else 1, max((t.shape[1] for _, t in tables), default=1)))
    for p, t in tables:
        modes_all[p : p + t.shape[0], : t.shape[1]] = t
    return FreeStep(blk, ops, gamma0, gamma1, aa, rows, dev_aa, modal, modes_all,
                    np.zeros((blk.size - 1, 1), dtype=np.int64))


_FREE_CACHE: dict[bytes, FreeStep] = {}


def free_step(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
              r: NDArray[np.float64], h: float,
              c_links: NDArray[np.float64] | None = None) -> FreeStep:
    """:func:`compute_free_step`, remembered per structure and step like
    :func:`propagator` (the arrays are read-only)."""
    if c_links is None:
        return _remembered(_FREE_CACHE, compute_free_step, M, C, K, r, h)
    return _remembered(_FREE_CACHE,
                       lambda M_, C_, K_, r_, h_: compute_free_step(M_, C_, K_, r_, h_, c_links),
                       M, C, K, r, h, extra=c_links)
