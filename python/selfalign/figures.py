"""The paper's figures, one function per figure (Hunnekens et al. 2010).

Each ``fig_*`` function computes its data with the library, writes the data as CSV and the
figure as PNG and SVG into ``out_dir``, and returns a :class:`Figure` describing what it drew,
which statement of the paper it reproduces and, in ``differences``, where the reproduction
does not show what the paper says. Everything is dimensionless (Sect. 3.2).

Colour maps are drawn as raster layers (``rasterized=True``) inside otherwise vector SVGs:
written as vector paths, one per grid cell, they made 10-15 MB files that took most of the
run time to write.
"""

from __future__ import annotations

import dataclasses
import os
from typing import Callable, Optional

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import _selfalign as sa  # noqa: E402
from . import claims  # noqa: E402
from .claims import CASE_SETTINGS, optimum_shape  # noqa: E402  (shared with the claims)

Progress = Optional[Callable[[int, int], None]]


@dataclasses.dataclass
class Figure:
    """A reproduced figure: its files and the paper's statement it illustrates."""

    number: str
    title: str
    statement: str
    files: list[str]
    data: list[str]
    notes: str = ""
    raw: Optional[dict] = None  # the computed data, for the claims table
    differences: str = ""  # where the reproduction differs from the paper's statement


# Settings used throughout (the paper's, where it gives them).
SECT72 = dict(period=1.0, stroke=0.084)  # Sect. 7.2: Δt = 1, Δy = 0.084
WIDTH, C_MU = 0.05, 2.5  # Sect. 7.2: w = 0.05, c_mu = 2.5
CASE_COLORS = ["#bbbbbb", "#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"]


def _save(fig: plt.Figure, out_dir: str, name: str, dpi: int = 130) -> list[str]:
    """Writes name.png (at dpi) and name.svg (vector; rasterised artists embedded at dpi),
    both cropped to the figure's tight bounding box, computed once for the two formats
    (bbox_inches="tight" would lay the figure out again for each)."""
    fig.set_dpi(dpi)
    bbox = fig.get_tightbbox(fig.canvas.get_renderer()).padded(0.1)  # [in]
    files = []
    for ext in ("png", "svg"):
        path = os.path.join(out_dir, f"{name}.{ext}")
        fig.savefig(path, dpi=dpi, bbox_inches=bbox)
        files.append(path)
    plt.close(fig)
    return files


def _case_colorbar(fig: plt.Figure, mappable, ax: plt.Axes) -> None:
    """A colour bar with one labelled tick per motion case of Table 1."""
    bar = fig.colorbar(mappable, ax=ax, ticks=range(6))
    bar.ax.set_yticklabels([f"{k}: {sa.describe(k)}" for k in range(6)])


def _csv(out_dir: str, name: str, columns: dict[str, np.ndarray]) -> str:
    path = os.path.join(out_dir, f"{name}.csv")
    arrays = [np.asarray(v, dtype=float).ravel() for v in columns.values()]
    np.savetxt(path, np.column_stack(arrays), delimiter=",", header=",".join(columns), comments="",
               fmt="%.17g")
    return path


def _three_phase(period: float, stroke: float, a2: float, a3: float) -> sa.ThreePhaseProfile:
    return sa.ThreePhaseProfile(period=period, stroke=stroke, a2=a2, a3=a3)


