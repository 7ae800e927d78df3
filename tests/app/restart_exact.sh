#!/usr/bin/env bash
# Restarts continue bit for bit on the same rank count (docs/output.md, "Checkpoints and
# --restart"): every dataset of the restarted output file (samples, steps, contact forces,
# mesh) equals the uninterrupted run's exactly (numpy array_equal). The stop and crash
# points are the testing hooks CATENA_STOP_AFTER_STEPS, CATENA_KILL_AFTER_STEPS and
# CATENA_CHECKPOINT_EVERY_STEPS (apps/catena/test_hooks.hpp), not the wall clock.
#  A. Stop (as SIGTERM) after N steps, --restart, same rank count:
#     HHT on meshes/pantograph_wire.yaml (moving contact, local Newton), np 1 and np 2;
#     Radau IIA s = 3 on meshes/taut_string.yaml, np 1 and np 2;
#     adaptive steps (embedded estimates): Radau IIA on the taut string and HHT on the
#     pantograph, np 1; step doubling (HHT on the pantograph), np 2; a linear structure
#     (HHT on the pantograph, np 2), and with the linearly implicit step (np 1); the modal
#     model (np 2), to round-off (its restart projects the state on the modes); HHT and its
#     linearly implicit step stopped one step before the end (np 1).
#  B. A crash: checkpoints every 7 steps, SIGKILL after 40 (HHT on the pantograph, np 2)
#     or 19 (Radau IIA, np 1) steps, so that the last checkpoint (step 35 or 14) is not the
#     stop point, then --restart.
#  C. Twice: stop after N, restart and stop again, restart to the end (np 2, pantograph).
#  D. Another rank count: stopped at np 2, restarted at np 1: equal to the Newton tolerance
#     (positions 1e-9 m, contact force 1e-4 N), not bit for bit.
#  E. A format-1 checkpoint (no solver state) still restarts, to the same tolerance.
# The cases are in two groups: `core` (the default run: same-rank HHT and Radau IIA, a
# linear and a modal structure, a crash, another rank count) and `more` (labelled long:
# adaptive steps, the linearly implicit step, the last step, twice, a second crash, format 1).
# Usage: restart_exact.sh CATENA MPIEXEC WORKDIR [core|more|all]
set -u
catena=$1 mpiexec=$2 dir=$3 group=${4:-all}
case "$group" in core|more|all) ;; *) echo "restart_exact: group '$group': core, more or all"; exit 2 ;; esac
in_group() { [ "$group" = all ] || [ "$group" = "$1" ]; }
fail() { echo "restart_exact: FAILED: $*"; exit 1; }
run() {  # ranks, then catena's arguments
  local n=$1
  shift
  if [ "$n" -eq 1 ]; then "$catena" run "$@"; else "$mpiexec" -n "$n" --oversubscribe "$catena" run "$@"; fi
}
compare() {  # reference, restarted, exact|<position tolerance> [force tolerance]
  /usr/bin/python3 - "$@" <<'PY'
import sys
import h5py
import numpy as np
ref, out, mode = sys.argv[1], sys.argv[2], sys.argv[3]
def datasets(f):
    names = []
    f.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
    return sorted(names)
with h5py.File(ref) as a, h5py.File(out) as b:
    assert b.attrs["status"] == "complete", b.attrs["status"]
    assert datasets(a) == datasets(b), (datasets(a), datasets(b))
    assert a["steps/time"].shape[0] > 0
    if mode == "exact":
        differ = [n for n in datasets(a) if not np.array_equal(a[n][()], b[n][()])]
        assert not differ, f"datasets not bit-identical: {differ}"
        print(f"restart_exact: {out}: {len(datasets(a))} datasets identical "
              f"({a['time'].shape[0]} samples, {a['steps/time'].shape[0]} steps)")
    else:
        tol_p, tol_f = float(mode), float(sys.argv[4])
        assert a["time"].shape == b["time"].shape
        assert np.abs(a["time"][:] - b["time"][:]).max() < 1e-12
        dp = np.abs(a["samples/positions"][:] - b["samples/positions"][:]).max()
        df = np.abs(a["samples/contact_force"][:] - b["samples/contact_force"][:]).max()
        print(f"restart_exact: {out}: positions within {dp:.2e} m, contact force {df:.2e} N")
        assert dp < tol_p and df < tol_f
PY
}
# reference RANKS SCENE ARGS...: sets $ref to the uninterrupted run's output (run once per
# rank count, scene and arguments).
declare -A references=()
reference() {
  local n=$1
  shift
  local key="$n $*"
  ref=${references[$key]:-}
  if [ -z "$ref" ]; then
    ref=$dir/exact_${group}_ref_${#references[@]}.h5
    rm -f "$ref" "$ref.chk"
    run "$n" "$@" -o "$ref" > "$ref.log" 2>&1 || fail "reference run (log $ref.log)"
    references[$key]=$ref
  fi
}
# case NAME RANKS_FIRST RANKS_RESTART STOP_ENV COMPARE SCENE ARGS...: the reference run,
# the stopped run, its restart, the comparison.
case_() {
  local name=$1 n1=$2 n2=$3 stop=$4 mode=$5
  shift 5
  reference "$n2" "$@"
  local out=$dir/exact_$name.h5
  rm -f "$out" "$out.chk"
  (export $stop; run "$n1" "$@" -o "$out") > "$out.log" 2>&1
  local code=$?
  case "$stop" in
    *KILL*) [ "$code" -ne 0 ] || fail "$name: the killed run exited 0" ;;
    *) [ "$code" -eq 143 ] || fail "$name: the stopped run exited $code, expected 143" ;;
  esac
  [ -f "$out.chk" ] || fail "$name: no checkpoint"
  run "$n2" "$@" -o "$out" --restart >> "$out.log" 2>&1 || fail "$name: restart (log $out.log)"
  if [ "$mode" = exact ]; then
    compare "$ref" "$out" exact || fail "$name: restarted output differs (log $out.log)"
  else
    compare "$ref" "$out" $mode || fail "$name: restarted output differs (log $out.log)"
  fi
}

