"""Sweeps, positioning surfaces and Monte Carlo spread over a ``concurrent.futures.Executor``.

Local threads stay the default: every study runs in parallel inside the library. Given an
``executor`` (Dask distributed's ``Client.get_executor()``, ``mpi4py.futures.MPIPoolExecutor``,
or the standard library's ``ProcessPoolExecutor``), the wrappers below cut the study into
chunks of points — rows of the (a2, a3) grid, runs ``first_run .. first_run + n`` of a Monte
Carlo — submit one task per chunk, and merge the chunks in order. Each chunk is computed by the
same library call on the same inputs as in a local run, and cells / runs are independent and
deterministic, so the merged result is identical, byte for byte, to the local one
(docs/scale-out.md). The arguments (profiles, friction laws, options, requests, uncertainty)
travel pickled; every selfalign value type pickles.

Inside a chunk the library uses ``threads`` workers; with an executor the default is 1 per
chunk (one task per worker core), which the caller may raise.
"""

from __future__ import annotations

import concurrent.futures
import math
from typing import Any, Callable

import numpy as np

from . import _selfalign

__all__ = ["map_chunks", "split", "sweep_accelerations", "sweep_period", "sweep_stroke",
           "positioning_surfaces", "monte_carlo"]


def split(n: int, chunk_size: int | None, default_chunks: int = 16) -> list[tuple[int, int]]:
    """[begin, end) ranges covering range(n) in order, each of chunk_size items (the last may be
    shorter); chunk_size None: about `default_chunks` chunks."""
    if chunk_size is None:
        chunk_size = max(1, math.ceil(n / default_chunks))
    if not isinstance(chunk_size, (int, np.integer)) or chunk_size < 1:
        raise _selfalign.InvalidParameter(f"invalid chunk_size = {chunk_size}: must be an integer >= 1")
    return [(b, min(n, b + int(chunk_size))) for b in range(0, n, int(chunk_size))]


def map_chunks(executor: concurrent.futures.Executor, fn: Callable, chunks: list[tuple],
               progress: Callable[[int, int], Any] | None = None,
               sizes: list[int] | None = None) -> list:
    """Submits fn(*args) for each args in chunks; returns the results in chunk order. progress,
    if given, is called as progress(done, total) (in points when sizes are given, else chunks)
    as chunks complete. A chunk's exception is re-raised after the others are cancelled."""
    futures = [executor.submit(fn, *args) for args in chunks]
    index = {f: k for k, f in enumerate(futures)}
    sizes = sizes or [1] * len(chunks)
    total, done = sum(sizes), 0
    try:
        for f in concurrent.futures.as_completed(futures):
            f.result()  # raises the chunk's error
            done += sizes[index[f]]
            if progress is not None:
                progress(done, total)
    except BaseException:
        for f in futures:
            f.cancel()
        raise
    return [f.result() for f in futures]


def _merge_rows(parts: list[dict], keep: tuple[str, ...]) -> dict:
    out = {}
    for key in parts[0]:
        out[key] = parts[0][key] if key in keep else np.concatenate([p[key] for p in parts], axis=0)
    return out


# Module-level chunk functions: workers import them by name (selfalign.scaleout._...).
def _sweep_accelerations_chunk(period, stroke, a2, a3, kwargs):
    return _selfalign.sweep_accelerations(period, stroke, a2, a3, **kwargs)


def _family_chunk(name, family, fixed, values, kwargs):
    return getattr(_selfalign, name)(family, fixed, values, **kwargs)


def _positioning_chunk(period, stroke, table, a2, a3, kwargs):
    # table: (width, c_mu) of the two-region table, or (friction,) a FrictionMap
    return _selfalign.positioning_surfaces(period, stroke, *table, a2, a3, **kwargs)


def _monte_carlo_chunk(request, process, uncertainty, first_run, runs, kwargs):
    return _selfalign.monte_carlo(request, process, uncertainty, first_run=first_run, runs=runs,
                                  **kwargs)


def _chunk_kwargs(kwargs: dict) -> tuple[dict, Callable | None]:
    kwargs = dict(kwargs)
    progress = kwargs.pop("progress", None)
    kwargs.setdefault("threads", 1)
    return kwargs, progress


def sweep_accelerations(period, stroke, a2, a3, *, executor=None, chunk_size=None, **kwargs):
    if executor is None:
        return _selfalign.sweep_accelerations(period, stroke, a2, a3, **kwargs)
    a2 = np.ascontiguousarray(a2, dtype=float)
    a3 = np.ascontiguousarray(a3, dtype=float)
    kw, progress = _chunk_kwargs(kwargs)
    ranges = split(len(a2), chunk_size)
    parts = map_chunks(executor, _sweep_accelerations_chunk,
                       [(period, stroke, a2[b:e], a3, kw) for b, e in ranges], progress,
                       [(e - b) * len(a3) for b, e in ranges])
    return _merge_rows(parts, keep=("a3",)) if parts else \
        _selfalign.sweep_accelerations(period, stroke, a2, a3, **kwargs)


