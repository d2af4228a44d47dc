"""Buildings given as matrices: mass ``M``, stiffness ``K`` and damping ``C`` read from files.

A linear lateral model of a building modelled elsewhere (ETABS, SAP2000, OpenSees — see
:mod:`pounding.structure.opensees_matrices`) is, for the equation of motion relative to the
ground (Chopra, *Dynamics of Structures*, 4th ed., §9.4),

    M ü + C u̇ + K u = −M r a_g(t),

a symmetric positive-definite mass matrix ``M``, a symmetric positive-definite stiffness matrix
``K`` (the building is restrained against the ground), a symmetric positive semi-definite
damping matrix ``C`` or a damping model that builds it (:mod:`pounding.structure.damping`), and
the influence vector ``r`` of the ground motion (Chopra §9.4.1; all ones when every degree of
freedom (DOF) is a translation along the shaking). Every DOF also carries a label and an
elevation [m].

Formats read (one matrix a file, except ``.npz``):

* plain text (``.csv``, ``.txt``, ``.dat``): numbers only, one row a line, separated by commas
  or by whitespace; ``#`` starts a comment; no header;
* NumPy ``.npy`` (one 2-D array) and ``.npz`` (arrays named ``M``, ``K`` and optionally ``C``);
* Matrix Market ``.mtx`` (read with :func:`scipy.io.mmread`; real or integer, general or
  symmetric, array or coordinate).

Everything is checked on reading and on construction, and a fault raises :class:`ValueError`
in one line that names the file (or the building) and the problem: a matrix that is not
square, not finite or not symmetric (to
:data:`~pounding.structure.matrix_checks.SYMMETRY_RTOL` of its largest entry; the worst
entry is named), sizes that disagree with each other or with the labels, elevations and ``r``,
a stiffness or mass matrix that is not positive definite (Cholesky factorisation; the
smallest eigenvalue is named) and a damping matrix with a negative eigenvalue. Matrix indices
in messages are 0-based, as in NumPy.

The project's time stepper takes lumped (diagonal) masses:
:meth:`MatrixBuilding.lumped_masses` returns them or says which off-diagonal entry is in the
way. :meth:`MatrixBuilding.to_shear_building` turns a matrix building that is a shear
building (Chopra §9.2) back into a :class:`~pounding.structure.ShearBuilding`.

Checking one matrix (and the labels, elevations, ``r`` and floors that go with them) is
:mod:`pounding.structure.matrix_checks`; reading one matrix or a whole building from files
(:func:`~pounding.structure.matrix_files.read_matrix_building`) is
:mod:`pounding.structure.matrix_files`; this module is the building.

In a :class:`pounding.model.PoundingModel` a planar matrix building stands in a row beside
shear buildings: every DOF named in :attr:`MatrixBuilding.floors` (all of them by default) is
a floor's lateral translation along the row at its elevation, where contacts are found and
storey drifts measured (between consecutive floors ordered by elevation); the other DOFs
(rotations, say) take no contact and have no drift. Where a neighbour strikes other DOFs
than the floors — a frame without rigid floors, struck at its outer column line on each side,
or at a column node between its floors — :attr:`MatrixBuilding.faces` names them for each
side. A matrix building has no storey law: storey yielding is the shear building's.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.hysteresis.base import StoreyLaw
from pounding.structure.damping import DampingModel, RayleighDamping
from pounding.structure.floor_arrays import readonly
from pounding.structure.matrix_checks import (
    SYMMETRY_RTOL,
    check_matrix,
    check_positive_definite,
    dof_labels,
    dof_vector,
    floor_indices,
    is_diagonal,
    lumped_masses,
    matrix_shape,
    smallest_eigenvalue,
)
from pounding.structure.modal import ModalResult, modal_result
from pounding.structure.shear_building import ShearBuilding

__all__ = ["MatrixBuilding"]


# --------------------------------------------------------------------------- the building
@dataclass(frozen=True, eq=False, init=False)
class MatrixBuilding:
    """A building's linear lateral model given by its matrices.

    Equation of motion relative to the ground (Chopra §9.4):
    ``M ü + C u̇ + K u = −M r a_g(t)`` (+ contact forces in a
    :class:`~pounding.model.PoundingModel`).

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass matrix [kg] (rotational DOFs: [kg·m²]); symmetric positive definite. It need not
        be diagonal here, but the time stepper will need it to be (:meth:`lumped_masses`).
    K : array_like, shape (n, n)
        Stiffness matrix [N/m]; symmetric positive definite (restrained against the ground).
    labels : sequence of str, length n
        One unique, non-empty label per DOF (for example ``"F1"`` … ``"F5"``).
    elevations : array_like, shape (n,)
        Elevation of each DOF above the ground [m], finite.
    r : array_like, shape (n,), optional
        Influence vector of the ground motion [-] (Chopra §9.4.1); default 1 on the
        ``floors`` (all ones when every DOF is a floor), 0 elsewhere. Not all zero.
    C : array_like, shape (n, n), optional
        Damping matrix [N·s/m], symmetric positive semi-definite. Give ``C`` or ``damping``,
        not both.
    damping : DampingModel, optional
        How ``C`` is built from ``M`` and ``K`` (:class:`RayleighDamping`,
        :class:`ModalDamping`, :mod:`pounding.structure.damping`). With neither ``C`` nor
        ``damping``, 5 % Rayleigh damping at modes 1 and 2 (as :class:`ShearBuilding`).
    name : str
        A label for tables, plots and messages.
    sources : mapping of str to str
        Where each matrix came from (``{"M": "m.csv", "K": "k.csv"}``), named in messages;
        :func:`~pounding.structure.matrix_files.read_matrix_building` fills it in.
    floors : sequence of int or str, optional
        The DOFs that are floor translations along the row (0-based indices or labels);
        default all. Only these have a storey drift and, unless ``faces`` says otherwise,
        meet a neighbour in contact; the default ``r`` is 1 on them and 0 on the others
        (rotations).
    faces : mapping of str to sequence of int or str, optional
        For a side (``"left"``, ``"right"``), the DOFs a neighbour on that side strikes
        (indices or labels; translations along the row at distinct elevations), in place of
        the floors: the outer column line of a frame without rigid floors, say, with any
        column nodes on it. A side not given is struck at the floors.

    Raises
    ------
    ValueError
        One line naming the file or building and the fault (see the module docstring).

    Notes
    -----
    Immutable; the stored arrays are read-only float64, symmetric matrices stored as
    ``(A + Aᵀ)/2``; the matrix methods return fresh writable copies.

    Examples
    --------
    >>> b = MatrixBuilding(M=[[2.0e5, 0.0], [0.0, 1.0e5]],
    ...                    K=[[6.0e7, -2.0e7], [-2.0e7, 2.0e7]],
    ...                    labels=["F1", "F2"], elevations=[3.5, 6.5], name="A")
    >>> b.n, b.is_shear_building()
    (2, True)
    >>> [float(k) for k in b.to_shear_building().stiffnesses]
    [40000000.0, 20000000.0]
    """

    M: NDArray[np.float64]
    K: NDArray[np.float64]
    labels: tuple[str, ...]
    elevations: NDArray[np.float64]
    r: NDArray[np.float64]
    C: NDArray[np.float64] | None
    damping: DampingModel | None
    name: str
    sources: Mapping[str, str]
    floors: tuple[int, ...]
    faces: Mapping[str, tuple[int, ...]]

    def __init__(self, M: ArrayLike, K: ArrayLike, labels: Sequence[str], elevations: ArrayLike,
                 r: ArrayLike | None = None, C: ArrayLike | None = None,
                 damping: DampingModel | None = None, name: str = "",
                 sources: Mapping[str, str] = MappingProxyType({}),
                 floors: Sequence[int | str] | None = None,
                 faces: Mapping[str, Sequence[int | str]] | None = None) -> None:
        if not isinstance(name, str):
            raise ValueError(f"name must be a string (got {name!r})")
        if not isinstance(sources, Mapping):
            raise ValueError(f"sources must map matrix names to where they came from "
                             f"(got {sources!r})")
        given = MappingProxyType({str(k): str(v) for k, v in sources.items()})
        who = f"building {name!r}" if name else "matrix building"

        def where(key: str) -> str:
            return given.get(key, who)

        def _from(key: str) -> str:
            return f" (from {given[key]})" if key in given else ""

        M_ = check_matrix(M, "M", where("M"))
        K_ = check_matrix(K, "K", where("K"))
        if K_.shape != M_.shape:
            raise ValueError(f"{where('K')}: K is {matrix_shape(K_)} but M{_from('M')} is "
                             f"{matrix_shape(M_)}; they must be the same size")
        n = M_.shape[0]
        labels_ = dof_labels(labels, n, who)
        elevations_ = dof_vector("elevations", elevations, n, who)
        floors_ = floor_indices(floors, labels_, who)
        if faces is not None and not isinstance(faces, Mapping):
            raise ValueError(f"{who}: faces must map a side (left, right) to DOFs "
                             f"(got {faces!r})")
        faces_: dict[str, tuple[int, ...]] = {}
        for side, value in (faces or {}).items():
            if side not in ("left", "right"):
                raise ValueError(f"{who}: faces: {side!r} is not a side (left or right)")
            if value is None:
                continue  # (struck at the floors)
            faces_[side] = floor_indices(value, labels_, who, f"faces.{side}")
        r0 = np.zeros(n)
        r0[list(floors_)] = 1.0
        r_ = dof_vector("r", r0 if r is None else r, n, who)
        if not np.any(r_ != 0.0):
            raise ValueError(f"{who}: r is all zero: the ground motion would not move the "
                             "building")
        for side, dofs in faces_.items():
            z = elevations_[list(dofs)]
            for k, d in enumerate(dofs):
                if r_[d] != 1.0:
                    raise ValueError(f"{who}: faces.{side}: {labels_[d]!r} is not a translation "
                                     f"along the row (its r is {r_[d]:g}, not 1); a neighbour "
                                     "strikes translations only")
                same = [labels_[e] for e, ze in zip(dofs, z) if e != d and ze == z[k]]
                if same:
                    raise ValueError(f"{who}: faces.{side}: {labels_[d]!r} and {same[0]!r} are "
                                     f"both at elevation {z[k]:g} m; a face has one DOF at "
                                     "each elevation")
        diagonal, _, _ = is_diagonal(M_)
        if diagonal:
            for k in range(n):
                if not M_[k, k] > 0.0:
                    raise ValueError(f"{where('M')}: M[{k},{k}] = {M_[k, k]:g} must be > 0: every "
                                     "degree of freedom needs a positive mass (condense "
                                     "massless ones out first)")
        check_positive_definite(M_, "M", where("M"),
                                 "every degree of freedom needs mass; condense massless ones "
                                 "out first")
        check_positive_definite(K_, "K", where("K"),
                                 "the building must be restrained against the ground, with no "
                                 "mechanism")
        if C is not None and damping is not None:
            raise ValueError(f"{who}: give a damping matrix C or a damping model, not both")
        if C is not None:
            C_ = check_matrix(C, "C", where("C"))
            if C_.shape != M_.shape:
                raise ValueError(f"{where('C')}: C is {matrix_shape(C_)} but M{_from('M')} is "
                                 f"{matrix_shape(M_)}; they must be the same size")
            scale = float(np.max(np.abs(C_)))
            lam = smallest_eigenvalue(C_)
            if lam < -SYMMETRY_RTOL * scale:
                raise ValueError(f"{where('C')}: C must be positive semi-definite (damping "
                                 f"cannot add energy); its smallest eigenvalue is {lam:.6g}")
        else:
            if damping is None:
                damping = RayleighDamping()
            if not isinstance(damping, DampingModel):
                raise ValueError(f"{who}: damping must be a DampingModel such as "
                                 f"RayleighDamping or ModalDamping (got {damping!r})")
            damping.check(n)
            C_ = np.ascontiguousarray(damping.matrix(M_, K_), dtype=np.float64)
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "M", readonly(M_))
        frozen_set(self, "K", readonly(K_))
        frozen_set(self, "labels", labels_)
        frozen_set(self, "elevations", elevations_)
        frozen_set(self, "r", r_)
        frozen_set(self, "C", None if C is None else readonly(C_))
        frozen_set(self, "damping", damping)
        frozen_set(self, "name", name)
        frozen_set(self, "sources", given)
        frozen_set(self, "floors", floors_)
        frozen_set(self, "faces", MappingProxyType(faces_))
        # the matrices, read-only (private: the methods hand out copies)
        self._C: NDArray[np.float64]
        frozen_set(self, "_C", readonly(C_))

    # ----------------------------------------------------------------- constructors
    @classmethod
    def from_shear_building(cls, building: ShearBuilding) -> MatrixBuilding:
        """The matrix building of a linear :class:`ShearBuilding`: its ``M``, ``K``, damping
        model and floor levels, ``r = 1``, DOFs labelled ``F1`` … ``Fn``.

        Raises
        ------
        ValueError
            If the building has a storey law: a matrix building is linear.
        """
        if building.storey_law is not None:
            raise ValueError(f"building {building.name!r} has a storey law; a matrix building "
                             "is linear (use to_shear_building(storey_law=...) on the way back)")
        return cls(M=building.mass_matrix(), K=building.stiffness_matrix(),
                   labels=tuple(f"F{j + 1}" for j in range(building.n)),
                   elevations=building.floor_levels, damping=building.damping,
                   name=building.name)

    # ----------------------------------------------------------------- matrices
    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return int(self.M.shape[0])

    def mass_matrix(self) -> NDArray[np.float64]:
        """``M`` [kg], shape (n, n), a fresh copy."""
        return np.array(self.M)

    def stiffness_matrix(self) -> NDArray[np.float64]:
        """``K`` [N/m], shape (n, n), a fresh copy."""
        return np.array(self.K)

    def damping_matrix(self) -> NDArray[np.float64]:
        """``C`` [N·s/m], shape (n, n): the given matrix, or the damping model's."""
        return np.array(self._C)

    def influence_vector(self) -> NDArray[np.float64]:
        """``r`` [-], shape (n,), a fresh copy."""
        return np.array(self.r)

    # ----------------------------------------------------------------- in a row of buildings
    @property
    def floor_dofs(self) -> NDArray[np.int64]:
        """The floor DOFs (:attr:`floors`), lowest first (equal elevations: by index)."""
        f = np.array(self.floors, dtype=np.int64)
        return f[np.argsort(self.elevations[f], kind="stable")]

    def floor_below(self) -> NDArray[np.int64]:
        """For every DOF, the floor DOF below it (−1: the ground; −2: not a floor), so that
        the storey drift of floor DOF j is ``u[j] − u[below[j]]`` (``u = 0`` at the ground)."""
        below = np.full(self.n, -2, dtype=np.int64)
        f = self.floor_dofs
        below[f] = np.concatenate(([-1], f[:-1]))
        return below

    def face_dofs(self, side: str) -> NDArray[np.int64]:
        """The DOFs a neighbour on ``side`` (``"left"``, ``"right"``) strikes, lowest first:
        :attr:`faces` of that side, or the floors (:attr:`floor_dofs`)."""
        if side not in self.faces:
            return self.floor_dofs
        f = np.array(self.faces[side], dtype=np.int64)
        return f[np.argsort(self.elevations[f], kind="stable")]

    def face_below(self, side: str) -> NDArray[np.int64]:
        """For every DOF, the DOF below it on the face of ``side`` (−1: the ground; −2: not
        on that face): a point between two of them moves with their linear interpolation
        (floor-to-column contact)."""
        if side not in self.faces:
            return self.floor_below()
        below = np.full(self.n, -2, dtype=np.int64)
        f = self.face_dofs(side)
        below[f] = np.concatenate(([-1], f[:-1]))
        return below

    @property
    def masses(self) -> NDArray[np.float64]:
        """Lumped mass of every DOF [kg] (rotations: [kg·m²]), shape (n,); raises unless
        ``M`` is diagonal (:func:`lumped_masses`)."""
        return self.lumped_masses()

    @property
    def floor_levels(self) -> NDArray[np.float64]:
        """Elevation of every DOF [m], shape (n,) (the :attr:`elevations`; the name every
        building of a row answers to)."""
        return np.array(self.elevations)

    @property
    def heights(self) -> NDArray[np.float64]:
        """Height of the storey below every floor DOF [m] (its elevation less the floor
        below's, or the ground's), shape (n,); NaN for a DOF that is not a floor."""
        below = self.floor_below()
        z = self.elevations
        out = np.full(self.n, np.nan)
        f = below > -2
        out[f] = z[f] - np.where(below[f] >= 0, z[np.maximum(below[f], 0)], 0.0)
        return out

    @property
    def total_height(self) -> float:
        """Elevation of the highest floor [m]."""
        return float(np.max(self.elevations[list(self.floors)]))

    @property
    def total_mass(self) -> float:
        """The mass the ground motion moves, ``rᵀ M r`` [kg] (the sum of the floor masses
        for a building whose DOFs are all floors)."""
        return float(self.r @ self.M @ self.r)

    @property
    def storey_law(self) -> None:
        """None: a matrix building is linear (storey yielding is the shear building's)."""
        return None

    @property
    def is_inelastic(self) -> bool:
        """False: a matrix building has no yielding storeys."""
        return False

    @property
    def yielding(self) -> tuple[int, ...]:
        """No storey follows a storey law (empty): a matrix building is linear."""
        return ()

    def yielding_storey_dofs(self) -> list[tuple[int, int, int, float]]:
        """No yielding storeys (empty): a matrix building is linear."""
        return []

    def storey_law_params(self) -> NDArray[np.float64]:
        """Raises: a matrix building has no storey law."""
        raise ValueError(f"{self._who}: its storeys are linear (no storey_law)")

    def linear_stiffness_matrix(self) -> NDArray[np.float64]:
        """``K`` [N/m], all of it linear (the row of buildings asks every building for the
        stiffness of its linear part)."""
        return self.stiffness_matrix()

    @property
    def yield_forces(self) -> NDArray[np.float64] | None:
        """None: no storey yield shears (linear)."""
        return None

    @property
    def is_lumped(self) -> bool:
        """True if ``M`` is diagonal (to
        :data:`~pounding.structure.matrix_checks.DIAGONAL_RTOL`)."""
        return is_diagonal(self.M)[0]

    def lumped_masses(self) -> NDArray[np.float64]:
        """The diagonal masses [kg], shape (n,); raises unless ``M`` is diagonal
        (:func:`~pounding.structure.matrix_checks.lumped_masses`)."""
        return lumped_masses(self.M, self.sources.get("M", self._who))

    @property
    def _who(self) -> str:
        return f"building {self.name!r}" if self.name else "matrix building"

    # ----------------------------------------------------------------- dynamics
    def modes(self) -> ModalResult:
        """Natural modes: ``K φ = ω² M φ`` solved by :func:`scipy.linalg.eigh` (Chopra §10.2),
        longest period first, mass-normalised shapes, with this building's ``C`` and ``r``
        (:func:`pounding.structure.modal.modal_result`)."""
        return modal_result(self.M, self.K, self._C, self.r)

    @property
    def fundamental_period(self) -> float:
        """Period of mode 1 [s]."""
        return float(self.modes().periods[0])

    # ----------------------------------------------------------------- shear building
    def shear_building_mismatch(self) -> str | None:
        """Why this is not a shear building (Chopra §9.2), or None if it is one.

        It is one when, DOFs ordered from floor 1 up to the roof:

        * ``M`` is diagonal (:data:`~pounding.structure.matrix_checks.DIAGONAL_RTOL`) and
          ``r`` is all ones;
        * the elevations rise strictly from above the ground;
        * ``K`` is tridiagonal with negative off-diagonal entries, and ``K · 1 = k₁ e₁``
          (every row sums to zero but the first, whose sum is the ground storey's stiffness
          ``k₁ = 1ᵀ K 1``, positive as ``K`` is positive definite) — the pattern
          ``K[j,j] = k_j + k_{j+1}``, ``K[j,j+1] = −k_{j+1}`` of
          :func:`pounding.structure.shear_stiffness_matrix`.

        Zero is judged to :data:`SYMMETRY_RTOL` of the largest entry of ``K``.
        """
        K, n = self.K, self.n
        if not self.is_lumped:
            return "M is not diagonal (lumped floor masses)"
        if not np.all(self.r == 1.0):
            return "r is not all ones"
        if not self.elevations[0] > 0.0 or np.any(np.diff(self.elevations) <= 0.0):
            return "elevations do not rise strictly from above the ground, floor 1 first"
        tol = SYMMETRY_RTOL * float(np.max(np.abs(K)))
        band = np.abs(np.subtract.outer(np.arange(n), np.arange(n))) > 1
        if np.any(np.abs(K[band]) > tol):
            i, j = (int(x) for x in np.argwhere(band & (np.abs(K) > tol))[0])
            return f"K is not tridiagonal: K[{i},{j}] = {K[i, j]:.6g}"
        for j in range(n - 1):
            if not -K[j, j + 1] > tol:
                return f"K[{j},{j + 1}] = {K[j, j + 1]:.6g} is not negative"
        sums = K.sum(axis=1)
        for j in range(1, n):
            if abs(sums[j]) > tol:
                return (f"row {j} of K sums to {sums[j]:.6g}, not 0: not the shear-building "
                        "pattern")
        # Row 0's sum, k₁ = 1ᵀ K 1, is > 0 because K is positive definite.
        return None

    def is_shear_building(self) -> bool:
        """True if :meth:`shear_building_mismatch` finds nothing."""
        return self.shear_building_mismatch() is None

    def storey_stiffnesses(self) -> NDArray[np.float64]:
        """Storey stiffnesses [N/m] of a shear building: ``k₁ = K[0,0] + K[0,1]`` (row 0's
        sum), ``k_{j+1} = −K[j,j+1]``; raises if it is not one."""
        why = self.shear_building_mismatch()
        if why is not None:
            raise ValueError(f"{self._who} is not a shear building: {why}")
        K = self.K
        k = np.empty(self.n)
        k[0] = K[0, 0] + (K[0, 1] if self.n > 1 else 0.0)
        k[1:] = -np.diag(K, 1)
        return k

    def to_shear_building(self, damping: DampingModel | None = None,
                          storey_law: StoreyLaw | None = None) -> ShearBuilding:
        """The equivalent :class:`ShearBuilding`.

        Masses from the diagonal of ``M``, storey stiffnesses from ``K``
        (:meth:`storey_stiffnesses`), storey heights from the elevations
        (``h_j = z_j − z_{j−1}``, ``z_0 = 0``).

        Parameters
        ----------
        damping : DampingModel, optional
            Default: this building's damping model. Needed when the building was given a
            damping matrix ``C`` (a shear building takes a model).
        storey_law : StoreyLaw, optional
            Storey yielding for the shear building (``None``: linear).

        Raises
        ------
        ValueError
            If it is not a shear building (saying why), or it has a ``C`` matrix and no
            ``damping`` is given.
        """
        k = self.storey_stiffnesses()
        model = self.damping if damping is None else damping
        if model is None:
            raise ValueError(f"{self._who} was given a damping matrix C; a ShearBuilding takes a "
                             "damping model: pass damping=...")
        z = np.concatenate(([0.0], self.elevations))
        return ShearBuilding(masses=np.diag(self.M).copy(), stiffnesses=k, heights=np.diff(z),
                             damping=model, name=self.name, storey_law=storey_law)

    # ----------------------------------------------------------------- value semantics
    def __eq__(self, other: Any) -> bool:
        if not isinstance(other, MatrixBuilding):
            return NotImplemented
        same_c = ((self.C is None and other.C is None)
                  or (self.C is not None and other.C is not None
                      and np.array_equal(self.C, other.C)))
        return (np.array_equal(self.M, other.M) and np.array_equal(self.K, other.K)
                and self.labels == other.labels
                and np.array_equal(self.elevations, other.elevations)
                and np.array_equal(self.r, other.r)
                and same_c and self.damping == other.damping and self.name == other.name
                and self.floors == other.floors and dict(self.faces) == dict(other.faces))

    __hash__ = None  # type: ignore[assignment]

    # pickling (multiprocessing, copy.deepcopy): ``sources`` is a read-only mapping proxy,
    # which cannot be pickled; it travels as a dict and is made read-only again
    def __getstate__(self) -> dict[str, Any]:
        return {**self.__dict__, "sources": dict(self.sources), "faces": dict(self.faces)}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)
        object.__setattr__(self, "sources", MappingProxyType(dict(state["sources"])))
        object.__setattr__(self, "faces", MappingProxyType(dict(state.get("faces", {}))))
