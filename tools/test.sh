#!/usr/bin/env bash
# The default test suite: set-up, build, then every unit, validation and stability test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --test-dir build --output-on-failure --no-tests=error --parallel "$(nproc)" "$@"
