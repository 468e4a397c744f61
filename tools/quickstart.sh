#!/usr/bin/env bash
# The toolkit's main job from a fresh clone: set-up, build, run the default scenario.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
# Passive OpenMP waiting: spinning threads cost 30-100x on a machine with other load.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
./build/tools/tamponade demo --out runs/dam-break --force
