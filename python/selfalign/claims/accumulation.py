"""Sect. 7.3, accumulation: the fixed point of map (59), map (59) against the simulated stick
positions, "accumulation always" under the section's condition, the approach to x_stick,min,
case-1 entries staying in the high-friction region, Fig. 18's dependence on the entry, and the
periods to accumulate over Fig. 17."""

from __future__ import annotations

import itertools
import math
from typing import Optional

import numpy as np

from .. import _selfalign as sa
from .accumulation_grid import AccumulationCase, accumulation_grid
from .claim import Claim, _fmt, _judge, _physical, _profile
from .closed_forms import (_first_map_stop, _map_governed, _t21, basin_bound, stick_map,
                           stick_map_fixed_point, x_stick_min)
from .positioning import _fig16_accuracies, _fig17_surfaces
from .settings import (ACCUMULATION_ENTRIES, ACCUMULATION_GRID, ACCUMULATION_RESTS, ROUND_OFF,
                       SECT72)
from .stick_sequences import StickSequences, _accumulated, _accumulation_tails, _run_cumsum


def fixed_point_is_stick_min() -> Claim:
    worst, count = 0.0, 0
    for period, w, c_mu, x_mu in itertools.product((1.0, 1.05), (0.02, 0.05, 0.1), (1.5, 2.5, 4.0),
                                                   (0.0, 0.3)):
        table = sa.TwoRegionTable(x_mu, w, c_mu)
        for a2, a3 in itertools.product(np.linspace(1.1, 3.9, 8), np.linspace(0.5, 3.9, 8)):
            if not (a3 <= a2 <= c_mu) or not _physical(period, 0.084, a2, a3):
                continue
            profile = _profile(period, 0.084, a2, a3)
            fixed = sa.StickPositionMap(profile, table).fixed_point()
            eq60 = stick_map_fixed_point(a2, w, c_mu, x_mu)
            on_map = float(stick_map(eq60, a2, a3, w, c_mu, x_mu, _t21(profile)))
            worst = max(worst, abs(fixed - eq60), abs(eq60 - x_stick_min(x_mu, w, c_mu, a2)),
                        abs(on_map - eq60))
            count += 1
    profile = _profile(1.05, 0.084, 2.2, 0.9)  # Fig. 18
    fig18 = sa.StickPositionMap(profile, sa.TwoRegionTable(0.0, 0.05, 2.5)).fixed_point()
    return Claim("Fixed point of map (59)", "Sect. 7.3, eqs. (59), (60), (41)",
                 "the fixed point of the stick-position map is (b2 + y2'')/b1 = x_stick,min "
                 "(y2'' the peak acceleration)",
                 f"{count} settings: max deviation among library fixed point, eq. (60), eq. (41) "
                 f"and eq. (59) at eq. (60): {worst:.2g}; Fig. 18: {fig18:.15f} (eq. 41: "
                 f"{x_stick_min(0.0, 0.05, 2.5, 2.2):.15f})",
                 _judge(count > 0 and worst <= ROUND_OFF))


