"""Sect. 6.1, local stability: the Floquet analysis over FLOQUET_PLANES and the claims on the
monodromy matrix and its multipliers (eqs. 30, 33) by the analytic, saltation-matrix and
finite-difference methods."""

from __future__ import annotations

import itertools
import math
from typing import Optional

import numpy as np

from .. import _selfalign as sa
from .claim import Claim, _fmt, _judge, _physical, _profile
from .closed_forms import slip_slip_c4
from .settings import CASE_SETTINGS, FD_TOL, FLOQUET_PLANES, ROUND_OFF, SALTATION_TOL


FloquetGrid = list  # [((Δt, Δy, y2'', y3''), FloquetAnalysis)]


def floquet_grid() -> FloquetGrid:
    """The Floquet analysis of every physical setting of FLOQUET_PLANES."""
    rows = []
    for period, stroke, values in FLOQUET_PLANES:
        for a2, a3 in itertools.product(values, values):
            if _physical(period, stroke, a2, a3):
                setting = (period, stroke, float(a2), float(a3))
                rows.append((setting, sa.floquet_multipliers(_profile(*setting))))
    return rows


def _case(analysis) -> int:
    return int(analysis.steady.motion_case)


def _sorted_moduli(monodromy) -> np.ndarray:
    return np.sort(np.abs(np.asarray(monodromy.multipliers)))


def case1_multipliers(grid: Optional[FloquetGrid] = None) -> Claim:
    rows = [(s, a) for s, a in (grid or []) if _case(a) == 1]
    if not grid:
        setting = CASE_SETTINGS[1]
        rows = [(setting, sa.floquet_multipliers(_profile(*setting)))]
    expected = np.array([[1.0, 0.0], [0.0, 0.0]])  # eq. (30)
    worst, where, ok = {}, {}, True
    for setting, a in rows:
        for method, tol in (("analytic", ROUND_OFF), ("saltation", SALTATION_TOL),
                            ("finite_difference", FD_TOL)):
            err = float(np.abs(np.asarray(getattr(a, method).matrix) - expected).max())
            if err >= worst.get(method, -1.0):
                worst[method], where[method] = err, setting
            ok &= err < tol
    text = "; ".join(f"{m}: max |Φ - [[1,0],[0,0]]| = {worst[m]:.2g}" for m in worst)
    return Claim("Case-1 monodromy matrix", "Sect. 6.1, eq. (30)",
                 "for a case-1 response Φ(t3, t0) = [[1, 0], [0, 0]]: λ1 = 1 (eigenvector "
                 "[1, 0]), λ2 = 0 (eigenvector [0, 1])",
                 f"{len(rows)} case-1 settings; {text}", _judge(ok and rows),
                 f"tolerances: analytic {ROUND_OFF:g}, saltation {SALTATION_TOL:g}, finite "
                 f"differences {FD_TOL:g}")


def cases23_multipliers(grid: Optional[FloquetGrid] = None) -> Claim:
    if grid is None:
        grid = [(CASE_SETTINGS[c], sa.floquet_multipliers(_profile(*CASE_SETTINGS[c])))
                for c in (2, 3)]
    rows = [(s, a) for s, a in grid if _case(a) in (2, 3)]
    worst, ok = 0.0, bool(rows)
    for setting, a in rows:
        for method, tol in (("analytic", ROUND_OFF), ("saltation", SALTATION_TOL),
                            ("finite_difference", FD_TOL)):
            err = float(np.abs(_sorted_moduli(getattr(a, method)) - [0.0, 1.0]).max())
            worst = max(worst, err)
            ok &= err < tol
    counts = {c: sum(_case(a) == c for _, a in rows) for c in (2, 3)}
    return Claim("Cases 2 and 3 multipliers", "Sect. 6.1",
                 "cases 2 and 3 have the same Floquet multipliers as case 1: λ1 = 1, λ2 = 0",
                 f"{counts[2]} case-2 and {counts[3]} case-3 settings; max deviation of "
                 f"(|λ2|, |λ1|) from (0, 1) over the three methods: {worst:.2g}", _judge(ok))


