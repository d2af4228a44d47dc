"""Buildings on different grounds (spatially varying ground motion) as the kernel reads them.

Under a :class:`~pounding.ground_motion.spatial.SpatialMotion` each building moves relative
to its own ground, shaken by its own record — its rows of the influence matrix in the column
of its ground (its *station*; buildings on equal records share one) — so its storey drifts,
displacements and absolute accelerations are those of a building on that ground. A contact
between buildings on different stations must see the grounds' relative displacement too:

    δ = (u_left + u_g,left) − (u_right + u_g,right) − gap.

Each station's ground displacement ``u_g,s`` joins the state as one more degree of freedom
whose motion is prescribed: no stiffness, no damping, its acceleration the station's
record (influence −1 in its column: ``ü = −r a_g = a_g,s``), integrated by the same exact
and adaptive steps as the buildings — so, for records linear between their samples, exactly
the double integral of the record from rest. It has a negligible mass
(:data:`~pounding.integrate.layout.STATION_MASS`, so it adds nothing to the kinetic or input
energy), and no force moves it: :func:`pounding.integrate.rhs.deriv` takes back what the
contacts push on it (outside its contact loop, which stays as it is for every other model)
and counts the work the moving ground does through the contact forces as input energy, so
the energy balance still closes. The contact rows gain the two stations' displacements with
weights +1 (left) and −1 (right).

A wall at an end of the row (a moat wall, a bridge's abutment) stands on its building's
ground, or on a station of its own where the motion gives it one
(:attr:`~pounding.ground_motion.spatial.SpatialMotion.walls`): its contact rows then gain
the wall's station and the building's, ``δ = u_g,wall − (u_1 + u_g,1) − gap`` on the left,
``(u_n + u_g,n) − u_g,wall − gap`` on the right.

A link between buildings on different stations (a bridge's restrainers across a joint
between frames on their own grounds) stretches by ``(u_right + u_g,right) − (u_left +
u_g,left)``: its row reads one more prescribed DOF, the grounds' offset
``u_g,right − u_g,left`` (its record the difference of the two stations'; after the
stations), through the slot a storey over a rocking footing uses for the footing
(:data:`~pounding.integrate.layout.EL_ROCK` with lever −1); what the link pushes on it is
taken back like a contact's, and its work through the moving grounds is input.

Not yet: buildings in plan (two ground components), yielding frames (refused in one line).
"""

from __future__ import annotations

import numpy as np

from pounding.integrate.kernel_model import (
    ContactRows,
    KernelModel,
    fold_linear_links,
    kernel_bands,
    kernel_model,
    padded_rows,
    remembered_for,
)
from pounding.integrate.layout import EL_FOLDED, EL_LEVER, EL_ROCK, STATION_MASS
from pounding.model import PoundingModel

__all__ = ["STATION_MASS", "link_stations", "station_kernel_model"]


_STATION_MODELS: dict[tuple[int, tuple[int, ...]], KernelModel] = {}


def _check(model: PoundingModel, stations: tuple[int, ...]) -> None:
    # (one record per building: simulate's own check, before the stations are counted)
    if model.system.r.ndim != 1:
        raise ValueError("motion: buildings in plan (two ground components) on spatially "
                         "varying ground are not modelled yet; give one record for the row")
    if model.yielding_frames:
        raise ValueError("motion: yielding frames on spatially varying ground are not modelled "
                         "yet; give one record for the row")


def station_kernel_model(model: PoundingModel, stations: tuple[int, ...],
                         wall_stations: tuple[tuple[str, int], ...] = ()) -> KernelModel:
    """The model's :class:`~pounding.integrate.kernel_model.KernelModel` with each building
    on the ground of its station ``stations[b]`` (0 … S − 1), the walls on the sides of
    ``wall_stations`` on theirs ((side, station) pairs; the others on their building's
    ground), and the S stations' ground displacements as DOFs ``N … N + S − 1`` (module
    docstring); remembered like :func:`~pounding.integrate.kernel_model.kernel_model`.

    Raises
    ------
    ValueError
        For what is not modelled yet (module docstring), in one line.
    """
    _check(model, stations)
    sides = {w.side for w in model.walls}
    for side, _ in wall_stations:
        if side not in sides:
            raise ValueError(f"motion: a ground for the {side} wall, but the row has no wall "
                             f"on its {side}")
    return remembered_for(model, _STATION_MODELS, (id(model), stations, wall_stations),
                          lambda: _assemble(model, stations, dict(wall_stations)))


