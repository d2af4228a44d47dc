"""An animation of a run: the buildings swaying and striking (``pounding animate``).

:func:`animation_frames` turns a run's time histories (the ``timehistories.nc`` dataset,
read elsewhere) into frames: the deformed shape of every building at ``fps`` frames a second
of ground-motion time, the contacts that struck since the frame before, and the ground
motion and contact forces for the panels below. :func:`write_video` draws the frames with
matplotlib into an MP4 (ffmpeg) or, where no ffmpeg is found, a GIF (Pillow).

What is drawn
-------------
Each building is its outline from the ground (elevation 0, not moving: displacements are
relative to the ground) through its floors, floor ``i`` moved sideways by ``exaggeration ×
u_i``; elevations are true. Buildings stand left to right as in the model, each drawn
``BUILDING_WIDTH × tallest height`` wide, the space between two neighbours drawn as their
smallest gap times the same ``exaggeration``: two faces touch in the drawing exactly when
the contact closes. A contact that carried force at any output step between the previous
frame and this one is marked (an impact lasts milliseconds, far shorter than a frame: a
frame sampled at its own instant would miss most of them).

Units on the figures: displacements mm, contact forces kN, ground acceleration m/s², time
s. NumPy at import; matplotlib only in :func:`write_video`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.plot.decimate import envelope_indices

__all__ = ["BUILDING_WIDTH", "MAX_FPS", "AnimatedBuilding", "AnimatedContact", "AnimationFrames",
           "animation_frames", "auto_exaggeration", "video_format", "write_video"]

BUILDING_WIDTH = 0.4
"""Drawn width of a building, as a fraction of the tallest building's height."""

MAX_FPS = 60.0
"""Largest ``fps`` accepted (a frame is never shorter than a screen refresh)."""

CURVE_BUCKETS = 1200
"""Buckets of the M4 decimation of the curves below the buildings (every peak kept)."""


@dataclass
class AnimatedBuilding:
    """One building: its name, drawn left edge [m of drawing], drawn width [m], the floor
    elevations [m] and the floor displacements at every frame [m] (frames × floors)."""

    name: str
    left: float
    width: float
    elevations: NDArray[np.float64]
    displacement: NDArray[np.float64]


@dataclass
class AnimatedContact:
    """One contact: its label, elevation [m], the drawn position of its gap's middle at
    rest [m] (None: not between two drawn buildings) with the buildings on either side,
    and the largest force [N] at the output steps from the previous frame to each frame."""

    label: str
    elevation: float
    x_rest: float | None
    left_building: int | None
    right_building: int | None
    force: NDArray[np.float64]


@dataclass
class AnimationFrames:
    """Everything drawn: frame times [s], buildings, contacts, the exaggeration factor and
    the curves below (``curve_time`` [s], ``ground_acceleration`` [m/s²],
    ``contact_force`` [N], contacts × samples, decimated keeping every peak)."""

    title: str
    time: NDArray[np.float64]
    fps: float
    exaggeration: float
    buildings: list[AnimatedBuilding]
    contacts: list[AnimatedContact]
    curve_time: NDArray[np.float64]
    ground_acceleration: NDArray[np.float64]
    contact_force: NDArray[np.float64]
    height: float
    notes: list[str] = field(default_factory=list)

    def struck(self, frame: int) -> list[int]:
        """Indices of the contacts that carried force since the frame before ``frame``."""
        return [i for i, c in enumerate(self.contacts) if c.force[frame] > 0.0]


def auto_exaggeration(peak_displacement: float, height: float) -> float:
    """A round factor (1, 2 or 5 × 10ⁿ, at least 1) drawing the largest displacement about a
    tenth of the tallest building's height."""
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


