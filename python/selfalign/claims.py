"""The paper's quantitative claims, each computed (never typed in) and judged PASS or FAIL.

Every claim function calls the library and compares with a value from the paper or a closed
form written out here, so breaking the code behind a claim turns its row to FAIL.
"""

from __future__ import annotations

import dataclasses
from typing import Callable, Optional

import numpy as np

from . import _selfalign as sa


@dataclasses.dataclass
class Claim:
    """One row of the claims table."""

    name: str
    source: str  # where the paper states it
    statement: str
    computed: str  # what selfalign computed
    status: str  # "PASS", "FAIL" or "PENDING"

    @property
    def passed(self) -> bool:
        return self.status == "PASS"


def _judge(ok: bool) -> str:
    return "PASS" if ok else "FAIL"


def case1_multipliers() -> Claim:
    f = sa.floquet_multipliers(sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=3.0, a3=0.9))
    rows, ok = [], True
    for method, tol in (("analytic", 1e-12), ("saltation", 1e-10), ("finite_difference", 1e-5)):
        m = getattr(f, method).multipliers
        rows.append(f"{method}: {m[0].real:.3g}, {m[1].real:.3g}")
        ok &= abs(m[0] - 1) < tol and abs(m[1]) < tol
    return Claim("Case-1 Floquet multipliers", "Sect. 6.1, eq. (30)",
                 "λ1 = 1, λ2 = 0 for a case-1 response (y2'' = 3, y3'' = 0.9)", "; ".join(rows),
                 _judge(ok))


def slip_slip_lambda2() -> Claim:
    a2, a3 = 1.05, 2.0
    f = sa.floquet_multipliers(sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=a2, a3=a3))
    formula = ((a2 - 1) * (a3 - 1)) / ((a2 + 1) * (a3 + 1))  # eq. (33)
    salt = f.saltation.multipliers[1].real
    fd = f.finite_difference.multipliers[1].real
    ok = int(f.steady.motion_case) == 4 and abs(salt - formula) < 1e-10 and abs(fd - formula) < 1e-5
    return Claim("Slip-slip multiplier", "Sect. 6.1, eq. (33)",
                 "λ2 = ((y2''-1)(y3''-1))/((y2''+1)(y3''+1)) in slip-slip",
                 f"formula {formula:.10f}; saltation {salt:.10f}; finite difference {fd:.8f}",
                 _judge(ok))


def fixed_point_is_stick_min() -> Claim:
    profile = sa.ThreePhaseProfile(period=1.05, stroke=0.084, a2=2.2, a3=0.9)
    friction = sa.TwoRegionFriction(0.0, 0.05, 2.5)
    fixed = sa.StickPositionMap(profile, friction).fixed_point()
    x_min = 0.0 + 0.05 * (2.2 - 1) / (2.5 - 1)  # eq. (41) by hand
    ok = abs(fixed - x_min) < 1e-12
    return Claim("Fixed point of map (59)", "Sect. 7.3, eqs. (60), (41)",
                 "the fixed point of the stick-position map is x_stick,min (Fig. 18 setting)",
                 f"fixed point {fixed:.15f}; x_stick,min {x_min:.15f}", _judge(ok))


def accumulation_periods(surfaces: Optional[dict] = None) -> Claim:
    if surfaces is None:
        grid = sa.linear_grid(2.5 / 60, 2.5, 60)
        surfaces = sa.positioning_surfaces(
            1.0, 0.084, 0.05, 2.5, grid, grid,
            options=sa.PositioningOptions(entries=40, stopping=sa.StoppingOptions(max_periods=300)))
    acc = surfaces["accumulating_entries"] > 0
    p99 = int(surfaces["max_periods_p99"][acc].max()) if acc.any() else -1
    p999 = int(surfaces["max_periods_p999"][acc].max()) if acc.any() else -1
    ok = acc.any() and 1 <= p99 <= 5 and 1 <= p999 <= 7
    return Claim("Periods to accumulate", "Sect. 7.3",
                 "where accumulation occurs in Fig. 17, p = 0.99 is reached within 5 periods and "
                 "p = 0.999 within 7",
                 f"{int(acc.sum())} cells with accumulating entries; max periods p=0.99: {p99}, "
                 f"p=0.999: {p999}", _judge(ok))


def fig16_settings() -> Claim:
    res = {}
    for a2, a3 in ((2.3, 1.3), (1.8, 1.1)):
        profile = sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=a2, a3=a3)
        res[(a2, a3)] = sa.positioning_accuracy(profile, 0.05, 2.5)
    up, low = res[(2.3, 1.3)], res[(1.8, 1.1)]
    ok = up.accumulates and up.dx_d == 0 and not low.accumulates and low.dx_d > 1e-4
    return Claim("Fig. 16 settings", "Sect. 7.2, Fig. 16",
                 "(2.3, 1.3) stops at one position for every entry (accumulation); (1.8, 1.1) "
                 "stops at different positions",
                 f"(2.3, 1.3): Δx_d = {up.dx_d:.3g}, {up.accumulating_entries}/100 accumulate; "
                 f"(1.8, 1.1): Δx_d = {low.dx_d:.3g}, {low.accumulating_entries}/100 accumulate",
                 _judge(ok))


