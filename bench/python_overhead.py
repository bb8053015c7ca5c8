#!/usr/bin/env python3
"""What a solve costs through Python: bimdf.solve's wall time (validation, the solve, the flow
and statistics handed back as numpy / dict) against the CLI's own solve time (`time_solve_s` of
`bimdf solve --json`, reading excluded), medians of --repeats runs each, on the given instances.

    PYTHONPATH=build/python python3 bench/python_overhead.py --cli build/bin/bimdf \
        ../shared/data/instances/bull__flow_0.bimdf …

Prints a markdown table (instance, nodes, edges, objective, CLI solve, Python solve, overhead).
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import bimdf


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("instances", nargs="+")
    parser.add_argument("--cli", default="build/bin/bimdf")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    print("| instance | nodes | edges | objective | CLI solve (ms) | Python solve (ms) | overhead |")
    print("|---|---|---|---|---|---|---|")
    for path in args.instances:
        problem = bimdf.read(path)
        cli_times, py_times = [], []
        objectives = set()
        for _ in range(args.repeats):
            out = subprocess.run([args.cli, "solve", path, "--json"], capture_output=True,
                                 text=True, check=True).stdout
            result = json.loads(out)
            cli_times.append(result["stats"]["time_solve_s"])
            objectives.add(round(result["objective"], 9))
            start = time.perf_counter()
            solution = bimdf.solve(problem)
            py_times.append(time.perf_counter() - start)
            objectives.add(round(solution.objective, 9))
        if len(objectives) != 1:
            sys.exit(f"{path}: objectives differ: {sorted(objectives)}")
        cli, py = statistics.median(cli_times), statistics.median(py_times)
        print(f"| {os.path.basename(path)} | {problem.num_nodes} | {problem.num_edges} | "
              f"{objectives.pop():.9g} | {cli * 1e3:.1f} | {py * 1e3:.1f} | "
              f"{(py / cli - 1) * 100:+.1f}% |")


if __name__ == "__main__":
    main()
