#!/usr/bin/env bash
# Configures and builds the toolkit in ./build (Release). Used by quickstart.sh and test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
generator=()
command -v ninja >/dev/null && [ ! -f build/Makefile ] && generator=(-G Ninja)
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DTAMPONADE_WERROR=$werror >/dev/null
cmake --build build --parallel "$(nproc)"
