"""The paper's quantitative claims, each computed on the spot and judged PASS or FAIL.

Every claim function calls the library and compares the result with a value from the paper or
with a closed form written out in this package (eqs. 9, 30, 33, 37, 39, 41, 59, 60 and the
basin bound of docs/accumulation.md), never with a pasted result. Breaking the code behind a
claim turns its row to FAIL, and a statement of the paper that the computation contradicts is a
FAIL whose ``computed`` text gives the counterexample. Sects. 6 and 7 are covered statement by
statement, Sects. 4 and 5 through their figures.

A FAIL is a finding about the paper or the reproduction, not an error of the tool:
``python -m selfalign reproduce`` exits 0 when it ran to completion (``--strict``: 1 on FAIL).

Each claim function can be called alone; :func:`compute_all` computes the shared inputs (the
Floquet grid, the Sect. 7.3 accumulation grid) once and reuses the figures' data.

One module per part of the paper; this one holds the table (ALL, compute_all) and re-exports
every public name:

* ``claim``: the row (:class:`Claim`) and the helpers every claim uses;
* ``settings``: tolerances and the settings the claims are computed at;
* ``closed_forms``: the paper's closed forms written out (eqs. 7-9, 33, 41, 59, 60, basin bound);
* ``trends``: Sect. 4.4, Figs. 4-6 (trends, Fourier optimum and its shape);
* ``motion``: Sect. 5.1 (case-1 average velocity, motion cases a priori);
* ``stability``: Sect. 6.1 (Floquet grid, monodromy matrices and multipliers);
* ``convergence``: Sect. 6.2;
* ``positioning``: Sects. 7-7.2 (stick condition, x_stick,min, Δx_d, Figs. 16, 17);
* ``stick_sequences``, ``accumulation_grid``, ``accumulation``: Sect. 7.3.

Every module reaches the library as ``sa``, the one module object ``selfalign._selfalign``
(also ``claims.sa``): replacing a function on it, as the tests do with
``monkeypatch.setattr(claims.sa, ...)``, reaches every claim.
"""

from __future__ import annotations

import time
from typing import Callable, Optional

from .. import _selfalign as sa
from .accumulation import (ROUNDED_ONTO, accumulation_at_stick_min, accumulation_periods,
                           always_accumulates, case1_stays, fig18_initial_conditions,
                           fixed_point_is_stick_min, map_predicts_stick_positions)
from .accumulation_grid import AccumulationCase, accumulation_grid
from .claim import Claim
from .closed_forms import (basin_bound, friction_bound, slip_angle, slip_slip_c4, stick_map,
                           stick_map_fixed_point, x_stick_min)
from .convergence import (finite_time_convergence, lyapunov_decreasing, period_velocity_change,
                          slip_slip_convergence)
from .motion import case1_average_velocity, cases_a_priori
from .positioning import (_fig16_accuracies, _fig17_surfaces, accumulation_zero_error,
                          fig16_settings, fig17_design_rules, positioning_error_definition,
                          stick_condition, stick_position_formula)
from .settings import (ACCUMULATION_ENTRIES, ACCUMULATION_GRID, ACCUMULATION_MAX_PERIODS,
                       ACCUMULATION_RESTS, CASE_SETTINGS, FD_TOL, FIG10, FIG11, FLOQUET_PLANES,
                       INITIAL_VELOCITIES, NEAR_ZERO_BAND, ROUND_OFF, SALTATION_TOL, SECT72,
                       SLIP_SLIP_SETTINGS)
from .stability import (FloquetGrid, case1_multipliers, cases23_multipliers,
                        finite_difference_close, floquet_grid, local_stability,
                        saltation_identical, slip_slip_lambda2)
from .stick_sequences import StickSequences
from .trends import (OptimumShape, _fourier_optimum_result, fig4_trend, fig5_trend,
                     fourier_optimum, fourier_shape, optimum_shape)

