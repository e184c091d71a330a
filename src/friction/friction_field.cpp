#include "selfalign/friction/friction_field.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <string_view>

#include "../io/csv_fields.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"

namespace selfalign {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Breakpoints of the averaged map closer than this many ulps are merged.
constexpr double kMergeUlps = 4.0;

void check_position(const std::string& name, double p) {
  if (!(std::abs(p) <= kMaxMagnitude))
    throw InvalidParameter(name, p, "must be a finite number with |value| <= 1e50");
}

void check_level(const std::string& name, double level) {
  if (level < 0) throw InvalidParameter(name, level, "must be >= 0");
  if (!(level <= kMaxMagnitude))
    throw InvalidParameter(name, level, "must be a finite number in [0, 1e50]");
}

// The field on the stretch [a.position, b.position): straight from a.right to b.left.
double on_stretch(const FieldNode& a, const FieldNode& b, double xi) noexcept {
  if (a.right == b.left) return a.right;
  const double t = (xi - a.position) / (b.position - a.position);
  return std::max(0.0, a.right + (b.left - a.right) * t);
}


}  // namespace

FieldInterpolation parse_field_interpolation(const std::string& text) {
  if (text == "steps") return FieldInterpolation::steps;
  if (text == "linear") return FieldInterpolation::linear;
  throw InvalidParameter("interpolation", text, "must be one of: steps, linear");
}

// ---------------------------------------------------------------------------------------------
// FrictionField

FrictionField::FrictionField(std::vector<FieldNode> nodes) : nodes_(std::move(nodes)) {
  if (nodes_.empty())
    throw InvalidParameter("friction field nodes", 0.0, "need at least 1 node");
  bool positive = false;
  min_level_ = kInf;
  max_level_ = 0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const FieldNode& n = nodes_[i];
    const std::string name = "friction field nodes[" + std::to_string(i) + "]";
    check_position(name + " position", n.position);
    if (i > 0 && !(n.position > nodes_[i - 1].position))
      throw InvalidParameter(name + " position", n.position,
                             "must be > the previous position " +
                                 format_number(nodes_[i - 1].position));
    check_level(name + " left", n.left);
    check_level(name + " right", n.right);
    positive = positive || n.left > 0 || n.right > 0;
    min_level_ = std::min({min_level_, n.left, n.right});
    max_level_ = std::max({max_level_, n.left, n.right});
    if (i > 0 && nodes_[i - 1].right != n.left) piecewise_constant_ = false;
  }
  if (!positive) throw InvalidParameter("friction field levels", "all 0", "must be > 0 somewhere");
}

FrictionField FrictionField::steps(const std::vector<double>& positions,
                                   const std::vector<double>& levels) {
  if (levels.size() != positions.size() + 1)
    throw InvalidParameter("friction field levels", static_cast<double>(levels.size()) ,
                           "must number the positions + 1 = " +
                               std::to_string(positions.size() + 1) +
                               " (one level before the first position and one after each)");
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const std::string name = "friction field positions[" + std::to_string(i) + "]";
    check_position(name, positions[i]);
    if (i > 0 && !(positions[i] > positions[i - 1]))
      throw InvalidParameter(name, positions[i],
                             "must be > positions[" + std::to_string(i - 1) + "] = " +
                                 format_number(positions[i - 1]));
  }
  for (std::size_t i = 0; i < levels.size(); ++i)
    check_level("friction field levels[" + std::to_string(i) + "]", levels[i]);
  std::vector<FieldNode> nodes;
  if (positions.empty()) nodes.push_back({0.0, levels[0], levels[0]});  // a uniform field
  for (std::size_t i = 0; i < positions.size(); ++i)
    nodes.push_back({positions[i], levels[i], levels[i + 1]});
  return FrictionField(std::move(nodes));
}

FrictionField FrictionField::ramps(const std::vector<double>& positions,
                                   const std::vector<double>& levels) {
  if (positions.empty())
    throw InvalidParameter("friction field positions", 0.0, "need at least 1 position");
  if (levels.size() != positions.size())
    throw InvalidParameter("friction field levels", static_cast<double>(levels.size()),
                           "must number the positions = " + std::to_string(positions.size()));
  std::vector<FieldNode> nodes;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const std::string name = "friction field positions[" + std::to_string(i) + "]";
    check_position(name, positions[i]);
    if (i > 0 && !(positions[i] > positions[i - 1]))
      throw InvalidParameter(name, positions[i],
                             "must be > positions[" + std::to_string(i - 1) + "] = " +
                                 format_number(positions[i - 1]));
    check_level("friction field levels[" + std::to_string(i) + "]", levels[i]);
    nodes.push_back({positions[i], levels[i], levels[i]});
  }
  return FrictionField(std::move(nodes));
}

