"""Figures of planar motion (issue 13): a rigid part's path over the table's friction level,
the drift field, and an animation of the part on the moving table.

The functions take the dicts that :func:`selfalign.simulate_planar` and
:func:`selfalign.planar_drift_field` return. Poses in those results are on the table (table
coordinates, angle relative to the table); the table's own world pose is in the columns
``table_x``, ``table_y``, ``table_angle``. Everything is dimensionless. Drawing uses
matplotlib's Agg backend (no display needed); the GIF is written with Pillow
(``matplotlib.animation.PillowWriter``). Not imported by ``import selfalign`` (it loads
matplotlib): ``from selfalign import planar_figures``.
"""

from __future__ import annotations

import os
import tempfile
from typing import Any, Callable, Mapping, Optional, Sequence, Union

import matplotlib

matplotlib.use("Agg")
import matplotlib.animation  # noqa: E402
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.transforms  # noqa: E402
import numpy as np  # noqa: E402

from . import _selfalign as sa  # noqa: E402

PathLike = Union[str, "os.PathLike[str]"]

__all__ = ["plot_planar_path", "plot_drift_field", "animate_planar"]


def _patch_points(part: sa.RigidPart) -> np.ndarray:
    """The contact points of the part's patch as an (n, 2) array (body frame)."""
    return np.array([[p.x, p.y] for p in part.patch], dtype=float).reshape(-1, 2)


def _hull(points: np.ndarray) -> np.ndarray:
    """The convex hull of 2-D points, counter-clockwise (Andrew's monotone chain)."""
    pts = np.unique(points, axis=0)
    if len(pts) < 3:
        return pts
    pts = pts[np.lexsort((pts[:, 1], pts[:, 0]))]

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[np.ndarray] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list[np.ndarray] = []
    for p in pts[::-1]:
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def _placed(body: np.ndarray, x: float, y: float, angle: float) -> np.ndarray:
    """Body-frame points placed at pose (x, y, angle)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.column_stack([x + c * body[:, 0] - s * body[:, 1],
                            y + s * body[:, 0] + c * body[:, 1]])


def _extent(result: Mapping[str, np.ndarray], part: sa.RigidPart,
            margin: float) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1): the path's bounding box grown by the patch radius and a margin."""
    r = float(np.max(np.hypot(*_patch_points(part).T))) if part.patch else 0.0
    x, y = np.asarray(result["x"], float), np.asarray(result["y"], float)
    pad = r + margin * max(float(np.ptp(x)), float(np.ptp(y)), 2 * r, 1e-3)
    return float(x.min() - pad), float(x.max() + pad), float(y.min() - pad), float(y.max() + pad)


def _level_image(field: Any, extent: Sequence[float], resolution: int) -> np.ndarray:
    x0, x1, y0, y1 = extent
    gx = np.linspace(x0, x1, resolution)
    gy = np.linspace(y0, y1, resolution)
    return np.asarray(sa.planar_level(field, gx[None, :], gy[:, None]))


def _write_atomically(path: PathLike, suffix: str, write: Callable[[str], None]) -> str:
    """write(tmp) into a temporary file beside path, then os.replace (no half-written file);
    the file gets the permissions a new file would (0666 less the umask, not mkstemp's 0600)."""
    path = os.fspath(path)
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=folder, suffix=suffix, prefix=".tmp-")
    os.close(fd)
    try:
        write(tmp)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise
    return path


def _save_atomic(fig: plt.Figure, path: PathLike, dpi: int) -> None:
    """savefig to path atomically, in the format its extension names (PNG by default)."""
    suffix = os.path.splitext(os.fspath(path))[1] or ".png"
    _write_atomically(path, suffix,
                      lambda tmp: fig.savefig(tmp, dpi=dpi, format=suffix.lstrip(".") or "png"))