pantograph=(meshes/pantograph_wire.yaml --set analysis.duration=0.06)
string=(meshes/taut_string.yaml --set analysis.duration=0.6 --set integrator.stages=3)
adaptive_string=("${string[@]}" --set integrator.adaptive=true --set integrator.rtol=1e-6)
adaptive_pantograph=("${pantograph[@]}" --set integrator.adaptive=true --set integrator.rtol=1e-3)
doubling_pantograph=("${adaptive_pantograph[@]}" --set integrator.error_estimate=step_doubling)

# A.
in_group core && case_ hht_np1 1 1 CATENA_STOP_AFTER_STEPS=130 exact "${pantograph[@]}"
in_group core && case_ hht_np2 2 2 CATENA_STOP_AFTER_STEPS=130 exact "${pantograph[@]}"
in_group more && case_ radau_np1 1 1 CATENA_STOP_AFTER_STEPS=13 exact "${string[@]}"
in_group core && case_ radau_np2 2 2 CATENA_STOP_AFTER_STEPS=13 exact "${string[@]}"
in_group more && case_ radau_adaptive_np1 1 1 CATENA_STOP_AFTER_STEPS=9 exact "${adaptive_string[@]}"
in_group more && case_ hht_adaptive_np1 1 1 CATENA_STOP_AFTER_STEPS=25 exact "${adaptive_pantograph[@]}"
in_group more && case_ hht_doubling_np2 2 2 CATENA_STOP_AFTER_STEPS=6 exact "${doubling_pantograph[@]}"
#    A linear structure: the restart solves the equilibrium again and linearises about it.
in_group core && case_ hht_linear_np2 2 2 CATENA_STOP_AFTER_STEPS=130 exact "${pantograph[@]}" \
  --set analysis.structure=linear
