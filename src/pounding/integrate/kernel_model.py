"""A model as the compiled kernel reads it: banded matrices, masses, contact and storey
tables, assembled once per model and remembered; the kernel's scratch; how free steps are
taken."""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any, NamedTuple, TypeVar

import numpy as np

from pounding.contact.dispatch import PARAMS_SIZE as P_CONTACT_LAW
from pounding.integrate.layout import (
    EL_FOLDED,
    EL_LEVER,
    EL_ROCK,
    ELEMENT_PARAMS,
    HS_COLUMNS,
    ROW_BLOCK,
)
from pounding.integrate.propagator import FreeStep
from pounding.memo import Memo
from pounding.model import PoundingModel

EXACT_FREE_MAX_DOF: int = 400
"""``free_stepping="auto"`` uses the exact propagator up to this many floors in all.

Measured on 2 cores (shear pair of ``benchmarks/bench_opensees.py``, El Centro 20 s, gap
0.02 m; ``free_stepping="exact"`` against ``"rk"``): 100 floors 0.14 s against 0.22 s,
300 floors 1.2 s against 1.5 s, 500 floors 2.7 s against 6.1 s. Exact stepping was the
faster at every size tried; the limit bounds its O(N²) products and (2N)² memory for
models far beyond that.
"""


EXACT_LINKED_BLOCK_MAX: int = 120
"""``free_stepping="auto"`` uses the exact propagator for a model whose links are folded into
K and C (:func:`fold_linear_links`) only if the largest block they tie holds at most this
many floors: such a block's exact step also sweeps the links' dissipation form, twice the
work. Measured on two shear buildings of n storeys with a dashpot at every floor (El Centro
10 s, gap 10 m, 2026-11-28; exact against RK): 2 × 50 floors 112 against 149 ms, 2 × 75 227
against 217 ms, 2 × 100 356 against 305 ms, 2 × 150 815 against 431 ms."""


def half_bandwidth(*mats: np.ndarray) -> int:
    """Largest ``|i − j|`` with a non-zero entry in any of the matrices."""
    bw = 0
    for a in mats:
        i, j = np.nonzero(a)
        if i.size:
            bw = max(bw, int(np.max(np.abs(i - j))))
    return bw


FAR_COST = 2.0
"""How many band entries one entry outside the band costs in the kernel's products (it is
read and added by index, not in a vectorised row) — what :func:`banding` weighs."""


def banding(K: np.ndarray, C: np.ndarray) -> tuple[int, np.ndarray]:
    """The half-bandwidth the kernel stores ``K`` and ``C`` with, and their entries outside
    it (``far``, :func:`kernel_bands`): the bandwidth that makes ``N (2 bw + 1) + FAR_COST ·
    (entries outside)`` least — the whole band for a banded building, a narrow band and a
    few rows and columns apart for a building on a flexible base (its footing's sway and
    rocking coupled to every floor), whose products would otherwise sweep a band of zeros.
    A model with any coupling keeps a band of at least 1 (``bw == 0`` means uncoupled
    DOFs to the kernel)."""
    n = K.shape[0]
    full = half_bandwidth(K, C)
    i, j = np.nonzero((K != 0.0) | (C != 0.0))
    dist = np.abs(i - j)
    best, best_cost = full, float(n * (2 * full + 1))
    for bw in range(1 if full else 0, full):
        cost = n * (2 * bw + 1) + FAR_COST * int(np.count_nonzero(dist > bw))
        if cost < best_cost:
            best, best_cost = bw, cost
    return best, far_entries(K, C, best)


def far_entries(K: np.ndarray, C: np.ndarray, bw: int) -> np.ndarray:
    """The entries of ``K`` and ``C`` outside half-bandwidth ``bw``: rows ``[i, j, K_ij,
    C_ij]``, row by row."""
    i, j = np.nonzero((K != 0.0) | (C != 0.0))
    out = np.abs(i - j) > bw
    i, j = i[out], j[out]
    far = np.column_stack([i, j, K[i, j], C[i, j]]).astype(float)
    return np.ascontiguousarray(far.reshape(-1, 4))


