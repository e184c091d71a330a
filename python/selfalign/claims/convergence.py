"""Sect. 6.2, convergence: the velocity change over a period (eq. 37), the Lyapunov function
(eqs. 35, 36, Fig. 13), finite-time convergence for cases 1-3, and convergence only as t → ∞
for case 4 (contraction by c4, eq. 33)."""

from __future__ import annotations

import itertools
from typing import Sequence

import numpy as np

from .. import _selfalign as sa
from .claim import Claim, _fmt, _judge, _profile
from .closed_forms import slip_slip_c4
from .settings import CASE_SETTINGS, INITIAL_VELOCITIES, ROUND_OFF, SLIP_SLIP_SETTINGS


def period_velocity_change() -> Claim:
    profiles = {f"case {c}": _profile(*s) for c, s in CASE_SETTINGS.items()}
    profiles["quadratic sequence"] = sa.ScaledShapeFamily.paper_like().make(2.5, 1.5)
    worst = 0.0
    for profile in profiles.values():
        period = profile.period
        yd = profile.sample(np.linspace(0.0, period, 2001))[1]
        v0 = 1.0 + period + float(np.ptp(yd))  # v = v0 - t - (y'(t) - y'(0)) stays > 0
        for sign in (1.0, -1.0):
            end = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(0, 0, sign * v0),
                              sa.SimulationOptions(duration=period, record=False)).final_state
            expected = sign * v0 - period * sign  # eq. (37): Δv = -Δt Sign(v)
            worst = max(worst, abs(end.xd - expected) / v0)
    return Claim("Velocity change over a period", "Sect. 6.2, eq. (37)",
                 "over a period in which v keeps its sign, v(t + Δt) - v(t) = -Δt Sign(v): the "
                 "table's acceleration averages to zero",
                 f"{len(profiles)} profiles, v0 = ±(1 + Δt + range of y'); max relative error "
                 f"{worst:.2g}", _judge(worst < ROUND_OFF))


def _convergence_runs(settings: Sequence[tuple], periods: int) -> list:
    runs = []
    for setting in settings:
        profile = _profile(*setting)
        for v1, v2 in itertools.combinations(INITIAL_VELOCITIES, 2):
            options = sa.ConvergenceOptions(v1=v1, v2=v2, duration=periods * setting[0])
            runs.append((setting, v1, v2, sa.velocity_convergence(profile, options)))
    return runs


def lyapunov_decreasing() -> Claim:
    settings = [CASE_SETTINGS[c] for c in (1, 2, 3, 4)] + [SLIP_SLIP_SETTINGS[0]]
    runs = _convergence_runs(settings, 10)
    rise, flat, strict, ok, same_n, diff_n = 0.0, 0.0, True, True, 0, 0
    for _, _, _, c in runs:
        v = (np.asarray(c.v1) - np.asarray(c.v2)) ** 2 / 2  # eq. (35), recomputed
        t = np.asarray(c.t)
        scale = max(1.0, float(v[0]))
        ok &= float(np.abs(v - c.lyapunov).max()) <= ROUND_OFF * scale
        rise = max(rise, float(np.diff(v).max()) / scale)
        for iv in c.intervals:
            inside = v[(t > iv.t_begin) & (t < iv.t_end)]
            if inside.size < 2:
                continue
            if iv.same:
                same_n += 1
                flat = max(flat, float(np.ptp(inside)) / scale)
            elif inside[0] > ROUND_OFF * scale:
                diff_n += 1
                strict &= inside[-1] < inside[0]
    ok &= rise <= ROUND_OFF and flat <= ROUND_OFF and strict
    return Claim("Lyapunov function", "Sect. 6.2, eqs. (35), (36), Fig. 13",
                 "V = (v1 - v2)²/2 never increases (V' <= 0); it is constant where v̂1 = v̂2 and "
                 "decreases where v̂1 ≠ v̂2",
                 f"{len(runs)} pairs of responses (cases 1-4); largest rise of V between "
                 f"samples {rise:.2g} (relative); largest change inside {same_n} '=' intervals "
                 f"{flat:.2g}; V fell inside {'all' if strict else 'not all'} {diff_n} '≠' "
                 "intervals", _judge(ok))


