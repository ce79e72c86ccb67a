"""The Solver: set up once, solved again with new loads or gaps, warm starts; the callback sees
every iteration and may stop the run; errors are exceptions; the GIL is released while it
solves."""

import threading
import time

import numpy as np
import pytest

import signorini
from conftest import SOURCE

PAPER = SOURCE / "examples/paper.toml"


@pytest.fixture(scope="module")
def model():
    return signorini.Model(signorini.Problem(PAPER, overrides={"mesh.nx": 60, "mesh.ny": 20}))


def test_new_loads_with_a_warm_start_equal_a_cold_solve(model):
    solver = signorini.Solver(model)
    first = solver.solve()
    solver.warm_start(first)
    assert solver.solve().iterations == 1  # from the solution itself
    solver.set_load_factor(1.2)
    solver.warm_start(first)
    warm = solver.solve()
    cold_solver = signorini.Solver(model)
    cold_solver.set_loads(model.free_loads(1.2))
    cold = cold_solver.solve()
    assert warm.summary["warm_started"] and not cold.summary["warm_started"]
    assert warm.iterations <= cold.iterations
    assert np.abs(warm.u - cold.u).max() <= 1e-8 * np.abs(cold.u).max()
    assert warm.load_factor == 1.2 and cold.load_factor == 1.0
    # loads times 1.2 and no gap: the solution scales with them
    np.testing.assert_allclose(cold.u, 1.2 * first.u, rtol=0, atol=1e-9 * np.abs(cold.u).max())
    # a step of a loading history the problem does not have
    with pytest.raises(signorini.InputError, match="step = 99 is not a step"):
        solver.set_load_factor(1.0, step=99)


def test_set_gaps_moves_the_foundation(model):
    solver = signorini.Solver(model)
    base = solver.solve()
    solver.set_gaps(np.full(model.num_contact_nodes, 1.0))  # far away: no contact
    free = solver.solve()
    assert base.num_active > 0 and free.num_active == 0
    assert free.contact_force == 0.0


def test_the_callback_sees_iterations_and_may_stop(model):
    events = []
    solver = signorini.Solver(model, callback=events.append)
    result = solver.solve()
    assert max(e["outer"] for e in events) == result.iterations
    assert [e["outer"] for e in events if e["kind"] == "outer"] == list(range(1, result.iterations))
    assert {"inner", "residual", "active"} <= set(events[0])

    stopper = signorini.Solver(model, callback=lambda e: e["kind"] != "outer")
    stopped = stopper.solve()  # a stop asked for is no error
    assert not stopped.converged and stopped.termination == "stopped_by_callback"
    assert stopped.iterations == 1


def test_an_exception_in_the_callback_stops_and_propagates(model):
    def fail(event):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        signorini.Solver(model, callback=fail).solve()


def test_a_solver_refuses_a_second_solve_while_it_solves(model):
    holder = {}

    def again(event):
        holder["solver"].solve()

    holder["solver"] = signorini.Solver(model, callback=again)
    with pytest.raises(RuntimeError, match="solving already"):
        holder["solver"].solve()


def test_not_converged_raises_convergence_error_with_the_result():
    problem = signorini.Problem(PAPER,
                                overrides={"mesh.nx": 60, "mesh.ny": 20,
                                           "solver.max_uzawa_iterations": 2})
    solver = signorini.Solver(signorini.Model(problem))
    with pytest.raises(signorini.ConvergenceError, match="not converged") as e:
        solver.solve()
    assert not e.value.result.converged
    assert "residual" in e.value.result.message or "KKT" in e.value.result.message
    assert isinstance(e.value, RuntimeError)
    unchecked = solver.solve(check=False)
    assert not unchecked.converged


def test_bad_loads_and_gaps_raise_input_error(model):
    solver = signorini.Solver(model)
    with pytest.raises(signorini.InputError, match=r"Solver.set_loads: b: expected 2520 numbers"):
        solver.set_loads(np.zeros(3))
    b = model.b.copy()
    b[7] = np.nan
    with pytest.raises(signorini.InputError, match=r"b\[7\] is not finite"):
        solver.set_loads(b)
    with pytest.raises(signorini.InputError, match="gaps: expected 61 numbers"):
        solver.set_gaps([0.0])
    other = signorini.Model(signorini.Problem(PAPER,
                                              overrides={"mesh.nx": 6, "mesh.ny": 2}))
    with pytest.raises(signorini.InputError, match="another model"):
        solver.warm_start(signorini.solve(other))


def test_arrays_are_read_only_views_that_keep_the_result_alive(model):
    result = signorini.Solver(model).solve()
    u, p = result.u, result.pressure
    assert not u.flags.writeable and not u.flags.owndata
    with pytest.raises(ValueError):
        u[0] = 1.0
    expected = u.copy()
    del result
    import gc
    gc.collect()
    np.testing.assert_array_equal(u, expected)  # the view keeps its Result alive
    assert p.shape == (model.num_contact_nodes,)


def test_the_gil_is_released_while_solving():
    problem = signorini.Problem(PAPER,
                                overrides={"mesh.nx": 240, "mesh.ny": 80,
                                           "solver.schur_complement": False})
    solver = signorini.Solver(signorini.Model(problem))
    done = threading.Event()
    seconds = []

    def run():
        start = time.perf_counter()
        solver.solve()
        seconds.append(time.perf_counter() - start)
        done.set()

    ticks = 0
    thread = threading.Thread(target=run)
    thread.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    thread.join()
    # Python ran alongside: about one tick per millisecond of the solve (with the GIL held it
    # would have run none until the solve returned).
    assert seconds[0] > 0.02
    assert ticks >= 0.25 * seconds[0] / 0.001


def test_a_loading_history_step_by_step_with_friction(tmp_path):
    steps = []
    last = signorini.solve(signorini.Problem(SOURCE / "examples/cattaneo_mindlin.toml"),
                           output=tmp_path, each_step=lambda k, r: steps.append((k, r)))
    assert [k for k, _ in steps] == [1, 2, 3, 4]
    assert [r.load_step for _, r in steps] == [1, 2, 3, 4]
    np.testing.assert_array_equal(steps[-1][1].u, last.u)
    n = last.pressure.size
    assert last.tangential.shape == (n, 1) and last.slip.shape == (n,)
    states = last.contact["state"]
    assert {"sticking", "sliding"} <= set(states)
    # |t| <= mu p at every node, reached where it slides (mu = 0.5 in the example)
    mu = 0.5
    t, p = np.abs(last.tangential[:, 0]), last.pressure
    assert np.all(t <= mu * p * (1 + 1e-8) + 1e-12 * p.max())
    sliding = np.array([s == "sliding" for s in states])
    np.testing.assert_allclose(t[sliding], mu * p[sliding], rtol=1e-6)
    assert (tmp_path / "solution.pvd").exists() and len(list((tmp_path / "steps").iterdir())) == 8
