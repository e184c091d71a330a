#!/usr/bin/env python3
"""Independent check of docs/single-harmonic-steady-state.md and single_harmonic.hpp.

(a) brute-force simulation written from the model alone (doc Sect. 1), for a general Fourier
    table motion y = sum_j A_j cos(j w t) + B_j sin(j w t) (no use of the doc's quadratic in
    cos(w t), of its brackets or of its break-away map): from rest at t = 0, march on a uniform
    grid of N steps per period; a stick is left when |a| > s at a grid point (crossing located by
    bisection); during a slip the exact velocity v(t) = -(y'(t) - y'(tb)) - sig k (t - tb) is
    tested for sign at grid points and its zero located by bisection; at a zero the mass sticks
    or reverses by the rule of the model.  March until the displacement per period repeats,
    vbar = displacement over the last period / period.  With mpmath (present on Debian's
    /usr/bin/python3) this runs at 32 significant digits, otherwise in floats.
    Run at two grid sizes; both must give the same vbar (a missed event would differ).
(b) a cruder check with no closed form at all: fixed-step midpoint integration of
    v' = a(t) - sig k with the stick / reversal rule applied at the steps; first order in the
    step, so it must agree only to ~1e-3 of the velocity scale; it guards the sign conventions.
(c) with --cxx: compiles the C++ oracle with a throw-away main in a temporary directory
    (g++ -std=c++20) and checks that it prints the doc's table values (the 32-digit reference
    rounded to 15 significant digits: the oracle must be within one unit of the 15th digit,
    or 1e-15 V for the zero rows) and the patterns, and NaN outside the derivation.
Tolerance of (a) against the table: 1e-12 * V, V = w (|A1| + 2|A2|) the table's velocity
amplitude.  The oracle's event times are exact to about one ulp, each slip displacement (3.3) is
a difference of terms of size |A| and k T^2, so its rounding is a few 1e-16 of those; vbar is a
sum of few such terms over T.  1e-12 V leaves a margin of ~1000 over what is observed and
is far below any pattern-level error (which would be O(1e-3 V) or more).
Usage: /usr/bin/python3 single_harmonic_check.py [--cxx] [--float]
"""
import math, os, subprocess, sys, tempfile

try:
    if "--float" in sys.argv:
        raise ImportError
    import mpmath
    mpmath.mp.dps = 32
    NUM, SIN, COS, PI, EPS_REL = mpmath.mpf, mpmath.sin, mpmath.cos, mpmath.pi, mpmath.mpf("1e-28")
    PREC = "mpmath, 32 digits"
except ImportError:
    mpmath = None
    NUM, SIN, COS, PI, EPS_REL = float, math.sin, math.cos, math.pi, 1e-15
    PREC = "float"

