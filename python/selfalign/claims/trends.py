"""Sect. 4.4 (Figs. 4-6): the trends of f with the excitation period and the stroke, the
12th-order Fourier optimum, and the shape of its acceleration over a period
(:func:`optimum_shape`, which figures.py uses for Fig. 6 too)."""

from __future__ import annotations

import dataclasses
import math
from typing import Optional

import numpy as np

from .. import _selfalign as sa
from .claim import Claim, _judge
from .settings import NEAR_ZERO_BAND


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
                 _judge(rho >= 0.9),
                 "Fig. 7-like polynomial sequence (the paper's sequence is not given).")


def fig5_trend(sweep: Optional[dict] = None) -> Claim:
    if sweep is None:
        sweep = sa.sweep_stroke(sa.ScaledShapeFamily.paper_like(), 0.05, np.linspace(0.002, 0.04, 30))
    rho = _spearman(sweep["stroke"], sweep["f"])
    return Claim("Fig. 5 trend", "Sect. 4.4.1, Fig. 5",
                 "a large stroke is beneficial: f decreases with Δy (Δt = 0.05)",
                 f"Spearman rank correlation of f with Δy: {rho:.3f} (PASS if <= -0.9)",
                 _judge(rho <= -0.9),
                 "Fig. 7-like polynomial sequence (the paper's sequence is not given).")


def _fourier_optimum_result():
    return sa.optimize_fourier(sa.ActuatorLimits(), sa.OptimizeOptions(order=12, starts=4))


def fourier_optimum(result=None) -> Claim:
    if result is None:
        result = _fourier_optimum_result()
    ok = result.feasible and result.f <= 5.6e-4 and result.max_velocity <= 3.2 * (1 + 1e-9) \
        and result.max_acceleration <= 1275 * (1 + 1e-9)
    return Claim("Fig. 6 Fourier optimum", "Sect. 4.4.2, Fig. 6",
                 "the 12th-order Fourier optimum under Δt = 0.072, Δy = 0.021, y'_max = 3.2, "
                 "y''_max = 1275 reaches the paper's f = 56, read as f = 5.6e-4",
                 f"f = {result.f:.3g} (v̄ = {result.v_bar:.3f}), max|y'| = "
                 f"{result.max_velocity:.3g}, max|y''| = {result.max_acceleration:.4g}",
                 _judge(ok), "f = 56 as printed is impossible under these limits (f ~ 1e-4).")


@dataclasses.dataclass
class OptimumShape:
    """The shape of an optimised profile's acceleration over one period (Fig. 6)."""

    sign_changes: int  # sign changes of y'' per period (exact zeros skipped)
    band: float  # |y''| below this counts as "approximately zero" [-]
    band_fraction: float  # band / y''_max
    negative_lobes: int  # intervals with y'' < -band per period
    positive_lobes: int  # intervals with y'' > +band
    near_zero_intervals: int  # intervals with |y''| <= band
    longest_near_zero: float  # longest near-zero interval / period
    back_slide: float  # backward relative sliding / forward relative sliding per period
    min_absolute_velocity: float  # min of x' + y' over the steady period [-]
    x_dot_0s: float  # steady initial velocity

    @property
    def as_paper(self) -> bool:
        """The paper's description: one near-zero, one negative, one positive interval."""
        return self.negative_lobes == 1 and self.positive_lobes == 1 \
            and self.near_zero_intervals >= 1

    def describe(self) -> str:
        lead = ("The computed optimum has the paper's shape" if self.as_paper else
                "The computed optimum does not have the paper's shape")
        return (f"{lead}: per period y'' changes sign {self.sign_changes} times; counting "
                f"|y''| < {self.band:g} ({self.band_fraction:.0%} of y''_max) as zero it has "
                f"{self.negative_lobes} negative and {self.positive_lobes} positive "
                f"acceleration intervals (paper: one of each) and {self.near_zero_intervals} "
                f"near-zero intervals, the longest {self.longest_near_zero:.0%} of the period. "
                f"As the paper says, the object (almost) does not slide back: backward sliding "
                f"relative to the table is {self.back_slide:.0%} of the forward sliding, and "
                f"its absolute velocity x' + y' stays >= {self.min_absolute_velocity:.3f}.")


def _cyclic_runs(classes: np.ndarray) -> tuple[list[int], list[int]]:
    """Values and lengths of the runs of a periodic sequence (first and last run merged)."""
    edges = np.flatnonzero(classes[1:] != classes[:-1]) + 1
    starts = np.concatenate(([0], edges))
    lengths = list(np.diff(np.concatenate((starts, [len(classes)]))))
    values = [int(classes[s]) for s in starts]
    if len(values) > 1 and values[0] == values[-1]:
        lengths[0] += lengths.pop()
        values.pop()
    return values, lengths


def optimum_shape(result, samples: int = 7200) -> OptimumShape:
    """Measures an optimised profile (Fig. 6): sign changes of y'' and its intervals of
    negative, positive and near-zero acceleration over one period, and the steady response's
    backward sliding (time-stepping, 4000 steps per period as in Fig. 6)."""
    profile = sa.rebuild_profile(result)
    limits = result.limits
    period = limits.period
    band = NEAR_ZERO_BAND * limits.max_acceleration
    t = np.linspace(0.0, period, samples, endpoint=False)
    ydd = profile.sample(t)[2]
    signs = np.sign(ydd[ydd != 0])
    sign_changes = int(np.count_nonzero(signs != np.roll(signs, 1))) if signs.size else 0
    classes = np.where(ydd > band, 1, np.where(ydd < -band, -1, 0))
    values, lengths = _cyclic_runs(classes)
    zero_lengths = [n for v, n in zip(values, lengths) if v == 0]
    steady = sa.steady_state(profile)
    options = sa.SimulationOptions(method="time-stepping", duration=period, step=period / 4000,
                                   output_step=period / 4000)
    tr = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(0, 0, steady.x_dot_0s),
                     options).trajectory
    dt = np.diff(tr.t)
    forward = float(np.sum(np.maximum(tr.xd[:-1], 0.0) * dt))
    backward = float(-np.sum(np.minimum(tr.xd[:-1], 0.0) * dt))
    return OptimumShape(sign_changes, band, NEAR_ZERO_BAND, values.count(-1), values.count(1),
                        len(zero_lengths), max(zero_lengths, default=0) / samples,
                        backward / forward if forward > 0 else math.inf,
                        float(np.min(tr.xd + tr.yd)), steady.x_dot_0s)


def fourier_shape(result=None) -> Claim:
    if result is None:
        result = _fourier_optimum_result()
    shape = optimum_shape(result)
    return Claim("Fig. 6 optimum shape", "Sect. 4.4.2, Fig. 6",
                 "the optimised profile has, in approximation, a zero-acceleration interval, "
                 "then one interval of negative and one of positive acceleration (the motivation "
                 "of the three-phase profile)", shape.describe(), _judge(shape.as_paper),
                 f"'Approximately zero': |y''| < {NEAR_ZERO_BAND:.0%} of y''_max; the optimum "
                 "is a local one (SLSQP from 4 starts), the paper's may differ.")
