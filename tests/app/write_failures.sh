#!/usr/bin/env bash
# write_failures.sh APP MPIEXEC WORKDIR CASE — a write error on one rank is the same clean
# error on every rank (docs/output.md, "When the output cannot be written"):
#   exit code 4 on every rank, within a time limit (a hang fails, it does not block),
#   one message (rank 0's) naming the file and the cause, no HDF5 error-stack dump, no
#   signal, and the last checkpoint (dynamic) or the previous result (static) kept.
# CASE:
#   dynamic_sample, dynamic_flush, dynamic_checkpoint   2 ranks, meshes/taut_string.yaml,
#       a checkpoint every step; CATENA_FAULT_INJECT_WRITE fails rank 1's write of a
#       sample, of the steps at a flush, or of the second checkpoint
#   static_np1, static_np2     meshes/default.yaml, the last rank's write of
#       /static/positions fails; an older file at the output path is kept
#   full_disk_static_np1, full_disk_static_np2, full_disk_dynamic_np2   a real full disk:
#       a small tmpfs (skipped, exit 77, where mounting is not permitted)
set -u
app=$1 mpiexec=$2 workdir=$3 case=$4
python=/usr/bin/python3
limit=120
dir="$workdir/write_failures_$case"
rm -rf "$dir"
mkdir -p "$dir"

fail() {
  echo "FAIL ($case): $*" >&2
  exit 1
}

# run NP FAULT -- ARGS...: runs the app on NP ranks under `timeout` (FAULT: the value of
# CATENA_FAULT_INJECT_WRITE, or ""), output in $dir/log, each rank's exit code in
# $dir/exit.RANK and rank 0's in $code (124: the time limit). Each rank's wrapper exits 0
# after recording its code: a nonzero exit would make mpiexec kill the other ranks, whose
# wrappers might then die between their app's exit and writing its code (seen under load).
run() {
  local np=$1 fault=$2
  shift 3
  local -a env_args=()
  [ -n "$fault" ] && env_args=(-x "CATENA_FAULT_INJECT_WRITE=$fault")
  rm -f "$dir"/exit.*
  timeout $limit "$mpiexec" -n "$np" --oversubscribe "${env_args[@]}" bash -c \
    '"$@"; echo $? > "$0/exit.$OMPI_COMM_WORLD_RANK"' "$dir" \
    "$app" "$@" > "$dir/log" 2>&1
  code=$?
  [ "$code" -eq 124 ] || code=$(cat "$dir/exit.0" 2> /dev/null || echo "none")
  cat "$dir/log"
  n_ranks=$np
}

# The checks every case shares: exit code 4 (124: the time limit, a hang), one message
# containing each argument, no HDF5 error-stack dump.
expect_one_clean_error() {
  [ "$code" = 124 ] && fail "no exit within $limit s (a hang)"
  [ "$code" = 4 ] || fail "exit code $code, expected 4 (output could not be written)"
  local rank
  for ((rank = 0; rank < n_ranks; ++rank)); do
    [ "$(cat "$dir/exit.$rank" 2> /dev/null)" = 4 ] ||
      fail "rank $rank exited with $(cat "$dir/exit.$rank" 2> /dev/null || echo "no code"), expected 4"
  done
  local n_messages
  n_messages=$(grep -c '^catena: output could not be written: ' "$dir/log")
  [ "$n_messages" -eq 1 ] || fail "$n_messages messages, expected one (rank 0's)"
  local message
  message=$(grep '^catena: output could not be written: ' "$dir/log")
  for text in "$@"; do
    [[ "$message" == *"$text"* ]] || fail "the message does not contain '$text'"
  done
  grep -q 'HDF5-DIAG' "$dir/log" && fail "HDF5's error stack was printed"
  grep -q -i 'internal error\|segmentation\|signal' "$dir/log" && fail "a crash or an internal error"
  return 0
}

# The checkpoint the message says is kept is there and readable, at that time.
expect_checkpoint_kept() {
  local output=$1
  local message time
  message=$(grep '^catena: output could not be written: ' "$dir/log")
  [[ "$message" =~ the\ last\ checkpoint,\ .*\.chk\ at\ t\ =\ ([0-9.e+-]+)\ s,\ is\ kept ]] ||
    fail "the message names no kept checkpoint"
  time=${BASH_REMATCH[1]}
  "$python" - "$output.chk" "$time" <<'EOF' || fail "the checkpoint is not the one named"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    assert f.attrs["format"].startswith("catena-checkpoint-"), f.attrs["format"]
    assert abs(f.attrs["time"] - float(sys.argv[2])) <= 1e-9 * max(1.0, abs(f.attrs["time"])), \
        (f.attrs["time"], sys.argv[2])
    for name in ("q", "v", "a"):
        f[name][...]
EOF
  ls "$(dirname "$output")" | grep -q '\.tmp-' && fail "a temporary file was left"
  return 0
}

