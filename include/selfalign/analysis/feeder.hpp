#pragma once
/// \file feeder.hpp
/// The vibratory feeder (issue 23, first part): a track inclined by theta, driven along a line at
/// the vibration angle psi to its surface, so that the normal load m (g cos theta + z''(t))
/// changes over the period and the friction bound with it (docs/feeder.md).
///
///  - the classic sinusoidal drive (FeederDrive): x = a0 cos(psi) sin(w t) along the track,
///    z = a0 sin(psi) sin(w t) along its normal; its machine number K = a0 w^2 / g and throw
///    number Gamma = K sin(psi) / cos(theta);
///  - the closed-form onsets (feeder_onsets): the least K at which a part at rest on the track
///    first slips forward, slips backward, or lifts off, from the stick inequality
///    |a_x + g sin theta| <= mu_s (g cos theta + a_z);
///  - the track as a contact-core model (FeederTable, feeder_model): the table's motion along
///    the track and its normal, gravity and the incline (core::Gravity), one 1-D part; and a
///    run of it by Moreau's time-stepping (feeder_run): the first event from rest, the mean
///    conveying velocity over the last period and the stick fraction.
/// With the model's flight (the default) the core integrates lift-off, flight and plastic
/// landing (Moreau-Jean); without it a run that reaches lift-off stops there.

#include <memory>
#include <string>
#include <string_view>

#include <cmath>
#include <vector>

#include "selfalign/analysis/sweep.hpp"  // ProgressCallback
#include "selfalign/core/model.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/method.hpp"

namespace selfalign {

/// The feeder drive on an inclined track: along the vibration line the displacement
/// a0 (sin w t + r sin(2 w t + phi2)), the classic sinusoid for r = 0 and a two-frequency drive
/// (a second harmonic of ratio r and phase phi2) otherwise. Dimensionless as the model:
/// accelerations in the model's unit (mu_1 g in the paper's, where g = 1 / mu_1).
struct FeederDrive {
  double amplitude = 0.0;        ///< a0 along the vibration line [-], > 0
  double period = 1.0;           ///< 2 pi / w [-], > 0
  double vibration_angle = 0.0;  ///< psi [rad], in (-pi/2, pi/2)
  double incline = 0.0;          ///< theta [rad], in (-pi/2, pi/2); > 0: the track rises along +x
  double g = 1.0;                ///< gravity in model units [-], > 0
  double harmonic_ratio = 0.0;   ///< r, the second harmonic's amplitude over a0 [-], in [0, 100]
  double harmonic_phase = 0.0;   ///< phi2 [rad], finite
};

/// Throws InvalidParameter naming "amplitude", "period", "vibration_angle" (|psi| >= pi/2),
/// "incline" (|theta| >= pi/2), "g", "harmonic_ratio" or "harmonic_phase".
void validate(const FeederDrive& drive);

/// Throws InvalidParameter naming `name` unless |angle| < pi/2 (a vibration angle or an
/// incline) [rad].
void require_feeder_angle(std::string_view name, double angle);

/// The track and drive settings the studies share (the regime chart, the drive design): throws
/// InvalidParameter naming "incline" (|theta| >= pi/2), "mu_static", "mu_kinetic" (not in
/// (0, mu_static]), "g" or "period".
void require_feeder_track(double incline, double mu_static, double mu_kinetic, double g,
                          double period);

/// K = a0 w^2 / g [-]: the fundamental's peak acceleration over g (the drive's peak
/// acceleration for the classic sinusoid).
double machine_number(const FeederDrive& drive);

/// The drive's acceleration shape along the vibration line, s(phi) = sin(phi) + 4 r sin(2 phi +
/// phi2) (the acceleration is -a0 w^2 s(w t)): its largest value and the largest of -s over the
/// period (both 1 for the classic sinusoid). Found on 4096 samples, each extremum then closed by
/// bisection on s' = cos(phi) + 8 r cos(2 phi + phi2) (to the rounding of phi).
struct FeederShape {
  double peak_up = 1, peak_down = 1;
};
FeederShape feeder_shape(const FeederDrive& drive);

/// Gamma [-]: the drive's peak acceleration away from the track's surface over g cos(theta),
/// K S sin(psi) / cos(theta) with S the shape's peak on that side (K sin(psi) / cos(theta) for
/// the classic sinusoid): the part lifts off where |Gamma| > 1.
double throw_number(const FeederDrive& drive);

/// The onsets as critical machine numbers K (docs/feeder.md): the least K at which a part at
/// rest on the track, held while |a_x + g sin theta| <= mu_s (g cos theta + a_z), first slips
/// forward (+x), slips backward, or lifts off (g cos theta + a_z < 0). +inf: never at any K;
/// 0: the part is not held even at rest (the incline exceeds the friction angle).
struct FeederOnsets {
  double forward_slip = 0, backward_slip = 0, lift_off = 0;
};

/// \param static_friction mu_s, the absolute static coefficient [-] (> 0): s m / g in model
/// units (s the law's static coefficient, m the friction level). Throws InvalidParameter
/// naming "vibration_angle", "incline" or "static_friction".
FeederOnsets feeder_onsets(double vibration_angle, double incline, double static_friction);
/// The onsets of the drive's own shape (a two-frequency drive: each inequality is first met at
/// the shape's peak on its side, FeederShape), as machine numbers K of its fundamental.
FeederOnsets feeder_onsets(const FeederDrive& drive, double static_friction);

/// The drive's table motion (it owns its profiles): along the track (e1 = x) a0 cos(psi)
/// sin(w t), along its normal a0 sin(psi) sin(w t) (none at psi = 0), and gravity with the
/// incline (downhill along -x for theta > 0).
class FeederTable {
 public:
  explicit FeederTable(const FeederDrive& drive);
  const PlanarTableMotion& motion() const noexcept { return motion_; }
  core::Gravity gravity() const noexcept { return gravity_; }
  const FeederDrive& drive() const noexcept { return drive_; }

