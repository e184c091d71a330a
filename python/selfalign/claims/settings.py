"""Tolerances and settings shared by the claims (Sects. 4-7): how close counts as equal, and where
each claim is computed (one setting per case of Table 1, Sect. 7.2's setting, the Floquet grid of
Sect. 6.1, the convergence runs of Sect. 6.2 and the accumulation grid of Sect. 7.3)."""

from __future__ import annotations

import numpy as np


# ---- tolerances -------------------------------------------------------------------------------
# Closed-form arithmetic and the exact solver (arcs in closed form) on O(1) numbers: rounding
# ~1e-16 per operation over a few hundred operations; 1e-12 leaves headroom.
ROUND_OFF = 1e-12
# Saltation-matrix monodromy against the analytic one: products of a few 2x2 matrices built
# from event times found to rounding; the paper calls the results "identical".
SALTATION_TOL = 1e-10
# Central finite differences (step 1e-7) of the period map: O(h^2) truncation plus ~eps/h
# rounding (~1e-9) on O(1) entries; the paper only says "a good approximation".
FD_TOL = 1e-5
# Part of y''_max below which Fig. 6's acceleration counts as "approximately zero". For bands
# of 5 % ... 30 % the optimum shows 5-6 negative and 5-6 positive intervals (checked when
# written): the verdict does not hinge on this choice.
NEAR_ZERO_BAND = 0.10

# One three-phase setting (Δt, Δy, y2'', y3'') per case of Table 1 (figures use them too).
CASE_SETTINGS = {
    1: (1.0, 0.084, 3.0, 0.9),
    2: (1.0, 0.084, 0.9, 3.0),
    3: (1.0, 0.084, 2.3, 1.3),
    4: (1.0, 0.084, 1.05, 2.0),
    5: (2.0, 0.084, 0.9, 0.9),
}
SECT72 = (1.0, 0.084, 0.05, 2.5)  # Sect. 7.2: Δt, Δy, w, c_mu

# Floquet grid (Sect. 6.1): the Fig. 11 plane (cases 1-4), the Fig. 10 plane (slip-slip with
# λ2 close to 1) and a low-acceleration plane at Δt = 2 (pure stick, case 5).
FLOQUET_PLANES = ((1.0, 0.084, tuple(np.linspace(0.6, 3.0, 13))),
                  (0.072, 0.021, tuple(np.geomspace(20.0, 1275.0, 10))),
                  (2.0, 0.084, tuple(np.linspace(0.5, 1.0, 4))))

# Initial velocities for the convergence claims (Sect. 6.2): every pair of them.
INITIAL_VELOCITIES = (-2.0, -0.5, 0.0, 0.05, 0.6, 2.0)
# Slip-slip settings with λ2 = c4 near 1, so |v1 - v2| stays far above rounding for 40 periods.
SLIP_SLIP_SETTINGS = ((0.072, 0.021, 50.0, 1275.0), (0.072, 0.021, 1275.0, 45.0))

# Sect. 7.3 grid: several (Δt, Δy, w, c_mu) and (y2'', y3'') with y3'' < 1 < y2'', where the
# steady motion is case 1 (the section's assumption), each with many entries.
ACCUMULATION_GRID = dict(periods=(0.8, 1.0, 1.05, 1.3), strokes=(0.05, 0.084),
                         widths=(0.02, 0.05, 0.1), c_mus=(1.5, 2.5, 4.0),
                         a2=tuple(np.linspace(1.05, 3.9, 12)), a3=tuple(np.linspace(0.1, 0.95, 6)))
ACCUMULATION_ENTRIES = 40  # steady entries per setting (Sect. 7.1), all phases of a period
ACCUMULATION_RESTS = 16  # starts at rest at x_1 in [x_mu, x_stick,min) (Sect. 7.3's x_1)
ACCUMULATION_MAX_PERIODS = 400
# The (y2'', y3'') planes of Figs. 10 and 11: Δt, Δy, (grid kind, lo, hi, n).
FIG10 = (0.072, 0.021, ("log", 1.0, 1275.0, 200))
FIG11 = (1.0, 0.084, ("linear", 3.0 / 200, 3.0, 200))
