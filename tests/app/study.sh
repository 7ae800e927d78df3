#!/usr/bin/env bash
# `catena study` end to end (docs/study.md) on the taut string with HHT (alpha = 0, second
# order) and Radau IIA against a Radau IIA reference:
#   1. two one-rank groups (mpirun -n 2): every case completes; the errors are checked by
#      check_study.py (HHT's fall as dt^2, Radau's below HHT's);
#   2. the same command again: every case is kept, none runs again;
#   3. one rank, and one group of three ranks (mpirun -n 3 --ranks-per-case 3): the same
#      errors as on two groups;
#   4. a study stopped in its last case (CATENA_STOP_AFTER_STEPS, as SIGTERM would) exits
#      143 and, run again, keeps the finished cases and continues the stopped one from its
#      checkpoint;
#   5. the same after a crash (CATENA_KILL_AFTER_STEPS: SIGKILL in the last case, no record
#      written for it);
#   6. a stop in one of two groups stops the other (no hang), and the study resumes;
#   7. another --set runs every case again (the scene changed), the same keeps them;
#   8. a varied mesh: the probe is found by its point in every mesh, and the errors fall;
#   9. a probe id the scene does not have is refused before anything runs.
# Usage: study.sh CATENA SCENE WORK_DIR CHECK_SCRIPT
set -u
app=$1 scene=$2 work=$3 check=$4
mpirun="mpirun --oversubscribe"
rm -rf "$work" && mkdir -p "$work" || exit 1
study=(study "$scene" --set analysis.duration=1 --vary integrator.type=hht,radau
       --vary integrator.dt=0.04,0.02,0.01 --reference integrator.type=radau
       --reference integrator.dt=0.0025)
fail() { echo "study.sh: $*" >&2; exit 1; }

$mpirun -n 2 "$app" "${study[@]}" -o "$work/np2" > "$work/np2.out" 2>&1 \
  || { cat "$work/np2.out"; fail "the study on two groups failed"; }
cat "$work/np2.out"
grep -q "on 2 groups of 1 rank" "$work/np2.out" || fail "not two groups"

$mpirun -n 2 "$app" "${study[@]}" -o "$work/np2" > "$work/again.out" 2>&1 \
  || { cat "$work/again.out"; fail "the resumed study failed"; }
kept=$(grep -c "done before, kept" "$work/again.out")
started=$(grep -c " started on group" "$work/again.out")
[ "$kept" -eq 7 ] && [ "$started" -eq 0 ] || fail "again: $kept cases kept, $started run (7, 0 expected)"

"$app" "${study[@]}" -o "$work/np1" > "$work/np1.out" 2>&1 \
  || { cat "$work/np1.out"; fail "the study on one rank failed"; }
$mpirun -n 3 "$app" "${study[@]}" --ranks-per-case 3 -o "$work/np3" > "$work/np3.out" 2>&1 \
  || { cat "$work/np3.out"; fail "the study on a group of three ranks failed"; }
grep -q "on 1 group of 3 ranks" "$work/np3.out" || fail "not one group of three"

/usr/bin/python3 "$check" "$work/np2" "$work/np1" "$work/np3" || exit 1

# 4. Cases in queue order: reference (50 steps), then dt 0.04, 0.02, 0.01, 0.005 (200).
stop=(study "$scene" --set analysis.duration=1 --vary integrator.dt=0.04,0.02,0.01,0.005
      --reference integrator.dt=0.02 -o "$work/stopped")
CATENA_STOP_AFTER_STEPS=150 "$app" "${stop[@]}" > "$work/stop.out" 2>&1
code=$?
[ "$code" -eq 143 ] || { cat "$work/stop.out"; fail "stopped study exited $code, not 143"; }
"$app" "${stop[@]}" > "$work/resume.out" 2>&1 || { cat "$work/resume.out"; fail "resume failed"; }
cat "$work/resume.out"
kept=$(grep -c "done before, kept" "$work/resume.out")
started=$(grep -c " started on group" "$work/resume.out")
[ "$kept" -eq 4 ] && [ "$started" -eq 1 ] || fail "resume: $kept kept, $started run (4, 1 expected)"
grep -q "hht_dt=0.005 (integrator.dt=0.005) started" "$work/resume.out" || fail "wrong case rerun"
grep -q "restart: from .*hht_dt=0.005.h5.chk at t = 0.75 s" "$work/stopped/cases/hht_dt=0.005.log" \
  || fail "the stopped case did not continue from its checkpoint"
