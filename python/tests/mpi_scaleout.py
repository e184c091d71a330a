"""Run under `mpiexec -n 2 python -m mpi4py.futures mpi_scaleout.py OUT`: a sweep and a Monte
Carlo through mpi4py.futures.MPIPoolExecutor (rank 1 is the worker), each compared with the
local run; writes "identical" or what differs to OUT (test_scaleout.py reads it)."""

import sys

import numpy as np
from mpi4py.futures import MPIPoolExecutor

import selfalign as sa
from scaleout_cases import monte_carlo_case, same_dicts, sweep_case

if __name__ == "__main__":
    out = sys.argv[1]
    with MPIPoolExecutor() as executor:
        sweep_local, sweep_remote = sweep_case(executor)
        mc_local, mc_remote = monte_carlo_case(executor)
    problems = same_dicts(sweep_local, sweep_remote)
    if mc_local != mc_remote:
        problems.append("monte carlo differs")
    with open(out, "w") as f:
        f.write("identical" if not problems else "; ".join(problems))
