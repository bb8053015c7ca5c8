#!/usr/bin/env bash
# Installs the Debian packages bimdf needs to build, test and fuzz. Idempotent: it asks dpkg
# first and only calls apt-get when something is missing, so running it again is a no-op.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  nlohmann-json3-dev libcli11-dev  # file formats, command line
  liblemon-dev                     # network simplex and perfect matching (solver)
  googletest libgtest-dev          # unit and property tests
  coinor-libcbc-dev                # MILP oracle in tests and the baseline in benchmarks
  libeigen3-dev                    # linear algebra for the geometry stages
  zlib1g-dev                       # PNG compression (bimdf render)
  clang libclang-rt-14-dev         # libFuzzer harnesses in CI
  pybind11-dev python3-pybind11    # the Python module (python/)
  python3-dev python3-numpy python3-pytest python3-matplotlib
  parallel                         # scripts/batch.sh: whole folders of meshes
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