TWO_PI = "6.283185307179586"  # the double nearest 2 pi: w = 1 up to one ulp
# name, period, cos_coeffs, sin_coeffs, s, k, doc vbar (15 digits), doc signature ; doc Sect. 7
# Rows marked with a source row name in `same_as` are not oracle inputs (sin terms or sign
# flips): their vbar must equal +- that row's by the symmetries (2.5)-(2.7).
CASES = [
    # name   period   cos [A1, A2]      sin        s      k      vbar                  signature
    ("H1", TWO_PI, ["1.3", "0"], ["0", "0"], "1", "1", "0", "-.+."),
    ("H2", "1", ["0.035", "0"], ["0", "0"], "1.2", "1", "0", "-.+."),
    ("E1", TWO_PI, ["1.1", "0.1"], ["0", "0"], "1", "1", "0.0746622484606172", "+."),
    ("E2", TWO_PI, ["1.5", "0.1"], ["0", "0"], "1", "1", "0.188632127431796", "-.+."),
    ("E3", TWO_PI, ["1.5", "0.3"], ["0", "0"], "1", "1", "0.374785171423526", "-.+-."),
    ("E4", "1", ["0.04", "0.004"], ["0", "0"], "1.2", "1", "0.0501176126804382", "+."),
    ("E5", "1", ["0.04", "0.002"], ["0", "0"], "1.2", "1", "0.0261738474621927", "-.+."),
    ("E6", "1", ["0.045", "0.008"], ["0", "0"], "1.5", "1", "0.0818621239253180", "-.+-."),
    ("E7", "2.5", ["0.3", "-0.02"], ["0", "0"], "1.6", "1", "-0.167118207832410", "-."),
    ("E8", "0.5", ["0.005", "0.0008"], ["0", "0"], "0.8", "0.5", "0.0153701988290841", "+."),
]
# oracle must return NaN (doc Sect. 5, V1-V4): (name, period, A1, A2, s, k)
NAN_CASES = [
    ("N1", TWO_PI, "2", "0", "1", "1"),     # (V1): pure slip, reversals only, no stick
    ("N2", TWO_PI, "1.5", "0.3", "0.9", "1"),  # parameters: s < k
]
# rows checked by simulation only: (name, period, cos, sin, s, k, source row, sign)
DERIVED = [
    ("E2q", TWO_PI, ["0", "-0.1"], ["-1.5", "0"], "1", "1", "E2", +1),   # y(t + Δt/4)   (2.5)
    ("E2h", TWO_PI, ["-1.5", "0.1"], ["0", "0"], "1", "1", "E2", +1),    # y(t + Δt/2)   (2.6)
    ("E2m", TWO_PI, ["1.5", "-0.1"], ["0", "0"], "1", "1", "E2", -1),    # A2 -> -A2     (2.7)
    ("E7m", "2.5", ["-0.3", "0.02"], ["0", "0"], "1.6", "1", "E7", -1),  # y -> -y       (2.6)
]


class Table:
    """y, y' and a = -y'' of y = sum_j A_j cos(j w t) + B_j sin(j w t)."""

    def __init__(self, period, cos_c, sin_c):
        self.T = NUM(float(period))  # the double the C++ side gets, exactly
        self.A = [NUM(float(c)) for c in cos_c]
        self.B = [NUM(float(c)) for c in sin_c]
        self.w = 2 * PI / self.T

    def eval(self, t):
        th = self.w * t
        y = yp = a = 0
        for j, (A, B) in enumerate(zip(self.A, self.B), start=1):
            c, s, jw = COS(j * th), SIN(j * th), j * self.w
            y += A * c + B * s
            yp += jw * (-A * s + B * c)
            a += jw * jw * (A * c + B * s)  # -y''
        return y, yp, a


def bisect(f, lo, hi, tol):
    """f(lo) > 0 >= f(hi): a root of f in (lo, hi]."""
    while hi - lo > tol:
        mid = (lo + hi) / 2
        if mid <= lo or mid >= hi:
            break
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    return hi