FrictionField FrictionField::from_csv(const std::string& path, const std::string& interpolation) {
  return from_csv(path, parse_field_interpolation(interpolation));
}

FrictionField FrictionField::from_csv(const std::string& path, FieldInterpolation interpolation) {
  constexpr std::uintmax_t kMaxFieldBytes = 256u << 20;  // ~10 million rows
  require_input_file("friction field", path, "the friction field", kMaxFieldBytes);
  std::ifstream in(path);
  if (!in) throw InvalidParameter("friction field", path, "must be a readable CSV file");
  std::vector<double> positions, levels;
  auto where = [&](int number) { return "friction field " + path + ":" + std::to_string(number); };
  detail::read_csv_pairs(
      in,
      [&](int number, double p, double level) {
        check_position(where(number) + " position", p);
        if (!positions.empty() && !(p > positions.back()))
          throw InvalidParameter(where(number) + " position", p,
                                 "must be > the previous position " +
                                     format_number(positions.back()) +
                                     " (positions strictly increasing)");
        check_level(where(number) + " level", level);
        positions.push_back(p);
        levels.push_back(level);
      },
      [&](int number, const std::string& line, bool range) {
        throw InvalidParameter(where(number), "'" + line + "'",
                               range ? "holds a number beyond the range of a double"
                                     : "must be two numbers 'position,level'");
      });
  if (positions.empty())
    throw InvalidParameter("friction field", path, "must hold at least one row 'position,level'");
  if (std::none_of(levels.begin(), levels.end(), [](double l) { return l > 0; }))
    throw InvalidParameter("friction field " + path + " levels", "all 0",
                           "must be > 0 somewhere");
  return samples(positions, levels, interpolation);
}

FrictionField FrictionField::samples(const std::vector<double>& positions,
                                     const std::vector<double>& levels,
                                     FieldInterpolation interpolation) {
  if (positions.empty() || positions.size() != levels.size())
    throw InvalidParameter("friction field levels", static_cast<double>(levels.size()),
                           "must give one level per position (" +
                               std::to_string(positions.size()) + " positions), at least one");
  for (std::size_t i = 1; i < positions.size(); ++i)  // steps drops the first position
    if (!(positions[i] > positions[i - 1]))
      throw InvalidParameter("friction field positions", positions[i],
                             "must be > the previous position " +
                                 format_number(positions[i - 1]) + " (strictly increasing)");
  if (interpolation == FieldInterpolation::linear) return ramps(positions, levels);
  // Each sample's level holds from its position to the next one (and before the first).
  return steps(std::vector<double>(positions.begin() + 1, positions.end()), levels);
}

FrictionField FrictionField::in_units_of(double length) const {
  std::vector<FieldNode> nodes = nodes_;
  for (FieldNode& n : nodes) n.position /= length;  // as Scales::length_from_si
  return FrictionField(std::move(nodes));
}

double FrictionField::operator()(double xi) const noexcept {
  if (!(xi >= nodes_.front().position)) return nodes_.front().left;
  const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), xi,
                                   [](double v, const FieldNode& n) { return v < n.position; });
  const std::size_t k = static_cast<std::size_t>(it - nodes_.begin()) - 1;  // position <= xi
  if (k + 1 == nodes_.size()) return nodes_[k].right;
  return on_stretch(nodes_[k], nodes_[k + 1], xi);
}

