"""An animation of a run: the structures swaying and striking (``pounding animate``).

The frames of any kind of structure are one thing, :class:`AnimationFrames`: a few
*channels* (displacement histories of degrees of freedom at the frame times [m]) and
*shapes* (polylines) whose every vertex sits at its rest position plus ``exaggeration ×``
a fixed linear combination of the channels — a floor's corner in plan moves by ``u_x −
(y − y_c) θ`` and ``u_y + (x − x_c) θ``, a deck end by the deck's displacement. Every
contact is marked at such a point when it struck. A penetration is itself a linear
combination of the degrees of freedom, so two faces drawn this way touch exactly when the
contact closes (the gaps are drawn × the same factor). One drawing code then serves every
kind: the video (:mod:`pounding.plot.animate_video`) and the page's JavaScript
(``report/templates/animation_view.html.j2``).

The kinds, one module each, each reading only this one:

* buildings in a row, in elevation (:func:`animation_frames`, here);
* buildings in plan, their floor slabs seen from above, moving and rotating
  (:mod:`pounding.plot.animate_plan`);
* bridges: the deck frames along the bridge in elevation (the joints opening and closing,
  the decks striking each other and the abutments' backwalls), or across its axis in plan
  (the decks swaying against the shear keys) (:mod:`pounding.plot.animate_bridge`).

What is drawn for a row: each building's outline from the ground (elevation 0, not moving:
displacements are relative to the ground) through its floors, floor ``i`` moved sideways by
``exaggeration × u_i``; elevations are true. Buildings stand left to right as in the model,
each ``BUILDING_WIDTH × tallest height`` wide, the space between two neighbours drawn as
their smallest gap times the same ``exaggeration``. A contact that carried force at any
output step between the previous frame and this one is marked (an impact lasts
milliseconds, far shorter than a frame: a frame sampled at its own instant would miss most
of them).

Units on the figures: displacements mm, contact forces kN, ground acceleration m/s², time
s. NumPy at import; matplotlib only in the video.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.plot.decimate import envelope_indices

__all__ = ["BUILDING_WIDTH", "MAX_FPS", "AnimatedBuilding", "AnimatedContact", "AnimationFrames",
           "Shape", "Timeline", "Vertex", "animation_frames", "assemble", "auto_exaggeration",
           "contact_histories", "dof_table", "exaggeration_for", "timeline"]

BUILDING_WIDTH = 0.4
"""Drawn width of a building, as a fraction of the tallest building's height."""

MAX_FPS = 60.0
"""Largest ``fps`` accepted (a frame is never shorter than a screen refresh)."""

CURVE_BUCKETS = 1200
"""Buckets of the M4 decimation of the curves below the structures (every peak kept)."""

Weights = tuple[tuple[int, float], ...]
"""A linear combination of channels: ``(channel, weight)`` pairs."""


@dataclass(frozen=True)
class Vertex:
    """A point of the drawing: rest position ``(x, y)`` [m of drawing] and the channel
    weights of its move along x and along y (the drawing's vertical: elevation, or plan y)."""

    x: float
    y: float
    wx: Weights = ()
    wy: Weights = ()

    def at(self, channels: NDArray[np.float64], factor: float) -> tuple[float, float]:
        """Where it is drawn with ``channels`` (one frame's, [m]) × ``factor``."""
        return (self.x + factor * sum(w * channels[c] for c, w in self.wx),
                self.y + factor * sum(w * channels[c] for c, w in self.wy))


@dataclass(frozen=True)
class Shape:
    """A polyline (closed: a polygon) of vertices, drawn in the style ``kind`` (``outline``,
    ``floor``, ``slab``, ``deck``, ``pier``, ``wall``)."""

    vertices: tuple[Vertex, ...]
    kind: str = "outline"
    closed: bool = False


@dataclass
class AnimatedBuilding:
    """One building of a row: its name, drawn left edge [m of drawing], drawn width [m], the
    floor elevations [m] and the floor displacements at every frame [m] (frames × floors)."""

    name: str
    left: float
    width: float
    elevations: NDArray[np.float64]
    displacement: NDArray[np.float64]