def simulate(tab, s, k, nsteps, max_periods=400):
    """(a): from rest at t = 0; returns (vbar, number of periods run, slip signs of last period)."""
    s, k = NUM(float(s)), NUM(float(k))
    T = tab.T
    h = T / nsteps
    tol = T * EPS_REL
    x = NUM(0)
    slip = None  # None: stuck; else (tb, xb, yb, ypb, sig): a slip from rest at tb
    X = [x]
    signs, last_signs = [], []

    def v_of(sl, t):
        tb, xb, yb, ypb, sig = sl
        return -(tab.eval(t)[1] - ypb) - sig * k * (t - tb)

    def x_of(sl, t):
        tb, xb, yb, ypb, sig = sl
        y = tab.eval(t)[0]
        return xb - (y - yb - ypb * (t - tb)) - sig * k * (t - tb) ** 2 / 2

    def start(t, sig, xb):
        y, yp, _ = tab.eval(t)
        signs.append("+" if sig > 0 else "-")
        return (t, xb, y, yp, sig)

    a0 = tab.eval(NUM(0))[2]
    if abs(a0) > s:
        slip = start(NUM(0), 1 if a0 > 0 else -1, x)
    for n in range(max_periods):
        for i in range(nsteps):
            t0, t1 = (n * nsteps + i) * h, (n * nsteps + i + 1) * h
            tc = t0
            while True:
                if slip is None:
                    a1 = tab.eval(t1)[2]
                    if abs(a1) <= s:
                        break
                    tb = bisect(lambda t: s - abs(tab.eval(t)[2]), tc, t1, tol)
                    slip = start(tb, 1 if tab.eval(tb)[2] > 0 else -1, x)
                    tc = tb
                sig = slip[4]
                if sig * v_of(slip, t1) > 0:
                    break
                lo = tc
                if lo == slip[0]:  # slip began in this step: probe just after its start
                    lo = lo + (t1 - lo) * NUM(2) ** -20
                    if sig * v_of(slip, lo) <= 0:
                        raise RuntimeError("slip ends within 2^-20 of a step after its start")
                te = bisect(lambda t: sig * v_of(slip, t), lo, t1, tol)
                x = x_of(slip, te)
                ae = tab.eval(te)[2]
                if abs(ae) <= s:  # stick
                    signs.append(".")
                    slip = None
                else:  # reversal (1.3)
                    slip = start(te, 1 if ae > 0 else -1, x)
                tc = te
        xe = x if slip is None else x_of(slip, (n + 1) * nsteps * h)
        X.append(xe)
        last_signs, signs = signs, []
        if n >= 6:
            d = [X[-1] - X[-2], X[-2] - X[-3], X[-3] - X[-4]]
            scale = max(abs(v) for v in d) + T * k
            if abs(d[0] - d[1]) <= 100 * EPS_REL * scale and abs(d[1] - d[2]) <= 100 * EPS_REL * scale:
                return d[0] / T, n + 1, "".join(last_signs)
    raise RuntimeError("no periodic steady state within %d periods" % max_periods)


def crude(tab, s, k, nsteps, periods=12):
    """(b): midpoint rule for v, no closed form; vbar over the last period."""
    T, s, k = float(tab.T), float(s), float(k)
    A = [float(c) for c in tab.A]
    B = [float(c) for c in tab.B]
    w = 2 * math.pi / T
    h = T / nsteps

    def acc(t):
        return sum((j * w) ** 2 * (a * math.cos(j * w * t) + b * math.sin(j * w * t))
                   for j, (a, b) in enumerate(zip(A, B), start=1))

    x = v = 0.0
    sig = 0
    X = [0.0]
    for n in range(periods):
        for i in range(nsteps):
            t = (n * nsteps + i) * h
            am = acc(t + h / 2)
            if sig == 0:
                if abs(am) <= s:
                    continue
                sig = 1 if am > 0 else -1
            vn = v + h * (am - sig * k)
            if sig * vn <= 0:  # stop within the step
                tau = h * v / (v - vn) if v != vn else 0.0
                x += v * tau / 2
                v, sig = 0.0, 0
                ae = acc(t + h)
                if abs(ae) > s:  # reversal: continue with the rest of the step
                    sig = 1 if ae > 0 else -1
                    v = (h - tau) * (ae - sig * k)
                    x += v * (h - tau) / 2
            else:
                x += h * (v + vn) / 2
                v = vn
        X.append(x)
    return (X[-1] - X[-2]) / T