double FrictionField::integral(double a, double b) const noexcept {
  if (!(a < b)) return 0.0;
  const std::size_t n = nodes_.size();
  double sum = 0.0, x = a;
  if (x < nodes_.front().position) {  // the constant part before the first node
    const double e = std::min(b, nodes_.front().position);
    sum += nodes_.front().left * (e - x);
    x = e;
    if (x >= b) return sum;
  }
  auto it = std::upper_bound(nodes_.begin(), nodes_.end(), x,
                             [](double v, const FieldNode& nd) { return v < nd.position; });
  for (std::size_t k = static_cast<std::size_t>(it - nodes_.begin()) - 1; x < b; ++k) {
    if (k + 1 == n) return sum + nodes_[k].right * (b - x);  // the constant tail
    const FieldNode &lo = nodes_[k], &hi = nodes_[k + 1];
    const double e = std::min(b, hi.position);
    if (lo.right == hi.left) {
      sum += lo.right * (e - x);
    } else {
      const double fe = e == hi.position ? hi.left : on_stretch(lo, hi, e);
      sum += 0.5 * (on_stretch(lo, hi, x) + fe) * (e - x);  // trapezoid: exact on a line
    }
    x = e;
  }
  return sum;
}

// ---------------------------------------------------------------------------------------------
// FieldFriction

namespace {

// Keeps a piece's value at its end >= 0 where rounding of a slope to a zero level made it a
// hair negative (PiecewiseAffineFriction refuses negative bounds).
void push_piece(std::vector<AffinePiece>& pieces, AffinePiece p) {
  p.bound_at_begin = std::max(p.bound_at_begin, 0.0);
  if (std::isfinite(p.end))
    for (int i = 0; i < 64 && p.slope < 0 && p.bound(p.end) < 0; ++i)
      p.slope = std::nextafter(p.slope, 0.0);
  // Flat neighbours at the same level are one piece (a uniform map keeps one piece, which the
  // exact solver's fast path takes).
  if (!pieces.empty() && pieces.back().slope == 0 && p.slope == 0 &&
      pieces.back().bound_at_begin == p.bound_at_begin) {
    pieces.back().end = p.end;
    return;
  }
  pieces.push_back(p);
}

[[noreturn]] void throw_too_steep(double width, double slope, double where) {
  throw InvalidParameter("footprint width", width,
                         "the averaged friction must be resolvable: its slope reaches " +
                             format_number(slope) + " near x = " + format_number(where) +
                             ", need |slope| <= 1e12 (widen the footprint or soften the field)");
}

}  // namespace

