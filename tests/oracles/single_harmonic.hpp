// Oracle: steady-state average relative velocity vbar of the mass on a uniform table whose
// motion is a single harmonic, optionally plus its second harmonic (cosine phase):
//     y(t) = c0 + A1 cos(w t) + A2 cos(2 w t),   w = 2 pi / period,
// i.e. a FourierProfile(period, cos_coeffs {A1, A2}, sin_coeffs {0, 0}); c0 plays no role.
// Coulomb friction, static coefficient s >= kinetic k > 0 (paper Sect. 3.2, eq. (6)).
// Derivation and equation numbers: docs/single-harmonic-steady-state.md.
// Self-contained (no selfalign includes); checked by single_harmonic_check.py.
//
// Method (doc Sects. 3-5): every level crossing of a(t) = -y''(t) is a closed form (a quadratic
// in cos(w t), (4.2)); every slip has a closed-form velocity (3.2) whose end is the first root
// of an explicit function on a bracket where it is strictly monotone (Lemma 3.4), found by
// bisection to one ulp; every stick erases the past, so the motion after a stick is a map on the
// finitely many break-away instants (5.2) and the steady state is a cycle of that map.
// vbar = NaN when the conditions V1-V4 of the doc (Sect. 5) do not hold: no stick in the steady
// state (pure slip / reversal regime), more than one stick cycle, a borderline event.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace oracle {

struct SingleHarmonicCase {
    double period;   // Δt
    double A1;       // cos coefficient of the first harmonic
    double A2;       // cos coefficient of the second harmonic (0: pure single harmonic)
    double s;        // static friction coefficient (>= k)
    double k;        // kinetic friction coefficient (> 0)
};

enum class SingleHarmonicPattern {
    locked = 0,       // max |a| <= s: the mass never slips, vbar = 0            (5.4)
    stick_cycle = 1,  // steady state is a cycle of the break-away map (Sect. 5)
    invalid = 2,      // conditions V1-V4 of Sect. 5 fail: vbar = NaN
};

struct SingleHarmonicEvent {
    double t_start, t_end;  // slip interval, time measured from the cycle's first break-away
    int sigma;              // slip direction
    bool ends_in_stick;     // false: reversal at t_end (|a(t_end)| > s)
    double dx;              // displacement over the slip (3.3)
};

struct SingleHarmonicResult {
    SingleHarmonicPattern pattern = SingleHarmonicPattern::invalid;
    double vbar = std::numeric_limits<double>::quiet_NaN();
    int cycle_periods = 0;          // M: the steady state repeats after M periods   (5.3)
    double t_first = NAN;           // phase in [0, Δt) of the cycle's first break-away
    std::string signature;          // e.g. "+.-." : '+'/'-' a slip, '.' it ends in a stick
    std::vector<SingleHarmonicEvent> slips;  // one steady cycle, times from the break-away at t_first
    std::string why;                // for invalid: which condition V1-V4 (Sect. 5) failed
    bool valid() const { return pattern != SingleHarmonicPattern::invalid; }
};

namespace single_harmonic_detail {

struct Profile {
    double T, w, A1, A2;
    // (2.2)-(2.4); the constant c0 is left out: only differences of y enter.
    double y(double t) const { const double th = w * t; return A1 * std::cos(th) + A2 * std::cos(2 * th); }
    double yp(double t) const { const double th = w * t; return -w * (A1 * std::sin(th) + 2 * A2 * std::sin(2 * th)); }
    double a(double t) const {  // a = -y''
        const double th = w * t; return w * w * (A1 * std::cos(th) + 4 * A2 * std::cos(2 * th));
    }
};

// (4.2): all t in [0, T) with a(t) = L, sorted. P(c) = 8 A2 c^2 + A1 c - 4 A2, a = w^2 P(cos wt).
inline std::vector<double> level_times(const Profile& p, double L) {
    const double lam = L / (p.w * p.w);
    std::vector<double> cs;
    if (p.A2 == 0) {
        if (p.A1 != 0) cs.push_back(lam / p.A1);
    } else {
        const double qa = 8 * p.A2, qb = p.A1, qc = -(4 * p.A2 + lam);
        const double disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
            if (q != 0) { cs.push_back(q / qa); cs.push_back(qc / q); }
            else cs.push_back(0.0);  // qb = 0 and disc = 0
        }
    }
    std::vector<double> th;
    for (double c : cs) {
        if (!(std::abs(c) <= 1 + 1e-14)) continue;
        c = std::clamp(c, -1.0, 1.0);
        const double t0 = std::acos(c);
        for (double t : {t0, 2 * std::numbers::pi - t0}) {
            for (int it = 0; it < 3; ++it) {  // Newton polish on h(θ) = P(cos θ) - λ
                const double h = p.A1 * std::cos(t) + 4 * p.A2 * std::cos(2 * t) - lam;
                const double hp = -p.A1 * std::sin(t) - 8 * p.A2 * std::sin(2 * t);
                if (hp == 0) break;
                const double d = h / hp;
                if (!(std::abs(d) < 1e-6)) break;
                t -= d;
            }
            if (t < 0) t += 2 * std::numbers::pi;
            if (t >= 2 * std::numbers::pi) t -= 2 * std::numbers::pi;
            th.push_back(t / p.w);
        }
    }
    std::sort(th.begin(), th.end());
    th.erase(std::unique(th.begin(), th.end()), th.end());
    return th;
}

