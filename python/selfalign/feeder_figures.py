"""The feeder's regime chart as a figure (issue 23, docs/feeder.md): the closed-form regimes
of :func:`selfalign.feeder_regime_chart` over (machine number K, vibration angle psi) as
coloured cells, the closed-form onset curves K_f(psi), K_b(psi), K_l(psi) from
:func:`selfalign.feeder_onsets`, and the simulated dimensionless speed v / (a0 w cos psi) as
contours. Uses matplotlib's Agg backend; not imported by ``import selfalign``:
``from selfalign import feeder_figures``.
"""

from __future__ import annotations

from typing import Any, Mapping, Optional

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors  # noqa: E402
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import _selfalign as sa  # noqa: E402
from .planar_figures import PathLike, _save_atomic  # noqa: E402

__all__ = ["onset_curves", "plot_regime_chart"]

_REGIME_COLOURS = ["#d9d9d9", "#8dd3c7", "#fb8072", "#bebada", "#ffffb3"]  # FeederRegime order


def onset_curves(vibration_angles: Any, incline: float, mu_static: float) -> dict[str, np.ndarray]:
    """K of the forward slip, backward slip and lift-off onsets (feeder_onsets) at each angle:
    a dict of arrays 'forward_slip', 'backward_slip', 'lift_off' (inf where never)."""
    angles = np.asarray(vibration_angles, dtype=float)
    rows = [sa.feeder_onsets(float(a), incline, mu_static) for a in angles]
    return {k: np.array([getattr(r, k) for r in rows])
            for k in ("forward_slip", "backward_slip", "lift_off")}


def plot_regime_chart(chart: Mapping[str, Any], *, incline: float, mu_static: float,
                      ax: Optional[plt.Axes] = None, path: Optional[PathLike] = None,
                      dpi: int = 120) -> plt.Axes:
    """Draws a :func:`selfalign.feeder_regime_chart` dict: regimes as cells over
    (K, psi) with K on a log axis, the closed-form onset curves (the same ``incline`` and
    ``mu_static`` as the chart), and contours of the simulated dimensionless speed. Returns
    the Axes; with ``path``, also saves the figure there (atomically)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 5.0))
    ks = np.asarray(chart["machine_numbers"], dtype=float)
    angles = np.asarray(chart["vibration_angles"], dtype=float)
    regime = np.asarray(chart["regime"], dtype=float)
    cmap = matplotlib.colors.ListedColormap(_REGIME_COLOURS)
    ax.pcolormesh(ks, angles, regime, cmap=cmap, vmin=-0.5, vmax=4.5, shading="nearest")
    speed = np.asarray(chart["dimensionless_speed"], dtype=float)
    if len(ks) > 1 and len(angles) > 1 and np.isfinite(speed).any():
        lines = ax.contour(ks, angles, speed, colors="k", linewidths=0.6)
        ax.clabel(lines, fontsize=7)
    fine = np.linspace(angles.min(), angles.max(), 200)
    curves = onset_curves(fine, incline, mu_static)
    for name, style in (("forward_slip", "-"), ("backward_slip", "--"), ("lift_off", ":")):
        ax.plot(curves[name], fine, style, color="navy", label=name.replace("_", " "))
    ax.set_xscale("log")
    ax.set_xlim(ks.min(), ks.max())
    ax.set_ylim(angles.min(), angles.max())
    ax.set_xlabel("machine number K = a0 w^2 / g [-]")
    ax.set_ylabel("vibration angle psi [rad]")
    handles = [matplotlib.patches.Patch(color=c, label=sa.FeederRegime(i).name)
               for i, c in enumerate(_REGIME_COLOURS)]
    ax.legend(handles=handles + ax.get_legend_handles_labels()[0], fontsize=7, loc="upper left")
    ax.set_title("feeder regimes; contours: v / (a0 w cos psi)")
    if path is not None:
        _save_atomic(ax.figure, path, dpi)
    return ax


def flight_equation_angle(throw_number: float) -> float:
    """The bouncing-ball flight angle (docs/feeder.md): with phi0 = asin(1/Gamma), the first
    root phi_L > phi0 of (phi - phi0)^2/2 + Gamma (sin phi - sin phi0 - (phi - phi0) cos phi0)
    = 0, by a scan and bisection; returns phi_L - phi0 [rad]. Written from the equation alone
    (the second method for the exact solver's flights)."""
    gamma = float(throw_number)
    phi0 = np.arcsin(1.0 / gamma)

    def f(phi: float) -> float:
        d = phi - phi0
        return d * d / 2 + gamma * (np.sin(phi) - np.sin(phi0) - d * np.cos(phi0))

    lo = hi = phi0 + 1e-3
    while f(hi) < 0:
        lo, hi = hi, hi + 1e-3
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi) - phi0


def flight_angles(throw_numbers: Any, vibration_angle: float = 0.6,
                  incline: float = 0.05) -> dict[str, np.ndarray]:
    """Flight angles over throw numbers: the exact feeder solver's (`feeder_run`, plastic
    landing, mu = 20 so that the part is held on the track, 4 periods) and the flight
    equation's; arrays ``throw_number``, ``exact``, ``equation``."""
    gammas = np.asarray(throw_numbers, dtype=float)
    w = 2 * np.pi
    exact, equation = [], []
    for gamma in gammas:
        K = gamma * np.cos(incline) / np.sin(vibration_angle)
        drive = sa.FeederDrive(K / w**2, 1.0, vibration_angle, incline, 1.0)
        exact.append(sa.feeder_run(drive, sa.FrictionLaw(20.0, 20.0), periods=4).flight_angle)
        equation.append(flight_equation_angle(gamma))
    return {"throw_number": gammas, "exact": np.array(exact), "equation": np.array(equation)}