def kernel_bands(K: np.ndarray, C: np.ndarray, bw: int) -> tuple[np.ndarray, np.ndarray]:
    """``K`` and ``C`` as the kernel reads them (:attr:`Floors.k_band`, ``c_band``): band
    storage of half-bandwidth ``bw`` (N columns), then one column ``[i, j, K_ij]`` /
    ``[i, j, C_ij]`` (and zeros below) for each entry outside the band — in the two band
    arrays rather than an array of their own, because every array of a group is passed to
    every call that takes it (an extra one cost the SDOF pair's contact steps 5–8 %).
    Needs ``bw ≥ 1`` where there are such entries (three rows; :func:`banding` keeps it)."""
    n = K.shape[0]
    far = far_entries(K, C, bw)
    kb = np.zeros((2 * bw + 1, n + far.shape[0]))
    cb = np.zeros_like(kb)
    kb[:, :n] = band_storage(K, bw)
    cb[:, :n] = band_storage(C, bw)
    if far.shape[0]:
        if 2 * bw + 1 < 3:
            raise ValueError("kernel_bands: entries outside a band of 0")
        kb[0, n:] = cb[0, n:] = far[:, 0]
        kb[1, n:] = cb[1, n:] = far[:, 1]
        kb[2, n:] = far[:, 2]
        cb[2, n:] = far[:, 3]
    return kb, cb


def band_storage(a: np.ndarray, bw: int) -> np.ndarray:
    """``(2 bw + 1, N)`` band storage of a square matrix: ``out[d, i] = a[i, i + d − bw]``
    (zero outside the matrix), the layout the kernel's O(N·bw) products read."""
    n = a.shape[0]
    out = np.zeros((2 * bw + 1, n))
    for d in range(2 * bw + 1):
        off = d - bw
        i = np.arange(max(0, -off), min(n, n - off))
        out[d, i] = a[i, i + off]
    return out


def choose_free_stepping(mode: str, n_dof: int, bw: int, linked_block: int = 0) -> bool:
    """True to step contact-free intervals with the exact propagator (see :func:`simulate`);
    ``linked_block``: the floors of the largest block that links folded into K and C tie
    (:attr:`KernelModel.linked_block`, :data:`EXACT_LINKED_BLOCK_MAX`)."""
    from pounding.validation import choice

    mode = choice("free_stepping", mode, ("auto", "exact", "rk"))
    if mode == "auto":
        return n_dof <= EXACT_FREE_MAX_DOF and linked_block <= EXACT_LINKED_BLOCK_MAX
    return mode == "exact"


def exact_stepping(km: KernelModel, mode: str, yielding_frames: bool) -> bool:
    """True to step the model's contact-free intervals with the exact propagator
    (:func:`choose_free_stepping`), which needs its element rows to allow it
    (:attr:`KernelModel.exact_allowed`) and no yielding frames.

    Raises
    ------
    ValueError
        ``mode`` ``"exact"`` for a model that does not allow it, in one line.
    """
    allowed = km.exact_allowed and not yielding_frames
    if not allowed and mode == "exact":
        raise ValueError("free_stepping: 'exact' needs linear storeys and linear links; this "
                         "model has yielding storeys, nonlinear links between buildings (or "
                         "Maxwell links beside restrainers or under several ground "
                         "components) or frames with plastic hinges (use 'auto' or 'rk')")
    linked = max(km.linked_block, maxwell_linked_block(km)) if allowed else km.linked_block
    return choose_free_stepping(mode, km.n, km.floors.bw, linked) and allowed


