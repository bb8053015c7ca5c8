#!/usr/bin/env bash
# Sets up (Debian packages), builds the bimdf CLI and runs the main job on the bundled example:
# validate a real Bi-MDF instance (the Stanford bunny's quantization model from QuadWild) and
# print its summary. Usage: scripts/run_example.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
build="${BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target bimdf_cli
"$build/bin/bimdf" info "$root/examples/npm_bunny__flow_noalign_lemon_0.bimdf"
