"""A building on a flexible base: its floors, a footing that sways and rocks, and the soil's
springs and dashpots (soil–structure interaction, the substructure method with a
lumped-parameter soil).

Degrees of freedom: every floor's displacement ``x_j`` relative to the free-field ground
(what a neighbour strikes, as on a fixed base), the footing's sway ``u_f`` [m] and its rocking
``φ`` [rad] (positive: the floors above move along +x, ``z φ`` at elevation ``z``). The
building's own deformation is what is left once the rigid-body motion of its base is taken
out,

    u = T y,   T = [I | −1 | −z],   y = [x, u_f, φ],

so its stiffness and damping act on ``u`` while the masses carry the absolute motion
``x + u_g`` of the floors and ``u_f + u_g`` of the footing (Wolf 1985, *Dynamic
Soil-Structure Interaction*, §2; Chopra §9.4):

    M_y = diag(M, m_f, I_f),
    K_y = Tᵀ K T + diag(0, k_x, k_φ),
    C_y = Tᵀ C T + diag(0, c_x, c_φ),
    r_y = [1, 1, 0].

The building's damping ``C`` is its fixed-base damping matrix (its damping model on its
fixed-base modes), acting on its deformation: the soil's damping is the dashpots', not a
Rayleigh term across the soil springs (the practice for isolated buildings, Ryan & Polanco
2008, carried over). The floors' own rotary inertia is not included.

A massless footing (``m_f = 0``, ``I_f = 0``; either may be zero alone) is condensed out
statically: with ``S`` the footing's static response to the floors (``y_f = −K_ff⁻¹ K_fx x``)
the building keeps its floors only, with ``K̃ = K_xx + K_xf S`` and ``C̃ = [I; S]ᵀ C_y [I; S]``
— the dashpots acting through the footing's static motion, which is exactly the replacement
oscillator of Veletsos & Meek (1974) and Wolf (1985) to first order in the damping: for one
storey of stiffness ``k``, mass ``m`` at height ``h``,

    T̃ = T √(1 + k/k_x + k h²/k_φ),
    ζ̃ = ζ (T/T̃)³ + ζ_x (T_x/T̃)² + ζ_φ (T_φ/T̃)²,   ζ_i = ω̃ c_i / (2 k_i),

``T_x = 2π √(m/k_x)``, ``T_φ = 2π √(m h²/k_φ)`` (the sums of springs in series).

The dashpots are taken at the flexible-base building's first mode (:mod:`.impedance`). Only
buildings whose every degree of freedom is a floor's translation along the row take a
flexible base here (shear buildings, matrix buildings of that kind — their floors first, then
any other lateral DOF such as a column node of a frame without rigid floors, each at its
elevation — and frames, :func:`pounding.structure.frame_linear.frame_on_flexible_base`).
Linear, except a frame with plastic hinges (:mod:`pounding.integrate.frame_run`) and a shear
building with a storey law, each on a footing with mass and rocking inertia.

A shear building with a storey law (yielding storeys) stands on a footing with mass and
rocking inertia, whose sway and rocking are then degrees of freedom (a massless footing is
condensed out statically, which only a linear building allows): each yielding storey's law
reads the building's own deformation, ``d_j = x_j − x_{j−1} − h_j φ`` (``x_0 = u_f``, ``h_j``
the storey's height), and its shear ``V_j`` acts on the floors above and below and as the
moment ``h_j V_j`` on the footing — the row ``j`` of ``Tᵀ`` (:meth:`FlexibleBaseBuilding.
yielding_storey_dofs`); its linear storeys and the soil are in :meth:`FlexibleBaseBuilding.
linear_stiffness_matrix` (``Tᵀ K_lin T`` + the springs). The damping stays the fixed-base
building's on its elastic modes, on its deformation, plus the dashpots.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.contact.geometry import MOVING_BASE
from pounding.structure.foundation.impedance import (
    Footing,
    Impedance,
    footing_dashpots,
    footing_stiffness,
)
from pounding.structure.foundation.soil import Soil
from pounding.structure.matrices import MatrixBuilding
from pounding.structure.modal import eigenmodes
from pounding.structure.shear_building import ShearBuilding

__all__ = ["FlexibleBaseBuilding", "Foundation", "flexible_base", "static_shape"]

SWAY_LABEL = "Fdn"
"""The label of a footing's sway DOF (its rocking: ``Fdn_r``)."""


