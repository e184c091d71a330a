"""Sects. 7-7.2, stopping and positioning accuracy: the friction map and the stick condition
(eqs. 9, 38, 40), x_stick,min and the c_mu limit (eqs. 40, 41), the positioning error Δx_d
(Sect. 7.1, eq. 39), the settings of Fig. 16, and Fig. 17's zero-error region and design rules
(Fig. 17's surfaces are shared with the Sect. 7.3 claim on the periods to accumulate)."""

from __future__ import annotations

import itertools
import math
from typing import Optional

import numpy as np

from .. import _selfalign as sa
from .claim import Claim, _judge, _profile
from .closed_forms import friction_bound, x_stick_min
from .settings import ACCUMULATION_MAX_PERIODS, ROUND_OFF, SECT72
from .stick_sequences import _accumulated
from .trends import _spearman


def stick_condition() -> Claim:
    x_mu = 0.3
    worst, disagree, total = 0.0, 0, 0
    for w, c_mu in itertools.product((0.02, 0.05, 0.1), (1.5, 2.5, 4.0)):
        friction = sa.two_region_friction(x_mu, w, c_mu)
        x = np.linspace(x_mu - 0.5 * w, x_mu + 1.5 * w, 401)
        m = friction_bound(x, x_mu, w, c_mu)  # eqs. (7)-(9)
        worst = max(worst, float(np.abs(np.asarray(friction.bound(x)) - m).max()))
        for peak in np.linspace(0.5, c_mu + 0.5, 9):
            held = np.asarray(sa.sticks_permanently(friction, float(peak), x))
            clear = np.abs(m - peak) > ROUND_OFF  # skip points on the boundary itself
            disagree += int(np.count_nonzero(held[clear] != (m >= peak)[clear]))
            total += int(np.count_nonzero(clear))
    return Claim("Friction map and stick condition", "Sect. 7, eqs. (9), (38), (40)",
                 "in the transition region the friction is 1 + (c_mu - 1)(x - x_mu)/w; the mass "
                 "can stick for good at x as long as y_i'' < 1 + (c_mu - 1)(x - x_mu)/w",
                 f"max |m(x) - eq. (9)| = {worst:.2g} over 9 (w, c_mu); sticks_permanently "
                 f"disagrees with eq. (40) at {disagree}/{total} points",
                 _judge(worst <= ROUND_OFF and disagree == 0))


def stick_position_formula() -> Claim:
    worst = 0.0
    for x_mu, w, c_mu in itertools.product((0.0, 0.3), (0.02, 0.05, 0.1), (1.5, 2.5, 4.0)):
        table = sa.TwoRegionTable(x_mu, w, c_mu)
        for peak in np.linspace(1.0, c_mu, 7):
            got = sa.stick_position_min(table, float(peak))
            worst = max(worst, abs(got - x_stick_min(x_mu, w, c_mu, float(peak))))
    period, stroke, w, c_mu = SECT72
    outcomes = {}
    for a2 in (2.4, 2.6):  # peak just below and just above c_mu = 2.5
        acc = sa.positioning_accuracy(_profile(period, stroke, a2, 1.0), w, c_mu,
                                      sa.PositioningOptions(entries=20, stopping=sa.StoppingOptions(
                                          max_periods=ACCUMULATION_MAX_PERIODS)))
        outcomes[a2] = sum(r.kind != sa.StopKind.not_stopped for r in acc.runs)
    beyond = sa.stick_position_min(sa.TwoRegionTable(0.0, w, c_mu), 2.6)
    ok = worst <= ROUND_OFF and outcomes[2.4] == 20 and outcomes[2.6] == 0 and math.isinf(beyond)
    return Claim("x_stick,min and the c_mu limit", "Sect. 7.2, eqs. (40), (41)",
                 "x_stick,min = x_mu + w (max y_i'' - 1)/(c_mu - 1); permanent stick needs "
                 "y_i'' < c_mu (here 2.5)",
                 f"max |x_stick,min - eq. (41)| = {worst:.2g} over 126 settings; stopped entries "
                 f"of 20: {outcomes[2.4]} at y2'' = 2.4 < c_mu, {outcomes[2.6]} at 2.6 > c_mu "
                 f"(x_stick,min = {beyond})", _judge(ok))


def positioning_error_definition(accuracies: Optional[dict] = None) -> Claim:
    accuracies = accuracies if accuracies is not None else _fig16_accuracies()
    worst = 0.0
    for acc in accuracies.values():
        over = np.asarray(acc.end_positions) - acc.x_mu
        dx_d = (over.max() - over.min()) / 2  # eq. (39)
        x_d = acc.x_mu + over.min() + dx_d
        worst = max(worst, abs(acc.dx_d - dx_d), abs(acc.x_d - x_d))
    return Claim("Positioning error Δx_d", "Sect. 7.1, eq. (39)",
                 "Δx_d = (Δx_overshoot,max - Δx_overshoot,min)/2 over steady entries "
                 "-v̄Δt <= x_0s <= 0 with x_mu = Δx; x_d = x_mu + Δx_overshoot,min + Δx_d",
                 f"max |library - eq. (39)| over the Fig. 16 settings: {worst:.2g}",
                 _judge(worst <= ROUND_OFF))


