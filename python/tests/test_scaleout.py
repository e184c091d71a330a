"""Sweeps and Monte Carlo through concurrent.futures executors give the local result, byte for
byte: a process pool, a Dask LocalCluster with 2 workers (Client.get_executor()), and
mpi4py.futures under `mpiexec -n 2` (docs/scale-out.md)."""

import concurrent.futures
import os
import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest

import selfalign as sa
from scaleout_cases import PROCESS, REQUEST, UNCERTAINTY, monte_carlo_case, same_dicts, sweep_case

HERE = pathlib.Path(__file__).parent


def test_chunks_of_a_monte_carlo_merge_into_the_single_call():
    whole = sa.monte_carlo(REQUEST, PROCESS, UNCERTAINTY, runs=500, seed=9)
    parts = [sa.monte_carlo(REQUEST, PROCESS, UNCERTAINTY, runs=n, seed=9, first_run=b)
             for b, n in [(0, 123), (123, 300), (423, 77)]]
    assert sa.merge_monte_carlo(parts) == whole
    with pytest.raises(sa.InvalidParameter):
        sa.merge_monte_carlo([parts[1], parts[0]])


def test_process_pool_gives_the_local_results():
    with concurrent.futures.ProcessPoolExecutor(2) as ex:
        sweep_local, sweep_remote = sweep_case(ex)
        mc_local, mc_remote = monte_carlo_case(ex)
        surfaces_local = sa.positioning_surfaces(1.0, 0.084, 0.05, 2.5, [1.5, 2.0, 2.5], [1.0, 1.4],
                                                 options=sa.PositioningOptions(entries=3))
        surfaces_remote = sa.positioning_surfaces(1.0, 0.084, 0.05, 2.5, [1.5, 2.0, 2.5],
                                                  [1.0, 1.4],
                                                  options=sa.PositioningOptions(entries=3),
                                                  executor=ex, chunk_size=1)
        family = sa.ThreePhaseFamily(3.0, 0.9)
        periods = np.linspace(0.6, 1.4, 5)
        period_local = sa.sweep_period(family, 0.084, periods)
        period_remote = sa.sweep_period(family, 0.084, periods, executor=ex, chunk_size=2)
    assert same_dicts(sweep_local, sweep_remote) == []
    assert mc_local == mc_remote
    assert same_dicts(surfaces_local, surfaces_remote) == []
    assert same_dicts(period_local, period_remote) == []


def test_progress_counts_points_as_chunks_complete():
    seen = []
    with concurrent.futures.ThreadPoolExecutor(2) as ex:
        sa.monte_carlo(REQUEST, PROCESS, UNCERTAINTY, runs=300, executor=ex, chunk_size=100,
                       progress=lambda done, total: seen.append((done, total)))
    assert sorted(seen) == [(100, 300), (200, 300), (300, 300)]


def test_a_bad_chunk_size_names_the_parameter():
    with concurrent.futures.ThreadPoolExecutor(1) as ex:
        with pytest.raises(sa.InvalidParameter, match="chunk_size"):
            sa.monte_carlo(REQUEST, PROCESS, UNCERTAINTY, runs=10, executor=ex, chunk_size=0)


def test_dask_local_cluster_gives_the_local_results():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=50) as cluster, \
            distributed.Client(cluster) as client:
        executor = client.get_executor()
        sweep_local, sweep_remote = sweep_case(executor)
        mc_local, mc_remote = monte_carlo_case(executor)
    assert same_dicts(sweep_local, sweep_remote) == []
    assert mc_local == mc_remote
    assert mc_remote.runs == 3000


def test_mpi4py_futures_under_mpiexec_gives_the_local_results(tmp_path):
    pytest.importorskip("mpi4py")
    mpiexec = shutil.which("mpiexec")
    if mpiexec is None:
        pytest.skip("no mpiexec (Debian openmpi-bin)")
    out = tmp_path / "result.txt"
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", PYTHONPATH=str(HERE))
    r = subprocess.run([mpiexec, "-n", "2", sys.executable, "-m", "mpi4py.futures",
                        str(HERE / "mpi_scaleout.py"), str(out)],
                       env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr[-2000:]
    assert out.read_text() == "identical"
