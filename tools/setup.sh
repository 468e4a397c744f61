#!/usr/bin/env bash
# Installs the Debian 12 packages the toolkit needs to build and test. Idempotent: when every
# package is already installed it does nothing (and needs no network).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config  # compiler and build tools
  libeigen3-dev                                 # linear algebra (sim, meshing, anatomy)
  libcgal-dev                                   # mesh validation, repair, inside tests (meshing)
  libassimp-dev                                 # mesh import: STL, OBJ, PLY, OFF ... (meshing)
  libhdf5-dev hdf5-tools                        # frames and checkpoints; h5dump for inspection
  libtomlplusplus-dev                           # protocol files with exact line/column
  nlohmann-json3-dev                            # summary.json and sweep manifests
  libcli11-dev                                  # command-line options: typed, range-checked, --help
  libfmt-dev                                    # messages: fmt::format (no false -Wrestrict)
  slurm-wlm munge                               # the sweep's Slurm test: a one-node cluster
  catch2                                        # tests
  clang-format                                  # the format test (tests/check_format.sh)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
