#!/usr/bin/env python3
"""Whole-process time of `bimdf solve` on small instances (issue 25, item 5) against a lower
bound of libSatsuma's timing driver's process, which cannot be run here.

The bound: that driver is a dynamically linked C++ program that reads the .bimdf file with
iostreams, solves and prints. This script compiles a program that only does the reading (g++
-O2, dynamically linked, like the driver) and times it beside `bimdf solve FILE -o OUT`,
alternating, medians of --runs processes each; adding libSatsuma's own solve time from the
instances' README (measured in its process, reading excluded) gives a time its driver cannot
beat. bimdf is "no slower" where its process takes at most that bound.

    python3 bench/process_time.py --cli build-release/bin/bimdf \
        --instances ../shared/data/instances --max-edges 300

Prints a markdown table (instance, edges, bimdf process, reading program, libSatsuma solve,
bound, ratio).
"""

import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time

READER = r"""
#include <fstream>
#include <iostream>
#include <string>
#include <vector>
int main(int argc, char** argv) {
  std::ifstream in(argv[1]);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  std::cout << tokens.size() << "\n";
}
"""


def libsatsuma_times(instances):
    """file → (edges, libSatsuma exact ms) from the instances' README table."""
    times = {}
    with open(os.path.join(instances, "README.md"), encoding="utf-8") as readme:
        for line in readme:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) == 7 and cells[0].endswith(".bimdf") and re.match(r"^[\d.]+$", cells[6]):
                times[cells[0]] = (int(cells[2]), float(cells[6]))
    return times


def process_ms(command):
    start = time.perf_counter()
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return (time.perf_counter() - start) * 1000


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default="build-release/bin/bimdf")
    parser.add_argument("--instances", default="../shared/data/instances")
    parser.add_argument("--max-edges", type=int, default=300)
    parser.add_argument("--runs", type=int, default=200)
    args = parser.parse_args()
    reference = libsatsuma_times(args.instances)
    chosen = sorted((edges, name) for name, (edges, _) in reference.items()
                    if edges <= args.max_edges)
    with tempfile.TemporaryDirectory() as tmp:
        source, reader = os.path.join(tmp, "reader.cpp"), os.path.join(tmp, "reader")
        with open(source, "w", encoding="utf-8") as out:
            out.write(READER)
        subprocess.run(["g++", "-O2", source, "-o", reader], check=True)
        solution = os.path.join(tmp, "solution.json")
        print("| instance | edges | bimdf solve process (ms) | reading program (ms) | "
              "libSatsuma solve (ms) | libSatsuma process at least (ms) | bimdf / bound |")
        print("|---|---|---|---|---|---|---|")
        for edges, name in chosen:
            path = os.path.join(args.instances, name)
            ours, theirs = [], []
            for run in range(args.runs):
                commands = [("ours", [args.cli, "solve", path, "-o", solution]),
                            ("reader", [reader, path])]
                for which, command in commands if run % 2 == 0 else reversed(commands):
                    (ours if which == "ours" else theirs).append(process_ms(command))
            ours_ms, reader_ms = statistics.median(ours), statistics.median(theirs)
            bound = reader_ms + reference[name][1]
            print(f"| {name} | {edges} | {ours_ms:.2f} | {reader_ms:.2f} | "
                  f"{reference[name][1]:.3f} | {bound:.2f} | {ours_ms / bound:.2f} |")


if __name__ == "__main__":
    main()