# The output file is closed with status "failed: <the message's first part>".
expect_output_status_failed() {
  "$python" - "$1" <<'EOF' || fail "the output's status is not failed"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    status = f.attrs["status"]
    assert status.startswith("failed: ") and "No space left on device" in status, status
EOF
}

dynamic_run() {  # FAULT
  run 2 "$1" -- run meshes/taut_string.yaml --set analysis.duration=0.1 \
    --set output.checkpoint_wall_seconds=1e-9 --set output.flush_wall_seconds=1e-9 \
    -o "$dir/run.h5"
}

static_run() {  # NP FAULT OUTPUT
  run "$1" "$2" -- run meshes/default.yaml -o "$3"
}

# A tmpfs of SIZE at $dir/disk, unmounted on exit; exit 77 (skipped) if not permitted.
mount_small_disk() {
  mkdir -p "$dir/disk"
  if ! mount -t tmpfs -o "size=$1" tmpfs "$dir/disk" 2> "$dir/mount_error"; then
    echo "SKIPPED ($case): cannot mount a tmpfs here: $(cat "$dir/mount_error")"
    exit 77
  fi
  trap 'umount "$dir/disk"' EXIT
}

fill_disk() {
  dd if=/dev/zero of="$dir/disk/filler" bs=4k > /dev/null 2>&1
  return 0
}

case $case in
  dynamic_sample)
    # Samples every 5 ms, a step and a checkpoint every 20 ms; samples are written at each
    # flush, so the second write of positions holds the second step's samples, after the
    # first checkpoint.
    dynamic_run "rank=1,call=2,at=/samples/positions"
    expect_one_clean_error "H5Dwrite failed for '$dir/run.part.h5' at /samples/positions" \
      "No space left on device" "(on rank 1)" "$dir/run.part.h5 is closed with status \"failed\""
    expect_checkpoint_kept "$dir/run.h5"
    expect_output_status_failed "$dir/run.part.h5"
    ;;
  dynamic_flush)
    # Each checkpoint flushes the steps first: the second flush of /steps/time fails.
    dynamic_run "rank=1,call=2,at=/steps/time"
    expect_one_clean_error "H5Dwrite failed for '$dir/run.part.h5' at /steps/time" \
      "No space left on device" "(on rank 1)"
    expect_checkpoint_kept "$dir/run.h5"
    expect_output_status_failed "$dir/run.part.h5"
    ;;
  dynamic_checkpoint)
    # Every checkpoint writes /q once: the second such write is the second checkpoint's.
    dynamic_run "rank=1,call=2,at=/q"
    expect_one_clean_error "cannot write the checkpoint '$dir/run.h5.chk'" "H5Dwrite failed" \
      "No space left on device" "(on rank 1)"
    expect_checkpoint_kept "$dir/run.h5"
    expect_output_status_failed "$dir/run.part.h5"
    ;;
  static_np1 | static_np2)
    np=${case#static_np}
    echo "an older result" > "$dir/static.h5"
    static_run "$np" "rank=$((np - 1)),call=1,at=/static/positions" "$dir/static.h5"
    expect_one_clean_error "cannot write '$dir/static.h5'" "at /static/positions" \
      "No space left on device"
    [ "$(cat "$dir/static.h5")" = "an older result" ] || fail "the older result was replaced"
    [ -z "$(ls "$dir" | grep -v '^log$\|^exit\.\|^static\.h5$')" ] || fail "files left: $(ls "$dir")"
    ;;
  full_disk_static_np1 | full_disk_static_np2)
    mount_small_disk 256k
    fill_disk
    static_run "${case#full_disk_static_np}" "" "$dir/disk/static.h5"
    expect_one_clean_error "cannot write '$dir/disk/static.h5'" "No space left on device"
    ;;
  full_disk_dynamic_np2)
    # Room for the file's start and some samples, not for the whole run.
    mount_small_disk 512k
    run 2 "" -- run meshes/taut_string.yaml --set analysis.duration=2 \
      --set output.checkpoint_wall_seconds=0 -o "$dir/disk/run.h5"
    expect_one_clean_error "$dir/disk/run.part.h5" "No space left on device"
    ;;
  *)
    fail "unknown case"
    ;;
esac
echo "PASS ($case)"