def fig3(out_dir: str) -> Figure:
    """Fig. 3: a stick-slip response computed with time-stepping.

    The table follows a periodic sequence of second-order polynomials (the scaled Fig. 7-like
    shape). As in the paper (Sect. 3.1), x is the object's position relative to the table, so
    x' = 0 while it sticks; the absolute position x + y is in the CSV as well."""
    profile = sa.ScaledShapeFamily.paper_like().make(2.5, 1.5)
    options = sa.SimulationOptions(method="time-stepping", duration=14.0, step=1e-3,
                                   output_step=0.01)
    tr = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(), options).trajectory
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    top.plot(tr.t, tr.x, label="x (object, relative to the table)")
    top.plot(tr.t, tr.y, "--", label="y (table)")
    top.set_ylabel("position x, y [-]")
    top.legend(fontsize=8)
    bottom.plot(tr.t, tr.xd, label="x' (object, relative to the table)")
    bottom.plot(tr.t, tr.yd, "--", label="y' (table)")
    bottom.axhline(0, color="k", lw=0.5)
    bottom.set_xlabel("time [-]")
    bottom.set_ylabel("velocity x', y' [-]")
    bottom.legend(fontsize=8)
    fig.suptitle("Fig. 3: stick-slip with a sequence of quadratics (time-stepping)")
    data = _csv(out_dir, "fig03", {"t": tr.t, "x": tr.x, "y": tr.y, "x_dot": tr.xd,
                                    "y_dot": tr.yd, "x_abs": tr.x + tr.y,
                                    "x_dot_abs": tr.xd + tr.yd})
    return Figure("3", "Stick-slip response (time-stepping)",
                  "The table moves slowly forward dragging the mass along and fast backward, so "
                  "the mass slips and walks forward (Sect. 4.2).",
                  _save(fig, out_dir, "fig03"), [data],
                  "x and x' are the paper's variables: position and velocity of the object "
                  "relative to the table (Sect. 3.1); x' = 0 marks stick. The paper's exact "
                  "polynomial sequence is not given, a Fig. 7-like shape with Δt = 2.5, "
                  "Δy = 1.5 is used.")


_FAMILY_NOTE = "Scaled Fig. 7-like polynomial sequence (the paper's sequence is not given)."


def _f_against(out_dir: str, number: str, column: str, values: np.ndarray, fixed: float,
               progress: Progress) -> tuple[list[str], list[str], dict]:
    """f of the scaled-shape family against Δt (column 'period') or Δy ('stroke')."""
    family = sa.ScaledShapeFamily.paper_like()
    sweep = sa.sweep_period if column == "period" else sa.sweep_stroke
    r = sweep(family, fixed, values, progress=progress)
    symbol, other = ("Δt", f"Δy = {fixed:g}") if column == "period" else ("Δy", f"Δt = {fixed:g}")
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.semilogy(r[column], r["f"], "o-", ms=3)
    ax.set_xlabel(f"{symbol} [-]")
    ax.set_ylabel("f [-]")
    ax.set_title(f"Fig. {number}: f against {symbol} ({other})")
    name = f"fig{int(number):02d}"
    data = _csv(out_dir, name, {column: r[column], "f": r["f"], "v_bar": r["v_bar"]})
    return _save(fig, out_dir, name), [data], r


def fig4(out_dir: str, progress: Progress = None) -> Figure:
    """Fig. 4: f against Δt at Δy = 0.02."""
    files, data, r = _f_against(out_dir, "4", "period", np.linspace(0.02, 0.2, 46), 0.02, progress)
    return Figure("4", "Objective against excitation period",
                  "A large excitation frequency (small Δt) is beneficial: f grows with Δt "
                  "(Sect. 4.4.1).", files, data, _FAMILY_NOTE, r)


def fig5(out_dir: str, progress: Progress = None) -> Figure:
    """Fig. 5: f against Δy at Δt = 0.05."""
    files, data, r = _f_against(out_dir, "5", "stroke", np.linspace(0.002, 0.04, 39), 0.05,
                                progress)
    return Figure("5", "Objective against stroke",
                  "A large stroke is beneficial: f falls as Δy grows (Sect. 4.4.1).", files, data,
                  _FAMILY_NOTE, r)