struct Slip { double t_end, dx; };

// Lemma 3.4: end of a slip that starts at rest at tb in direction sig: the first root > tb of
// sig v(t), v from (3.2). Subdivision points: the zeros of a - sig k (4.2) and the multiples of
// T/2 (where a' = 0); sig v is strictly monotone between consecutive ones.
inline bool slip_end(const Profile& p, double k, double tb, int sig, Slip& out) {
    const double ypb = p.yp(tb), yb = p.y(tb);
    auto sv = [&](double t) { return -sig * (p.yp(t) - ypb) - k * (t - tb); };  // sig * (3.2)
    std::vector<double> base = level_times(p, sig * k);
    base.push_back(0.0);
    base.push_back(p.T / 2);
    std::sort(base.begin(), base.end());
    const double guard = tb + 8 * std::numeric_limits<double>::epsilon() * p.T * (1 + std::abs(tb) / p.T);
    double lo = tb;
    // (3.5): sig v(tb + T) = -k T < 0, so the slip ends within one period; the loop bound is generous.
    const int max_periods = 64 + static_cast<int>(4 * p.w * (std::abs(p.A1) + 2 * std::abs(p.A2)) / (k * p.T));
    const double n0 = std::floor(tb / p.T);
    for (int n = 0; n <= max_periods; ++n) {
        for (double b : base) {
            const double z = (n0 + n) * p.T + b;
            if (z <= guard) continue;
            const double val = sv(z);
            if (val > 0) { lo = z; continue; }
            double hi = z;  // sig v(lo) > 0 >= sig v(hi), sig v monotone on [lo, hi]: bisection
            if (val < 0) {
                for (int it = 0; it < 200; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi) break;
                    (sv(mid) > 0 ? lo : hi) = mid;
                }
            }
            const double te = hi, d = te - tb;
            out.t_end = te;
            out.dx = -(p.y(te) - yb - ypb * d) - sig * k * d * d / 2;  // (3.3)
            return true;
        }
    }
    return false;
}

struct Candidate { double t; int sig; };  // break-away instant in [0, T) and slip direction

// (4.3): break-away candidates, the starts of the runs of |a| > s within one period.
inline std::vector<Candidate> breakaways(const Profile& p, double s) {
    std::vector<double> x = level_times(p, s), m = level_times(p, -s);
    x.insert(x.end(), m.begin(), m.end());
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
    std::vector<Candidate> out;
    const std::size_t n = x.size();
    auto out_mid = [&](std::size_t i) {  // |a| - s on the arc (x[i], x[i+1]) (cyclic)
        const double b = (i + 1 < n) ? x[i + 1] : x[0] + p.T;
        return p.a(0.5 * (x[i] + b));
    };
    for (std::size_t i = 0; i < n; ++i) {
        const double after = out_mid(i), before = out_mid((i + n - 1) % n);
        if (std::abs(after) > s && std::abs(before) <= s) out.push_back({x[i], after > 0 ? 1 : -1});
    }
    return out;
}

struct Step {                 // one application of the break-away map (5.2)
    bool ok = false;
    std::size_t next = 0;     // index of the next break-away candidate
    long periods = 0;         // m: next break-away at cand[next].t + m T (time origin: this one's period)
    std::vector<SingleHarmonicEvent> slips;
    std::string why;          // when !ok
};

