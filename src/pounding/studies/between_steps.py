"""Between output steps: the peak of a sampled history on its cubic Hermite interpolant,
and each building's ground motion on the output grid. What the gap study
(:mod:`pounding.studies.gap`) and a sweep's bridge columns
(:mod:`pounding.studies.sweep.bridge_measures`) both read a run with.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["ground_fields", "ground_histories", "hermite_max", "wall_ground_histories"]

FloatArray = NDArray[np.float64]


def hermite_max(y: ArrayLike, dy: ArrayLike, dt: float) -> tuple[FloatArray, FloatArray]:
    """Largest value and its time of the piecewise cubic Hermite interpolant of samples.

    On each step ``[t_k, t_k + dt]`` the cubic matching ``y`` and its derivative ``dy`` at
    both ends is maximised exactly (its stationary points are the roots of a quadratic), so
    a peak between samples is not missed. The interpolation error is at most
    ``dt⁴ max|y''''| / 384``.

    Parameters
    ----------
    y, dy : array_like, shape (nt,) or (nt, m)
        Samples at ``k·dt`` and their time derivatives, column by column.
    dt : float
        Sample step [s].

    Returns
    -------
    value, time : ndarray, shape (m,) (or scalars' 0-d arrays for 1-D input)
    """
    Y = np.asarray(y, dtype=float)
    D = np.asarray(dy, dtype=float)
    one = Y.ndim == 1
    if one:
        Y, D = Y[:, None], D[:, None]
    nt = Y.shape[0]
    if nt == 1:
        val, tm = Y[0].copy(), np.zeros(Y.shape[1])
        return (val[0], tm[0]) if one else (val, tm)
    y0, y1 = Y[:-1], Y[1:]
    m0, m1 = D[:-1] * dt, D[1:] * dt
    # p(s) = a s³ + b s² + c s + y0 on s ∈ [0, 1]
    a = 2.0 * y0 + m0 - 2.0 * y1 + m1
    b = -3.0 * y0 - 2.0 * m0 + 3.0 * y1 - m1
    c = m0
    A, B, C = 3.0 * a, 2.0 * b, c
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        disc = B * B - 4.0 * A * C
        sq = np.sqrt(np.maximum(disc, 0.0))
        q = -0.5 * (B + np.where(B >= 0.0, sq, -sq))
        s1 = np.where(A != 0.0, q / A, np.nan)
        s2 = np.where(q != 0.0, C / q, np.nan)
    ok = disc >= 0.0
    best = np.maximum(y0, y1)
    sbest = np.where(y1 > y0, 1.0, 0.0)
    for s in (s1, s2):
        valid = ok & np.isfinite(s) & (s > 0.0) & (s < 1.0)
        ss = np.where(valid, s, 0.0)
        p = ((a * ss + b) * ss + c) * ss + y0
        better = valid & (p > best)
        best = np.where(better, p, best)
        sbest = np.where(better, ss, sbest)
    k = np.argmax(best, axis=0)
    cols = np.arange(Y.shape[1])
    val = best[k, cols]
    tm = (k + sbest[k, cols]) * dt
    return (val[0], tm[0]) if one else (val, tm)


def ground_histories(motion: object, n_buildings: int, dt: float, nt: int
                     ) -> list[tuple[FloatArray, FloatArray]]:
    """Each building's ground displacement [m] and velocity [m/s] at the ``nt`` output
    steps ``dt`` apart: all zero under one record;
    under a :class:`~pounding.ground_motion.spatial.SpatialMotion` its record integrated
    exactly (linear between samples, from rest), as the time stepper integrates it (the
    absolute ground displacement: only differences between grounds enter a gap)."""
    from pounding.ground_motion.spatial import SpatialMotion

    zero = np.zeros(nt)
    if not isinstance(motion, SpatialMotion):
        return [(zero, zero)] * n_buildings
    from pounding.integrate.grid import ground_displacement_on_grid

    return [ground_displacement_on_grid(rec, dt, nt) for rec in motion.records]


def wall_ground_histories(motion: object, dt: float, nt: int
                          ) -> dict[str, tuple[FloatArray, FloatArray]]:
    """The ground displacement [m] and velocity [m/s] of each end wall on a ground of its
    own (by side, :attr:`~pounding.ground_motion.spatial.SpatialMotion.walls`), as
    :func:`ground_histories`; empty when the walls stand on their buildings' grounds."""
    from pounding.ground_motion.spatial import SpatialMotion

    if not isinstance(motion, SpatialMotion):
        return {}
    from pounding.integrate.grid import ground_displacement_on_grid

    return {side: ground_displacement_on_grid(rec, dt, nt)
            for side, rec in motion.walls.items()}


def ground_fields(motion: object, model: object, dt: float, nt: int) -> dict[str, object]:
    """What :func:`pounding.integrate.simulate` keeps of the grounds in a
    :class:`~pounding.result.Result` on spatially varying ground (``building_ground``,
    ``wall_ground``, ``link_ground``), rebuilt from the records as the stepper integrates
    them — for a Result read back from its files; empty (all None) on one ground."""
    from pounding.ground_motion.spatial import SpatialMotion

    if not isinstance(motion, SpatialMotion) or len(motion.stations()[1]) < 2:
        return {}
    nb = len(model.buildings)  # type: ignore[attr-defined]
    grounds = ground_histories(motion, nb, dt, nt)
    building = np.stack([np.column_stack([g[0] for g in grounds]),
                         np.column_stack([g[1] for g in grounds])])
    walls = {side: np.stack(g) for side, g in wall_ground_histories(motion, dt, nt).items()}
    links = model.links  # type: ignore[attr-defined]
    link = None
    if links:  # (each link's grounds' offset: its right end's building's less its left's)
        link = np.stack([building[:, :, lk.ends[1][0]] - building[:, :, lk.ends[0][0]]
                         for lk in links], axis=2)
    return {"building_ground": building, "wall_ground": walls or None, "link_ground": link}
