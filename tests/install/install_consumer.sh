#!/usr/bin/env bash
# The installed package (README, "Install and use as a library"): `cmake --install` of the
# build tree BUILD into WORK/prefix; the installed catena runs and its plot scripts are
# there; the example consumer (tests/install/consumer) is configured with find_package(Catena)
# against the prefix, built and run. WORK is emptied first; any failing step fails the test.
# Usage: install_consumer.sh CMAKE BUILD WORK SOURCE CXX BINDIR DATADIR [LAUNCHER]
set -euo pipefail
cmake=$1 build=$2 work=$3 source=$4 cxx=$5 bindir=$6 datadir=$7 launcher=${8:-}
prefix=$work/prefix

# A step's output is kept in WORK/NAME.log and shown only when the step fails.
step() {
  local name=$1
  shift
  echo "install_consumer: $name: $*"
  if ! "$@" >"$work/$name.log" 2>&1; then
    cat "$work/$name.log"
    echo "install_consumer: $name failed" >&2
    exit 1
  fi
}

rm -rf "$work"
mkdir -p "$work"
step install "$cmake" --install "$build" --prefix "$prefix"

step version "$prefix/$bindir/catena" --version
grep -Eq '^catena [0-9]+\.[0-9]+\.[0-9]+ ' "$work/version.log" || {
  cat "$work/version.log"
  echo "install_consumer: '$prefix/$bindir/catena --version' printed no version" >&2
  exit 1
}
scripts=0
for script in "$source"/apps/*.py; do
  installed=$prefix/$datadir/catena/$(basename "$script")
  cmp -s "$script" "$installed" || {
    echo "install_consumer: $installed is missing or differs from $script" >&2
    exit 1
  }
  scripts=$((scripts + 1))
done
echo "install_consumer: $scripts plot scripts in $prefix/$datadir/catena"

launch=()
[ -z "$launcher" ] || launch=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
step configure "$cmake" -S "$source/tests/install/consumer" -B "$work/consumer" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
  "${launch[@]}"
step build "$cmake" --build "$work/consumer"
step run "$work/consumer/catena_consumer"
cat "$work/run.log"
