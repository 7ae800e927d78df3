#!/usr/bin/env bash
# Runs the static line benchmark at np = 1 and 2 (the project machine has 2 cores) and
# prints both reports; copy the numbers into docs/performance.md with this command line.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for np in 1 2; do
  mpirun -n "$np" --oversubscribe build/scaling/static_line_benchmark "$@"
done
