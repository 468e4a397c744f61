#!/usr/bin/env bash
# The contact angle benchmark's command line (tools/bench/contact_angle_bench.cpp): bad options exit 2
# naming the option and the accepted range, an unwritable folder exits 1 before any run, --help
# exits 0. No run is started, so this takes a fraction of a second.
set -u
bench="$1"
source "$(dirname "$0")/cli_checks.sh"

expects 2 "--angles: '200' is not a number in \[1, 179\]" --angles 30,200
expects 2 "must be cap, hemisphere or both" --start sideways
expects 2 "must be layered, single, tissue, both (layered and single) or all" --walls painted
expects 2 "needs a value" --time
expects 2 "needs a droplet heavier than the aqueous" --gravity 9.81 --out /nonexistent/folder
expects 1 "cannot write to '/nonexistent/folder'" --out /nonexistent/folder
grep -q "run 1 of" <<<"$out" && fail "a run started although the folder cannot be written"

"$bench" --help | grep -q "usage: sim_contact_angle_bench" || fail "--help does not print the usage"
echo "ok"
