#!/usr/bin/env bash
# The equilibrium benchmark's command line (tools/bench/equilibrium_bench.cpp): bad options exit 2
# naming the option or the value and what it accepts, an unwritable folder exits 1 before any
# solve and writes no table, --help exits 0. No solve is started, so this takes a fraction of a
# second.
set -u
bench="$1"
fail() { echo "FAIL: $*"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || fail "no temporary folder"

out=$("$bench" --threshold bogus 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--threshold bogus exited $rc, expected 2"
grep -q "\-\-threshold bogus: use auto, whole or fractional" <<<"$out" || fail "no --threshold message: $out"

out=$("$bench" --voxels 0.3,-1 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--voxels 0.3,-1 exited $rc, expected 2"
grep -q "'-1' is not a positive number" <<<"$out" || fail "no --voxels message: $out"

out=$("$bench" --gravity -9.81 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--gravity -9.81 exited $rc, expected 2"
grep -q "'-9.81' is not a number >= 0" <<<"$out" || fail "no --gravity message: $out"

out=$("$bench" --colour red 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--colour red exited $rc, expected 2"
grep -q "unknown option '--colour'" <<<"$out" || fail "no unknown-option message: $out"

out=$("$bench" --fills 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--fills without a value exited $rc, expected 2"
grep -q "needs a value: '--fills'" <<<"$out" || fail "no missing-value message: $out"

out=$("$bench" --out /proc/not-a-folder 2>&1); rc=$?
[ "$rc" -eq 1 ] || fail "an unwritable --out exited $rc, expected 1"
grep -q "cannot write to '/proc/not-a-folder'" <<<"$out" || fail "no folder message: $out"
grep -q "| voxel |" <<<"$out" && fail "a table started although the folder cannot be written"

[ -z "$(ls -A "$work")" ] || fail "bad input left files behind: $(ls -A "$work")"
"$bench" --help | grep -q "usage: sim_equilibrium_bench" || fail "--help does not print the usage"
echo "ok"
