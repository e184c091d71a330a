#include "selfalign/analysis/motion_case.hpp"

#include <algorithm>

namespace selfalign {

std::string describe(StickSlipCase c) {
  switch (c) {
    case StickSlipCase::non_physical: return "non-physical profile";
    case StickSlipCase::stick_slip_forward: return "stick-slip with x' >= 0";
    case StickSlipCase::stick_slip_backward: return "stick-slip with x' <= 0";
    case StickSlipCase::general_stick_slip: return "general stick-slip";
    case StickSlipCase::slip_slip: return "slip-slip";
    case StickSlipCase::pure_stick: return "pure stick";
  }
  return "unknown";
}

StickSlipCase predict_case(const ThreePhaseParameters& p) {
  return predict_case(p, solve_three_phase(p));  // validates p
}

StickSlipCase predict_case(const ThreePhaseParameters& p, const ThreePhaseSolution& r) {
  if (!r.physical) return StickSlipCase::non_physical;
  const double a = p.a2, b = p.a3;
  // Sticking needs |y''| <= 1 (Sect. 3.2); slipping starts from rest only where |y''| > 1.
  const bool forward_push = a > 1, backward_push = b > 1;
  if (!forward_push && !backward_push) return StickSlipCase::pure_stick;
  if (forward_push && !backward_push) return StickSlipCase::stick_slip_forward;
  if (!forward_push) return StickSlipCase::stick_slip_backward;
  // a, b > 1: sticking is possible only on [t0, t1] (y'' = 0). Follow the motion from rest at
  // t1 (docs/motion-cases.md): forward slip on [t1, t2], stop in [t2, t3], backward slip.
  const double T1 = r.t1, T2 = r.t2 - r.t1, T3 = r.t3 - r.t2;
  const double tau_s = (a - 1) * T2 / (1 + b);  // <= T3 always, since (a-1)T2 <= (1+b)T3
  const double back_speed = (b - 1) * (T3 - tau_s);
  return back_speed < T1 ? StickSlipCase::general_stick_slip : StickSlipCase::slip_slip;
}

void MotionCensus::on_motion(const MotionInterval& a, const Arc*) {
  if (a.t1 <= a.t0) return;
  if (a.end == ArcEnd::time_step) {
    zero_steps_ = a.direction == 0 ? zero_steps_ + 1 : 0;
    if (a.direction == 0 && zero_steps_ != 2) return;
  }
  char c = 0;
  if (a.direction == 0) ++stick, c = '0';
  else if (a.direction > 0) ++forward, c = '+';
  else ++backward, c = '-';
  if (c && (sequence.empty() || sequence.back() != c)) sequence.push_back(c);
}

std::string MotionCensus::pattern() const {
  std::string cyc = sequence;
  if (cyc.size() > 1 && cyc.front() == cyc.back()) cyc.pop_back();
  std::size_t s = cyc.find('0');  // start at a stick, else at a forward slip
  if (s == std::string::npos) s = cyc.find('+');
  if (s != std::string::npos) std::rotate(cyc.begin(), cyc.begin() + static_cast<long>(s), cyc.end());
  std::string out;
  for (char c : cyc) {
    if (!out.empty()) out += ',';
    out += c == '0' ? "stick" : c == '+' ? "forward" : "backward";
  }
  return out;
}

StickSlipCase MotionCensus::motion_case() const {
  if (forward == 0 && backward == 0) return StickSlipCase::pure_stick;
  if (stick == 0) return StickSlipCase::slip_slip;
  if (backward == 0) return StickSlipCase::stick_slip_forward;
  if (forward == 0) return StickSlipCase::stick_slip_backward;
  return StickSlipCase::general_stick_slip;
}

}  // namespace selfalign
