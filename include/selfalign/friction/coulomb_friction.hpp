#pragma once
/// \file coulomb_friction.hpp
/// The contact's friction law as a value type: Coulomb friction with a static coefficient at
/// least the kinetic one, and optionally kinetic coefficients that depend on the slip
/// direction (sawtooth or textured surfaces). The paper's Sect. 8, item (3).
///
/// Dimensionless like the rest of the model (Sect. 3.2): every coefficient is relative to the
/// unit mu_1, the forward kinetic coefficient of the low-friction region, so the paper's law is
/// CoulombFriction{} = (1, 1, 1). With the position-dependent level m(x) of the table's
/// friction field averaged over the object's footprint (friction_map.hpp), the friction force
/// on the object, per unit m g mu_1, is
///   stick  (x' = 0):  any value in [-s m(x), s m(x)],   s = static coefficient
///   slip   (x' != 0): -k_sigma m(x) sigma,               sigma = sign(x'), k_+ / k_- kinetic
/// so eq. (6) reads x'' = -k_sigma m(x) sigma - y'' while slipping, and x stays stuck while
/// |y''| <= s m(x). Modelled on Drake's CoulombFriction(static, dynamic), which also refuses a
/// dynamic coefficient above the static one.

#include <string>

namespace selfalign {

class CoulombFriction {
 public:
  /// The paper's law: static = kinetic = 1 in both directions.
  CoulombFriction() = default;
  /// Symmetric law. \param static_coefficient s [-], \param kinetic k [-]: finite, 0 < k <= s
  /// (and <= 1e50). Throws InvalidParameter naming both when k > s.
  CoulombFriction(double static_coefficient, double kinetic);
  /// Direction-dependent kinetic coefficients: k_+ for forward slip (x' > 0), k_- for backward.
  /// Needs 0 < k_+, k_- <= s. Throws InvalidParameter naming the offending pair.
  CoulombFriction(double static_coefficient, double kinetic_forward, double kinetic_backward);

  double static_coefficient() const noexcept { return static_; }
  double kinetic_forward() const noexcept { return forward_; }
  double kinetic_backward() const noexcept { return backward_; }
  /// k_sigma for slip direction sigma (> 0: forward, < 0: backward).
  double kinetic(int sigma) const noexcept { return sigma > 0 ? forward_ : backward_; }
  /// True for the paper's law (all coefficients 1).
  bool is_unit() const noexcept { return static_ == 1.0 && forward_ == 1.0 && backward_ == 1.0; }
  /// "static 1.2, kinetic 1" or "static 1.2, kinetic forward 1, backward 0.8".
  std::string describe() const;

  friend bool operator==(const CoulombFriction&, const CoulombFriction&) = default;

 private:
  double static_ = 1.0, forward_ = 1.0, backward_ = 1.0;
};

}  // namespace selfalign
