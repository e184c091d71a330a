#include "selfalign/friction/friction_map.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "selfalign/error.hpp"

namespace selfalign {

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
}  // namespace

UniformFriction::UniformFriction(double level)
    : level_(require_positive("friction level", level)), affine_(uniform_pieces(level)) {}

}  // namespace selfalign