def _spearman(x: np.ndarray, y: np.ndarray) -> float:
    finite = np.isfinite(x) & np.isfinite(y)
    rx = np.argsort(np.argsort(x[finite]))
    ry = np.argsort(np.argsort(y[finite]))
    return float(np.corrcoef(rx, ry)[0, 1])


def fig4_trend(sweep: Optional[dict] = None) -> Claim:
    if sweep is None:
        sweep = sa.sweep_period(sa.ScaledShapeFamily.paper_like(), 0.02, np.linspace(0.02, 0.2, 30))
    rho = _spearman(sweep["period"], sweep["f"])
    return Claim("Fig. 4 trend", "Sect. 4.4.1, Fig. 4",
                 "a large excitation frequency is beneficial: f increases with Δt (Δy = 0.02)",
                 f"Spearman rank correlation of f with Δt: {rho:.3f} (PASS if >= 0.9)",
                 _judge(rho >= 0.9))


def fig5_trend(sweep: Optional[dict] = None) -> Claim:
    if sweep is None:
        sweep = sa.sweep_stroke(sa.ScaledShapeFamily.paper_like(), 0.05, np.linspace(0.002, 0.04, 30))
    rho = _spearman(sweep["stroke"], sweep["f"])
    return Claim("Fig. 5 trend", "Sect. 4.4.1, Fig. 5",
                 "a large stroke is beneficial: f decreases with Δy (Δt = 0.05)",
                 f"Spearman rank correlation of f with Δy: {rho:.3f} (PASS if <= -0.9)",
                 _judge(rho <= -0.9))


def case1_average_velocity() -> Claim:
    a2, a3 = 3.0, 0.9
    profile = sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=a2, a3=a3)
    sol = profile.solution
    t2 = sol.t2 - sol.t1
    v2, x2 = (a2 - 1) * t2, 0.5 * (a2 - 1) * t2 ** 2  # eqs. (16), (17)
    closed = (x2 + v2 ** 2 / (2 * (1 + a3))) / 1.0  # eqs. (20), (21), (24), (10)
    v_bar = sa.steady_state(profile).v_bar
    return Claim("Case-1 average velocity", "Sect. 5.1, eqs. (12)-(24), (10)",
                 "the steady v̄ of a case-1 response follows from the analytic solution",
                 f"closed form {closed:.15f}; simulated {v_bar:.15f}",
                 _judge(abs(v_bar - closed) < 1e-13))


def cases_a_priori(grids: Optional[list[dict]] = None) -> Claim:
    if grids is None:
        g = sa.linear_grid(0.03, 3.0, 100)
        grids = [sa.sweep_accelerations(1.0, 0.084, g, g)]
    cells = sum(r["predicted"].size for r in grids)
    agree = sum(int((r["predicted"] == r["observed"]).sum()) for r in grids)
    seen = sorted(set(int(c) for r in grids for c in np.unique(r["observed"])))
    return Claim("Motion cases a priori", "Sect. 5.1, Fig. 8, Table 1",
                 "the case follows a priori from (Δt, Δy, y2'', y3'') (flow chart, "
                 "docs/motion-cases.md)",
                 f"{agree}/{cells} cells agree with the simulated steady state; cases seen {seen}",
                 _judge(agree == cells))


def fourier_optimum(result=None) -> Claim:
    if result is None:
        result = sa.optimize_fourier(sa.ActuatorLimits(), sa.OptimizeOptions(order=12, starts=4))
    ok = result.feasible and result.f <= 5.6e-4 and result.max_velocity <= 3.2 * (1 + 1e-9) \
        and result.max_acceleration <= 1275 * (1 + 1e-9)
    return Claim("Fig. 6 Fourier optimum", "Sect. 4.4.2, Fig. 6",
                 "the 12th-order Fourier optimum under Δt = 0.072, Δy = 0.021, y'_max = 3.2, "
                 "y''_max = 1275 reaches the paper's f = 56, read as f = 5.6e-4",
                 f"f = {result.f:.3g} (v̄ = {result.v_bar:.3f}), max|y'| = "
                 f"{result.max_velocity:.3g}, max|y''| = {result.max_acceleration:.4g}",
                 _judge(ok))


ALL: list[Callable[[], Claim]] = [case1_average_velocity, case1_multipliers, slip_slip_lambda2,
                                   cases_a_priori, fig4_trend, fig5_trend, fixed_point_is_stick_min,
                                   fig16_settings, accumulation_periods, fourier_optimum]