def main():
    by_name = {c[0]: c for c in CASES}
    vals = {}
    fails = 0
    print("(a)/(b) simulation in %s" % PREC)
    rows = [(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], None, 1) for c in CASES]
    rows += [(d[0], d[1], d[2], d[3], d[4], d[5], None, None, d[6], d[7]) for d in DERIVED]
    for name, per, cc, sc, s, k, doc, sigdoc, src, sign in rows:
        tab = Table(per, cc, sc)
        V = float(tab.w) * (sum(abs(float(a)) * j for j, a in enumerate(cc, 1)) +
                            sum(abs(float(b)) * j for j, b in enumerate(sc, 1)))
        v1, n1, sg1 = simulate(tab, s, k, 400)
        v2, n2, sg2 = simulate(tab, s, k, 1000)
        vc = crude(tab, s, k, 20000)
        vals[name] = v2
        ok_grid = abs(v1 - v2) <= 1e-20 * V if mpmath else abs(v1 - v2) <= 1e-13 * V
        if doc is None and src is None:
            ref, what = None, "(no table value)"
        elif src is None:
            ref, what = float(doc), "table"
        else:
            ref, what = sign * vals[src], ("+" if sign > 0 else "-") + src
            ok_sym = abs(v2 - ref) <= (1e-25 if mpmath else 1e-13) * V  # symmetry: to the sim's precision
        ok_ref = ref is None or (abs(float(v2) - float(ref)) <= 1e-12 * V and (src is None or ok_sym))
        ok_crude = abs(vc - float(v2)) <= 1e-3 * V
        ok_sig = sigdoc is None or sigdoc == sg2 or rotated(sigdoc, sg2)
        ok = ok_grid and ok_ref and ok_crude and ok_sig
        fails += not ok
        print("%-4s vbar_sim %s  periods %3d  signs/period %-8s  |sim-%s| %s  crude %.6g  %s"
              % (name, fmt(v2), n2, sg2, what,
                 "-" if ref is None else "%.2e" % abs(v2 - ref), vc, "ok" if ok else "FAIL"))
    if "--cxx" in sys.argv:
        fails += check_cxx(vals)
    print("FAILED: %d" % fails if fails else "all checks passed")
    return 1 if fails else 0


def rotated(a, b):
    """same cyclic slip sequence, e.g. '-.+.' vs '+.-.' (the period grid cuts the cycle anywhere)"""
    return len(a) == len(b) and b in a + a


def fmt(v):
    return mpmath.nstr(v, 18) if mpmath else "%.17g" % v


MAIN_CPP = r'''
#include "single_harmonic.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    for (int i = 1; i + 4 < argc; i += 5) {
        oracle::SingleHarmonicCase c{std::atof(argv[i]), std::atof(argv[i + 1]), std::atof(argv[i + 2]),
                                     std::atof(argv[i + 3]), std::atof(argv[i + 4])};
        const auto r = oracle::single_harmonic_vbar(c);
        std::printf("%.15g %.17g %s %d\n", r.vbar, r.vbar, r.signature.empty() ? "none" : r.signature.c_str(),
                    r.cycle_periods);
    }
}
'''


def check_cxx(vals):
    here = os.path.dirname(os.path.abspath(__file__))
    fails = 0
    with tempfile.TemporaryDirectory() as d:
        src, exe = os.path.join(d, "main.cpp"), os.path.join(d, "main")
        open(src, "w").write(MAIN_CPP)
        subprocess.run(["g++", "-std=c++20", "-O2", "-Wall", "-Wextra", "-Werror", "-I", here, src, "-o", exe],
                       check=True)
        args = []
        for c in CASES:
            args += [c[1], c[2][0], c[2][1], c[4], c[5]]
        for c in NAN_CASES:
            args += list(c[1:])
        out = subprocess.run([exe] + args, check=True, capture_output=True, text=True).stdout.split("\n")
    print("(c) C++ oracle")
    for c, line in zip(CASES, out):
        v15, v17, sig, M = line.split()
        tab = Table(c[1], c[2], c[3])
        V = float(tab.w) * (abs(float(c[2][0])) + 2 * abs(float(c[2][1])))
        # the table holds the 32-digit reference rounded to 15 digits: within one unit of the 15th
        doc_ok = c[6] is None or abs(float(v17) - float(c[6])) <= max(1e-14 * abs(float(c[6])), 1e-15 * V)
        sig_ok = c[7] is None or sig == c[7]
        sim_ok = abs(float(v17) - float(vals[c[0]])) <= 1e-12 * V
        ok = doc_ok and sig_ok and sim_ok
        fails += not ok
        print("%-4s oracle %-22s = %-18s pattern %-8s M %s  |oracle-sim|/V %.1e  %s"
              % (c[0], v17, v15, sig, M, abs(float(v17) - float(vals[c[0]])) / V, "ok" if ok else "FAIL"))
    for c, line in zip(NAN_CASES, out[len(CASES):]):
        ok = math.isnan(float(line.split()[1]))
        fails += not ok
        print("%-4s oracle %s (NaN expected)  %s" % (c[0], line.split()[1], "ok" if ok else "FAIL"))
    return fails


if __name__ == "__main__":
    sys.exit(main())
