#include "selfalign/friction/friction_map.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {
}

PiecewiseAffineFriction::PiecewiseAffineFriction(std::span<const AffinePiece> pieces) {
  if (pieces.empty() || pieces.size() > kMaxPieces)
    throw InvalidParameter("friction pieces", static_cast<double>(pieces.size()),
                           "must be between 1 and " + std::to_string(kMaxPieces) + " pieces");
  if (pieces.front().begin != -kInf || pieces.back().end != kInf)
    throw InvalidParameter("friction pieces", "bounded",
                           "must cover the real line (-inf, inf)");
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const AffinePiece& p = pieces[i];
    if (!(p.begin < p.end))
      throw InvalidParameter("friction piece " + std::to_string(i) + " begin", p.begin,
                             "must be < its end " + format_number(p.end));
    if (i + 1 < pieces.size() && p.end != pieces[i + 1].begin)
      throw InvalidParameter("friction piece " + std::to_string(i + 1) + " begin",
                             pieces[i + 1].begin, "must equal the previous piece's end");
    require_finite("friction piece bound", p.bound_at_begin);
    require_finite("friction piece slope", p.slope);
    if (std::isinf(p.begin) || std::isinf(p.end)) {
      if (p.slope != 0.0)
        throw InvalidParameter("friction piece slope", p.slope, "must be 0 on unbounded pieces");
    }
    const double at_end = std::isinf(p.end) ? p.bound_at_begin : p.bound(p.end);
    if (p.bound_at_begin < 0.0 || at_end < 0.0)
      throw InvalidParameter("friction bound", std::min(p.bound_at_begin, at_end), "must be >= 0");
  }
  pieces_.assign(pieces.begin(), pieces.end());
}

std::size_t PiecewiseAffineFriction::piece_index(double x) const noexcept {
  // The first piece whose end exceeds x; the last piece (end +inf) when none does. A NaN x
  // gives piece 0, as the former linear scan did.
  if (!(x >= pieces_.front().end)) return 0;  // also the single-piece case (end = +inf)
  const auto last = pieces_.end() - 1;
  const auto it = std::upper_bound(pieces_.begin() + 1, last, x,
                                   [](double v, const AffinePiece& p) { return v < p.end; });
  return static_cast<std::size_t>(it - pieces_.begin());
}

namespace {
PiecewiseAffineFriction uniform_pieces(double level) {
  const AffinePiece p{-kInf, kInf, level, 0.0};
  return PiecewiseAffineFriction({&p, 1});
}
PiecewiseAffineFriction two_region_pieces(double x_mu, double w, double c_mu) {
  const AffinePiece p[3] = {{-kInf, x_mu, 1.0, 0.0},
                            {x_mu, x_mu + w, 1.0, (c_mu - 1.0) / w},
                            {x_mu + w, kInf, c_mu, 0.0}};
  return PiecewiseAffineFriction(p);
}
}  // namespace

UniformFriction::UniformFriction(double level)
    : level_(require_positive("friction level", level)), affine_(uniform_pieces(level)) {}

namespace {
// The transition region must be resolvable in double precision, or the exact solver's harmonic
// arcs there (frequency sqrt(b1), amplitude ~ y''/b1) shrink below the rounding of t and x and
// the object chatters through ~1e8 zero-progress arcs a period (issue 9, D09, D12).
//  - b1 = (c_mu - 1)/w <= 1e12: arcs last >= 1e-6 periods and their amplitude is >= 1e-12 (for
//    |y''| ~ 1), four orders above the rounding of positions of order 1;
//  - w >= 1e-9 |x_mu|: the transition spans >= 4e6 ulps of x_mu.
constexpr double kMaxTransitionStiffness = 1e12;  // largest b1 [1/-]
constexpr double kMinRelativeWidth = 1e-9;        // smallest w / |x_mu| [-]

double resolvable_width(double x_mu, double width, double c_mu) {
  if (!std::isfinite(x_mu + width))
    throw InvalidParameter("width", width,
                           "x_mu + width must be finite (x_mu = " + format_number(x_mu) + ")");
  if (width < kMinRelativeWidth * std::abs(x_mu))
    throw InvalidParameter("width", width,
                           "must be >= 1e-9 |x_mu| = " +
                               format_number(kMinRelativeWidth * std::abs(x_mu)) +
                               " for the transition region to be resolvable");
  if (!((c_mu - 1.0) / width <= kMaxTransitionStiffness))
    throw InvalidParameter("c_mu, width", format_number(c_mu) + ", " + format_number(width),
                           "the friction transition must be resolvable: need (c_mu - 1)/width "
                           "<= 1e12, i.e. c_mu <= " +
                               format_number(1.0 + kMaxTransitionStiffness * width) +
                               " for this width");
  return width;
}
}  // namespace

TwoRegionFriction::TwoRegionFriction(double x_mu, double width, double c_mu)
    : x_mu_(require_finite("x_mu", x_mu)),
      width_(require_positive("width", width)),
      c_mu_(require_greater("c_mu", c_mu, 1.0)),
      affine_(two_region_pieces(x_mu_, resolvable_width(x_mu_, width_, c_mu_), c_mu_)) {}

double TwoRegionFriction::bound(double x) const {
  const double z = std::min(std::max(x - x_mu_, 0.0), width_);  // eq. (8)
  return 1.0 + (c_mu_ - 1.0) / width_ * z;                      // eqs. (7), (9)
}

}  // namespace selfalign