@dataclass(frozen=True)
class Foundation:
    """What a flexible base adds to a building: its footing, soil and impedance, the
    fixed-base building's periods, and how the footing's sway and rocking follow from the
    building's DOFs (``[u_f, φ] = recovery @ y``; rows of the identity where they are DOFs,
    the static condensation where they are not)."""

    footing: Footing
    soil: Soil
    impedance: Impedance
    fixed_base_periods: NDArray[np.float64]  #: the building's on a rigid base [s]
    recovery: NDArray[np.float64]  #: (2, n) [m/m, rad/m]: u_f and φ from the DOFs
    explicit: tuple[bool, bool]  #: whether sway and rocking are DOFs of the building
    #: the fixed-base building's storey stiffnesses [N/m] where it is a shear building (its
    #: storey shears are ``k_j`` times the deformation drifts), else None
    storey_stiffnesses: NDArray[np.float64] | None = None
    #: (n_0, n) [m/m, m/rad]: the fixed-base building's own deformation ``u = T y`` (its n_0
    #: DOFs relative to the footing's sway and rocking) from the DOFs ``y``
    deformation: NDArray[np.float64] | None = None

    def deformation_drifts(self, displacement: NDArray[np.float64],
                           elevations: NDArray[np.float64]) -> NDArray[np.float64]:
        """The storeys' drifts of the building's own deformation [m] (nt, n_floors),
        ``x_j − x_{j−1} − (z_j − z_{j−1}) φ`` with ``x_0 = u_f`` and ``z_0 = −D`` (the
        footing's base, about which it rocks, ``D`` below the ground), from its DOFs' displacement
        histories (nt, n) (relative to the free-field ground) and its floors' elevations
        [m] — what its storeys feel, without the footing's rigid sway and rocking."""
        u = displacement @ self.recovery.T
        n = elevations.size
        x = displacement[:, :n]
        below = np.concatenate([u[:, :1], x[:, :-1]], axis=1)
        # (the rocking turns about the footing's base, D below the ground: storey 1's lever
        # is z_1 + D, as the footing's rigid motion moves the ground storey's foot by D φ)
        dz = np.diff(elevations, prepend=-self.footing.embedment)
        return np.asarray(x - below - dz[None, :] * u[:, 1:2])

    def base_reactions(self, displacement: NDArray[np.float64],
                       velocity: NDArray[np.float64]) -> tuple[NDArray[np.float64], ...]:
        """The footing's sway [m] and rocking [rad], and the soil's base shear [N] and base
        moment [N·m] on it, ``V = k_x u_f + c_x u̇_f``, ``M = k_φ φ + c_φ φ̇``, from the
        building's displacement and velocity histories (nt, n)."""
        u = displacement @ self.recovery.T
        v = velocity @ self.recovery.T
        imp = self.impedance
        shear = imp.k_x * u[:, 0] + imp.c_x * v[:, 0]
        moment = imp.k_r * u[:, 1] + imp.c_r * v[:, 1]
        return u[:, 0], u[:, 1], shear, moment


