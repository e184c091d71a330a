#pragma once
/// \file friction_law.hpp
/// The contact's friction law as a value type: Coulomb friction with a static coefficient at
/// least the kinetic one, kinetic coefficients that may depend on the slip direction (sawtooth
/// or textured surfaces), and optionally on the slip speed: a Stribeck decay from the static to
/// the kinetic value and a viscous term. The paper's Sect. 8, items (3) and (4).
///
/// Dimensionless like the rest of the model (Sect. 3.2): every coefficient is relative to the
/// unit mu_1, the forward kinetic coefficient of the low-friction region, so the paper's law is
/// FrictionLaw{} = (1, 1, 1). With the position-dependent level m(x) of the table's friction
/// field averaged over the object's footprint (friction_map.hpp), the friction force on the
/// object, per unit m g mu_1, is
///   stick  (x' = 0):  any value in [-s m(x), s m(x)],                 s = static coefficient
///   slip   (x' != 0): -mu_sigma(|x'|) m(x) sigma - c x',              sigma = sign(x')
/// with the kinetic coefficient of the slip direction (k_+ forward, k_- backward)
///   mu_sigma(v) = k_sigma                                              (Coulomb)
///   mu_sigma(v) = k_sigma + (s - k_sigma) exp(-(v / v_s)^delta)        (Stribeck, v_s > 0)
/// and c >= 0 a viscous coefficient (0 by default). So eq. (6) reads
///   x'' = -sigma mu_sigma(|x'|) m(x) - c x' - y''   while slipping,
/// and x stays stuck while |y''| <= s m(x): sticking stays set-valued (no regularisation). The
/// Stribeck curve starts at the static value at zero speed and tends to k_sigma; v_s -> 0 gives
/// back the Coulomb law with static != kinetic. Velocity-dependent laws have no closed-form
/// slip arcs: the event-locating integrator solves them (simulate/slip_integrator.hpp).
/// Modelled on Drake's CoulombFriction(static, dynamic), which also refuses a dynamic
/// coefficient above the static one.

#include <optional>
#include <string>

namespace selfalign {

class FrictionLaw {
 public:
  /// The paper's law: static = kinetic = 1 in both directions, no speed dependence.
  FrictionLaw() = default;
  /// Symmetric law. \param static_coefficient s [-], \param kinetic k [-]: finite, 0 < k <= s
  /// (and <= 1e50). Throws InvalidParameter naming both when k > s.
  FrictionLaw(double static_coefficient, double kinetic);
  /// Direction-dependent kinetic coefficients: k_+ for forward slip (x' > 0), k_- for backward.
  /// Needs 0 < k_+, k_- <= s. Throws InvalidParameter naming the offending pair.
  FrictionLaw(double static_coefficient, double kinetic_forward, double kinetic_backward);

  /// This law with a Stribeck decay: \param stribeck_velocity v_s [-], finite and > 0;
  /// \param exponent delta [-], finite, in (0, 100]. Throws InvalidParameter naming
  /// "stribeck_velocity" or "stribeck_exponent".
  FrictionLaw with_stribeck(double stribeck_velocity, double exponent = 1.0) const;
  /// This law with a viscous term c x': \param viscous c [-], finite and >= 0 (<= 1e50).
  /// Throws InvalidParameter naming "viscous".
  FrictionLaw with_viscous(double viscous) const;

  double static_coefficient() const noexcept { return static_; }
  double kinetic_forward() const noexcept { return forward_; }
  double kinetic_backward() const noexcept { return backward_; }
  /// k_sigma for slip direction sigma (> 0: forward, < 0: backward): the coefficient at high
  /// slip speed (the only one of a Coulomb law).
  double kinetic(int sigma) const noexcept { return sigma > 0 ? forward_ : backward_; }
  /// v_s [-]; 0 when the law has no Stribeck decay.
  double stribeck_velocity() const noexcept { return stribeck_velocity_; }
  /// delta [-] (1 when the law has no Stribeck decay).
  double stribeck_exponent() const noexcept { return exponent_; }
  /// c [-]; 0 when the law has no viscous term.
  double viscous() const noexcept { return viscous_; }
  /// True when the slip force depends on the slip speed (a Stribeck decay or a viscous term was
  /// given): such a law has no closed-form arcs; the integrator solves it.
  bool velocity_dependent() const noexcept { return stribeck_velocity_ > 0 || viscous_ > 0; }
  /// mu_sigma(speed) of the header comment [-], speed = |x'| >= 0.
  double kinetic(int sigma, double speed) const noexcept;
  /// True for the paper's law (all coefficients 1, no speed dependence).
  bool is_unit() const noexcept {
    return static_ == 1.0 && forward_ == 1.0 && backward_ == 1.0 && !velocity_dependent();
  }
  /// "static 1.2, kinetic 1", "static 1.2, kinetic forward 1, backward 0.8", with
  /// ", Stribeck v_s 0.01 delta 2, viscous 0.1" when given.
  std::string describe() const;

  friend bool operator==(const FrictionLaw&, const FrictionLaw&) = default;

 private:
  double static_ = 1.0, forward_ = 1.0, backward_ = 1.0;
  double stribeck_velocity_ = 0.0, exponent_ = 1.0, viscous_ = 0.0;
};

/// The law of absolute friction coefficients, the convention of every front end (docs/config.md,
/// "Friction law"): FrictionLaw(mu_static/mu, 1, mu_backward/mu).
/// \param mu the kinetic coefficient mu_1 of forward slip [-], the model's unit, in [1e-50, 1e50].
/// \param mu_static the static coefficient [-], >= mu and >= mu_backward; none: mu.
/// \param mu_backward the kinetic coefficient of backward slip [-], > 0; none: mu.
/// Each coefficient is checked as given, before the ratios are formed, and a failure names it
/// ("mu", "mu_static", "mu_backward") with its value and range.
FrictionLaw law_of_coefficients(double mu, std::optional<double> mu_static,
                                std::optional<double> mu_backward);

}  // namespace selfalign
