#!/usr/bin/env bash
# Install, build and run the whole test suite (unit, regression and MPI tests).
set -euo pipefail
cd "$(dirname "$0")"
./install_deps.sh
./build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd build
ctest --output-on-failure -j2 "$@"