@dataclass
class AnimatedContact:
    """One contact: its label, elevation [m], where it is marked (None: not drawn), and the
    largest force [N] at the output steps from the previous frame to each frame."""

    label: str
    elevation: float
    mark: Vertex | None
    force: NDArray[np.float64]


@dataclass
class AnimationFrames:
    """Everything drawn: frame times [s], the channels at the frames [m] (frames ×
    channels), the shapes, labels (text at a vertex), contacts, the exaggeration factor, the
    view (``elevation``: x across, elevation up, a ground line; ``plan``: seen from above)
    with its vertical axis label and whether both axes are drawn to one scale, and the
    curves below (``curve_time`` [s], ``ground_acceleration`` [m/s²], ``contact_force`` [N],
    contacts × samples, decimated keeping every peak). ``buildings`` is filled for a row of buildings."""

    title: str
    time: NDArray[np.float64]
    fps: float
    exaggeration: float
    channels: NDArray[np.float64]
    shapes: list[Shape]
    labels: list[tuple[str, Vertex]]
    contacts: list[AnimatedContact]
    curve_time: NDArray[np.float64]
    ground_acceleration: NDArray[np.float64]
    contact_force: NDArray[np.float64]
    view: str = "elevation"
    y_label: str = "elevation [m]"
    equal_scales: bool = False
    buildings: list[AnimatedBuilding] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    @property
    def height(self) -> float:
        """The highest rest point of the drawing [m]."""
        return max((v.y for s in self.shapes for v in s.vertices), default=1.0)

    def struck(self, frame: int) -> list[int]:
        """Indices of the contacts that carried force since the frame before ``frame``."""
        return [i for i, c in enumerate(self.contacts) if c.force[frame] > 0.0]

    def extent(self) -> tuple[float, float, float, float]:
        """``(x_min, x_max, y_min, y_max)`` [m of drawing] over every vertex and frame."""
        xs, ys = [], []
        for s in self.shapes:
            for v in s.vertices:
                xs.append(_reach(v.x, v.wx, self.channels, self.exaggeration))
                ys.append(_reach(v.y, v.wy, self.channels, self.exaggeration))
        x = np.array(xs, dtype=float).reshape(-1, 2)
        y = np.array(ys, dtype=float).reshape(-1, 2)
        return float(x[:, 0].min()), float(x[:, 1].max()), float(y[:, 0].min()), float(
            y[:, 1].max())


def _reach(rest: float, weights: Weights, channels: NDArray[np.float64],
           factor: float) -> tuple[float, float]:
    if not weights:
        return rest, rest
    move = factor * sum(w * channels[:, c] for c, w in weights)
    return rest + float(np.nanmin(move)), rest + float(np.nanmax(move))


def auto_exaggeration(peak_displacement: float, height: float) -> float:
    """A round factor (1, 2 or 5 × 10ⁿ, at least 1) drawing the largest displacement about a
    tenth of ``height`` (the tallest building's, or the size of the drawing's kind)."""
    if not peak_displacement > 0.0:
        return 1.0
    raw = 0.1 * height / peak_displacement
    if raw <= 1.0:
        return 1.0
    decade = 10.0 ** math.floor(math.log10(raw))
    return max(m * decade for m in (1.0, 2.0, 5.0) if m * decade <= raw)


def _check_number(value: float, option: str, low: float, high: float, unit: str) -> float:
    if not (math.isfinite(value) and low < value <= high):
        raise ValueError(f"animate: {option}: must be in ({low:g}, {high:g}]{unit} "
                         f"(got {value!r})")
    return float(value)


@dataclass
class Timeline:
    """The output times ``t`` [s], the output steps drawn as frames ``idx``, the steps
    within the stretch animated ``window`` (mask), the frames asked for, and the options."""

    t: NDArray[np.float64]
    idx: NDArray[np.int64]
    window: NDArray[np.bool_]
    wanted: int
    fps: float
    exaggeration: float | None