def unfolded(K: np.ndarray, C: np.ndarray, c_links: np.ndarray | None, lo: np.ndarray,
             hi: np.ndarray, code: np.ndarray, params: np.ndarray
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """``K``, ``C`` and the links' dashpots without the linear links ``lo``–``hi`` that
    :func:`~pounding.integrate.kernel_model.fold_linear_links` added (new arrays)."""
    K2, C2, c2 = fold_linear_links(np.zeros_like(K), np.zeros_like(C), lo, hi, code, params)
    return K - K2, C - C2, None if c_links is None else c_links - c2


def link_stations(model: PoundingModel, stations: tuple[int, ...]
                  ) -> list[tuple[int, int, int]]:
    """``(link, left station, right station)`` of every link whose ends stand on different
    grounds (its left end the row's ``lo`` DOF, :meth:`PoundingModel.storey_arrays`, the
    building of ``link.ends[0]``)."""
    out = []
    for i, link in enumerate(model.links):
        (b_lo, _), (b_hi, _) = link.ends
        if stations[b_lo] != stations[b_hi]:
            out.append((i, stations[b_lo], stations[b_hi]))
    return out


def _assemble(model: PoundingModel, stations: tuple[int, ...],
              wall_stations: dict[str, int]) -> KernelModel:
    """:func:`station_kernel_model`, assembled."""
    base = kernel_model(model)
    N = base.n
    S = max([*stations, *wall_stations.values()]) + 1
    crossing = link_stations(model, stations)
    Q = len(crossing)
    n = N + S + Q
    fl = base.floors
    r = np.zeros((n, S))
    offsets = model.system.offsets
    for b, bl in enumerate(model.buildings):
        rows = slice(int(offsets[b]), int(offsets[b]) + bl.n)
        r[rows, stations[b]] = fl.r[rows, 0]
    r[N + np.arange(S), np.arange(S)] = -1.0
    el = base.elements
    par = el.params.copy()
    first_link = el.lo.size - len(model.links)
    K_base, C_base = base.K, base.C
    c_links_base = base.C_links
    unfold = []
    for q, (i, left, right) in enumerate(crossing):
        # the grounds' offset u_g,right − u_g,left: ü = a_g,right − a_g,left
        r[N + S + q, right] -= 1.0
        r[N + S + q, left] += 1.0
        row = first_link + i
        par[row, EL_ROCK] = N + S + q
        par[row, EL_LEVER] = -1.0
        if par[row, EL_FOLDED] != 0.0:  # (a linear link folded into K and C: its row
            par[row, EL_FOLDED] = 0.0   # reads the grounds' offset, so it is a row again)
            unfold.append(row)
    if unfold:
        at = np.array(unfold)
        K_base, C_base, c_links_base = unfolded(K_base, C_base, c_links_base, el.lo[at],
                                                el.hi[at], el.code[at], el.params[at])
    m_diag = np.r_[fl.m_diag, np.full(S + Q, STATION_MASS)]
    m_inv = np.r_[fl.m_inv, np.ones(S + Q)]  # (what is pushed on them is taken back: rhs)
    K = np.zeros((n, n))
    K[:N, :N] = K_base
    C = np.zeros((n, n))
    C[:N, :N] = C_base
    below = np.r_[fl.below, N + np.arange(S + Q)]  # (a station is not a floor: no drift)
    k_band, c_band = kernel_bands(K, C, fl.bw)
    floors = fl._replace(k_band=k_band, c_band=c_band,
                         m_diag=m_diag, m_inv=m_inv, mr=np.ascontiguousarray(m_diag[:, None] * r),
                         r=np.ascontiguousarray(r), below=below)
    ct = base.contacts
    cdof, cw = ct.dof, ct.weight
    nc, width = cdof.shape
    dof = np.concatenate([cdof, np.zeros((nc, 2), dtype=np.int64)], axis=1)
    w = np.concatenate([cw, np.zeros((nc, 2))], axis=1)
    last = len(model.buildings) - 1
    for c in model.contacts:
        if c.on_wall:  # (on its own station, or on its building's ground)
            side = "left" if c.left.building < 0 else "right"
            if side not in wall_stations:
                continue
            if side == "left":
                left, right = wall_stations["left"], stations[0]
            else:
                left, right = stations[last], wall_stations["right"]
        else:
            # (the stations of the points' own buildings: a stop's left point may be the
            # right building of its pair, a transverse bridge's key between decks)
            left, right = stations[c.left.building], stations[c.right.building]
        if left != right:
            dof[c.index, width:] = (N + left, N + right)
            w[c.index, width:] = (1.0, -1.0)
        else:
            dof[c.index, width:] = cdof[c.index, 0]
    dof, w = padded_rows(dof, w)
    contacts = ContactRows(dof, w, ct.gap, ct.code, ct.params)
    c_links = None
    if c_links_base is not None and np.any(c_links_base):  # (the links folded into C)
        c_links = np.zeros((n, n))
        c_links[:N, :N] = c_links_base
    return KernelModel(n=n, nz=base.nz, K=K, C=C,
                       arrays=base.arrays._replace(floors=floors, contacts=contacts,
                                                   elements=el._replace(params=par)),
                       free_steps={}, periods_checked=set(), C_links=c_links,
                       linked_block=base.linked_block, adaptive_only=bool(crossing))