def fig6(out_dir: str) -> Figure:
    """Fig. 6: the optimised 12th-order Fourier profile and its steady response.

    Constrained optimisation of the Fourier coefficients (Sect. 4.4.2) at Δt = 0.072,
    Δy = 0.021, y'_max = 3.2, y''_max = 1275 (selfalign.optimize_fourier). The shape of the
    optimum is measured (claims.optimum_shape) and compared with the paper's description."""
    period = 0.072
    result = sa.optimize_fourier(sa.ActuatorLimits(), sa.OptimizeOptions(order=12, starts=4))
    profile = sa.rebuild_profile(result)
    shape = optimum_shape(result)
    options = sa.SimulationOptions(method="time-stepping", duration=3 * period, step=period / 4000,
                                   output_step=period / 400)
    tr = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(0, 0, shape.x_dot_0s),
                     options).trajectory
    limits = result.limits
    fig, axes = plt.subplots(3, 1, figsize=(9.5, 8), sharex=True)
    axes[0].plot(tr.t, tr.y, label="y (table)")
    axes[0].set_ylabel("y [-]")
    axes[1].plot(tr.t, tr.yd, label="y' (table)")
    axes[1].plot(tr.t, tr.xd + tr.yd, "--", label="x' + y' (object, absolute)")
    axes[1].axhline(limits.max_velocity, color="k", lw=0.5,
                    label=f"±y'_max = ±{limits.max_velocity:g}")
    axes[1].axhline(-limits.max_velocity, color="k", lw=0.5)
    axes[1].set_ylabel("velocity [-]")
    axes[2].axhspan(-shape.band, shape.band, color="0.85", lw=0,
                    label=f"|y''| < {shape.band:g}: 'near zero'\n({shape.band_fraction:.0%} of "
                          "y''_max)")
    axes[2].plot(tr.t, tr.ydd, label="y'' (table)")
    axes[2].axhline(limits.max_acceleration, color="k", lw=0.5,
                    label=f"±y''_max = ±{limits.max_acceleration:g}")
    axes[2].axhline(-limits.max_acceleration, color="k", lw=0.5)
    axes[2].set_ylabel("y'' [-]")
    axes[2].set_xlabel("time [-]")
    for ax in axes:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    axes[2].set_title(f"per period: y'' changes sign {shape.sign_changes} times; "
                      f"{shape.negative_lobes} negative and {shape.positive_lobes} positive "
                      "intervals (paper: 1 and 1)", fontsize=9)
    fig.suptitle(f"Fig. 6: optimised 12th-order Fourier profile, f = {result.f:.3g}")
    data = _csv(out_dir, "fig06", {"t": tr.t, "y": tr.y, "y_dot": tr.yd, "y_ddot": tr.ydd,
                                    "x_dot": tr.xd})
    return Figure("6", "Optimised Fourier profile",
                  "Δt = 0.072, Δy = 0.021, y'_max = 3.2, y''_max = 1275; the optimum has, in "
                  "approximation, a zero-acceleration interval, then one negative and one "
                  "positive acceleration interval (Sect. 4.4.2).", _save(fig, out_dir, "fig06"),
                  [data],
                  "The paper's printed f = 56 is read as f = 5.6e-4 (lost exponent): under these "
                  "limits v̄ ≈ 0.4-0.6, so f is of order 1e-4.", {"result": result},
                  differences=shape.describe())


def fig7(out_dir: str) -> Figure:
    """Fig. 7: the three-phase profile, y, y', y'' over a period with t0..t3."""
    profile = _three_phase(1.0, 0.084, 2.3, 1.3)
    sol = profile.solution
    t = np.linspace(0, 1, 1001)
    y, yd, ydd = profile.sample(t)
    fig, axes = plt.subplots(3, 1, figsize=(6, 6), sharex=True)
    for ax, v, label in zip(axes, (y, yd, ydd), ("y [-]", "y' [-]", "y'' [-]")):
        ax.plot(t, v)
        ax.set_ylabel(label)
        for tk, name in ((0, "t0"), (sol.t1, "t1"), (sol.t2, "t2"), (sol.t3, "t3")):
            ax.axvline(tk, color="k", lw=0.5, ls=":")
        ax.axhline(0, color="k", lw=0.5)
    axes[1].fill_between(t, yd, 0, alpha=0.2)
    axes[2].fill_between(t, ydd, 0, alpha=0.2)
    axes[2].set_xlabel("time [-]")
    fig.suptitle("Fig. 7: three-phase table profile (Δt = 1, Δy = 0.084, y2'' = 2.3, y3'' = 1.3)")
    data = _csv(out_dir, "fig07", {"t": t, "y": y, "y_dot": yd, "y_ddot": ydd})
    return Figure("7", "Three-phase table profile",
                  "Three intervals of constant acceleration 0, -y2'', +y3''; min y = 0, stroke "
                  "Δy, periodic y and y' (Sect. 4.4.3, Appendix).", _save(fig, out_dir, "fig07"),
                  [data])


