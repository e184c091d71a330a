#pragma once
/// \file process_uncertainty.hpp
/// A designed process (SI) under uncertain inputs, and one run of it for one draw of those
/// inputs.
///
/// The process is the family `selfalign design` produces: a three-phase table motion (jump
/// accelerations, or ramps at a jerk limit) and where the rough region starts, x_mu. Its seven
/// uncertain inputs (kUncertainInputs) are the friction coefficient mu of the smooth region,
/// c_mu, the static/kinetic ratio, the width of the transition region (the object's width:
/// eqs. 7-9 average the friction step over the footprint), an error of x_mu, and factors on
/// the table's amplitude and period (y~(t) -> a y~(t / p): strokes scale by a, accelerations by
/// a / p^2, jerks by a / p^3). One run converts the draw to model units (Sect. 3.2 with L = the
/// drawn width and the drawn mu) and runs the exact stopping run of analysis/stopping.hpp from
/// rest at x = 0.

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "selfalign/analysis/stopping.hpp"
#include "selfalign/design/process_design.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/robust/distribution.hpp"
#include "selfalign/units.hpp"

namespace selfalign {

inline constexpr std::size_t kUncertainInputs = 7;

/// The widest a normal draw reaches: u in [2^-54, 1 - 2^-54] maps to about +-8.3 sd (the
/// box(d, known, kDrawSigmas) every draw lies in).
inline constexpr double kDrawSigmas = 8.3;

/// One value per uncertain input, in the order of uncertain_inputs().
using InputValues = std::array<double, kUncertainInputs>;

/// What is known about each input; Known (the default) is the request's nominal value.
struct ProcessUncertainty {
  Distribution mu;             ///< kinetic coefficient mu_1 of the smooth region [-]
  Distribution c_mu;           ///< mu_2 / mu_1 [-], > 1
  Distribution static_ratio;   ///< mu_static / mu_1 [-], >= 1
  Distribution width;          ///< transition width = object width w~ [m], > 0
  Distribution x_mu_offset;    ///< error of the rough region's start [m] (nominal 0)
  Distribution amplitude;      ///< factor on the table's displacement [-] (nominal 1), > 0
  Distribution period_factor;  ///< factor on the table's period [-] (nominal 1), > 0
};

/// One uncertain input: its name (CLI `--uncertain NAME=...`, config and Python keyword), unit,
/// where it lives in ProcessUncertainty, and its nominal value for a request.
struct UncertainInput {
  const char* name;
  const char* unit;
  Distribution ProcessUncertainty::*member;
  double (*known)(const DesignRequest&);
  double lowest;  ///< values a draw must exceed (positivity, c_mu > 1, ratio >= 1)
  bool inclusive; ///< whether a draw may equal `lowest`
  const char* meaning;
};

/// The closed set of uncertain inputs, in InputValues order.
const std::array<UncertainInput, kUncertainInputs>& uncertain_inputs();

/// The index of an input by name; throws InvalidParameter("uncertain", name, ...) for another.
std::size_t uncertain_input_index(const std::string& name);

/// Sets input `name` from its text form (parse_distribution), e.g. ("mu", "normal:0.2,5%").
/// Throws InvalidParameter naming the input.
void set_input(ProcessUncertainty& uncertainty, const std::string& name, const std::string& text);

/// Validates every distribution (names like "mu.sd"), and that their supports keep draws
/// physical (e.g. a normal on mu must be truncated at or above 0 when mean - 6 sd <= 0).
void validate(const ProcessUncertainty& uncertainty);

/// The nominal values: each distribution's nominal (known: the request's value).
InputValues nominal_inputs(const DesignRequest& request, const ProcessUncertainty& u);

/// The draw of run `run` for `seed`: input k takes quantile(u_k) with u_k a counter-based
/// hash of (seed, run, k) mapped into (0, 1) — a pure function, so any split of the runs over
/// threads, chunks or machines draws the same values.
InputValues draw_inputs(const DesignRequest& request, const ProcessUncertainty& u,
                        std::uint64_t seed, std::uint64_t run);

/// The same draw with the known values given (`known`, InputValues order: what an input
/// without uncertainty takes) and input k taking uniform_draw(seed, run, stream + k):
/// draw_inputs(request, u, seed, run) is stream 0 with the request's known values. A queue's
/// part i draws stream kUncertainInputs * i (robust/row_monte_carlo.hpp), so part 0 draws
/// what the single-part study draws.
InputValues draw_inputs(const InputValues& known, const ProcessUncertainty& u,
                        std::uint64_t seed, std::uint64_t run, std::uint64_t stream);

/// The uniform number in (0, 1) behind draw (seed, run, input): SplitMix64 of a mix of the
/// three, top 53 bits, offset by half a unit so 0 and 1 never occur.
double uniform_draw(std::uint64_t seed, std::uint64_t run, std::uint64_t input);

/// A designed process in SI: the table motion and where the rough region starts.
struct Process {
  double period = 0;   ///< Δt~ [s]
  double stroke = 0;   ///< Δy~ [m]
  double a2 = 0;       ///< y2''~ [m/s^2]
  double a3 = 0;       ///< y3''~ [m/s^2]
  double jerk = std::numeric_limits<double>::infinity();  ///< [m/s^3]; inf: jumps
  double x_mu = 0;     ///< start of the rough region [m] (from the start position)
};

/// The process of a feasible design.
Process process_of(const DesignResult& design);

/// Throws InvalidParameter naming the first field out of range.
void validate(const Process& process);

/// Checks, before any run, that every draw of `u` gives `process` a model (profile and friction
/// map in units of the drawn width): each uncertain input at either end of its draws (a
/// normal's to ~8.3 sd) with the others nominal, then every corner of the box. Throws
/// InvalidParameter naming the input ("x_mu_offset.upper", "width.lower") or, for a corner,
/// the inputs together, with what the model refused. monte_carlo and worst_case call it.
void validate_draws(const DesignRequest& request, const Process& process,
                    const ProcessUncertainty& u);

/// How one run ended, SI.
struct ProcessOutcome {
  StopKind kind = StopKind::not_stopped;
  /// Where it stops for good [m] (accumulation: the limit x_stick,min); NaN when not stopped.
  double end_position = std::numeric_limits<double>::quiet_NaN();
  /// T_p [s]: when the final stick starts; for accumulation when 0.999 of the way from x_mu
  /// to the limit is reached for good (as `design`); NaN when not stopped.
  double process_time = std::numeric_limits<double>::quiet_NaN();
  /// When the object first reaches the rough region [s]; NaN if never.
  double entry_time = std::numeric_limits<double>::quiet_NaN();
};

class ProcessFamily;

/// One draw of a process in model units (Sect. 3.2 with L = the drawn width and the drawn mu):
/// the table motion y~(t) -> a y~(t / p), the law (drawn static ratio, kinetic 1, the request's
/// backward ratio capped by the static one) and where the rough region starts, x_mu + offset.
/// Built from the process's model config with the draw's parameters (ProcessFamily).
struct ProcessModel {
  ProcessModel(const DesignRequest& request, const Process& process, const InputValues& inputs);
  ProcessModel(const ProcessFamily& family, const InputValues& inputs);
  Scales scales;
  std::unique_ptr<TableProfile> profile;
  FrictionLaw law;
  double c_mu;  ///< the drawn mu_2/mu_1 [-]
  double x_mu;  ///< start of the rough region, x_mu + offset [-]
  /// Options of its stopping runs: `max_periods`, and the 0.999 fraction that times an
  /// accumulation (as design_process).
  static StoppingOptions stopping(int max_periods);
  /// A stopping run's outcome in SI.
  ProcessOutcome outcome(const StoppingRun& run) const;
};

/// The models of one process under its uncertain inputs: the process as a model config (SI,
/// three-phase table, two-region table at x_mu, the request's law and gravity) and the seven
/// inputs as parameters of its view (io/parameter_view.hpp), the one place where robust
/// analyses change a model:
///   mu -> mu; c_mu -> c_mu; static_ratio s -> mu_static = s mu; mu_backward = min(request's
///   ratio, s) mu; width -> width (and the unit length L); x_mu_offset d -> x_mu = x_mu + d;
///   amplitude a -> amplitude_scale; period_factor p -> time_scale.
/// Built once per process (the names are looked up once); model(inputs) per draw.
class ProcessFamily {
 public:
  ProcessFamily(const DesignRequest& request, const Process& process);
  /// The model config of this draw (SI; the unit length L = the drawn width).
  SimulateConfig config(const InputValues& inputs) const;
  const DesignRequest& request() const noexcept { return request_; }
  const Process& process() const noexcept { return process_; }

 private:
  DesignRequest request_;
  Process process_;
  ParameterView view_;
};

/// One exact stopping run of a model of `family` with these input values.
ProcessOutcome run_process(const ProcessFamily& family, const InputValues& inputs,
                           int max_periods);

/// One exact stopping run of `process` with these input values (the request supplies g and
/// mu_backward). max_periods bounds the run; a run that does not stop by then is not_stopped.
ProcessOutcome run_process(const DesignRequest& request, const Process& process,
                           const InputValues& inputs, int max_periods);

}  // namespace selfalign