def timeline(ds: Any, fps: float, exaggeration: float | None, start: float | None,
             end: float | None) -> Timeline:
    """The frames of ``ds`` every ``1/fps`` s of ``[start, end]``, on output steps (never
    more frames than steps); the options checked (one line naming the option)."""
    fps = _check_number(fps, "--fps", 0.0, MAX_FPS, " frames/s")
    if exaggeration is not None:
        exaggeration = _check_number(exaggeration, "--exaggeration", 0.0, 1e6, "")
    t = np.asarray(ds["time"].values, dtype=float)
    if t.size < 2:
        raise ValueError("animate: the run holds fewer than 2 output times; nothing to animate")
    t0 = t[0] if start is None else start
    t1 = t[-1] if end is None else end
    for name, value in (("--start", t0), ("--end", t1)):
        if not (math.isfinite(value) and t[0] <= value <= t[-1]):
            raise ValueError(f"animate: {name}: must be within the run, [{t[0]:g}, {t[-1]:g}] s "
                             f"(got {value!r})")
    if not t1 > t0:
        raise ValueError(f"animate: --end ({t1:g} s) must be after --start ({t0:g} s)")
    n_frames = int(math.floor((t1 - t0) * fps + 1e-9)) + 1
    wanted = t0 + np.arange(n_frames) / fps
    idx = np.unique(np.clip(np.searchsorted(t, wanted - 1e-12), 0, t.size - 1))
    idx = idx[(t[idx] >= t0 - 1e-12) & (t[idx] <= t1 + 1e-12)]
    return Timeline(t, idx, (t >= t0) & (t <= t1), n_frames, fps, exaggeration)


def contact_histories(ds: Any, n_time: int) -> tuple[list[str], NDArray[np.float64],
                                                     NDArray[np.float64]]:
    """Labels, forces [N] and penetrations [m] of the contacts (time × contacts)."""
    labels = [str(c) for c in ds["contact"].values] if "contact" in ds.dims else []
    if not labels:
        return [], np.zeros((n_time, 0)), np.zeros((n_time, 0))
    force = np.asarray(ds["contact_force"].values, dtype=float).reshape(n_time, -1)
    pen = np.asarray(ds["penetration"].values, dtype=float).reshape(n_time, -1)
    return labels, force, pen


def assemble(ds: Any, tl: Timeline, *, title: str, columns: list[int], shapes: list[Shape],
             labels: list[tuple[str, Vertex]], marks: list[Vertex | None], size: float,
             view: str = "elevation", y_label: str = "elevation [m]",
             equal_scales: bool = False, notes: list[str] | None = None) -> AnimationFrames:
    """The frames: channels = the displacement [m] of the DOF ``columns`` of ``ds`` at the
    frames; ``marks`` one a contact (None: not drawn); the factor, unless given, from the
    largest move of any vertex over the stretch and ``size`` (:func:`auto_exaggeration`)."""
    t, idx = tl.t, tl.idx
    u = np.asarray(ds["displacement"].values, dtype=float)[:, columns]
    labels_c, force_all, _ = contact_histories(ds, t.size)
    factor = tl.exaggeration
    if factor is None:
        factor = exaggeration_for(u[tl.window], shapes, size)
    # the largest force at the output steps since the previous frame (the first: at it)
    bounds = np.concatenate([[idx[0]], idx[:-1] + 1])
    c_elev = (np.asarray(ds["contact_elevation"].values, dtype=float)
              if "contact_elevation" in ds.coords else np.full(len(labels_c), np.nan))
    contacts = []
    for k, label in enumerate(labels_c):
        f = np.where(np.isfinite(force_all[:, k]), force_all[:, k], 0.0)
        per_frame = np.array([f[a:b + 1].max() for a, b in zip(bounds, idx, strict=True)])
        contacts.append(AnimatedContact(label, float(c_elev[k]), marks[k],
                                        np.maximum(per_frame, 0.0)))
    # the curves below: decimated keeping every peak (M4), within [start, end]
    sel = np.flatnonzero(tl.window)
    ag = np.asarray(ds["ground_acceleration"].values, dtype=float).reshape(t.size, -1)[:, 0]
    keep = set(envelope_indices(ag[sel], CURVE_BUCKETS).tolist())
    for k in range(force_all.shape[1]):
        keep |= set(envelope_indices(force_all[sel, k], CURVE_BUCKETS).tolist())
    pick = sel[np.array(sorted(keep), dtype=int)]
    notes = list(notes or [])
    if idx.size < tl.wanted:
        notes.append(f"{idx.size} frames: the output step {t[1] - t[0]:g} s is longer than "
                     f"a frame (1/{tl.fps:g} s)")
    return AnimationFrames(title, t[idx], tl.fps, float(factor), u[idx], shapes, labels,
                           contacts, t[pick], ag[pick], force_all[pick].T.copy(), view,
                           y_label, equal_scales, notes=notes)