def animation_frames(ds: Any, *, fps: float = 25.0, exaggeration: float | None = None,
                     start: float | None = None, end: float | None = None,
                     title: str = "") -> AnimationFrames:
    """The frames of a run's histories.

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
        Factor on the displacements drawn; default :func:`auto_exaggeration`.
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
        An option out of range, or histories that are not buildings in a row (one line).
    """
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

    # frames: every 1/fps s, on output steps (never more frames than steps)
    n_frames = int(math.floor((t1 - t0) * fps + 1e-9)) + 1
    wanted = t0 + np.arange(n_frames) / fps
    idx = np.unique(np.clip(np.searchsorted(t, wanted - 1e-12), 0, t.size - 1))
    idx = idx[(t[idx] >= t0 - 1e-12) & (t[idx] <= t1 + 1e-12)]
    frame_time = t[idx]

    u = np.asarray(ds["displacement"].values, dtype=float)
    floors = [str(f) for f in ds["floor"].values]
    owner = ([str(b) for b in ds["building"].values] if "building" in ds.coords
             else ["B1"] * len(floors))
    elev = (np.asarray(ds["floor_elevation"].values, dtype=float)
            if "floor_elevation" in ds.coords else np.arange(1.0, len(floors) + 1.0))
    unit = ([str(x) for x in ds["dof_unit"].values] if "dof_unit" in ds.coords
            else ["m"] * len(floors))
    names: list[str] = []
    for b in owner:
        if b not in names:
            names.append(b)
    columns = {b: [j for j in range(len(floors)) if owner[j] == b and unit[j] == "m"]
               for b in names}
    columns = {b: cols for b, cols in columns.items() if cols}
    if not columns:
        raise ValueError("animate: the run has no floor displacements [m] to draw")
    for b, cols in columns.items():
        if len(set(np.round(elev[cols], 9))) != len(cols):
            raise ValueError(f"animate: building {b} has several degrees of freedom at one "
                             "elevation (a building in plan or a bridge): animate draws "
                             "buildings in a row, one lateral displacement a floor")
    height = float(max(np.max(elev[c]) for c in columns.values()))
    height = height if height > 0 else 1.0
    window = (t >= t0) & (t <= t1)
    peak = float(np.nanmax(np.abs(u[window][:, sum(columns.values(), [])])))
    factor = exaggeration if exaggeration is not None else auto_exaggeration(peak, height)

    # contacts: their floors, and the gap between neighbours (u_l - u_r - penetration at t0)
    contact_labels = ([str(c) for c in ds["contact"].values] if "contact" in ds.dims else [])
    force_all = (np.asarray(ds["contact_force"].values, dtype=float).reshape(t.size, -1)
                 if contact_labels else np.zeros((t.size, 0)))
    pen = (np.asarray(ds["penetration"].values, dtype=float).reshape(t.size, -1)
           if contact_labels else np.zeros((t.size, 0)))
    c_elev = (np.asarray(ds["contact_elevation"].values, dtype=float)
              if "contact_elevation" in ds.coords else np.full(len(contact_labels), np.nan))
    building_order = list(columns)
    floor_index = {f: j for j, f in enumerate(floors)}
    pairs: list[tuple[int | None, int | None]] = []
    gap_between: dict[int, float] = {}
    for k, label in enumerate(contact_labels):
        left, _, right = label.partition("-")
        jl, jr = floor_index.get(left), floor_index.get(right)
        bl = building_order.index(owner[jl]) if jl is not None and owner[jl] in columns else None
        br = building_order.index(owner[jr]) if jr is not None and owner[jr] in columns else None
        pairs.append((bl, br))
        if bl is not None and br == bl + 1 and jl is not None and jr is not None:
            gap = float(u[0, jl] - u[0, jr] - pen[0, k])
            if math.isfinite(gap) and gap >= 0:
                gap_between[bl] = min(gap_between.get(bl, gap), gap)

    width = BUILDING_WIDTH * height
    buildings: list[AnimatedBuilding] = []
    left_edge = 0.0
    for i, b in enumerate(building_order):
        cols = columns[b]
        order = np.argsort(elev[cols], kind="stable")
        cols = [cols[o] for o in order]
        buildings.append(AnimatedBuilding(b, left_edge, width, elev[cols].copy(), u[idx][:, cols]))
        between = gap_between.get(i)
        left_edge += width + (between * factor if between is not None else 0.25 * width)

    # the largest force at the output steps since the previous frame (the first: at it)
    bounds = np.concatenate([[idx[0]], idx[:-1] + 1])
    contacts: list[AnimatedContact] = []
    for k, label in enumerate(contact_labels):
        f = np.where(np.isfinite(force_all[:, k]), force_all[:, k], 0.0)
        per_frame = np.array([f[a:b + 1].max() for a, b in zip(bounds, idx, strict=True)])
        bl, br = pairs[k]
        x_rest = None
        if bl is not None and br is not None and br == bl + 1:
            right_face = buildings[bl].left + width
            x_rest = 0.5 * (right_face + buildings[br].left)
        contacts.append(AnimatedContact(label, float(c_elev[k]), x_rest, bl, br,
                                        np.maximum(per_frame, 0.0)))

    # the curves below: decimated keeping every peak (M4), within [start, end]
    sel = np.flatnonzero(window)
    ag = np.asarray(ds["ground_acceleration"].values, dtype=float).reshape(t.size, -1)[:, 0]
    keep = set(envelope_indices(ag[sel], CURVE_BUCKETS).tolist())
    for k in range(force_all.shape[1]):
        keep |= set(envelope_indices(force_all[sel, k], CURVE_BUCKETS).tolist())
    pick = sel[np.array(sorted(keep), dtype=int)]
    notes = []
    if idx.size < n_frames:
        notes.append(f"{idx.size} frames: the output step {t[1] - t[0]:g} s is longer than "
                     f"a frame (1/{fps:g} s)")
    return AnimationFrames(title, frame_time, fps, float(factor), buildings, contacts,
                           t[pick], ag[pick], force_all[pick].T.copy(), height, notes)


