"""Dask overhead per chunk of a Monte Carlo (docs/scale-out.md).

Runs the issue's 1e5-run Monte Carlo (the nominal design, mu and c_mu +-5 %) locally on 2
threads and through a Dask LocalCluster of 2 single-threaded worker processes
(Client.get_executor()) with chunks of 50 000, 10 000, 1 000 and 100 runs; every result is
checked byte-identical to the local one. Overhead per chunk = (Dask time - local time) / chunks.
Each configuration is timed `--repetitions` times, alternating; medians with min-max.

    .venv/bin/python bench/scaleout_overhead.py [--repetitions 5]
"""

import argparse
import statistics
import time

import distributed

import selfalign as sa

REQUEST = sa.DesignRequest(mass=0.02, width=0.003, mu=0.2, c_mu=2.5, distance=0.04,
                           stroke_max=0.002, acceleration_max=50, frequency_max=30, tolerance=1e-4)
UNCERTAIN = sa.ProcessUncertainty(mu="normal:0.2,5%", c_mu="normal:2.5,5%")
PROCESS = sa.Process(period=0.09767186838611738, stroke=0.002, a2=4.905, a3=2.6568750000000003,
                     x_mu=0.037)
RUNS = 100_000


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repetitions", type=int, default=5)
    args = parser.parse_args()
    chunks = [50_000, 10_000, 1_000, 100]
    times = {"local": []} | {c: [] for c in chunks}
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=50) as cluster, \
            distributed.Client(cluster) as client:
        executor = client.get_executor()
        sa.monte_carlo(REQUEST, PROCESS, UNCERTAIN, runs=1000, executor=executor)  # warm up
        for _ in range(args.repetitions):
            t0 = time.perf_counter()
            local = sa.monte_carlo(REQUEST, PROCESS, UNCERTAIN, runs=RUNS, threads=2)
            times["local"].append(time.perf_counter() - t0)
            for c in chunks:
                t0 = time.perf_counter()
                remote = sa.monte_carlo(REQUEST, PROCESS, UNCERTAIN, runs=RUNS, executor=executor,
                                        chunk_size=c)
                times[c].append(time.perf_counter() - t0)
                assert remote == local, f"chunk {c}: differs from the local run"
    local_median = statistics.median(times["local"])
    print(f"local, 2 threads: median {local_median * 1e3:.1f} ms "
          f"[{min(times['local']) * 1e3:.1f}-{max(times['local']) * 1e3:.1f}]")
    for c in chunks:
        n = RUNS // c
        t = times[c]
        per_chunk = [(x - local_median) / n * 1e3 for x in t]
        print(f"dask, {n:4d} chunks of {c:6d}: median {statistics.median(t) * 1e3:.1f} ms "
              f"[{min(t) * 1e3:.1f}-{max(t) * 1e3:.1f}], overhead per chunk "
              f"{statistics.median(per_chunk):.2f} ms [{min(per_chunk):.2f}-{max(per_chunk):.2f}]")


if __name__ == "__main__":
    main()