def fig9(out_dir: str) -> Figure:
    """Fig. 9: time histories of the five cases (steady state)."""
    fig, axes = plt.subplots(5, 1, figsize=(6, 10), sharex=False)
    columns = {}
    for ax, (case, (dt, dy, a2, a3)) in zip(axes, CASE_SETTINGS.items()):
        profile = _three_phase(dt, dy, a2, a3)
        steady = sa.steady_state(profile)
        options = sa.SimulationOptions(duration=2 * dt, output_step=dt / 500)
        tr = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(0, 0, steady.x_dot_0s),
                         options).trajectory
        ax.plot(tr.t, tr.xd, label="x' (relative)")
        ax.plot(tr.t, tr.yd, "--", label="y' (table)")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_title(f"case {case}: {sa.describe(int(steady.motion_case))} "
                     f"(y2''={a2}, y3''={a3}, Δt={dt})", fontsize=9)
        ax.set_ylabel("velocity [-]")
        columns[f"t_case{case}"] = tr.t
        columns[f"x_dot_case{case}"] = tr.xd
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("time [-]")
    fig.tight_layout()
    length = min(len(v) for v in columns.values())
    data = _csv(out_dir, "fig09", {k: v[:length] for k, v in columns.items()})
    return Figure("9", "The five cases of Table 1",
                  "Stick-slip x' >= 0, stick-slip x' <= 0, general stick-slip, slip-slip, pure "
                  "stick (Table 1, Fig. 9).", _save(fig, out_dir, "fig09"), [data])


FIG10, FIG11 = claims.FIG10, claims.FIG11  # Δt, Δy, (grid kind, lo, hi, n)


def _grid(spec: tuple) -> np.ndarray:
    kind, lo, hi, n = spec
    return (sa.log_grid if kind == "log" else sa.linear_grid)(lo, hi, n)


def case_f_data(setting: tuple, progress: Progress = None) -> dict:
    """f and case over the (y2'', y3'') grid of FIG10 or FIG11 (sa.sweep_accelerations).
    Runs without the GIL, so reproduce computes it in the background while drawing."""
    period, stroke, spec = setting
    grid = _grid(spec)
    return sa.sweep_accelerations(period, stroke, grid, grid, progress=progress)


def _case_f_surfaces(out_dir: str, name: str, title: str, setting: tuple, log: bool,
                     f_cap: float, progress: Progress, data: Optional[dict]):
    r = data if data is not None else case_f_data(setting, progress)
    grid = np.asarray(r["a2"])
    f = np.minimum(np.where(np.isfinite(r["f"]), r["f"], f_cap), f_cap)
    f = np.where(r["observed"] == 0, np.nan, f)
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.8), width_ratios=(1, 1.15))
    mesh = left.pcolormesh(grid, grid, f.T, shading="nearest", cmap="viridis", rasterized=True)
    fig.colorbar(mesh, ax=left)
    left.set_title(f"f (capped at {f_cap:g}; white: non-physical)")
    right.set_title("case of Table 1 (simulated)")
    cmap = matplotlib.colors.ListedColormap(CASE_COLORS)
    cases = right.pcolormesh(grid, grid, r["observed"].T.astype(float), shading="nearest",
                             cmap=cmap, vmin=-0.5, vmax=5.5, rasterized=True)
    _case_colorbar(fig, cases, right)
    for ax in (left, right):
        ax.set_xlabel("y2'' [-]")
        ax.set_ylabel("y3'' [-]")
        if log:
            ax.set_xscale("log")
            ax.set_yscale("log")
    fig.suptitle(title)
    a2, a3 = np.meshgrid(grid, grid, indexing="ij")
    data = _csv(out_dir, name, {"a2": a2, "a3": a3, "case_a_priori": r["predicted"],
                                 "case": r["observed"], "v_bar": r["v_bar"], "f": r["f"]})
    return _save(fig, out_dir, name), [data], r


def fig10(out_dir: str, progress: Progress = None, data: Optional[dict] = None) -> Figure:
    """Fig. 10: f and case over (y2'', y3'') in [1, 1275]^2, Δt = 0.072, Δy = 0.021.

    ``data``: case_f_data(FIG10), if already computed."""
    files, data, r = _case_f_surfaces(out_dir, "fig10",
                                      "Fig. 10: f and case, Δt = 0.072, Δy = 0.021",
                                      FIG10, True, 1.6e-3, progress, data)
    return Figure("10", "f and case over large accelerations",
                  "f rises sharply where general stick-slip turns into slip-slip; f capped at "
                  "1.6e-3 (Sect. 5.2).", files, data,
                  "The paper does not state Fig. 10's (Δt, Δy); the Fig. 6 setting is used, whose "
                  "v̄ ≈ 0.3 matches the 1.6e-3 colour scale.", r)


