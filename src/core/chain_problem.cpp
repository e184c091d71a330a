#include "selfalign/core/chain_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace selfalign::core {

namespace {

using Block = ChainBlock;

// The minimiser of sum m_i ((y - u_i)^2 / 2 + f_i y+ + b_i y-) with all kinks at y = 0: the
// block's soft threshold. One part: its closed form term for term (the 1-D projection).
double soft_threshold(const Block& b, std::span<const ChainPart> parts) {
  if (b.end - b.begin == 1) {
    const ChainPart& p = parts[static_cast<std::size_t>(b.begin)];
    if (p.target > p.forward) return p.target - p.forward;
    if (p.target < -p.backward) return p.target + p.backward;
    return 0.0;
  }
  if (b.mu > b.mf) return (b.mu - b.mf) / b.mass;
  if (b.mu < -b.mb) return (b.mu + b.mb) / b.mass;
  return 0.0;
}

// The minimiser in w of sum m_i ((w + C_i - u_i)^2 / 2 + f_i (w + C_i)+ + b_i (w + C_i)-)
// when the kinks -C_i differ: its derivative
//   g(w) = M w - (sum m u - sum m C) + sum_{kink < w} m f - sum_{kink > w} m b + [at a kink]
// increases; scan the sorted kinks for the interval or kink where 0 is in g's subdifferential.
double scanned_minimiser(const Block& b, std::span<const ChainPart> parts,
                         std::span<const double> shift, std::vector<double>& kinks) {
  kinks.clear();
  for (int i = b.begin; i < b.end; ++i) kinks.push_back(-shift[static_cast<std::size_t>(i)]);
  std::sort(kinks.begin(), kinks.end());
  kinks.erase(std::unique(kinks.begin(), kinks.end()), kinks.end());
  const double s = b.mu - b.mc;
  double below_f = 0;      // sum m f over kinks below the current interval
  double above_b = b.mb;   // sum m b over kinks above it
  for (std::size_t j = 0; j <= kinks.size(); ++j) {
    // the open interval (kinks[j-1], kinks[j]): g linear
    const double w = (s + above_b - below_f) / b.mass;
    const bool above_lo = j == 0 || w > kinks[j - 1];
    const bool below_hi = j == kinks.size() || w < kinks[j];
    if (above_lo && below_hi) return w;
    if (j == kinks.size()) break;
    // the kink kinks[j]: the parts whose kink it is switch from -b to +f
    double at_f = 0, at_b = 0;
    for (int i = b.begin; i < b.end; ++i)
      if (-shift[static_cast<std::size_t>(i)] == kinks[j]) {
        const ChainPart& p = parts[static_cast<std::size_t>(i)];
        at_f += p.mass * p.forward;
        at_b += p.mass * p.backward;
      }
    const double k = kinks[j];
    const double g_lo = b.mass * k - s + below_f - above_b;  // g just below the kink
    const double g_hi = g_lo + at_f + at_b;                   // g just above it
    if (g_lo <= 0 && g_hi >= 0) return k;
    below_f += at_f;
    above_b -= at_b;
  }
  // unreachable for finite data (g runs from -inf to +inf); the last interval's value
  return (s + 0.0 - below_f) / b.mass;
}

void settle(Block& b, std::span<const ChainPart> parts, std::span<const double> shift,
            std::vector<double>& kinks) {
  if (b.uniform) {
    b.y = soft_threshold(b, parts);
    b.w = b.y - b.shift;
  } else {
    b.w = scanned_minimiser(b, parts, shift, kinks);
  }
}

}  // namespace

void solve_chain(std::span<const ChainPart> parts, std::span<const double> c,
                 std::span<double> v, ChainWorkspace& work) {
  const std::size_t n = parts.size();
  if (n == 0) return;
  // shifts C_i = c_0 + ... + c_{i-1}: the constraints become w_0 <= w_1 <= ... (w = v - C)
  work.shift.resize(n);
  work.shift[0] = 0;
  for (std::size_t i = 1; i < n; ++i) work.shift[i] = work.shift[i - 1] + c[i - 1];
  // pool adjacent violators; the stack of blocks lives in the workspace's vectors
  std::vector<Block>& stack = work.blocks;
  stack.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const ChainPart& p = parts[i];
    Block b;
    b.begin = static_cast<int>(i);
    b.end = b.begin + 1;
    b.mass = p.mass;
    b.mu = p.mass * p.target;
    b.mc = p.mass * work.shift[i];
    b.mf = p.mass * p.forward;
    b.mb = p.mass * p.backward;
    b.shift = work.shift[i];
    settle(b, parts, work.shift, work.kinks);
    stack.push_back(b);
    while (stack.size() >= 2 && stack[stack.size() - 2].w > stack.back().w) {
      const Block top = stack.back();
      stack.pop_back();
      Block& m = stack.back();
      m.end = top.end;
      m.mass += top.mass;
      m.mu += top.mu;
      m.mc += top.mc;
      m.mf += top.mf;
      m.mb += top.mb;
      m.uniform = m.uniform && top.uniform && m.shift == top.shift;
      settle(m, parts, work.shift, work.kinks);
    }
  }
  for (const Block& b : stack)
    for (int i = b.begin; i < b.end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      v[k] = b.uniform ? b.y : b.w + work.shift[k];
    }
}

std::vector<double> solve_chain(std::span<const ChainPart> parts, std::span<const double> c) {
  std::vector<double> v(parts.size());
  ChainWorkspace work;
  solve_chain(parts, c, v, work);
  return v;
}

int solve_chain_static_kinetic(std::span<ChainPart> parts, std::span<const ChainFriction> friction,
                               std::span<const double> c, std::span<double> v,
                               ChainWorkspace& work) {
  const std::size_t n = parts.size();
  // part i has broken loose forward / backward: it then pulls with its kinetic bound that way
  auto& fwd = work.broken_forward;
  auto& bwd = work.broken_backward;
  fwd.assign(n, 0);
  bwd.assign(n, 0);
  int solves = 0;
  for (;;) {
    for (std::size_t i = 0; i < n; ++i) {
      const ChainFriction& f = friction[i];
      const bool kinetic_forward = f.sliding_on > 0 || fwd[i];
      const bool kinetic_backward = f.sliding_on < 0 || bwd[i];
      parts[i].forward = kinetic_forward ? f.forward : f.hold;
      parts[i].backward = kinetic_backward ? f.backward : f.hold;
    }
    solve_chain(parts, c, v, work);
    ++solves;
    bool more = false;
    for (std::size_t i = 0; i < n; ++i) {
      const ChainFriction& f = friction[i];
      if (v[i] > 0 && f.sliding_on <= 0 && !fwd[i]) fwd[i] = 1, more = true;
      if (v[i] < 0 && f.sliding_on >= 0 && !bwd[i]) bwd[i] = 1, more = true;
    }
    if (!more) return solves;
  }
}

}  // namespace selfalign::core