__all__ = [
    "sa", "Claim", "ALL", "compute_all",
    # settings
    "ROUND_OFF", "SALTATION_TOL", "FD_TOL", "NEAR_ZERO_BAND", "CASE_SETTINGS", "FIG10", "FIG11", "SECT72",
    "FLOQUET_PLANES", "INITIAL_VELOCITIES", "SLIP_SLIP_SETTINGS", "ACCUMULATION_GRID",
    "ACCUMULATION_ENTRIES", "ACCUMULATION_RESTS", "ACCUMULATION_MAX_PERIODS", "ROUNDED_ONTO",
    # closed forms
    "friction_bound", "x_stick_min", "slip_slip_c4", "stick_map", "stick_map_fixed_point",
    "slip_angle", "basin_bound",
    # Sects. 4 and 5
    "fig4_trend", "fig5_trend", "fourier_optimum", "OptimumShape", "optimum_shape",
    "fourier_shape", "case1_average_velocity", "cases_a_priori",
    # Sect. 6
    "FloquetGrid", "floquet_grid", "case1_multipliers", "cases23_multipliers",
    "slip_slip_lambda2", "local_stability", "saltation_identical", "finite_difference_close",
    "period_velocity_change", "lyapunov_decreasing", "finite_time_convergence",
    "slip_slip_convergence",
    # Sect. 7
    "stick_condition", "stick_position_formula", "positioning_error_definition",
    "fig16_settings", "fixed_point_is_stick_min", "AccumulationCase", "accumulation_grid",
    "always_accumulates", "StickSequences", "map_predicts_stick_positions",
    "accumulation_at_stick_min", "case1_stays", "fig18_initial_conditions",
    "accumulation_zero_error", "fig17_design_rules", "accumulation_periods",
]


ALL: list[Callable[[], Claim]] = [
    fig4_trend, fig5_trend, fourier_optimum, fourier_shape, case1_average_velocity,
    cases_a_priori,
    case1_multipliers, cases23_multipliers, slip_slip_lambda2, local_stability,
    saltation_identical, finite_difference_close,
    period_velocity_change, lyapunov_decreasing, finite_time_convergence, slip_slip_convergence,
    stick_condition, stick_position_formula, positioning_error_definition, fig16_settings,
    fig17_design_rules, accumulation_zero_error, fixed_point_is_stick_min,
    map_predicts_stick_positions, accumulation_at_stick_min, case1_stays, fig18_initial_conditions,
    accumulation_periods, always_accumulates,
]


def compute_all(raw: Optional[dict] = None, timings: Optional[dict] = None,
                threads: int = 0, shared: Optional[dict] = None) -> list[Claim]:
    """Every claim of ALL, in order. ``raw`` maps figure numbers to Figure.raw (reused where a
    figure already computed a claim's data); ``shared`` may hold inputs computed beforehand
    ("sect73": accumulation_grid(), "floquet": floquet_grid(), "fig16", "fig17",
    "fourier"); ``timings`` collects seconds per claim."""
    raw = raw or {}
    shared = dict(shared or {})

    def get(name: str, make: Callable[[], object]) -> object:
        if name not in shared:
            start = time.perf_counter()
            shared[name] = make()
            if timings is not None:
                timings[f"({name})"] = time.perf_counter() - start
        return shared[name]

    fig6 = (raw.get("6") or {}).get("result")
    surfaces = raw.get("17")
    sweeps = [(setting[0], setting[1], raw[k])
              for k, setting in (("10", FIG10), ("11", FIG11)) if raw.get(k) is not None]
    inputs: dict[Callable, Callable[[], tuple]] = {
        fig4_trend: lambda: (raw.get("4"),),
        fig5_trend: lambda: (raw.get("5"),),
        fourier_optimum: lambda: (fig6 if fig6 is not None else
                                  get("fourier", _fourier_optimum_result),),
        fourier_shape: lambda: (fig6 if fig6 is not None else
                                get("fourier", _fourier_optimum_result),),
        cases_a_priori: lambda: (sweeps or None,),
        accumulation_periods: lambda: (surfaces,),
        accumulation_zero_error: lambda: (surfaces,),
        fig17_design_rules: lambda: (surfaces,),
        positioning_error_definition: lambda: (get("fig16", _fig16_accuracies),),
        fig16_settings: lambda: (get("fig16", _fig16_accuracies),),
        always_accumulates: lambda: (get("sect73", lambda: accumulation_grid(threads)),),
        map_predicts_stick_positions: lambda: (get("sect73", lambda: accumulation_grid(threads)),
                                               get("fig16", _fig16_accuracies)),
        accumulation_at_stick_min: lambda: (get("sect73", lambda: accumulation_grid(threads)),
                                            get("fig16", _fig16_accuracies)),
        case1_stays: lambda: (get("sect73", lambda: accumulation_grid(threads)),),
    }
    for fn in (case1_multipliers, cases23_multipliers, slip_slip_lambda2, local_stability,
               saltation_identical, finite_difference_close):
        inputs[fn] = lambda: (get("floquet", floquet_grid),)
    if surfaces is None:
        shared_surfaces = lambda: (get("fig17", _fig17_surfaces),)  # noqa: E731
        for fn in (accumulation_periods, accumulation_zero_error, fig17_design_rules):
            inputs[fn] = shared_surfaces
    table = []
    for fn in ALL:
        args = inputs[fn]() if fn in inputs else ()
        start = time.perf_counter()
        table.append(fn(*args))
        if timings is not None:
            timings[fn.__name__] = time.perf_counter() - start
    return table
