#!/usr/bin/python3
"""A 16-point patch to 1e-6: Moreau against the patch integrator (issue 22, item 4).

    build/release/bench/selfalign_bench_simulate --benchmark_filter=planar_patch_accuracy \
        --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
        --benchmark_out=acc.json --benchmark_out_format=json
    bench/planar_patch_accuracy.py acc.json [target]

Each run of bench_simulate.cpp's planar_patch_accuracy_* benchmarks reports its end-pose error
against the integrator at tolerance 1e-13 (counter "error"). Per method, the cheapest setting
whose error is within the target (default 1e-6) is picked; the ratio of the two times (CPU time
per run) is taken repetition by repetition and printed as its median with min-max, with every
setting's error and time. Standard library only.
"""
import json
import statistics
import sys


def main(path: str, target: float = 1e-6) -> None:
    runs: dict[str, list] = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "iteration":
            runs.setdefault(b["run_name"], []).append(b)
    picked = {}
    for method in ("moreau", "integrator"):
        names = sorted(n for n in runs if n.startswith(f"planar_patch_accuracy_{method}/"))
        for n in names:
            r = runs[n]
            ms = [x["cpu_time"] * {"ms": 1, "us": 1e-3, "ns": 1e-6, "s": 1e3}[x["time_unit"]] for x in r]
            print(f"{n:40s} error {r[0]['error']:.3e}  time {statistics.median(ms):10.3f} ms "
                  f"[{min(ms):.3f}-{max(ms):.3f}]")
        within = [n for n in names if runs[n][0]["error"] <= target]
        if not within:
            print(f"{method}: no setting within {target:g}")
            return
        picked[method] = min(within, key=lambda n: statistics.median(x["cpu_time"] for x in runs[n]))
    a, b = runs[picked["moreau"]], runs[picked["integrator"]]
    ratios = [x["cpu_time"] / y["cpu_time"] for x, y in zip(a, b)]
    print(f"to {target:g}: {picked['moreau']} / {picked['integrator']} = "
          f"{statistics.median(ratios):.0f}x [{min(ratios):.0f}-{max(ratios):.0f}] "
          f"({len(ratios)} repetitions)")


if __name__ == "__main__":
    main(sys.argv[1], *(float(a) for a in sys.argv[2:3]))
