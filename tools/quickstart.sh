#!/usr/bin/env bash
# The toolkit's main job from a fresh clone: set-up, build, run the default scenario.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
./build/tools/tamponade demo --out runs/dam-break --force
