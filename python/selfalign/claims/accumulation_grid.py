"""Sect. 7.3: the accumulation grid, computed once (in parallel: the library releases the GIL):
every physical setting of ACCUMULATION_GRID with y2'' < c_mu, its steady entries' stopping runs
and its starts at rest in [x_mu, x_stick,min)."""

from __future__ import annotations

import concurrent.futures
import dataclasses
import itertools
import math
import os
from typing import Optional

import numpy as np

from .. import _selfalign as sa
from .claim import _physical, _profile
from .closed_forms import _t21, slip_angle, stick_map, x_stick_min
from .settings import (ACCUMULATION_ENTRIES, ACCUMULATION_GRID, ACCUMULATION_MAX_PERIODS,
                       ACCUMULATION_RESTS)
from .stick_sequences import StickSequences


@dataclasses.dataclass
class AccumulationCase:
    """One setting of ACCUMULATION_GRID with its stopping runs."""

    period: float
    stroke: float
    width: float
    c_mu: float
    a2: float
    a3: float
    motion_case: int
    theta: float  # slip angle of eq. (59)
    condition: bool  # eq. (59) at x_mu < eq. (41) (Sect. 7.3's condition)
    library_every: Optional[bool]  # StickPositionMap.accumulates_for_every_entry()
    accuracy: object  # PositioningAccuracy over ACCUMULATION_ENTRIES steady entries
    rests: list  # (x_1 - x_mu, StoppingRun) from rest at x_1, phase 0
    sequences: "StickSequences"  # the entries' stick positions

    @property
    def setting(self) -> tuple:
        return (self.period, self.stroke, self.width, self.c_mu, self.a2, self.a3)

    @property
    def in_domain(self) -> bool:
        """Sect. 7.3's assumptions: case-1 entry, peak < c_mu, eq. (59) valid (θ < π)."""
        return self.motion_case == 1 and self.a2 < self.c_mu and self.theta < math.pi


def _accumulation_case(setting: tuple) -> AccumulationCase:
    period, stroke, w, c_mu, a2, a3 = setting
    profile = _profile(period, stroke, a2, a3)
    options = sa.PositioningOptions(entries=ACCUMULATION_ENTRIES, stopping=sa.StoppingOptions(
        max_periods=ACCUMULATION_MAX_PERIODS))
    acc = sa.positioning_accuracy(profile, w, c_mu, options)
    x_mu = acc.x_mu
    t21 = _t21(profile)
    theta = slip_angle(w, c_mu, t21)
    target = x_stick_min(x_mu, w, c_mu, max(a2, a3))
    condition = bool(stick_map(x_mu, a2, a3, w, c_mu, x_mu, t21) < target)
    table = sa.TwoRegionTable(x_mu, w, c_mu)
    every = sa.StickPositionMap(profile, table).accumulates_for_every_entry()
    friction = sa.FieldFriction(table)  # the table as a friction map (two_region_friction)
    rests = []
    for x1 in np.linspace(x_mu, target, ACCUMULATION_RESTS, endpoint=False):
        run = sa.stopping_run(profile, friction, sa.ObjectState(0.0, float(x1), 0.0),
                              sa.StoppingOptions(max_periods=ACCUMULATION_MAX_PERIODS))
        rests.append((float(x1 - x_mu), run))
    return AccumulationCase(period, stroke, w, c_mu, a2, a3, int(acc.steady.motion_case), theta,
                            condition, every, acc, rests, StickSequences.of(acc.runs))


def accumulation_grid(threads: int = 0) -> list[AccumulationCase]:
    """Every physical setting of ACCUMULATION_GRID with y2'' < c_mu, with its runs."""
    g = ACCUMULATION_GRID
    settings = [(p, s, w, c, float(a2), float(a3))
                for p, s, w, c, a2, a3 in itertools.product(g["periods"], g["strokes"],
                                                            g["widths"], g["c_mus"], g["a2"],
                                                            g["a3"])
                if a2 < c and _physical(p, s, a2, a3)]
    workers = threads or os.cpu_count() or 1
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(_accumulation_case, settings))
