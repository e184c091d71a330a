#pragma once
// Test helper: a profile with its closed forms hidden (no piecewise_polynomial(), no smooth()),
// so that PeriodMap, steady_state and simulate can only take it by time-stepping: the second
// method the exact solvers are checked against.
#include <string>

#include "selfalign/profiles/table_profile.hpp"

namespace selfalign::testing_support {

class Opaque final : public TableProfile {
 public:
  explicit Opaque(const TableProfile& p) : p_(p) {}
  double period() const override { return p_.period(); }
  TableState state(double t) const override { return p_.state(t); }
  double velocity(double t) const override { return p_.velocity(t); }
  double peak_acceleration() const override { return p_.peak_acceleration(); }
  double stroke() const override { return p_.stroke(); }
  std::string kind() const override { return "opaque"; }

 private:
  const TableProfile& p_;
};

}  // namespace selfalign::testing_support
