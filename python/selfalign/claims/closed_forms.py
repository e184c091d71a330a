"""The paper's closed forms, written out here independently of the library, for the claims to
compare the library with: the friction bound (eqs. 7-9, Sect. 7), x_stick,min (eq. 41), the
slip-slip multiplier c4 (eq. 33, Sect. 6.1), the stick-position map (59) by hand, its fixed
point (60), the slip angle θ and the basin bound of Sect. 7.3 (docs/accumulation.md), and which
stick positions start a slide that map (59) describes."""

from __future__ import annotations

import math
from typing import Optional

import numpy as np

from .. import _selfalign as sa


def friction_bound(x: np.ndarray, x_mu: float, w: float, c_mu: float) -> np.ndarray:
    """Eqs. (7)-(9): the friction level μ̄/μ at x (1 before x_mu, c_mu after x_mu + w)."""
    z = np.clip(np.asarray(x, dtype=float) - x_mu, 0.0, w)  # eq. (8)
    return (w + (c_mu - 1.0) * z) / w  # eq. (7)


def x_stick_min(x_mu: float, w: float, c_mu: float, peak: float) -> float:
    """Eq. (41): x_stick,min = x_mu + w (max|y''| - 1)/(c_mu - 1) (for 1 <= peak <= c_mu)."""
    return x_mu + w * (peak - 1.0) / (c_mu - 1.0)


def slip_slip_c4(a2: float, a3: float) -> float:
    """Eq. (33): λ2 = c4 = ((y2'' - 1)(y3'' - 1))/((y2'' + 1)(y3'' + 1))."""
    return ((a2 - 1.0) * (a3 - 1.0)) / ((a2 + 1.0) * (a3 + 1.0))


def stick_map(x_n, a2: float, a3: float, w: float, c_mu: float, x_mu: float, t21: float):
    """Eq. (59): the next stick position from rest at x_n (slip on [t1, t2] of length t21)."""
    b1 = (c_mu - 1.0) / w
    b2 = (c_mu - 1.0) * x_mu / w - 1.0
    root = math.sqrt(b1)
    d = np.asarray(x_n, dtype=float) - (b2 + a2) / b1
    inner = ((a2 + a3) / b1 + d * math.cos(root * t21)) ** 2 + (d * math.sin(root * t21)) ** 2
    return (b2 - a3) / b1 + np.sqrt(inner)


def stick_map_fixed_point(a2: float, w: float, c_mu: float, x_mu: float) -> float:
    """Eq. (60): x_n = x_{n+1} = (b2 + y2'')/b1."""
    b1 = (c_mu - 1.0) / w
    return ((c_mu - 1.0) * x_mu / w - 1.0 + a2) / b1


def slip_angle(w: float, c_mu: float, t21: float) -> float:
    """θ = sqrt(b1) (t2 - t1): eq. (59) describes the next stop only for θ < π (the slip
    lasts through [t1, t2], the derivation's assumption; docs/accumulation.md)."""
    return math.sqrt((c_mu - 1.0) / w) * t21


def basin_bound(a2: float, a3: float, w: float, c_mu: float, x_mu: float, t21: float) -> float:
    """x_{n+1}(x) < x_stick,min iff x > c1 - 2K cos θ, K = (y2'' + y3'')/b1 (from eq. 59)."""
    b1 = (c_mu - 1.0) / w
    return (stick_map_fixed_point(a2, w, c_mu, x_mu)
            - 2.0 * (a2 + a3) / b1 * math.cos(slip_angle(w, c_mu, t21)))


def _t21(profile: sa.ThreePhaseProfile) -> float:
    return profile.solution.t2 - profile.solution.t1


def _map_governed(stick_positions: np.ndarray, a2: float, a3: float, w: float, c_mu: float,
                  x_mu: float, t21: float) -> np.ndarray:
    """Which stick positions x_n start a slide that eq. (59) describes: at rest in
    [x_mu, x_stick,min) with friction >= y3'' there, so the object holds through the y3'' part
    and slips first at t1 (Sect. 7.3: "the mass will stick at the y3'' part"), and a next stop
    inside the transition region x <= x_mu + w, where eq. (42) holds."""
    x = np.asarray(stick_positions, dtype=float)
    c1 = stick_map_fixed_point(a2, w, c_mu, x_mu)
    return (x >= x_mu) & (x < c1) & (friction_bound(x, x_mu, w, c_mu) >= a3) \
        & (stick_map(x, a2, a3, w, c_mu, x_mu, t21) <= x_mu + w)


def _first_map_stop(stick_positions: np.ndarray, a2: float, a3: float, w: float, c_mu: float,
                    x_mu: float, t21: float) -> Optional[float]:
    """The first stick position from which eq. (59) governs the motion."""
    x = np.asarray(stick_positions, dtype=float)
    governed = np.flatnonzero(_map_governed(x, a2, a3, w, c_mu, x_mu, t21))
    return float(x[governed[0]]) if governed.size else None
