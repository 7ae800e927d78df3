#!/usr/bin/env bash
# What a run does to the files of an earlier run with the same output name
# (docs/output.md, "What survives what"):
#  A. a run that fails does not destroy an earlier complete result: OUT.h5 keeps it, the
#     failed run's time series is OUT.part.h5 with status "failed: ...";
#  B. a checkpoint of another run is never spliced in: run 1 is interrupted (checkpoint),
#     run 2 with other inputs and the same name dies before its first checkpoint, and
#     --restart of run 2 is refused with the reason (exit 2);
#  C. two runs cannot write the same output at once: the second is refused (exit 2,
#     "another run is writing this output") and the first goes on undisturbed;
#  D. after SIGTERM the time series is OUT.part.h5 ("interrupted"), and --restart makes
#     OUT.h5 ("complete"), removes the partial file and any temporary checkpoint file
#     a killed run left.
# Usage: run_files.sh CATENA WORKDIR
set -u
catena=$1 dir=$2
fail() { echo "run_files: FAILED: $*"; exit 1; }
status() { /usr/bin/python3 -c "import h5py, sys; print(h5py.File(sys.argv[1]).attrs['status'])" "$1"; }
clean() { rm -f "$1" "$1".chk "$1".lock "${1%.h5}".part.h5 "${1%.h5}".xmf "${1%.h5}".part.xmf "${1%.h5}".xmf2 "${1%.h5}".part.xmf2; }
scene=meshes/cable_pendulum.yaml
# Waits until the run logging to $1 is in its dynamics (the stop handling covers stepping).
in_dynamics() {
  for _ in $(seq 1 300); do grep -q "^dynamics:" "$1" && { sleep 1; return 0; }; sleep 0.2; done
  fail "no dynamics after 60 s: $(cat "$1")"
}

# A.
out=$dir/files_a.h5; clean "$out"
"$catena" run $scene --set analysis.duration=0.05 -o "$out" > /dev/null || fail "A: first run"
[ "$(status "$out")" = complete ] || fail "A: first run not complete"
"$catena" run $scene --set integrator.adaptive=true --set integrator.rtol=1e-12 \
  --set integrator.atol=1e-15 --set integrator.dt_min=1e-4 -o "$out" > "$dir/files_a.log" 2>&1
code=$?
[ "$code" -eq 3 ] || fail "A: failing run exited $code, expected 3"
[ "$(status "$out")" = complete ] || fail "A: the earlier complete result was replaced"
case "$(status "${out%.h5}.part.h5")" in failed:*) ;; *) fail "A: partial output status" ;; esac
grep -q "is an earlier run's, kept" "$dir/files_a.log" || fail "A: message does not say the earlier result is kept"
echo "run_files: A passed"

# B.
out=$dir/files_b.h5; clean "$out"
"$catena" run $scene --set analysis.duration=100 -o "$out" > "$dir/files_b1.log" 2>&1 &
pid=$!
in_dynamics "$dir/files_b1.log"; kill -TERM $pid; wait $pid
[ -f "$out.chk" ] || fail "B: no checkpoint after SIGTERM"
# Run 2: another alpha; killed (-9) while shape finding or stepping, before any checkpoint.
"$catena" run $scene --set integrator.alpha=-0.2 --set analysis.duration=100 \
  --set output.checkpoint_wall_seconds=0 -o "$out" > "$dir/files_b2.log" 2>&1 &
pid=$!
in_dynamics "$dir/files_b2.log"; kill -KILL $pid; wait $pid 2>/dev/null
"$catena" run $scene --set integrator.alpha=-0.2 --set analysis.duration=100 -o "$out" --restart \
  > "$dir/files_b.log" 2>&1
code=$?
[ "$code" -eq 2 ] || fail "B: restart of another run exited $code, expected 2"
grep -q "belongs to another run (integrator.alpha: '-0.2' here, nothing in the checkpoint" "$dir/files_b.log" ||
  fail "B: the refusal does not name the difference: $(cat "$dir/files_b.log")"
echo "run_files: B passed"

# C.
out=$dir/files_c.h5; clean "$out"
"$catena" run $scene --set analysis.duration=2000 -o "$out" > "$dir/files_c1.log" 2>&1 &
pid=$!
in_dynamics "$dir/files_c1.log"
"$catena" run $scene --set analysis.duration=2000 -o "$out" > "$dir/files_c2.log" 2>&1
code=$?
kill -TERM $pid; wait $pid
[ $? -eq 143 ] || fail "C: the first run did not stop cleanly: $(tail -2 "$dir/files_c1.log")"
[ "$code" -eq 2 ] || fail "C: the second run exited $code, expected 2"
grep -q "another run is writing this output" "$dir/files_c2.log" || fail "C: message"
[ "$(status "${out%.h5}.part.h5")" = interrupted ] || fail "C: first run's output status"
[ -e "$out.lock" ] && fail "C: lock file left behind"
echo "run_files: C passed"

# D.
out=$dir/files_d.h5; clean "$out"
"$catena" run $scene --set analysis.duration=100 -o "$out" > "$dir/files_d.log" 2>&1 &
pid=$!
in_dynamics "$dir/files_d.log"; kill -TERM $pid; wait $pid
[ -e "$out" ] && fail "D: OUT.h5 exists after an interrupted first run"
[ "$(status "${out%.h5}.part.h5")" = interrupted ] || fail "D: partial output status"
t=$(/usr/bin/python3 -c "import h5py, sys; print(h5py.File(sys.argv[1]).attrs['time'] + 0.05)" "$out.chk")
# A checkpoint a killed run was writing (its temporary file) is removed by the next run.
echo "half a checkpoint" > "$out.chk.tmp-999999"
"$catena" run $scene --set analysis.duration="$t" -o "$out" --restart > /dev/null || fail "D: restart"
[ "$(status "$out")" = complete ] || fail "D: restarted output not complete"
[ -e "${out%.h5}.part.h5" ] && fail "D: partial output left after completion"
[ -e "$out.chk.tmp-999999" ] && fail "D: an abandoned temporary checkpoint was left"
echo "run_files: passed"