def always_accumulates(grid: Optional[list[AccumulationCase]] = None) -> Claim:
    grid = grid if grid is not None else accumulation_grid()
    domain = [c for c in grid if c.in_domain]
    held = [c for c in domain if c.condition]
    failures = []  # (overshoot / w, case, entry index, run)
    rest_failures = 0
    library_agrees = sum(c.library_every == c.condition for c in domain)
    for c in held:
        target = x_stick_min(c.accuracy.x_mu, c.width, c.c_mu, c.a2)
        for i, run in enumerate(c.accuracy.runs):
            if not _accumulated(run, target):
                failures.append(((run.end_position - target) / c.width, c, i, run))
        rest_failures += sum(not _accumulated(run, target) for _, run in c.rests)
    entries = sum(len(c.accuracy.runs) + len(c.rests) for c in held)
    text = (f"{len(grid)} physical settings (Δt {ACCUMULATION_GRID['periods']}, Δy "
            f"{ACCUMULATION_GRID['strokes']}, w {ACCUMULATION_GRID['widths']}, c_mu "
            f"{ACCUMULATION_GRID['c_mus']}, {len(ACCUMULATION_GRID['a2'])} y2'' x "
            f"{len(ACCUMULATION_GRID['a3'])} y3''); {len(domain)} meet Sect. 7.3's "
            f"assumptions, {len(held)} of them satisfy x_(n+1)(x_mu) < x_stick,min; "
            f"{entries} runs ({ACCUMULATION_ENTRIES} steady entries, {ACCUMULATION_RESTS} starts "
            f"at rest at x_1 in [x_mu, x_stick,min) each). ")
    if failures:
        bad_settings = {id(f[1]) for f in failures}
        over, c, i, run = max(failures, key=lambda f: f[0])
        x_mu = c.accuracy.x_mu
        target = x_stick_min(x_mu, c.width, c.c_mu, c.a2)
        first = stick_map(x_mu, c.a2, c.a3, c.width, c.c_mu, x_mu,
                          _t21(_profile(c.period, c.stroke, c.a2, c.a3)))
        failed_here = sum(not _accumulated(r, target) for r in c.accuracy.runs)
        stops = [x for x in np.asarray(run.stick_positions) if x >= x_mu]
        why = (f"It enters sliding and its first stop in the transition region, x_mu + "
               f"{stops[0] - x_mu:.6f}, already lies beyond x_stick,min: the condition bounds "
               "only slides that start at rest there." if stops and stops[0] >= target else
               f"Its stick positions beyond x_mu: {[round(x - x_mu, 6) for x in stops[:4]]}.")
        text += (f"Counterexample: settings where some steady entries do not accumulate: "
                 f"{len(bad_settings)} ({len(failures)} runs). Largest: "
                 f"(Δt, Δy, w, c_mu, y2'', y3'') = {_fmt(c.setting)}, case-1 entry, θ = {c.theta:.3f} < π: x_(n+1)(x_mu) - x_mu "
                 f"= {float(first) - x_mu:.6f} < x_stick,min - x_mu = {target - x_mu:.6f} "
                 f"(eqs. 59, 41), yet entry {i} (x_0s = {c.accuracy.entries[i]:.5f}) ends by "
                 f"{run.kind.name.replace('_', ' ')} at x_mu + {run.end_position - x_mu:.6f}, "
                 f"{over:.2%} of w beyond x_stick,min ({failed_here}/{len(c.accuracy.runs)} "
                 f"entries there). {why} Starts at rest at x_1: {rest_failures} failures.")
    else:
        text += "Every run accumulates at x_stick,min."
    text += (f" Library StickPositionMap.accumulates_for_every_entry() agrees with the "
             f"condition in {library_agrees}/{len(domain)} of these settings.")
    return Claim("Accumulation always (Sect. 7.3)", "Sect. 7.3, eqs. (59), (41)",
                 "accumulation to an end position will always occur if x_(n+1)(x_mu) < "
                 "x_stick,min, and is then independent of the initial conditions",
                 text, _judge(held and not failures and rest_failures == 0),
                 "Judged only where the section's assumptions hold: case-1 steady entry, "
                 "y2'' < c_mu (x_stick,min exists), θ = sqrt(b1)(t2 - t1) < π (eq. 59 derived "
                 "for a slip through [t1, t2]). The condition and x_stick,min are eqs. (59), "
                 "(41) written in claims/closed_forms.py. accumulates_for_every_entry() is only "
                 "compared; it is None where the condition's derivation does not hold (peak > "
                 "c_mu, y3'' > y2'').")


def _stick_sets(grid: list[AccumulationCase], accuracies: dict, theta_below_pi: bool) -> list:
    """(Δt, Δy, w, c_mu, y2'', y3'', x_mu, stick sequences) of the Fig. 16 settings and the grid
    (only its settings with θ < π when ``theta_below_pi``: eq. (59) is derived for them)."""
    period, stroke, w, c_mu = SECT72
    sets = [(period, stroke, w, c_mu, a2, a3, acc.x_mu, StickSequences.of(acc.runs))
            for (a2, a3), acc in accuracies.items()]
    sets += [(c.period, c.stroke, c.width, c.c_mu, c.a2, c.a3, c.accuracy.x_mu, c.sequences)
             for c in grid if not theta_below_pi or c.theta < math.pi]
    return sets


def map_predicts_stick_positions(grid: Optional[list[AccumulationCase]] = None,
                                 accuracies: Optional[dict] = None) -> Claim:
    grid = grid if grid is not None else accumulation_grid()
    accuracies = accuracies if accuracies is not None else _fig16_accuracies()
    sets = _stick_sets(grid, accuracies, theta_below_pi=True)
    worst, pairs = 0.0, 0
    for p, s, w_, c_, a2, a3, x_mu, seq in sets:
        t21 = _t21(_profile(p, s, a2, a3))
        x_n, x_next = seq.pairs()
        governed = _map_governed(x_n, a2, a3, w_, c_, x_mu, t21)
        if governed.any():
            err = np.abs(stick_map(x_n[governed], a2, a3, w_, c_, x_mu, t21) - x_next[governed])
            worst = max(worst, float(err.max()))
            pairs += int(governed.sum())
    return Claim("Map (59) = simulated stick positions", "Sect. 7.3, eqs. (42)-(59)",
                 "the next stick position x_(n+1) follows from x_n by map (59)",
                 f"{pairs} consecutive stick positions of exact stopping runs against eq. (59) "
                 f"written here: max difference {worst:.2g}",
                 _judge(pairs > 0 and worst <= ROUND_OFF),
                 "pairs where the map's assumptions hold: x_mu <= x_n < x_stick,min, friction "
                 "at x_n >= y3'', next stop within the transition region, θ < π")