def finite_time_convergence() -> Claim:
    settings = [CASE_SETTINGS[c] for c in (1, 2, 3)] + [(1.0, 0.084, 1.8, 1.1)]
    runs = _convergence_runs(settings, 30)
    missing, latest, apart = [], 0.0, 0.0
    for setting, v1, v2, c in runs:
        if c.t_coincide is None:
            missing.append((setting, v1, v2))
            continue
        latest = max(latest, c.t_coincide / setting[0])
        after = np.asarray(c.t) >= c.t_coincide
        apart = max(apart, float(np.abs(np.asarray(c.v1) - c.v2)[after].max()))
    cases = sorted({int(sa.steady_state(_profile(*s)).motion_case) for s in settings})
    text = (f"{len(runs) - len(missing)}/{len(runs)} pairs (cases {cases}) coincide, at the "
            f"latest after {latest:.2f} periods; afterwards max |v1 - v2| = {apart:.2g}")
    if missing:
        s, v1, v2 = missing[0]
        text += f"; never coincide: e.g. {_fmt(s)} from v = {v1}, {v2}"
    return Claim("Finite-time convergence, cases 1-3", "Sect. 6.2",
                 "for cases 1-3 two responses from different initial velocities coincide in "
                 "finite time (a unique steady velocity, no coexisting solutions)", text,
                 _judge(not missing and apart <= ROUND_OFF))


def slip_slip_convergence() -> Claim:
    periods = 40
    runs = _convergence_runs(SLIP_SLIP_SETTINGS, periods)
    ok = all(sa.steady_state(_profile(*s)).motion_case == sa.StickSlipCase.slip_slip
             for s in SLIP_SLIP_SETTINGS)
    worst, resting, coincided = 0.0, 0, []
    for setting, v1, v2, c in runs:
        period, _, a2, a3 = setting
        t, d = np.asarray(c.t), np.abs(np.asarray(c.v1) - c.v2)
        rests = bool(np.any((np.asarray(c.v1)[1:] == 0) | (np.asarray(c.v2)[1:] == 0)))
        if c.t_coincide is not None or d[-1] == 0:
            coincided.append((setting, v1, v2, c.t_coincide))
            ok &= rests  # only responses that stick in the transient may meet in finite time
            continue
        resting += rests
        at = np.searchsorted(t, [(periods - 2) * period, (periods - 1) * period])
        ratio = d[at[1]] / d[at[0]]
        worst = max(worst, abs(ratio - slip_slip_c4(a2, a3)))
        ok &= d[-1] < d[0]
    ok &= worst < 1e-6  # contraction per period vs eq. (33); |v1 - v2| >> rounding here
    text = (f"{len(runs) - len(coincided)}/{len(runs)} pairs never coincide within {periods} "
            f"periods; |v1 - v2| contracts per period by c4 of eq. (33) to {worst:.2g}")
    if coincided:
        s, v1, v2, tc = coincided[0]
        text += (f"; {len(coincided)} pairs coincide in finite time because both responses "
                 f"stick in the transient (e.g. {_fmt(s)} from v = {v1}, {v2})")
    return Claim("Convergence only as t → ∞, case 4", "Sect. 6.2, eq. (33)",
                 "for a case-4 (slip-slip) solution the mass never sticks and v1 = v2 is "
                 "reached only in the limit t → ∞; |v1 - v2| contracts by λ2 = c4 per period",
                 text, _judge(ok), "settings of the Fig. 10 plane with c4 ≈ 0.96; tolerance "
                                   "1e-6 on the contraction per period")