#    The linearly implicit step, its tangent re-evaluated every 50 steps (the count since
#    the last one travels in the checkpoint).
in_group more && case_ hht_linearly_implicit_np1 1 1 CATENA_STOP_AFTER_STEPS=130 exact "${pantograph[@]}" \
  --set analysis.structure=linear --set integrator.newton=linearly_implicit \
  --set integrator.tangent_every=50
#    Stopped one step before the end: the last step (t_end − t, dt but for round-off) keeps
#    the matrix of dt, which the restart rebuilds from the saved step, not from t_end − t.
in_group more && case_ hht_last_step_np1 1 1 CATENA_STOP_AFTER_STEPS=299 exact "${pantograph[@]}"
in_group more && case_ hht_linearly_implicit_last_step_np1 1 1 CATENA_STOP_AFTER_STEPS=299 exact \
  "${pantograph[@]}" --set analysis.structure=linear --set integrator.newton=linearly_implicit \
  --set integrator.tangent_every=50
#    The modal model: the restart builds its modes again and projects the checkpoint's state
#    on them (η = Φᵀ M (q − q0)): equal to round-off (1e-9 m, 1e-5 N), not bit for bit.
in_group core && case_ modal_np2 2 2 CATENA_STOP_AFTER_STEPS=130 "1e-9 1e-5" "${pantograph[@]}" \
  --set analysis.structure=modal
# B.
in_group core && case_ hht_crash_np2 2 2 "CATENA_CHECKPOINT_EVERY_STEPS=7 CATENA_KILL_AFTER_STEPS=40" exact \
  "${pantograph[@]}"
in_group more && case_ radau_crash_np1 1 1 "CATENA_CHECKPOINT_EVERY_STEPS=7 CATENA_KILL_AFTER_STEPS=19" exact \
  "${string[@]}"
# C.
if in_group more; then
reference 2 "${pantograph[@]}"
out=$dir/exact_twice.h5
rm -f "$out" "$out.chk"
CATENA_STOP_AFTER_STEPS=60 run 2 "${pantograph[@]}" -o "$out" > "$out.log" 2>&1
[ $? -eq 143 ] || fail "twice: first stop"
CATENA_STOP_AFTER_STEPS=90 run 2 "${pantograph[@]}" -o "$out" --restart >> "$out.log" 2>&1
[ $? -eq 143 ] || fail "twice: second stop"
run 2 "${pantograph[@]}" -o "$out" --restart >> "$out.log" 2>&1 || fail "twice: restart"
compare "$ref" "$out" exact || fail "twice: restarted output differs"
fi
# D.
in_group core && case_ hht_np2_to_np1 2 1 CATENA_STOP_AFTER_STEPS=130 "1e-9 1e-4" "${pantograph[@]}"
# E. A checkpoint of the first format (no /resume) still restarts, to the Newton tolerance,
#    and says why it is not exact.
if in_group more; then
reference 1 "${pantograph[@]}"
out=$dir/exact_format1.h5
rm -f "$out" "$out.chk"
CATENA_STOP_AFTER_STEPS=130 run 1 "${pantograph[@]}" -o "$out" > "$out.log" 2>&1
[ $? -eq 143 ] || fail "format 1: stop"
/usr/bin/python3 - "$out.chk" <<'PY' || fail "format 1: could not rewrite the checkpoint"
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    del f["resume"]
    del f.attrs["ranks"]
    f.attrs["format"] = "catena-checkpoint-1"
PY
run 1 "${pantograph[@]}" -o "$out" --restart > "$out.restart.log" 2>&1 || fail "format 1: restart"
grep -q "holds no solver state" "$out.restart.log" || fail "format 1: no note"
compare "$ref" "$out" 1e-9 1e-4 || fail "format 1: differs"
fi
echo "restart_exact: $group passed"
