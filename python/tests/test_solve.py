"""bimdf.solve and bimdf.check: optima against brute force and against the CLI, infeasibility,
limits, progress, the GIL and Ctrl-C."""

import itertools
import json
import math
import os
import random
import signal
import threading
import time

import numpy as np
import pytest

import bimdf
from helpers import BUNNY_PROBLEM, run_cli, shared_data


def brute_force(num_nodes, ends, kinds, lower, upper, targets, weights, demand):
    """Minimum of Σ w (x − t)² over every integer flow in the (finite) bounds, or None."""
    best = None
    for x in itertools.product(*[range(lo, up + 1) for lo, up in zip(lower, upper)]):
        net = [0] * num_nodes
        for e, (a, b) in enumerate(ends):
            net[a] += kinds[e][0] * x[e]
            if b >= 0:
                net[b] += kinds[e][1] * x[e]
        if net != list(demand):
            continue
        cost = sum(w * (xe - t) ** 2 for xe, t, w in zip(x, targets, weights))
        best = cost if best is None else min(best, cost)
    return best


def random_tiny_problem(rng):
    n, m = rng.randint(1, 4), rng.randint(1, 5)
    ends, kinds = [], []
    for _ in range(m):
        a = rng.randrange(n)
        b = rng.randrange(-1, n)  # -1: an outer edge
        ends.append([a, b])
        kinds.append([rng.choice([1, -1]), 0 if b < 0 else rng.choice([1, -1])])
        if a == b and kinds[-1][0] != kinds[-1][1]:  # a head-tail loop is not allowed
            kinds[-1][1] = kinds[-1][0]
    lower = [rng.randint(-2, 1) for _ in range(m)]
    upper = [lo + rng.randint(0, 4) for lo in lower]
    targets = [rng.uniform(-2, 4) for _ in range(m)]
    weights = [rng.choice([0.5, 1.0, 2.0]) for _ in range(m)]
    demand = [rng.randint(-3, 3) for _ in range(n)]
    return n, ends, kinds, lower, upper, targets, weights, demand


def test_optimum_equals_brute_force_on_random_tiny_problems():
    rng = random.Random(7)
    solved = infeasible = 0
    for _ in range(300):
        n, ends, kinds, lower, upper, targets, weights, demand = random_tiny_problem(rng)
        p = bimdf.Problem(n, ends=ends, kinds=kinds, lower=lower, upper=upper, demand=demand,
                          cost={"kind": "quad", "target": targets, "weight": weights})
        expected = brute_force(n, ends, kinds, lower, upper, targets, weights, demand)
        if expected is None:
            with pytest.raises(bimdf.Infeasible):
                bimdf.solve(p)
            infeasible += 1
            continue
        s = bimdf.solve(p)
        assert s.status == "optimal"
        assert s.objective == pytest.approx(expected, abs=1e-9)
        assert s.flow.dtype == np.int64 and s.flow.shape == (len(ends),)
        c = bimdf.check(p, s.flow)
        assert c.feasible and c.objective == pytest.approx(s.objective)
        solved += 1
    assert solved > 50 and infeasible > 20  # both kinds of answer were exercised


def cli_objective(path):
    return json.loads(run_cli("solve", path, "--json").stdout)["objective"]


def test_objective_equals_the_cli_on_the_bundled_instance():
    s = bimdf.solve(bimdf.read(str(BUNNY_PROBLEM)))
    assert s.status == "optimal"
    assert s.objective == pytest.approx(cli_objective(BUNNY_PROBLEM), rel=1e-12)
    assert s.lower_bound == pytest.approx(s.objective) and s.gap == pytest.approx(0, abs=1e-12)


@pytest.mark.parametrize("name", ["mushroom__flow_0.bimdf", "camel__flow_1.bimdf",
                                  "ChineseDragon-10kv__flow_0.bimdf"])
def test_objective_equals_the_cli_and_the_reference_optimum_on_shared_instances(name):
    folder = shared_data("instances")
    expected = {}
    with open(folder / "expected.tsv") as f:
        header = f.readline().split("\t")
        for line in f:
            row = dict(zip(header, line.rstrip("\n").split("\t")))
            expected[row["file"]] = float(row["optimum"])
    p = bimdf.read(str(folder / name))
    s = bimdf.solve(p)
    assert s.status == "optimal"
    assert s.objective == pytest.approx(cli_objective(folder / name), rel=1e-12)
    assert s.objective == pytest.approx(expected[name], rel=1e-8)
    assert bimdf.check(p, s.flow).feasible


