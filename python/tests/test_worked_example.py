"""The worked example of docs/python.md runs and prints what the docs show."""

import subprocess
import sys

from helpers import REPO


def test_worked_example_runs_and_solves_the_problem_by_hand(tmp_path):
    png = tmp_path / "bunny.png"
    out = subprocess.run([sys.executable, str(REPO / "examples" / "python" / "worked_example.py"),
                          str(png)], capture_output=True, text=True, check=True, timeout=300)
    lines = out.stdout.splitlines()
    # By hand: the demands fix x0 = 3 - x3, x1 = x2 = 1 - x3; x3 = -1 costs
    # 0.6² + 0.8² + 2·0.5² + 0.5·1² = 2.0, x3 = 0 costs 4.7, x3 = -2 costs 8.3.
    assert lines[0] == "status optimal, objective 2.0000, flow [ 4  2  2 -1]"
    assert lines[1] == "check: feasible True, objective 2.0000"
    assert lines[2].startswith("remesh: ") and lines[2].endswith(", 0 inverted")
    assert lines[3].startswith("requantize --coarse: ")
    assert png.stat().st_size > 10000
