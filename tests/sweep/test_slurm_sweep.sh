#!/usr/bin/env bash
# End to end on a one-node Slurm started here (local_slurm.sh): a three-point equilibrium sweep
# submitted with `tamponade sweep --slurm` runs as a job array; `sweep status` and `sweep collect`
# then see three done points. Exit 77 (skipped) when Slurm cannot be started on this machine.
#   test_slurm_sweep.sh TAMPONADE SOURCE_DIR
set -u
tamponade=$1
source_dir=$2
work=$(mktemp -d)
here=$(cd "$(dirname "$0")" && pwd)
cleanup() { "$here/local_slurm.sh" stop "$work/slurm"; rm -rf "$work"; }
trap cleanup EXIT

start=$("$here/local_slurm.sh" start "$work/slurm") || exit $?
eval "$start"
cat >"$work/sweep.toml" <<TOML
base = "$source_dir/data/sweeps/emmetropic_one_posture.toml"
[vary]
"tamponade.fill" = ["70 %", "80 %", "90 %"]
TOML
fail() { echo "FAILED: $*"; for f in "$work"/out/slurm/*.log "$work"/slurm/*.log; do echo "== $f"; tail -5 "$f"; done; exit 1; }

"$tamponade" sweep "$work/sweep.toml" --out "$work/out" --slurm --time 00:10:00 --mem 1G ||
  fail "submission"
# Every point done within two minutes (each takes about a second).
for _ in $(seq 240); do
  status=$("$tamponade" sweep status "$work/out")
  echo "$status" | grep -q "3 points: 3 done" && break
  echo "$status" | grep -qE " [1-9][0-9]* failed" && fail "a point failed: $status"
  sleep 0.5
done
echo "$status"
echo "$status" | grep -q "3 points: 3 done" || fail "not done after 2 minutes"
grep -q '"backend": "slurm"' "$work/out/points/p002/point.json" || fail "point.json backend"
collected=$("$tamponade" sweep collect "$work/out") || fail "collect"
echo "$collected" | grep -q "3 of 3 points have results" || fail "collect: $collected"
[ "$(wc -l <"$work/out/sweep.csv")" -eq 4 ] || fail "sweep.csv rows"
echo "slurm sweep ok"
