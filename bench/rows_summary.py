#!/usr/bin/python3
"""Rows of 1-D parts (bench/rows.cpp): medians with min-max over the repetitions of one Google
Benchmark JSON run of selfalign_bench_simulate.

    build/release/bench/selfalign_bench_simulate --benchmark_filter=row \
        --benchmark_repetitions=5 --benchmark_min_time=0.1 \
        --benchmark_enable_random_interleaving=true \
        --benchmark_out=rows.json --benchmark_out_format=json
    bench/rows_summary.py rows.json

Prints the row stage's CPU time per part and step for N = 1..1000 (touching and apart), each
over its N = 1 value, and the exact row solver's CPU time over Moreau's on the 3-part queue
(5 periods each; the ratio taken repetition by repetition). Standard library only.
"""
import json
import statistics
import sys


def stats(values: list) -> str:
    return f"{statistics.median(values):9.3f} [{min(values):.3f}-{max(values):.3f}]"


def main(path: str) -> None:
    runs: dict[str, list] = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "iteration":
            runs.setdefault(b["run_name"], []).append(b)
    for k in runs:
        runs[k].sort(key=lambda b: b["repetition_index"])

    print("ns per part-step (CPU), median [min-max]; chained: mean fraction of parts in a chain")
    for name in ("BM_row_moreau_step", "BM_row_moreau_step_apart"):
        base = None
        for n in (1, 10, 100, 1000):
            r = runs.get(f"{name}/{n}")
            if not r:
                continue
            per = [b["ns_per_part_step"] for b in r]
            base = base or statistics.median(per)
            print(f"  {name + '/' + str(n):32s} {stats(per)}  / N=1: "
                  f"{statistics.median(per) / base:6.2f}  chained {r[0]['chained']:.4f}")

    exact = runs.get("BM_row_exact_period")
    if exact:
        print(f"exact row, 5 periods: {stats([b['cpu_time'] for b in exact])} "
              f"{exact[0]['time_unit']}, {exact[0]['arcs']:.0f} arcs")
        for n in (1000, 100000):
            m = runs.get(f"BM_row_moreau_same_accuracy/{n}")
            if not m:
                continue
            ratios = [a["cpu_time"] / b["cpu_time"] for a, b in zip(exact, m)]
            r = statistics.median(ratios)
            print(f"  Moreau at {n:6d} steps/period: {stats([b['cpu_time'] for b in m])} "
                  f"{m[0]['time_unit']}, distance {m[0]['distance']:.3g}; "
                  f"exact / Moreau {r:.3g} [{min(ratios):.3g}-{max(ratios):.3g}] "
                  f"(Moreau {1 / r:.0f} times slower)")


if __name__ == "__main__":
    main(*sys.argv[1:])