def slip_slip_lambda2(grid: Optional[FloquetGrid] = None) -> Claim:
    if grid is None:
        setting = CASE_SETTINGS[4]
        grid = [(setting, sa.floquet_multipliers(_profile(*setting)))]
    rows = [(s, a) for s, a in grid if _case(a) == 4]
    ok, worst_salt, worst_fd, c4s = bool(rows), 0.0, 0.0, []
    for (period, stroke, a2, a3), a in rows:
        c4 = slip_slip_c4(a2, a3)  # eq. (33)
        c4s.append(c4)
        salt = np.sort(np.abs(np.asarray(a.saltation.matrix).diagonal()))  # Φ is triangular
        err_salt = abs(_sorted_moduli(a.saltation)[0] - c4)
        err_fd = abs(_sorted_moduli(a.finite_difference)[0] - c4)
        worst_salt, worst_fd = max(worst_salt, err_salt), max(worst_fd, err_fd)
        ok &= err_salt < SALTATION_TOL and err_fd < FD_TOL and a2 > 1 and a3 > 1 \
            and 0 < c4 < 1 and abs(salt[1] - 1) < SALTATION_TOL
    span = f"c4 in [{min(c4s):.4g}, {max(c4s):.4g}]" if c4s else "no case-4 setting"
    return Claim("Slip-slip multiplier", "Sect. 6.1, eq. (33)",
                 "λ2 = c4 = ((y2''-1)(y3''-1))/((y2''+1)(y3''+1)), positive and < 1 because "
                 "y2'', y3'' > 1 in slip-slip",
                 f"{len(rows)} case-4 settings, {span}; max |λ2 - c4|: saltation "
                 f"{worst_salt:.2g}, finite differences {worst_fd:.2g}", _judge(ok))


def local_stability(grid: Optional[FloquetGrid] = None) -> Claim:
    if grid is None:
        grid = floquet_grid()
    ok, largest, where, cases = bool(grid), 0.0, None, set()
    for setting, a in grid:
        moduli = _sorted_moduli(a.analytic if a.analytic.available else a.saltation)
        cases.add(_case(a))
        ok &= abs(moduli[1] - 1) < SALTATION_TOL and moduli[0] < 1
        if moduli[0] >= largest:
            largest, where = float(moduli[0]), setting
    return Claim("Local stability", "Sect. 6.1",
                 "all steady-state solutions are locally stable: λ1 = 1 (freedom in position), "
                 "|λ2| < 1",
                 f"{len(grid)} settings, cases {sorted(cases)}; largest |λ2| = {largest:.4f} at "
                 f"(Δt, Δy, y2'', y3'') = {_fmt(where) if where else '-'}", _judge(ok))


def saltation_identical(grid: Optional[FloquetGrid] = None) -> Claim:
    if grid is None:
        grid = floquet_grid()
    worst = max((float(np.abs(np.asarray(a.saltation.matrix) - a.analytic.matrix).max())
                 for _, a in grid if a.analytic.available), default=math.inf)
    return Claim("Saltation = analytic", "Sect. 6.1",
                 "the monodromy matrix by saltation matrices gives identical results",
                 f"max |Φ_saltation - Φ_analytic| over {len(grid)} settings: {worst:.2g} "
                 f"(PASS if < {SALTATION_TOL:g})", _judge(worst < SALTATION_TOL))


def finite_difference_close(grid: Optional[FloquetGrid] = None) -> Claim:
    if grid is None:
        grid = floquet_grid()
    worst, where = -1.0, None
    for setting, a in grid:
        err = float(np.abs(np.asarray(a.finite_difference.matrix) - a.analytic.matrix).max())
        if err > worst:
            worst, where = err, setting
    return Claim("Finite differences approximate", "Sect. 6.1",
                 "the numerical (sensitivity) estimate of the monodromy matrix is a good "
                 "approximation of the analytic one",
                 f"max |Φ_fd - Φ_analytic| over {len(grid)} settings: {worst:.2g} at "
                 f"{_fmt(where) if where else '-'} (PASS if < {FD_TOL:g})",
                 _judge(0 <= worst < FD_TOL))
