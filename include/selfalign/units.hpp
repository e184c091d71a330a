#pragma once
/// \file units.hpp
/// The one conversion between SI units and the dimensionless model of Sect. 3.2.
///
/// Dimensionless variables (eq. 4): x = x~/L, y = y~/L, t = t~/T with the time scale
/// T = sqrt(L / (mu g)). In these variables the equation of motion (3) becomes (6),
/// -Sign(x') ∋ x'' + y'', and the friction bound is 1 in the low-friction region.
/// Accelerations scale with L/T^2 = mu g, velocities with L/T = sqrt(L mu g).
///
/// Everything inside selfalign is dimensionless ([-]); SI appears only at the edges
/// (CLI, config files, Python), through the functions below. They are plain products and
/// quotients: NaN (a value that is absent) stays NaN and +-inf (e.g. "no jerk limit") stays
/// +-inf.

namespace selfalign {

/// How a key's value converts between SI and dimensionless units (Sect. 3.2).
enum class Dimension {
  none,         ///< same value in both systems ([-], or always SI like g [m/s^2])
  length,       ///< [m] = L [-]
  time,         ///< [s] = T [-],  T = sqrt(L/(mu g))
  velocity,     ///< [m/s] = L/T [-]
  acceleration, ///< [m/s^2] = mu g [-]
  jerk,         ///< [m/s^3] = mu g / T [-]
  rate          ///< [1/s] = 1/T [-] (a viscous coefficient per unit mass)
};


/// Characteristic scales of the dimensionless model (Sect. 3.2).
class Scales {
 public:
  /// \param length_m   characteristic length L~ [m], > 0
  /// \param mu         low-friction Coulomb coefficient mu = mu_1 [-], > 0
  /// \param gravity    gravitational acceleration g~ [m/s^2], > 0 (default 9.81)
  /// Throws InvalidParameter naming the offending argument.
  Scales(double length_m, double mu, double gravity = 9.81);

  double length() const noexcept { return length_; }          ///< L~ [m]
  double mu() const noexcept { return mu_; }                  ///< mu_1 [-]
  double gravity() const noexcept { return gravity_; }        ///< g~ [m/s^2]
  double time() const noexcept { return time_; }              ///< T~ = sqrt(L~/(mu g~)) [s]
  double velocity() const noexcept { return length_ / time_; }       ///< L~/T~ [m/s]
  double acceleration() const noexcept { return mu_ * gravity_; }    ///< L~/T~^2 = mu g~ [m/s^2]
  double jerk() const noexcept { return acceleration() / time_; }    ///< L~/T~^3 = mu g~/T~ [m/s^3]

  // SI -> dimensionless
  double length_from_si(double metres) const noexcept { return metres / length_; }
  double time_from_si(double seconds) const noexcept { return seconds / time_; }
  double velocity_from_si(double m_per_s) const noexcept { return m_per_s / velocity(); }
  double acceleration_from_si(double m_per_s2) const noexcept { return m_per_s2 / acceleration(); }
  double jerk_from_si(double m_per_s3) const noexcept {
    return acceleration_from_si(m_per_s3) * time_;
  }
  // dimensionless -> SI
  double length_to_si(double x) const noexcept { return x * length_; }
  double time_to_si(double t) const noexcept { return t * time_; }
  double velocity_to_si(double v) const noexcept { return v * velocity(); }
  double acceleration_to_si(double a) const noexcept { return a * acceleration(); }
  double jerk_to_si(double j) const noexcept { return acceleration_to_si(j) / time_; }

 private:
  double length_, mu_, gravity_, time_;
};

}  // namespace selfalign