def exaggeration_for(u: NDArray[np.float64], shapes: list[Shape], size: float) -> float:
    """:func:`auto_exaggeration` of the largest move of any vertex of ``shapes`` with the
    channels ``u`` (time × channels [m]) against ``size`` [m]."""
    peak = 0.0
    for s in shapes:
        for v in s.vertices:
            for weights in (v.wx, v.wy):
                if weights:
                    move = sum(w * u[:, c] for c, w in weights)
                    peak = max(peak, float(np.nanmax(np.abs(move))))
    return auto_exaggeration(peak, size)


def dof_table(ds: Any) -> tuple[list[str], list[str], NDArray[np.float64], list[str]]:
    """Floor labels, their buildings, elevations [m] and units of ``ds``'s DOFs."""
    floors = [str(f) for f in ds["floor"].values]
    owner = ([str(b) for b in ds["building"].values] if "building" in ds.coords
             else ["B1"] * len(floors))
    elev = (np.asarray(ds["floor_elevation"].values, dtype=float)
            if "floor_elevation" in ds.coords else np.arange(1.0, len(floors) + 1.0))
    unit = ([str(x) for x in ds["dof_unit"].values] if "dof_unit" in ds.coords
            else ["m"] * len(floors))
    return floors, owner, elev, unit


def animation_frames(ds: Any, *, fps: float = 25.0, exaggeration: float | None = None,
                     start: float | None = None, end: float | None = None,
                     title: str = "") -> AnimationFrames:
    """The frames of a row of buildings, in elevation.

    Parameters
    ----------
    ds : xarray.Dataset
        The run's ``timehistories.nc`` (``displacement`` by floor with coordinates
        ``building``, ``floor_elevation``, ``dof_unit``; ``contact_force``,
        ``penetration`` by contact; ``ground_acceleration``).
    fps : float
        Frames per second of ground-motion time, in (0, 60]; fewer where the output step
        is longer than a frame.
    exaggeration : float, optional
        Factor on the displacements drawn; default :func:`auto_exaggeration` of the
        tallest height.
    start, end : float, optional
        The stretch of time animated [s]; default the whole run.
    title : str
        Shown above the buildings.

    Returns
    -------
    AnimationFrames

    Raises
    ------
    ValueError
        An option out of range, or histories that are not buildings in a row (one line:
        buildings in plan and bridges are drawn by :mod:`pounding.plot.animate_plan` and
        :mod:`pounding.plot.animate_bridge`).
    """
    tl = timeline(ds, fps, exaggeration, start, end)
    floors, owner, elev, unit = dof_table(ds)
    names = list(dict.fromkeys(owner))
    columns = {b: [j for j in range(len(floors)) if owner[j] == b and unit[j] == "m"]
               for b in names}
    columns = {b: cols for b, cols in columns.items() if cols}
    if not columns:
        raise ValueError("animate: the run has no floor displacements [m] to draw")
    for b, cols in columns.items():
        if len(set(np.round(elev[cols], 9))) != len(cols):
            raise ValueError(f"animate: building {b} has several degrees of freedom at one "
                             "elevation and no plan or bridge to draw them by (run it from "
                             "its folder, with its model.toml)")
    height = float(max(np.max(elev[c]) for c in columns.values()))
    height = height if height > 0 else 1.0
    order = list(columns)
    drawn: list[int] = []  # the DOF columns drawn, building by building, bottom up
    for b in order:
        cols = columns[b]
        drawn += [cols[o] for o in np.argsort(elev[cols], kind="stable")]
    channel = {j: c for c, j in enumerate(drawn)}

    labels_c, _, pen = contact_histories(ds, tl.t.size)
    u0 = np.asarray(ds["displacement"].values[0], dtype=float)
    floor_index = {f: j for j, f in enumerate(floors)}
    pairs: list[tuple[int | None, int | None]] = []
    gap_between: dict[int, float] = {}
    for k, label in enumerate(labels_c):
        left, _, right = label.partition("-")
        jl, jr = floor_index.get(left), floor_index.get(right)
        bl = order.index(owner[jl]) if jl is not None and owner[jl] in columns else None
        br = order.index(owner[jr]) if jr is not None and owner[jr] in columns else None
        pairs.append((bl, br))
        if bl is not None and br == bl + 1 and jl is not None and jr is not None:
            gap = float(u0[jl] - u0[jr] - pen[0, k])
            if math.isfinite(gap) and gap >= 0:
                gap_between[bl] = min(gap_between.get(bl, gap), gap)

    # the factor first: it sets the drawn gaps
    factor = tl.exaggeration
    if factor is None:
        probe = [Shape(tuple(Vertex(0.0, float(elev[j]), ((channel[j], 1.0),)) for j in drawn))]
        u_all = np.asarray(ds["displacement"].values, dtype=float)[:, drawn]
        factor = tl.exaggeration = exaggeration_for(u_all[tl.window], probe, height)

    width = BUILDING_WIDTH * height
    shapes: list[Shape] = []
    names_at: list[tuple[str, Vertex]] = []
    lefts: list[float] = []
    left_edge = 0.0
    for i, b in enumerate(order):
        cols = [j for j in drawn if owner[j] == b]
        z = [0.0] + [float(elev[j]) for j in cols]
        w: list[Weights] = [()] + [((channel[j], 1.0),) for j in cols]
        if elev[cols[0]] <= 0:  # a DOF at the ground (a base slab): no fixed foot
            z, w = z[1:], w[1:]
        side_l = [Vertex(left_edge, zz, ww) for zz, ww in zip(z, w, strict=True)]
        side_r = [Vertex(left_edge + width, zz, ww) for zz, ww in zip(z, w, strict=True)]
        shapes.append(Shape(tuple(side_l + side_r[::-1]), "outline", closed=True))
        shapes += [Shape((a, c), "floor") for a, c in zip(side_l, side_r, strict=True)
                   if a.y > 0]
        names_at.append((b, Vertex(left_edge + 0.5 * width, 1.06 * height)))
        lefts.append(left_edge)
        between = gap_between.get(i)
        left_edge += width + (between * factor if between is not None else 0.25 * width)

    marks: list[Vertex | None] = []
    c_elev = (np.asarray(ds["contact_elevation"].values, dtype=float)
              if "contact_elevation" in ds.coords else np.full(len(labels_c), np.nan))
    for k, label in enumerate(labels_c):
        bl, br = pairs[k]
        if bl is None or br is None or br != bl + 1 or not math.isfinite(c_elev[k]):
            marks.append(None)
            continue
        wx = _face_weights(drawn, owner, elev, channel, order[bl], c_elev[k], 0.5) + \
            _face_weights(drawn, owner, elev, channel, order[br], c_elev[k], 0.5)
        x = 0.5 * (lefts[bl] + width + lefts[br])
        marks.append(Vertex(x, float(c_elev[k]), wx))

    frames = assemble(ds, tl, title=title, columns=drawn, shapes=shapes, labels=names_at,
                      marks=marks, size=height)
    u = frames.channels
    for b, left_at in zip(order, lefts, strict=True):
        cols = [j for j in drawn if owner[j] == b]
        frames.buildings.append(AnimatedBuilding(b, left_at, width, elev[cols].copy(),
                                                 u[:, [channel[j] for j in cols]]))
    return frames


def _face_weights(drawn: list[int], owner: list[str], elev: NDArray[np.float64],
                  channel: dict[int, int], building: str, z: float, scale: float) -> Weights:
    """``scale ×`` the weights of building ``building``'s face at elevation ``z``: linear
    between its floors (between the ground and the first floor, from zero)."""
    cols = [j for j in drawn if owner[j] == building]
    zs = [float(elev[j]) for j in cols]
    if z >= zs[-1]:
        return ((channel[cols[-1]], scale),)
    for k, zk in enumerate(zs):
        if z <= zk:
            below = zs[k - 1] if k else 0.0
            a = (z - below) / (zk - below) if zk > below else 1.0
            out = [(channel[cols[k]], scale * a)]
            if k and a < 1.0:
                out.append((channel[cols[k - 1]], scale * (1.0 - a)))
            return tuple(out)
    return ()