class FlexibleBaseBuilding(MatrixBuilding):
    """A building on a flexible base (module docstring): a
    :class:`~pounding.structure.MatrixBuilding` whose matrices include the footing and soil,
    and its :attr:`foundation`; and, when the building on it is a shear building with a
    storey law, its yielding storeys (:attr:`storey_law`, :meth:`yielding_storey_dofs`).
    Made by :func:`flexible_base`."""

    foundation: Foundation
    #: the building on its fixed base (its storeys, their law)
    fixed_base: ShearBuilding | MatrixBuilding

    def __init__(self, foundation: Foundation, fixed_base: ShearBuilding | MatrixBuilding,
                 linear_stiffness: NDArray[np.float64] | None = None,
                 **matrices: Any) -> None:
        super().__init__(**matrices)
        object.__setattr__(self, "foundation", foundation)
        object.__setattr__(self, "fixed_base", fixed_base)
        object.__setattr__(self, "_linear_k", linear_stiffness)

    # ----------------------------------------------------------------- yielding storeys
    @property
    def storey_law(self) -> Any:  # (the fixed-base shear building's law, or None)
        """The storey law of the building on the footing (None: linear)."""
        return getattr(self.fixed_base, "storey_law", None)

    @property
    def is_inelastic(self) -> bool:
        """True if the building on the footing has yielding storeys."""
        return self.storey_law is not None

    @property
    def yielding(self) -> tuple[int, ...]:
        """The yielding storeys (0-based; storey ``j`` under floor ``j``, the floors being
        this building's first DOFs)."""
        return tuple(self.fixed_base.yielding) if self.storey_law is not None else ()

    def storey_law_params(self) -> NDArray[np.float64]:
        """The constants of every yielding storey's law (the fixed-base building's)."""
        assert isinstance(self.fixed_base, ShearBuilding)
        return self.fixed_base.storey_law_params()

    def yielding_storey_dofs(self) -> list[tuple[int, int, int, float]]:
        """``(lower, upper, rock, lever)`` of every yielding storey: its drift is the
        building's own deformation ``u[upper] − u[lower] − lever · φ``, with ``lower`` the
        footing's sway DOF under the first storey and ``rock`` the footing's rocking DOF,
        ``lever`` the storey's height [m] (module docstring: ``u = T y``)."""
        n = self.fixed_base.n  # (a shear building: its DOFs are its floors)
        sway, rock = n, n + 1  # (both DOFs of a footing under a yielding building)
        z = np.r_[-self.foundation.footing.embedment, self.elevations[:n]]  # (from its base)
        return [(j - 1 if j > 0 else sway, j, rock, float(z[j + 1] - z[j]))
                for j in self.yielding]

    @property
    def yield_forces(self) -> NDArray[np.float64] | None:
        """The storeys' yield shears [N] under the floors (NaN for linear storeys and for
        the footing's DOFs); None if the building is linear."""
        fy = getattr(self.fixed_base, "yield_forces", None)
        if fy is None:
            return None
        out = np.full(self.n, np.nan)
        out[: len(self.floors)] = fy
        return out

    def face_below(self, side: str) -> NDArray[np.int64]:
        """:meth:`MatrixBuilding.face_below`, except below the lowest DOF of the face: the
        foot of the ground storey moves with the footing, ``u_f + D φ``, not with the
        ground — the footing's sway DOF for a surface footing with mass (a column point of
        the ground storey between it and the floor above moves as their interpolation,
        exactly: the rocking's part is linear in the height too), else
        :data:`~pounding.contact.geometry.MOVING_BASE` (a column point there is refused)."""
        below = super().face_below(side)
        low = int(self.face_dofs(side)[0])
        sway = self.fixed_base.n  # (the footing's sway DOF, where it is one)
        explicit = self.foundation.explicit[0] and self.foundation.footing.embedment == 0.0
        below[low] = sway if explicit else MOVING_BASE
        return below

    def linear_stiffness_matrix(self) -> NDArray[np.float64]:
        """``Tᵀ K_lin T`` + the soil's springs [N/m]: the stiffness of the storeys that stay
        linear (the yielding ones' shears come from their law), on the footing."""
        k = self._linear_k  # type: ignore[attr-defined]
        return self.stiffness_matrix() if k is None else k

    def __eq__(self, other: Any) -> bool:
        same = super().__eq__(other)
        if same is NotImplemented or not same:
            return same
        return (isinstance(other, FlexibleBaseBuilding)
                and self.foundation.footing == other.foundation.footing
                and self.foundation.soil == other.foundation.soil)

    __hash__ = None


def static_shape(K: NDArray[np.float64], keep: NDArray[np.int64]) -> NDArray[np.float64]:
    """The static shape ``Φ`` (n × n_keep) that gives every DOF from the kept ones,
    ``y = Φ y_keep``: the identity on the kept DOFs, ``−K_dd⁻¹ K_dk`` on the dropped ones
    (Guyan's static condensation of a massless footing's DOFs; the reduced matrices are
    ``Φᵀ A Φ``)."""
    n = K.shape[0]
    drop = np.setdiff1d(np.arange(n), keep)
    Phi = np.zeros((n, keep.size))
    Phi[keep, np.arange(keep.size)] = 1.0
    if drop.size:
        Phi[drop] = -np.linalg.solve(K[np.ix_(drop, drop)], K[np.ix_(drop, keep)])
    return Phi


def _first_omega(M: NDArray[np.float64], K: NDArray[np.float64]) -> float:
    return float(eigenmodes(M, K)[0][0])


