#!/usr/bin/python3
"""Library / bare-loop time ratios from one Google Benchmark JSON run of selfalign_bench_simulate.

    build/release/bench/selfalign_bench_simulate --benchmark_filter='per_period|per_step' \
        --benchmark_repetitions=9 --benchmark_min_time=0.2 \
        --benchmark_enable_random_interleaving=true \
        --benchmark_out=sim.json --benchmark_out_format=json
    bench/bare_loop_ratios.py sim.json

Each library benchmark is paired with its bare loop, a transliteration of the library's own loop
in the same binary ("dispatch overhead"), and with its floor, a minimal loop written from the
equations (bench/floors.cpp: "distance to the floor", issue 22); the ratio is taken repetition by
repetition (CPU time), and the median with min-max is printed. Standard library only.
"""
import json
import statistics
import sys

PAIRS = [
    ("exact_per_period/case1_uniform", "bare_exact_per_period/case1_uniform"),
    ("exact_per_period/case3_uniform", "bare_exact_per_period/case3_uniform"),
    ("exact_per_period/case3_jerk50_uniform", "bare_exact_per_period/case3_jerk50_uniform"),
    ("exact_per_period/case3_jerk12_uniform", "bare_exact_per_period/case3_jerk12_uniform"),
    ("time_stepping_per_step/case1_uniform", "bare_time_stepping_per_step/case1_uniform_inlined"),
    ("time_stepping_per_step/case3_uniform", "bare_time_stepping_per_step/case3_uniform_inlined"),
    ("planar_point_per_step", "bare_planar_point_per_step"),
    ("feeder_exact_per_period/sliding", "bare_feeder_exact_per_period/sliding"),
    ("feeder_exact_per_period/hopping", "bare_feeder_exact_per_period/hopping"),
]
FLOORS = [
    ("exact_per_period/case1_uniform", "floor_exact_per_period/case1_uniform"),
    ("exact_per_period/case3_uniform", "floor_exact_per_period/case3_uniform"),
    ("time_stepping_per_step/case1_uniform", "floor_time_stepping_per_step/case1_uniform"),
    ("time_stepping_per_step/case3_uniform", "floor_time_stepping_per_step/case3_uniform"),
    ("planar_point_per_step", "floor_planar_point_per_step"),
]


def main(path: str, key: str = "cpu_time") -> None:
    runs: dict[str, list] = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "iteration":
            runs.setdefault(b["run_name"], []).append(b)
    for k in runs:
        runs[k].sort(key=lambda b: b["repetition_index"])
    for label, pairs in (("bare", PAIRS), ("floor", FLOORS)):
        for lib, other in pairs:
            if lib not in runs or other not in runs:
                continue
            ratios = [a[key] / b[key] for a, b in zip(runs[lib], runs[other])]
            print(f"{lib:40s} / {label}: median {statistics.median(ratios):.3f} "
                  f"[{min(ratios):.3f}, {max(ratios):.3f}] over {len(ratios)} repetitions")


if __name__ == "__main__":
    main(*sys.argv[1:])
