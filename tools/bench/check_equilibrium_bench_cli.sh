#!/usr/bin/env bash
# The equilibrium benchmark's command line (tools/bench/equilibrium_bench.cpp): bad options exit 2
# naming the option or the value and what it accepts, an unwritable folder exits 1 before any
# solve and writes no table, --help exits 0. No solve is started, so this takes a fraction of a
# second.
set -u
bench="$1"
source "$(dirname "$0")/cli_checks.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || fail "no temporary folder"

expects 2 "--threshold bogus: use auto, whole or fractional" --threshold bogus
expects 2 "'-1' is not a positive number" --voxels 0.3,-1
expects 2 "'-9.81' is not a number >= 0" --gravity -9.81
expects 2 "--angles: 200 is not an angle in (0, 180) deg" --angles 30,200
expects 2 "--fills: 1 is not a fill in (0, 1)" --fills 0.9,1
expects 2 "unknown option '--colour'" --colour red
expects 2 "needs a value: '--fills'" --fills
expects 1 "cannot write to '/proc/not-a-folder'" --out /proc/not-a-folder
grep -q "| voxel |" <<<"$out" && fail "a table started although the folder cannot be written"

[ -z "$(ls -A "$work")" ] || fail "bad input left files behind: $(ls -A "$work")"
"$bench" --help | grep -q "usage: sim_equilibrium_bench" || fail "--help does not print the usage"
echo "ok"
