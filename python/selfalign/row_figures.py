"""Queues of parts as figures (issue 24, docs/rows.md): each part's leading edge over time from
a :func:`selfalign.row_run` or :func:`selfalign.row_stop` result, optionally the part itself
as a band [x - L, x], and a demo of a queue stopping at a friction step. Uses matplotlib's Agg
backend; not imported by ``import selfalign``: ``from selfalign import row_figures``.
"""

from __future__ import annotations

from typing import Any, Optional, Union

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import _selfalign as sa  # noqa: E402
from .planar_figures import PathLike, _save_atomic  # noqa: E402

__all__ = ["queue_trajectories", "figure_queue_stop", "QUEUE_STOP_STEP"]

Result = Union[sa.RowRun, sa.RowStop]

# The demo of figure_queue_stop (tests/test_rows.cpp, RowAnalysis.
# AQueueStopsAtTheStepAndTheMethodsAgree): the paper's Sect. 7.2 profile, three parts of length
# 0.25 with gaps, the rear one conveying faster, and a step from level 1 to 4 at 1.5.
QUEUE_STOP_STEP = 1.5


def _queue_stop_demo() -> tuple[sa.ThreePhaseProfile, sa.RowQueue, sa.FrictionField]:
    profile = sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=3.0, a3=0.9)
    laws = [sa.FrictionLaw(1.1, 0.8), sa.FrictionLaw(1.2, 1.0), sa.FrictionLaw(1.2, 1.0)]
    queue = sa.RowQueue([sa.RowPart(length=0.25, law=law, x=0.375 * i)
                         for i, law in enumerate(laws)])
    field = sa.FrictionField.steps([QUEUE_STOP_STEP], [1.0, 4.0])
    return profile, queue, field


def _part_lengths(lengths: Any, parts: int) -> np.ndarray:
    """lengths as one float per part: an array-like (or one number for every part), a
    RowQueue or a list of RowPart."""
    if isinstance(lengths, sa.RowQueue):
        lengths = lengths.parts
    if isinstance(lengths, (list, tuple)) and lengths and isinstance(lengths[0], sa.RowPart):
        lengths = [p.length for p in lengths]
    out = np.broadcast_to(np.asarray(lengths, dtype=float), (parts,))
    if not np.all(np.isfinite(out)) or np.any(out <= 0):
        raise ValueError("lengths: expected positive finite part lengths")
    return out


def queue_trajectories(result: Result, ax: Optional[plt.Axes] = None,
                       lengths: Any = None) -> plt.Figure:
    """Plots each part's leading edge x [-] over time [-] from a RowRun or RowStop (its
    ``times`` and ``positions``), part 0 the rear one. With ``lengths`` (one per part, one
    number for all, or the RowQueue / list of RowPart that was run), also each part as a band
    [x - L, x]. Draws into ``ax`` (a new figure when None); returns the figure."""
    times = np.asarray(result.times, dtype=float)
    positions = np.asarray(result.positions, dtype=float).reshape(len(times), -1)
    parts = positions.shape[1]
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 4.5))
    widths = None if lengths is None else _part_lengths(lengths, parts)
    colours = plt.get_cmap("tab10")
    for i in range(parts):
        colour = colours(i % 10)
        x = positions[:, i]
        end = " (rear)" if i == 0 else " (front)" if i == parts - 1 else ""
        ax.plot(times, x, color=colour, linewidth=1.2, label=f"part {i}{end if parts > 1 else ''}")
        if widths is not None:
            ax.fill_between(times, x - widths[i], x, color=colour, alpha=0.25, linewidth=0)
    ax.set_xlabel("time t [-]")
    ax.set_ylabel("leading edge x [-]" if widths is None else "part [x - L, x] [-]")
    if parts:
        ax.legend(fontsize=8, loc="upper left")
    return ax.figure


def figure_queue_stop(path_png: PathLike, *, method: str = "exact",
                      samples_per_period: int = 40, dpi: int = 120) -> sa.RowStop:
    """The demo of a queue stopping at a friction step: the paper's profile
    ThreePhaseProfile(1, 0.084, 3.0, 0.9), three parts of length 0.25 at x = 0, 0.375, 0.75
    with laws (1.1, 0.8), (1.2, 1.0), (1.2, 1.0) (the rear one conveys faster and catches up),
    and a friction step at x = 1.5 from level 1 to 4, run by :func:`selfalign.row_stop`
    (``method``, at most 400 periods). Saves the trajectories, the parts as bands and the step
    as a horizontal line to ``path_png`` (atomically); returns the RowStop."""
    profile, queue, field = _queue_stop_demo()
    stop = sa.row_stop(profile, queue, field, 400, method=method,
                       samples_per_period=samples_per_period)
    fig = queue_trajectories(stop, lengths=queue)
    try:
        ax = fig.axes[0]
        ax.axhline(QUEUE_STOP_STEP, color="k", linestyle="--", linewidth=1.0,
                   label="friction step (level 1 -> 4)")
        ax.legend(fontsize=8, loc="lower right")
        state = (f"stopped at t = {stop.stop_time:.3g}" if stop.stopped
                 else f"not stopped after {stop.periods} periods")
        ax.set_title(f"a queue of three parts stopping at a friction step ({state}"
                     f"{', accumulated' if stop.accumulated else ''})", fontsize=9)
        _save_atomic(fig, path_png, dpi)
    finally:
        plt.close(fig)
    return stop
