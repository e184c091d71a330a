#include "selfalign/friction/friction_map.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
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
    pieces_[i] = p;
  }
  count_ = pieces.size();
}

std::size_t PiecewiseAffineFriction::piece_index(double x) const noexcept {
  std::size_t i = 0;
  while (i + 1 < count_ && x >= pieces_[i].end) ++i;
  return i;
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

TwoRegionFriction::TwoRegionFriction(double x_mu, double width, double c_mu)
    : x_mu_(require_finite("x_mu", x_mu)),
      width_(require_positive("width", width)),
      c_mu_(require_greater("c_mu", c_mu, 1.0)),
      affine_(two_region_pieces(x_mu_, width_, c_mu_)) {}

double TwoRegionFriction::bound(double x) const {
  const double z = std::min(std::max(x - x_mu_, 0.0), width_);  // eq. (8)
  return 1.0 + (c_mu_ - 1.0) / width_ * z;                      // eqs. (7), (9)
}

}  // namespace selfalign