# A stop onto x_stick,min from closer than this is the rounding end of the geometric approach
# (distances shrink by about cos θ per period, so the last one before rounding is
# ~1e-12/cos θ); from farther away x_stick,min would be reached in finite time.
ROUNDED_ONTO = 1e-6


def accumulation_at_stick_min(grid: Optional[list[AccumulationCase]] = None,
                              accuracies: Optional[dict] = None) -> Claim:
    grid = grid if grid is not None else accumulation_grid()
    accuracies = accuracies if accuracies is not None else _fig16_accuracies()
    sets = _stick_sets(grid, accuracies, theta_below_pi=False)
    runs = labelled = not_increasing = reached = not_shrinking = overshoot = rounded = 0
    for p, s, w_, c_, a2, a3, x_mu, seq in sets:
        target = x_stick_min(x_mu, w_, c_, max(a2, a3))
        ended = seq.ended_at(target)  # accumulation by eq. (41), whatever the label says
        if not ended.any():
            continue
        runs += int(ended.sum())
        labelled += int((ended & seq.labelled).sum())
        keep = ended[seq.run]
        x, rid = seq.x[keep], seq.run[keep]
        governed = _map_governed(x, a2, a3, w_, c_, x_mu, _t21(_profile(p, s, a2, a3)))
        tail = _accumulation_tails(x, rid, governed)
        landed = tail & (x >= target - ROUND_OFF)
        approach = tail & (_run_cumsum(landed, rid) - landed == 0)  # up to the first landing
        overshoot += np.unique(rid[tail & (x > target + ROUND_OFF)]).size
        at = np.flatnonzero(approach[:-1] & approach[1:] & (rid[1:] == rid[:-1]))
        gaps = x[at + 1] - x[at]
        not_increasing += np.unique(rid[at][gaps <= 0]).size
        free = ~landed[at + 1]  # the landing step itself is rounding, not compared
        chained = (at[1:] == at[:-1] + 1) & (rid[at[1:]] == rid[at[:-1]]) & free[1:]
        not_shrinking += np.unique(rid[at[1:]][chained & (gaps[1:] >= gaps[:-1])]).size
        lands = at[landed[at + 1]]
        far = target - x[lands] > ROUNDED_ONTO
        reached += np.unique(rid[lands][far]).size
        rounded += np.unique(rid[lands][~far]).size
        first = tail & landed & (_run_cumsum(tail, rid) == 1)  # a run that starts on it
        reached += np.unique(rid[first]).size
    ok = runs > 0 and not_increasing == 0 and reached == 0 and not_shrinking == 0 \
        and overshoot == 0
    return Claim("Accumulation at x_stick,min", "Sect. 7.2, 7.3",
                 "when accumulation occurs the stick positions approach x_stick,min on smaller "
                 "and smaller scales and reach it only as t → ∞",
                 f"{runs} runs end at x_stick,min of eq. (41) ({labelled} labelled accumulation "
                 f"by the library); stick positions not increasing in {not_increasing}, gaps "
                 f"not shrinking in {not_shrinking}, beyond x_stick,min in {overshoot}, "
                 f"x_stick,min reached from farther than {ROUNDED_ONTO:g} in {reached}; "
                 f"{rounded} iterate onto it to rounding (distance < {ROUNDED_ONTO:g} before "
                 "the last stop)", _judge(ok),
                 "Accumulation is read from the end or last stick position against eq. (41), "
                 "not from the library's StopKind label, which builds set differently for a "
                 "sequence that iterates onto x_stick,min.")


