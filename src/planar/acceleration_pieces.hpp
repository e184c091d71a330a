#pragma once
// The table's piecewise-constant accelerations along its two directions, segment by segment:
// the windows of the planar event-driven solvers (the exact point solver, the patch
// integrator), in which the table acceleration is one constant vector.

#include <cmath>
#include <cstddef>

#include "selfalign/error.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign::detail {

// The acceleration of one profile on the segment holding t, and the next switch > t.
struct Piece {
  double accel = 0;
  double next = kInf;
};

inline Piece piece_at(const PiecewisePolynomialProfile* p, double t) {
  if (!p) return {};
  const auto segs = p->segments();
  const double P = p->period();
  double n = std::floor(t / P);
  std::size_t i = 0;
  const double tp = t - n * P;
  while (i + 1 < segs.size() && segs[i + 1].begin <= tp) ++i;
  const auto end_of = [&](std::size_t j) {
    return j + 1 < segs.size() ? n * P + segs[j + 1].begin : (n + 1) * P;
  };
  while (!(end_of(i) > t)) {  // rounding put t at or past the segment's end: the next one
    if (++i == segs.size()) i = 0, n += 1;
  }
  return {segs[i].accel, end_of(i)};
}

// The profile as piecewise-constant acceleration segments (null for no profile); throws
// InvalidParameter naming `name` for any other profile, saying which `solver` needs it.
inline const PiecewisePolynomialProfile* constant_pieces(const TableProfile* p, const char* name,
                                                         const char* solver) {
  if (!p) return nullptr;
  const PiecewisePolynomialProfile* pp = p->piecewise_polynomial();
  bool constant = pp != nullptr;
  if (pp)
    for (const AccelerationSegment& s : pp->segments()) constant = constant && s.jerk == 0;
  if (!constant)
    throw InvalidParameter(name, p->kind(),
                           std::string("must have piecewise-constant acceleration for ") + solver);
  return pp;
}

// The table acceleration A (world axes) on the window holding t, and the window's end (the
// next switch of either direction, at most t_end).
struct AccelerationWindow {
  double ax = 0, ay = 0;
  double end = kInf;
};

inline AccelerationWindow acceleration_window(const PlanarTableMotion& motion,
                                              const PiecewisePolynomialProfile* p1,
                                              const PiecewisePolynomialProfile* p2, double t,
                                              double t_end) {
  const Piece a = piece_at(p1, t), b = piece_at(p2, t);
  return {a.accel * motion.e1_x + b.accel * motion.e2_x,
          a.accel * motion.e1_y + b.accel * motion.e2_y, std::min({a.next, b.next, t_end})};
}

}  // namespace selfalign::detail
