// Closed-form oracle: steady-state average relative velocity for Coulomb friction with
// static coefficient mu_s >= kinetic mu_k under the "two-level" piecewise-constant table
// acceleration  A = a_s on [0,T1), -a_max on [T1,T1+T2), +a_max on [T1+T2,dt).
// Derivation and equation numbers: docs/static-kinetic-two-level.md.
// Self-contained (no selfalign includes); checked by two_level_static_kinetic_check.py.
#pragma once

#include <cmath>
#include <limits>

namespace oracle {

struct TwoLevelCase {
    double mu_s, mu_k, a_max, a_s, T1, T2, T3;
};

enum class TwoLevelPattern {
    locked = 0,     // a_max <= mu_s and |a_s| <= mu_s: never slips from rest, vbar = 0 (4.1)
    stick_slip = 1, // pattern A (Sect. 2): stick in phase 1, forward slip, backward slip
    slip_slip = 2,  // pattern B (Sect. 3): a_s < -mu_s, no stick, two reversals per period
    invalid = 3,    // neither pattern's conditions hold: vbar = NaN
};

struct TwoLevelResult {
    TwoLevelPattern pattern = TwoLevelPattern::invalid;
    double vbar = std::numeric_limits<double>::quiet_NaN();
    double V1 = NAN;  // forward speed at t = T1+T2                       (2.2)/(3.3)
    double V2 = NAN;  // backward speed |x'| at t = 0 (= at t = dt)        (2.4)/(3.6)
    // Event times within one period [0, dt), NaN if the event does not occur:
    double t_forward_start = NAN;  // forward slip starts (A: T1; B: tau1)
    double t_forward_stop = NAN;   // x' = 0 in phase 3, reversal: T1+T2+tau3   (2.3)
    double t_backward_stop = NAN;  // backward slip ends in phase 1: tau1       (2.5)/(3.1)
    bool valid() const { return pattern != TwoLevelPattern::invalid; }
};

inline TwoLevelResult two_level_vbar(const TwoLevelCase& c) {
    const double s = c.mu_s, k = c.mu_k, al = c.a_max, a = c.a_s;
    const double T1 = c.T1, T2 = c.T2, T3 = c.T3, dt = T1 + T2 + T3;
    TwoLevelResult res;
    if (!(k > 0 && s >= k && T1 > 0 && T2 > 0 && T3 > 0)) return res;
    if (al <= s) {  // (4.1): every |A| <= mu_s, rest is kept forever
        if (std::abs(a) <= s) { res.pattern = TwoLevelPattern::locked; res.vbar = 0.0; res.V1 = res.V2 = 0.0; }
        return res;
    }
    const double r = (al - k) / (al + k);  // (2.3)
    if (std::abs(a) <= s) {                // ---- pattern A, conditions (C1)-(C5)
        const double V1 = (al - k) * T2;   // (2.2)
        const double tau3 = r * T2;        // (2.3)
        if (tau3 > T3) return res;         // (C3)
        const double V2 = (al - k) * (T3 - tau3);  // (2.4)
        double dx = al * r * T2 * T2;      // (2.7), first term
        res.t_forward_stop = T1 + T2 + tau3;
        if (V2 > 0) {
            if (a >= k) return res;        // (C4)
            const double tau1 = V2 / (k - a);  // (2.5)
            if (tau1 > T1) return res;     // (C5)
            dx -= (al - k) * (al - a) * (T3 - tau3) * (T3 - tau3) / (2 * (k - a));  // (2.7)
            res.t_backward_stop = tau1;
        }
        res.pattern = TwoLevelPattern::stick_slip;
        res.vbar = dx / dt;                // (2.8)
        res.V1 = V1; res.V2 = V2; res.t_forward_start = T1;
        return res;
    }
    if (a < 0) {                           // ---- pattern B, |a_s| > mu_s, conditions (C1'),(C3'),(C5')
        const double q = -(k + a) / (k - a);                          // (3.5)
        const double cc = (al - k) * (T3 - r * T2) + r * (k + a) * T1;  // (3.5)
        const double V2 = cc / (1 - r * q);                           // (3.6)
        if (V2 < 0) return res;                                       // (C3')
        const double tau1 = V2 / (k - a);                             // (3.1)
        if (tau1 > T1) return res;                                    // (C5')
        const double u1 = -(k + a) * (T1 - tau1);                     // (3.2)
        const double V1 = u1 + (al - k) * T2;                         // (3.3)
        const double dx = -V2 * V2 / (2 * (k - a)) + u1 * u1 / (2 * (-(k + a))) + (u1 + V1) * T2 / 2
                        + V1 * V1 / (2 * (al + k)) - V2 * V2 / (2 * (al - k));  // (3.7)
        res.pattern = TwoLevelPattern::slip_slip;
        res.vbar = dx / dt;                                           // (3.8)
        res.V1 = V1; res.V2 = V2;
        res.t_forward_start = tau1; res.t_backward_stop = tau1;
        res.t_forward_stop = T1 + T2 + V1 / (al + k);                 // (3.4)
        return res;
    }
    return res;  // a_s > mu_s: backward slip is not decelerated in phase 1; not derived
}

}  // namespace oracle