def fig11(out_dir: str, progress: Progress = None, data: Optional[dict] = None) -> Figure:
    """Fig. 11: f and case over small accelerations (0, 3]^2, Δt = 1, Δy = 0.084.

    ``data``: case_f_data(FIG11), if already computed."""
    files, data, r = _case_f_surfaces(out_dir, "fig11", "Fig. 11: f and case, Δt = 1, Δy = 0.084",
                                      FIG11, False, 0.8, progress, data)
    return Figure("11", "f and case over small accelerations",
                  "Stick is possible where |y''| < 1: cases 1 and 2 appear; case 1 is preferable; "
                  "f >= 0.8 set to 0.8 (Sect. 5.2).", files, data, raw=r)


def fig12(out_dir: str) -> Figure:
    """Fig. 12: an illustrative case-1 trajectory over one period."""
    profile = _three_phase(*CASE_SETTINGS[1])
    sol = profile.solution
    tr = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(),
                     sa.SimulationOptions(duration=1.0, output_step=1e-3)).trajectory
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 5), sharex=True)
    top.plot(tr.t, tr.x)
    top.set_ylabel("x [-]")
    bottom.plot(tr.t, tr.xd, label="x'")
    bottom.plot(tr.t, tr.ydd / 10, "--", label="y''/10")
    bottom.legend()
    for ax in (top, bottom):
        for tk in (0, sol.t1, sol.t2, sol.t3):
            ax.axvline(tk, color="k", lw=0.5, ls=":")
    bottom.set_xlabel("time [-]")
    fig.suptitle("Fig. 12: case-1 trajectory (y2'' = 3, y3'' = 0.9)")
    data = _csv(out_dir, "fig12", {"t": tr.t, "x": tr.x, "x_dot": tr.xd, "y_ddot": tr.ydd})
    return Figure("12", "Case-1 trajectory",
                  "Stick on [t0, t1], slip with x'' = y2'' - 1 on [t1, t2], decelerate with "
                  "-1 - y3'' until x' = 0, stick until t3 (eqs. 12-24).",
                  _save(fig, out_dir, "fig12"), [data])


def fig13(out_dir: str) -> Figure:
    """Fig. 13: convergence of two velocity responses and V = (v1 - v2)^2/2."""
    profile = _three_phase(*CASE_SETTINGS[1])
    c = sa.velocity_convergence(profile, sa.ConvergenceOptions(v1=0.6, v2=-0.4, duration=4.0))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    top.plot(c.t, c.v1, label="v1")
    top.plot(c.t, c.v2, "--", label="v2")
    top.set_ylabel("velocity [-]")
    bottom.plot(c.t, c.lyapunov, label="V = (v1 - v2)²/2, eq. (35)")
    bottom.set_ylabel("V [-]")
    bottom.set_xlabel("time [-]")
    top_v = max(c.lyapunov)
    bottom.set_ylim(-0.05 * top_v, 1.2 * top_v)
    for iv in c.intervals:  # '=' where v̂1 = v̂2, '≠' where they differ
        mid = 0.5 * (iv.t_begin + iv.t_end)
        bottom.text(mid, 1.07 * top_v, "=" if iv.same else "≠", ha="center")
    if c.t_coincide is not None:
        for ax in (top, bottom):
            ax.axvline(c.t_coincide, color="k", lw=0.7, ls=":",
                       label=f"responses coincide, t = {c.t_coincide:.3f}")
    top.legend(fontsize=8)
    bottom.legend(fontsize=8, loc="center right")
    fig.suptitle("Fig. 13: convergence of two case-1 responses")
    data = _csv(out_dir, "fig13", {"t": c.t, "v1": c.v1, "v2": c.v2, "V": c.lyapunov})
    return Figure("13", "Convergence of velocity responses",
                  "V is constant where v̂1 = v̂2 and decreases where v̂1 ≠ v̂2; for case 1 the "
                  "responses coincide in finite time (Sect. 6.2).", _save(fig, out_dir, "fig13"),
                  [data])


