"""Sect. 5.1 (Fig. 8, Table 1): the case-1 average velocity from the analytic solution and the
motion case known a priori from (Δt, Δy, y2'', y3'')."""

from __future__ import annotations

from typing import Optional

import numpy as np

from .. import _selfalign as sa
from .claim import Claim, _judge, _profile


def case1_average_velocity() -> Claim:
    a2, a3 = 3.0, 0.9
    profile = _profile(1.0, 0.084, a2, a3)
    sol = profile.solution
    t2 = sol.t2 - sol.t1
    v2, x2 = (a2 - 1) * t2, 0.5 * (a2 - 1) * t2 ** 2  # eqs. (16), (17)
    closed = (x2 + v2 ** 2 / (2 * (1 + a3))) / 1.0  # eqs. (20), (21), (24), (10)
    v_bar = sa.steady_state(profile).v_bar
    return Claim("Case-1 average velocity", "Sect. 5.1, eqs. (12)-(24), (10)",
                 "the steady v̄ of a case-1 response follows from the analytic solution",
                 f"closed form {closed:.15f}; simulated {v_bar:.15f}",
                 _judge(abs(v_bar - closed) < 1e-13))


def cases_a_priori(grids: Optional[list[tuple[float, float, dict]]] = None) -> Claim:
    """grids: (Δt, Δy, sweep) of the figures' sweeps (Figs. 10, 11: sweep_accelerations with
    closed-form cells). The claim simulates the same grids (the fixed-point search,
    closed_form=False) and compares the a priori case with the simulated one, and the figures'
    closed-form v̄ with the simulated v̄."""
    if grids is None:
        g = sa.linear_grid(0.03, 3.0, 100)
        grids = [(1.0, 0.084, sa.sweep_accelerations(1.0, 0.084, g, g))]
    cells = agree = 0
    worst = 0.0
    seen: set[int] = set()
    for period, stroke, r in grids:
        simulated = sa.sweep_accelerations(period, stroke, r["a2"], r["a3"], closed_form=False)
        cells += r["predicted"].size
        agree += int((r["predicted"] == simulated["observed"]).sum())
        seen |= set(int(c) for c in np.unique(simulated["observed"]))
        ok = ~np.isnan(simulated["v_bar"])
        diff = np.abs(r["v_bar"][ok] - simulated["v_bar"][ok]) / (1 + np.abs(simulated["v_bar"][ok]))
        worst = max(worst, float(diff.max(initial=0.0)))
    # 1e-10: the closed form's agreement with the search (tests/test_three_phase_steady_state)
    return Claim("Motion cases a priori", "Sect. 5.1, Fig. 8, Table 1",
                 "the case follows a priori from (Δt, Δy, y2'', y3'') (flow chart, "
                 "docs/motion-cases.md); so does v̄ (closed form, "
                 "docs/three-phase-steady-state.md)",
                 f"{agree}/{cells} cells agree with the simulated steady state; cases seen "
                 f"{sorted(seen)}; closed-form v̄ within {worst:.1e} of the simulated",
                 _judge(agree == cells and worst <= 1e-10))
