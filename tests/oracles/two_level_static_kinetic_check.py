#!/usr/bin/env python3
"""Independent check of docs/static-kinetic-two-level.md and two_level_static_kinetic.hpp.

(a) closed form of the doc, eqs. (2.1)-(4.8), in exact rational arithmetic (fractions.Fraction);
(b) brute-force event-driven simulation written from the model alone (Sect. 1 of the doc):
    piecewise-constant relative acceleration, propagated segment by segment in exact
    arithmetic from rest at t = 0 for many periods;
(c) with --cxx: compiles the C++ oracle with a throw-away main in a temporary directory
    (g++ -std=c++20) and compares its doubles with (a) to 1e-13.
Standard library only.  Usage: /usr/bin/python3 two_level_static_kinetic_check.py [--cxx]
"""
from fractions import Fraction as F
import math, os, subprocess, sys, tempfile

# name, mu_s, mu_k, a_max, T1, T2, T3 ; a_s = a_max (T2 - T3) / T1 (zero net table velocity)
CASES = [
    ("S1",  "1",   "1",   "2",   "1",   "1",   "1"),
    ("S2",  "1.5", "1",   "2",   "1",   "1",   "1"),
    ("S3",  "1",   "1",   "3",   "1",   "1",   "1.5"),
    ("S4",  "1.2", "1",   "3",   "1",   "1",   "1.5"),
    ("S5",  "1.6", "1",   "3",   "1",   "1",   "1.5"),
    ("S6",  "2.5", "1",   "3",   "1",   "1",   "1.5"),
    ("S7",  "3.5", "1",   "3",   "1",   "1",   "1.5"),
    ("S8",  "0.8", "0.5", "1.7", "0.7", "0.4", "0.55"),
    ("S9",  "1",   "1",   "2",   "1",   "1.1", "1"),
    ("S10", "0.5", "0.5", "2",   "0.8", "0.3", "0.6"),
    ("S11", "0.8", "0.5", "2",   "0.8", "0.3", "0.6"),
    ("S12", "1",   "1",   "2",   "0.2", "1",   "1"),
    ("S13", "2",   "1",   "4",   "2",   "1",   "0.2"),
]


def params(c):
    name, ms, mk, am, t1, t2, t3 = c
    ms, mk, am, t1, t2, t3 = (F(v) for v in (ms, mk, am, t1, t2, t3))
    return dict(name=name, mu_s=ms, mu_k=mk, a_max=am, a_s=am * (t2 - t3) / t1, T1=t1, T2=t2, T3=t3)


# ----------------------------------------------------------------------------------------
# (a) closed form (doc Sects. 2-4), exact
# ----------------------------------------------------------------------------------------
def closed_form(p):
    s, k, al, a = p["mu_s"], p["mu_k"], p["a_max"], p["a_s"]
    T1, T2, T3 = p["T1"], p["T2"], p["T3"]
    T = T1 + T2 + T3
    r = (al - k) / (al + k)                                      # (2.3)
    if al <= s and abs(a) <= s:
        return "locked", F(0)                                     # (4.1)
    if al <= s:
        return "invalid", None
    if abs(a) <= s:                                               # pattern A
        V1 = (al - k) * T2                                        # (2.2)
        tau3 = r * T2                                             # (2.3)
        if tau3 > T3:
            return "invalid", None                                # (C3)
        V2 = (al - k) * (T3 - tau3)                               # (2.4)
        if V2 > 0:
            if a >= k:
                return "invalid", None                            # (C4)
            if V2 / (k - a) > T1:                                 # (2.5), (C5)
                return "invalid", None
            dx = al * r * T2**2 - (al - k) * (al - a) * (T3 - tau3)**2 / (2 * (k - a))  # (2.7)
        else:
            dx = al * r * T2**2
        return "A", dx / T                                        # (2.8)
    if a < 0:                                                     # pattern B, |a| > mu_s
        q = -(k + a) / (k - a)                                    # (3.5)
        c = (al - k) * (T3 - r * T2) + r * (k + a) * T1           # (3.5)
        V2 = c / (1 - r * q)                                      # (3.6)
        if V2 < 0:
            return "invalid", None                                # (C3')
        tau1 = V2 / (k - a)                                       # (3.1)
        if tau1 > T1:
            return "invalid", None                                # (C5')
        u1 = -(k + a) * (T1 - tau1)                               # (3.2)
        V1 = u1 + (al - k) * T2                                   # (3.3)
        dx = (-V2**2 / (2 * (k - a)) + u1**2 / (2 * (-(k + a))) + (u1 + V1) * T2 / 2
              + V1**2 / (2 * (al + k)) - V2**2 / (2 * (al - k)))  # (3.7)
        return "B", dx / T                                        # (3.8)
    return "invalid", None


# ----------------------------------------------------------------------------------------
# (b) brute force from the model only
# ----------------------------------------------------------------------------------------
def sign(z):
    return (z > 0) - (z < 0)


