"""Repeated solves hold no references and no memory: reference counts of the model and solver
come back, Python's allocations (tracemalloc) and the process's resident memory do not grow."""

import gc
import sys
import tracemalloc

import signorini
from conftest import SOURCE


def resident_kb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4


def test_repeated_solves_do_not_grow():
    model = signorini.Model(signorini.Problem(SOURCE / "examples/paper.toml",
                                              overrides={"mesh.nx": 60, "mesh.ny": 20}))
    events = []
    solver = signorini.Solver(model, callback=lambda e: events.clear())

    def round_of(n):
        previous = None
        for k in range(n):
            solver.set_load_factor(1.0 + 0.001 * (k % 10))
            if previous is not None:
                solver.warm_start(previous)
            previous = solver.solve()
            _ = previous.u, previous.pressure, previous.displacement, previous.summary
        return previous

    round_of(50)  # warm-up: caches, the allocator's arenas
    gc.collect()
    counts = (sys.getrefcount(model), sys.getrefcount(solver))
    tracemalloc.start()
    before_py = tracemalloc.get_traced_memory()[0]
    before_rss = resident_kb()
    round_of(1000)
    gc.collect()
    after_py = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    after_rss = resident_kb()
    assert (sys.getrefcount(model), sys.getrefcount(solver)) == counts
    assert after_py - before_py < 64 * 1024, (before_py, after_py)
    # 1000 solves of 2520 unknowns: a leak of one vector per solve would be 20 MB.
    assert after_rss - before_rss < 4 * 1024, (before_rss, after_rss)
