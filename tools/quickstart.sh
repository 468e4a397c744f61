#!/usr/bin/env bash
# The toolkit's main job from a fresh clone: set-up, build, run the default eye protocol
# (data/protocols/default_eye.toml, draft accuracy) and print where its report is. The dam-break
# demo of the engine stays available as `build/tools/tamponade demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
# Passive OpenMP waiting: spinning threads cost 30-100x on a machine with other load.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
# The run refuses a folder that holds a run (nothing is overwritten by accident); this script
# owns runs/default_eye and starts it afresh.
rm -rf runs/default_eye
./build/tools/tamponade run data/protocols/default_eye.toml --out runs/default_eye
echo "report: runs/default_eye/report.html (the interfaces in ParaView: runs/default_eye/interfaces.xmf)"