class Floors(NamedTuple):
    """The buildings' linear part as the kernel reads it, floor by floor (N floors)."""

    bw: int  #: half-bandwidth of K and C
    #: K of the linear storeys [N/m] in band storage (2 bw + 1, N), then its m entries
    #: outside the band as columns ``[i, j, K_ij]`` (N + m columns: :func:`kernel_bands`)
    k_band: np.ndarray
    c_band: np.ndarray  #: C [N·s/m] likewise, its entries outside as ``[i, j, C_ij]``
    m_diag: np.ndarray  #: lumped floor masses [kg] (N,)
    m_inv: np.ndarray  #: 1 / floor mass [1/kg] (N,)
    mr: np.ndarray  #: M R [kg], (N, G)
    r: np.ndarray  #: influence matrix R of the G ground components, (N, G)
    below: np.ndarray  #: DOF of the floor below each floor (−1: the ground), (N,)
    #: the floors of yielding frames, whose restoring force in the frame's current
    #: configuration is ``K u + f0`` (:mod:`pounding.integrate.frame_run`): each floor's
    #: DOF (a whole number), ``f0`` [N], and a constant [J] that makes the frames' work
    #: ``Σ ½ uᵀ K u + f0ᵀ u + c`` continuous across configurations, (N_f, 3) — one array,
    #: not three: every array of a group is passed to every call that takes the group, and
    #: an RK step takes this one (two more arrays cost the SDOF pair's contact steps
    #: 3–4 %); empty without yielding frames
    f_rows: np.ndarray


class ContactRows(NamedTuple):
    """The contacts as the kernel reads them: ``δ_c = Σ_q weight[c, q] u[dof[c, q]] − gap[c]``
    (rows padded to a multiple of :data:`~pounding.integrate.layout.ROW_BLOCK`) and the
    law of each (:mod:`pounding.contact.dispatch`)."""

    dof: np.ndarray  #: contact DOFs (n_c, W)
    weight: np.ndarray  #: signed weights (n_c, W)
    gap: np.ndarray  #: gaps [m] (n_c,)
    code: np.ndarray  #: contact-law codes (n_c,)
    params: np.ndarray  #: contact-law constants (n_c, 3)


class ElementRows(NamedTuple):
    """The yielding storeys and then the links between buildings, rows of one kind
    (:meth:`pounding.model.PoundingModel.storey_arrays`): each a force between DOF ``lo``
    (−1: the ground) and ``hi`` from its law."""

    lo: np.ndarray  #: DOF below (−1: the ground) (n_s,)
    hi: np.ndarray  #: DOF above (n_s,)
    code: np.ndarray  #: storey-law or link codes (n_s,)
    #: their constants (n_s, ELEMENT_PARAMS): the law's, then a rocking footing's DOF and lever
    #: (:data:`pounding.integrate.layout.EL_ROCK`)
    params: np.ndarray
    z_index: np.ndarray  #: index of each row's internal variable z among the states (−1: none)


class HingeRows(NamedTuple):
    """The plastic hinges of yielding frames: rows ``θ_h = Σ_q weight[h, q] u[dof[h, q]] +
    a0_h`` over their frame's floors (padded to a multiple of
    :data:`~pounding.integrate.layout.ROW_BLOCK`), set by Python for each configuration of
    the frame (:mod:`pounding.integrate.frame_run`); empty without yielding frames. A group
    of its own, passed only to the event search and the outputs (not to the RK step)."""

    dof: np.ndarray  #: the frame's floors (n_h, W)
    weight: np.ndarray  #: their weights [rad/m] (n_h, W)
    #: each hinge's branch and committed point (n_h, HS_COLUMNS),
    #: :data:`pounding.integrate.layout.HS_A0` …
    state: np.ndarray


class KernelArrays(NamedTuple):
    """Every array the compiled kernel reads that depends on the model alone, in three
    groups: a function takes the groups it uses (numba passes a tuple as its members), and a
    new kind of row adds a field to a group, not a parameter to every signature."""

    floors: Floors
    contacts: ContactRows
    elements: ElementRows
    hinges: HingeRows


