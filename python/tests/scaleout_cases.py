"""The studies test_scaleout.py and mpi_scaleout.py run locally and through an executor."""

import numpy as np

import selfalign as sa

REQUEST = sa.DesignRequest(mass=0.02, width=0.003, mu=0.2, c_mu=2.5, distance=0.04,
                           stroke_max=0.002, acceleration_max=50.0, frequency_max=30.0,
                           tolerance=1e-4)
UNCERTAINTY = sa.ProcessUncertainty(mu="normal:0.2,5%", c_mu="normal:2.5,5%")
PROCESS = sa.Process(period=0.1, stroke=0.002, a2=4.2, a3=3.0, x_mu=0.0375)


def sweep_case(executor):
    a2 = np.linspace(0.8, 3.0, 7)
    a3 = np.linspace(0.5, 2.5, 5)
    local = sa.sweep_accelerations(1.0, 0.084, a2, a3)
    remote = sa.sweep_accelerations(1.0, 0.084, a2, a3, executor=executor, chunk_size=2)
    return local, remote


def monte_carlo_case(executor):
    local = sa.monte_carlo(REQUEST, PROCESS, UNCERTAINTY, runs=3000, seed=5)
    remote = sa.monte_carlo(REQUEST, PROCESS, UNCERTAINTY, runs=3000, seed=5, executor=executor,
                            chunk_size=700)
    return local, remote


def same_dicts(a, b):
    """What differs between two dicts of arrays, byte for byte (empty: identical)."""
    problems = []
    if set(a) != set(b):
        problems.append(f"keys {sorted(set(a) ^ set(b))}")
    for key in set(a) & set(b):
        x, y = np.asarray(a[key]), np.asarray(b[key])
        if x.dtype != y.dtype or x.shape != y.shape or x.tobytes() != y.tobytes():
            problems.append(key)
    return problems
