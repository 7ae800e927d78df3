#!/usr/bin/env bash
# Install, build and run the test suite (unit, regression, MPI and app tests). Without
# arguments every test but those labelled `long` (minutes each: ./run_tests.sh -L long runs
# them, ./run_tests.sh -R <regex> a selection); arguments go to ctest instead.
set -euo pipefail
cd "$(dirname "$0")"
./install_deps.sh --tests
./build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd build
[ "$#" -gt 0 ] || set -- -LE long
ctest --output-on-failure -j2 "$@"
