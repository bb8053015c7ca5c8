#!/usr/bin/env bash
# Sets up (Debian packages), builds the bimdf CLI and runs the main job on the bundled example:
# remesh the bunny's QuadWild patch layout end to end (quantize exactly, tessellate, smooth,
# measure), draw the quad mesh into a PNG; remesh the same bunny from its bare triangle mesh
# (bimdf's own cross field and layout, issue 51); then solve a real Bi-MDF instance (the bunny's
# quantization model from QuadWild) exactly and verify the solution with `bimdf check`.
# Usage: scripts/run_example.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
build="${BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target bimdf_cli
layout="$root/examples/npm_bunny/npm_bunny.obj"
"$build/bin/bimdf" remesh "$layout" -o "$build/npm_bunny.quads.obj"
"$build/bin/bimdf" render "$build/npm_bunny.quads.obj" -o "$build/npm_bunny.png"
echo
# The layout's triangles alone (no NAME.patch beside the copy): a bare mesh.
bare="$build/npm_bunny_bare.obj"
cp "$layout" "$bare"
"$build/bin/bimdf" remesh "$bare" -o "$build/npm_bunny_bare.quads.obj"
echo
example="$root/examples/npm_bunny__flow_noalign_lemon_0.bimdf"
solution="$build/npm_bunny.solution.json"
"$build/bin/bimdf" info "$example"
echo
"$build/bin/bimdf" solve "$example" -o "$solution"
echo
"$build/bin/bimdf" check "$example" "$solution"
echo "solution written to $solution"
