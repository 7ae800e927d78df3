#!/usr/bin/env bash
# The main job: install, build, and run the default scene on 2 MPI ranks.
set -euo pipefail
cd "$(dirname "$0")"
./install_deps.sh
./build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun -n 2 --oversubscribe build/apps/catena run meshes/default.yaml -o default.h5
