#!/usr/bin/env bash
# A damaged checkpoint is refused as bad input (exit 2) with what is wrong in it, never run
# on: a short run of meshes/cable_pendulum.yaml writes OUT.h5 and OUT.h5.chk; copies of
# both, each with one damage made by h5py, are restarted with --restart:
#   time NaN, last_dt negative, a negative step count, a NaN in /q, /v deleted.
# The undamaged copy restarts (exit 0), so the refusals are the damage's.
# Usage: restart_damaged.sh CATENA WORKDIR
set -u
catena=$1 dir=$2/restart_damaged
fail() { echo "restart_damaged: FAILED: $*"; exit 1; }
rm -rf "$dir" && mkdir -p "$dir" || fail "cannot make $dir"
scene=meshes/cable_pendulum.yaml
"$catena" run "$scene" --set analysis.duration=0.05 -o "$dir/base.h5" > /dev/null ||
  fail "the first run"
[ -f "$dir/base.h5.chk" ] || fail "no checkpoint written"

# damage NAME PYTHON: copies base to NAME.h5(.chk) and runs PYTHON on the checkpoint `f`.
damage() {
  cp "$dir/base.h5" "$dir/$1.h5" && cp "$dir/base.h5.chk" "$dir/$1.h5.chk" || fail "copy $1"
  /usr/bin/python3 -c "import h5py, numpy as np, sys
f = h5py.File(sys.argv[1], 'r+')
$2
f.close()" "$dir/$1.h5.chk" || fail "damaging $1"
}
# restart NAME CODE REGEX
restart() {
  "$catena" run "$scene" --set analysis.duration=0.1 -o "$dir/$1.h5" --restart \
    > "$dir/$1.log" 2>&1
  code=$?
  [ "$code" -eq "$2" ] || { cat "$dir/$1.log"; fail "$1: exit $code, expected $2"; }
  grep -E -q "$3" "$dir/$1.log" || { cat "$dir/$1.log"; fail "$1: no line matching '$3'"; }
  echo "restart_damaged: $1: exit $code: $(grep -E -o "$3" "$dir/$1.log" | head -1)"
}

damage intact "pass"
restart intact 0 "done at t = 0.1 s"
damage nan_time "f.attrs['time'] = np.nan"
restart nan_time 2 "cannot restart from this checkpoint: the file is damaged: time = nan is not a finite number"
damage negative_dt "f.attrs['last_dt'] = -1e-3"
restart negative_dt 2 "the file is damaged: last_dt = -0.001 is not a step"
damage negative_steps "f.attrs['steps'] = np.int64(-4)"
restart negative_steps 2 "the file is damaged: samples = [0-9]+, steps = -4"
damage nan_position "q = f['q'][...]; q[3, 2] = np.nan; f['q'][...] = q"
restart nan_position 2 "the file is damaged: /q holds nan \(value [0-9]+\), not a finite number"
damage missing_velocity "del f['v']"
restart missing_velocity 2 "cannot restart from this checkpoint: the file is damaged: it has no dataset /v"
echo "restart_damaged: passed"