class KernelModel(NamedTuple):
    """A :class:`~pounding.model.PoundingModel` as the kernel reads it: the
    :class:`KernelArrays` :func:`simulate` passes to the kernel, and what the Python around
    it needs of the model (sizes, the dense K and C for the exact step and the first row).

    Assembled once per model by :func:`kernel_model` — the one place that asks the model for
    its arrays — and reused by every later run of it, so a repeated run (a record sweep, a
    benchmark) pays only for its own outputs; the part that depends on the buildings alone
    is assembled once for the same building objects (:data:`STRUCTURES`), so the cases of a
    sweep over gaps, contacts or records share it. The kernel only reads these arrays; they
    are left writeable because numba compiles a separate signature for read-only ones. Do
    not modify them.
    """

    n: int  #: floors (degrees of freedom)
    nz: int  #: internal variables of the yielding storeys and links (Bouc–Wen, Maxwell z)
    #: stiffness of the linear storeys and of the springs of the links folded into it
    #: (:func:`fold_linear_links`) [N/m], (N, N)
    K: np.ndarray
    C: np.ndarray  #: damping, the folded links' dashpots included [N·s/m], (N, N)
    arrays: KernelArrays  #: what the compiled kernel reads
    #: exact grid steps already built, by step [s] (shared by the models of the same
    #: buildings, :data:`STRUCTURES`)
    free_steps: dict[float, FreeStep]
    #: output steps [s] whose building and link periods passed their check
    #: (:mod:`pounding.integrate.periods`; shared like ``free_steps``)
    periods_checked: set[float]
    #: the dashpots of the links folded into C alone [N·s/m], (N, N) — what the exact step
    #: counts as the links' dissipated energy (:func:`pounding.integrate.propagator.
    #: compute_free_step`); None without folded links
    C_links: np.ndarray | None = None
    #: floors of the largest block of the exact step that holds folded links' dashpots
    #: (:func:`pounding.integrate.propagator.independent_blocks`; 0: none)
    linked_block: int = 0
    #: True when some element row reads a prescribed DOF that the exact steps do not (a
    #: link between buildings on different grounds, :mod:`pounding.integrate.stations`):
    #: every step adaptive
    adaptive_only: bool = False

    @property
    def exact_allowed(self) -> bool:
        """True if the model's element rows let contact-free steps be exact: none, links
        folded into K and C (:func:`fold_linear_links`) and cable restrainers, stepped
        exactly while slack (:func:`pounding.integrate.exact_links.rows_allow_exact`), or
        links folded into K and C and linear Maxwell links between floors under one ground
        component, whose springs the exact steps carry in their state
        (:func:`maxwell_exact_rows`)."""
        from pounding.devices.laws import RESTRAINER

        el = self.elements
        if self.adaptive_only:
            return False
        folded = el.params[:, EL_FOLDED] != 0.0
        if bool(np.all(folded | (el.code == RESTRAINER))):
            return True
        mx = maxwell_exact_rows(self)
        return mx is not None and bool(np.all(folded | mx))

    @property
    def floors(self) -> Floors:
        """:attr:`KernelArrays.floors`."""
        return self.arrays.floors

    @property
    def contacts(self) -> ContactRows:
        """:attr:`KernelArrays.contacts`."""
        return self.arrays.contacts

    @property
    def elements(self) -> ElementRows:
        """:attr:`KernelArrays.elements`."""
        return self.arrays.elements

    @property
    def hinges(self) -> HingeRows:
        """:attr:`KernelArrays.hinges`."""
        return self.arrays.hinges


_KERNEL_MODELS: dict[int, KernelModel] = {}


def _read_only_free_step(fs: FreeStep) -> FreeStep:
    for a in fs:
        a.setflags(write=False)
    return fs


NO_FRAME_ROWS = np.zeros((0, 3))
NO_HINGES = HingeRows(np.zeros((0, ROW_BLOCK), dtype=np.int64), np.zeros((0, ROW_BLOCK)),
                      np.zeros((0, HS_COLUMNS)))
"""The frame floors and hinge rows of a model without yielding frames: empty (never
written), and writeable like a run's own rows, so that the kernel is compiled for one
signature."""

