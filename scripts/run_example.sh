#!/usr/bin/env bash
# Sets up (Debian packages), builds the bimdf CLI and runs the main job on the bundled example, a
# real Bi-MDF instance (the Stanford bunny's quantization model from QuadWild): validate it and
# print its summary, solve it exactly, write the solution JSON and verify it with
# `bimdf check`; then quantize the bunny's patch layout itself (bimdf quantize), writing the
# integer subside lengths as JSON. Usage: scripts/run_example.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
build="${BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target bimdf_cli
example="$root/examples/npm_bunny__flow_noalign_lemon_0.bimdf"
solution="$build/npm_bunny.solution.json"
"$build/bin/bimdf" info "$example"
echo
"$build/bin/bimdf" solve "$example" -o "$solution"
echo
"$build/bin/bimdf" check "$example" "$solution"
echo "solution written to $solution"
echo
layout="$root/examples/npm_bunny/npm_bunny.obj"
quantization="$build/npm_bunny.quant.json"
"$build/bin/bimdf" quantize "$layout"
"$build/bin/bimdf" quantize "$layout" -o "$quantization" >/dev/null
echo "quantization written to $quantization"