 private:
  FeederDrive drive_;
  std::shared_ptr<const TableProfile> along_, normal_;
  PlanarTableMotion motion_;
  core::Gravity gravity_;
};

/// A model of one 1-D part (a point footprint, `law`) on the table's track at the uniform
/// level `level`, Moreau's step h = period / steps_per_period (>= 2; InvalidParameter naming
/// "steps_per_period" otherwise); `flight`: lift-off, flight and landing by Moreau-Jean
/// (core::Gravity::flight) with Newton's `restitution` e in [0, 1] (InvalidParameter naming
/// "gravity.restitution" otherwise), else a run stops at a lift-off. The table must outlive
/// the model.
core::Model feeder_model(const FeederTable& table, const FrictionLaw& law, double level,
                         long long steps_per_period, bool flight = true,
                         double restitution = 0);

/// The first thing that happens to a part at rest on the track.
enum class FeederEvent { none, forward_slip, backward_slip, lift_off };
/// "none", "forward slip", "backward slip", "lift-off".
const char* feeder_event_name(FeederEvent event) noexcept;

struct FeederRun {
  FeederEvent first_event = FeederEvent::none;
  double first_event_time = 0;  ///< the end of the step where it happened [-]; NaN for none
  /// The part left the track. Without the model's flight the run stopped there: velocity and
  /// fractions are NaN.
  bool lifted_off = false;
  /// Mean velocity along the track over the last period (relative to the track, which does
  /// not advance over a period) [-].
  double velocity = 0;
  double stick_fraction = 0;   ///< of the last period's steps: held on the track
  double flight_fraction = 0;  ///< of the last period's steps: ended off the track
  /// The last period's flight in the feeder literature's angles: the phase w (t - t_period)
  /// at which the part first left the track in it (the end of that step) [rad], and the flight
  /// angle 2 pi flight_fraction (w times the time off the track) [rad]; NaN without a flight.
  double lift_off_phase = NAN, flight_angle = NAN;
};

/// From rest at x = 0, t = 0, `periods` (>= 1) periods of `period` [-] of the model by the
/// contact core's Moreau step (core/step.hpp). The model must have one SliderBody.
FeederRun feeder_run(const core::Model& model, double period, long long periods);

/// The same run by the exact feeder solver (feeder_exact.hpp) on the table's sinusoidal drive:
/// the part (`law` at the uniform `level`) from rest at x = 0, t = 0 for `periods` (>= 1)
/// periods, landings with Newton's `restitution` e in [0, 1]. The numbers are feeder_run's
/// without the step: the first event at its exact time, the last period's mean velocity, its
/// stick and flight fractions of the period's time, the lift-off phase of its first lift-off
/// and its flight angle. `flight` false: as feeder_run without the model's flight, a run that
/// lifts off stops in that period (velocity and fractions NaN). Throws InvalidParameter as
/// validate(FeederTrack) and naming "periods".
FeederRun feeder_run_exact(const FeederTable& table, const FrictionLaw& law, double level,
                           long long periods, double restitution = 0, bool flight = true);

/// Stopping on a vibrating feeder track: the part, released at rest at `start` on the track
/// whose friction level along it is `field` (for the law's coefficients to be absolute, the
/// level g where the track is smooth and c_mu g where it is rough, as `level` in feeder_run),
/// runs period by period until it is held through a whole period: the drive is periodic, so
/// it stays there (stopped). A part that moves in every one of `max_periods` periods has not
/// stopped: end_position and stop_time are NaN (a result, not an error).
struct FeederStop {
  bool stopped = false;
  double end_position = NAN;  ///< x on the track where it rests [-]; NaN: not stopped
  double stop_time = NAN;     ///< the instant it last moved, from the release [-]; NaN: not stopped
  long long periods = 0;      ///< periods run (the stopping one included)
  bool lifted_off = false;    ///< it left the track at some time
};

/// By the exact feeder solver: `field` must be piecewise constant (FrictionField::steps: a
/// friction step without a transition width; InvalidParameter naming "field" otherwise),
/// landings with Newton's `restitution`. Throws InvalidParameter naming "start" (not finite),
/// "max_periods" (< 1) or as validate(FeederTrack).
FeederStop feeder_stop_exact(const FeederTable& table, const FrictionLaw& law,
                             const FrictionField& field, double start, long long max_periods,
                             double restitution = 0);

/// The same by the contact core (Moreau, Moreau-Jean flight) on `model` (feeder_model with the
/// field): held through a period means every step of it a stick on the track; stop_time is the
/// end of the last step that moved. The model must have one SliderBody.
FeederStop feeder_stop(const core::Model& model, double period, double start,
                       long long max_periods);

/// A model of one 1-D part on the track with the friction level `field` along it (an AxisField
/// at the track's origin, e1 = x), otherwise as feeder_model above.
core::Model feeder_model(const FeederTable& table, const FrictionLaw& law,
                         const FrictionField& field, long long steps_per_period,
                         bool flight = true, double restitution = 0);

/// How a feeder run is solved: Method::exact (the exact feeder solver) or
/// Method::time_stepping (the contact core: Moreau, Moreau-Jean flight, `steps_per_period`);
/// `flight` false: a run stops at a lift-off (the exact stopping run always flies); landings
/// with Newton's `restitution`.
struct FeederSolver {
  Method method = Method::exact;
  long long steps_per_period = 2000;
  bool flight = true;
  double restitution = 0;
};

/// feeder_run_exact or feeder_run on feeder_model, as `solver` says (InvalidParameter naming
/// "method" for any other method).
FeederRun feeder_run(const FeederTable& table, const FrictionLaw& law, double level,
                     long long periods, const FeederSolver& solver);
/// feeder_stop_exact or feeder_stop on feeder_model with the field, as `solver` says.
FeederStop feeder_stop(const FeederTable& table, const FrictionLaw& law,
                       const FrictionField& field, double start, long long max_periods,
                       const FeederSolver& solver);

/// The regime the closed-form onsets give at machine number K (docs/feeder.md): stick (below
/// both slips), forward (the forward slip only), backward, both (slips both ways each period),
/// hopping (at or above the lift-off: flights, whatever else happens).
enum class FeederRegime { stick, forward, backward, both, hopping };
/// "stick", "forward", "backward", "both", "hopping".
const char* feeder_regime_name(FeederRegime regime) noexcept;
FeederRegime feeder_regime(const FeederOnsets& onsets, double machine_number);

/// A regime chart's common settings: the track and the friction, the runs' length and step.
struct FeederChartOptions {
  double incline = 0;                     ///< theta [rad]
  double mu_static = 0.5, mu_kinetic = 0.4;  ///< absolute coefficients, 0 < k <= s
  double g = 1;                           ///< [-] (9.81 in SI)
  double period = 1;                      ///< drive period [-] (s in SI)
  long long periods = 10;                 ///< from rest; the last one is reported
  long long steps_per_period = 200;       ///< Moreau's steps (time-stepping only)
  bool flight = true;                     ///< flight and landing (else runs stop at lift-off)
  /// Method::exact (feeder_run_exact, plastic landing; the default) or Method::time_stepping
  /// (feeder_run: Moreau, Moreau-Jean flight, steps_per_period steps).
  Method method = Method::exact;
  double restitution = 0;                 ///< Newton's e at landings, in [0, 1]
  int threads = 0;                        ///< 0: all cores
  ProgressCallback progress;              ///< (cells done, cells), optional
};

/// One cell: its drive, the closed-form regime, and the simulated run.
struct FeederChartCell {
  double vibration_angle = 0, machine_number = 0, throw_number = 0;
  FeederRegime regime = FeederRegime::stick;
  FeederRun run;
  double dimensionless_speed = NAN;  ///< run.velocity / (a0 w cos psi)
  std::string failure;               ///< empty when computed (a failed cell keeps NaN numbers)
};

/// The regime chart over vibration angles x machine numbers (machine number fastest): per cell
/// the closed-form regime from feeder_onsets and a run of feeder_run_exact or feeder_run
/// (options.method; amplitude K g / w^2, the part at the friction level g so that the bound is
/// mu (g cos theta + z'')); a stick cell's run is known without running it (the onsets prove
/// the part is held at every instant: no event, velocity 0, stick fraction 1, as both runs
/// give it), in parallel through the studies' one loop (results independent of the thread
/// count). Throws InvalidParameter naming the first bad option or grid value.
std::vector<FeederChartCell> feeder_regime_chart(const std::vector<double>& vibration_angles,
                                                 const std::vector<double>& machine_numbers,
                                                 const FeederChartOptions& options);

}  // namespace selfalign