def fig16(out_dir: str) -> Figure:
    """Fig. 16: phase portraits for (2.3, 1.3) and (1.8, 1.1), two entries each."""
    fig, axes = plt.subplots(2, 1, figsize=(9.5, 7))
    columns = {}
    for ax, (a2, a3) in zip(axes, ((2.3, 1.3), (1.8, 1.1))):
        profile = _three_phase(1.0, 0.084, a2, a3)
        acc = sa.positioning_accuracy(profile, WIDTH, C_MU)  # 100 entries, Sect. 7.1
        friction = sa.two_region_friction(acc.x_mu, WIDTH, C_MU)
        for k, x0 in enumerate((acc.entries[10], acc.entries[60])):  # two of the entries
            tr = sa.simulate(profile, friction, sa.ObjectState(0, x0, acc.steady.x_dot_0s),
                             sa.SimulationOptions(duration=12.0, output_step=2e-3)).trajectory
            ax.plot(tr.x, tr.xd, lw=0.8, label=f"x0s = {x0:.4f}")
            columns[f"x_{a2}_{a3}_{k}"] = tr.x
            columns[f"x_dot_{a2}_{a3}_{k}"] = tr.xd
        ax.axvline(acc.x_mu, color="0.4", ls="--", lw=1.0,
                   label=f"x_mu = {acc.x_mu:.4f}: high friction starts")
        ax.axvline(acc.x_stick_min, color="r", ls="--", lw=1.0,
                   label=f"x_stick,min = {acc.x_stick_min:.4f}, eq. (41)")
        ax.set_title(f"(y2'', y3'') = ({a2}, {a3}): Δx_d = {acc.dx_d:.3g}", fontsize=10)
        ax.set_xlabel("x [-]")
        ax.set_ylabel("x' [-]")
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    data = _csv(out_dir, "fig16", columns)
    return Figure("16", "Phase portraits entering the high-friction region",
                  "Upper: both trajectories stop at the same position (accumulation to "
                  "x_stick,min); lower: the end positions differ (Sect. 7.2).",
                  _save(fig, out_dir, "fig16"), [data],
                  "Dashed lines: x_mu (grey), where the high-friction region starts, and "
                  "x_stick,min (red), from where permanent stick is possible (eq. 41). The two "
                  "entries are entries 10 and 60 of the 100 steady entries of Sect. 7.1.")


FIG17_CELLS, FIG17_ENTRIES = 120, 60  # grid n x n over (0, 2.5]^2, steady entries per cell


def fig17_data(n: int = FIG17_CELLS, entries: int = FIG17_ENTRIES,
               progress: Progress = None) -> dict:
    """The Fig. 17 surfaces (sa.positioning_surfaces) at the Sect. 7.2 setting. Runs without
    the GIL, so reproduce computes it in the background while drawing."""
    grid = sa.linear_grid(2.5 / n, 2.5, n)
    options = sa.PositioningOptions(entries=entries, stopping=sa.StoppingOptions(max_periods=300))
    return sa.positioning_surfaces(1.0, 0.084, WIDTH, C_MU, grid, grid, options=options,
                                   progress=progress)