def flexible_base(building: ShearBuilding | MatrixBuilding, footing: Footing,
                  soil: Soil) -> FlexibleBaseBuilding:
    """``building`` on ``footing`` on ``soil`` (module docstring).

    Parameters
    ----------
    building : ShearBuilding or MatrixBuilding
        The fixed-base building: every DOF a translation along the row (``r`` = 1) at its
        elevation above the footing's base [m], the floors first (a matrix building's floors
        and faces carry over); a shear building may yield (its storey law) on a footing
        with mass and inertia.
    footing : Footing
        The footing, its mass and rocking inertia (zero: condensed out).
    soil : Soil
        The half-space under it.

    Raises
    ------
    ValueError
        If the building has a storey law and the footing no mass or no rocking inertia, is
        base-isolated, or has a DOF that is not a floor's translation.

    Examples
    --------
    The issue's example: a one-storey building of 1.0e6 kg, T = 0.5 s, h = 10 m, on a
    massless disk of radius 5 m on V_s = 150 m/s, ρ = 1800 kg/m³, ν = 0.33:

    >>> b = ShearBuilding.sdof(1.0e6, period=0.5, height=10.0)
    >>> fb = flexible_base(b, Footing(radius=5.0), Soil(150.0, 1800.0, 0.33))
    >>> round(float(fb.modes().periods[0]), 4)
    0.6976
    """
    name = building.name
    yielding = getattr(building, "storey_law", None) is not None
    if yielding and not (footing.mass > 0.0 and footing.inertia > 0.0):
        what = "mass" if footing.mass <= 0.0 else "inertia"
        raise ValueError(f"building {name!r}: foundation.{what}: a yielding building's footing "
                         f"needs its mass and rocking inertia (got {what} = 0): its sway and "
                         "rocking are then degrees of freedom (a massless footing is condensed "
                         "out, which only a linear building allows)")
    if getattr(building, "isolator", None) is not None:
        raise ValueError(f"building {name!r}: foundation: not under a base-isolated building")
    floors: list[int] = list(range(building.n))
    faces = None
    if isinstance(building, MatrixBuilding):
        r = building.influence_vector()
        floors = [int(f) for f in building.floors]
        if not np.all(r == 1.0) or floors != list(range(len(floors))):
            raise ValueError(f"building {name!r}: foundation: every degree of freedom must be "
                             "a translation along the row (r = 1), the floors first, to take "
                             "a flexible base")
        labels = list(building.labels)
        faces = dict(building.faces) or None
    else:
        labels = [f"F{j + 1}" for j in range(building.n)]
    M0 = building.mass_matrix()
    K0 = building.stiffness_matrix()
    C0 = building.damping_matrix()
    z = np.asarray(building.floor_levels if isinstance(building, ShearBuilding)
                   else building.elevations, dtype=float)
    n = M0.shape[0]
    fixed_periods = 2.0 * np.pi / eigenmodes(M0, K0)[0]
    T = np.zeros((n, n + 2))
    T[:, :n] = np.eye(n)
    T[:, n] = -1.0
    T[:, n + 1] = -(z + footing.embedment)  # (levers from the footing's base, D below ground)
    k_x, k_r = footing_stiffness(footing, soil)
    M = np.zeros((n + 2, n + 2))
    M[:n, :n] = M0
    M[n, n] = footing.mass
    M[n + 1, n + 1] = footing.inertia
    K = T.T @ K0 @ T
    K[n, n] += k_x
    K[n + 1, n + 1] += k_r
    K_lin = None
    if yielding:  # (footing DOFs explicit: nothing condensed)
        K_lin = T.T @ building.linear_stiffness_matrix() @ T
        K_lin[n, n] += k_x
        K_lin[n + 1, n + 1] += k_r
        K_lin = 0.5 * (K_lin + K_lin.T)
    keep = np.r_[np.arange(n), [n] if footing.mass > 0.0 else [], [n + 1] if footing.inertia > 0.0
                 else []].astype(np.int64)
    Phi = static_shape(K, keep)  # every DOF of y from the kept ones, y = Φ y_keep
    M_k = Phi.T @ M @ Phi
    K_k = Phi.T @ K @ Phi
    omega = _first_omega(M_k, K_k)
    c_x, c_r = footing_dashpots(footing, soil, omega)
    C = T.T @ C0 @ T
    C[n, n] += c_x
    C[n + 1, n + 1] += c_r
    C_k = Phi.T @ C @ Phi
    # (exactly symmetric, as the matrix building stores them)
    M_k, K_k, C_k = (0.5 * (A + A.T) for A in (M_k, K_k, C_k))
    extra = [lab for lab, d in ((SWAY_LABEL, n), (f"{SWAY_LABEL}_r", n + 1)) if d in keep]
    storeys = (np.asarray(building.stiffnesses, dtype=float)
               if isinstance(building, ShearBuilding) else
               building.storey_stiffnesses() if building.is_shear_building() else None)
    foundation = Foundation(footing, soil, Impedance(k_x, k_r, c_x, c_r, omega), fixed_periods,
                            Phi[[n, n + 1]], (footing.mass > 0.0, footing.inertia > 0.0),
                            storeys, T @ Phi)
    return FlexibleBaseBuilding(
        foundation, building, K_lin, M=M_k, K=K_k, C=C_k, labels=labels + extra,
        elevations=np.r_[z, np.zeros(len(extra))],
        r=np.r_[np.ones(n), np.ones(1 if footing.mass > 0.0 else 0),
                np.zeros(1 if footing.inertia > 0.0 else 0)],
        name=name, floors=floors, faces=faces)
