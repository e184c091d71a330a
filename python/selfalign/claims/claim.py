"""One row of the claims table (:class:`Claim`) and what every claim uses to build one: the
verdict, the three-phase profile of a setting (Δt, Δy, y2'', y3''), whether that setting is
physical, and a setting written as text."""

from __future__ import annotations

import dataclasses
from typing import Sequence

from .. import _selfalign as sa


@dataclasses.dataclass
class Claim:
    """One row of the claims table."""

    name: str
    source: str  # where the paper states it
    statement: str
    computed: str  # what selfalign computed; for a FAIL, the counterexample
    status: str  # "PASS" or "FAIL"
    note: str = ""  # what the verdict depends on (assumptions, pending library fixes)

    @property
    def passed(self) -> bool:
        return self.status == "PASS"


def _judge(ok: bool) -> str:
    return "PASS" if bool(ok) else "FAIL"


def _profile(period: float, stroke: float, a2: float, a3: float) -> sa.ThreePhaseProfile:
    return sa.ThreePhaseProfile(period=period, stroke=stroke, a2=a2, a3=a3)


def _physical(period: float, stroke: float, a2: float, a3: float) -> bool:
    return sa.solve_three_phase(sa.ThreePhaseParameters(period, stroke, a2, a3)).physical


def _fmt(setting: Sequence[float]) -> str:
    return "(" + ", ".join(f"{v:.4g}" for v in setting) + ")"