def fig17(out_dir: str, progress: Progress = None, n: int = FIG17_CELLS,
          entries: int = FIG17_ENTRIES, data: Optional[dict] = None) -> Figure:
    """Fig. 17: (A) f, (B) case, (C) accumulation, (D) Δx_d over (y2'', y3'').

    ``data``: fig17_data(n, entries), if already computed."""
    r = data if data is not None else fig17_data(n, entries, progress)
    grid = np.asarray(r["a2"])
    f = np.minimum(np.nan_to_num(r["f"], nan=np.nan, posinf=0.8), 0.8)
    accumulation = matplotlib.colors.ListedColormap(["#d0d0d0", "#1b7837"])
    with plt.rc_context({"font.size": 13, "axes.titlesize": 14}):
        fig, axes = plt.subplots(2, 2, figsize=(15, 12.5))
        (a, b), (c, d) = axes
        mesh = a.pcolormesh(grid, grid, f.T, shading="nearest", cmap="viridis", rasterized=True)
        fig.colorbar(mesh, ax=a)
        a.set_title("A: f (capped at 0.8; white: non-physical)")
        cases = b.pcolormesh(grid, grid, r["case"].T.astype(float), shading="nearest",
                             cmap=matplotlib.colors.ListedColormap(CASE_COLORS), vmin=-0.5,
                             vmax=5.5, rasterized=True)
        _case_colorbar(fig, cases, b)
        b.set_title("B: case of Table 1")
        mesh = c.pcolormesh(grid, grid, r["accumulates"].T.astype(float), shading="nearest",
                            cmap=accumulation, vmin=0, vmax=1, rasterized=True)
        fig.colorbar(mesh, ax=c).ax.set_visible(False)  # same panel size as A, B, D
        c.legend(handles=[matplotlib.patches.Patch(color="#1b7837",
                                                   label=f"yes: all {entries} entries accumulate"),
                          matplotlib.patches.Patch(color="#d0d0d0", label="no")],
                 loc="lower left", title="accumulation")
        c.set_title("C: accumulation to x_stick,min")
        mesh = d.pcolormesh(grid, grid, r["dx_d"].T, shading="nearest", cmap="magma",
                            rasterized=True)
        fig.colorbar(mesh, ax=d)
        d.set_title("D: Δx_d, eq. (39) (white: never at rest)")
        for ax in axes.ravel():
            ax.set_xlabel("y2'' [-]")
            ax.set_ylabel("y3'' [-]")
        fig.suptitle("Fig. 17: Δt = 1, Δy = 0.084, w = 0.05, c_mu = 2.5")
        fig.tight_layout()
        files = _save(fig, out_dir, "fig17", dpi=110)
    a2, a3 = np.meshgrid(grid, grid, indexing="ij")
    data = _csv(out_dir, "fig17", {"a2": a2, "a3": a3, "case": r["case"], "f": r["f"],
                                    "accumulates": r["accumulates"], "dx_d": r["dx_d"],
                                    "max_periods_p99": r["max_periods_p99"],
                                    "max_periods_p999": r["max_periods_p999"]})
    return Figure("17", "f, case, accumulation and positioning error",
                  "High y2'' moves fast but must stay low enough to stick; low y3'' favours case "
                  "1; where accumulation occurs (C) the positioning error vanishes (D) (Sect. 7.2).",
                  files, [data],
                  f"{n} x {n} grid over (0, 2.5]^2, {entries} entries per cell; white in A, D: "
                  "non-physical profile, or the object never arrives (case 0, 2, 5 or v̄ <= 0) "
                  "or never comes to rest.", r)


def fig18(out_dir: str) -> Figure:
    """Fig. 18: the stick-position map (59), the diagonal and the fixed point."""
    profile = _three_phase(1.05, 0.084, 2.2, 0.9)
    table = sa.TwoRegionTable(0.0, WIDTH, C_MU)
    m = sa.StickPositionMap(profile, table)
    x_stick_min = sa.stick_position_min(table, profile.peak_acceleration)
    x = np.linspace(0.0, WIDTH, 400)
    x_next = m(x)
    basin = m.basin_lower_bound()
    fig, ax = plt.subplots(figsize=(7, 6))
    ax.plot(x, x_next, label="x_{n+1}(x_n), eq. (59)")
    ax.plot(x, x, "k:", label="diagonal x_{n+1} = x_n")
    ax.plot([m.fixed_point()], [m.fixed_point()], "ro", label="fixed point, eq. (60)")
    every = m(0.0) < x_stick_min  # Sect. 7.3's condition for accumulation from every x_1
    ax.plot([0.0], [m(0.0)], "s", color="tab:blue", mfc="none",
            label=f"x_{{n+1}}(x_mu) = {m(0.0):.4f} {'<' if every else '>='} x_stick,min: "
                  + ("accumulation from every x_1" if every else "accumulation depends on x_1"))
    ax.axvline(0.0, color="0.4", ls="--", lw=1.2, label="x_mu = 0: high friction starts")
    ax.axvline(x_stick_min, color="r", ls="--", lw=1.0,
               label=f"x_stick,min = {x_stick_min:.3f}, eq. (41)")
    ax.axvline(basin, color="tab:green", ls="-.", lw=1.0,
               label=f"c1 - 2K cos θ = {basin:.4f}: a first stop x_1 between this and "
                     "x_stick,min accumulates")
    ax.set_xlabel("x_n [-]  (x_mu = 0)")
    ax.set_ylabel("x_{n+1} [-]")
    ax.set_xlim(-0.1 * WIDTH, WIDTH)
    ax.set_ylim(-0.1 * WIDTH, WIDTH)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.1))
    ax.set_title("Fig. 18: y2'' = 2.2, y3'' = 0.9, Δt = 1.05, Δy = 0.084")
    data = _csv(out_dir, "fig18", {"x_n": x, "x_next": x_next, "diagonal": x})
    return Figure("18", "Stick-position map",
                  "The fixed point of map (59) lies at x_stick,min; depending on the initial "
                  "conditions the mass accumulates there or sticks beyond it (Sect. 7.3).",
                  _save(fig, out_dir, "fig18"), [data],
                  "Dashed lines: x_mu (grey), x_stick,min (red); dash-dotted: the basin bound "
                  "c1 - 2K cos θ (docs/accumulation.md): a first stick position x_1 between it "
                  "and x_stick,min accumulates, one below it sticks beyond x_stick,min.")