def video_format() -> str:
    """``"mp4"`` where matplotlib finds ffmpeg, else ``"gif"`` (Pillow, always there)."""
    from matplotlib import animation

    return "mp4" if animation.writers.is_available("ffmpeg") else "gif"


def _outline(b: AnimatedBuilding, frame: int, factor: float) -> tuple[list[float], list[float]]:
    """The closed outline of building ``b`` at ``frame`` in drawing coordinates [m]."""
    z = b.elevations
    dx = factor * b.displacement[frame]
    if z[0] > 0:  # the ground does not move (displacements are relative to it)
        z = np.concatenate([[0.0], z])
        dx = np.concatenate([[0.0], dx])
    xs = list(b.left + dx) + list(b.left + b.width + dx[::-1])
    zs = list(z) + list(z[::-1])
    return xs + [xs[0]], zs + [zs[0]]


def write_video(frames: AnimationFrames, path: str | Path, *, dpi: int = 80) -> Path:
    """Draw ``frames`` into ``path``: MP4 by ffmpeg for a ``.mp4`` name, else a GIF by
    Pillow. The file is written where it is named (atomic placement is the caller's).

    Returns
    -------
    Path
        ``path``.
    """
    from matplotlib import animation

    from pounding.plot import new_figure

    path = Path(path)
    fig = new_figure(8.0, 6.4, laid_out=False)
    grid = fig.add_gridspec(3, 1, height_ratios=[3.2, 1, 1], hspace=0.45)
    ax = fig.add_subplot(grid[0])
    ax_g = fig.add_subplot(grid[1])
    ax_f = fig.add_subplot(grid[2], sharex=ax_g)
    fig.subplots_adjust(left=0.1, right=0.97, top=0.93, bottom=0.08)

    factor = frames.exaggeration
    bs = frames.buildings
    reach = max(float(np.nanmax(np.abs(b.displacement))) for b in bs) * factor
    ax.set_xlim(bs[0].left - reach - 0.1 * bs[0].width, bs[-1].left + bs[-1].width + reach
                + 0.1 * bs[-1].width)
    ax.set_ylim(-0.05 * frames.height, 1.12 * frames.height)
    ax.axhline(0.0, color="0.3", lw=2)
    ax.set_ylabel("elevation [m]")
    ax.set_xticks([])
    ax.set_title(f"{frames.title}  —  displacements × {factor:g}", fontsize=10)
    shapes = [ax.plot(*_outline(b, 0, factor), color="C0", lw=1.6)[0] for b in bs]
    floors = [ax.plot([], [], color="C0", lw=0.8)[0] for _ in bs]
    for b in bs:
        ax.text(b.left + 0.5 * b.width, 1.03 * frames.height, b.name, ha="center", fontsize=9)
    marks = ax.scatter([], [], s=160, marker="*", color="C3", zorder=5)
    clock = fig.text(0.01, 0.985, "", va="top", fontsize=9)

    ax_g.plot(frames.curve_time, frames.ground_acceleration, color="0.3", lw=0.7)
    ax_g.set_ylabel("ground acc.\n[m/s²]", fontsize=8)
    for k, c in enumerate(frames.contacts):
        ax_f.plot(frames.curve_time, frames.contact_force[k] / 1e3, lw=0.8, label=c.label)
    if 1 < len(frames.contacts) <= 6:
        ax_f.legend(fontsize=7, loc="upper right")
    ax_f.set_ylabel("contact force\n[kN]", fontsize=8)
    ax_f.set_xlabel("time [s]")
    ax_g.set_xlim(frames.time[0], frames.time[-1])
    cursors = [a.axvline(frames.time[0], color="C3", lw=1) for a in (ax_g, ax_f)]

    def draw(i: int) -> list[Any]:
        for b, shape, fl in zip(bs, shapes, floors, strict=True):
            xs, zs = _outline(b, i, factor)
            shape.set_data(xs, zs)
            dx = factor * b.displacement[i]
            fx: list[float] = []
            fz: list[float] = []
            for z, d in zip(b.elevations, dx, strict=True):
                fx += [b.left + d, b.left + b.width + d, np.nan]
                fz += [z, z, np.nan]
            fl.set_data(fx, fz)
        hit = [c for c in frames.contacts if c.x_rest is not None]
        pts = [(_contact_x(frames, c, i), c.elevation) for c in hit if c.force[i] > 0]
        marks.set_offsets(np.array(pts) if pts else np.empty((0, 2)))
        clock.set_text(f"t = {frames.time[i]:.2f} s" + ("   impact" if pts else ""))
        for cur in cursors:
            cur.set_xdata([frames.time[i], frames.time[i]])
        return [*shapes, *floors, marks, clock, *cursors]

    animated = [*shapes, *floors, marks, clock, *cursors]
    for artist in animated:
        artist.set_animated(True)
    if path.suffix.lower() == ".mp4":
        writer = animation.FFMpegWriter(fps=frames.fps)  # type: ignore[arg-type]  # (a float is fine)
        with writer.saving(fig, str(path), dpi):
            for i in range(len(frames.time)):
                draw(i)
                writer.grab_frame()
        return path
    _write_gif(fig, animated, draw, len(frames.time), frames.fps, path, dpi)
    return path


