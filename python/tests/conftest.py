"""Shared settings and independent closed forms for the selfalign Python tests.

Expected values come from closed forms (the paper's equations, docs/three-phase-profile.md,
docs/motion-cases.md) evaluated here in NumPy, or from a second computation, never from
pasted outputs of the module under test.
"""

import math

import numpy as np
import pytest

import selfalign as sa

# Sect. 7.2 setting of the paper: Δt = 1, Δy = 0.084.
PERIOD = 1.0
STROKE = 0.084

# Closed-form arithmetic on O(1) numbers: rounding ~1e-16; 1e-12 leaves headroom.
CLOSED_FORM_TOL = 1e-12


def three_phase_times(period, stroke, a2, a3):
    """docs/three-phase-profile.md, written out independently: (t1, t2, yd_ini, y_ini) or None."""
    s = 1.0 / a2 + 1.0 / a3
    g = math.sqrt(2.0 * s * stroke) / period
    if g > 0.5:
        return None  # case 0: no physical profile
    u = 1.0 - math.sqrt(1.0 - 2.0 * g)
    t1 = (1.0 - u) * period
    t2 = t1 + (u * period / s) / a2
    yd_ini = u * u * period / (2.0 * s)
    y_ini = yd_ini**2 / (2.0 * a3)
    return t1, t2, yd_ini, y_ini


def fig8_case(period, stroke, a2, a3):
    """The a priori rules of Fig. 8 (docs/motion-cases.md), independently of predict_case."""
    times = three_phase_times(period, stroke, a2, a3)
    if times is None:
        return 0
    t1, t2, _, _ = times
    if a2 <= 1 and a3 <= 1:
        return 5
    if a2 > 1 and a3 <= 1:
        return 1
    if a2 <= 1 and a3 > 1:
        return 2
    T1, T2, T3 = t1, t2 - t1, period - t2
    tau_s = (a2 - 1) * T2 / (1 + a3)
    back = (a3 - 1) * (T3 - tau_s)
    return 3 if back < T1 else 4


def case1_mean_velocity(period, stroke, a2, a3):
    """v̄ of case 1 (a2 > 1 >= a3) from eqs. (12)-(24) and (10): stuck on [t0, t1], forward
    slip at x'' = a2 - 1 on [t1, t2] (eqs. 15-17), deceleration at -(1 + a3) until x' = 0
    (eqs. 18-21), stuck until t3 (eqs. 22-24)."""
    t1, t2, _, _ = three_phase_times(period, stroke, a2, a3)
    T2 = t2 - t1
    v2 = (a2 - 1) * T2  # eq. (16) at t2
    x2 = 0.5 * (a2 - 1) * T2**2  # eq. (17) at t2
    x3 = x2 + v2**2 / (2 * (1 + a3))  # eqs. (20), (21), (24)
    return x3 / period


@pytest.fixture
def case1_profile():
    """A case-1 three-phase profile of Sect. 7.2 (a2 = 3, a3 = 0.9)."""
    return sa.ThreePhaseProfile(period=PERIOD, stroke=STROKE, a2=3.0, a3=0.9)


@pytest.fixture
def rng():
    return np.random.default_rng(20100601)