def test_approximation_and_limits_give_feasible_flows_no_better_than_the_optimum():
    p = bimdf.read(str(BUNNY_PROBLEM))
    optimum = bimdf.solve(p).objective
    approx = bimdf.solve(p, exact=False)
    assert approx.status == "feasible" and approx.objective >= optimum - 1e-12
    assert bimdf.check(p, approx.flow).feasible
    limited = bimdf.solve(p, max_rounds=1)
    assert limited.status == "feasible"
    assert limited.lower_bound <= optimum + 1e-12 <= limited.objective + 2e-12
    assert bimdf.solve(p, threads=2).objective == pytest.approx(optimum, rel=1e-12)
    with pytest.raises(ValueError, match="^time_limit must be a positive number of seconds$"):
        bimdf.solve(p, time_limit=float("nan"))
    with pytest.raises(ValueError, match="^threads must be >= 1, got 0$"):
        bimdf.solve(p, threads=0)


def test_infeasible_carries_its_proof():
    # An outer head edge of capacity 3 cannot meet a demand of 5.
    p = bimdf.Problem(1, ends=[[0, -1]], kinds=[[1, 0]], upper=[3], demand=[5])
    with pytest.raises(bimdf.Infeasible, match="infeasible"):
        bimdf.solve(p)
    # Odd demand on a node that only even amounts can change (a head-head loop).
    q = bimdf.Problem(1, ends=[[0, 0]], kinds=[[1, 1]], upper=[9], demand=[3])
    with pytest.raises(bimdf.Infeasible):
        bimdf.solve(q)


def test_check_lists_violations():
    p = bimdf.Problem(2, ends=[[0, 1]], kinds=[[1, -1]], upper=[5], demand=[1, -1])
    c = bimdf.check(p, [7])
    assert not c.feasible
    assert c.bound_violations == [(0, 7)]
    assert c.conservation_violations == [(0, 7, 1), (1, -7, -1)]
    assert not bimdf.check(p, [1, 2]).size_ok
    assert bimdf.check(p, [1]).feasible


def test_progress_reports_rounds_and_its_exception_cancels_the_solve():
    p = bimdf.read(str(BUNNY_PROBLEM))
    events = []
    s = bimdf.solve(p, progress=events.append)
    assert events[0]["event"] == "approximated"
    assert sum(e["event"] == "round" for e in events) == s.rounds

    def stop(event):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="^stop here$"):
        bimdf.solve(p, progress=stop)


@pytest.fixture(scope="module")
def large_problem(tmp_path_factory):
    """A generated QuadWild-like instance of ~30k edges: a solve long enough (~1 s) to watch."""
    path = tmp_path_factory.mktemp("gen") / "g.bimdf"
    run_cli("generate", "quadwild", "--size", "30000", "--seed", "3", "-o", path)
    return bimdf.read(str(path))


def test_solve_releases_the_gil(large_problem):
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        events = []
        start = time.perf_counter()
        bimdf.solve(large_problem, progress=lambda e: events.append(time.perf_counter()))
        end = time.perf_counter()
    finally:
        stop.set()
        counter.join()
    # Ticks between the solve's own progress reports happened while C++ was solving: with the
    # GIL held there would be none between the first report and the end.
    first = events[0]
    inside = [t for t in ticks if first < t < end]
    assert end - first > 0.05, "the instance solved too fast to tell"
    assert len(inside) >= 10


def test_ctrl_c_interrupts_a_solve(large_problem):
    whole = []
    bimdf.solve(large_problem, progress=whole.append)
    # SIGINT is sent right after the first progress report, while C++ works without the GIL;
    # the solve must stop at a later report with KeyboardInterrupt instead of finishing.
    first_report = threading.Event()
    events = []

    def report(event):
        events.append(event)
        first_report.set()

    def interrupt():
        first_report.wait()
        os.kill(os.getpid(), signal.SIGINT)

    killer = threading.Thread(target=interrupt)
    killer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            bimdf.solve(large_problem, progress=report)
    finally:
        first_report.set()
        killer.join()
    assert 1 <= len(events) < len(whole)