NO_FREE_STEP = _read_only_free_step(FreeStep(np.array([0, 1], dtype=np.int64), np.zeros((2, 4)),
                                              np.zeros((2, 1)), np.zeros((2, 1)),
                                              np.zeros((3, 1, 1)), np.array([4], dtype=np.int64),
                                              np.zeros((3, 1, 1)), np.zeros(1, dtype=np.int64),
                                              np.zeros((1, 1)),
                                              np.zeros((1, 1), dtype=np.int64)))
"""The exact-step arguments of an RK-stepped run, which the kernel never reads: read-only
like a real :class:`FreeStep`'s arrays, so that numba compiles the kernel for one signature
only (not a second one, 37–56 s on 2 cores, for yielding or very large models)."""


_T = TypeVar("_T")


def remembered_for(model: object, store: dict[Any, _T], key: Any, make: Callable[[], _T]) -> _T:
    """``store[key]``, made by ``make()`` the first time and kept until ``model`` is
    garbage-collected (models are frozen and hold NumPy arrays, so what belongs to one is
    remembered by its identity, in ``key``, not by its value); not kept for a model that
    cannot be weakly referenced."""
    value = store.get(key)
    if value is None:
        value = make()
        try:
            # the entry must go when the model does (before its id can be reused)
            weakref.finalize(model, store.pop, key, None)
        except TypeError:
            return value
        store[key] = value
    return value


def kernel_model(model: PoundingModel) -> KernelModel:
    """The model's :class:`KernelModel`, assembled on its first run and remembered until the
    model is garbage-collected (:func:`remembered_for`)."""
    return remembered_for(model, _KERNEL_MODELS, id(model),
                          lambda: _assemble_kernel_model(model))


STRUCTURES = Memo(max_items=64, max_bytes=256 << 20)
"""The buildings' part of a :class:`KernelModel` (everything but the contacts), by the
identity of the buildings, the links between them and the influence matrix: the cases of a
sweep that change only gaps, contact law or record share it, with its exact steps."""


def _assemble_kernel_model(model: PoundingModel) -> KernelModel:
    r = np.asarray(model.system.r)
    key = (tuple(map(id, model.buildings)), tuple(link.describe() for link in model.links),
           r.shape, r.tobytes())
    structure = STRUCTURES.get(key, lambda: _assemble_structure(model),
                               size=lambda st: 8 * 8 * st.n ** 2, keep=model.buildings)
    cdof, cw, cgap, ccode, cparams = model.contact_arrays()
    cdof, cw = padded_rows(cdof, cw)
    contacts = ContactRows(cdof, cw, cgap, ccode, np.ascontiguousarray(cparams))
    return structure._replace(arrays=structure.arrays._replace(contacts=contacts))