def simulate(p, max_periods=120):
    """Event-driven integration from rest (x = v = 0 at t = 0).

    Returns (vbar of the last simulated period, exactly_periodic, |change of vbar over the
    last period|, number of periods)."""
    s, k = p["mu_s"], p["mu_k"]
    phases = [(p["T1"], p["a_s"]), (p["T2"], -p["a_max"]), (p["T3"], p["a_max"])]
    x, v = F(0), F(0)
    seen = {}                  # v at period start -> (period index, x)
    dx_hist = []
    for n in range(max_periods):
        if v in seen:          # state repeats exactly: the motion is periodic from here
            m, xm = seen[v]
            per = n - m
            T = sum(d for d, _ in phases)
            return (x - xm) / (per * T), True, F(0), n
        seen[v] = (n, x)
        x_start = x
        for dur, A in phases:
            left = dur
            while left > 0:
                if v == 0:
                    if abs(A) <= s:          # stick: relative motion frozen
                        acc, left_seg = F(0), left
                    else:                    # slip starts in direction -sign(A)
                        sig = -sign(A)
                        acc, left_seg = -sig * k - A, left
                else:
                    sig = sign(v)
                    acc = -sig * k - A
                    left_seg = left
                    if acc != 0 and sign(acc) != sig:      # decelerating: v = 0 at -v/acc
                        tz = -v / acc
                        if tz < left:
                            left_seg = tz
                x += v * left_seg + acc * left_seg**2 / 2
                v_new = v + acc * left_seg
                if v != 0 and left_seg != left:
                    v_new = F(0)                          # exact zero at the event
                v = v_new
                left -= left_seg
        dx_hist.append(x - x_start)
    T = sum(d for d, _ in phases)
    return dx_hist[-1] / T, False, abs(dx_hist[-1] - dx_hist[-2]) / T, max_periods


def fmt(z):
    return "nan" if z is None else "%.17g" % float(z)


def run_cxx(ps):
    here = os.path.dirname(os.path.abspath(__file__))
    main = ['#include "two_level_static_kinetic.hpp"', "#include <cstdio>", "int main() {"]
    for p in ps:
        vals = ", ".join("%.17g" % float(p[n]) for n in ("mu_s", "mu_k", "a_max"))
        ts = ", ".join("%.17g" % float(p[n]) for n in ("T1", "T2", "T3"))
        main.append("  { oracle::TwoLevelCase c{%s, 0.0, %s};" % (vals, ts))
        main.append("    c.a_s = c.a_max * (c.T2 - c.T3) / c.T1;")
        main.append('    auto r = oracle::two_level_vbar(c); std::printf("%.17g %d\\n", r.vbar, (int)r.pattern); }')
    main.append("}")
    with tempfile.TemporaryDirectory(dir="/tmp") as d:
        src, exe = os.path.join(d, "m.cpp"), os.path.join(d, "m")
        open(src, "w").write("\n".join(main) + "\n")
        subprocess.run(["g++", "-std=c++20", "-O1", "-Wall", "-Wextra", "-Werror", "-I", here, src, "-o", exe], check=True)
        out = subprocess.run([exe], check=True, capture_output=True, text=True).stdout.split("\n")
    return [(float(l.split()[0]), int(l.split()[1])) for l in out if l.strip()]


def main():
    ok = True
    ps = [params(c) for c in CASES]
    print("%-4s %5s %5s %5s %9s %-8s %-24s %-24s %s" % ("set", "mu_s", "mu_k", "a_max", "a_s", "pattern",
                                                         "vbar closed form", "vbar simulation", "check"))
    results = []
    for p in ps:
        pat, vb = closed_form(p)
        vs, periodic, drift, n = simulate(p)
        if vb is None:
            verdict = "oracle NaN (pattern fails); sim %s" % ("periodic" if periodic else "converging")
        elif periodic:
            good = vs == vb
            verdict = ("EXACT (periodic after %d periods)" % n) if good else "MISMATCH"
            ok &= good
        else:
            err = abs(vs - vb)
            good = err < F(1, 10**30) and drift < F(1, 10**30)
            verdict = "|diff| = %.1e after %d periods (geometric convergence)" % (float(err), n)
            ok &= good
        results.append((pat, vb))
        print("%-4s %5s %5s %5s %9.5g %-8s %-24s %-24s %s" % (p["name"], p["mu_s"], p["mu_k"], p["a_max"],
              float(p["a_s"]), pat, fmt(vb), fmt(vs), verdict))
    if "--cxx" in sys.argv:
        codes = {"locked": 0, "A": 1, "B": 2, "invalid": 3}
        for p, (pat, vb), (vc, pc) in zip(ps, results, run_cxx(ps)):
            if vb is None:
                good = math.isnan(vc) and pc == codes[pat]
            else:
                good = pc == codes[pat] and abs(vc - float(vb)) <= 1e-13 * max(1.0, abs(float(vb)))
            ok &= good
            print("C++ %-4s %-24s %s" % (p["name"], "%.17g" % vc, "ok" if good else "MISMATCH"))
    print("ALL CHECKS PASSED" if ok else "SOME CHECKS FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
