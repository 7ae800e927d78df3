#!/usr/bin/env bash
# Configures and builds Catena in ./build (Release, warnings as errors when CI=true).
# Without arguments everything (libraries, catena, tests, benchmarks); with target names
# only those and what they need: ./build.sh catena builds the command alone.
set -euo pipefail
cd "$(dirname "$0")"
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCATENA_WERROR=$werror >/dev/null
targets=()
for target in "$@"; do
  targets+=(--target "$target")
done
cmake --build build -j"$(nproc)" "${targets[@]}"
