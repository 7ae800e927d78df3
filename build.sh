#!/usr/bin/env bash
# Configures and builds Catena in ./build (Release, warnings as errors when CI=true).
set -euo pipefail
cd "$(dirname "$0")"
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCATENA_WERROR=$werror >/dev/null
cmake --build build -j"$(nproc)"
