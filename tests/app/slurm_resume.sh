#!/usr/bin/env bash
# The Slurm batch script scaling/slurm/catena_run.sbatch (docs/output.md, "Batch jobs
# (Slurm)") without Slurm. Fake srun, scancel and scontrol on PATH record their arguments:
# srun runs its command here as one task and, as srun does, kills it at SIGTERM; scancel
# --signal=SIG sends SIG to that task. The SLURM_* variables are set by hand, and every
# start of the job appends to one log, as --open-mode=append does. A dynamic scene (the
# pantograph on a wire, 3 s at 30 km/h, several seconds of wall time) goes through:
#  A. srun (fake), SIGUSR1 to the batch shell (--signal=B:USR1@...) once it is stepping:
#     scancel --signal=TERM JOBID stops catena (exit 143, output "interrupted", a
#     checkpoint), the script calls scontrol requeue JOBID and exits 0; the log has
#     progress lines and the restart count;
#  B. the requeued job (SLURM_RESTART_COUNT=1) with mpirun -n 2 as the launcher resumes
#     with --restart; SIGUSR1 again: the script signals catena's ranks under mpirun, which
#     stop with a new checkpoint; requeued again;
#  C. as scancel: SIGTERM to the batch shell and to catena, after the restart: catena stops
#     with a new checkpoint, the script exits 143 and does not requeue;
#  D. submitted again: resumes and completes (status complete, t = 3 s, 301 samples);
#  E. submitted again: "already complete", exit 0, catena not started;
#  F. a scene error (exit 2 from catena): exit 2, not requeued.
# Usage: slurm_resume.sh CATENA MPIEXEC WORKDIR
set -u
catena=$1 mpiexec=$2 dir=$3/slurm_resume
script=$(cd "$(dirname "$0")/../.." && pwd)/scaling/slurm/catena_run.sbatch
fail() {
  echo "slurm_resume: FAILED: $*"
  echo "--- log:"
  cat "$log" 2> /dev/null
  exit 1
}
rm -rf "$dir"
mkdir -p "$dir/bin"
log=$dir/slurm-4242.out
export FAKE_SLURM_DIR=$dir
cat > "$dir/bin/srun" << 'EOF'
#!/bin/bash
# fake srun: one task, here (srun.pid: its pid). As srun, it answers SIGTERM by killing its
# task ("forcing job termination"): catena must be signalled through scancel.
while [ "$#" -gt 0 ] && [ "${1#-}" != "$1" ]; do shift; done
"$@" &
task=$!
echo "$task" > "$FAKE_SLURM_DIR/srun.pid"
trap 'echo "srun: forcing job termination"; kill -KILL "$task"' TERM
while :; do
  wait "$task"
  code=$?
  kill -0 "$task" 2> /dev/null || exit "$code"
done
EOF
cat > "$dir/bin/scancel" << 'EOF'
#!/bin/bash
echo "$*" >> "$FAKE_SLURM_DIR/scancel.args"
case $1 in --signal=*) kill -"${1#--signal=}" "$(cat "$FAKE_SLURM_DIR/srun.pid")" ;; esac
EOF
cat > "$dir/bin/scontrol" << 'EOF'
#!/bin/bash
echo "$*" >> "$FAKE_SLURM_DIR/scontrol.args"
EOF
chmod +x "$dir/bin/"*
export PATH=$dir/bin:$PATH SLURM_JOB_ID=4242 SLURM_NTASKS=2 CATENA_BIN=$catena
export CATENA_PROGRESS=0.5
unset SLURM_RESTART_COUNT CATENA_LAUNCHER
out=$dir/run.h5 part=$dir/run.part.h5
scene=(meshes/pantograph_wire.yaml --set "pantographs[0].speed_kmh=30"
       --set analysis.duration=3 --set output.interval=0.01)

attr() {  # file, attribute
  /usr/bin/python3 -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r').attrs[sys.argv[2]])" "$@"
}
lines() { grep -c -- "$1" "$log"; }
# Starts the batch script in the background ($job), as sbatch would, appending to the log.
start() { bash "$script" "${scene[0]}" "$out" "${scene[@]:1}" >> "$log" 2>&1 & job=$!; }
# Waits until the log has more than N lines matching a pattern.
await() {  # pattern, N, what
  for _ in $(seq 1 600); do
    [ "$(lines "$1")" -gt "$2" ] && return 0
    kill -0 "$job" 2> /dev/null || fail "$3: the script ended before"
    sleep 0.1
  done
  fail "$3: not within 60 s"
}
finish() {  # what: waits for the script, sets $code
  timeout 120 tail --pid="$job" -f /dev/null || fail "$1: the script did not end (hung?)"
  wait "$job"
  code=$?
}
later() {  # t1, t2: t2 > t1
  /usr/bin/python3 -c "import sys; sys.exit(not float(sys.argv[2]) > float(sys.argv[1]))" "$@"
}
requeues() { [ -f "$dir/scontrol.args" ] && wc -l < "$dir/scontrol.args" || echo 0; }

# A.
t0=$SECONDS
start
await "^progress: t = " 0 "A: catena stepping"
kill -USR1 "$job"
finish A
[ "$code" -eq 0 ] || fail "A: the script exited $code after requeueing, expected 0"
[ "$(cat "$dir/scancel.args")" = "--signal=TERM 4242" ] ||
  fail "A: scancel called as '$(cat "$dir/scancel.args")'"
[ "$(cat "$dir/scontrol.args")" = "requeue 4242" ] ||
  fail "A: scontrol called as '$(cat "$dir/scontrol.args" 2> /dev/null)', expected 'requeue 4242'"