[ "$(grep -c ',completed,' "$work/stopped/study.csv")" -eq 5 ] || fail "not every case completed"

# 5. Killed outright in the same case: nothing of it recorded, the rest kept.
CATENA_KILL_AFTER_STEPS=150 "$app" "${stop[@]/stopped/killed}" > "$work/kill.out" 2>&1
code=$?
[ "$code" -ne 0 ] || { cat "$work/kill.out"; fail "the killed study exited 0"; }
[ ! -e "$work/killed/cases/hht_dt=0.005.result" ] || fail "the killed case left a record"
"$app" "${stop[@]/stopped/killed}" > "$work/rekill.out" 2>&1 \
  || { cat "$work/rekill.out"; fail "resume after the kill failed"; }
kept=$(grep -c "done before, kept" "$work/rekill.out")
started=$(grep -c " started on group" "$work/rekill.out")
[ "$kept" -eq 4 ] && [ "$started" -eq 1 ] || fail "after kill: $kept kept, $started run (4, 1 expected)"

# 6. Two groups: the group whose case stops tells the other to take no more; both exit.
CATENA_STOP_AFTER_STEPS=150 timeout 120 $mpirun -n 2 "$app" "${stop[@]/stopped/two}" \
  > "$work/two.out" 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || { cat "$work/two.out"; fail "two groups: exit $code"; }
timeout 120 $mpirun -n 2 "$app" "${stop[@]/stopped/two}" > "$work/two_again.out" 2>&1 \
  || { cat "$work/two_again.out"; fail "two groups: resume failed"; }
[ "$(grep -c ',completed,' "$work/two/study.csv")" -eq 5 ] || fail "two groups: not all completed"

# 7. The study's --set is part of every case's scene.
"$app" "${stop[@]}" > "$work/same.out" 2>&1 || fail "the same study again failed"
[ "$(grep -c ' started on group' "$work/same.out")" -eq 0 ] || fail "the same study ran cases"
"$app" "${stop[@]}" --set output.interval=0.0025 > "$work/changed.out" 2>&1 \
  || { cat "$work/changed.out"; fail "the changed study failed"; }
[ "$(grep -c ' started on group' "$work/changed.out")" -eq 5 ] || fail "a changed --set kept cases"

# 8. Elements 10 and 20 against 80 at the same step: the spatial error alone, each probe
#    found by its point (ids differ between the meshes); cubic ANCF elements: it falls about
#    ten times when the elements are halved (measured 12.2).
"$app" study "$scene" --set analysis.duration=0.5 --vary 'lines[0].elements=10,20' \
  --reference 'lines[0].elements=80' -o "$work/mesh" > "$work/mesh.out" 2>&1 \
  || { cat "$work/mesh.out"; fail "mesh study failed"; }
/usr/bin/python3 - "$work/mesh/study.csv" <<'PY' || fail "mesh study: errors"
import csv, sys
rows = {r["setting"]: r for r in csv.DictReader(open(sys.argv[1]))}
coarse = float(rows["lines[0].elements=10"]["probe_rms_m"])
fine = float(rows["lines[0].elements=20"]["probe_rms_m"])
print("mesh study: probe RMS", coarse, fine, "ratio", coarse / fine)
sys.exit(0 if 0 < fine and coarse / fine > 6 else 1)
PY

# 9. Refused before any case runs.
"$app" study "$scene" --vary integrator.dt=0.04,0.02 --probe 999 -o "$work/bad_probe" \
  > "$work/bad_probe.out" 2>&1
code=$?
[ "$code" -eq 2 ] && grep -q "no node with id 999" "$work/bad_probe.out" \
  && [ ! -e "$work/bad_probe/cases" ] || { cat "$work/bad_probe.out"; fail "bad probe: exit $code"; }
echo "study.sh: passed"
