"""The animation of buildings in plan (:class:`pounding.structure.plan.PlanBuilding`): their
rigid floor slabs seen from above, moving and rotating.

Every floor ``j`` has three degrees of freedom at its centre of mass ``(x_c, y_c)``: ``u_x``,
``u_y`` and the rotation ``θ`` (counter-clockwise). A point ``(x, y)`` of the slab moves by
``u_x − (y − y_c) θ`` along x and ``u_y + (x − x_c) θ`` along y
(:meth:`~pounding.structure.plan.PlanBuilding.point_weights`), the small-rotation kinematics
the contacts are computed with — so a corner drawn ``× exaggeration`` touches its neighbour
exactly when the contact there closes (the gaps drawn × the same factor). The top floor is
drawn bold, the floors below it faint; buildings stand left to right along x at their site
y; each contact is marked where it struck, at the middle of its two points.

Reads the model (its plans and contacts: rebuilt from the run's ``model.toml``) beside the
histories; see :mod:`pounding.plot.animate` for what is common to every kind.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from pounding.plot.animate import (
    AnimationFrames,
    Shape,
    Vertex,
    Weights,
    assemble,
    contact_histories,
    exaggeration_for,
    timeline,
)

__all__ = ["is_plan", "plan_frames"]

_POINT = re.compile(r"F(\d+)@y=(.+)$")


def is_plan(model: Any) -> bool:
    """True if every building of ``model`` is a building in plan."""
    return bool(model.buildings) and all(getattr(b, "plan", None) is not None
                                         for b in model.buildings)


def _point(plan: Any, off: int, floor: int, x: float, y: float, scale: float = 1.0
           ) -> tuple[Weights, Weights]:
    """Channel weights (along x, along y) of the slab point at plan ``(x, y)`` of ``floor``
    (0-based) of the building whose DOFs start at column ``off``."""
    xc, yc = (float(v) for v in plan.mass_centres[floor])
    base = off + 3 * floor
    return (((base, scale), (base + 2, -scale * (y - yc))),
            ((base + 1, scale), (base + 2, scale * (x - xc))))


def plan_frames(ds: Any, model: Any, *, fps: float = 25.0, exaggeration: float | None = None,
                start: float | None = None, end: float | None = None,
                title: str = "") -> AnimationFrames:
    """The frames of a row of buildings in plan (module docstring); arguments as
    :func:`pounding.plot.animate.animation_frames`, and ``model`` the run's
    :class:`~pounding.model.PoundingModel`.

    Raises
    ------
    ValueError
        An option out of range, or histories that are not the model's (one line).
    """
    tl = timeline(ds, fps, exaggeration, start, end)
    n_dof = sum(3 * b.plan.n_floors for b in model.buildings)
    if ds.sizes.get("floor") != n_dof:
        raise ValueError(f"animate: the histories hold {ds.sizes.get('floor')} degrees of "
                         f"freedom, the model's buildings in plan {n_dof}: not this run's model")
    offsets = [int(o) for o in model.system.offsets]
    plans = [b.plan for b in model.buildings]
    gaps: dict[int, float] = {}
    for c in model.contacts:
        bl, br = c.left.building, c.right.building
        if bl >= 0 and br == bl + 1:
            gaps[bl] = min(gaps.get(bl, c.gap), c.gap)
    size = max(max(p.width, p.depth) for p in plans)

    def shapes_at(factor: float) -> tuple[list[Shape], list[float]]:
        shapes: list[Shape] = []
        lefts: list[float] = []
        x0 = 0.0
        for i, (p, off) in enumerate(zip(plans, offsets, strict=True)):
            lefts.append(x0)
            for j in range(p.n_floors):
                corners = []
                for x, y in ((0.0, 0.0), (p.width, 0.0), (p.width, p.depth), (0.0, p.depth)):
                    wx, wy = _point(p, off, j, x, y)
                    corners.append(Vertex(x0 + x, p.site_y + y, wx, wy))
                top = j == p.n_floors - 1
                shapes.append(Shape(tuple(corners), "slab" if top else "lower", closed=True))
            x0 += p.width + gaps.get(i, 0.1 * size / max(factor, 1.0)) * factor
        return shapes, lefts

    factor = tl.exaggeration
    if factor is None:
        u = np.asarray(ds["displacement"].values, dtype=float)[tl.window]
        factor = tl.exaggeration = exaggeration_for(u, shapes_at(1.0)[0], size)
    shapes, lefts = shapes_at(factor)
    labels = [(f"B{i + 1}", Vertex(lefts[i] + 0.5 * p.width, p.site_y + 1.04 * p.depth))
              for i, p in enumerate(plans)]

    names, _, _ = contact_histories(ds, tl.t.size)
    by_label = {c.label: c for c in model.contacts}
    marks: list[Vertex | None] = []
    for label in names:
        c = by_label.get(label)
        ends = [] if c is None else [(c.left, True), (c.right, False)]
        parsed = [(e.building, _POINT.search(e.name or ""), is_left) for e, is_left in ends]
        if len(parsed) != 2 or any(b < 0 or m is None for b, m, _ in parsed):
            marks.append(None)  # a wall, a link, or a contact with no point in plan
            continue
        xs: list[float] = []
        ys: list[float] = []
        wx: list[tuple[int, float]] = []
        wy: list[tuple[int, float]] = []
        for b, m, is_left in parsed:
            assert m is not None
            p = plans[b]
            floor, y_site = int(m.group(1)) - 1, float(m.group(2))
            x_local = p.width if is_left else 0.0
            a, bw = _point(p, offsets[b], floor, x_local, y_site - p.site_y, 0.5)
            xs.append(lefts[b] + x_local)
            ys.append(y_site)
            wx += a
            wy += bw
        marks.append(Vertex(float(np.mean(xs)), float(np.mean(ys)), tuple(wx), tuple(wy)))
    return assemble(ds, tl, title=title, columns=list(range(n_dof)), shapes=shapes,
                    labels=labels, marks=marks, size=size, view="plan",
                    y_label="plan y [m]", equal_scales=True,
                    notes=[("Plan view from above: the slabs' corners moved × the factor "
                            "(the top floor bold)")])
