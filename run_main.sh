#!/usr/bin/env bash
# The main job: install, build, and run the EN 50318 reference case at 250 km/h on 2 MPI
# ranks (shape finding, static equilibrium, 3.85 s of pantograph-catenary dynamics), then
# print its EN 50318 contact-force statistics (docs/validation.md has the table).
set -euo pipefail
cd "$(dirname "$0")"
./install_deps.sh
./build.sh catena   # the command and the libraries it links, not the tests
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun -n 2 --oversubscribe build/apps/catena run meshes/en50318_250.yaml -o en50318_250.h5
build/apps/catena stats en50318_250.h5
build/apps/catena stats en50318_250.h5 --json
