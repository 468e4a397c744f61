#!/usr/bin/env bash
# The contact angle benchmark's command line (tools/bench/contact_angle_bench.cpp): bad options exit 2
# naming the option and the accepted range, an unwritable folder exits 1 before any run, --help
# exits 0. No run is started, so this takes a fraction of a second.
set -u
bench="$1"
fail() { echo "FAIL: $*"; exit 1; }

out=$("$bench" --angles 30,200 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--angles 30,200 exited $rc, expected 2"
grep -q "\-\-angles: '200' is not a number in \[1, 179\]" <<<"$out" || fail "no range message: $out"

out=$("$bench" --start sideways 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--start sideways exited $rc, expected 2"
grep -q "must be cap, hemisphere or both" <<<"$out" || fail "no --start message: $out"

out=$("$bench" --walls painted 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--walls painted exited $rc, expected 2"
grep -q "must be layered, single, tissue, both (layered and single) or all" <<<"$out" || fail "no --walls message: $out"

out=$("$bench" --time 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--time without a value exited $rc, expected 2"
grep -q "needs a value" <<<"$out" || fail "no missing-value message: $out"

out=$("$bench" --gravity 9.81 --out /nonexistent/folder 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "--gravity with the default (light) droplet exited $rc, expected 2"
grep -q "needs a droplet heavier than the aqueous" <<<"$out" || fail "no --gravity message: $out"

out=$("$bench" --out /nonexistent/folder 2>&1); rc=$?
[ "$rc" -eq 1 ] || fail "an unwritable --out exited $rc, expected 1"
grep -q "cannot write to '/nonexistent/folder'" <<<"$out" || fail "no folder message: $out"
grep -q "run 1 of" <<<"$out" && fail "a run started although the folder cannot be written"

"$bench" --help | grep -q "usage: sim_contact_angle_bench" || fail "--help does not print the usage"
echo "ok"
