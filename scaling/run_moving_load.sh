#!/usr/bin/env bash
# Runs the moving load benchmark (10 km line, HHT and Radau IIA s = 3) at np = 1 and 2 (the
# project machine has 2 cores) and prints the reports; copy the numbers into
# docs/performance.md with this command line. Extra arguments go to every run, e.g.
#   scaling/run_moving_load.sh -steps 50 -dt 5e-4
#   scaling/run_moving_load.sh -steps 40 -linear_algebra coupled   # radau's stage solve
#                                       (auto = decoupled; hht ignores it)
# BUILD_DIR selects the build tree (default: build).
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
bench="${BUILD_DIR:-build}/scaling/moving_load_benchmark"
for integrator in hht radau; do
  for np in 1 2; do
    mpirun -n "$np" --oversubscribe "$bench" -integrator "$integrator" "$@"
  done
done
