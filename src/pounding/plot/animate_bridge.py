"""The animation of a bridge (:mod:`pounding.structure.bridge`): its deck frames along the
bridge, the joints between them and the abutments opening and closing, impacts marked.

* **Along the axis** (longitudinal): an elevation. The abutments' backwalls stand at both
  ends; every frame's deck is a bold line of its length (the sum of its spans) at the
  deck's elevation, moved along the axis by ``exaggeration × u_deck``; its piers stand at
  the span ends inside the frame, their caps moved by their own DOF. Decks and backwalls are
  drawn the model's gaps × the same factor apart, so a joint drawn shut is a joint shut.
* **Across the axis** (``direction = "transverse"``): a plan. The decks lie along x and sway
  across (y) by ``exaggeration × u_deck``, between the shear keys at the abutments (drawn
  at ± their gap × the factor); the keys at a joint act between the two decks.

Each contact (a joint, a backwall, a key) is marked where it struck. Reads the model's
frames and contacts (the run's ``model.toml`` rebuilt) beside the histories; what is
common to every kind is in :mod:`pounding.plot.animate`.
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

__all__ = ["DEFAULT_DECK_LENGTH", "bridge_frames", "is_bridge_model"]

DEFAULT_DECK_LENGTH = 30.0
"""Drawn length of a deck whose spans were not given [m]."""

_ABUTMENT = re.compile(r"^A(\d+)([+-]y)?$")


def is_bridge_model(model: Any) -> bool:
    """True if every building of ``model`` is a bridge frame (a deck on piers)."""
    return bool(model.buildings) and all(hasattr(b, "deck_dof") and hasattr(b, "piers")
                                         for b in model.buildings)


def bridge_frames(ds: Any, model: Any, *, transverse: bool = False, fps: float = 25.0,
                  exaggeration: float | None = None, start: float | None = None,
                  end: float | None = None, title: str = "") -> AnimationFrames:
    """The frames of a bridge (module docstring); arguments as
    :func:`pounding.plot.animate.animation_frames`, ``model`` the run's
    :class:`~pounding.model.PoundingModel` and ``transverse`` its direction.

    Raises
    ------
    ValueError
        An option out of range, or histories that are not the model's (one line).
    """
    tl = timeline(ds, fps, exaggeration, start, end)
    frames = list(model.buildings)
    offsets = [int(o) for o in model.system.offsets]
    n_dof = sum(int(f.n) for f in frames)
    if ds.sizes.get("floor") != n_dof:
        raise ValueError(f"animate: the histories hold {ds.sizes.get('floor')} degrees of "
                         f"freedom, the bridge's frames {n_dof}: not this run's model")
    lengths = [f.deck_length or DEFAULT_DECK_LENGTH for f in frames]
    deck = [off + int(f.deck_dof) for f, off in zip(frames, offsets, strict=True)]
    elevation = max(float(f.elevations[f.deck_dof]) for f in frames)
    joint_gap: dict[int, float] = {}
    wall_gap: dict[str, float] = {}
    for c in model.contacts:
        bl, br = c.left.building, c.right.building
        if bl >= 0 and br >= 0 and abs(br - bl) == 1:
            lo = min(bl, br)
            joint_gap[lo] = min(joint_gap.get(lo, c.gap), c.gap)
        for end_ in (c.left, c.right):
            if end_.building < 0 and _ABUTMENT.match(end_.name or ""):
                wall_gap[end_.name] = min(wall_gap.get(end_.name, c.gap), c.gap)
    size = max(lengths) / 2.0
    total = sum(lengths)

    def layout(factor: float) -> tuple[list[Shape], list[float], float]:
        """Shapes, the decks' left ends and the right abutment's x at ``factor``."""
        shapes: list[Shape] = []
        starts: list[float] = []
        x = 0.0 if transverse else wall_gap.get("A1", 0.0) * factor
        for i, (f, off) in enumerate(zip(frames, offsets, strict=True)):
            starts.append(x)
            w: Weights = ((deck[i], 1.0),)
            a, b = (Vertex(x, 0.0, (), w), Vertex(x + lengths[i], 0.0, (), w)) if transverse \
                else (Vertex(x, elevation, w), Vertex(x + lengths[i], elevation, w))
            shapes.append(Shape((a, b), "deck"))
            for k, pier in enumerate(f.piers):
                xp = x + _pier_position(f, k, lengths[i])
                cap: Weights = ((off + int(f.cap_dof(k)), 1.0),)
                if transverse:
                    half = 0.02 * total
                    shapes.append(Shape((Vertex(xp, -half, (), cap), Vertex(xp, half, (), cap)),
                                        "pier"))
                else:
                    shapes.append(Shape((Vertex(xp, 0.0), Vertex(xp, float(pier.height), cap)),
                                        "pier"))
            x += lengths[i]
            if i < len(frames) - 1:
                x += (0.02 * total if transverse
                      else joint_gap.get(i, 0.01 * total / factor) * factor)
        last = [g for name, g in wall_gap.items() if not name.startswith("A1")]
        right = x + (0.0 if transverse else min(last, default=0.0) * factor)
        if transverse:  # the abutments' keys, fixed, at ± their gap
            for name, gap in wall_gap.items():
                m = _ABUTMENT.match(name)
                assert m is not None
                xk = 0.0 if m.group(1) == "1" else right
                yk = (gap if m.group(2) == "+y" else -gap) * factor
                shapes.append(Shape((Vertex(xk - 0.01 * total, yk), Vertex(xk + 0.01 * total,
                                                                             yk)), "wall"))
        else:  # the backwalls
            for xw in (0.0, right):
                shapes.append(Shape((Vertex(xw, 0.0), Vertex(xw, 1.15 * elevation)), "wall"))
        return shapes, starts, right

    factor = tl.exaggeration
    if factor is None:
        u = np.asarray(ds["displacement"].values, dtype=float)[tl.window]
        factor = tl.exaggeration = exaggeration_for(u, layout(1.0)[0], size)
    shapes, starts, right = layout(factor)
    y_label = 0.0 if transverse else 1.08 * elevation
    labels = [(f"B{i + 1}", Vertex(starts[i] + 0.5 * lengths[i], y_label))
              for i in range(len(frames))]

    names, _, _ = contact_histories(ds, tl.t.size)
    by_label = {c.label: c for c in model.contacts}
    marks = [_mark(by_label.get(label), transverse, starts, lengths, deck, right, elevation,
                   wall_gap, factor) for label in names]
    if transverse:
        what = ("Plan from above: the decks sway across the axis (y × the factor) between the "
                "shear keys; x along the bridge to scale")
    else:
        what = ("Elevation along the bridge: decks, piers and backwalls; the decks move along "
                "the axis × the factor, the joints and backwall gaps drawn × the same factor")
    return assemble(ds, tl, title=title, columns=list(range(n_dof)), shapes=shapes,
                    labels=labels, marks=marks, size=size,
                    view="plan" if transverse else "elevation",
                    y_label="across the axis [m of drawing]" if transverse
                    else "elevation [m]", notes=[what])


def _pier_position(frame: Any, k: int, length: float) -> float:
    """Where pier ``k`` stands along its frame [m]: at the inner span ends, else evenly."""
    spans = list(frame.spans or [])
    n = len(frame.piers)
    if len(spans) == n + 1:
        return float(np.cumsum(spans)[k])
    return length * (k + 1) / (n + 1)


def _mark(c: Any, transverse: bool, starts: list[float], lengths: list[float],
          deck: list[int], right: float, elevation: float, wall_gap: dict[str, float],
          factor: float) -> Vertex | None:
    """Where contact ``c`` is marked: between the two decks of a joint, or between a deck's
    end and the abutment (its backwall, or across the axis its key); None for another."""
    if c is None:
        return None
    bl, br = c.left.building, c.right.building
    y = 0.0 if transverse else elevation
    if bl >= 0 and br >= 0:
        lo, hi = min(bl, br), max(bl, br)
        w: Weights = ((deck[lo], 0.5), (deck[hi], 0.5))
        x = 0.5 * (starts[lo] + lengths[lo] + starts[hi])
        return Vertex(x, y, (), w) if transverse else Vertex(x, y, w)
    wall, b = (c.left, br) if bl < 0 else (c.right, bl)
    m = _ABUTMENT.match(wall.name or "")
    if m is None or b < 0:
        return None
    first = m.group(1) == "1"
    w = ((deck[b], 0.5),)
    if transverse:
        key = wall_gap.get(wall.name, 0.0) * factor * (1.0 if m.group(2) == "+y" else -1.0)
        return Vertex(0.0 if first else right, 0.5 * key, (), w)
    x_deck = starts[b] if first else starts[b] + lengths[b]
    return Vertex(0.5 * (x_deck + (0.0 if first else right)), y, w)
