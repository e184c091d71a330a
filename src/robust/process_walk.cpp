#include "selfalign/robust/process_walk.hpp"

#include <algorithm>

#include "selfalign/friction/friction_field.hpp"

namespace selfalign {

ProcessWalk::ProcessWalk(const DesignRequest& q, const Process& p, const InputValues& v,
                         int max_periods)
    : model_(q, p, v), offset_(v[4]), max_periods_(max_periods) {
  smooth_ = std::make_unique<PeriodMap>(*model_.profile, model_.law);
  const ObjectState rest{0, 0, 0};
  run_.emplace(smooth_->start(rest));
  looks_.push_back(rest);
  reach_.push_back(rest.x);
}

void ProcessWalk::walk_to(double x) {
  // Without arcs (no exact solver for this law) the walk is not observed: at() runs from rest.
  if (!smooth_->has_arcs()) return;
  const double period = model_.profile->period();
  while (reach_.back() < x && !stalled_ && periods() < max_periods_) {
    Reach reach(reach_.back());
    const ObjectState s =
        run_->advance_to(static_cast<double>(looks_.size()) * period, &reach);
    stalled_ = s.x == looks_.back().x && s.xd == looks_.back().xd;
    looks_.push_back(s);
    reach_.push_back(std::max(reach.x, s.x));
  }
}

ProcessOutcome ProcessWalk::at(double x_mu) {
  const double start = model_.scales.length_from_si(x_mu + offset_);
  walk_to(start);
  // The last look before the part first reaches `start` (the rest at t = 0 if it starts there).
  const auto first_reached = std::lower_bound(reach_.begin(), reach_.end(), start);
  const std::size_t k =
      first_reached == reach_.begin() ? 0 : static_cast<std::size_t>(first_reached - reach_.begin()) - 1;
  const int budget = max_periods_ - static_cast<int>(k);
  if (budget < 1) return {};  // the budget ended on the smooth region: never entered
  const FieldFriction friction = two_region_friction(start, 1.0, model_.c_mu);
  return model_.outcome(
      stopping_run(*model_.profile, friction, model_.law, looks_[k], ProcessModel::stopping(budget)));
}

}  // namespace selfalign