FieldFriction::FieldFriction(FrictionField field, Footprint footprint)
    : field_(std::move(field)), footprint_(footprint) {
  const auto nodes = field_.nodes();
  const std::size_t n = nodes.size();
  std::vector<AffinePiece> pieces;

  if (std::holds_alternative<PointFootprint>(footprint_)) {
    // m = field: its own pieces. Ramps must be resolvable; jumps are exact piece boundaries.
    pieces.push_back({-kInf, nodes[0].position, nodes[0].left, 0.0});
    for (std::size_t k = 0; k < n; ++k) {
      if (k + 1 == n) {
        push_piece(pieces, {nodes[k].position, kInf, nodes[k].right, 0.0});
        break;
      }
      const FieldNode &a = nodes[k], &b = nodes[k + 1];
      double slope = 0.0;
      if (a.right != b.left) {
        const double len = b.position - a.position;
        slope = (b.left - a.right) / len;
        const std::string ramp = "[" + format_number(a.position) + ", " +
                                 format_number(b.position) + "]";
        if (!(std::abs(slope) <= kMaxFrictionSlope))
          throw InvalidParameter("friction field ramp", ramp,
                                 "its slope " + format_number(slope) +
                                     " must be <= 1e12 in magnitude for the friction to be "
                                     "resolvable under a point footprint");
        const double scale = std::max(std::abs(a.position), std::abs(b.position));
        if (len < kMinRelativeStretch * scale)
          throw InvalidParameter("friction field ramp", ramp,
                                 "must be >= 1e-9 |position| = " +
                                     format_number(kMinRelativeStretch * scale) +
                                     " wide to be resolvable");
      }
      push_piece(pieces, {a.position, b.position, a.right, slope});
    }
    affine_.emplace(pieces);
    return;
  }

  // Uniform footprint over [x - w, x].
  const double w =
      require_positive_moderate("footprint width", std::get<UniformFootprint>(footprint_).width);
  width_ = w;
  const double reach = std::max(std::abs(nodes.front().position), std::abs(nodes.back().position));
  if (w < kMinRelativeStretch * reach)
    throw InvalidParameter("footprint width", w,
                           "must be >= 1e-9 max |position| = " +
                               format_number(kMinRelativeStretch * reach) +
                               " for the friction transitions to be resolvable");
  std::vector<double> positions(n), ends(n);
  for (std::size_t k = 0; k < n; ++k) {
    positions[k] = nodes[k].position;
    ends[k] = nodes[k].position + w;  // sorted: rounding is monotone
  }
  // m can change slope only at the positions and the positions + w.
  std::vector<double> breaks;
  breaks.reserve(2 * n);
  std::merge(positions.begin(), positions.end(), ends.begin(), ends.end(),
             std::back_inserter(breaks));
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  if (!field_.piecewise_constant()) {
    // Ramps: m is piecewise quadratic, no affine form. Check its slope m' = (f(x) - f(x-w))/w,
    // linear between breakpoints: extrapolated to each stretch's ends from its quarter points.
    auto diff = [&](double y) { return field_(y) - field_(y - w); };
    for (std::size_t j = 0; j + 1 < breaks.size(); ++j) {
      const double len = breaks[j + 1] - breaks[j];
      const double q1 = breaks[j] + 0.25 * len, q3 = breaks[j] + 0.75 * len;
      const double d1 = diff(q1), d3 = diff(q3);
      const double worst = std::max(std::abs(d1 - 0.5 * (d3 - d1)), std::abs(d3 + 0.5 * (d3 - d1)));
      if (!(worst / w <= kMaxFrictionSlope)) throw_too_steep(w, worst / w, breaks[j]);
    }
    return;
  }

  // Steps: step k adds (right_k - left_k)/w (x - p_k) while p_k < x < p_k + w (eq. 9 per step).
  window_ends_ = ends;
  jump_per_width_.resize(n);
  for (std::size_t k = 0; k < n; ++k) jump_per_width_[k] = (nodes[k].right - nodes[k].left) / w;

  // A piece a few ulps wide would stall the exact solver: merge such breakpoints (keep the later
  // one, so that the last breakpoint, after which m is constant, stays).
  std::vector<double> kept;
  for (std::size_t j = 0; j < breaks.size(); ++j) {
    if (j + 1 < breaks.size() &&
        breaks[j + 1] - breaks[j] <=
            kMergeUlps * kEps * std::max(std::abs(breaks[j]), std::abs(breaks[j + 1])))
      continue;
    kept.push_back(breaks[j]);
  }
  pieces.push_back({-kInf, kept.front(), nodes.front().left, 0.0});
  for (std::size_t j = 0; j < kept.size(); ++j) {
    const double b = kept[j];
    const double end = j + 1 < kept.size() ? kept[j + 1] : kInf;
    // Active steps on (b, end): p_k <= b < p_k + w; contiguous, lo..hi. Their jumps telescope.
    const std::size_t lo =
        static_cast<std::size_t>(std::upper_bound(ends.begin(), ends.end(), b) - ends.begin());
    const std::size_t hi_end =
        static_cast<std::size_t>(std::upper_bound(positions.begin(), positions.end(), b) -
                                 positions.begin());  // one past the last p_k <= b
    double slope = 0.0;
    if (lo < hi_end) slope = (nodes[hi_end - 1].right - nodes[lo].left) / w;
    if (!(std::abs(slope) <= kMaxFrictionSlope)) throw_too_steep(w, slope, b);
    if (std::isinf(end)) slope = 0.0;  // (it is: every step is fully under the window)
    push_piece(pieces, {b, end, window_average_of_steps(b), slope});
  }
  affine_.emplace(pieces);
}

double FieldFriction::window_average_of_steps(double x) const noexcept {
  const auto nodes = field_.nodes();
  // Steps fully under the window (p_k + w <= x) are in the base level; the rest ramp in.
  const std::size_t lo = static_cast<std::size_t>(
      std::upper_bound(window_ends_.begin(), window_ends_.end(), x) - window_ends_.begin());
  const double base = lo == 0 ? nodes.front().left : nodes[lo - 1].right;
  double sum = 0.0;
  for (std::size_t k = lo; k < nodes.size() && nodes[k].position < x; ++k)
    sum += jump_per_width_[k] * (x - nodes[k].position);
  return std::max(0.0, base + sum);
}

double FieldFriction::bound(double x) const {
  if (width_ == 0.0) return field_(x);  // point footprint
  if (!jump_per_width_.empty()) return window_average_of_steps(x);
  return std::max(0.0, field_.integral(x - width_, x) / width_);
}

}  // namespace selfalign
