#!/usr/bin/env bash
# The sphere run reader's command line (tools/bench/sphere_run_reading.cpp): missing or bad
# options exit 2 naming the option, a file that is not a run's frames exits 1 naming the file,
# --help exits 0. No frame is read, so this takes a fraction of a second.
set -u
bench="$1"
source "$(dirname "$0")/cli_checks.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

expects 2 "give the run's frames file" --angle 18 --radius 12
expects 2 "--angle: give the contact angle in (0, 180) deg" "$work/frames.h5" --radius 12
expects 2 "--angle: give the contact angle in (0, 180) deg" "$work/frames.h5" --angle 180 --radius 12
expects 2 "--radius: give the cavity's radius in mm" "$work/frames.h5" --angle 18
expects 2 "needs a value: '--frame'" "$work/frames.h5" --angle 18 --radius 12 --frame
expects 2 "unexpected argument '--colour'" "$work/frames.h5" --colour red
expects 1 "$work/frames.h5" "$work/frames.h5" --angle 18 --radius 12
echo "not hdf5" >"$work/text.h5"
expects 1 "$work/text.h5" "$work/text.h5" --angle 18 --radius 12
"$bench" --help | grep -q "usage: sphere_run_reading" || fail "--help does not print the usage"
echo "ok"
