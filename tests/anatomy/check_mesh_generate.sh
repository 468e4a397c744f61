#!/usr/bin/env bash
# `tamponade mesh generate`: good runs exit 0 and report a watertight cavity; bad input exits 2
# with a message naming the problem; an unwritable file exits 1.
# usage: check_mesh_generate.sh <tamponade executable> <scratch directory>
set -u
exe=$1
dir=$2
mkdir -p "$dir"
status=0
expect() {  # expect <exit code> <text in output> <args...>
  local code=$1 text=$2; shift 2
  local out; out=$("$exe" mesh generate "$@" 2>&1); local rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -qF -- "$text" <<<"$out"; then
    echo "FAIL: mesh generate $* -> exit $rc (want $code), output lacks '$text':"; echo "$out"
    status=1
  fi
}
expect 0 "watertight      yes" --type emmetropic --resolution 32 --out "$dir/e.stl"
expect 0 "axial length    28.00 mm" --type myopic --axial-length 28mm --resolution 32 --out "$dir/m.obj"
expect 0 "staphyloma      depth 2.00 mm, width 8.00 mm" --type staphyloma --axial-length 29mm \
  --staphyloma-depth 2mm --staphyloma-width 8mm --resolution 32 --out "$dir/s.ply"
expect 0 "usage: tamponade mesh generate" --help
expect 2 "--axial-length: 28 needs a unit" --type myopic --axial-length 28 --out "$dir/x.stl"
expect 2 "myopic axial length 40.00 mm is out of range" --type myopic --axial-length 40mm --out "$dir/x.stl"
expect 2 "folds its edge" --type staphyloma --staphyloma-depth 5mm --staphyloma-width 6mm --out "$dir/x.stl"
expect 2 "apply only to --type staphyloma" --type emmetropic --staphyloma-depth 2mm --out "$dir/x.stl"
expect 2 "--type: 'round' must be emmetropic, myopic or staphyloma" --type round --out "$dir/x.stl"
expect 2 "not expected: --axial" --type myopic --axial 28mm --out "$dir/x.stl"
expect 2 "--out is required" --type myopic
expect 2 "must end in .stl, .obj or .ply" --type myopic --out "$dir/x.vtk"
expect 2 "resolution 2 is out of range" --type myopic --resolution 2 --out "$dir/x.stl"
expect 1 "cannot open for writing" --type myopic --resolution 16 --out /nonexistent-dir/x.stl
[ $status -eq 0 ] && echo "mesh generate checks ok"
exit $status