// From rest (just broken away) at tb with direction sig: slips and reversals up to the next stick,
// then the next break-away (Sect. 5). tb may lie anywhere; times in the result are absolute.
inline Step run_to_next_breakaway(const Profile& p, double s, double k, const std::vector<Candidate>& cand,
                                  double tb, int sig) {
    Step st;
    const double margin = 1e-10 * s;  // (V4): a borderline stop is not decided
    for (int rev = 0; rev < 10000; ++rev) {
        Slip sl;
        if (!slip_end(p, k, tb, sig, sl)) { st.why = "slip end not found"; return st; }
        const double ae = p.a(sl.t_end);
        if (std::abs(std::abs(ae) - s) <= margin) { st.why = "V4: |a| = s at a stop"; return st; }
        if (std::abs(ae - sig * k) <= 1e-12 * (k + std::abs(ae))) { st.why = "V4: tangential stop"; return st; }
        const bool stick = std::abs(ae) <= s;
        st.slips.push_back({tb, sl.t_end, sig, stick, sl.dx});
        if (stick) {
            double best = INFINITY;
            for (std::size_t i = 0; i < cand.size(); ++i) {
                const double m = std::floor((sl.t_end - cand[i].t) / p.T) + 1;  // first cand[i].t + m T > t_end
                const double t = cand[i].t + m * p.T;
                if (t < best) { best = t; st.next = i; st.periods = static_cast<long>(m); }
            }
            st.ok = best < INFINITY;
            return st;
        }
        sig = ae > 0 ? 1 : -1;  // (1.3) reversal; necessarily -sig
        tb = sl.t_end;
    }
    st.why = "V1: no stick after 10000 reversals";
    return st;
}

}  // namespace single_harmonic_detail

inline SingleHarmonicResult single_harmonic_vbar(const SingleHarmonicCase& c) {
    using namespace single_harmonic_detail;
    SingleHarmonicResult res;
    if (!(c.period > 0 && c.k > 0 && c.s >= c.k && std::isfinite(c.period) && std::isfinite(c.A1) &&
          std::isfinite(c.A2) && std::isfinite(c.s))) {
        res.why = "parameters";
        return res;
    }
    const Profile p{c.period, 2 * std::numbers::pi / c.period, c.A1, c.A2};
    const std::vector<Candidate> cand = breakaways(p, c.s);
    if (cand.empty()) {  // (5.4): |a| <= s everywhere (a has mean 0, so |a| > s everywhere is impossible)
        if (std::abs(p.a(0)) <= c.s) { res.pattern = SingleHarmonicPattern::locked; res.vbar = 0; res.cycle_periods = 1; }
        else res.why = "V4: max |a| = s";  // a touches the level s only tangentially
        return res;
    }
    const std::size_t n = cand.size();
    std::vector<Step> map(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double tb = cand[i].t;
        map[i] = run_to_next_breakaway(p, c.s, c.k, cand, tb, cand[i].sig);
        if (!map[i].ok) { res.why = map[i].why; return res; }
    }
    // Cycles of the finite map (V2): every candidate must run into the same cycle.
    auto cycle_of = [&](std::size_t i) {  // smallest index on the cycle that i runs into
        std::vector<bool> seen(n, false);
        while (!seen[i]) { seen[i] = true; i = map[i].next; }
        std::size_t mn = i;
        for (std::size_t j = map[i].next; j != i; j = map[j].next) mn = std::min(mn, j);
        return mn;
    };
    const std::size_t c0 = cycle_of(0);
    for (std::size_t i = 1; i < n; ++i)
        if (cycle_of(i) != c0) { res.why = "V2: more than one stick cycle"; return res; }
    // From rest at t = 0 (V1): the motion must reach a stick (then it is in the map's cycle).
    if (std::abs(p.a(0)) > c.s) {
        const Step st = run_to_next_breakaway(p, c.s, c.k, cand, 0.0, p.a(0) > 0 ? 1 : -1);
        if (!st.ok) { res.why = "V1 from rest: " + st.why; return res; }
    }
    // (5.3): vbar = (sum of dx over the cycle) / (M T), M = sum of m.
    double dx = 0, t_origin = 0;
    long M = 0;
    std::size_t i = c0;
    do {
        const double off = t_origin - cand[i].t;  // candidate i's frame -> time since the cycle's start
        for (const auto& e : map[i].slips) {
            res.slips.push_back({off + e.t_start, off + e.t_end, e.sigma, e.ends_in_stick, e.dx});
            res.signature += (e.sigma > 0 ? '+' : '-');
            if (e.ends_in_stick) res.signature += '.';
            dx += e.dx;
        }
        t_origin += cand[map[i].next].t + static_cast<double>(map[i].periods) * p.T - cand[i].t;
        M += map[i].periods;
        i = map[i].next;
    } while (i != c0);
    res.t_first = cand[c0].t;
    res.cycle_periods = static_cast<int>(M);
    res.vbar = dx / (static_cast<double>(M) * p.T);
    res.pattern = SingleHarmonicPattern::stick_cycle;
    return res;
}

}  // namespace oracle