ALL = [fig3, fig4, fig5, fig6, fig7, fig9, fig10, fig11, fig12, fig13, fig16, fig17, fig18]


# ---- beyond the paper ----------------------------------------------------------------------

def figF1(out_dir: str) -> Figure:
    """Fig. F1: the vibratory feeder's regimes and the bouncing-ball flight (beyond the paper)."""
    from . import feeder_figures  # matplotlib is already loaded here

    angles = np.linspace(0.0, 1.2, 49)
    ks = 0.1 * 100.0 ** np.linspace(0.0, 1.0, 81)
    chart = sa.feeder_regime_chart(angles, ks, incline=0.0, mu_static=0.5, mu_kinetic=0.4)
    flights = feeder_figures.flight_angles(np.linspace(1.05, 3.2, 44))
    worst = float(np.max(np.abs(flights["exact"] - flights["equation"])))
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))
    feeder_figures.plot_regime_chart(chart, incline=0.0, mu_static=0.5, ax=left)
    left.set_title("regimes (exact runs), mu_s = 0.5, mu_k = 0.4, level track;\n"
                   "contours: v / (a0 w cos psi)", fontsize=9)
    right.plot(flights["throw_number"], flights["equation"], "-", color="0.3",
               label="flight equation (bisection)")
    right.plot(flights["throw_number"], flights["exact"], "o", ms=4, mfc="none",
               color="tab:red", label=f"exact feeder solver (largest difference {worst:.1e} rad)")
    right.set_xlabel("throw number Gamma = K sin psi / cos theta [-]")
    right.set_ylabel("flight angle [rad]")
    right.set_title("plastic landing, part held on the track (mu = 20), psi = 0.6", fontsize=9)
    right.legend(fontsize=8)
    data = _csv(out_dir, "figF1", {
        "vibration_angle": chart["vibration_angle"], "machine_number": chart["machine_number"],
        "regime": chart["regime"], "dimensionless_speed": chart["dimensionless_speed"]})
    flight_data = _csv(out_dir, "figF1_flight", flights)
    return Figure("F1", "Vibratory feeder: regimes and flight (beyond the paper)",
                  "Classical vibratory-feeder theory (Redford and Boothroyd; Sloot and Kruyt), "
                  "which the paper's planar table leaves out (issue 23): a part on a track driven "
                  "along the vibration angle slips forward, slips backward or hops where the "
                  "closed-form onsets say, and with plastic landing its flight angle obeys the "
                  "bouncing-ball flight equation.",
                  _save(fig, out_dir, "figF1"), [data, flight_data],
                  "Left: cells coloured by the closed-form regime, the onset curves, contours of "
                  "the exact solver's dimensionless speed (10 periods from rest). Right: the "
                  f"exact solver's flight angle against the flight equation, largest difference "
                  f"{worst:.1e} rad over {len(flights['exact'])} throw numbers (docs/feeder.md).",
                  raw={"worst_flight_difference": worst})


# Figures beyond the paper, drawn after the paper's by the reproduce run.
BEYOND = [figF1]
