#!/usr/bin/env bash
# Enforces the layering of docs/developer-guide.md: arrows point down. A library may include only itself and
# the libraries below it; CGAL may appear only in meshing/ .cpp files.
set -u
root=${1:-.}
status=0
check() {  # check <folder> <forbidden include prefix regex> <why>
  local hits
  hits=$(grep -rnE "#include [<\"]($2)" "$root/$1" --include='*.h' --include='*.cpp' 2>/dev/null)
  if [ -n "$hits" ]; then
    echo "layering violation in $1/ ($3):"; echo "$hits"; status=1
  fi
}
check sim 'meshing/|anatomy/|protocols/|tools/|CGAL/|assimp/|hdf5|H5|toml' "sim knows no eyes, meshes, files or HDF5"
check meshing 'sim/|anatomy/|protocols/|tools/|toml' "meshing is geometry only"
check anatomy 'sim/|protocols/|tools/|CGAL/|toml' "anatomy builds on meshing, never on sim"
check protocols 'tools/|CGAL/' "protocols is below tools; CGAL stays in meshing"
# Inside protocols: the scenario's data, then tissues, then assembly, then the runner.
check protocols/scenario 'protocols/(tissue|assembly|run|equilibrium|sweep)/' "scenario/ is the data the layers above share"
check protocols/tissue 'protocols/(assembly|run|equilibrium|sweep)/' "tissue/ builds on scenario/ only"
check protocols/assembly 'protocols/(run|equilibrium|sweep)/' "assembly/ is below the runner"
check protocols/equilibrium 'protocols/(run|sweep)/' "equilibrium/ solves postures; the runner runs schedules of them"
hdr=$(grep -rln "#include <CGAL/" "$root/meshing" --include='*.h' 2>/dev/null)
if [ -n "$hdr" ]; then echo "CGAL included from a header (keep it in meshing .cpp files): $hdr"; status=1; fi
[ $status -eq 0 ] && echo "layering ok"
exit $status
