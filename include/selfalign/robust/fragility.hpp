#pragma once
/// \file fragility.hpp
/// How fragile a designed process is to its friction data: the margins by which mu and c_mu
/// may err before the part no longer moves or no longer stops (closed form), and how far the
/// end position moves when mu, c_mu or the static/kinetic ratio mu_static/mu is off by a given
/// relative amount (exact stopping runs). `selfalign design` prints its warnings beside every
/// nominal design, and a plain one when the design assumed mu_static = mu.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign {

struct Fragility {
  double level = 0.05;  ///< the relative error of mu and c_mu examined [-]
  /// 1 - max(y2'', y3'') / (mu_static c_mu g): the relative drop of mu_static c_mu after which
  /// no position holds the part for good (eq. 40) and it never stops [-]; <= 0: already so.
  double stop_margin = 0;
  /// y2'' / (mu_static g) - 1: the relative rise of mu_static after which the table cannot make
  /// the part slip forward on the smooth region [-].
  double motion_margin = 0;
  double end_nominal = std::numeric_limits<double>::quiet_NaN();  ///< [m]
  /// End positions [m] with mu, then c_mu, at (1 - level) and (1 + level) times nominal; NaN
  /// where that run does not stop.
  std::array<double, 2> end_mu{}, end_c_mu{};
  /// End positions [m] with the static ratio s = mu_static/mu at max(1, (1 - level) s) and
  /// (1 + level) s (a static coefficient is never below the kinetic one); NaN where that run
  /// does not stop.
  std::array<double, 2> end_static{};
  /// The largest |end - end_nominal| over those runs [m]; +inf when one does not stop.
  double end_shift_mu = 0, end_shift_c_mu = 0, end_shift_static = 0;
  /// The request left mu_static unset or equal to mu: the design assumed that the part sticks
  /// no harder than it slides.
  bool assumes_equal_static = false;
  /// One line per finding; empty when the design is not fragile at this level.
  std::vector<std::string> warnings;
};

/// Evaluates `process` for the request's nominal inputs at relative error `level` in (0, 1):
/// mu, c_mu and the static ratio (one at a time).
/// The tolerance compared with the end shifts is request.tolerance (accumulation designs,
/// tolerance 0: any shift above 1e-3 x width is reported).
Fragility fragility(const DesignRequest& request, const Process& process, double level = 0.05,
                    int max_periods = 3000);

}  // namespace selfalign
