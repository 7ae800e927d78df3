#!/usr/bin/env bash
# Restarts of dynamic runs from their checkpoints (catena run --restart).
#  A. Kill and restart (meshes/taut_string.yaml, Radau IIA s = 3):
#     1. the whole run, uninterrupted, at np 2 (the reference);
#     2. the same run on one rank, stopped by SIGTERM part-way: exit 143, the partial
#        output (OUT.part.h5) with status "interrupted", a checkpoint written;
#     3. --restart at np 2 (another rank count) from that checkpoint: exit 0;
#     4. the restarted output equals the reference: same sample times and step count,
#        positions within 1e-9 m (the restarted Newton starts from a fresh tangent, so
#        Newton's tolerance, not round-off, separates them; the string is linear enough
#        not to amplify it).
#  B. Extend a finished run with constraints (meshes/driven_pendulum.yaml, HHT): 0.2 s,
#     then --restart with duration 0.4 s at np 2, against a 0.4 s run: positions within
#     1e-8 m, constraint forces within 1e-5 N. (A longer comparison is meaningless: the
#     driven pendulum's whipping amplifies any difference by ~10^3 per 0.4 s.)
# Usage: restart_roundtrip.sh CATENA MPIEXEC WORKDIR
set -u
catena=$1 mpiexec=$2 dir=$3
fail() { echo "restart_roundtrip: FAILED: $*"; exit 1; }
compare() {  # reference, restarted, position tolerance, force tolerance
  /usr/bin/python3 - "$@" <<'PY'
import sys
import h5py
import numpy as np
ref, out, tol_p, tol_f = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
with h5py.File(ref) as a, h5py.File(out) as b:
    assert b.attrs["status"] == "complete", b.attrs["status"]
    assert a["time"].shape == b["time"].shape, (a["time"].shape, b["time"].shape)
    assert np.abs(a["time"][:] - b["time"][:]).max() < 1e-12
    dp = np.abs(a["samples/positions"][:] - b["samples/positions"][:]).max()
    df = 0.0
    if "constraint_forces" in a["samples"]:
        df = np.abs(a["samples/constraint_forces"][:] - b["samples/constraint_forces"][:]).max()
    steps = (a["steps/time"].shape[0], b["steps/time"].shape[0])
    print(f"restart_roundtrip: {out}: {b['time'].shape[0]} samples, steps {steps}, "
          f"max position difference {dp:.2e} m, max constraint force difference {df:.2e} N")
    assert steps[0] == steps[1], steps
    assert dp < tol_p and df <= tol_f
PY
}

# A.
scene=meshes/taut_string.yaml
common=(--set analysis.duration=4 --set integrator.dt=2e-4)
ref=$dir/restart_ref.h5 out=$dir/restart_out.h5
rm -f "$ref" "$ref.chk" "$out" "$out.chk" "${out%.h5}.part.h5" "${ref%.h5}.part.h5"
"$mpiexec" -n 2 --oversubscribe "$catena" run "$scene" "${common[@]}" -o "$ref" > /dev/null ||
  fail "reference run"
"$catena" run "$scene" "${common[@]}" -o "$out" > "$dir/restart_interrupted.log" 2>&1 &
pid=$!
sleep 1.5
kill -TERM "$pid"
wait "$pid"
code=$?
[ "$code" -eq 143 ] || fail "interrupted run exited $code, expected 143 (128 + SIGTERM)"
[ -f "$out.chk" ] || fail "no checkpoint $out.chk after SIGTERM"
/usr/bin/python3 -c "import h5py, sys; s = h5py.File(sys.argv[1]).attrs['status']; \
  sys.exit(0 if s == 'interrupted' else 'status ' + s)" "${out%.h5}.part.h5" ||
  fail "status after SIGTERM"
"$mpiexec" -n 2 --oversubscribe "$catena" run "$scene" "${common[@]}" -o "$out" --restart ||
  fail "restart"
compare "$ref" "$out" 1e-9 0 || fail "restarted output differs from the reference"

# B.
scene=meshes/driven_pendulum.yaml
ref=$dir/extend_ref.h5 out=$dir/extend_out.h5
rm -f "$ref" "$ref.chk" "$out" "$out.chk" "${out%.h5}.part.h5" "${ref%.h5}.part.h5"
"$catena" run "$scene" --set analysis.duration=0.4 -o "$ref" > /dev/null || fail "reference run"
"$catena" run "$scene" --set analysis.duration=0.2 -o "$out" > /dev/null || fail "first part"
"$mpiexec" -n 2 --oversubscribe "$catena" run "$scene" --set analysis.duration=0.4 -o "$out" \
  --restart > /dev/null || fail "extension"
compare "$ref" "$out" 1e-8 1e-5 || fail "extended output differs from the reference"
echo "restart_roundtrip: passed"