[ -f "$out.chk" ] || fail "A: no checkpoint $out.chk"
[ -e "$out" ] && fail "A: $out exists: the run was not interrupted"
[ "$(attr "$part" status)" = interrupted ] || fail "A: $part status is not 'interrupted'"
t_a=$(attr "$out.chk" time)
grep -q "catena: interrupted by signal 15" "$log" || fail "A: catena did not report the stop"
grep -q "requeued" "$log" || fail "A: the log does not say requeued"
grep -q "restart count 0" "$log" || fail "A: the log does not give the restart count"
echo "slurm_resume: A passed: stopped at t = $t_a s, requeued ($((SECONDS - t0)) s)"

# B.
t0=$SECONDS
n_progress=$(lines "^progress: t = ")
SLURM_RESTART_COUNT=1 CATENA_LAUNCHER="$mpiexec -n 2 --oversubscribe" start
await "^restart: from .*run.h5.chk at t = " 0 "B: catena's restart"
await "^progress: t = " "$n_progress" "B: catena stepping after the restart"
kill -USR1 "$job"
finish B
[ "$code" -eq 0 ] || fail "B: the script exited $code after requeueing, expected 0"
grep -q "restart count 1" "$log" || fail "B: the log does not give the restart count"
grep -q "resuming: .*catena run --restart" "$log" || fail "B: the log does not say --restart"
grep -q "sending SIGTERM to catena (pid [0-9]* [0-9]*)" "$log" ||
  fail "B: the script did not signal the two ranks"
{ [ "$(requeues)" -eq 2 ] && [ "$(tail -1 "$dir/scontrol.args")" = "requeue 4242" ]; } ||
  fail "B: not requeued: scontrol called as '$(cat "$dir/scontrol.args")'"
[ "$(attr "$part" status)" = interrupted ] || fail "B: $part status is not 'interrupted'"
t_b=$(attr "$out.chk" time)
later "$t_a" "$t_b" || fail "B: the checkpoint did not advance ($t_a s, then $t_b s)"
echo "slurm_resume: B passed: resumed at np 2, stopped at t = $t_b s, requeued" \
  "($((SECONDS - t0)) s)"

# C.
t0=$SECONDS
n_restarts=$(lines "^restart: from ")
n_progress=$(lines "^progress: t = ")
SLURM_RESTART_COUNT=2 start
await "^restart: from " "$n_restarts" "C: catena's restart"
await "^progress: t = " "$n_progress" "C: catena stepping after the restart"
kill -TERM "$job"
kill -TERM "$(cat "$dir/srun.pid")"
finish C
[ "$code" -eq 143 ] || fail "C: the script exited $code, expected catena's 143"
[ "$(requeues)" -eq 2 ] || fail "C: requeued after SIGTERM: $(cat "$dir/scontrol.args")"
grep -q "SIGTERM: the job is being ended" "$log" || fail "C: the log does not report SIGTERM"
[ "$(attr "$part" status)" = interrupted ] || fail "C: $part status is not 'interrupted'"
t_c=$(attr "$out.chk" time)
later "$t_b" "$t_c" || fail "C: the checkpoint did not advance ($t_b s, then $t_c s)"
echo "slurm_resume: C passed: stopped at t = $t_c s, not requeued ($((SECONDS - t0)) s)"

# D.
t0=$SECONDS
n_restarts=$(lines "^restart: from ")
start
finish D
[ "$code" -eq 0 ] || fail "D: the script exited $code, expected 0"
[ "$(lines "^restart: from ")" -gt "$n_restarts" ] || fail "D: catena did not restart"
[ "$(requeues)" -eq 2 ] || fail "D: requeued: $(cat "$dir/scontrol.args")"
[ -e "$part" ] && fail "D: $part left after completion"
/usr/bin/python3 - "$out" << 'PY' || fail "D: the completed output"
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    assert f.attrs["status"] == "complete", f.attrs["status"]
    assert abs(f.attrs["t_reached"] - 3.0) < 1e-9, f.attrs["t_reached"]
    t = f["time"][:]
    assert t.shape == (301,), t.shape
    assert np.allclose(t, np.arange(301) * 0.01, atol=1e-9), "sample times"
    steps = f["steps/time"][:]
    assert np.all(np.diff(steps) > 0), "step times not increasing"
    assert abs(steps[-1] - 3.0) < 1e-9, steps[-1]
PY
grep -q "complete: $out" "$log" || fail "D: the log does not say complete"
echo "slurm_resume: D passed: complete at t = 3 s ($((SECONDS - t0)) s)"

# E.
rm -f "$dir/srun.pid"
start
finish E
[ "$code" -eq 0 ] || fail "E: the script exited $code on a complete output, expected 0"
grep -q "already complete" "$log" || fail "E: the log does not say already complete"
[ -e "$dir/srun.pid" ] && fail "E: catena was started again"
echo "slurm_resume: E passed: already complete"

# F.
out=$dir/bad.h5
scene+=(--set analysis.duration=-1)
start
finish F
[ "$code" -eq 2 ] || fail "F: the script exited $code on a scene error, expected 2"
[ "$(requeues)" -eq 2 ] || fail "F: requeued after a scene error: $(cat "$dir/scontrol.args")"
grep -q "catena failed (exit 2" "$log" || fail "F: the log does not report the failure"
[ -e "$out.chk" ] && fail "F: a checkpoint of the failed run"
echo "slurm_resume: F passed: scene error, exit 2, not requeued"
echo "slurm_resume: passed"
