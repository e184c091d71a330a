"""selfalign: vibrational self-alignment of a rigid object exploiting friction.

A rigid object on a table that follows a prescribed periodic motion y(t) is walked in one
direction by Coulomb stick-slip friction and stopped where the table's friction rises
(Hunnekens, Fey, Shukla & Nijmeijer, Nonlinear Dynamics, 2010). This package is a thin
binding of the C++ library: profiles, friction maps, the exact and time-stepping solvers, and
the paper's analyses, with results as NumPy arrays.

Everything is dimensionless (Sect. 3.2: x = x~/L, t = t~/T, T = sqrt(L/(mu g)), accelerations
in units of mu g) unless stated; Scales converts to and from SI. Misuse raises
InvalidParameter (a ValueError with .name, .value, .allowed).

    >>> import selfalign as sa
    >>> profile = sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=3.0, a3=0.9)
    >>> sa.predict_case(profile.parameters)
    <StickSlipCase.stick_slip_forward: 1>
    >>> run = sa.simulate(profile, sa.UniformFriction(), options=sa.SimulationOptions(duration=5))
    >>> run.trajectory.x.shape
    (1001,)
"""

from ._selfalign import (  # the whole public API of the extension; _selfalign.pyi types it
    AccelerationSamples,
    ArcEnd,
    ArcKind,
    ConvergenceOptions,
    ExactState,
    FloquetAnalysis,
    FloquetOptions,
    FourierProfile,
    FieldFriction,
    FrictionField,
    FrictionMap,
    Interpolation,
    InvalidParameter,
    JerkLimitedCase0,
    JerkLimitedThreePhaseFamily,
    JerkLimitedThreePhaseParameters,
    JerkLimitedThreePhaseProfile,
    JerkLimitedThreePhaseSolution,
    LinearAccelerationProfile,
    Method,
    Monodromy,
    OBJECTIVE_SCALE,
    ObjectState,
    PeriodMap,
    PiecewiseConstantProfile,
    PiecewisePolynomialProfile,
    PointFootprint,
    PositioningAccuracy,
    PositioningOptions,
    ProfileFamily,
    Scales,
    ScaledFourierFamily,
    ScaledShapeFamily,
    SignInterval,
    SimulationOptions,
    SimulationResult,
    SteadyState,
    SteadyStateOptions,
    StickPositionMap,
    StickSlipCase,
    StopKind,
    StoppingOptions,
    StoppingRun,
    TableProfile,
    TableState,
    ThreePhaseFamily,
    ThreePhaseParameters,
    ThreePhaseProfile,
    ThreePhaseSolution,
    TimeSteppingOptions,
    TimeSteppingState,
    Trajectory,
    TwoRegionFriction,
    CoulombFriction,
    FrictionLaw,
    IntegratorOptions,
    IntegratorStatistics,
    UniformFootprint,
    UniformFriction,
    VelocityConvergence,
    advance_exact,
    advance_time_stepping,
    ActuatorLimits,
    DesignRequest,
    DesignResult,
    actuator_samples,
    describe,
    design_process,
    compare_families,
    optimize_fourier,
    optimize_piecewise_constant,
    optimize_three_phase,
    rebuild_profile,
    OptimizeOptions,
    OptimizationResult,
    exact_arcs,
    floquet_multipliers,
    linear_grid,
    log_grid,
    make_exact_state,
    make_monodromy,
    make_sampled_profile,
    make_time_stepping_state,
    objective_f,
    positioning_accuracy,
    positioning_surfaces,
    predict_case,
    read_acceleration_samples,
    simulate,
    slip_slip_multiplier,
    solve_jerk_limited_three_phase,
    solve_three_phase,
    steady_state,
    stick_position_min,
    sticks,
    sticks_permanently,
    stopping_run,
    sweep_accelerations,
    sweep_period,
    sweep_stroke,
    velocity_convergence,
    # robust design under uncertainty (docs/robust-design.md)
    Known,
    Normal,
    Uniform,
    Samples,
    Interval,
    ProcessUncertainty,
    Process,
    MonteCarloResult,
    WorstCase,
    Fragility,
    FailureCounts,
    RobustDesignResult,
    parse_distribution,
    uncertain_inputs,
    process_of,
    draw_inputs,
    monte_carlo,
    merge_monte_carlo,
    worst_case,
    fragility,
    design_robust,
)

# Studies that also take executor= and chunk_size= (a concurrent.futures.Executor: Dask,
# mpi4py; docs/scale-out.md): Python wrappers over the extension's functions (their
# __wrapped__), identical to them without an executor.
from .scaleout import (  # noqa: E402
    monte_carlo,
    positioning_surfaces,
    sweep_accelerations,
    sweep_period,
    sweep_stroke,
)
from . import scaleout  # noqa: E402

__version__ = "0.1.0"

__all__ = [name for name in dir() if not name.startswith("_") and name != "scaleout"]
