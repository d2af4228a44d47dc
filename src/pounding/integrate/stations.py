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

Not yet: buildings in plan (two ground components), links between buildings on different
stations, yielding frames (refused in one line).
"""

from __future__ import annotations

import numpy as np

from pounding.integrate.kernel_model import (
    ContactRows,
    KernelModel,
    kernel_bands,
    kernel_model,
    padded_rows,
    remembered_for,
)
from pounding.integrate.layout import STATION_MASS
from pounding.model import PoundingModel

__all__ = ["STATION_MASS", "station_kernel_model"]


_STATION_MODELS: dict[tuple[int, tuple[int, ...]], KernelModel] = {}


def _check(model: PoundingModel, stations: tuple[int, ...]) -> None:
    # (one record per building: simulate's own check, before the stations are counted)
    if model.system.r.ndim != 1:
        raise ValueError("motion: buildings in plan (two ground components) on spatially "
                         "varying ground are not modelled yet; give one record for the row")
    if model.yielding_frames:
        raise ValueError("motion: yielding frames on spatially varying ground are not modelled "
                         "yet; give one record for the row")
    for link in model.links:
        b = {e[0] for e in link.ends}
        if len({stations[i] for i in b}) > 1:
            raise ValueError(f"motion: link {link.name} joins buildings on different grounds "
                             f"({', '.join(f'B{i + 1}' for i in sorted(b))}); links between "
                             "differently shaken buildings are not modelled yet")


def station_kernel_model(model: PoundingModel, stations: tuple[int, ...]) -> KernelModel:
    """The model's :class:`~pounding.integrate.kernel_model.KernelModel` with each building
    on the ground of its station ``stations[b]`` (0 … S − 1) and the S stations' ground
    displacements as DOFs ``N … N + S − 1`` (module docstring); remembered like
    :func:`~pounding.integrate.kernel_model.kernel_model`.

    Raises
    ------
    ValueError
        For what is not modelled yet (module docstring), in one line.
    """
    _check(model, stations)
    return remembered_for(model, _STATION_MODELS, (id(model), stations),
                          lambda: _assemble(model, stations))


def _assemble(model: PoundingModel, stations: tuple[int, ...]) -> KernelModel:
    """:func:`station_kernel_model`, assembled."""
    base = kernel_model(model)
    N = base.n
    S = max(stations) + 1
    n = N + S
    fl = base.floors
    r = np.zeros((n, S))
    offsets = model.system.offsets
    for b, bl in enumerate(model.buildings):
        rows = slice(int(offsets[b]), int(offsets[b]) + bl.n)
        r[rows, stations[b]] = fl.r[rows, 0]
    r[N + np.arange(S), np.arange(S)] = -1.0
    m_diag = np.r_[fl.m_diag, np.full(S, STATION_MASS)]
    m_inv = np.r_[fl.m_inv, np.ones(S)]  # (what the contacts push is taken back: rhs.deriv)
    K = np.zeros((n, n))
    K[:N, :N] = base.K
    C = np.zeros((n, n))
    C[:N, :N] = base.C
    below = np.r_[fl.below, N + np.arange(S)]  # (a station is not a floor: no drift)
    k_band, c_band = kernel_bands(K, C, fl.bw)
    floors = fl._replace(k_band=k_band, c_band=c_band,
                         m_diag=m_diag, m_inv=m_inv, mr=np.ascontiguousarray(m_diag[:, None] * r),
                         r=np.ascontiguousarray(r), below=below)
    ct = base.contacts
    cdof, cw = ct.dof, ct.weight
    nc, width = cdof.shape
    dof = np.concatenate([cdof, np.zeros((nc, 2), dtype=np.int64)], axis=1)
    w = np.concatenate([cw, np.zeros((nc, 2))], axis=1)
    for c in model.contacts:
        if c.on_wall:
            continue  # (a moat wall stands on its building's ground)
        left, right = stations[c.pair], stations[c.pair + 1]
        if left != right:
            dof[c.index, width:] = (N + left, N + right)
            w[c.index, width:] = (1.0, -1.0)
        else:
            dof[c.index, width:] = cdof[c.index, 0]
    dof, w = padded_rows(dof, w)
    contacts = ContactRows(dof, w, ct.gap, ct.code, ct.params)
    c_links = None
    if base.C_links is not None:  # (the links folded into C: within one station)
        c_links = np.zeros((n, n))
        c_links[:N, :N] = base.C_links
    return KernelModel(n=n, nz=base.nz, K=K, C=C,
                       arrays=base.arrays._replace(floors=floors, contacts=contacts),
                       free_steps={}, periods_checked=set(), C_links=c_links,
                       linked_block=base.linked_block)