def case1_stays(grid: Optional[list[AccumulationCase]] = None) -> Claim:
    grid = grid if grid is not None else accumulation_grid()
    chosen = [c for c in grid if c.motion_case == 1][::25]
    worst, runs = 0.0, 0
    for c in chosen:
        profile = _profile(c.period, c.stroke, c.a2, c.a3)
        friction = sa.two_region_friction(c.accuracy.x_mu, c.width, c.c_mu)
        for x0 in np.asarray(c.accuracy.entries)[::8]:
            tr = sa.simulate(profile, friction,
                             sa.ObjectState(0.0, float(x0), c.accuracy.steady.x_dot_0s),
                             sa.SimulationOptions(duration=8 * c.period,
                                                  output_step=c.period / 500)).trajectory
            x = np.asarray(tr.x)
            inside = np.flatnonzero(x >= c.accuracy.x_mu)
            if inside.size:
                worst = max(worst, c.accuracy.x_mu - float(x[inside[0]:].min()))
                runs += 1
    return Claim("Case-1 entry stays", "Sect. 7.3",
                 "a case-1 motion guarantees that the mass stays in the high-friction region "
                 "once it entered it",
                 f"{runs} entries in {len(chosen)} case-1 settings, 8 periods each, sampled at "
                 f"Δt/500: largest excursion back below x_mu {max(worst, 0.0):.2g}",
                 _judge(runs > 0 and worst <= ROUND_OFF))


def fig18_initial_conditions() -> Claim:
    period, stroke, a2, a3, w, c_mu = 1.05, 0.084, 2.2, 0.9, 0.05, 2.5
    profile = _profile(period, stroke, a2, a3)
    acc = sa.positioning_accuracy(profile, w, c_mu)
    x_mu = acc.x_mu
    target = x_stick_min(x_mu, w, c_mu, a2)
    bound = basin_bound(a2, a3, w, c_mu, x_mu, _t21(profile))
    agree, beyond, accumulated = 0, True, 0
    for run in acc.runs:
        first = _first_map_stop(run.stick_positions, a2, a3, w, c_mu, x_mu, _t21(profile))
        predicted = first is not None and first > bound  # first map-governed stop in the basin
        actual = _accumulated(run, target)
        accumulated += actual
        agree += predicted == actual
        if not actual:
            beyond &= run.end_position > target
    n = len(acc.runs)
    ok = 0 < accumulated < n and agree == n and beyond
    return Claim("Fig. 18: outcome depends on entry", "Sect. 7.3, Fig. 18",
                 "depending on the initial conditions the mass accumulates at x_stick,min or "
                 "sticks beyond it; the middle dashed line separates the two",
                 f"{accumulated}/{n} entries end at x_stick,min (eq. 41), the others stop "
                 f"beyond it: {beyond}; the basin bound c1 - 2K cos θ = x_mu + "
                 f"{bound - x_mu:.5f} (closed form) predicts the outcome of {agree}/{n}",
                 _judge(ok))


def accumulation_periods(surfaces: Optional[dict] = None) -> Claim:
    s = surfaces if surfaces is not None else _fig17_surfaces()
    acc = s["accumulating_entries"] > 0
    p99 = int(s["max_periods_p99"][acc].max()) if acc.any() else -1
    p999 = int(s["max_periods_p999"][acc].max()) if acc.any() else -1
    ok = acc.any() and 1 <= p99 <= 5 and 1 <= p999 <= 7
    text = (f"{int(acc.sum())} cells with accumulating entries; max periods p=0.99: {p99}, "
            f"p=0.999: {p999}")
    if not ok and acc.any():
        worst = np.where(acc, np.maximum(s["max_periods_p99"] - 5, s["max_periods_p999"] - 7),
                         -np.inf)
        i, j = np.unravel_index(np.argmax(worst), worst.shape)
        over = acc & ((s["max_periods_p99"] > 5) | (s["max_periods_p999"] > 7))
        a2, a3 = np.meshgrid(s["a2"], s["a3"], indexing="ij")
        text += (f"; over the paper's bound in {int(over.sum())} cells "
                 f"({int((over & (a2 == a3)).sum())} on the diagonal y2'' = y3''), e.g. "
                 f"(y2'', y3'') = ({s['a2'][i]:.4g}, {s['a3'][j]:.4g}): "
                 f"{int(s['max_periods_p99'][i, j])} and {int(s['max_periods_p999'][i, j])} "
                 "periods")
    return Claim("Periods to accumulate", "Sect. 7.3",
                 "where accumulation occurs in Fig. 17, x_mu + p (x_stick,min - x_mu) is reached "
                 "within 5 periods for p = 0.99 and within 7 for p = 0.999", text, _judge(ok),
                 "Exact stopping runs instead of the paper's time-stepping. Builds that count "
                 "the diagonal y2'' = y3'' (geometric convergence, factor ~0.46 per period) as "
                 "accumulation include those cells here; older builds label them permanent "
                 "stick and leave them out.")
