#!/usr/bin/env bash
# The default test suite: set-up, build, then every unit, validation and stability test but the
# long validations.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
# Tests run in parallel processes, one OpenMP thread each: more threads than cores makes every
# OpenMP barrier wait for a time slice (measured: 10x slower steps on a loaded 2-core machine).
# Tests that check thread-count independence set their thread counts themselves.
# Without arguments: every test except the long validations (label `long`, minutes each;
# `bash tools/test.sh -L long` runs them, docs/developer-guide.md#tests).
[ $# -eq 0 ] && set -- -LE long
OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} ctest --test-dir build --output-on-failure --no-tests=error --parallel "$(nproc)" "$@"