def _fig16_accuracies() -> dict:
    period, stroke, w, c_mu = SECT72
    return {s: sa.positioning_accuracy(_profile(period, stroke, *s), w, c_mu)
            for s in ((2.3, 1.3), (1.8, 1.1))}


def fig16_settings(accuracies: Optional[dict] = None) -> Claim:
    res = accuracies if accuracies is not None else _fig16_accuracies()
    up, low = res[(2.3, 1.3)], res[(1.8, 1.1)]
    w, c_mu = SECT72[2:]
    at_up = sum(_accumulated(r, x_stick_min(up.x_mu, w, c_mu, 2.3)) for r in up.runs)
    at_low = sum(_accumulated(r, x_stick_min(low.x_mu, w, c_mu, 1.8)) for r in low.runs)
    ok = at_up == len(up.runs) and up.dx_d <= ROUND_OFF and at_low < len(low.runs) \
        and low.dx_d > 1e-4
    return Claim("Fig. 16 settings", "Sect. 7.2, Fig. 16",
                 "(2.3, 1.3) stops at one position for every entry (accumulation); (1.8, 1.1) "
                 "stops at different positions",
                 f"(2.3, 1.3): Δx_d = {up.dx_d:.3g}, {at_up}/{len(up.runs)} entries end at "
                 f"x_stick,min (eq. 41); (1.8, 1.1): Δx_d = {low.dx_d:.3g}, "
                 f"{at_low}/{len(low.runs)} end there", _judge(ok))


def _fig17_surfaces(n: int = 60, entries: int = 40) -> dict:
    period, stroke, w, c_mu = SECT72
    grid = sa.linear_grid(2.5 / n, 2.5, n)
    options = sa.PositioningOptions(entries=entries,
                                    stopping=sa.StoppingOptions(max_periods=300))
    return sa.positioning_surfaces(period, stroke, w, c_mu, grid, grid, options=options)


def accumulation_zero_error(surfaces: Optional[dict] = None) -> Claim:
    s = surfaces if surfaces is not None else _fig17_surfaces()
    acc = np.asarray(s["accumulates"], dtype=bool)
    dx = np.asarray(s["dx_d"])
    zero = np.isfinite(dx) & (np.abs(dx) <= ROUND_OFF)
    a2, a3 = np.meshgrid(s["a2"], s["a3"], indexing="ij")
    other = zero & ~acc
    diagonal = int(np.count_nonzero(other & (a2 == a3)))
    ok = acc.any() and bool(np.all(zero[acc]))
    return Claim("Accumulation gives Δx_d = 0", "Sect. 7.2, Fig. 17 (C), (D)",
                 "a design space with Δx_d = 0 exists; where accumulation occurs (C) the "
                 "positioning error vanishes (D)",
                 f"{int(acc.sum())} accumulating cells, Δx_d = 0 in {int(zero[acc].sum())} of "
                 f"them; Δx_d = 0 without accumulation in {int(other.sum())} cells "
                 f"({diagonal} on the diagonal y2'' = y3'')", _judge(ok),
                 "Uses the library's labels: builds differ on the diagonal y2'' = y3'' (one "
                 "end position reached geometrically), labelled permanent stick by older "
                 "builds and accumulation, hence part of (C), by newer ones.")


def fig17_design_rules(surfaces: Optional[dict] = None) -> Claim:
    s = surfaces if surfaces is not None else _fig17_surfaces()
    a2, a3 = np.meshgrid(s["a2"], s["a3"], indexing="ij")
    f, case = np.asarray(s["f"]), np.asarray(s["case"])
    moving = np.isfinite(f) & np.isin(case, (1, 3, 4))
    rho = _spearman(a2[moving], f[moving])
    high = np.median(f[moving & (a2 >= np.quantile(a2[moving], 0.75))])
    low = np.median(f[moving & (a2 <= np.quantile(a2[moving], 0.25))])
    case1_a3 = a3[case == 1]
    ok = rho < 0 and high < low and case1_a3.size > 0 and case1_a3.max() <= 1.0
    return Claim("Fig. 17 design rules", "Sect. 7.2, Fig. 17 (A), (B)",
                 "a high y2'' moves the mass fast (low f); a low y3'' increases the chance of "
                 "case 1",
                 f"Spearman(f, y2'') over cells in motion (cases 1, 3, 4) {rho:.2f}; median f "
                 f"over the highest quarter of y2'' {high:.3g} vs the lowest quarter {low:.3g}; "
                 f"case 1 ({int(case1_a3.size)} cells) only at y3'' <= "
                 f"{case1_a3.max() if case1_a3.size else float('nan'):.3f}",
                 _judge(ok), "f is not monotone in y2'' (a band of slip-slip with high f); the "
                             "rule is read as a trend: negative rank correlation and lower f at "
                             "high y2''. 'y2'' < c_mu to stick': see 'x_stick,min and the c_mu "
                             "limit'.")