def plot_planar_path(result: Mapping[str, np.ndarray], field: Any, part: sa.RigidPart,
                     ax: Optional[plt.Axes] = None, *, instants: int = 5,
                     resolution: int = 200, margin: float = 0.15,
                     path: Optional[PathLike] = None, dpi: int = 120) -> plt.Axes:
    """The part's path on the table over the table's friction level.

    Draws the level m(x, y) of ``field`` (planar_level on a ``resolution`` square grid) as an
    image in table coordinates, the centre-of-mass path of ``result`` (a
    :func:`selfalign.simulate_planar` dict), and the contact points of ``part`` with their
    convex outline at ``instants`` evenly spaced samples (first and last included). Returns
    the Axes (a new figure's when ``ax`` is None); with ``path``, also saves the figure there
    (format from the extension; written to a temporary file, then renamed)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 5.0))
    extent = _extent(result, part, margin)
    level = _level_image(field, extent, resolution)
    image = ax.imshow(level, origin="lower", extent=extent, cmap="viridis", aspect="equal",
                      interpolation="nearest")
    ax.figure.colorbar(image, ax=ax, label="friction level m [-]")
    x, y, angle = (np.asarray(result[k], float) for k in ("x", "y", "angle"))
    ax.plot(x, y, color="white", lw=1.2, label="centre of mass")
    body = _patch_points(part)
    outline = _hull(body)
    n = len(x)
    for k, i in enumerate(np.unique(np.linspace(0, n - 1, max(1, instants)).round().astype(int))):
        pts = _placed(body, x[i], y[i], angle[i])
        ax.scatter(pts[:, 0], pts[:, 1], s=6, color="tab:red", zorder=3,
                   label="contact points" if k == 0 else None)
        if len(outline) >= 3:
            ring = _placed(np.vstack([outline, outline[:1]]), x[i], y[i], angle[i])
            ax.plot(ring[:, 0], ring[:, 1], color="tab:red", lw=0.8)
    ax.plot(x[:1], y[:1], "o", color="white", ms=4)
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_xlabel("table x [-]")
    ax.set_ylabel("table y [-]")
    ax.set_title("path on the table")
    ax.legend(loc="upper right", fontsize="small")
    if path is not None:
        _save_atomic(ax.figure, path, dpi)
    return ax


def plot_drift_field(field_result: Mapping[str, Any], ax: Optional[plt.Axes] = None, *,
                     angle_index: int = 0, path: Optional[PathLike] = None,
                     dpi: int = 120) -> plt.Axes:
    """Quiver of the drift velocity (drift_x, drift_y) of a :func:`selfalign.planar_drift_field`
    dict over its (x, y) grid, at the start angle ``angles[angle_index]`` (the first by
    default), coloured by the drift speed. Returns the Axes; with ``path``, also saves the
    figure there."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.0, 5.0))
    x = np.asarray(field_result["x"])[:, :, angle_index]
    y = np.asarray(field_result["y"])[:, :, angle_index]
    u = np.asarray(field_result["drift_x"])[:, :, angle_index]
    v = np.asarray(field_result["drift_y"])[:, :, angle_index]
    speed = np.hypot(u, v)
    arrows = ax.quiver(x, y, u, v, speed, cmap="plasma", angles="xy", pivot="tail")
    ax.figure.colorbar(arrows, ax=ax, label="drift speed [-]")
    ax.set_aspect("equal")
    ax.set_xlabel("table x [-]")
    ax.set_ylabel("table y [-]")
    angle = float(np.asarray(field_result["angles"])[angle_index])
    ax.set_title(f"drift field (start angle {angle:g} rad)")
    if path is not None:
        _save_atomic(ax.figure, path, dpi)
    return ax


def animate_planar(result: Mapping[str, np.ndarray], field: Any, part: sa.RigidPart,
                   path: PathLike, fps: int = 20, *, max_frames: int = 100,
                   margin: float = 0.15, resolution: int = 80, dpi: int = 80) -> str:
    """Writes a GIF of the part on the moving table to ``path`` and returns the path.

    Each frame shows, in world coordinates, the table as a rectangle outline (the region
    around the part's path, placed at the table's pose table_x, table_y, table_angle) with its
    friction level m(x, y) as an image carried along, and the part's contact points with their
    convex outline. At most ``max_frames`` frames, evenly spaced over ``result``'s samples,
    played at ``fps`` frames per second (Pillow writer). The GIF goes to a temporary file in
    the same folder first and is renamed onto ``path`` when complete."""
    path = os.fspath(path)
    if fps <= 0:
        raise ValueError("fps must be > 0")
    if max_frames < 1:
        raise ValueError("max_frames must be >= 1")
    x, y, angle = (np.asarray(result[k], float) for k in ("x", "y", "angle"))
    tx, ty, ta = (np.asarray(result[k], float) for k in ("table_x", "table_y", "table_angle"))
    t = np.asarray(result["t"], float)
    frames = np.unique(np.linspace(0, len(x) - 1, min(max_frames, len(x))).round().astype(int))

    extent = _extent(result, part, margin)
    x0, x1, y0, y1 = extent
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    world = np.vstack([_placed(corners, tx[i], ty[i], ta[i]) for i in frames])
    lo, hi = world.min(axis=0), world.max(axis=0)
    pad = 0.05 * float(max(hi - lo))

    fig, ax = plt.subplots(figsize=(5.0, 5.0))
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("world x [-]")
    ax.set_ylabel("world y [-]")
    image = ax.imshow(_level_image(field, extent, resolution), origin="lower", extent=extent,
                      cmap="viridis", alpha=0.6, interpolation="nearest")
    table = matplotlib.patches.Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, lw=1.5,
                                         edgecolor="black")
    ax.add_patch(table)
    body = _patch_points(part)
    outline = _hull(body)
    points = ax.scatter([], [], s=8, color="tab:red", zorder=3)
    (ring,) = ax.plot([], [], color="tab:red", lw=1.0, zorder=3)
    label = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top", fontsize="small")

    def draw(i: int):
        on_table = matplotlib.transforms.Affine2D().rotate(ta[i]).translate(tx[i], ty[i])
        image.set_transform(on_table + ax.transData)
        table.set_transform(on_table + ax.transData)
        c, s = np.cos(ta[i]), np.sin(ta[i])
        cx, cy = tx[i] + c * x[i] - s * y[i], ty[i] + s * x[i] + c * y[i]
        points.set_offsets(_placed(body, cx, cy, ta[i] + angle[i]))
        if len(outline) >= 3:
            r = _placed(np.vstack([outline, outline[:1]]), cx, cy, ta[i] + angle[i])
            ring.set_data(r[:, 0], r[:, 1])
        label.set_text(f"t = {t[i]:.3f}")
        return image, table, points, ring, label

    anim = matplotlib.animation.FuncAnimation(fig, draw, frames=list(frames), blit=False)
    try:
        return _write_atomically(
            path, ".gif",
            lambda tmp: anim.save(tmp, writer=matplotlib.animation.PillowWriter(fps=fps), dpi=dpi))
    finally:
        plt.close(fig)
