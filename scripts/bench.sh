#!/usr/bin/env bash
# Sets up, builds (Release) and runs the benchmark runner; rewrites the results section of
# docs/benchmarks.md and docs/benchmarks.csv. Extra arguments go to bimdf_bench, e.g.
#   scripts/bench.sh --scaling 1000,10000 --repeats 3 --milp-seconds 0
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
build="${BUILD_DIR:-$root/build-release}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBIMDF_BUILD_TESTS=OFF \
  -DBIMDF_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target bimdf_bench bimdf_cli
instances=()
[ -d "$root/../shared/data/instances" ] && instances=(--instances "$root/../shared/data/instances")
[ -d "$root/../shared/data/layouts" ] && instances+=(--layouts "$root/../shared/data/layouts")
"$build/bin/bimdf_bench" "${instances[@]}" --csv "$root/docs/benchmarks.csv" \
  --markdown "$root/docs/benchmarks.md" --milp-seconds 10 "$@"