def padded_rows(cdof: np.ndarray, cw: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The contact rows (n_c, W) padded to a width that is a multiple of
    :data:`~pounding.integrate.layout.ROW_BLOCK` with zero weights on each row's first DOF
    (W = 4, today's contacts, unchanged)."""
    nc, w = cdof.shape
    wide = -(-w // ROW_BLOCK) * ROW_BLOCK if w else ROW_BLOCK
    dof = np.zeros((nc, wide), dtype=np.int64)
    wt = np.zeros((nc, wide))
    dof[:, :w] = cdof
    wt[:, :w] = cw
    if nc and w:
        dof[:, w:] = cdof[:, :1]
    return np.ascontiguousarray(dof), np.ascontiguousarray(wt)


def _assemble_structure(model: PoundingModel) -> KernelModel:
    """A :class:`KernelModel` of the buildings (and the links between them) alone: its
    contacts empty, for :func:`_assemble_kernel_model` to fill in."""
    sys_ = model.system
    M, C = sys_.M, sys_.C
    r = influence_matrix(sys_.r)
    K = model.linear_stiffness()
    m_diag = np.diag(M).copy()
    if np.any(M != np.diag(m_diag)):
        raise ValueError("model: the mass matrix must be diagonal (lumped floor masses)")
    s_lo, s_hi, s_code, s_par, s_zi = model.storey_arrays()
    folded = (np.zeros(s_lo.size, dtype=bool) if model.yielding_frames
              else foldable_rows(s_code, s_par))
    C = np.asarray(C)
    c_links = None
    if folded.any():
        K, C, c_links = fold_linear_links(K, C, s_lo[folded], s_hi[folded], s_code[folded],
                                          s_par[folded])
    bw, _ = banding(K, C)
    k_band, c_band = kernel_bands(K, C, bw)
    floors = Floors(bw, k_band, c_band, m_diag, 1.0 / m_diag,
                    np.ascontiguousarray(M @ r), np.ascontiguousarray(r), floor_below(model),
                    NO_FRAME_ROWS)
    rock, lever = model.storey_rocking()
    if s_par.shape[1] > EL_ROCK:  # (a law with more constants would overwrite the rocking)
        raise AssertionError(f"element rows: {s_par.shape[1]} law constants, the layout "
                             f"keeps {EL_ROCK} (integrate.layout.EL_ROCK)")
    par = np.zeros((s_lo.size, ELEMENT_PARAMS))
    par[:, : s_par.shape[1]] = s_par
    par[:, EL_ROCK] = rock
    par[:, EL_LEVER] = lever
    par[:, EL_FOLDED] = folded
    elements = ElementRows(s_lo, s_hi, s_code, par, s_zi)
    no_contacts = ContactRows(np.zeros((0, ROW_BLOCK), dtype=np.int64),
                              np.zeros((0, ROW_BLOCK)), np.zeros(0),
                              np.zeros(0, dtype=np.int64), np.zeros((0, P_CONTACT_LAW)))
    return KernelModel(n=r.shape[0], nz=int(np.sum(s_zi >= 0)), K=K, C=C,
                       arrays=KernelArrays(floors, no_contacts, elements, NO_HINGES),
                       free_steps={}, periods_checked=set(), C_links=c_links,
                       linked_block=largest_linked_block(K, C, c_links))


def maxwell_exact_rows(km: KernelModel) -> np.ndarray | None:
    """The element rows that are linear Maxwell links the exact steps can carry
    (:func:`pounding.integrate.maxwell_propagator.linear_maxwell_rows`, each between two
    floors, the model under one ground component), as a mask; None if the model has none or
    one it cannot (then every row that is not folded into K and C keeps the model
    adaptive)."""
    from pounding.integrate.maxwell_propagator import linear_maxwell_rows

    el = km.elements
    mx = linear_maxwell_rows(el.code, el.params[:, :3])
    if not mx.any() or km.floors.r.shape[1] != 1 or np.any(el.lo[mx] < 0):
        return None
    return mx


def maxwell_free_step(km: KernelModel, step: float) -> FreeStep:
    """The exact step [s] of a model with linear Maxwell links (:func:`maxwell_exact_rows`):
    :func:`pounding.integrate.maxwell_propagator.free_step_maxwell`."""
    from pounding.integrate.maxwell_propagator import free_step_maxwell, maxwell_links

    mx = maxwell_exact_rows(km)
    assert mx is not None
    el = km.elements
    links = maxwell_links(el.lo, el.hi, el.code, el.params[:, :3])
    return free_step_maxwell(np.diag(km.floors.m_diag), km.C, km.K, km.floors.r, step,
                                     km.C_links, links, np.flatnonzero(mx),
                                     2 * km.n + el.z_index[mx], 2 * km.n + km.nz)


def maxwell_linked_block(km: KernelModel) -> int:
    """Floors of the largest block that linear Maxwell links tie (0: none), for
    :data:`EXACT_LINKED_BLOCK_MAX`: each holds a dissipation form as a block of folded
    links' dashpots does."""
    mx = maxwell_exact_rows(km)
    if mx is None:
        return 0
    from pounding.integrate.maxwell_propagator import extended_blocks, maxwell_links

    el = km.elements
    links = maxwell_links(el.lo, el.hi, el.code, el.params[:, :3])
    blk = extended_blocks(np.diag(km.floors.m_diag), km.C, km.K, links)
    return max((int(q - p) for p, q in zip(blk[:-1], blk[1:])
                if np.any((links.lo >= p) & (links.lo < q))), default=0)


def largest_linked_block(K: np.ndarray, C: np.ndarray, c_links: np.ndarray | None) -> int:
    """Floors of the largest independent block of K and C that holds a folded link's
    dashpot (0 without: ``c_links`` None)."""
    if c_links is None:
        return 0
    from pounding.integrate.propagator import independent_blocks

    blk = independent_blocks(K, C)
    return max((int(q - p) for p, q in zip(blk[:-1], blk[1:])
                if np.any(c_links[p:q, p:q] != 0.0)), default=0)


def foldable_rows(code: np.ndarray, params: np.ndarray) -> np.ndarray:
    """True for every element row that is a link with a linear law and no internal variable
    (:func:`pounding.devices.laws.linear_link_constants`: Kelvin, a dashpot with α = 1)."""
    from pounding.devices.laws import linear_link_constants

    return np.array([linear_link_constants(int(c), float(p[0]), float(p[1])) is not None
                     for c, p in zip(code, params)], dtype=bool)


def fold_linear_links(K: np.ndarray, C: np.ndarray, lo: np.ndarray, hi: np.ndarray,
                      code: np.ndarray, params: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``K`` and ``C`` with the springs and dashpots of linear links between DOFs ``lo`` and
    ``hi`` added (each link ``F = k d + c ḋ``, ``d = u[hi] − u[lo]``: ``k`` and ``c`` at
    ``[lo, lo]`` and ``[hi, hi]``, ``−k`` and ``−c`` at ``[lo, hi]`` and ``[hi, lo]``, as a
    storey between two floors), and the links' dashpots alone (N, N). New arrays; ``K`` and
    ``C`` are not modified.

    Folded, a linear link is part of the linear structure: the exact propagator steps it
    between events (:mod:`pounding.integrate.exact_steps`), and the buildings it ties form
    one block of it (:func:`pounding.integrate.propagator.independent_blocks`)."""
    from pounding.devices.laws import linear_link_constants

    K = np.array(K, dtype=float)
    C = np.array(C, dtype=float)
    c_links = np.zeros_like(C)
    for a, b, cd, p in zip(lo, hi, code, params):
        kc = linear_link_constants(int(cd), float(p[0]), float(p[1]))
        assert kc is not None and a >= 0 and b >= 0
        for mat, value in ((K, kc[0]), (C, kc[1]), (c_links, kc[1])):
            if value != 0.0:
                mat[a, a] += value
                mat[b, b] += value
                mat[a, b] -= value
                mat[b, a] -= value
    return K, C, c_links


def influence_matrix(r: np.ndarray) -> np.ndarray:
    """The influence matrix R (N, G) of a system's ``r``: an (N,) influence vector is the
    one column of G = 1."""
    r = np.asarray(r, dtype=float)
    return np.array(r.reshape(r.shape[0], -1), dtype=float)


def floor_below(model: PoundingModel) -> np.ndarray:
    """The DOF of the floor below each floor (−1 for a first floor: the ground), so that
    the drift of storey j is ``u[j] − u[below[j]]``."""
    below = model.floor_below()  # consecutive floors by elevation; −2: not a floor
    own = below == -2
    below[own] = np.flatnonzero(own)  # a DOF that is not a floor: drift u − u = 0
    return below


def peak_margin(km: KernelModel, step: float) -> float:
    """How much larger (relative) an acceleration peak between two samples an exact step
    apart can be than the larger sample: 4 (ω_max h)²/8, with ω_max² bounded by the largest
    Gershgorin row sum of M⁻¹K (a sinusoid at ω sampled every h misses its crest by at most
    (ω h)²/8; the factor 4 covers what a bound on the modes and the ground's linear pieces
    leave). Floors whose sampled peak is further below their peak so far are not searched
    between samples: no peak there can beat it."""
    w2 = float(np.max(np.sum(np.abs(km.K), axis=1) / km.floors.m_diag)) if km.n else 0.0
    return min(1.0, 0.5 * w2 * step * step)
