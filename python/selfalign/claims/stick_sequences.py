"""Sect. 7.3, accumulation read from stopping runs: whether a run ended at x_stick,min of
eq. (41), and the stick positions of many runs as flat arrays (:class:`StickSequences`, per-run
cumulative counts, map-governed tails) for the Sect. 7.3 claims."""

from __future__ import annotations

import dataclasses
import math
from typing import Sequence

import numpy as np

from .. import _selfalign as sa
from .settings import ROUND_OFF


def _accumulated(run, target: float) -> bool:
    """Accumulation read from the run itself: its end position or its last stick position is
    x_stick,min of eq. (41), to rounding. The library's StopKind label is not used: builds
    differ in how they label a sequence that iterates onto x_stick,min (accumulation,
    permanent stick, or not stopped once the period-start state repeats)."""
    stops = np.asarray(run.stick_positions)
    last = float(stops[-1]) if stops.size else math.nan
    return abs(run.end_position - target) <= ROUND_OFF or abs(last - target) <= ROUND_OFF


@dataclasses.dataclass
class StickSequences:
    """The stick positions of a set of stopping runs, concatenated run after run."""

    x: np.ndarray  # every stick position [-]
    run: np.ndarray  # index of the run each position belongs to
    labelled: np.ndarray  # per run: the library says StopKind.accumulation
    end: np.ndarray  # per run: end position [-]
    last: np.ndarray  # per run: last stick position [-] (NaN if none)

    @staticmethod
    def of(runs: Sequence) -> "StickSequences":
        seqs = [np.asarray(r.stick_positions, dtype=float) for r in runs]
        run = np.repeat(np.arange(len(seqs)), [len(q) for q in seqs])
        return StickSequences(np.concatenate(seqs) if seqs else np.zeros(0), run,
                              np.array([r.kind == sa.StopKind.accumulation for r in runs],
                                       dtype=bool),
                              np.array([r.end_position for r in runs]),
                              np.array([q[-1] if q.size else np.nan for q in seqs]))

    def pairs(self) -> tuple[np.ndarray, np.ndarray]:
        """All consecutive (x_n, x_{n+1}) within a run."""
        same = self.run[1:] == self.run[:-1]
        return self.x[:-1][same], self.x[1:][same]

    def ended_at(self, target: float) -> np.ndarray:
        """Per run: the end or last stick position is `target` (x_stick,min) to rounding, as
        in _accumulated."""
        return (np.abs(self.end - target) <= ROUND_OFF) \
            | (np.abs(self.last - target) <= ROUND_OFF)


def _run_cumsum(flags: np.ndarray, run: np.ndarray) -> np.ndarray:
    """Inclusive cumulative count of `flags` within each run (positions grouped by run)."""
    if flags.size == 0:
        return np.zeros(0, dtype=int)
    starts = np.flatnonzero(np.r_[True, run[1:] != run[:-1]])
    count = np.cumsum(flags.astype(int))
    before = count[starts] - flags[starts].astype(int)
    return count - np.repeat(before, np.diff(np.r_[starts, flags.size]))


def _accumulation_tails(x: np.ndarray, run: np.ndarray, governed: np.ndarray) -> np.ndarray:
    """Per position: part of its run's map-governed tail (from the first governed stick
    position on; the last position alone where no position is governed)."""
    if x.size == 0:
        return np.zeros(0, dtype=bool)
    last = np.r_[run[1:] != run[:-1], True]
    none = np.repeat(_run_cumsum(governed, run)[last] == 0,
                     np.diff(np.r_[np.flatnonzero(np.r_[True, run[1:] != run[:-1]]), x.size]))
    return (_run_cumsum(governed, run) > 0) | (none & last)