def _family_sweep(name, family, fixed, values, executor, chunk_size, kwargs):
    if executor is None:
        return getattr(_selfalign, name)(family, fixed, values, **kwargs)
    values = np.ascontiguousarray(values, dtype=float)
    kw, progress = _chunk_kwargs(kwargs)
    ranges = split(len(values), chunk_size)
    parts = map_chunks(executor, _family_chunk,
                       [(name, family, fixed, values[b:e], kw) for b, e in ranges], progress,
                       [e - b for b, e in ranges])
    return _merge_rows(parts, keep=()) if parts else \
        getattr(_selfalign, name)(family, fixed, values, **kwargs)


def sweep_period(family, stroke, periods, *, executor=None, chunk_size=None, **kwargs):
    return _family_sweep("sweep_period", family, stroke, periods, executor, chunk_size, kwargs)


def sweep_stroke(family, period, strokes, *, executor=None, chunk_size=None, **kwargs):
    return _family_sweep("sweep_stroke", family, period, strokes, executor, chunk_size, kwargs)


def positioning_surfaces(period, stroke, *table_and_grid, executor=None, chunk_size=None,
                         **kwargs):
    # table_and_grid: (width, c_mu, a2, a3) on the two-region table, or (friction, a2, a3) on a
    # FrictionMap where it stands; either also by keyword, as the extension's two overloads.
    if executor is None:
        return _selfalign.positioning_surfaces(period, stroke, *table_and_grid, **kwargs)
    on_map = ((table_and_grid and isinstance(table_and_grid[0], _selfalign.FrictionMap))
              or "friction" in kwargs)
    names = ("friction", "a2", "a3") if on_map else ("width", "c_mu", "a2", "a3")
    given = dict(zip(names, table_and_grid))
    rest = dict(kwargs)
    for name in names:
        if name in rest:
            given[name] = rest.pop(name)
    if set(given) != set(names) or len(table_and_grid) > len(names):  # the extension's error
        return _selfalign.positioning_surfaces(period, stroke, *table_and_grid, **kwargs)
    table = tuple(given[n] for n in names[:-2])
    a2 = np.ascontiguousarray(given["a2"], dtype=float)
    a3 = np.ascontiguousarray(given["a3"], dtype=float)
    kw, progress = _chunk_kwargs(rest)
    ranges = split(len(a2), chunk_size)
    parts = map_chunks(executor, _positioning_chunk,
                       [(period, stroke, table, a2[b:e], a3, kw) for b, e in ranges],
                       progress, [(e - b) * len(a3) for b, e in ranges])
    return _merge_rows(parts, keep=("a3",)) if parts else \
        _selfalign.positioning_surfaces(period, stroke, *table, a2, a3, **rest)


def monte_carlo(request, process, uncertainty, *, runs=10_000, first_run=0, executor=None,
                chunk_size=None, **kwargs):
    if executor is None:
        return _selfalign.monte_carlo(request, process, uncertainty, runs=runs,
                                      first_run=first_run, **kwargs)
    kw, progress = _chunk_kwargs(kwargs)
    ranges = split(int(runs), chunk_size)
    if not ranges:  # runs < 1: the library's own error
        return _selfalign.monte_carlo(request, process, uncertainty, runs=runs,
                                      first_run=first_run, **kwargs)
    parts = map_chunks(executor, _monte_carlo_chunk,
                       [(request, process, uncertainty, first_run + b, e - b, kw)
                        for b, e in ranges], progress, [e - b for b, e in ranges])
    return _selfalign.merge_monte_carlo(parts)


def _document(wrapper, wrapped):
    wrapper.__wrapped__ = wrapped
    wrapper.__doc__ = (wrapped.__doc__ or "") + """

executor: a concurrent.futures.Executor (Dask distributed's Client.get_executor(),
mpi4py.futures.MPIPoolExecutor, ProcessPoolExecutor, ...): the study is cut into chunks of
chunk_size points (default: about 16 chunks), one task each, merged in order into the same
result as a local run, byte for byte (selfalign.scaleout, docs/scale-out.md). threads is then
per chunk (default 1); progress(done, total) is called as chunks complete."""
    wrapper.__name__ = wrapped.__name__
    wrapper.__qualname__ = wrapped.__name__
    return wrapper


for _name in ("sweep_accelerations", "sweep_period", "sweep_stroke", "positioning_surfaces",
              "monte_carlo"):
    _document(globals()[_name], getattr(_selfalign, _name))
