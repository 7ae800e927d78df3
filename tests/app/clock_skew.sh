#!/usr/bin/env bash
# Wall-clock decisions are taken once for all ranks: a 2-rank dynamic run whose ranks'
# MPI_Wtime origins differ by 5 s (in either direction; an LD_PRELOAD shim shifts rank 1's
# clock) must flush and checkpoint on the wall clock and finish, not deadlock at its first
# flush. A hang is caught by `timeout`.
# Usage: clock_skew.sh CATENA MPIEXEC SHIM WORKDIR
set -u
catena=$1 mpiexec=$2 shim=$3 dir=$4
fail() { echo "clock_skew: FAILED: $*"; exit 1; }
for skew in -5 5; do
  out=$dir/clock_skew_$skew.h5
  rm -f "$out" "$out.chk"
  timeout 240 "$mpiexec" -n 2 --oversubscribe -x LD_PRELOAD="$shim" \
    -x CATENA_TEST_WTIME_SKEW="1:$skew" "$catena" run meshes/pantograph_wire.yaml \
    --set analysis.duration=0.06 --set output.flush_wall_seconds=0.2 \
    --set output.checkpoint_wall_seconds=0.5 -o "$out" > "$dir/clock_skew_$skew.log" 2>&1
  code=$?
  [ "$code" -eq 124 ] && fail "rank 1 ${skew} s off: the run hung (killed after 240 s)"
  [ "$code" -eq 0 ] || fail "rank 1 ${skew} s off: exit $code: $(tail -3 "$dir/clock_skew_$skew.log")"
  /usr/bin/python3 -c "import h5py, sys; s = h5py.File(sys.argv[1]).attrs['status']; \
    sys.exit(0 if s == 'complete' else 'status ' + s)" "$out" || fail "status of $out"
  echo "clock_skew: rank 1 ${skew} s off: complete"
done
echo "clock_skew: passed"