def _write_gif(fig: Any, animated: list[Any], draw: Any, n_frames: int, fps: float, path: Path,
               dpi: int) -> None:
    """Each frame drawn over a background drawn once (blitting: the axes, ticks and curves
    are drawn a single time), handed to Pillow one at a time (never all in memory)."""
    from PIL import Image

    fig.set_dpi(dpi)
    canvas = fig.canvas
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)

    def images() -> Any:
        for i in range(n_frames):
            canvas.restore_region(background)
            draw(i)
            for artist in animated:
                fig.draw_artist(artist)
            rgba = np.asarray(canvas.buffer_rgba())
            yield Image.fromarray(rgba[..., :3].copy()).quantize(colors=64)

    frames_iter = images()
    first = next(frames_iter)
    first.save(path, format="GIF", save_all=True, append_images=frames_iter,
               duration=round(1000.0 / fps), loop=0)


def _contact_x(frames: AnimationFrames, c: AnimatedContact, i: int) -> float:
    """Where contact ``c`` is drawn at frame ``i``: the middle of the two faces [m]."""
    assert c.left_building is not None and c.right_building is not None
    pos = []
    for bi, face in ((c.left_building, 1.0), (c.right_building, 0.0)):
        b = frames.buildings[bi]
        d = np.interp(c.elevation, b.elevations, b.displacement[i])
        pos.append(b.left + face * b.width + frames.exaggeration * d)
    return 0.5 * (pos[0] + pos[1])
